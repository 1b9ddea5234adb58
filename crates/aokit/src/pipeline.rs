//! [`AoPipeline`]: owns the passes and the intermediate textures, and wires them per frame.

use std::collections::HashMap;

use crate::error::AoError;
use crate::gpu::{PairFormat, create_texture_2d, create_uniform_buffer, missing_storage_formats};
use crate::inputs::AoInputs;
use crate::passes::PassContext;
use crate::passes::back_faces::{BackFacesPass, THICKNESS_FORMAT};
use crate::passes::decode_normals::DecodeNormalsPass;
use crate::passes::depth_mips::{DepthMipsPass, DepthReduction, atlas_format};
use crate::passes::edge_filter::EdgeFilterPass;
use crate::passes::guided_filter::GuidedFilterPass;
use crate::passes::linear_depth::{DepthInput, LINEAR_DEPTH_FORMAT, LinearDepthPass};
use crate::passes::mask::MaskPass;
use crate::passes::method::{AO_FORMAT, BENT_NORMALS_FORMAT, MethodPass};
use crate::passes::msvo::MsvoPass;
use crate::passes::normals_from_depth::{NORMALS_FORMAT, NormalsFromDepthPass};
use crate::passes::resample::{DownsampleTargets, ResampleFrame, ResamplePass};
use crate::passes::separable_hbao::SeparableHbaoPass;
use crate::passes::spatial_filter::{SpatialFilterPass, SpatialOutput};
use crate::passes::temporal_filter::{FrameMotion, History, TemporalFilterPass, TemporalInput};
use crate::settings::{
    AoSettings, FilterResolution, Method, NormalEncoding, NormalSource, NormalSpace, SpatialKind,
};
use crate::timing::{PassTime, PassTimer};
use crate::uniforms::ViewUniforms;

/// A texture and the view the passes bind.
type Target = (wgpu::Texture, wgpu::TextureView);

/// What the intermediate textures are made for; any change remakes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Layout {
    /// The input's size.
    size: [u32; 2],
    /// The kernel's size: `size` at full resolution.
    working: [u32; 2],
    bent_normals: bool,
    /// Size of the spatial filter's textures, when it is on.
    spatial: Option<[u32; 2]>,
    /// Whether the spatial filter hands the temporal filter its AO and depth packed in one
    /// texture (the bilateral kind with the temporal filter on).
    spatial_packed: bool,
    /// Whether the downsample writes motion vectors, for a temporal filter at working
    /// resolution.
    working_motion: bool,
    /// Whether an exclusion mask is applied.
    mask: bool,
    /// Whether the method reads a depth MIP chain.
    depth_mips: bool,
    /// The format of the [`AoSettings::depth_mips`] atlas, when the kernel reads one.
    depth_mip_atlas: Option<wgpu::TextureFormat>,
    /// Whether VBAO measures its occluders from the back faces.
    back_faces: bool,
}

/// The intermediate textures.
struct Targets {
    layout: Layout,
    /// Linear depth at the input's size.
    linear_depth: Target,
    /// oct32 normals decoded from the input or reconstructed from depth, at the input's size.
    normals: Target,
    /// Below full resolution, the kernel's inputs at working size and the upsampled outputs.
    working: Option<WorkingTargets>,
    /// The kernel's AO, at working size.
    ao: Target,
    /// The kernel's bent normals, at working size.
    bent_normals: Option<Target>,
    /// The spatial filter's textures, when it is on.
    spatial: Option<SpatialTargets>,
    /// The AO with the exclusion mask applied, at the input's size.
    masked_ao: Option<Target>,
    /// The working depth's MIP chain, for a method that reads one; its view shows every level.
    depth_mips: Option<Target>,
    /// The [`AoSettings::depth_mips`] chain, for a kernel that reads far samples from it.
    depth_mip_atlas: Option<Target>,
    /// The occluders' thickness from the back faces, at working size.
    back_thickness: Option<Target>,
}

/// The downsample's and the upsample's textures.
struct WorkingTargets {
    linear_depth: Target,
    normals: Target,
    motion_vectors: Option<Target>,
    /// The AO at the input's size.
    upsampled_ao: Target,
    /// The bent normals at the input's size.
    upsampled_bent_normals: Option<Target>,
}

/// The spatial filter's AO and depth after the bilateral kind's horizontal pass (or the guided
/// kind's window lines, in the same format), and its filtered AO: `R32Float`, or with
/// `ao_and_depth` (`Layout::spatial_packed`) the AO and depth in the pair format.
struct SpatialTargets {
    packed_view: wgpu::TextureView,
    ao: Target,
    ao_and_depth: bool,
}

