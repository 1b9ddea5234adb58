//! Typed AO settings with named presets and validation.
//!
//! Everything a user can tune lives in one [`AoSettings`] value. It serialises with serde, so the
//! CLI reaches every field by its dotted path (`gtao.slice_count`) and TOML files hold any subset.

use serde::{Deserialize, Serialize};

use crate::presets;

/// An enum of settings values with the names the CLI and settings files use: `ALL`, `name()`,
/// `FromStr` (an error lists the names on offer) and serde by the same names.
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        pub enum $name:ident ($what:literal) {
            $($(#[$variant_meta:meta])* $variant:ident = $text:literal,)+
        }
    ) => {
        $(#[$meta])*
        #[derive(
            Clone,
            Copy,
            Debug,
            Default,
            PartialEq,
            Eq,
            Hash,
            serde::Serialize,
            serde::Deserialize,
        )]
        pub enum $name {
            $($(#[$variant_meta])* #[serde(rename = $text)] $variant,)+
        }

        impl $name {
            /// Every value, in the order help texts list them.
            pub const ALL: [$name; [$($text),+].len()] = [$($name::$variant),+];

            /// The name used on the command line and in settings files.
            ///
            #[doc = concat!("```\nuse aokit::", stringify!($name), ";\n")]
            /// // Every value reads back from its name, as `--set` and settings files give it.
            #[doc = concat!("for value in ", stringify!($name), "::ALL {")]
            #[doc = concat!("    assert_eq!(value.name().parse::<", stringify!($name), ">(), Ok(value));")]
            /// }
            /// ```
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)+
                }
            }
        }

        impl std::str::FromStr for $name {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                $crate::settings::find_by_name(&$name::ALL, $name::name, $what, s)
            }
        }
    };
}
pub(crate) use named_enum;

named_enum! {
    /// The AO method a pipeline runs. docs/methods/ has each one's formula and failure modes.
    ///
    /// ```
    /// use aokit::{AoSettings, Method};
    /// // `--method hbao-plus` on the command line, `method = "hbao-plus"` in a settings file.
    /// let method: Method = "hbao-plus".parse()?;
    /// let settings = AoSettings { method, ..AoSettings::default() };
    /// assert_eq!(settings.method, Method::HbaoPlus);
    /// // A typo is answered with the names on offer.
    /// let err = "gtoa".parse::<Method>().unwrap_err();
    /// assert!(err.contains("ssao-crytek, ssao, hbao, hbao-plus, gtao, vbao"), "{err}");
    /// # Ok::<(), String>(())
    /// ```
    pub enum Method ("method") {
        /// Crytek's 2007 SSAO: points in a sphere around the pixel tested against the depth
        /// buffer.
        SsaoCrytek = "ssao-crytek",
        /// Normal-oriented hemisphere SSAO: cosine-weighted points tested against the depth
        /// buffer.
        Ssao = "ssao",
        /// Horizon-based AO (Bavoil and Sainz 2008): per screen direction, the rise of the
        /// horizon above the tangent plane.
        Hbao = "hbao",
        /// HBAO+'s normal-based estimator: each sample occludes by its elevation above the
        /// tangent plane.
        HbaoPlus = "hbao-plus",
        /// Ground-truth based AO (Jimenez et al. 2016): cosine-weighted horizon integral per
        /// slice.
        #[default]
        Gtao = "gtao",
        /// Visibility bitmask AO (Therrien, Levesque and Gilet 2023): occluders of finite
        /// thickness mark sectors of each slice.
        Vbao = "vbao",
        /// Scalable Ambient Obscurance (McGuire, Mara and Luebke 2012): taps on a spiral read
        /// from a depth MIP level chosen by their distance, scored by the paper's obscurance
        /// estimator.
        Sao = "sao",
        /// Unreal Engine 4's legacy SSAO (PostProcessAmbientOcclusion.usf, Epic Games): sample
        /// pairs mirrored about the pixel, occlusion from the angle between each pair, read from a
        /// furthest-depth MIP chain.
        Ue4Ssao = "ue4-ssao",
        /// Multi-scale volumetric obscurance (Microsoft MiniEngine's SSAO, Unity
        /// PostProcessing's MSVO): the fraction of a sphere in front of the depth buffer,
        /// from mirrored sample pairs at each level of a depth MIP chain, the levels merged
        /// by a depth-aware upsample.
        Msvo = "msvo",
    }
}

impl Method {
    /// Whether the method integrates over slices and so can return bent normals.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset};
    /// let mut settings = AoSettings::preset(Method::Hbao, Preset::High);
    /// // Ask for bent normals only where the method computes them: elsewhere validation fails.
    /// settings.bent_normals = settings.method.has_bent_normals();
    /// settings.validate().unwrap();
    /// assert!(!settings.bent_normals);
    /// let slice_methods: Vec<Method> =
    ///     Method::ALL.into_iter().filter(|m| m.has_bent_normals()).collect();
    /// assert_eq!(slice_methods, [Method::Gtao, Method::Vbao]);
    /// ```
    pub fn has_bent_normals(self) -> bool {
        matches!(self, Method::Gtao | Method::Vbao)
    }

    /// Whether the method's samples lie in slices (half-planes through the view vector), which
    /// is what lets them read the nearest texel ([`AoSettings::sample_depth`]): the others read
    /// theirs one way only.
    ///
    /// ```
    /// use aokit::Method;
    /// let marching: Vec<Method> =
    ///     Method::ALL.into_iter().filter(|m| m.marches_slices()).collect();
    /// assert_eq!(marching, [Method::Hbao, Method::HbaoPlus, Method::Gtao, Method::Vbao]);
    /// ```
    pub fn marches_slices(self) -> bool {
        matches!(
            self,
            Method::Hbao | Method::HbaoPlus | Method::Gtao | Method::Vbao
        )
    }

    /// Whether the method's kernel reads a depth MIP chain, which the pipeline then builds
    /// from the working linear depth each frame (and otherwise never makes): `sao`'s keeps one
    /// depth of every 2x2 block (and `msvo`'s, whose levels are its scales), `ue4-ssao`'s the
    /// furthest.
    ///
    /// ```
    /// use aokit::Method;
    /// // Budget the chain's memory (a third more than the depth) only where it is built.
    /// let with_chain: Vec<Method> =
    ///     Method::ALL.into_iter().filter(|m| m.reads_depth_mips()).collect();
    /// assert_eq!(with_chain, [Method::Sao, Method::Ue4Ssao, Method::Msvo]);
    /// ```
    pub fn reads_depth_mips(self) -> bool {
        matches!(self, Method::Sao | Method::Ue4Ssao | Method::Msvo)
    }
}

