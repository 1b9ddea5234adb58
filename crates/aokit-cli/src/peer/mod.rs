//! Peers: other AO implementations, run beside aokit's on the same G-buffer, timed with the same
//! timer and scored against the same reference (docs/peers.md). The one peer is Intel's XeGTAO,
//! which the user checks out; aokit holds none of its code, only a wrapper of its own
//! (`peers/xegtao.hlsl`) that glslangValidator compiles against the user's files.

mod command;
mod compile;
mod constants;
mod gpu;
mod source;
mod spirv;
#[cfg(test)]
mod tests;

use std::path::PathBuf;
use std::str::FromStr;

use anyhow::{Result, anyhow, bail};
use aokit::Preset;
use serde_json::{Value, json};

pub use command::{PeerArgs, run};
pub use gpu::XeGtao;
pub use source::Shaders;

/// `--peer NAME=DIR`: which peer, and where its sources or compiled shaders are.
#[derive(Clone, Debug, PartialEq)]
pub struct PeerSpec {
    /// The peer's name; `xegtao` is the only one.
    pub name: String,
    /// A checkout (or the folder of its shader files), or a folder `aokit peer compile` wrote.
    pub dir: PathBuf,
}

/// The peers aokit knows.
const PEERS: [&str; 1] = ["xegtao"];

impl FromStr for PeerSpec {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let (name, dir) = text
            .split_once('=')
            .ok_or_else(|| format!("`{text}` is not NAME=DIR (e.g. xegtao=/path/to/XeGTAO)"))?;
        if !PEERS.contains(&name) {
            return Err(format!(
                "unknown peer `{name}` (known: {})",
                PEERS.join(", ")
            ));
        }
        if dir.is_empty() {
            return Err(format!("`{text}` names no folder"));
        }
        Ok(Self {
            name: name.to_string(),
            dir: PathBuf::from(dir),
        })
    }
}

/// Device features a peer uses where the adapter has them: SPIR-V passed through, and the
/// adapter's own storage formats (XeGTAO writes R16Float, R8Uint and R8Unorm).
pub const FEATURES: wgpu::Features = wgpu::Features::PASSTHROUGH_SHADERS
    .union(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);

/// The ways to the GPU to run: `chosen`, else naga and, where the device can, passthrough.
pub fn shader_paths(device: &wgpu::Device, chosen: Option<ShaderPath>) -> Vec<ShaderPath> {
    match chosen {
        Some(path) => vec![path],
        None if device
            .features()
            .contains(wgpu::Features::PASSTHROUGH_SHADERS) =>
        {
            vec![ShaderPath::Naga, ShaderPath::Passthrough]
        }
        None => vec![ShaderPath::Naga],
    }
}

/// A peer configuration's name in tables, JSON and file names: `xegtao-naga`.
pub fn method_name(spec: &PeerSpec, shader: ShaderPath) -> String {
    format!("{}-{}", spec.name, shader.name())
}

/// How the peer's SPIR-V reaches the GPU.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShaderPath {
    /// Through naga's SPIR-V front end, as wgpu translates any shader: naga's output is
    /// measured with the peer.
    Naga,
    /// Handed to the driver as it is (`Features::PASSTHROUGH_SHADERS`), where the adapter can.
    Passthrough,
}

impl ShaderPath {
    /// The name `--set peer.shader` takes and labels show.
    pub fn name(self) -> &'static str {
        match self {
            ShaderPath::Naga => "naga",
            ShaderPath::Passthrough => "passthrough",
        }
    }
}

/// XeGTAO's quality levels, as its entry points set slices and steps per side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quality {
    Low,
    Medium,
    High,
    Ultra,
}

impl Quality {
    /// Every level, lowest first.
    pub const ALL: [Quality; 4] = [Quality::Low, Quality::Medium, Quality::High, Quality::Ultra];