impl Targets {
    fn new(device: &wgpu::Device, layout: Layout, pair: PairFormat) -> Self {
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let make = |label, size, format| {
            let texture = create_texture_2d(device, label, size, format, usage);
            let view = texture.create_view(&Default::default());
            (texture, view)
        };
        let Layout { size, working, .. } = layout;
        let bent = layout.bent_normals;
        Self {
            layout,
            linear_depth: make("aokit linear depth", size, LINEAR_DEPTH_FORMAT),
            normals: make("aokit normals", size, NORMALS_FORMAT),
            working: (working != size).then(|| WorkingTargets {
                linear_depth: make("aokit working linear depth", working, LINEAR_DEPTH_FORMAT),
                normals: make("aokit working normals", working, NORMALS_FORMAT),
                motion_vectors: layout
                    .working_motion
                    .then(|| make("aokit working motion", working, pair.texture_format())),
                upsampled_ao: make("aokit upsampled ao", size, AO_FORMAT),
                upsampled_bent_normals: bent
                    .then(|| make("aokit upsampled bent normals", size, BENT_NORMALS_FORMAT)),
            }),
            ao: make("aokit ao", working, AO_FORMAT),
            bent_normals: bent.then(|| make("aokit bent normals", working, BENT_NORMALS_FORMAT)),
            spatial: layout.spatial.map(|size| SpatialTargets {
                packed_view: make(
                    "aokit spatial filter ao and depth",
                    size,
                    pair.texture_format(),
                )
                .1,
                ao: if layout.spatial_packed {
                    make(
                        "aokit spatially filtered ao and depth",
                        size,
                        pair.texture_format(),
                    )
                } else {
                    make("aokit spatially filtered ao", size, AO_FORMAT)
                },
                ao_and_depth: layout.spatial_packed,
            }),
            masked_ao: layout
                .mask
                .then(|| make("aokit masked ao", size, AO_FORMAT)),
            depth_mips: layout.depth_mips.then(|| {
                let texture = DepthMipsPass::create_texture(device, working);
                let view = texture.create_view(&Default::default());
                (texture, view)
            }),
            depth_mip_atlas: layout.depth_mip_atlas.map(|format| {
                let texture = DepthMipsPass::create_atlas(device, working, format);
                let view = texture.create_view(&Default::default());
                (texture, view)
            }),
            back_thickness: layout
                .back_faces
                .then(|| make("aokit back-face thickness", working, THICKNESS_FORMAT)),
        }
    }
}

/// Validates `settings` and checks that `device` can run them: the passes write the storage
/// formats of `gpu::STORAGE_FORMATS`, and `depth_mips = fp16` writes R16Float.
fn check_settings(device: &wgpu::Device, settings: &AoSettings) -> Result<(), AoError> {
    settings.validate()?;
    let missing = missing_storage_formats(device);
    if !missing.is_empty() {
        return Err(AoError::StorageFormats(missing));
    }
    let fp16_storage = wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES;
    if atlas_format(settings) == Some(wgpu::TextureFormat::R16Float)
        && !device.features().contains(fp16_storage)
    {
        return Err(AoError::Fp16DepthMipsUnsupported);
    }
    Ok(())
}

/// What the filters read, at the resolution they run at: `ao` may be what they return.
struct FilterInputs<'t, 'f> {
    ao: &'t Target,
    linear_depth: &'f wgpu::TextureView,
    normals: &'f wgpu::TextureView,
    /// In pixels of that resolution.
    motion_vectors: Option<&'f wgpu::TextureView>,
}

/// The spatial and temporal filters and each view's temporal history.
struct Denoiser {
    spatial: SpatialFilterPass,
    guided: GuidedFilterPass,
    edges: EdgeFilterPass,
    /// Compiled the first time the temporal filter is on.
    temporal: Option<TemporalFilterPass>,
    /// Each view's temporal history, by [`AoInputs::view_id`].
    histories: HashMap<u32, Option<History>>,
    /// The format of the temporal histories, for the pass compiled on first use.
    pair: PairFormat,
}

