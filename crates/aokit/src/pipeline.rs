//! [`AoPipeline`]: owns the passes and the intermediate textures, and wires them per frame.

use crate::device_errors::{DeviceLoss, allocating};
use crate::error::AoError;
use crate::gpu::{create_uniform_buffer, missing_storage_formats};
use crate::inputs::{AoInputs, InputError};
use crate::passes::PassContext;
use crate::passes::input::linear_depth::DepthInput;
use crate::passes::kernel::depth_mips::atlas_format;
use crate::plan::{At, FrameInputs, FramePlan, Kernel, Pass, Target};
use crate::record::{Passes, Views};
use crate::settings::{AoSettings, NormalSpace};
use crate::targets::{Layout, Targets};
use crate::timing::{PassTime, PassTimer};
use crate::uniforms::ViewUniforms;

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

/// Checks a frame's inputs against `settings` and the device; returns the input's size.
fn check_inputs(
    device: &wgpu::Device,
    settings: &AoSettings,
    inputs: &AoInputs<'_>,
) -> Result<[u32; 2], AoError> {
    let size = inputs.validate(settings.normals.encoding)?;
    inputs.projection.validate()?;
    let max = device.limits().max_texture_dimension_2d;
    if size[0] > max || size[1] > max {
        return Err(AoError::TooLarge { size, max });
    }
    // The decode pass normalises `to_view * n`: any scale is harmless, but a zero or
    // non-finite matrix turns every normal into garbage that the kernels would use as is.
    let world_normals = settings.normals.space == NormalSpace::World && inputs.normals.is_some();
    let determinant = glam::Mat3::from_mat4(inputs.view_from_world).determinant();
    if world_normals && !(determinant.is_finite() && determinant.abs() > 1e-6) {
        return Err(InputError::ViewFromWorld { determinant }.into());
    }
    if settings.reads_back_faces() && inputs.back_depth.is_none() {
        return Err(AoError::MissingBackDepth);
    }
    Ok(size)
}

/// What the plan needs to know of `inputs`, planned at `size` pixels.
fn describe(inputs: &AoInputs<'_>, size: [u32; 2]) -> FrameInputs {
    FrameInputs {
        size,
        normals: inputs.normals.is_some(),
        motion_vectors: inputs.motion_vectors.is_some(),
        mask: inputs.mask.is_some(),
        orthographic: inputs.projection.is_orthographic(),
        guard_band: inputs.guard_band > 0,
    }
}

/// With a guard band, the plan of the whole input, whose steps through the kernel run; `plan`
/// is the inner frame's, whose steps after the kernel run. Both grids must line up.
fn plan_band(
    settings: &AoSettings,
    inputs: &AoInputs<'_>,
    plan: &FramePlan,
) -> Result<Option<FramePlan>, AoError> {
    let band = inputs.guard_band;
    if band == 0 {
        return Ok(None);
    }
    let full = inputs.depth.size();
    let front = FramePlan::new(settings, &describe(inputs, full));
    if front.scale != plan.scale || !band.is_multiple_of(front.scale) {
        let scale = settings.resolution.scale();
        return Err(InputError::GuardBandResolution { band, scale }.into());
    }
    Ok(Some(front))
}

/// Copies the inner frame of each texture the steps after the kernel read from the whole
/// input's targets (`front`) into the inner frame's (`back`).
fn crop(
    encoder: &mut wgpu::CommandEncoder,
    front: &Targets,
    back: &Targets,
    plan: &FramePlan,
    band: u32,
) {
    let working = [
        Target::Ao,
        Target::BentNormals,
        Target::AoAndDepth,
        Target::WorkingLinearDepth,
        Target::WorkingNormals,
        Target::WorkingMotionVectors,
    ];
    let input = [Target::LinearDepth, Target::Normals];
    let cuts = working
        .map(|t| (t, band / plan.scale, plan.working))
        .into_iter()
        .chain(input.map(|t| (t, band, plan.size)));
    for (target, offset, [width, height]) in cuts {
        let (Some(from), Some(to)) = (front.get(target), back.get(target)) else {
            continue;
        };
        encoder.copy_texture_to_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &from.0,
                mip_level: 0,
                origin: wgpu::Origin3d {
                    x: offset,
                    y: offset,
                    z: 0,
                },
                aspect: wgpu::TextureAspect::All,
            },
            to.0.as_image_copy(),
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
        );
    }
}