named_enum! {
    /// Quality levels, from cheapest to most accurate.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset};
    /// // A quality menu, cheapest first, with what each entry costs.
    /// let costs = Preset::ALL.map(|p| AoSettings::preset(Method::Gtao, p).samples_per_pixel());
    /// assert_eq!(costs, [4, 8, 18, 54]);
    /// for (preset, samples) in Preset::ALL.iter().zip(costs) {
    ///     println!("{:>6}: {samples} depth samples per pixel", preset.name());
    /// }
    /// assert_eq!("ultra".parse::<Preset>(), Ok(Preset::Ultra));
    /// ```
    pub enum Preset ("preset") {
        /// Fewest samples: for low-end GPUs.
        Low = "low",
        /// A balance for mid-range GPUs.
        Medium = "medium",
        /// The default.
        #[default]
        High = "high",
        /// Many samples, for stills and comparisons.
        Ultra = "ultra",
    }
}

named_enum! {
    /// How a normal texture stores view-space unit normals: what the pipeline decodes from
    /// [`AoInputs::normals`](crate::AoInputs::normals), and what the scene renderer writes into
    /// its G-buffer. docs/normals.md has each one's texture format and measured error.
    ///
    /// ```
    /// use aokit::NormalEncoding;
    /// let encoding: NormalEncoding = "oct24".parse()?;
    /// assert_eq!(encoding.texture_format(), wgpu::TextureFormat::Rgba8Unorm);
    /// // The texture's format does not tell the encodings apart: five share `R32Uint`, so the
    /// // settings must name the one the renderer writes.
    /// let in_r32: Vec<&str> = NormalEncoding::ALL
    ///     .into_iter()
    ///     .filter(|e| e.texture_format() == wgpu::TextureFormat::R32Uint)
    ///     .map(|e| e.name())
    ///     .collect();
    /// assert_eq!(in_r32, ["oct32", "xy", "spherical", "stereographic", "lambert"]);
    /// # Ok::<(), String>(())
    /// ```
    pub enum NormalEncoding ("normal encoding") {
        /// Octahedral, two 16-bit unorms packed in an `R32Uint` texel.
        #[default]
        Oct32 = "oct32",
        /// Octahedral, 12 bits per coordinate packed in the RGB of an `Rgba8Unorm` texel (the
        /// packing of Unity's `PackFloat2To888`, Scriptable Render Pipeline Core library).
        Oct24 = "oct24",
        /// Octahedral, 8 bits per coordinate in an `Rg8Unorm` texel.
        Oct16 = "oct16",
        /// Octahedral, 10 bits per coordinate in the first two channels of `Rgb10a2Unorm`.
        Oct20 = "oct20",
        /// Plain xyz, 10 bits each, in `Rgb10a2Unorm`.
        Rgb10a2 = "rgb10a2",
        /// Plain xyz in half floats, `Rgba16Float`.
        Rgba16f = "rgba16f",
        /// x and y only, z reconstructed as facing the eye, two 16-bit snorms in `R32Uint`.
        Xy = "xy",
        /// Spherical angles, two 16-bit unorms in `R32Uint`.
        Spherical = "spherical",
        /// Stereographic projection, two 16-bit unorms in `R32Uint`.
        Stereographic = "stereographic",
        /// Lambert azimuthal equal-area projection, two 16-bit unorms in `R32Uint`.
        Lambert = "lambert",
    }
}

named_enum! {
    /// Where the AO kernels' normals come from.
    ///
    /// ```
    /// use aokit::{AoSettings, NormalSource};
    /// // Compare the G-buffer's normals with the best reconstruction from depth without
    /// // touching the renderer: the normal texture it passes is checked but not read.
    /// let mut settings = AoSettings::default();
    /// settings.normals.source = "depth-5tap".parse()?;
    /// assert_eq!(settings.normals.source, NormalSource::Depth5tap);
    /// # Ok::<(), String>(())
    /// ```
    pub enum NormalSource ("normal source") {
        /// The normal texture given in the inputs; without one, the best reconstruction from
        /// depth (`depth-5tap`).
        #[default]
        Buffer = "buffer",
        /// From depth: the cross product of the right and lower neighbours' offsets.
        DepthNaive = "depth-naive",
        /// From depth: per axis, the neighbour with the smaller depth difference (the improved
        /// method of Turánszki 2019, "Improved normal reconstruction from depth", Wicked Engine).
        Depth3tap = "depth-3tap",
        /// From depth: per axis, the side whose two samples extrapolate the centre best (the
        /// accurate method).
        Depth5tap = "depth-5tap",
    }
}

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

named_enum! {
    /// The space of the normals a renderer hands in. World-space normals are turned into view
    /// space with [`AoInputs::view_from_world`](crate::AoInputs::view_from_world) by the decode
    /// pass, which then runs for every encoding, oct32 included.
    ///
    /// ```
    /// use aokit::NormalSpace;
    /// assert_eq!("world".parse::<NormalSpace>(), Ok(NormalSpace::World));
    /// assert_eq!(NormalSpace::default(), NormalSpace::View);
    /// ```
    pub enum NormalSpace ("normal space") {
        /// View space: x right, y up, the camera looking down -Z.
        #[default]
        View = "view",
        /// World space.
        World = "world",
    }
}

