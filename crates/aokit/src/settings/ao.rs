//! [`AoSettings`]: every setting in one value, its presets and the costs derived from them.

use serde::{Deserialize, Serialize};

use super::*;
use crate::methods::{self, Knob};
use crate::presets;

/// Everything that shapes the AO a pipeline produces.
///
/// ```
/// use aokit::{AoSettings, Method, Preset};
/// let mut settings = AoSettings::preset(Method::Gtao, Preset::Medium);
/// settings.radius = 0.5;
/// settings.validate().unwrap();
/// settings.gtao.slice_count = 0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AoSettings {
    /// Which method runs.
    pub method: Method,
    /// World-space radius of the occlusion hemisphere.
    pub radius: f32,
    /// The kernel's radius over `radius`. Screen-space methods see only the depth buffer's
    /// front surfaces and each estimates occlusion its own way, so most under-occlude at the
    /// true radius; sampling a little farther brings their AO closer to the reference traced
    /// at `radius` (XeGTAO ships a multiplier for the same reason). Each preset sets the value
    /// `aokit tune` measured best for its method (docs/tuning.md); 1 samples at `radius`.
    pub radius_multiplier: f32,
    /// Fraction of the radius, at its outer end, over which a sample's influence fades to zero;
    /// 0 cuts off hard at the radius.
    pub falloff: f32,
    /// Scales occlusion: `ao = 1 - intensity * (1 - visibility)`, before `power`.
    pub intensity: f32,
    /// Exponent applied last: values above 1 darken and add contrast.
    pub power: f32,
    /// Largest screen radius in pixels of the input, whatever the working resolution: near the
    /// camera the world radius covers much of the screen, where samples spread thin and leave
    /// the cache (Max Radius Pixels of the Unity Asset Store package "Horizon Based Ambient
    /// Occlusion"). The separable HBAO variant may stop it sooner
    /// ([`AoSettings::effective_max_radius_px`]).
    pub max_radius_px: f32,
    /// Smallest screen radius in pixels of the input: where the world radius covers fewer
    /// pixels (far away), it is widened to this many, so distant geometry keeps a visible
    /// contact shadow instead of fading to nothing. This departs from the world radius (and
    /// so from the reference) on purpose; 0, the default, keeps the world radius, and AO stops
    /// where the radius falls under one pixel.
    pub min_radius_px: f32,
    /// Self-occlusion bias of the point-sampling methods, as a fraction of the radius: a sample
    /// must lie this far behind the depth buffer to count as occluded. For `ue4-ssao`'s
    /// depth-only version, Unreal's flat-surface bias: a pair occludes only where its two
    /// samples together lie this far nearer the eye than the pixel.
    pub bias: f32,
    /// Angle bias of the horizon methods, radians: horizons must rise this far above the tangent
    /// plane to occlude, which hides the false occlusion of tessellated curved surfaces.
    pub angle_bias: f32,
    /// How the marching methods (`hbao`, `hbao-plus`, `gtao`, `vbao`) space their steps between
    /// one pixel and the radius: `1 + t^step_power * (radius - 1)` pixels for `t` in [0, 1).
    /// 1 spaces them evenly; 2 (XeGTAO's choice) crowds them near the pixel. Each method's
    /// preset sets the spacing it measured best with.
    pub step_power: f32,
    /// View depth beyond which there is no AO (Max Distance of the Unity Asset Store package
    /// "Horizon Based Ambient Occlusion"); 0: no limit.
    pub max_distance: f32,
    /// World distance before `max_distance` over which AO fades out (Distance Falloff of the
    /// same package); 0 stops it hard.
    pub distance_falloff: f32,
    /// Also output bent normals (the mean unoccluded direction), for GTSO specular occlusion and
    /// bent-normal lighting. Only the slice-based methods, `gtao` and `vbao`, compute them.
    pub bent_normals: bool,
    /// `ssao-crytek` sampling.
    pub ssao_crytek: SsaoSettings,
    /// `ssao` sampling.
    pub ssao: SsaoSettings,
    /// `hbao` and `hbao-plus` sampling.
    pub hbao: HbaoSettings,
    /// `gtao` sampling and thickness.
    pub gtao: GtaoSettings,
    /// `vbao` sampling and thickness.
    pub vbao: VbaoSettings,
    /// `sao` taps on its spiral.
    pub sao: SsaoSettings,
    /// `ue4-ssao` sample pairs and version.
    pub ue4_ssao: Ue4SsaoSettings,
    /// `msvo` sample pairs, levels and thickness.
    pub msvo: MsvoSettings,
    /// Normal encoding and source.
    pub normals: NormalsSettings,
    /// Sampling noise.
    pub noise: NoiseSettings,
    /// The spatial denoiser.
    pub spatial: SpatialSettings,
    /// The temporal denoiser.
    pub temporal: TemporalSettings,
    /// Resolution of the AO kernel.
    pub resolution: Resolution,
    /// How depth and normals are reduced to the working resolution.
    pub downsample: Downsample,
    /// How the AO returns to full resolution.
    pub upsample: Upsample,
    /// Relative depth difference `|d - d0| / d0` below which a working texel counts as showing
    /// the same surface as a full-resolution pixel in the upsample.
    pub upsample_threshold: f32,
    /// Where the filters run below full resolution.
    pub filter_resolution: FilterResolution,
    /// Whether the marching and point kernels read far samples from a depth MIP chain, and
    /// its precision.
    pub depth_mips: DepthMips,
    /// With [`AoSettings::depth_mips`] on, in log2 pixels: a sample `d` pixels from the shaded
    /// pixel reads level `floor(log2(d) - depth_mip_offset)`, clamped to the levels there are
    /// (XeGTAO's `depthMIPSamplingOffset`, which rounds where this floors). Larger keeps more
    /// samples at full resolution; 16 keeps all of them.
    pub depth_mip_offset: f32,
    /// How the slice methods' samples read the depth where they land.
    pub sample_depth: SampleDepth,
    /// How the slice methods march their slices: lean or general, the same AO at different
    /// cost.
    pub slice_march: SliceMarch,
}