/// What [`AoPipeline::encode`] produced. Each texture says its size: the input's, or
/// [`AoOutputs::working_size`] for what the kernel wrote before the upsample. With an
/// [`AoInputs::guard_band`], "the input's size" is the inner frame's, the output: every
/// texture here covers the inner frame, except the depth MIP chains, which the kernel read
/// over the whole input.
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
    /// texture itself when it is oct32 in view space (given as a view, the view's texture:
    /// bind `normals_view`, the view itself), else the input decoded (and turned into view
    /// space) or the normals reconstructed from depth. The kernel read these, or below full
    /// resolution the downsample's copy.
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
    /// size: [`AoOutputs::working_size`], or the input's with
    /// [`FilterResolution::Full`](crate::FilterResolution::Full).
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
///     normals: Some(normals.into()),
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
    passes: Passes,
    /// A view of the input normals of the last frame, kept for [`AoOutputs::normals_view`] when
    /// the kernels read them as they are.
    input_normals_view: Option<wgpu::TextureView>,
    targets: Option<Targets>,
    /// With a guard band: the view uniforms and the targets of the steps through the kernel,
    /// which run on the whole input; `targets` then holds the inner frame's.
    band_view_uniforms: wgpu::Buffer,
    band_working_view_uniforms: wgpu::Buffer,
    front_targets: Option<Targets>,
    timer: Option<PassTimer>,
    /// Filled by the device's lost callback.
    loss: DeviceLoss,
}

