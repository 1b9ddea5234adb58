//! `ue4-ssao`: Unreal Engine 4's legacy SSAO (PostProcessAmbientOcclusion.usf, Epic Games),
//! sample pairs mirrored about the pixel read from a furthest-depth MIP chain.

use serde::{Deserialize, Serialize};

use super::{Knob, MethodSpec, max_radius_px};
use crate::passes::kernel::depth_mips::DepthReduction;
use crate::presets::{samples, tuned};
use crate::settings::{Method, Preset, count, setting};
use crate::shader;
use crate::uniforms::{KernelCounts, flags};

/// Sampling of `ue4-ssao`: how many mirrored sample pairs, and which of Unreal's two versions
/// scores them (Unreal Engine 4's PostProcessAmbientOcclusion.usf, Epic Games).
///
/// ```
/// use aokit::{AoSettings, Method, Preset};
/// let mut settings = AoSettings::preset(Method::Ue4Ssao, Preset::High);
/// // Nine pairs: 18 depth samples, the budget of every method at `high`.
/// assert_eq!(settings.ue4_ssao.sample_count, 9);
/// assert_eq!(settings.samples_per_pixel(), 18);
/// // The depth-only version, for inputs without normals worth reading.
/// settings.ue4_ssao.use_normals = false;
/// settings.validate()?;
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Ue4SsaoSettings {
    /// Sample pairs per pixel, each two depth samples mirrored about the pixel, so a pixel
    /// reads `2 * sample_count` depths. Their directions split the half circle evenly.
    pub sample_count: u32,
    /// The normal version: each sample's angle is measured from the tangent plane of the
    /// pixel's normal. Off, the depth-only version: the angle between the two samples of each
    /// pair, with the flat-surface bias ([`AoSettings::bias`](crate::AoSettings::bias)) telling creases from ridges.
    pub use_normals: bool,
}

impl Default for Ue4SsaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl Ue4SsaoSettings {
    /// The pairs of a preset, half its depth samples, and the normal version.
    ///
    /// ```
    /// use aokit::{Preset, Ue4SsaoSettings};
    /// let pairs = Preset::ALL.map(|p| Ue4SsaoSettings::preset(p).sample_count);
    /// assert_eq!(pairs, [2, 4, 9, 27]);
    /// ```
    pub fn preset(preset: Preset) -> Self {
        Self {
            sample_count: samples(preset) / 2,
            // Our inputs always carry normals (decoded or reconstructed), and the normal
            // version needs no bias to keep planes and ridges unoccluded.
            use_normals: true,
        }
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Ue4Ssao,
    shader: shader::UE4_SSAO,
    // Not tuned: Unreal's legacy SSAO as Unreal Engine 4's PostProcessAmbientOcclusion.usf
    // (Epic Games) gives it. Its weight fades linearly with how far a sample lies in front of
    // the pixel, to 0 at the radius (falloff 1); its flat-surface bias is 5 units, 2.5% of
    // Unreal's default 200-unit AO radius.
    tuned: |preset| tuned([samples(preset) / 2, 1], 1.0, 1.0, 0.025, 1.0, 1.0),
    knob: Knob::Bias,
    samples_per_pixel: |s| 2 * s.ue4_ssao.sample_count,
    max_radius_px,
    // Sample pairs, each one step.
    kernel_counts: |s, _| KernelCounts::new(s.ue4_ssao.sample_count, 1),
    flags: |s| {
        if s.ue4_ssao.use_normals {
            flags::UE4_SSAO_NORMALS
        } else {
            0
        }
    },
    bent_normals: false,
    marches_slices: false,
    depth_mips: Some(DepthReduction::Furthest),
    section: "ue4_ssao",
    settings: &[
        setting!(
            ue4_ssao.sample_count,
            count(),
            "sample pairs per pixel, each two depth samples mirrored about the pixel: a pixel \
             reads twice this many depths, so presets give 2, 4, 9 and 27 pairs \
             ([methods/ue4-ssao.md](methods/ue4-ssao.md))"
        ),
        setting!(
            ue4_ssao.use_normals,
            bool,
            "`ue4-ssao`'s normal version, each sample's angle measured from the tangent plane; \
             false: the depth-only version, the angle between the two samples of a pair with the \
             flat-surface `bias`"
        ),
    ],
};