impl Default for AoSettings {
    fn default() -> Self {
        Self::preset(Method::default(), Preset::default())
    }
}

impl AoSettings {
    /// A method at a preset quality, with a radius of 1 world unit. Every method's own sampling
    /// is set to the preset, so switching `method` later keeps the quality level.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset};
    /// // A scene modelled in centimetres: a 1 m radius is 100 units.
    /// let mut settings =
    ///     AoSettings { radius: 100.0, ..AoSettings::preset(Method::Gtao, Preset::Low) };
    /// // Every method's sampling is at the preset: another method costs the same.
    /// settings.method = Method::Hbao;
    /// assert_eq!(settings.samples_per_pixel(), 4);
    /// ```
    pub fn preset(method: Method, preset: Preset) -> Self {
        // The method's tuned values (docs/tuning.md). The bias and angle bias of the methods
        // not chosen come from their own rows, so that switching `method` later keeps them.
        let tuned = presets::preset_values(method, preset);
        let knob = |knob: Knob, otherwise: Method| {
            let owner = if methods::spec(method).knob == knob {
                method
            } else {
                otherwise
            };
            presets::preset_values(owner, preset).knob
        };
        Self {
            method,
            radius: 1.0,
            radius_multiplier: tuned.radius_multiplier,
            falloff: tuned.falloff,
            intensity: 1.0,
            power: tuned.power,
            // Past 256 pixels (a quarter of a 1080p screen) AO no longer reads as contact
            // shadowing, and samples that far apart miss the texture cache.
            max_radius_px: 256.0,
            min_radius_px: 0.0,
            bias: knob(Knob::Bias, Method::Ssao),
            angle_bias: knob(Knob::AngleBias, Method::Hbao),
            step_power: tuned.step_power,
            max_distance: 0.0,
            distance_falloff: 0.0,
            bent_normals: false,
            ssao_crytek: SsaoSettings::preset(preset),
            ssao: SsaoSettings::preset(preset),
            hbao: HbaoSettings::preset(preset),
            gtao: GtaoSettings::preset(preset),
            vbao: VbaoSettings::preset(preset),
            sao: SsaoSettings::preset(preset),
            ue4_ssao: Ue4SsaoSettings::preset(preset),
            msvo: MsvoSettings::preset(preset),
            normals: NormalsSettings::default(),
            noise: NoiseSettings::default(),
            spatial: SpatialSettings::default(),
            temporal: TemporalSettings::default(),
            // Full, so that every table published before lower resolutions existed stands.
            resolution: Resolution::Full,
            downsample: Downsample::default(),
            upsample: Upsample::default(),
            // The 5% of ybniaobu's Unity YPipeline: wider than a plane's depth changes between
            // neighbouring texels unless seen near grazing, narrower than most gaps between
            // objects.
            upsample_threshold: 0.05,
            filter_resolution: FilterResolution::default(),
            depth_mips: DepthMips::Off,
            // The lowest offset at which no measured configuration's error rises by more than
            // 0.001 (docs/depth-mips.md).
            depth_mip_offset: 3.0,
            sample_depth: SampleDepth::default(),
            slice_march: SliceMarch::default(),
        }
    }