named_enum! {
    /// The per-pixel noise that rotates and jitters every method's samples. docs/noise.md has
    /// each one's spectrum and the error it leaves.
    ///
    /// ```
    /// use aokit::{AoSettings, NoiseKind};
    /// // One setting per noise for a side-by-side comparison, named as the CLI names them.
    /// let runs: Vec<(String, AoSettings)> = NoiseKind::ALL
    ///     .into_iter()
    ///     .map(|kind| {
    ///         let mut settings = AoSettings::default();
    ///         settings.noise.kind = kind;
    ///         (format!("ao-{}.png", kind.name()), settings)
    ///     })
    ///     .collect();
    /// assert_eq!(runs[0].0, "ao-ign.png");
    /// assert_eq!("blue".parse::<NoiseKind>(), Ok(NoiseKind::Blue));
    /// ```
    pub enum NoiseKind ("noise kind") {
        /// Interleaved gradient noise (Jimenez 2014).
        #[default]
        Ign = "ign",
        /// Blue noise made in the project by void-and-cluster (Ulichney 1993), tiled, moved
        /// each frame by `noise.temporal`.
        Blue = "blue",
        /// GTAO's 4x4 spatial pattern with the paper's 6 rotations and 4 offsets over frames.
        Gtao = "gtao",
        /// A 4x4 Bayer dither matrix (the Dither noise of the Unity Asset Store package "Horizon
        /// Based Ambient Occlusion").
        Bayer = "bayer",
        /// White noise from a Mersenne Twister in a 4x4 texture (the Spatial Distribution noise
        /// of the Unity Asset Store package "Horizon Based Ambient Occlusion").
        White = "white",
        /// The pixel's index along a Hilbert curve driving the R2 sequence.
        HilbertR2 = "hilbert-r2",
    }
}

