//! `msvo`: multi-scale volumetric obscurance (Microsoft MiniEngine's SSAO, Unity
//! PostProcessing's MSVO), the fraction of a sphere in front of the depth buffer at each level
//! of a depth MIP chain. Its two passes are passes/kernel/msvo.rs.

use serde::{Deserialize, Serialize};

use super::{Knob, MAX_SAMPLE_COUNT, MethodSpec, no_flags};
use crate::passes::kernel::depth_mips::DepthReduction;
use crate::presets::{samples, tuned};
use crate::settings::{Method, Preset, integers, positive, setting};
use crate::shader;
use crate::uniforms::KernelCounts;

/// Sampling of `msvo`: sample pairs per level, how many levels, and Unity's thickness
/// modifier (docs/methods/msvo.md).
///
/// ```
/// use aokit::{AoSettings, Method, MsvoSettings, Preset};
/// // Unity's "Thickness Modifier" at 2: occluders count further in front of the sphere,
/// // darker creases at the price of halos around objects.
/// let msvo = MsvoSettings { thickness: 2.0, ..MsvoSettings::preset(Preset::High) };
/// let settings = AoSettings { msvo, ..AoSettings::preset(Method::Msvo, Preset::High) };
/// settings.validate()?;
/// // The coarsest of five levels holds a disc of 5 texels of 16 pixels: 80 pixels at most.
/// assert_eq!(settings.effective_max_radius_px(), 80.0);
/// // Samples come in mirrored pairs: an odd count is refused.
/// let odd = AoSettings { msvo: MsvoSettings { sample_count: 7, ..msvo }, ..settings };
/// assert_eq!(odd.validate().unwrap_err().field, "msvo.sample_count");
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MsvoSettings {
    /// Depth samples per texel at each level, in mirrored pairs, on a disc of
    /// 5 texels of the level. The working level costs this many per pixel; each coarser level
    /// a quarter of the one before, so all five at most a third more.
    pub sample_count: u32,
    /// Levels of the depth MIP chain the obscurance is computed at, at most [`MSVO_MAX_LEVELS`]:
    /// level `k` covers radii up to `5 * 2^k` working texels, so the screen radius stops at
    /// `5 * 2^(levels - 1)` ([`AoSettings::effective_max_radius_px`](crate::AoSettings::effective_max_radius_px)).
    pub levels: u32,
    /// Unity's thickness modifier (MiniEngine's rejection falloff): a sample more than this
    /// many sphere chords in front of the sphere is taken for a thin occluder and rejected.
    /// Larger values darken creases and add halos around objects.
    pub thickness: f32,
}

/// Most levels `msvo` runs: the working resolution and the four coarser levels of the depth
/// MIP chain, as Unity's MSVO merges four downsampled levels.
pub const MSVO_MAX_LEVELS: u32 = 5;

/// Radius of `msvo`'s sample disc in texels of each level (MiniEngine's and Unity's 5).
const MSVO_DISC_RADIUS: u32 = 5;

impl Default for MsvoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl MsvoSettings {
    /// A preset's samples per level, all five levels, and Unity's default thickness of 1.
    ///
    /// ```
    /// use aokit::{MsvoSettings, Preset};
    /// let counts = Preset::ALL.map(|p| MsvoSettings::preset(p).sample_count);
    /// assert_eq!(counts, [4, 8, 18, 54]);
    /// assert_eq!(MsvoSettings::preset(Preset::Low).levels, aokit::MSVO_MAX_LEVELS);
    /// ```
    pub fn preset(preset: Preset) -> Self {
        let tuned = (SPEC.tuned)(preset);
        Self {
            sample_count: tuned.split[0],
            // Every level at every preset: fewer levels cut the radius, not just the cost
            // (the coarser four add at most a third to the working level's samples).
            levels: MSVO_MAX_LEVELS,
            thickness: tuned.knob,
        }
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Msvo,
    shader: shader::MSVO_OBSCURANCE,
    // Not tuned: MSVO as Unity ships it (Post-processing Stack v2), every preset's samples at
    // each level, Unity's default thickness modifier of 1 (the knob), no falloff of ours (the
    // sphere's chords weight its samples), power and radius as given.
    tuned: |preset| tuned([samples(preset), 1], 1.0, 0.0, 1.0, 1.0, 1.0),
    knob: Knob::Own("msvo.thickness"),
    // The working level's; the coarser levels add at most a third.
    samples_per_pixel: |s| s.msvo.sample_count,
    // The coarsest level's disc, in the input's pixels.
    max_radius_px: |s| {
        let disc = MSVO_DISC_RADIUS << (s.msvo.levels.clamp(1, MSVO_MAX_LEVELS) - 1);
        s.max_radius_px.min((disc * s.resolution.scale()) as f32)
    },
    // Samples per level, the level count, and the rejection distance in chords.
    kernel_counts: |s, _| KernelCounts {
        thickness: s.msvo.thickness,
        ..KernelCounts::new(s.msvo.sample_count, s.msvo.levels)
    },
    flags: no_flags,
    bent_normals: false,
    marches_slices: false,
    // Its levels hold real depths as SAO's do: an average across an edge would occlude.
    depth_mips: Some(DepthReduction::Subsample),
    section: "msvo",
    settings: &[
        setting!(
            msvo.sample_count,
            integers(2, MAX_SAMPLE_COUNT, 2),
            "depth samples per texel at each level, in mirrored pairs on a disc of 5 texels of \
             the level; the working level costs this many per pixel, the coarser four together \
             at most a third more ([methods/msvo.md](methods/msvo.md))"
        ),
        setting!(
            msvo.levels,
            integers(1, MSVO_MAX_LEVELS, 1),
            "levels of the depth MIP chain the obscurance is computed at and merged from; the \
             screen radius stops at `5 * 2^(levels - 1)` working texels (80 with all five)"
        ),
        setting!(
            msvo.thickness,
            positive(),
            "Unity's thickness modifier: a sample more than this many sphere chords in front of \
             the sphere is taken for a thin occluder and rejected; larger darkens creases and \
             adds halos around objects",
            note = "Unity's default"
        ),
    ],
};