impl AoPipeline {
    /// Compiles the passes the settings need. Fails, naming the field, when the settings are
    /// out of range, with [`AoError::Fp16DepthMipsUnsupported`] when they ask for an fp16
    /// depth MIP chain the device cannot write, with [`AoError::StorageFormats`] on a
    /// device that cannot write the storage textures the passes write, and with
    /// [`AoError::OutOfMemory`] when its buffers and noise textures do not fit.
    ///
    /// Sets the device's lost callback, so that the calls after a device loss return
    /// [`AoError::DeviceLost`]. A device has one: a renderer with a callback of its own, or
    /// more than one pipeline on the device, forwards to each pipeline's
    /// [`AoPipeline::device_lost_callback`].
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
        let loss = DeviceLoss::watch(device);
        allocating(
            device,
            || "the pipeline's buffers and noise textures".to_string(),
            || Self {
                settings: *settings,
                view_uniforms: create_uniform_buffer::<ViewUniforms>(device, "aokit view"),
                working_view_uniforms: create_uniform_buffer::<ViewUniforms>(
                    device,
                    "aokit working view",
                ),
                band_view_uniforms: create_uniform_buffer::<ViewUniforms>(
                    device,
                    "aokit band view",
                ),
                band_working_view_uniforms: create_uniform_buffer::<ViewUniforms>(
                    device,
                    "aokit band working view",
                ),
                passes: Passes::new(device, queue, settings),
                input_normals_view: None,
                targets: None,
                front_targets: None,
                timer: None,
                loss,
            },
        )
    }

    /// A device-lost callback that makes this pipeline's next calls return
    /// [`AoError::DeviceLost`], for a renderer that sets a callback of its own (which replaces
    /// the one [`AoPipeline::new`] set) or runs several pipelines on one device: call it from
    /// yours.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), aokit::AoError> {
    /// use aokit::{AoError, AoPipeline, AoSettings};
    /// let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default())?;
    /// let aokit_lost = pipeline.device_lost_callback();
    /// device.set_device_lost_callback(move |reason, message| {
    ///     eprintln!("device lost: {reason:?} {message}");
    ///     aokit_lost(reason, message);
    /// });
    /// device.destroy();
    /// // wgpu runs the callback while polling, once the queue is idle.
    /// device.poll(wgpu::PollType::wait_indefinitely()).ok();
    /// let err = pipeline.set_settings(device, queue, &AoSettings::default()).unwrap_err();
    /// assert!(matches!(err, AoError::DeviceLost { .. }), "{err}");
    /// # Ok(()) }
    /// ```
    pub fn device_lost_callback(&self) -> impl Fn(wgpu::DeviceLostReason, String) + Send + 'static {
        self.loss.callback()
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
        self.loss.check()?;
        check_settings(device, settings)?;
        self.settings = *settings;
        self.passes.set_settings(device, queue, settings);
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
        self.loss.check()?;
        let settings = self.settings;
        let size = check_inputs(device, &settings, inputs)?;
        let plan = FramePlan::new(&settings, &describe(inputs, size));
        let front_plan = plan_band(&settings, inputs, &plan)?;
        let layout = Layout::of(&plan);
        let (layout, front_layout) = match &front_plan {
            Some(front) => (
                layout.after_kernel(),
                Some(Layout::of(front).through_kernel()),
            ),
            None => (layout, None),
        };
        let pair = self.passes.pair;
        if self.targets.as_ref().map(|t| t.layout) != Some(layout)
            || self.front_targets.as_ref().map(|t| t.layout) != front_layout
        {
            // The old textures go first, so that they do not count against the new ones.
            self.targets = None;
            self.front_targets = None;
            let what = || {
                format!(
                    "the intermediate textures of a {}x{} frame",
                    size[0], size[1]
                )
            };
            self.targets = Some(allocating(device, what, || {
                Targets::new(device, layout, pair)
            })?);
            if let Some(front_layout) = front_layout {
                self.front_targets = Some(allocating(device, what, || {
                    Targets::new(device, front_layout, pair)
                })?);
            }
        }
        let targets = self.targets.as_ref().expect("targets were just made");
        let (projection, frame_index) = (&inputs.projection, inputs.frame_index);
        let uniforms = ViewUniforms::new(projection, size, frame_index);
        queue.write_buffer(&self.view_uniforms, 0, bytemuck::bytes_of(&uniforms));
        // Written at full resolution too (where it equals the other): the working steps bind
        // it whatever the resolution.
        let scaled = ViewUniforms::scaled(projection, size, plan.scale, frame_index);
        queue.write_buffer(&self.working_view_uniforms, 0, bytemuck::bytes_of(&scaled));

        let whole = wgpu::TextureAspect::All;
        self.input_normals_view = inputs.normals.map(|n| n.bind(whole));
        let motion_vectors = inputs.motion_vectors.map(|t| t.bind(whole));
        let input_depth = DepthInput::view(&inputs.depth);
        let mut views = Views {
            targets,
            input_depth: &input_depth,
            input_normals: self.input_normals_view.as_ref(),
            motion_vectors: motion_vectors.as_ref(),
            history: None,
        };
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
        let mut steps = &plan.steps[..];
        if let Some(front) = &front_plan {
            // The steps through the kernel on the whole input, with the widened projection;
            // the per-pixel kernels shade the inner frame only (`kernel_offset`), the others
            // all of it. Then the inner frame of what the later steps read is cut out.
            let band = inputs.guard_band;
            let widened = projection.with_guard_band(size, band);
            let uniforms = ViewUniforms::new(&widened, front.size, frame_index);
            queue.write_buffer(&self.band_view_uniforms, 0, bytemuck::bytes_of(&uniforms));
            let mut scaled = ViewUniforms::scaled(&widened, front.size, front.scale, frame_index);
            scaled.kernel_offset = [band / front.scale; 2];
            let working = &self.band_working_view_uniforms;
            queue.write_buffer(working, 0, bytemuck::bytes_of(&scaled));
            let front_targets = self.front_targets.as_ref().expect("made with the targets");
            let front_views = Views {
                targets: front_targets,
                ..views
            };
            for step in &front.steps[..front.through_kernel()] {
                (ctx.size, ctx.view_uniforms) = match step.pass {
                    Pass::Kernel {
                        kernel: Kernel::Method { .. },
                        ..
                    } => (plan.working, working),
                    _ => match step.at {
                        At::Input => (front.size, &self.band_view_uniforms),
                        At::Working => (front.working, working),
                    },
                };
                self.passes
                    .record(&mut ctx, queue, &settings, inputs, step, &front_views);
            }
            views = Views {
                targets,
                ..front_views
            };
            crop(ctx.encoder, front_targets, targets, &plan, band);
            steps = &plan.steps[plan.through_kernel()..];
        }
        for step in steps {
            (ctx.size, ctx.view_uniforms) = match step.at {
                At::Input => (size, &self.view_uniforms),
                At::Working => (plan.working, &self.working_view_uniforms),
            };
            self.passes
                .record(&mut ctx, queue, &settings, inputs, step, &views);
            if let Pass::Temporal { .. } = step.pass {
                let history = &self.passes.histories[&inputs.view_id];
                views.history = history.as_ref().map(|h| h.ao().clone());
            }
        }
        if views.history.is_none() {
            // Off, histories go: when it is turned on again the old frames are stale.
            self.passes.histories.clear();
        }
        if let Some(timer) = &self.timer {
            timer.resolve(encoder);
        }
        Ok(self.outputs(&plan, inputs))
    }

    /// The textures `plan` left its results in.
    fn outputs<'a>(&'a self, plan: &FramePlan, inputs: &AoInputs<'a>) -> AoOutputs<'a> {
        let targets = self.targets.as_ref().expect("made by encode");
        let history = self
            .passes
            .histories
            .get(&inputs.view_id)
            .and_then(Option::as_ref);
        let made = |target| targets.get(target).expect("the plan's targets are made");
        let ao = match plan.ao {
            Target::History => history.expect("the temporal filter ran").ao(),
            target => made(target),
        };
        let (normals, normals_view) = match plan.normals {
            Target::InputNormals => (
                inputs
                    .normals
                    .expect("planned with input normals")
                    .texture(),
                self.input_normals_view.as_ref().expect("made by encode"),
            ),
            target => (&made(target).0, &made(target).1),
        };
        let bent_normals = plan.bent_normals.map(made);
        // With a guard band the kernel's depth chains cover the whole input.
        let kernel_targets = self.front_targets.as_ref().unwrap_or(targets);
        let optional = |target| kernel_targets.get(target).map(|(texture, _)| texture);
        AoOutputs {
            ao: &ao.0,
            ao_view: &ao.1,
            raw_ao: &targets.ao.0,
            raw_ao_view: &targets.ao.1,
            working_size: plan.working,
            linear_depth: &targets.linear_depth.0,
            working_linear_depth: &made(plan.working_depth).0,
            normals,
            normals_view,
            bent_normals: bent_normals.map(|(texture, _)| texture),
            bent_normals_view: bent_normals.map(|(_, view)| view),
            history_rejected: history.map(|h| &h.rejected().0),
            depth_mips: optional(Target::DepthMips),
            depth_mip_atlas: optional(Target::DepthMipAtlas),
        }
    }
}