impl Denoiser {
    /// Records the spatial and then the temporal filter, each when `settings` turn it on, at
    /// `ctx`'s resolution. Returns the filtered AO (`input.ao` itself with both off) and, with
    /// the temporal filter on, its rejected-history mask.
    fn encode<'t>(
        &'t mut self,
        ctx: &mut PassContext<'_>,
        queue: &wgpu::Queue,
        settings: &AoSettings,
        frame: &AoInputs<'_>,
        spatial: Option<&'t SpatialTargets>,
        input: FilterInputs<'t, '_>,
    ) -> (&'t Target, Option<&'t wgpu::Texture>) {
        let packed = spatial.is_some_and(|targets| targets.ao_and_depth);
        let ao = match spatial {
            Some(targets) => {
                match settings.spatial.kind {
                    SpatialKind::Bilateral => self.spatial.encode(
                        ctx,
                        &input.ao.1,
                        input.linear_depth,
                        input.normals,
                        &targets.packed_view,
                        if packed {
                            SpatialOutput::AoAndDepth(&targets.ao.1)
                        } else {
                            SpatialOutput::Ao(&targets.ao.1)
                        },
                    ),
                    SpatialKind::Guided => self.guided.encode(
                        ctx,
                        &input.ao.1,
                        input.linear_depth,
                        &targets.packed_view,
                        &targets.ao.1,
                    ),
                    SpatialKind::Edges => self.edges.encode(
                        ctx,
                        &input.ao.1,
                        input.linear_depth,
                        input.normals,
                        &targets.ao.1,
                    ),
                }
                &targets.ao
            }
            None => input.ao,
        };
        if !settings.temporal.enabled {
            // Off, histories go: when it is turned on again the old frames are stale.
            self.histories.clear();
            return (ao, None);
        }
        let history = self.histories.entry(frame.view_id).or_insert(None);
        let temporal = self.temporal.get_or_insert_with(|| {
            TemporalFilterPass::new(ctx.device, &settings.temporal, self.pair)
        });
        temporal.encode(
            ctx,
            queue,
            history,
            &FrameMotion {
                view_from_world: frame.view_from_world,
                projection: frame.projection,
                motion_vectors: input.motion_vectors,
                reset: frame.reset_history,
            },
            if packed {
                TemporalInput::Packed(&ao.1)
            } else {
                TemporalInput::Separate {
                    ao: &ao.1,
                    linear_depth: input.linear_depth,
                }
            },
        );
        let history = history
            .as_ref()
            .expect("the temporal filter keeps a history");
        (history.ao(), Some(&history.rejected().0))
    }
}

/// What [`AoPipeline::encode`] produced. Each texture says its size: the input's, or
/// [`AoOutputs::working_size`] for what the kernel wrote before the upsample.
///
/// The textures are the same from one `encode` to the next unless the pipeline had to make new
/// ones: for a new input size or [`AoSettings::resolution`], for settings that add or drop a
/// texture (bent normals, the spatial filter and [`AoSettings::filter_resolution`], a mask, a
/// method that reads a depth MIP chain, motion vectors for a temporal filter below full
/// resolution), and, with the temporal filter on, per [`AoInputs::view_id`] (each view keeps
/// its own history and output). wgpu textures compare by identity, so a renderer that keeps a
/// bind group remakes it only when `outputs.ao != cached_texture`.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, outputs: &aokit::AoOutputs<'_>) {
/// // `R32Float` is not filterable: the lighting layout declares the AO as
/// // `Float { filterable: false }` and the shader reads it with `textureLoad`.
/// let mut entries = vec![wgpu::BindGroupEntry {
///     binding: 0,
///     resource: wgpu::BindingResource::TextureView(outputs.ao_view),
/// }];
/// // Bent normals exist only when the settings ask for them (with gtao or vbao); `layout`
/// // has binding 1 exactly then.
/// if let Some(bent_normals) = outputs.bent_normals_view {
///     entries.push(wgpu::BindGroupEntry {
///         binding: 1,
///         resource: wgpu::BindingResource::TextureView(bent_normals),
///     });
/// }
/// let lighting = device.create_bind_group(&wgpu::BindGroupDescriptor {
///     label: Some("lighting ao"),
///     layout,
///     entries: &entries,
/// });
/// # }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct AoOutputs<'a> {
    /// Ambient occlusion, `R32Float`, 1 = unoccluded, at the input's size: the kernel's AO
    /// after the spatial and temporal filters that are on and, below full resolution, the
    /// upsample (in the order [`AoSettings::filter_resolution`] gives), then the
    /// [`AoInputs::mask`] when there is one.
    pub ao: &'a wgpu::Texture,
    /// A view of [`AoOutputs::ao`] for binding.
    pub ao_view: &'a wgpu::TextureView,
    /// The method kernel's AO before any denoising or upsampling, `R32Float`, at
    /// [`AoOutputs::working_size`], for comparing filters or feeding your own.
    pub raw_ao: &'a wgpu::Texture,
    /// A view of [`AoOutputs::raw_ao`] for binding.
    pub raw_ao_view: &'a wgpu::TextureView,
    /// The size the kernel ran at: the input's at full [`AoSettings::resolution`], else the
    /// input's divided by its scale, rounded up.
    pub working_size: [u32; 2],
    /// Linear view depth, `R32Float`, 0 where nothing was drawn, at the input's size (below
    /// full resolution the kernel read the downsample's copy).
    pub linear_depth: &'a wgpu::Texture,
    /// The linear depth the kernel read: [`AoOutputs::linear_depth`] at full resolution, the
    /// downsample's at [`AoOutputs::working_size`] below it.
    pub working_linear_depth: &'a wgpu::Texture,
    /// The view-space normals, oct32 (`R32Uint`, see
    /// [`normals::unpack_oct32`](crate::normals::unpack_oct32)), at the input's size: the input
    /// texture itself when it is oct32 in view space, else the input decoded (and turned into
    /// view space) or the normals reconstructed from depth. The kernel read these, or below
    /// full resolution the downsample's copy.
    pub normals: &'a wgpu::Texture,
    /// A view of [`AoOutputs::normals`] for binding.
    pub normals_view: &'a wgpu::TextureView,
    /// Bent normals when [`AoSettings::bent_normals`] is on, at the input's size (below full
    /// resolution upsampled with the AO's weights and renormalised): `Rgba16Float`, view-space
    /// unit vector in xyz (the mean unoccluded direction), the kernel's AO in w. Neither is
    /// denoised: the spatial and temporal filters smooth [`AoOutputs::ao`] only, so specular
    /// occlusion from these carries the kernel's noise.
    pub bent_normals: Option<&'a wgpu::Texture>,
    /// A view of [`AoOutputs::bent_normals`] for binding.
    pub bent_normals_view: Option<&'a wgpu::TextureView>,
    /// With the temporal filter on: `R32Float`, 1 where this frame rejected its history
    /// (disocclusions, the screen's edges, a reset) and showed the current frame alone, 0 where
    /// it blended. A debug view of where ghosting or fresh noise can show. At the filters'
    /// size: [`AoOutputs::working_size`], or the input's with [`FilterResolution::Full`].
    pub history_rejected: Option<&'a wgpu::Texture>,
    /// With a method that reads one (`sao`, `ue4-ssao`, see
    /// [`Method::reads_depth_mips`](crate::Method::reads_depth_mips)): the depth MIP chain its
    /// kernel read, `R32Float` at [`AoOutputs::working_size`], up to five levels: level 0 is
    /// [`AoOutputs::working_linear_depth`], each further level reduces every 2x2 block of the
    /// level below (blocks clamped to the level), never to an average. For `sao` it keeps one
    /// depth of the four, the texel at offset `(y & 1, x & 1)` of texel `(x, y)`'s block; for
    /// `ue4-ssao` the largest, so that each texel of level `k` holds the furthest depth of its
    /// `2^k x 2^k` block of level 0.
    pub depth_mips: Option<&'a wgpu::Texture>,
    /// With [`AoSettings::depth_mips`] on for a kernel that reads it: the chain its far samples
    /// read, `R32Float` (`fp32`) or `R16Float` (`fp16`), in one texture. Levels 1 to 4 of
    /// [`AoOutputs::working_linear_depth`] (fewer at small sizes: each keeps at least 2 texels
    /// a side), level `k` as large as a MIP level `k` would be and starting at row
    /// `H - (H >> (k - 1))` for a working depth `H` texels high; its texel holds the mean of
    /// the 2x2 texels below it where they lie on one surface (within 10% in depth; of 1 /
    /// depth, or of depth when orthographic), else their furthest depth. In `fp32` level 0, a
    /// copy of the working depth, sits at the origin and the coarser levels start at column
    /// `W`; in `fp16` they start at column 0 and level 0 is not in it.
    pub depth_mip_atlas: Option<&'a wgpu::Texture>,
}