named_enum! {
    /// How tiled noise moves from frame to frame.
    ///
    /// ```
    /// use aokit::{AoSettings, NoiseKind, TemporalOffset};
    /// let mut settings = AoSettings::default();
    /// settings.noise.kind = NoiseKind::Blue;
    /// // Offset the two noise values by different amounts each frame, rather than by the same
    /// // golden-ratio step.
    /// settings.noise.temporal = "r2".parse()?;
    /// assert_eq!(settings.noise.temporal, TemporalOffset::R2);
    /// # Ok::<(), String>(())
    /// ```
    pub enum TemporalOffset ("temporal offset") {
        /// Adds the frame index times the golden ratio's fraction to each value.
        #[default]
        GoldenRatio = "golden-ratio",
        /// Adds the R2 sequence's frame-th point to the two values.
        R2 = "r2",
    }
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
    /// Side of the blue-noise tile: 64 or 128.
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

named_enum! {
    /// How the spatial filter weighs a neighbour by its depth difference from the centre.
    ///
    /// ```
    /// use aokit::{AoSettings, DepthWeight};
    /// let mut settings = AoSettings::default();
    /// settings.spatial.enabled = true;
    /// // One compare per tap instead of an `exp`, for a GPU short of arithmetic.
    /// settings.spatial.depth_weight = "threshold".parse()?;
    /// assert_eq!(settings.spatial.depth_weight, DepthWeight::Threshold);
    /// # Ok::<(), String>(())
    /// ```
    pub enum DepthWeight ("depth weight") {
        /// A Gaussian of the relative depth difference: neighbours fade out smoothly.
        #[default]
        Gaussian = "gaussian",
        /// All or nothing: a neighbour counts fully while its relative depth difference is
        /// below `depth_sigma`, not at all above (NVIDIA's HBAO blur; one compare, no `exp`).
        Threshold = "threshold",
    }
}

named_enum! {
    /// Which edge-aware filter the spatial denoiser runs (docs/denoise.md compares them).
    ///
    /// ```
    /// use aokit::{AoSettings, SpatialKind};
    /// let mut settings = AoSettings::default();
    /// settings.spatial.enabled = true;
    /// // `--set spatial.kind=guided` on the command line.
    /// settings.spatial.kind = "guided".parse()?;
    /// assert_eq!(settings.spatial.kind, SpatialKind::Guided);
    /// # Ok::<(), String>(())
    /// ```
    pub enum SpatialKind ("spatial filter kind") {
        /// The separable bilateral blur: weights from pixel distance, relative depth difference
        /// and normals (`radius`, `sigma`, `depth_weight`, `depth_sigma`, `normal_power`).
        #[default]
        Bilateral = "bilateral",
        /// He, Sun and Tang's guided filter with the log of linear depth as the guide: a
        /// linear model of AO against depth in every `(2 guided_radius + 1)^2` window
        /// (`guided_radius`, `guided_epsilon`).
        Guided = "guided",
        /// One pass over each pixel's 3x3 neighbourhood with the bilateral kind's weights
        /// (`sigma`, `depth_weight`, `depth_sigma`, `normal_power`; `radius` does not apply):
        /// the shape of XeGTAO's denoiser, nine texels a pixel and no workgroup tile.
        Edges = "edges",
    }
}

/// The spatial denoiser: an edge-aware blur of the AO, run after the method kernel, either a
/// separable bilateral blur or a guided filter ([`SpatialSettings::kind`]). docs/denoise.md has
/// the formulas and the measured errors.
///
/// ```
/// use aokit::{AoSettings, Method, Preset, SpatialKind, SpatialSettings};
/// // The low preset's 4 samples are noisy: a wider blur, sigma kept at half the radius.
/// let spatial =
///     SpatialSettings { enabled: true, radius: 5, sigma: 2.5, ..SpatialSettings::default() };
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
    /// Filter the AO. Off by default for now: every table published in docs/ scores the raw
    /// AO of the methods, and the defaults must keep reproducing them.
    pub enabled: bool,
    /// Which filter runs: the bilateral blur (default) or the guided filter.
    pub kind: SpatialKind,
    /// Kernel radius of the bilateral filter in pixels, 1..=8: each pass averages
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
    /// Window radius of the guided filter in pixels, 1..=8: it fits AO against depth in
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
    /// Filter over frames. Off by default, like the spatial filter: the published tables score
    /// single frames.
    pub enabled: bool,
    /// Weight of the history in `[0, 1)`: the noise averages over about `1 / (1 - blend)`
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

named_enum! {
    /// The resolution the AO kernel (and, with [`FilterResolution::Working`], the filters) runs
    /// at; the result is upsampled to the input's resolution. docs/denoise.md has the measured
    /// error of each.
    ///
    /// ```
    /// use aokit::{AoSettings, Resolution};
    /// // A `--resolution` flag whose help lists the values.
    /// assert_eq!(Resolution::ALL.map(Resolution::name), ["full", "half", "quarter"]);
    /// let settings = AoSettings { resolution: "half".parse()?, ..AoSettings::default() };
    /// assert_eq!(settings.resolution.working_size([1920, 1080]), [960, 540]);
    /// # Ok::<(), String>(())
    /// ```
    pub enum Resolution ("resolution") {
        /// Every pixel.
        #[default]
        Full = "full",
        /// One texel per 2x2 pixels: a quarter of the kernel's cost.
        Half = "half",
        /// One texel per 4x4 pixels: a sixteenth of the kernel's cost.
        Quarter = "quarter",
    }
}

impl Resolution {
    /// Input pixels per working texel along each axis: 1, 2 or 4.
    ///
    /// ```
    /// use aokit::Resolution;
    /// // The kernel's share of its full-resolution cost, for a budget estimate.
    /// let share = |r: Resolution| 1.0 / (r.scale() * r.scale()) as f32;
    /// assert_eq!(Resolution::ALL.map(share), [1.0, 0.25, 0.0625]);
    /// ```
    pub fn scale(self) -> u32 {
        match self {
            Resolution::Full => 1,
            Resolution::Half => 2,
            Resolution::Quarter => 4,
        }
    }

    /// The working size for an input of `size` pixels: `ceil(size / scale)`, so that the last
    /// texel of an odd size covers the pixels left over.
    ///
    /// ```
    /// use aokit::Resolution;
    /// assert_eq!(Resolution::Quarter.working_size([1920, 1080]), [480, 270]);
    /// // One more pixel needs one more texel, which covers it alone.
    /// assert_eq!(Resolution::Quarter.working_size([1921, 1081]), [481, 271]);
    /// assert_eq!(Resolution::Full.working_size([1921, 1081]), [1921, 1081]);
    /// ```
    pub fn working_size(self, size: [u32; 2]) -> [u32; 2] {
        size.map(|side| side.div_ceil(self.scale()))
    }
}

named_enum! {
    /// Which input pixel of each block a working-resolution texel takes its depth (and that
    /// pixel's normal and motion) from, when [`AoSettings::resolution`] is below full.
    ///
    /// ```
    /// use aokit::{AoSettings, Downsample, Resolution};
    /// // Half resolution keeping each block's nearest surface, so that thin foreground
    /// // objects (railings, foliage) still reach the kernel.
    /// let settings = AoSettings {
    ///     resolution: Resolution::Half,
    ///     downsample: "min".parse()?,
    ///     ..AoSettings::default()
    /// };
    /// assert_eq!(settings.downsample, Downsample::Min);
    /// # Ok::<(), String>(())
    /// ```
    pub enum Downsample ("downsample") {
        /// A fixed pixel: the top-left one of the block's central 2x2 (the choice of ybniaobu's
        /// Unity YPipeline). The default: one load per texel and no lean towards either side of an
        /// edge. `max` and `checkerboard` score lower on average (docs/denoise.md), but `max` by
        /// dropping thin objects whose AO the kernels get wrong, and `checkerboard` at the cost of
        /// a pattern and more flicker.
        #[default]
        Point = "point",
        /// The nearest surface (smallest linear depth).
        Min = "min",
        /// The farthest surface (largest linear depth; a pixel without a surface counts as
        /// farthest of all).
        Max = "max",
        /// `min` and `max` alternating in a checkerboard of working texels (Hennessy, "Mixed
        /// Resolution Rendering in Skylanders: SuperChargers", GDC 2016), so that both sides of an
        /// edge are kept somewhere. The kernels then see a surface that zigzags between
        /// neighbouring texels, and HBAO shows the pattern.
        Checkerboard = "checkerboard",
    }
}

named_enum! {
    /// How working-resolution AO becomes full-resolution AO: each pixel combines the 2x2
    /// working texels around it by their depth's agreement with its own (docs/denoise.md).
    ///
    /// ```
    /// use aokit::{AoSettings, Resolution, Upsample};
    /// // Without the filters the equally weighted upsample scores best.
    /// let settings = AoSettings {
    ///     resolution: Resolution::Half,
    ///     upsample: "bilateral".parse()?,
    ///     ..AoSettings::default()
    /// };
    /// assert_eq!(settings.upsample, Upsample::Bilateral);
    /// assert_eq!(Upsample::default().name(), "bilateral-bilinear");
    /// # Ok::<(), String>(())
    /// ```
    pub enum Upsample ("upsample") {
        /// The texels on the pixel's surface (relative depth difference below
        /// `upsample_threshold`), equally weighted (the final choice of ybniaobu's Unity
        /// YPipeline): the lowest error without filters, blocky once they have removed the noise.
        Bilateral = "bilateral",
        /// The texels on the pixel's surface, bilinearly weighted (Mixed Resolution Rendering's
        /// bilateral upsample with a threshold for its depth weight). The default: the lowest
        /// error with both filters at half resolution, or within 0.0002 of it.
        #[default]
        BilateralBilinear = "bilateral-bilinear",
        /// Bilinear where all four texels lie on the pixel's surface, else the one texel of
        /// nearest depth (NVIDIA's nearest-depth upsample).
        NearestDepth = "nearest-depth",
    }
}

named_enum! {
    /// Where the spatial and temporal filters run when [`AoSettings::resolution`] is below full.
    ///
    /// ```
    /// use aokit::{AoSettings, FilterResolution, Resolution};
    /// // Quarter-resolution AO whose blocks the spatial filter smooths after the upsample.
    /// let mut settings = AoSettings {
    ///     resolution: Resolution::Quarter,
    ///     filter_resolution: "full".parse()?,
    ///     ..AoSettings::default()
    /// };
    /// settings.spatial.enabled = true;
    /// assert_eq!(settings.filter_resolution, FilterResolution::Full);
    /// # Ok::<(), String>(())
    /// ```
    pub enum FilterResolution ("filter resolution") {
        /// At the working resolution, before the upsample. The default: the filters cost a
        /// quarter (half resolution) or a sixteenth (quarter) of what they cost at full
        /// resolution, for about 2% more error (docs/denoise.md).
        #[default]
        Working = "working",
        /// At full resolution, after the upsample: the filters see full-resolution depth and
        /// normals, and smooth the upsample's blocks too.
        Full = "full",
    }
}

named_enum! {
    /// The depth MIP chain that the marching and point kernels (`gtao`, `vbao`, `hbao`,
    /// `hbao-plus`, `ssao`, `ssao-crytek`) read their far samples from (docs/depth-mips.md):
    /// levels 1 to 4 of the working depth, so that a sample many pixels away reads a coarser
    /// level and stays in the texture cache. Samples closer than
    /// [`AoSettings::depth_mip_offset`] allows, and the kernels' own depth and normal, read
    /// full resolution. `sao`, `ue4-ssao` and `msvo` are built on a chain of their own, which
    /// they read at every setting of this one; the separable `hbao` reads none.
    ///
    /// ```
    /// use aokit::{AoSettings, DepthMips, Method, Preset};
    /// // Far samples from half-precision levels, from 16 pixels out (2^(3 + 1)).
    /// let settings = AoSettings {
    ///     depth_mips: DepthMips::Fp16,
    ///     depth_mip_offset: 3.0,
    ///     ..AoSettings::preset(Method::Gtao, Preset::High)
    /// };
    /// settings.validate()?;
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub enum DepthMips ("depth mips") {
        /// Every sample reads the full-resolution depth. The default, so that every error
        /// table measured without the chain stands.
        #[default]
        Off = "off",
        /// Levels 1 to 4 stored as 32-bit floats.
        Fp32 = "fp32",
        /// Levels 1 to 4 stored as 16-bit floats: half the bytes per texel. R16Float storage
        /// is not in WebGPU's core; it needs a device with
        /// `Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` on an adapter that can write
        /// it (`GpuContext` asks for it where it can), and elsewhere the pipeline returns
        /// [`AoError::Fp16DepthMipsUnsupported`](crate::AoError::Fp16DepthMipsUnsupported).
        Fp16 = "fp16",
    }
}

named_enum! {
    /// How the slice methods (`gtao`, `vbao`, `hbao`, `hbao-plus`:
    /// [`Method::marches_slices`]) read the depth where a sample lands
    /// (docs/methods.md#sample-depth). The point methods always interpolate, since the nearest
    /// texel makes a plane seen at a grazing angle occlude itself there; the separable `hbao`,
    /// `sao`, `ue4-ssao` and `msvo` read theirs one way only.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset, SampleDepth};
    /// // The exact read, for stills where the kernel's time matters less than the last 1%.
    /// let settings = AoSettings {
    ///     sample_depth: SampleDepth::Interpolated,
    ///     ..AoSettings::preset(Method::Gtao, Preset::High)
    /// };
    /// settings.validate()?;
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub enum SampleDepth ("sample depth") {
        /// The texel the sample lands in: one load. Its point is moved onto the view ray
        /// through the sample, which lies in the slice, at the same height above the pixel's
        /// tangent plane, so a plane seen at any angle stays unoccluded. The default: on an
        /// H100 the slice methods' frames take 0.79 to 0.95 of the interpolated read's time
        /// (docs/performance.md).
        #[default]
        Nearest = "nearest",
        /// Inside one surface, 1 / depth interpolated over the 2x2 texels around the sample,
        /// exact on a plane; the nearest texel across a depth edge. A gather and about half a
        /// sample's arithmetic more, for slightly lower error (docs/methods.md#sample-depth).
        Interpolated = "interpolated",
    }
}

named_enum! {
    /// How the slice methods (`gtao`, `vbao`, `hbao`, `hbao-plus`: [`Method::marches_slices`])
    /// march their slices. Both take the same samples and give the same AO to rounding; they
    /// differ in cost. The lean march applies to the nearest read ([`SampleDepth::Nearest`]);
    /// with [`SampleDepth::Interpolated`] the general one runs. The separable `hbao` marches
    /// its own way.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, Preset, SliceMarch};
    /// // Time the general march against the lean one (`aokit bench --compare`).
    /// let general = AoSettings {
    ///     slice_march: SliceMarch::General,
    ///     ..AoSettings::preset(Method::Gtao, Preset::High)
    /// };
    /// general.validate()?;
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub enum SliceMarch ("slice march") {
        /// Each side of a slice set up once: the view ray through a sample is affine in its
        /// distance along the slice, so a sample costs one fetch through the clamping sampler
        /// and a few multiply-adds, with validity a select instead of branches, and the slice
        /// and step counts and the step power compiled in.
        #[default]
        Lean = "lean",
        /// Every sample placed from scratch (`side_sample` in common/slice.wgsl), with a
        /// branch for each way it can fail: the march every slice method shares.
        General = "general",
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
            // Off until the published tables score filtered AO (see `enabled`).
            enabled: false,
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
            // The bilateral filter scores a little better on average (docs/denoise.md).
            kind: SpatialKind::Bilateral,
            // 3x3 windows: larger ones blur creases, where depth is continuous and AO is not,
            // more than they remove noise (1 to 3% more RMSE at 2, 3 to 6% at 3).
            guided_radius: 1,
            // The best measured for both methods, and 1e-5 to 1e-8 agree within 0.0002: a
            // window is fitted against depth unless its depth varies by less than 0.1%.
            guided_epsilon: 1e-6,
        }
    }
}