    /// aokit's preset of the same name.
    pub fn of(preset: Preset) -> Self {
        match preset {
            Preset::Low => Quality::Low,
            Preset::Medium => Quality::Medium,
            Preset::High => Quality::High,
            Preset::Ultra => Quality::Ultra,
        }
    }

    /// Its name, as aokit's preset of the same level is named.
    pub fn name(self) -> &'static str {
        match self {
            Quality::Low => "low",
            Quality::Medium => "medium",
            Quality::High => "high",
            Quality::Ultra => "ultra",
        }
    }

    /// Slices, and steps per side of each slice.
    pub fn slices_and_steps(self) -> (u32, u32) {
        match self {
            Quality::Low => (1, 2),
            Quality::Medium => (2, 2),
            Quality::High => (3, 3),
            Quality::Ultra => (9, 3),
        }
    }
}

/// Most denoiser passes `peer.denoise_passes` takes; XeGTAO's own settings offer three.
const MAX_DENOISE_PASSES: u32 = 8;

/// A peer configuration, from aokit's flags: the preset picks the quality level,
/// `spatial.enabled` the denoiser.
#[derive(Clone, Debug, PartialEq)]
pub struct PeerSettings {
    /// XeGTAO's quality level, from the preset.
    pub quality: Quality,
    /// AO radius in world units: XeGTAO's effect radius.
    pub radius: f32,
    /// XeGTAO's `DenoisePasses`: 0 turns its denoiser off, yet one pass still runs, the
    /// last, with the blur off, to scale the AO term into the output; N > 0 runs N passes.
    pub denoise_passes: u32,
    /// Only this way to the GPU; both where the adapter can pass SPIR-V through, else naga.
    pub shader: Option<ShaderPath>,
}

impl PeerSettings {
    /// The peer's settings for `preset`, `radius` and the `--set KEY=VALUE` list. A peer maps
    /// `radius`, `spatial.enabled` (XeGTAO's one denoiser pass) and its own `peer.denoise_passes`
    /// and `peer.shader`; with `strict`, any other key is an error (a bench configuration),
    /// else it is ignored (compare's overrides, laid over every method).
    pub fn from_flags(preset: Preset, radius: f32, set: &[String], strict: bool) -> Result<Self> {
        let mut settings = PeerSettings {
            quality: Quality::of(preset),
            radius,
            denoise_passes: 0,
            shader: None,
        };
        // Denoised by default as aokit's presets are, so that the two compare like for like.
        let mut spatial = aokit::SpatialSettings::default().enabled;
        let mut passes = None;
        for assignment in set {
            let (key, value) = assignment
                .split_once('=')
                .map(|(k, v)| (k.trim(), v.trim()))
                .ok_or_else(|| anyhow!("--set `{assignment}` is not KEY=VALUE"))?;
            let invalid = |expected: &str| anyhow!("invalid setting `{key}` = {value}: {expected}");
            match key {
                "radius" => {
                    settings.radius = value
                        .parse()
                        .ok()
                        .filter(|r: &f32| r.is_finite() && *r > 0.0)
                        .ok_or_else(|| invalid("a positive number"))?;
                }
                "spatial.enabled" => {
                    spatial = value.parse().map_err(|_| invalid("true or false"))?;
                }
                "peer.denoise_passes" => {
                    passes = Some(
                        value
                            .parse()
                            .ok()
                            .filter(|n| *n <= MAX_DENOISE_PASSES)
                            .ok_or_else(|| invalid("an integer in 0..=8"))?,
                    );
                }
                "peer.shader" => {
                    settings.shader = Some(match value.trim_matches('"') {
                        "naga" => ShaderPath::Naga,
                        "passthrough" => ShaderPath::Passthrough,
                        _ => return Err(invalid("naga or passthrough")),
                    });
                }
                _ if strict || key.starts_with("peer.") => bail!(
                    "--set {key} has no counterpart in a peer, which takes radius, \
                     spatial.enabled, peer.denoise_passes and peer.shader"
                ),
                _ => {}
            }
        }
        settings.denoise_passes = passes.unwrap_or(u32::from(spatial));
        Ok(settings)
    }

