//! `hbao`: horizon-based AO (Bavoil and Sainz 2008), per screen direction the rise of the
//! horizon above the tangent plane. Its [`HbaoSettings`] also serve `hbao-plus`; its separable
//! variant's two passes are passes/kernel/separable_hbao.rs.

use serde::{Deserialize, Serialize};

use super::{Knob, MethodSpec, no_flags};
use crate::presets::tuned;
use crate::settings::{AoSettings, HbaoVariant, Method, Preset, Rule, count, setting};
use crate::shader;
use crate::uniforms::KernelCounts;

/// Ray-marching counts of `hbao` and `hbao-plus`, and how `hbao` runs.
///
/// ```
/// use aokit::{AoSettings, HbaoSettings, HbaoVariant, Method, Preset};
/// // Eight directions of four steps: the cost is their product.
/// let settings = AoSettings {
///     hbao: HbaoSettings { direction_count: 8, step_count: 4, variant: HbaoVariant::PerPixel },
///     ..AoSettings::preset(Method::HbaoPlus, Preset::High)
/// };
/// assert_eq!(settings.samples_per_pixel(), 32);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct HbaoSettings {
    /// Screen-space directions over the full circle, rotated per pixel. The separable variant
    /// has its own four and does not read this.
    pub direction_count: u32,
    /// Depth samples along each direction.
    pub step_count: u32,
    /// How `hbao` runs: one kernel per pixel, or the two separable passes. `hbao-plus` runs
    /// per pixel only ([`AoSettings::validate`] refuses it the separable variant).
    pub variant: HbaoVariant,
}

/// Largest screen radius of the separable HBAO variant, in texels of the working resolution:
/// each workgroup holds its 128-texel row or column segment and this many texels on each side
/// in workgroup memory, and a pixel's samples must fall inside. Where the radius would reach
/// farther, the pixel works with the world radius that covers this many texels, exactly as
/// [`AoSettings::max_radius_px`] clamps. 128 texels is the default `max_radius_px` (256 pixels)
/// at half resolution, NVIDIA's recommended resolution for HBAO, and keeps the tile at 1.5 KiB.
///
/// ```
/// use aokit::{AoSettings, HbaoVariant, Method, Preset, Resolution};
/// let mut settings = AoSettings::preset(Method::Hbao, Preset::High);
/// settings.hbao.variant = HbaoVariant::Separable;
/// // At full resolution the apron halves the default 256-pixel limit...
/// assert_eq!(settings.effective_max_radius_px(), aokit::SEPARABLE_HBAO_MAX_RADIUS_PX as f32);
/// // ...at half resolution its texels cover the default.
/// settings.resolution = Resolution::Half;
/// assert_eq!(settings.effective_max_radius_px(), settings.max_radius_px);
/// ```
pub const SEPARABLE_HBAO_MAX_RADIUS_PX: u32 = 128;

impl Default for HbaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl HbaoSettings {
    /// Counts of a preset: directions times steps equals the preset's samples, split as
    /// `aokit tune` measured best for `hbao` (docs/tuning.md); `hbao-plus` runs on the same.
    ///
    /// ```
    /// use aokit::{HbaoSettings, Preset};
    /// let high = HbaoSettings::preset(Preset::High);
    /// assert_eq!((high.direction_count, high.step_count), (6, 3));
    /// ```
    pub fn preset(preset: Preset) -> Self {
        let [direction_count, step_count] = (SPEC.tuned)(preset).split;
        Self {
            direction_count,
            step_count,
            // Per pixel, so that every table published before the separable variant stands.
            variant: HbaoVariant::PerPixel,
        }
    }

    /// The uniforms' counts of `hbao` and `hbao-plus`: directions and steps along each.
    pub(super) fn kernel_counts(self) -> KernelCounts {
        KernelCounts::new(self.direction_count, self.step_count)
    }
}

impl AoSettings {
    /// Whether the pipeline runs `hbao` as its two separable passes ([`HbaoVariant::Separable`])
    /// rather than one kernel.
    pub(crate) fn separable_hbao(&self) -> bool {
        self.method == Method::Hbao && self.hbao.variant == HbaoVariant::Separable
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Hbao,
    shader: shader::HBAO,
    tuned: |preset| match preset {
        Preset::Low => tuned([2, 2], 1.5, 0.0, 0.05, 1.6, 1.5),
        Preset::Medium => tuned([4, 2], 1.5, 0.0, 0.05, 1.6, 1.5),
        Preset::High => tuned([6, 3], 1.5, 0.0, 0.05, 1.25, 1.5),
        Preset::Ultra => tuned([6, 9], 1.5, 0.0, 0.1, 1.0, 1.35),
    },
    knob: Knob::AngleBias,
    samples_per_pixel: |s| {
        if s.separable_hbao() {
            // +-x and +-y.
            4 * s.hbao.step_count
        } else {
            s.hbao.direction_count * s.hbao.step_count
        }
    },
    // The separable passes' samples must stay inside their workgroup's apron.
    max_radius_px: |s| {
        if s.separable_hbao() {
            let apron = (SEPARABLE_HBAO_MAX_RADIUS_PX * s.resolution.scale()) as f32;
            s.max_radius_px.min(apron)
        } else {
            s.max_radius_px
        }
    },
    kernel_counts: |s, _| s.hbao.kernel_counts(),
    flags: no_flags,
    bent_normals: false,
    marches_slices: true,
    depth_mips: None,
    section: "hbao",
    settings: &[
        setting!(
            hbao.direction_count,
            count(),
            "screen directions over the full circle, rotated per pixel (`hbao`, `hbao-plus`; not \
             read by `hbao.variant = separable`, which has four)"
        ),
        setting!(
            hbao.step_count,
            count(),
            "samples per direction (`hbao`, `hbao-plus`)"
        ),
        setting!(
            hbao.variant,
            choice,
            "how `hbao` runs: one kernel per pixel, or two passes over rows and then columns of \
             depth in workgroup memory, after NVIDIA's compute-shader HBAO: four fixed directions \
             (+-x, +-y), `4 * step_count` samples, the screen radius stopped at 128 texels of \
             the working resolution \
             ([methods/hbao.md](methods/hbao.md#separable-hbao-hbaovariant--separable)); \
             `hbao-plus` accepts only `per-pixel`",
            rule = Rule {
                holds: |s| {
                    !(s.method == Method::HbaoPlus && s.hbao.variant == HbaoVariant::Separable)
                },
                value: |s| format!("{} with method {}", s.hbao.variant.name(), s.method.name()),
                expected: "per-pixel: the separable passes integrate hbao's horizons, which \
                           hbao-plus does not have",
            }
        ),
    ],
};