/// The AO pipeline for one view.
///
/// ```no_run
/// # fn frame(device: &wgpu::Device, queue: &wgpu::Queue, depth: &wgpu::Texture,
/// #          normals: &wgpu::Texture, projection: aokit::Projection) -> Result<(), aokit::AoError> {
/// use aokit::{AoInputs, AoPipeline, AoSettings};
/// let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default())?;
/// let mut encoder = device.create_command_encoder(&Default::default());
/// let outputs = pipeline.encode(device, queue, &mut encoder, &AoInputs {
///     normals: Some(normals),
///     ..AoInputs::new(depth, projection)
/// })?;
/// // ... bind `outputs.ao_view` in your lighting pass ...
/// queue.submit([encoder.finish()]);
/// # Ok(()) }
/// ```
pub struct AoPipeline {
    settings: AoSettings,
    /// `ViewUniforms` of the input's size, and of the working size.
    view_uniforms: wgpu::Buffer,
    working_view_uniforms: wgpu::Buffer,
    linear_depth: LinearDepthPass,
    back_faces: BackFacesPass,
    mask: MaskPass,
    normals_from_depth: NormalsFromDepthPass,
    decode_normals: DecodeNormalsPass,
    /// A view of the input normals of the last frame, kept for [`AoOutputs::normals_view`] when
    /// the kernels read them as they are.
    input_normals_view: Option<wgpu::TextureView>,
    method: MethodPass,
    /// Runs instead of `method`'s kernel for `hbao.variant = separable`; compiled the first
    /// time that is chosen.
    separable_hbao: Option<SeparableHbaoPass>,
    /// Runs instead of a single kernel for `msvo`; compiled the first time that is chosen.
    msvo: Option<MsvoPass>,
    denoiser: Denoiser,
    /// Compiled the first time the resolution is below full.
    resample: Option<ResamplePass>,
    /// Made the first time a method reads a depth MIP chain; each reduction's kernel compiles
    /// on first use.
    depth_mips: Option<DepthMipsPass>,
    targets: Option<Targets>,
    timer: Option<PassTimer>,
    /// How this device stores the two-channel targets, probed once.
    pair: PairFormat,
}

