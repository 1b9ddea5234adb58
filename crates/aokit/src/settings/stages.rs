//! Settings of the stages around the AO kernel: normal input, noise, and the spatial and
//! temporal filters.

use serde::{Deserialize, Serialize};

use super::*;

/// Normal storage and source.
///
/// ```
/// use aokit::{AoSettings, NormalEncoding, NormalsSettings};
/// // A renderer whose G-buffer holds half-float xyz normals: the pipeline decodes them.
/// let settings = AoSettings {
///     normals: NormalsSettings {
///         encoding: NormalEncoding::Rgba16f,
///         ..NormalsSettings::default()
///     },
///     ..AoSettings::default()
/// };
/// assert_eq!(settings.normals.encoding.texture_format(), wgpu::TextureFormat::Rgba16Float);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NormalsSettings {
    /// How the normal texture is encoded.
    pub encoding: NormalEncoding,
    /// Where the normals come from.
    pub source: NormalSource,
    /// The space the normal texture's vectors are in.
    pub space: NormalSpace,
}

/// Sampling noise.
///
/// ```
/// use aokit::{AoSettings, NoiseKind, NoiseSettings};
/// let noise = NoiseSettings { kind: NoiseKind::Blue, blue_size: 128, ..NoiseSettings::default() };
/// let settings = AoSettings { noise, ..AoSettings::default() };
/// settings.validate()?;
/// // Only 64- and 128-pixel tiles are generated.
/// let odd = AoSettings { noise: NoiseSettings { blue_size: 96, ..noise }, ..settings };
/// assert_eq!(odd.validate().unwrap_err().field, "noise.blue_size");
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NoiseSettings {
    /// Which noise.
    pub kind: NoiseKind,
    /// Side of the blue-noise tile, in texels.
    pub blue_size: u32,
    /// How the tiled kinds (`blue`, `bayer`, `white`, `hilbert-r2`) move each frame; `ign` and
    /// `gtao` keep their own schedules.
    pub temporal: TemporalOffset,
}

impl Default for NoiseSettings {
    fn default() -> Self {
        Self {
            kind: NoiseKind::default(),
            // 64x64 tiles are invisible at 1080p and a quarter the memory of 128x128.
            blue_size: 64,
            temporal: TemporalOffset::default(),
        }
    }
}

/// The spatial denoiser: an edge-aware blur of the AO, run after the method kernel: one 3x3
/// pass (the default), a separable bilateral blur or a guided filter
/// ([`SpatialSettings::kind`]). docs/denoise.md has the formulas and the measured errors.
///
/// ```
/// use aokit::{AoSettings, Method, Preset, SpatialKind, SpatialSettings};
/// // The low preset's 4 samples are noisy: the bilateral kind's wider blur, sigma kept at half
/// // the radius.
/// let spatial = SpatialSettings {
///     kind: SpatialKind::Bilateral,
///     radius: 5,
///     sigma: 2.5,
///     ..SpatialSettings::default()
/// };
/// let settings = AoSettings { spatial, ..AoSettings::preset(Method::Gtao, Preset::Low) };
/// settings.validate()?;
/// // The workgroup's tile holds at most 8 pixels on each side.
/// let wide = AoSettings { spatial: SpatialSettings { radius: 9, ..spatial }, ..settings };
/// assert_eq!(wide.validate().unwrap_err().field, "spatial.radius");
/// // The guided filter instead, in 5x5 windows: it has its own radius and regularisation.
/// let guided = SpatialSettings { kind: SpatialKind::Guided, guided_radius: 2, ..spatial };
/// AoSettings { spatial: guided, ..settings }.validate()?;
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SpatialSettings {
    /// Filter the AO. On by default: the error users see is the filtered AO's, and the
    /// presets are tuned with it on (docs/tuning.md). `false` gives the kernel's raw estimate.
    pub enabled: bool,
    /// Which filter runs: one 3x3 edge-aware pass (default), the bilateral blur or the guided
    /// filter.
    pub kind: SpatialKind,
    /// Kernel radius of the bilateral filter in pixels: each pass averages
    /// `2 * radius + 1` pixels.
    pub radius: u32,
    /// Standard deviation of the Gaussian spatial weight, in pixels.
    pub sigma: f32,
    /// How depth differences weigh neighbours.
    pub depth_weight: DepthWeight,
    /// Relative depth difference `|d - d0| / d0` the depth weight is scaled by: the Gaussian's
    /// standard deviation, or the threshold above which a neighbour is rejected. Relative, so
    /// one value separates surfaces near and far alike.
    pub depth_sigma: f32,
    /// Exponent of the normal weight `max(0, n . n0)^normal_power`; 0 turns the normal weight
    /// off (and its normal loads with it).
    pub normal_power: f32,
    /// The edges kind reads the AO and the linear depth from one texture into which the
    /// method's kernel packs them (a 32-bit texel: the AO to 1/1023, the depth to 1.3e-4 of
    /// itself): four gathers a pixel where the two textures take eight. The kernel writes its
    /// AO as well, unchanged. Applies where the filter runs on a per-pixel kernel's output at
    /// its resolution (not with MSVO, the separable HBAO or `filter_resolution = full`).
    pub packed_input: bool,
    /// Window radius of the guided filter in pixels: it fits AO against depth in
    /// windows of `(2 guided_radius + 1)^2` pixels, and each pixel averages the fits of the
    /// windows that hold it, so its AO mixes pixels up to `2 guided_radius` away.
    pub guided_radius: u32,
    /// The guided filter's regularisation `epsilon` (He, Sun and Tang's): the variance of the
    /// guide, the natural log of linear depth, below which a window is smoothed flat rather
    /// than its AO fitted against depth. Log-depth differences are relative depth differences,
    /// so `sqrt(guided_epsilon)` is a relative depth spread, at any distance: 1e-6 is 0.1%.
    /// Larger blurs across more depth change; below the default, nothing changes measurably.
    pub guided_epsilon: f32,
}

