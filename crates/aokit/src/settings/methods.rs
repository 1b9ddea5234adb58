//! Each method's own sampling settings, with the presets' values (`presets.rs`).

use serde::{Deserialize, Serialize};

use super::*;
use crate::presets;

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
            sample_count: presets::samples(preset),
        }
    }
}

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
    /// pair, with the flat-surface bias ([`AoSettings::bias`]) telling creases from ridges.
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
            sample_count: presets::samples(preset) / 2,
            // Our inputs always carry normals (decoded or reconstructed), and the normal
            // version needs no bias to keep planes and ridges unoccluded.
            use_normals: true,
        }
    }
}

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
    /// `5 * 2^(levels - 1)` ([`AoSettings::effective_max_radius_px`]).
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
pub(super) const MSVO_DISC_RADIUS: u32 = 5;

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
        let tuned = presets::preset_values(Method::Msvo, preset);
        Self {
            sample_count: tuned.split[0],
            // Every level at every preset: fewer levels cut the radius, not just the cost
            // (the coarser four add at most a third to the working level's samples).
            levels: MSVO_MAX_LEVELS,
            thickness: tuned.knob,
        }
    }
}

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
        let [direction_count, step_count] = presets::preset_values(Method::Hbao, preset).split;
        Self {
            direction_count,
            step_count,
            // Per pixel, so that every table published before the separable variant stands.
            variant: HbaoVariant::PerPixel,
        }
    }
}

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
        let tuned = presets::preset_values(Method::Gtao, preset);
        let [slice_count, steps_per_side] = tuned.split;
        Self {
            slice_count,
            steps_per_side,
            normalize_slices: true,
            thickness: tuned.knob,
        }
    }
}

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
        let tuned = presets::preset_values(Method::Vbao, preset);
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

/// Most samples, slices, directions or steps a kernel accepts: beyond this the cost is far past
/// any real-time budget and the estimate has long converged.
pub const MAX_SAMPLE_COUNT: u32 = 64;