impl AoPipeline {
    /// Compiles the passes the settings need. Fails, naming the field, when the settings are
    /// out of range, with [`AoError::Fp16DepthMipsUnsupported`] when they ask for an fp16
    /// depth MIP chain the device cannot write, and with [`AoError::StorageFormats`] on a
    /// device that cannot write the storage textures the passes write.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), aokit::AoError> {
    /// use aokit::{AoPipeline, AoSettings, Method, Preset, Resolution};
    /// // An integrated GPU: the cheap preset, with the kernel at half resolution.
    /// let settings = AoSettings {
    ///     resolution: Resolution::Half,
    ///     ..AoSettings::preset(Method::Gtao, Preset::Low)
    /// };
    /// let pipeline = AoPipeline::new(device, queue, &settings)?;
    /// # Ok(()) }
    /// ```
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) -> Result<Self, AoError> {
        check_settings(device, settings)?;
        let pair = PairFormat::of(device);
        Ok(Self {
            settings: *settings,
            view_uniforms: create_uniform_buffer::<ViewUniforms>(device, "aokit view"),
            working_view_uniforms: create_uniform_buffer::<ViewUniforms>(
                device,
                "aokit working view",
            ),
            linear_depth: LinearDepthPass::default(),
            back_faces: BackFacesPass::default(),
            mask: MaskPass::default(),
            normals_from_depth: NormalsFromDepthPass::new(device),
            decode_normals: DecodeNormalsPass::new(device),
            input_normals_view: None,
            method: MethodPass::new(device, queue, settings),
            separable_hbao: None,
            msvo: None,
            denoiser: Denoiser {
                spatial: SpatialFilterPass::new(device, queue, &settings.spatial, pair),
                guided: GuidedFilterPass::new(device, queue, &settings.spatial, pair),
                edges: EdgeFilterPass::new(device, queue, &settings.spatial),
                temporal: None,
                histories: HashMap::new(),
                pair,
            },
            resample: None,
            depth_mips: None,
            targets: None,
            timer: None,
            pair,
        })
    }

    /// Times every pass with GPU timestamps from now on. Returns `false`, and changes nothing,
    /// when the device was not created with `Features::TIMESTAMP_QUERY`.
    ///
    /// ```no_run
    /// # fn f(adapter: &wgpu::Adapter) -> Result<(), Box<dyn std::error::Error>> {
    /// // Timestamps are optional: request them where the adapter has them.
    /// let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
    ///     required_features: adapter.features() & wgpu::Features::TIMESTAMP_QUERY,
    ///     ..Default::default()
    /// }))?;
    /// let mut pipeline = aokit::AoPipeline::new(&device, &queue, &aokit::AoSettings::default())?;
    /// if !pipeline.enable_timing(&device, &queue) {
    ///     eprintln!("no GPU timestamps on {}: pass times unavailable", adapter.get_info().name);
    /// }
    /// # Ok(()) }
    /// ```
    pub fn enable_timing(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) -> bool {
        if self.timer.is_none() {
            self.timer = PassTimer::new(device, queue);
        }
        self.timer.is_some()
    }

    /// GPU time of each pass of the last encoded frame, once its commands were submitted;
    /// `None` unless [`AoPipeline::enable_timing`] succeeded. Blocks until the GPU is done.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline,
    /// #      inputs: &aokit::AoInputs<'_>) -> Result<(), Box<dyn std::error::Error>> {
    /// let mut encoder = device.create_command_encoder(&Default::default());
    /// pipeline.encode(device, queue, &mut encoder, inputs)?;
    /// queue.submit([encoder.finish()]);
    /// // Only after the submit: the read waits for the GPU to run this frame's passes.
    /// if let Some(times) = pipeline.last_pass_times(device) {
    ///     let total_ms: f64 = times?.iter().map(|t| t.ms).sum();
    ///     println!("AO: {total_ms:.2} ms");
    /// }
    /// # Ok(()) }
    /// ```
    pub fn last_pass_times(
        &self,
        device: &wgpu::Device,
    ) -> Option<Result<Vec<PassTime>, crate::GpuError>> {
        self.timer.as_ref().map(|timer| timer.read(device))
    }

    /// The settings in use.
    ///
    /// ```no_run
    /// # fn f(pipeline: &aokit::AoPipeline) {
    /// // An overlay shows what runs: a rejected `set_settings` left these unchanged.
    /// let s = pipeline.settings();
    /// println!("{} at {} resolution, radius {}", s.method.name(), s.resolution.name(), s.radius);
    /// # }
    /// ```
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// Replaces the settings. Only the settings buffer changes, unless the method is one not
    /// used before (its kernel compiles once), the noise needs a tile not used before (it is
    /// generated and uploaded once), bent normals, the spatial filter or the resolution are
    /// switched (their textures are made or dropped at the next `encode`; the filter's kernels
    /// and the downsample and upsample compile the first time they are needed) or the normals
    /// need a decode or reconstruction not used before (its kernel compiles once, at the next
    /// `encode`).
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline,
    /// #      slider: f32) -> Result<(), aokit::AoError> {
    /// use aokit::AoSettings;
    /// // A radius slider: only the settings buffer is rewritten, nothing compiles.
    /// let settings = AoSettings { radius: slider, ..*pipeline.settings() };
    /// pipeline.set_settings(device, queue, &settings)?;
    /// // Dragged to 0: refused, and the pipeline keeps the radius it had.
    /// let zero = AoSettings { radius: 0.0, ..settings };
    /// assert!(pipeline.set_settings(device, queue, &zero).is_err());
    /// assert_eq!(pipeline.settings().radius, settings.radius);
    /// # Ok(()) }
    /// ```
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) -> Result<(), AoError> {
        check_settings(device, settings)?;
        self.settings = *settings;
        self.method.set_settings(device, queue, settings);
        self.denoiser
            .spatial
            .set_settings(device, queue, &settings.spatial);
        self.denoiser
            .guided
            .set_settings(device, queue, &settings.spatial);
        self.denoiser
            .edges
            .set_settings(device, queue, &settings.spatial);
        if let Some(temporal) = &mut self.denoiser.temporal {
            temporal.set_settings(&settings.temporal);
        }
        Ok(())
    }

    /// Records the passes for one frame into `encoder`. Intermediate textures are (re)created
    /// when the input size or the resolution changes. The outputs borrow the inputs' textures
    /// too: with oct32 input normals, [`AoOutputs::normals`] is the input texture.
    ///
    /// ```no_run
    /// # fn light(encoder: &mut wgpu::CommandEncoder, ao: &wgpu::TextureView) {}
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline,
    /// #      player: aokit::AoInputs<'_>, mirror_depth: &wgpu::Texture,
    /// #      mirror_projection: aokit::Projection, mirror_view: glam::Mat4)
    /// #      -> Result<(), aokit::AoError> {
    /// use aokit::AoInputs;
    /// let mut encoder = device.create_command_encoder(&Default::default());
    /// let outputs = pipeline.encode(device, queue, &mut encoder, &player)?;
    /// // Lit before the next `encode`, which may write over these textures.
    /// light(&mut encoder, outputs.ao_view);
    /// // A mirror seen from its own camera: view 1 has a temporal history of its own, so the
    /// // player's frames never blend into it.
    /// let mirror = AoInputs {
    ///     view_id: 1,
    ///     view_from_world: mirror_view,
    ///     frame_index: player.frame_index,
    ///     ..AoInputs::new(mirror_depth, mirror_projection)
    /// };
    /// let outputs = pipeline.encode(device, queue, &mut encoder, &mirror)?;
    /// light(&mut encoder, outputs.ao_view);
    /// queue.submit([encoder.finish()]);
    /// # Ok(()) }
    /// ```
    pub fn encode<'a>(
        &'a mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &AoInputs<'a>,
    ) -> Result<AoOutputs<'a>, AoError> {
        let settings = self.settings;
        let encoding = settings.normals.encoding;
        let size = inputs.validate(encoding)?;
        inputs.projection.validate()?;
        let max = device.limits().max_texture_dimension_2d;
        if size[0] > max || size[1] > max {
            return Err(AoError::TooLarge { size, max });
        }
        let back_faces = settings.method == Method::Vbao && settings.vbao.back_faces;
        if back_faces && inputs.back_depth.is_none() {
            return Err(AoError::MissingBackDepth);
        }
        let working = settings.resolution.working_size(size);
        // A 1x1 image is its own working image at any resolution: it runs as at full.
        let scale = if working == size {
            1
        } else {
            settings.resolution.scale()
        };
        // Below full resolution the filters run before the upsample, at working resolution,
        // unless the settings move them after it.
        let filter_full = scale > 1 && settings.filter_resolution == FilterResolution::Full;
        let layout = Layout {
            size,
            working,
            bent_normals: settings.bent_normals,
            spatial: settings
                .spatial
                .enabled
                .then_some(if filter_full { size } else { working }),
            spatial_packed: settings.spatial.enabled
                && settings.spatial.kind == SpatialKind::Bilateral
                && settings.temporal.enabled,
            working_motion: scale > 1
                && !filter_full
                && settings.temporal.enabled
                && inputs.motion_vectors.is_some(),
            mask: inputs.mask.is_some(),
            depth_mips: settings.method.reads_depth_mips(),
            depth_mip_atlas: atlas_format(&settings),
            back_faces,
        };
        if self.targets.as_ref().map(|t| t.layout) != Some(layout) {
            self.targets = Some(Targets::new(device, layout, self.pair));
        }
        let targets = self.targets.as_ref().expect("targets were just created");
        let (projection, frame_index) = (&inputs.projection, inputs.frame_index);
        queue.write_buffer(
            &self.view_uniforms,
            0,
            bytemuck::bytes_of(&ViewUniforms::new(projection, size, frame_index)),
        );
        // Written at full resolution too (where it equals the other), so that the passes
        // between downsample and upsample bind it whatever the resolution.
        queue.write_buffer(
            &self.working_view_uniforms,
            0,
            bytemuck::bytes_of(&ViewUniforms::scaled(projection, size, scale, frame_index)),
        );

        if let Some(timer) = self.timer.as_mut() {
            timer.begin_frame();
        }
        let mut ctx = PassContext {
            device,
            encoder,
            view_uniforms: &self.view_uniforms,
            size,
            timer: self.timer.as_mut(),
        };
        // Input normals the settings use are read as they are when oct32, else decoded; without
        // them (or when the source is depth) the normals are reconstructed.
        let source = settings.normals.source;
        self.input_normals_view = inputs
            .normals
            .filter(|_| source == NormalSource::Buffer)
            .map(|n| n.create_view(&Default::default()));
        // The linear depth pass runs at full resolution, and where normals are reconstructed
        // from its output. Otherwise the downsample and the upsample read the renderer's depth
        // themselves, and the upsample writes the full-resolution linear depth: one pass less.
        let linear_pass = scale == 1 || self.input_normals_view.is_none();
        let input_view;
        let (resample_input, resample_depth) = if linear_pass {
            self.linear_depth
                .encode(&mut ctx, inputs.depth, &targets.linear_depth.1);
            (DepthInput::Linear, &targets.linear_depth.1)
        } else {
            input_view = DepthInput::view(inputs.depth);
            (DepthInput::of(inputs.depth), &input_view)
        };
        let world = settings.normals.space == NormalSpace::World;
        let (normals, normals_view) = match (inputs.normals, &self.input_normals_view) {
            (Some(texture), Some(view)) if encoding == NormalEncoding::Oct32 && !world => {
                (texture, view)
            }
            (_, Some(view)) => {
                let to_view = if world {
                    glam::Mat3::from_mat4(inputs.view_from_world)
                } else {
                    glam::Mat3::IDENTITY
                };
                self.decode_normals.encode(
                    &mut ctx,
                    queue,
                    encoding,
                    to_view,
                    view,
                    &targets.normals.1,
                );
                (&targets.normals.0, &targets.normals.1)
            }
            (_, None) => {
                self.normals_from_depth.encode(
                    &mut ctx,
                    source,
                    &targets.linear_depth.1,
                    &targets.normals.1,
                );
                (&targets.normals.0, &targets.normals.1)
            }
        };
        let motion_vectors = inputs
            .motion_vectors
            .map(|t| t.create_view(&Default::default()));

        // Below full resolution: depth, normals and the motion the filters need, downsampled.
        let resample = targets.working.as_ref().map(|working| {
            let pass = self
                .resample
                .get_or_insert_with(|| ResamplePass::new(device, self.pair));
            pass.prepare(
                device,
                queue,
                &settings,
                ResampleFrame {
                    input: resample_input,
                    motion_vectors: layout.working_motion,
                    bent_normals: settings.bent_normals,
                    write_linear_depth: !linear_pass,
                },
            );
            (&*pass, working)
        });
        ctx.size = working;
        ctx.view_uniforms = &self.working_view_uniforms;
        let (working_depth, working_normals) = match resample {
            Some((pass, working)) => {
                pass.downsample(
                    &mut ctx,
                    resample_depth,
                    normals_view,
                    motion_vectors.as_ref().filter(|_| layout.working_motion),
                    &DownsampleTargets {
                        linear_depth: &working.linear_depth.1,
                        normals: &working.normals.1,
                        motion_vectors: working.motion_vectors.as_ref().map(|(_, v)| v),
                    },
                );
                (&working.linear_depth.1, &working.normals.1)
            }
            None => (&targets.linear_depth.1, normals_view),
        };
        let back_thickness = targets.back_thickness.as_ref().map(|(_, view)| {
            let back_depth = inputs.back_depth.expect("checked with the settings");
            self.back_faces
                .encode(&mut ctx, scale, back_depth, working_depth, view);
            view
        });
        let working_texture = match &targets.working {
            Some(working) => &working.linear_depth.0,
            None => &targets.linear_depth.0,
        };
        // A method that reads a depth MIP chain binds it where the others bind the working
        // depth, which is its level 0.
        let kernel_depth = match (&targets.depth_mips, DepthReduction::of(settings.method)) {
            (Some((chain, view)), Some(reduction)) => {
                self.depth_mips
                    .get_or_insert_with(DepthMipsPass::default)
                    .encode(&mut ctx, reduction, working_texture, chain);
                view
            }
            _ => working_depth,
        };
        if let Some((atlas, _)) = &targets.depth_mip_atlas {
            self.depth_mips
                .get_or_insert_with(DepthMipsPass::default)
                .encode_atlas(
                    &mut ctx,
                    working_texture,
                    atlas,
                    projection.is_orthographic(),
                );
        }
        if settings.method == Method::Msvo {
            let (chain, _) = targets
                .depth_mips
                .as_ref()
                .expect("msvo reads a depth MIP chain");
            self.msvo
                .get_or_insert_with(|| MsvoPass::new(device))
                .encode(
                    &mut ctx,
                    &self.method,
                    chain,
                    working_normals,
                    &targets.ao.1,
                    settings.msvo.levels,
                );
        } else if settings.separable_hbao() {
            self.separable_hbao
                .get_or_insert_with(|| SeparableHbaoPass::new(device))
                .encode(
                    &mut ctx,
                    &self.method,
                    working_depth,
                    working_normals,
                    &targets.ao.1,
                );
        } else {
            self.method.encode(
                &mut ctx,
                settings.method,
                projection.is_orthographic(),
                kernel_depth,
                working_normals,
                &targets.ao.1,
                targets.bent_normals.as_ref().map(|(_, view)| view),
                targets.depth_mip_atlas.as_ref().map(|(_, view)| view),
                back_thickness,
            );
        }

        // The upsample of `ao` and the bent normals; `ctx` must be at the input's size.
        let upsample = |ctx: &mut PassContext<'_>, ao: &wgpu::TextureView| {
            resample.map(|(pass, working)| {
                pass.upsample(
                    ctx,
                    resample_depth,
                    normals_view,
                    working_depth,
                    ao,
                    &working.upsampled_ao.1,
                    targets
                        .bent_normals
                        .as_ref()
                        .zip(working.upsampled_bent_normals.as_ref())
                        .map(|((_, from), (_, to))| (from, to)),
                    (!linear_pass).then_some(&targets.linear_depth.1),
                );
                working
            })
        };
        let filter_inputs = if filter_full {
            ctx.size = size;
            ctx.view_uniforms = &self.view_uniforms;
            let working = upsample(&mut ctx, &targets.ao.1).expect("below full resolution");
            FilterInputs {
                ao: &working.upsampled_ao,
                linear_depth: &targets.linear_depth.1,
                normals: normals_view,
                motion_vectors: motion_vectors.as_ref(),
            }
        } else {
            FilterInputs {
                ao: &targets.ao,
                linear_depth: working_depth,
                normals: working_normals,
                motion_vectors: match &targets.working {
                    Some(working) => working.motion_vectors.as_ref().map(|(_, v)| v),
                    None => motion_vectors.as_ref(),
                },
            }
        };
        let (filtered, history_rejected) = self.denoiser.encode(
            &mut ctx,
            queue,
            &settings,
            inputs,
            targets.spatial.as_ref(),
            filter_inputs,
        );
        let ao = if filter_full {
            filtered
        } else {
            ctx.size = size;
            ctx.view_uniforms = &self.view_uniforms;
            upsample(&mut ctx, &filtered.1).map_or(filtered, |w| &w.upsampled_ao)
        };
        let ao = match (&inputs.mask, &targets.masked_ao) {
            (Some(mask), Some(masked)) => {
                self.mask.encode(&mut ctx, mask, &ao.1, &masked.1);
                masked
            }
            _ => ao,
        };
        let bent_normals = match &targets.working {
            Some(working) => working.upsampled_bent_normals.as_ref(),
            None => targets.bent_normals.as_ref(),
        };
        if let Some(timer) = &self.timer {
            timer.resolve(encoder);
        }
        Ok(AoOutputs {
            ao: &ao.0,
            ao_view: &ao.1,
            raw_ao: &targets.ao.0,
            raw_ao_view: &targets.ao.1,
            working_size: working,
            linear_depth: &targets.linear_depth.0,
            working_linear_depth: match &targets.working {
                Some(working) => &working.linear_depth.0,
                None => &targets.linear_depth.0,
            },
            normals,
            normals_view,
            bent_normals: bent_normals.map(|(texture, _)| texture),
            bent_normals_view: bent_normals.map(|(_, view)| view),
            history_rejected,
            depth_mips: targets.depth_mips.as_ref().map(|(texture, _)| texture),
            depth_mip_atlas: targets.depth_mip_atlas.as_ref().map(|(texture, _)| texture),
        })
    }
}
