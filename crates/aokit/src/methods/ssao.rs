//! `ssao`: normal-oriented hemisphere SSAO, cosine-weighted points tested against the depth
//! buffer. Its [`SsaoSettings`] also serve `ssao-crytek` and `sao`.

use serde::{Deserialize, Serialize};

use super::{Knob, MethodSpec, max_radius_px, no_flags};
use crate::presets::{samples, tuned};
use crate::settings::{Method, Preset, count, setting};
use crate::shader;
use crate::uniforms::KernelCounts;

/// Sample count of the point-sampling methods (`ssao-crytek`, `ssao`, `sao`).
///
/// ```
/// use aokit::{AoSettings, Method, Preset};
/// // A still for a comparison: twice the high preset's samples.
/// let mut settings = AoSettings::preset(Method::Ssao, Preset::High);
/// settings.ssao.sample_count *= 2;
/// assert_eq!(settings.samples_per_pixel(), 36);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SsaoSettings {
    /// Points tested against the depth buffer per pixel.
    pub sample_count: u32,
}

impl Default for SsaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl SsaoSettings {
    /// Sample count of a preset.
    ///
    /// ```
    /// use aokit::{Preset, SsaoSettings};
    /// // Each preset's whole budget goes to points, one depth sample each.
    /// let counts = Preset::ALL.map(|p| SsaoSettings::preset(p).sample_count);
    /// assert_eq!(counts, [4, 8, 18, 54]);
    /// ```
    pub fn preset(preset: Preset) -> Self {
        Self {
            sample_count: samples(preset),
        }
    }

    /// The uniforms' counts of a point method: its samples, one step each.
    pub(super) fn kernel_counts(self) -> KernelCounts {
        KernelCounts::new(self.sample_count, 1)
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Ssao,
    shader: shader::SSAO,
    tuned: |preset| match preset {
        Preset::Low => tuned([4, 1], 1.0, 1.0, 0.005, 3.5, 1.1),
        Preset::Medium => tuned([8, 1], 1.0, 1.0, 0.005, 3.0, 1.1),
        Preset::High => tuned([18, 1], 1.0, 0.75, 0.005, 2.0, 1.2),
        Preset::Ultra => tuned([54, 1], 1.0, 1.0, 0.005, 3.0, 1.0),
    },
    knob: Knob::Bias,
    samples_per_pixel: |s| s.ssao.sample_count,
    max_radius_px,
    kernel_counts: |s, _| s.ssao.kernel_counts(),
    flags: no_flags,
    bent_normals: false,
    marches_slices: false,
    depth_mips: None,
    section: "ssao",
    settings: &[setting!(
        ssao.sample_count,
        count(),
        "points in the hemisphere per pixel"
    )],
};