/// The member of `all` called `wanted`, or an error listing the names on offer.
pub(crate) fn find_by_name<T: Copy>(
    all: &[T],
    name: fn(T) -> &'static str,
    what: &str,
    wanted: &str,
) -> Result<T, String> {
    all.iter()
        .copied()
        .find(|&t| name(t) == wanted)
        .ok_or_else(|| {
            let known: Vec<&str> = all.iter().map(|&t| name(t)).collect();
            format!("unknown {what} `{wanted}` (known: {})", known.join(", "))
        })
}

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
    /// Depth samples per texel at each level, in mirrored pairs (even, 2 to 64), on a disc of
    /// 5 texels of the level. The working level costs this many per pixel; each coarser level
    /// a quarter of the one before, so all five at most a third more.
    pub sample_count: u32,
    /// Levels of the depth MIP chain the obscurance is computed at, 1 to [`MSVO_MAX_LEVELS`]:
    /// level `k` covers radii up to `5 * 2^k` working texels, so the screen radius stops at
    /// `5 * 2^(levels - 1)` ([`AoSettings::effective_max_radius_px`]).
    pub levels: u32,
    /// Unity's thickness modifier (MiniEngine's rejection falloff): a sample more than this
    /// many sphere chords in front of the sphere is taken for a thin occluder and rejected.
    /// Larger values darken creases and add halos around objects; must be > 0.
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