/// The temporal denoiser: each frame's AO blended with its reprojected history (docs/denoise.md).
///
/// ```
/// use aokit::{AoSettings, TemporalSettings};
/// // A fixed camera (a menu backdrop): the history always lines up, so a longer one only
/// // removes more noise, about ten frames' worth.
/// let temporal = TemporalSettings { enabled: true, blend: 0.9, ..TemporalSettings::default() };
/// let settings = AoSettings { temporal, ..AoSettings::default() };
/// settings.validate()?;
/// // A blend of 1 would keep the first frame forever.
/// let frozen = AoSettings { temporal: TemporalSettings { blend: 1.0, ..temporal }, ..settings };
/// assert_eq!(frozen.validate().unwrap_err().field, "temporal.blend");
/// # Ok::<(), aokit::SettingsError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TemporalSettings {
    /// Filter over frames. Off by default: a single frame has no history to blend. Turn it on
    /// where frames follow each other (`aokit render --frames N` and the viewer do).
    pub enabled: bool,
    /// Weight of the history: the noise averages over about `1 / (1 - blend)`
    /// frames, and a change takes as long to show fully.
    pub blend: f32,
    /// History is clipped to the mean of the pixel's 3x3 same-surface neighbours plus or minus
    /// this many of their standard deviations: smaller rejects stale history sooner (less
    /// trailing), larger keeps more of it (less flicker).
    pub variance_gamma: f32,
    /// Relative depth difference above which the reprojected history shows another surface
    /// and is not used (a disocclusion).
    pub depth_threshold: f32,
    /// Blend the mean of the pixel's 3x3 same-surface neighbours instead of its own value
    /// (the depth-aware filtered current value of ybniaobu's Unity YPipeline, its SSAO temporal
    /// filter): less noise where the history is rejected, but a blur of contact shadows everywhere,
    /// and more error on a still camera (docs/denoise.md).
    pub filter_current: bool,
}

impl Default for TemporalSettings {
    fn default() -> Self {
        Self {
            enabled: false,
            // Five frames' worth of history (1 / (1 - 0.8)), a twelfth of a second at 60 Hz: at
            // 0.9 the history's resampling blur and its older viewpoints cost more accuracy
            // under camera motion than the extra averaging gains (docs/denoise.md).
            blend: 0.8,
            // One standard deviation: the usual clip box of temporal filters.
            variance_gamma: 1.0,
            // 5%: wider than a grazing plane changes between neighbouring texels at 60 degrees
            // field of view, narrower than the gap between an object and what lies behind it.
            depth_threshold: 0.05,
            filter_current: false,
        }
    }
}

/// Largest [`SpatialSettings::radius`]: the filter's workgroup tile holds the row or column
/// segment of its 64 threads plus this many pixels on each side, and the guided filter's tile
/// the 8x8 block of its threads plus as many on each side (24x24 texels, 9 KiB of the 16 KiB
/// of workgroup memory WebGPU guarantees). Bounds `radius` and `guided_radius` alike.
pub const MAX_SPATIAL_RADIUS: u32 = 8;

impl Default for SpatialSettings {
    fn default() -> Self {
        // Each value scores within 0.0002 of the best mean RMSE measured for GTAO and HBAO at
        // `high` on room, stairs, thin and two Sponza cameras (docs/denoise.md has the sweep).
        Self {
            // On: single frames need it, and the presets are tuned with it (see `enabled`).
            enabled: true,
            // 7 taps per pass: wider kernels smear real AO detail more than they remove noise.
            radius: 3,
            // Half the radius, so the kernel is cut off at two standard deviations.
            sigma: 1.5,
            // The threshold scores the same; the Gaussian fades instead of switching at one value.
            depth_weight: DepthWeight::Gaussian,
            // 2% of the depth: 0.01 to 0.02 score best; wider lets more through depth steps.
            depth_sigma: 0.02,
            // Halves a neighbour's weight at 17 degrees: most of the gain of 64, milder on
            // normals with fine detail.
            normal_power: 16.0,
            // The same error (the packing's rounding changes GTAO `high`'s RMSE by under
            // 1e-4) in fewer reads (docs/denoise.md#edges-kind).
            packed_input: true,
            // The bilateral kind's error (within 0.0002 at `high`) in 0.70 to 0.80 of its time
            // on an H200, in one pass (docs/denoise.md#edges-kind).
            kind: SpatialKind::Edges,
            // 3x3 windows: larger ones blur creases, where depth is continuous and AO is not,
            // more than they remove noise (1 to 3% more RMSE at 2, 3 to 6% at 3).
            guided_radius: 1,
            // The best measured for both methods, and 1e-5 to 1e-8 agree within 0.0002: a
            // window is fitted against depth unless its depth varies by less than 0.1%.
            guided_epsilon: 1e-6,
        }
    }
}
