//! The settings' enums: every choice a setting offers, by the names `--set` and settings files
//! use.

use super::*;

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
        crate::methods::spec(self).bent_normals
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
        crate::methods::spec(self).marches_slices
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
        crate::methods::spec(self).depth_mips.is_some()
    }

    /// The settings of the method's own section (`gtao.*` for [`Method::Gtao`]; `hbao-plus`
    /// runs on `hbao.*`), in [`SETTINGS`]' order: what a method's settings
    /// panel or documentation page lists beside the shared ones.
    ///
    /// ```
    /// use aokit::Method;
    /// let keys: Vec<&str> = Method::HbaoPlus.own_settings().map(|s| s.name).collect();
    /// assert!(keys.contains(&"hbao.direction_count"));
    /// assert!(Method::Gtao.own_settings().all(|s| s.name.starts_with("gtao.")));
    /// ```
    pub fn own_settings(self) -> impl Iterator<Item = &'static SettingSpec> {
        let section = crate::methods::spec(self).section;
        SETTINGS
            .iter()
            .filter(move |s| s.section() == Some(section))
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

named_enum! {
    /// How the spatial filter weighs a neighbour by its depth difference from the centre.
    ///
    /// ```
    /// use aokit::{AoSettings, DepthWeight};
    /// let mut settings = AoSettings::default();
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
    /// // `--set spatial.kind=guided` on the command line.
    /// settings.spatial.kind = "guided".parse()?;
    /// assert_eq!(settings.spatial.kind, SpatialKind::Guided);
    /// # Ok::<(), String>(())
    /// ```
    pub enum SpatialKind ("spatial filter kind") {
        /// The separable bilateral blur: weights from pixel distance, relative depth difference
        /// and normals (`radius`, `sigma`, `depth_weight`, `depth_sigma`, `normal_power`).
        Bilateral = "bilateral",
        /// He, Sun and Tang's guided filter with the log of linear depth as the guide: a
        /// linear model of AO against depth in every `(2 guided_radius + 1)^2` window
        /// (`guided_radius`, `guided_epsilon`).
        Guided = "guided",
        /// One pass over each pixel's 3x3 neighbourhood with the bilateral kind's weights
        /// (`sigma`, `depth_weight`, `depth_sigma`, `normal_power`; `radius` does not apply):
        /// the shape of XeGTAO's denoiser, nine texels a pixel in gathers and no workgroup
        /// tile. The default: the bilateral kind's error in about three quarters of its time
        /// (docs/denoise.md).
        #[default]
        Edges = "edges",
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
    /// // The offset counts in log2 pixels from 0: a negative one is refused, naming it.
    /// let error = AoSettings { depth_mip_offset: -1.0, ..settings }.validate().unwrap_err();
    /// assert_eq!(error.field, "depth_mip_offset");
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
    /// // GTAO marches slices, so it reads the setting; `--set sample_depth=interpolated` names it.
    /// assert!(settings.method.marches_slices());
    /// assert_eq!(settings.sample_depth.name(), "interpolated");
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
    /// // The presets march the lean way; the flag's value parses to the general march.
    /// assert_eq!(AoSettings::preset(Method::Gtao, Preset::High).slice_march, SliceMarch::Lean);
    /// assert_eq!("general".parse::<SliceMarch>(), Ok(SliceMarch::General));
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub enum SliceMarch ("slice march") {
        /// Each side of a slice set up once: the view ray through a sample is affine in its
        /// distance along the slice, so a sample costs one fetch through the clamping sampler
        /// and a few multiply-adds, with validity a select instead of branches, and the slice
        /// and step counts, the step power and whether GTAO's thickness is above 0 compiled
        /// in.
        #[default]
        Lean = "lean",
        /// Every sample placed from scratch (`side_sample` in common/slice.wgsl), with a
        /// branch for each way it can fail: the march every slice method shares.
        General = "general",
    }
}

named_enum! {
    /// What the slice methods (`gtao`, `vbao`, `hbao`, `hbao-plus`:
    /// [`Method::marches_slices`]) take for a sample that lands off screen, where the depth
    /// buffer says nothing (docs/quality.md#off-screen-samples-and-silhouettes). The other
    /// methods, and the separable `hbao`, take such samples as unoccluded.
    ///
    /// ```
    /// use aokit::{AoSettings, Method, OffscreenSamples, Preset};
    /// // Continue the surface at the screen's edge: less error near the edges, more work.
    /// let settings = AoSettings {
    ///     offscreen_samples: OffscreenSamples::Extend,
    ///     ..AoSettings::preset(Method::Gtao, Preset::High)
    /// };
    /// settings.validate()?;
    /// // The default carries the last texel on screen on at its height, for a clamp a sample.
    /// assert_eq!(AoSettings::default().offscreen_samples, OffscreenSamples::Clamp);
    /// assert_eq!("unoccluded".parse::<OffscreenSamples>(), Ok(OffscreenSamples::Unoccluded));
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub enum OffscreenSamples ("off-screen samples") {
        /// The surface at the screen's edge continued: the sample lies where its view ray meets
        /// the plane of the last texel on screen along its slice (that texel's point and
        /// normal). On the held-out views it took GTAO `high`'s RMSE in the 12 px border band
        /// from 0.064 to 0.055 (mean over the views), and lowered it on every view of both
        /// sets; on lavapipe GTAO `high`'s frame took 1.22 to 1.26 times as long. Not the
        /// default until its cost is measured on a GPU.
        Extend = "extend",
        /// Dropped, as if the scene were open beyond the edge: pixels near it come out too
        /// bright wherever the geometry continues. The default before the presets were
        /// searched with `Clamp`.
        Unoccluded = "unoccluded",
        /// The last texel on screen, which a clamping sampler reads there, placed as any texel
        /// a sample reads is: on the sample's view ray, at that texel's height above the pixel's
        /// tangent plane. A rise at the edge goes on at its height; an open plane stays open
        /// (XeGTAO takes the edge's depth at the sample's position instead, which raises a
        /// receding plane into a wall). A clamp more than dropping the sample. It took the 12 px
        /// border band's RMSE 8 to 11% lower on the held-out views and 13 to 21% on the tuning
        /// views: from 60% (GTAO held out) to a little more than all (HBAO+) of what `Extend`
        /// gains there. The default.
        #[default]
        Clamp = "clamp",
    }
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