    /// [`AoSettings::preset`], for a renderer that hands in
    /// [`AoInputs::back_depth`](crate::AoInputs::back_depth): `vbao` then measures its
    /// occluders ([`VbaoSettings::back_faces`] on) with the values tuned for that, whose
    /// `vbao.thickness` is only the least an occluder gets and so lies well below the
    /// assumed thickness of [`AoSettings::preset`] (docs/tuning.md). The other methods do not
    /// read back faces and get [`AoSettings::preset`].
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset};
    /// let measured = AoSettings::preset_with_back_faces(Method::Vbao, Preset::High);
    /// assert!(measured.vbao.back_faces);
    /// // Solids take their thickness from the back faces: the floor is for poles and fences.
    /// let assumed = AoSettings::preset(Method::Vbao, Preset::High);
    /// assert!(measured.vbao.thickness < assumed.vbao.thickness);
    /// assert_eq!(measured.samples_per_pixel(), assumed.samples_per_pixel());
    /// assert_eq!(
    ///     AoSettings::preset_with_back_faces(Method::Gtao, Preset::High),
    ///     AoSettings::preset(Method::Gtao, Preset::High)
    /// );
    /// ```
    pub fn preset_with_back_faces(method: Method, preset: Preset) -> Self {
        let settings = Self::preset(method, preset);
        if method != Method::Vbao {
            return settings;
        }
        methods::with_back_faces(settings, preset)
    }

    /// Depth samples the AO kernel takes per pixel: the cost that does not depend on the GPU.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset};
    /// // Every method gets the same budget at a preset, so they compare at equal cost.
    /// let gtao = AoSettings::preset(Method::Gtao, Preset::High);
    /// let ssao = AoSettings::preset(Method::Ssao, Preset::High);
    /// assert_eq!(gtao.samples_per_pixel(), ssao.samples_per_pixel());
    /// // GTAO: 2 sides x 3 slices x 3 steps.
    /// assert_eq!(gtao.samples_per_pixel(), 18);
    /// ```
    pub fn samples_per_pixel(&self) -> u32 {
        (methods::spec(self.method).samples_per_pixel)(self)
    }

    /// The largest screen radius the kernel uses, in pixels of the input: [`max_radius_px`],
    /// or less with the separable HBAO variant, whose samples must stay inside its workgroup's
    /// apron of [`SEPARABLE_HBAO_MAX_RADIUS_PX`] working texels. A pixel whose radius would
    /// reach farther works with the world radius that covers this many pixels, and
    /// [`min_radius_px`] cannot widen past it. `msvo` stops at its coarsest level's disc,
    /// `5 * 2^(msvo.levels - 1)` working texels.
    ///
    /// [`max_radius_px`]: AoSettings::max_radius_px
    /// [`min_radius_px`]: AoSettings::min_radius_px
    ///
    /// ```
    /// use aokit::{AoSettings, HbaoVariant, Method, Preset, Resolution};
    /// // A settings panel shows the limit that applies, not only the one asked for.
    /// let mut settings = AoSettings::preset(Method::Hbao, Preset::High);
    /// assert_eq!(settings.effective_max_radius_px(), 256.0);
    /// settings.hbao.variant = HbaoVariant::Separable;
    /// assert_eq!(settings.effective_max_radius_px(), 128.0);
    /// // A quarter-resolution texel covers 4 pixels: the apron reaches 512, past the setting.
    /// settings.resolution = Resolution::Quarter;
    /// assert_eq!(settings.effective_max_radius_px(), 256.0);
    /// ```
    pub fn effective_max_radius_px(&self) -> f32 {
        (methods::spec(self.method).max_radius_px)(self)
    }
}