    /// `--set` entries a peer reads, which aokit's methods do not know.
    pub fn is_peer_key(assignment: &str) -> bool {
        assignment.trim_start().starts_with("peer.")
    }

    /// Samples per pixel of the main pass: two per step, both sides of each slice.
    pub fn samples_per_pixel(&self) -> u32 {
        let (slices, steps) = self.quality.slices_and_steps();
        2 * slices * steps
    }

    /// As bench's JSON writes a configuration's settings.
    pub fn json(&self, spec: &PeerSpec, shader: ShaderPath) -> Value {
        let (slices, steps) = self.quality.slices_and_steps();
        json!({
            "method": method_name(spec, shader),
            "peer": spec.name,
            "peer_dir": spec.dir.display().to_string(),
            "quality": self.quality.name(),
            "slices": slices,
            "steps_per_side": steps,
            "radius": self.radius,
            "denoise_passes": self.denoise_passes,
            "shader": shader.name(),
        })
    }
}

#[cfg(test)]
mod settings_tests {
    use super::*;

    fn sets(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn specs_name_a_known_peer_and_a_folder() {
        let spec: PeerSpec = "xegtao=/src/XeGTAO".parse().unwrap();
        assert_eq!(spec.dir, PathBuf::from("/src/XeGTAO"));
        assert!(
            "xegtao"
                .parse::<PeerSpec>()
                .unwrap_err()
                .contains("NAME=DIR")
        );
        assert!(
            "hbao=/x"
                .parse::<PeerSpec>()
                .unwrap_err()
                .contains("xegtao")
        );
        assert!("xegtao=".parse::<PeerSpec>().is_err());
    }

    #[test]
    fn presets_and_sets_map_to_quality_and_denoiser() {
        let s = PeerSettings::from_flags(Preset::High, 0.5, &[], true).unwrap();
        assert_eq!(
            (s.quality.slices_and_steps(), s.denoise_passes),
            ((3, 3), 1)
        );
        let raw = sets(&["spatial.enabled=false"]);
        let s = PeerSettings::from_flags(Preset::High, 0.5, &raw, true).unwrap();
        assert_eq!(s.denoise_passes, 0);
        assert_eq!(s.samples_per_pixel(), 18);
        let s = PeerSettings::from_flags(
            Preset::Ultra,
            0.5,
            &sets(&["spatial.enabled=true", "radius=2", "peer.shader=naga"]),
            true,
        )
        .unwrap();
        assert_eq!(
            (s.quality, s.denoise_passes, s.radius, s.shader),
            (Quality::Ultra, 1, 2.0, Some(ShaderPath::Naga))
        );
        let s = PeerSettings::from_flags(Preset::Low, 1.0, &sets(&["peer.denoise_passes=3"]), true)
            .unwrap();
        assert_eq!(s.denoise_passes, 3);
    }

    #[test]
    fn settings_without_a_counterpart_are_errors_in_a_configuration() {
        let err = PeerSettings::from_flags(Preset::High, 1.0, &sets(&["gtao.slice_count=4"]), true)
            .unwrap_err()
            .to_string();
        assert!(err.contains("gtao.slice_count"), "{err}");
        // Compare's overrides reach every method: others' keys pass, unknown peer keys do not.
        assert!(
            PeerSettings::from_flags(Preset::High, 1.0, &sets(&["gtao.slice_count=4"]), false)
                .is_ok()
        );
        assert!(
            PeerSettings::from_flags(Preset::High, 1.0, &sets(&["peer.slices=4"]), false).is_err()
        );
        for bad in [
            "peer.denoise_passes=9",
            "peer.shader=dxc",
            "spatial.enabled=1",
        ] {
            let err = PeerSettings::from_flags(Preset::High, 1.0, &sets(&[bad]), true)
                .unwrap_err()
                .to_string();
            assert!(err.contains("invalid setting"), "{bad}: {err}");
        }
    }
}
