//! `vbao`: visibility bitmask AO (Therrien, Levesque and Gilet 2023), occluders of finite
//! thickness marking sectors of each slice; with back faces, thickness measured.

use serde::{Deserialize, Serialize};

use super::{Knob, MethodSpec, max_radius_px};
use crate::presets::{Tuned, tuned};
use crate::settings::{AoSettings, Method, Preset, at_least, count, positive, setting};
use crate::shader;
use crate::uniforms::{KernelCounts, flags};

/// The visibility bitmask method's sampling and occluder thickness.
///
/// ```
/// use aokit::{AoSettings, Method, Preset};
/// // A large outdoor scene: far occluders get thicker, as their depth is less certain.
/// let mut settings = AoSettings::preset(Method::Vbao, Preset::High);
/// settings.vbao.thickness_growth = 0.01;
/// settings.validate()?;
/// settings.vbao.thickness = 0.0;
/// assert_eq!(settings.validate().unwrap_err().field, "vbao.thickness");
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct VbaoSettings {
    /// Slices per pixel, as GTAO's.
    pub slice_count: u32,
    /// Depth samples on each side of the pixel per slice.
    pub steps_per_side: u32,
    /// Thickness of every occluder behind its visible surface, as a fraction of the radius.
    pub thickness: f32,
    /// Extra thickness per unit of the occluder's view depth, so that distant occluders, whose
    /// depth is less certain and whose backs are further from their fronts in screen space, are
    /// thicker: `thickness * radius + thickness_growth * depth`. 0 keeps it constant.
    pub thickness_growth: f32,
    /// Measure each occluder's thickness from [`AoInputs::back_depth`](crate::AoInputs::back_depth),
    /// the depth of the nearest back faces, instead of assuming it: an occluder is then as
    /// thick as the distance from its front face to the back face behind it, or solid where
    /// no back face lies behind it, and never thinner than `thickness` says. Solids (boxes,
    /// spheres, steps) then stop letting light through behind them, while poles and fences
    /// keep their gaps. Needs the renderer to draw its depth a second time with front faces
    /// culled; the pipeline refuses frames without it.
    pub back_faces: bool,
}

impl Default for VbaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl VbaoSettings {
    /// Sample counts of a preset.
    ///
    /// ```
    /// use aokit::{GtaoSettings, Preset, VbaoSettings};
    /// // GTAO's slices and steps, so that the two compare at equal cost.
    /// let vbao = VbaoSettings::preset(Preset::Medium);
    /// let gtao = GtaoSettings::preset(Preset::Medium);
    /// assert_eq!(
    ///     (vbao.slice_count, vbao.steps_per_side),
    ///     (gtao.slice_count, gtao.steps_per_side)
    /// );
    /// // Thick enough that boxes occlude as solids, thin enough for light behind poles.
    /// assert!(vbao.thickness > 0.2 && vbao.thickness < 1.0);
    /// ```
    pub fn preset(preset: Preset) -> Self {
        let tuned = (SPEC.tuned)(preset);
        let [slice_count, steps_per_side] = tuned.split;
        Self {
            slice_count,
            steps_per_side,
            // A fraction of the radius, as tuned (docs/tuning.md); docs/methods/vbao.md shows what
            // thinner and thicker occluders look like.
            thickness: tuned.knob,
            thickness_growth: 0.0,
            back_faces: false,
        }
    }
}

impl AoSettings {
    /// Whether the frame reads back-face depth: `vbao` measuring its occluders.
    pub(crate) fn reads_back_faces(&self) -> bool {
        self.method == Method::Vbao && self.vbao.back_faces
    }
}

/// `vbao`'s values at `preset` with [`VbaoSettings::back_faces`] on, tuned as the others are:
/// its knob is then the least thickness, for occluders whose back faces lie closer than that
/// or were not seen.
pub(crate) fn back_faces_tuned(preset: Preset) -> Tuned {
    match preset {
        Preset::Low => tuned([1, 2], 1.0, 0.0, 0.5, 1.4, 1.2),
        Preset::Medium => tuned([1, 4], 2.0, 0.0, 0.1, 1.25, 1.2),
        Preset::High => tuned([3, 3], 1.5, 0.0, 0.2, 1.1, 1.35),
        Preset::Ultra => tuned([3, 9], 1.75, 0.0, 0.05, 1.0, 1.1),
    }
}

/// `settings`, `vbao` at `preset`, with its back-face values ([`back_faces_tuned`]).
pub(crate) fn with_back_faces(settings: AoSettings, preset: Preset) -> AoSettings {
    let tuned = back_faces_tuned(preset);
    let [slice_count, steps_per_side] = tuned.split;
    AoSettings {
        radius_multiplier: tuned.radius_multiplier,
        falloff: tuned.falloff,
        power: tuned.power,
        step_power: tuned.step_power,
        vbao: VbaoSettings {
            slice_count,
            steps_per_side,
            thickness: tuned.knob,
            back_faces: true,
            ..settings.vbao
        },
        ..settings
    }
}

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Vbao,
    shader: shader::VBAO,
    tuned: |preset| match preset {
        Preset::Low => tuned([1, 2], 1.0, 0.0, 0.75, 1.4, 1.1),
        Preset::Medium => tuned([1, 4], 1.75, 0.0, 0.5, 1.0, 1.2),
        Preset::High => tuned([3, 3], 1.0, 0.0, 0.6, 1.1, 1.1),
        Preset::Ultra => tuned([3, 9], 1.75, 0.0, 0.2, 1.0, 1.1),
    },
    knob: Knob::Own("vbao.thickness"),
    samples_per_pixel: |s| 2 * s.vbao.slice_count * s.vbao.steps_per_side,
    max_radius_px,
    // Thickness in world units at the kernel's radius.
    kernel_counts: |s, radius| KernelCounts {
        thickness: s.vbao.thickness * radius,
        thickness_growth: s.vbao.thickness_growth,
        ..KernelCounts::new(s.vbao.slice_count, s.vbao.steps_per_side)
    },
    flags: |s| {
        if s.vbao.back_faces {
            flags::BACK_FACES
        } else {
            0
        }
    },
    bent_normals: true,
    marches_slices: true,
    depth_mips: None,
    section: "vbao",
    settings: &[
        setting!(vbao.slice_count, count(), "slices per pixel"),
        setting!(
            vbao.steps_per_side,
            count(),
            "depth samples on each side per slice"
        ),
        setting!(
            vbao.thickness,
            positive(),
            "thickness of every occluder, as a fraction of the radius"
        ),
        setting!(
            vbao.thickness_growth,
            at_least(0.0),
            "extra thickness per unit of the occluder's view depth"
        ),
        setting!(
            vbao.back_faces,
            bool,
            "measure each occluder's thickness from `AoInputs::back_depth` (the depth of the \
             back faces; `aokit ao --back-depth`), `vbao.thickness` then being the least \
             thickness; turning it on in `--set` or a settings file starts from VBAO's presets \
             tuned with back faces (`AoSettings::preset_with_back_faces`, \
             [methods/vbao.md](methods/vbao.md#measured-thickness-vbaoback_faces))"
        ),
    ],
};
