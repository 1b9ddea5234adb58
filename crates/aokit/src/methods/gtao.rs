//! `gtao`: ground-truth based AO (Jimenez et al. 2016), the cosine-weighted horizon integral
//! per slice.

use serde::{Deserialize, Serialize};

use super::{Knob, MethodSpec, max_radius_px};
use crate::presets::tuned;
use crate::settings::{Method, Preset, count, setting, unit};
use crate::shader;
use crate::uniforms::{KernelCounts, flags};

/// GTAO's sampling and its thickness heuristic.
///
/// ```
/// use aokit::{AoSettings, GtaoSettings, Method, Preset};
/// // Poles and railings: let the horizon fall back behind them rather than treat the scene
/// // as a height field whose occluders reach down forever.
/// let gtao = GtaoSettings { thickness: 0.5, ..GtaoSettings::preset(Preset::High) };
/// let settings = AoSettings { gtao, ..AoSettings::preset(Method::Gtao, Preset::High) };
/// settings.validate()?;
/// let over = AoSettings { gtao: GtaoSettings { thickness: 1.5, ..gtao }, ..settings };
/// assert_eq!(over.validate().unwrap_err().field, "gtao.thickness");
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GtaoSettings {
    /// Slices (screen-space directions over a half circle) per pixel.
    pub slice_count: u32,
    /// Depth samples taken on each side of the pixel along a slice.
    pub steps_per_side: u32,
    /// Divide the visible arcs by the same slices' unoccluded arcs instead of by the slice count.
    /// A slice's unoccluded integral depends on its angle to the normal, so with few slices the
    /// plain average is noisy even on open ground; the ratio is exactly 1 there and converges to
    /// the same value as more slices are taken.
    pub normalize_slices: bool,
    /// The GTAO paper's thickness heuristic: how far the horizon falls back towards a
    /// sample that lies below it, so that an occluder the march has passed stops counting, as if
    /// objects were about as thick as they are wide. 0 keeps the highest horizon (a height field).
    pub thickness: f32,
}

impl Default for GtaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl GtaoSettings {
    /// Sample counts of a preset.
    ///
    /// ```
    /// use aokit::{GtaoSettings, Preset};
    /// // Steps go to both sides of every slice: the budget is 2 x slices x steps.
    /// let samples = Preset::ALL.map(|p| {
    ///     let g = GtaoSettings::preset(p);
    ///     2 * g.slice_count * g.steps_per_side
    /// });
    /// assert_eq!(samples, [4, 8, 18, 54]);
    /// ```
    pub fn preset(preset: Preset) -> Self {
        let tuned = (SPEC.tuned)(preset);
        let [slice_count, steps_per_side] = tuned.split;
        Self {
            slice_count,
            steps_per_side,
            normalize_slices: true,
            thickness: tuned.knob,
        }
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Gtao,
    shader: shader::GTAO,
    tuned: |preset| match preset {
        Preset::Low => tuned([1, 2], 1.0, 0.0, 0.05, 1.6, 1.1),
        Preset::Medium => tuned([1, 4], 1.75, 0.0, 0.1, 1.25, 1.1),
        Preset::High => tuned([3, 3], 1.25, 0.0, 0.1, 1.25, 1.1),
        Preset::Ultra => tuned([3, 9], 1.0, 0.1, 0.0, 1.1, 0.8),
    },
    knob: Knob::Own("gtao.thickness"),
    samples_per_pixel: |s| 2 * s.gtao.slice_count * s.gtao.steps_per_side,
    max_radius_px,
    kernel_counts: |s, _| KernelCounts {
        thickness: s.gtao.thickness,
        ..KernelCounts::new(s.gtao.slice_count, s.gtao.steps_per_side)
    },
    flags: |s| {
        if s.gtao.normalize_slices {
            flags::NORMALIZE_SLICES
        } else {
            0
        }
    },
    bent_normals: true,
    marches_slices: true,
    depth_mips: None,
    section: "gtao",
    settings: &[
        setting!(
            gtao.slice_count,
            count(),
            "slices (screen directions over a half circle) per pixel"
        ),
        setting!(
            gtao.steps_per_side,
            count(),
            "depth samples on each side of the pixel per slice"
        ),
        setting!(
            gtao.normalize_slices,
            bool,
            "divide by the slices' unoccluded integrals (see \
             [gtao.md](methods/gtao.md#slices-normalised-by-their-unoccluded-integrals))"
        ),
        setting!(
            gtao.thickness,
            unit(),
            "the GTAO paper's thickness heuristic: how far the horizon falls back towards a \
             sample below it"
        ),
    ],
};