named_enum! {
    /// How `hbao` marches its directions (docs/methods/hbao.md, "separable HBAO").
    ///
    /// ```
    /// use aokit::{AoSettings, HbaoVariant, Method, Preset, SEPARABLE_HBAO_MAX_RADIUS_PX};
    /// // `--method hbao --set hbao.variant=separable`: rows, then columns, in workgroup memory.
    /// let mut settings = AoSettings::preset(Method::Hbao, Preset::High);
    /// settings.hbao.variant = "separable".parse()?;
    /// assert_eq!(settings.hbao.variant, HbaoVariant::Separable);
    /// // Four fixed directions of `step_count` steps each.
    /// assert_eq!(settings.samples_per_pixel(), 4 * settings.hbao.step_count);
    /// // The screen radius stops at the workgroup's apron, in working texels.
    /// assert_eq!(settings.effective_max_radius_px(), SEPARABLE_HBAO_MAX_RADIUS_PX as f32);
    /// # Ok::<(), String>(())
    /// ```
    pub enum HbaoVariant ("hbao variant") {
        /// One kernel: `hbao.direction_count` directions, rotated per pixel by the noise, each
        /// sample read from the depth texture.
        #[default]
        PerPixel = "per-pixel",
        /// Two passes after NVIDIA's compute-shader HBAO (their DirectX 11 SDK sample SSAO11,
        /// Bavoil 2011): the +x and -x horizons of every pixel from its row of depth in workgroup
        /// memory, then +y and -y from its column. The four directions are fixed, not rotated
        /// (the noise jitters the steps only), and the screen radius stops at
        /// [`SEPARABLE_HBAO_MAX_RADIUS_PX`] working texels.
        Separable = "separable",
    }
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
    /// The GTAO paper's thickness heuristic, in [0, 1]: how far the horizon falls back towards a
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

/// A setting outside the range it can take.
///
/// ```
/// use aokit::{AoSettings, SettingsError};
/// let mut settings = AoSettings::default();
/// settings.gtao.slice_count = 0;
/// // A settings panel highlights the field by its dotted path, as `--set` takes it.
/// let SettingsError { field, value, expected } = settings.validate().unwrap_err();
/// assert_eq!(field, "gtao.slice_count");
/// assert_eq!((value.as_str(), expected), ("0", "an integer in 1..=64"));
/// assert_eq!(
///     settings.validate().unwrap_err().to_string(),
///     "setting `gtao.slice_count` = 0 is out of range: an integer in 1..=64"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("setting `{field}` = {value} is out of range: {expected}")]
pub struct SettingsError {
    /// Dotted path of the setting, as `--set` takes it.
    pub field: &'static str,
    /// The value given.
    pub value: String,
    /// What would be accepted.
    pub expected: &'static str,
}

/// Most samples, slices, directions or steps a kernel accepts: beyond this the cost is far past
/// any real-time budget and the estimate has long converged.
pub const MAX_SAMPLE_COUNT: u32 = 64;

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
        let knob = |owners: &[Method]| {
            let owner = if owners.contains(&method) {
                method
            } else {
                owners[0]
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
            bias: knob(&[
                Method::Ssao,
                Method::SsaoCrytek,
                Method::Sao,
                Method::Ue4Ssao,
            ]),
            angle_bias: knob(&[Method::Hbao, Method::HbaoPlus]),
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
        let tuned = presets::vbao_back_faces_values(preset);
        let [slice_count, steps_per_side] = tuned.split;
        Self {
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
        match self.method {
            Method::SsaoCrytek => self.ssao_crytek.sample_count,
            Method::Ssao => self.ssao.sample_count,
            // +-x and +-y.
            Method::Hbao if self.separable_hbao() => 4 * self.hbao.step_count,
            Method::Hbao | Method::HbaoPlus => self.hbao.direction_count * self.hbao.step_count,
            Method::Gtao => 2 * self.gtao.slice_count * self.gtao.steps_per_side,
            Method::Vbao => 2 * self.vbao.slice_count * self.vbao.steps_per_side,
            Method::Sao => self.sao.sample_count,
            Method::Ue4Ssao => 2 * self.ue4_ssao.sample_count,
            // The working level's; the coarser levels add at most a third.
            Method::Msvo => self.msvo.sample_count,
        }
    }

    /// Whether the pipeline runs `hbao` as its two separable passes ([`HbaoVariant::Separable`])
    /// rather than one kernel.
    pub(crate) fn separable_hbao(&self) -> bool {
        self.method == Method::Hbao && self.hbao.variant == HbaoVariant::Separable
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
        if self.separable_hbao() {
            let apron = (SEPARABLE_HBAO_MAX_RADIUS_PX * self.resolution.scale()) as f32;
            self.max_radius_px.min(apron)
        } else if self.method == Method::Msvo {
            // The coarsest level's disc, in the input's pixels.
            let disc = MSVO_DISC_RADIUS << (self.msvo.levels.clamp(1, MSVO_MAX_LEVELS) - 1);
            self.max_radius_px
                .min((disc * self.resolution.scale()) as f32)
        } else {
            self.max_radius_px
        }
    }

    /// Checks every field, naming the first one out of range.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// let mut settings = AoSettings::default();
    /// settings.max_distance = 50.0;
    /// // A fade longer than the distance it ends at.
    /// settings.distance_falloff = 80.0;
    /// assert_eq!(settings.validate().unwrap_err().field, "distance_falloff");
    /// settings.distance_falloff = 10.0;
    /// settings.validate()?;
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub fn validate(&self) -> Result<(), SettingsError> {
        positive("radius", self.radius)?;
        if !(self.radius_multiplier > 0.0 && self.radius_multiplier <= 4.0) {
            return Err(SettingsError {
                field: "radius_multiplier",
                value: self.radius_multiplier.to_string(),
                expected: "a number in (0, 4]",
            });
        }
        in_unit_range("falloff", self.falloff)?;
        at_least("intensity", self.intensity, 0.0)?;
        positive("power", self.power)?;
        at_least("max_radius_px", self.max_radius_px, 1.0)?;
        at_least("min_radius_px", self.min_radius_px, 0.0)?;
        if self.min_radius_px > self.max_radius_px {
            return Err(SettingsError {
                field: "min_radius_px",
                value: self.min_radius_px.to_string(),
                expected: "pixels in [0, max_radius_px]",
            });
        }
        in_unit_range("bias", self.bias)?;
        if !(0.0..std::f32::consts::FRAC_PI_2).contains(&self.angle_bias) {
            return Err(SettingsError {
                field: "angle_bias",
                value: self.angle_bias.to_string(),
                expected: "an angle in [0, pi/2) radians",
            });
        }
        if !(0.25..=4.0).contains(&self.step_power) {
            return Err(SettingsError {
                field: "step_power",
                value: self.step_power.to_string(),
                expected: "a number in [0.25, 4]",
            });
        }
        at_least("max_distance", self.max_distance, 0.0)?;
        at_least("distance_falloff", self.distance_falloff, 0.0)?;
        if self.max_distance > 0.0 && self.distance_falloff > self.max_distance {
            return Err(SettingsError {
                field: "distance_falloff",
                value: self.distance_falloff.to_string(),
                expected: "a distance in [0, max_distance]",
            });
        }
        if self.bent_normals && !self.method.has_bent_normals() {
            return Err(SettingsError {
                field: "bent_normals",
                value: format!("true with method {}", self.method.name()),
                expected: "false, or a method with slices (gtao, vbao)",
            });
        }
        count("ssao_crytek.sample_count", self.ssao_crytek.sample_count)?;
        count("ssao.sample_count", self.ssao.sample_count)?;
        count("hbao.direction_count", self.hbao.direction_count)?;
        count("hbao.step_count", self.hbao.step_count)?;
        if self.method == Method::HbaoPlus && self.hbao.variant == HbaoVariant::Separable {
            return Err(SettingsError {
                field: "hbao.variant",
                value: "separable with method hbao-plus".into(),
                expected: "per-pixel: the separable passes integrate hbao's horizons, which \
                           hbao-plus does not have",
            });
        }
        count("gtao.slice_count", self.gtao.slice_count)?;
        count("gtao.steps_per_side", self.gtao.steps_per_side)?;
        in_unit_range("gtao.thickness", self.gtao.thickness)?;
        count("vbao.slice_count", self.vbao.slice_count)?;
        count("vbao.steps_per_side", self.vbao.steps_per_side)?;
        count("sao.sample_count", self.sao.sample_count)?;
        count("ue4_ssao.sample_count", self.ue4_ssao.sample_count)?;
        count("msvo.sample_count", self.msvo.sample_count)?;
        if !self.msvo.sample_count.is_multiple_of(2) {
            return Err(SettingsError {
                field: "msvo.sample_count",
                value: self.msvo.sample_count.to_string(),
                expected: "an even integer in 2..=64: samples come in mirrored pairs",
            });
        }
        if !(1..=MSVO_MAX_LEVELS).contains(&self.msvo.levels) {
            return Err(SettingsError {
                field: "msvo.levels",
                value: self.msvo.levels.to_string(),
                expected: "an integer in 1..=5",
            });
        }
        positive("msvo.thickness", self.msvo.thickness)?;
        positive("vbao.thickness", self.vbao.thickness)?;
        at_least("vbao.thickness_growth", self.vbao.thickness_growth, 0.0)?;
        if ![64, 128].contains(&self.noise.blue_size) {
            return Err(SettingsError {
                field: "noise.blue_size",
                value: self.noise.blue_size.to_string(),
                expected: "64 or 128",
            });
        }
        if !(1..=MAX_SPATIAL_RADIUS).contains(&self.spatial.radius) {
            return Err(SettingsError {
                field: "spatial.radius",
                value: self.spatial.radius.to_string(),
                expected: "an integer in 1..=8",
            });
        }
        positive("spatial.sigma", self.spatial.sigma)?;
        if !(0.0..1.0).contains(&self.temporal.blend) {
            return Err(SettingsError {
                field: "temporal.blend",
                value: self.temporal.blend.to_string(),
                expected: "a weight in [0, 1)",
            });
        }
        positive("temporal.variance_gamma", self.temporal.variance_gamma)?;
        positive("temporal.depth_threshold", self.temporal.depth_threshold)?;
        positive("spatial.depth_sigma", self.spatial.depth_sigma)?;
        at_least("spatial.normal_power", self.spatial.normal_power, 0.0)?;
        if !(1..=MAX_SPATIAL_RADIUS).contains(&self.spatial.guided_radius) {
            return Err(SettingsError {
                field: "spatial.guided_radius",
                value: self.spatial.guided_radius.to_string(),
                expected: "an integer in 1..=8",
            });
        }
        positive("spatial.guided_epsilon", self.spatial.guided_epsilon)?;
        positive("upsample_threshold", self.upsample_threshold)?;
        // Below 0 a sample one pixel away would read a coarser texel than its distance; from
        // 16 on, no sample within any radius a texture can hold reads a coarser level.
        if !(0.0..=16.0).contains(&self.depth_mip_offset) {
            return Err(SettingsError {
                field: "depth_mip_offset",
                value: self.depth_mip_offset.to_string(),
                expected: "a number in [0, 16] (log2 pixels)",
            });
        }
        Ok(())
    }
}

fn at_least(field: &'static str, value: f32, min: f32) -> Result<(), SettingsError> {
    if value.is_finite() && value >= min {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: if min == 0.0 {
                "a finite number >= 0"
            } else {
                "a finite number >= 1"
            },
        })
    }
}

fn positive(field: &'static str, value: f32) -> Result<(), SettingsError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "a finite number > 0",
        })
    }
}

fn in_unit_range(field: &'static str, value: f32) -> Result<(), SettingsError> {
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "a number in [0, 1]",
        })
    }
}

fn count(field: &'static str, value: u32) -> Result<(), SettingsError> {
    if (1..=MAX_SAMPLE_COUNT).contains(&value) {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "an integer in 1..=64",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_grow_in_cost_and_cost_the_same_for_every_method() {
        let mut last = 0;
        for preset in Preset::ALL {
            let cost = AoSettings::preset(Method::Gtao, preset).samples_per_pixel();
            assert!(cost > last, "{preset:?}");
            last = cost;
            for method in Method::ALL {
                let s = AoSettings::preset(method, preset);
                s.validate().unwrap();
                assert_eq!(s.samples_per_pixel(), cost, "{method:?} {preset:?}");
            }
        }
    }

    #[test]
    fn bent_normals_need_a_slice_method_and_fades_need_room() {
        let mut s = AoSettings::preset(Method::Ssao, Preset::High);
        s.bent_normals = true;
        assert_eq!(s.validate().unwrap_err().field, "bent_normals");
        s.method = Method::Vbao;
        s.validate().unwrap();
        s.max_distance = 10.0;
        s.distance_falloff = 20.0;
        assert_eq!(s.validate().unwrap_err().field, "distance_falloff");
        s.distance_falloff = 5.0;
        s.validate().unwrap();
    }

    #[test]
    fn out_of_range_values_name_their_field() {
        let field = |s: AoSettings| s.validate().unwrap_err().field;
        let base = AoSettings::default();
        assert_eq!(
            field(AoSettings {
                radius: f32::NAN,
                ..base
            }),
            "radius"
        );
        let mut s = AoSettings::default();
        s.gtao.steps_per_side = 65;
        assert_eq!(s.validate().unwrap_err().field, "gtao.steps_per_side");
        for pairs in [0, MAX_SAMPLE_COUNT + 1] {
            let mut s = AoSettings::preset(Method::Ue4Ssao, Preset::High);
            s.ue4_ssao.sample_count = pairs;
            assert_eq!(s.validate().unwrap_err().field, "ue4_ssao.sample_count");
        }
        assert_eq!(
            field(AoSettings {
                falloff: 1.5,
                ..base
            }),
            "falloff"
        );
        assert_eq!(
            field(AoSettings {
                intensity: -1.0,
                ..base
            }),
            "intensity"
        );
        for depth_mip_offset in [-0.5, 16.5, f32::NAN] {
            assert_eq!(
                field(AoSettings {
                    depth_mip_offset,
                    ..base
                }),
                "depth_mip_offset"
            );
        }
    }

    #[test]
    fn spatial_settings_out_of_range_name_their_field() {
        let spatial = |spatial| {
            AoSettings {
                spatial,
                ..AoSettings::default()
            }
            .validate()
            .map_err(|e| e.field)
        };
        let base = SpatialSettings {
            enabled: true,
            ..SpatialSettings::default()
        };
        assert_eq!(spatial(base), Ok(()));
        for radius in [0, MAX_SPATIAL_RADIUS + 1] {
            assert_eq!(
                spatial(SpatialSettings { radius, ..base }),
                Err("spatial.radius")
            );
        }
        assert_eq!(
            spatial(SpatialSettings { sigma: 0.0, ..base }),
            Err("spatial.sigma")
        );
        assert_eq!(
            spatial(SpatialSettings {
                depth_sigma: f32::INFINITY,
                ..base
            }),
            Err("spatial.depth_sigma")
        );
        assert_eq!(
            spatial(SpatialSettings {
                normal_power: -1.0,
                ..base
            }),
            Err("spatial.normal_power")
        );
        for guided_epsilon in [0.0, -1e-3, f32::NAN] {
            assert_eq!(
                spatial(SpatialSettings {
                    kind: SpatialKind::Guided,
                    guided_epsilon,
                    ..base
                }),
                Err("spatial.guided_epsilon")
            );
        }
        for guided_radius in [0, MAX_SPATIAL_RADIUS + 1] {
            assert_eq!(
                spatial(SpatialSettings {
                    kind: SpatialKind::Guided,
                    guided_radius,
                    ..base
                }),
                Err("spatial.guided_radius")
            );
        }
        // Checked when off too, so that turning the filter on cannot fail later.
        assert_eq!(
            spatial(SpatialSettings {
                enabled: false,
                radius: 9,
                ..base
            }),
            Err("spatial.radius")
        );
    }

    #[test]
    fn names_parse_back() {
        for m in Method::ALL {
            assert_eq!(m.name().parse::<Method>().unwrap(), m);
        }
        for p in Preset::ALL {
            assert_eq!(p.name().parse::<Preset>().unwrap(), p);
        }
        for e in NormalEncoding::ALL {
            assert_eq!(e.name().parse::<NormalEncoding>().unwrap(), e);
        }
        for k in NoiseKind::ALL {
            assert_eq!(k.name().parse::<NoiseKind>().unwrap(), k);
        }
        for w in DepthWeight::ALL {
            assert_eq!(w.name().parse::<DepthWeight>().unwrap(), w);
        }
        for k in SpatialKind::ALL {
            assert_eq!(k.name().parse::<SpatialKind>().unwrap(), k);
        }
        for r in Resolution::ALL {
            assert_eq!(r.name().parse::<Resolution>().unwrap(), r);
        }
        for d in Downsample::ALL {
            assert_eq!(d.name().parse::<Downsample>().unwrap(), d);
        }
        for u in Upsample::ALL {
            assert_eq!(u.name().parse::<Upsample>().unwrap(), u);
        }
        for f in FilterResolution::ALL {
            assert_eq!(f.name().parse::<FilterResolution>().unwrap(), f);
        }
        for m in SampleDepth::ALL {
            assert_eq!(m.name().parse::<SampleDepth>().unwrap(), m);
        }
        for m in DepthMips::ALL {
            assert_eq!(m.name().parse::<DepthMips>().unwrap(), m);
        }
        assert!("hbao9".parse::<Method>().unwrap_err().contains("gtao"));
    }

    #[test]
    fn the_separable_hbao_variant_is_refused_to_hbao_plus_and_stops_at_its_apron() {
        let mut s = AoSettings::preset(Method::HbaoPlus, Preset::High);
        s.hbao.variant = "separable".parse().unwrap();
        assert_eq!(s.validate().unwrap_err().field, "hbao.variant");
        // Kept but unused by the methods that have no `hbao` block.
        s.method = Method::Gtao;
        s.validate().unwrap();
        assert_eq!(s.effective_max_radius_px(), s.max_radius_px);
        s.method = Method::Hbao;
        s.validate().unwrap();
        assert_eq!(s.samples_per_pixel(), 4 * s.hbao.step_count);
        let apron = SEPARABLE_HBAO_MAX_RADIUS_PX as f32;
        for (resolution, max_radius_px, expected) in [
            (Resolution::Full, 256.0, apron),
            (Resolution::Half, 256.0, 256.0),
            (Resolution::Half, 1000.0, 2.0 * apron),
            (Resolution::Quarter, 1000.0, 4.0 * apron),
            (Resolution::Full, 40.0, 40.0),
        ] {
            let s = AoSettings {
                resolution,
                max_radius_px,
                ..s
            };
            assert_eq!(s.effective_max_radius_px(), expected, "{resolution:?}");
        }
        assert_eq!(
            HbaoVariant::ALL.map(HbaoVariant::name),
            ["per-pixel", "separable"]
        );
        for v in HbaoVariant::ALL {
            assert_eq!(v.name().parse::<HbaoVariant>().unwrap(), v);
        }
    }
}
