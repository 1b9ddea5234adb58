//! AO for G-buffer passes that come from files or another renderer rather than the raster.

mod convert;

pub use convert::{DepthKind, linear_depth, view_normals};

use aokit::gpu::{TextureReadback, upload_texture_2d};
use aokit::normals::encode_texels;
use aokit::{
    AoInputs, AoPipeline, AoSettings, GpuContext, GpuError, NormalEncoding, PassTime, Projection,
};
use glam::{Mat4, Vec3};

use crate::renderer::RenderError;

/// One view's passes on the CPU, row-major from the top-left pixel.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, depth: Vec<f32>, normals: Vec<glam::Vec3>)
/// #     -> Result<(), aokit_scene::RenderError> {
/// use aokit::{AoSettings, Projection};
/// use aokit_scene::external::{Passes, ambient_occlusion};
/// // Another renderer's 1280x720 export: linear depth and view-space normals.
/// let passes = Passes {
///     size: [1280, 720],
///     linear_depth: &depth,
///     normals: Some(&normals),
///     back_depth: None,
///     projection: Projection::perspective(1.0, 1280.0 / 720.0, 0.1, None),
/// };
/// let ao = ambient_occlusion(gpu, &AoSettings::default(), &passes, 0)?;
/// # Ok(()) }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Passes<'a> {
    /// Width and height in pixels.
    pub size: [u32; 2],
    /// Linear view depth; 0, negative, NaN or infinity where there is no surface.
    pub linear_depth: &'a [f32],
    /// View-space unit normals, or `None` to reconstruct them from depth.
    pub normals: Option<&'a [Vec3]>,
    /// Linear view depth of the nearest back faces, as `linear_depth`, for
    /// [`aokit::VbaoSettings::back_faces`].
    pub back_depth: Option<&'a [f32]>,
    /// The camera's projection.
    pub projection: Projection,
}

/// Passes uploaded once, with a pipeline to run any settings on them. The normals are uploaded
/// in the settings' [`NormalEncoding`], and again when a later setting changes it, so the AO
/// shows the encoding's precision as the raster's does.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, passes: &aokit_scene::external::Passes<'_>)
/// #     -> Result<(), aokit_scene::RenderError> {
/// use aokit::{AoSettings, Method, Preset};
/// use aokit_scene::external::ExternalAo;
/// // Upload once, then compare methods on the same passes.
/// let mut external = ExternalAo::new(gpu, &AoSettings::default(), passes)?;
/// for method in Method::ALL {
///     external.set_settings(gpu, &AoSettings::preset(method, Preset::High))?;
///     let ao = external.run(gpu, 0)?;
///     println!("{}: mean AO {}", method.name(), ao.iter().sum::<f32>() / ao.len() as f32);
/// }
/// # Ok(()) }
/// ```
pub struct ExternalAo {
    depth: wgpu::Texture,
    back_depth: Option<wgpu::Texture>,
    /// The unit normals as given, kept to encode them again for another encoding.
    source_normals: Option<Vec<Vec3>>,
    normals: Option<wgpu::Texture>,
    projection: Projection,
    /// The camera's world-to-view transform, for the temporal filter's reprojection.
    view_from_world: Mat4,
    pipeline: AoPipeline,
    /// Start the temporal history over at the next run.
    reset_history: bool,
    /// Pixels of overscan on each side of the passes ([`AoInputs::guard_band`]).
    guard_band: u32,
}

impl ExternalAo {
    /// Uploads `passes` and compiles the pipeline for `settings`.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, passes: &aokit_scene::external::Passes<'_>)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::{AoSettings, NormalEncoding};
    /// use aokit_scene::external::ExternalAo;
    /// let mut settings = AoSettings::default();
    /// // What the AO would look like with a 16-bit normal buffer.
    /// settings.normals.encoding = NormalEncoding::Oct16;
    /// let mut external = ExternalAo::new(gpu, &settings, passes)?;
    /// let ao = external.run(gpu, 0)?;
    /// # Ok(()) }
    /// ```
    pub fn new(
        gpu: &GpuContext,
        settings: &AoSettings,
        passes: &Passes<'_>,
    ) -> Result<Self, RenderError> {
        let uploaded = Uploaded::new(gpu, passes)?;
        let mut external = Self {
            depth: uploaded.depth,
            back_depth: uploaded.back_depth,
            source_normals: uploaded.source_normals,
            normals: None,
            projection: passes.projection,
            view_from_world: Mat4::IDENTITY,
            pipeline: AoPipeline::new(&gpu.device, &gpu.queue, settings)?,
            reset_history: false,
            guard_band: 0,
        };
        external.upload_normals(gpu, settings.normals.encoding)?;
        Ok(external)
    }

    /// Reads the passes as an overscan of `band` pixels on each side ([`AoInputs::guard_band`]):
    /// [`Passes::projection`] is then the inner frame's, and the AO comes back for the inner
    /// frame only, `2 * band` pixels narrower and shorter than the passes. 0, the default,
    /// is no band.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, passes: &aokit_scene::external::Passes<'_>)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::AoSettings;
    /// use aokit_scene::external::ExternalAo;
    /// // Passes exported 16 px larger on each side than the image they light.
    /// let mut external = ExternalAo::new(gpu, &AoSettings::default(), passes)?;
    /// external.set_guard_band(16);
    /// let ao = external.run(gpu, 0)?;
    /// assert_eq!(ao.len() as u32, (passes.size[0] - 32) * (passes.size[1] - 32));
    /// # Ok(()) }
    /// ```
    pub fn set_guard_band(&mut self, band: u32) {
        self.guard_band = band;
    }

    /// Replaces the passes with `passes` (of any size), keeping the compiled pipeline and, for
    /// the temporal filter, the history: the next frame of a sequence, or another view run with
    /// the same settings without compiling the pipeline again.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, frames: &[aokit_scene::external::Passes<'_>])
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::AoSettings;
    /// use aokit_scene::external::ExternalAo;
    /// let mut external = ExternalAo::new(gpu, &AoSettings::default(), &frames[0])?;
    /// for (index, passes) in frames.iter().enumerate() {
    ///     external.set_passes(gpu, passes)?;
    ///     let ao = external.run(gpu, index as u32)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn set_passes(&mut self, gpu: &GpuContext, passes: &Passes<'_>) -> Result<(), RenderError> {
        let uploaded = Uploaded::new(gpu, passes)?;
        self.depth = uploaded.depth;
        self.back_depth = uploaded.back_depth;
        self.source_normals = uploaded.source_normals;
        self.projection = passes.projection;
        self.upload_normals(gpu, self.pipeline.settings().normals.encoding)?;
        Ok(())
    }

    /// Sets where the camera of the passes stands: its world-to-view transform
    /// ([`AoInputs::view_from_world`]; the identity until set). The temporal filter reprojects
    /// each run's history through the change from the last run's camera, so a sequence from a
    /// moving camera sets each frame's before running it; a still camera needs none.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext,
    /// #      frames: &[(aokit_scene::external::Passes<'_>, glam::Mat4)])
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::AoSettings;
    /// use aokit_scene::external::ExternalAo;
    /// let mut settings = AoSettings::default();
    /// settings.temporal.enabled = true;
    /// let mut external = ExternalAo::new(gpu, &settings, &frames[0].0)?;
    /// for (index, (passes, view_from_world)) in frames.iter().enumerate() {
    ///     external.set_passes(gpu, passes)?;
    ///     external.set_view_from_world(*view_from_world);
    ///     let ao = external.run(gpu, index as u32)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn set_view_from_world(&mut self, view_from_world: Mat4) {
        self.view_from_world = view_from_world;
    }

    /// Starts the temporal history over at the next run, as for the first frame of another
    /// sequence.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// external.reset_history();
    /// let first = external.run(gpu, 0)?;
    /// # Ok(()) }
    /// ```
    pub fn reset_history(&mut self) {
        self.reset_history = true;
    }

    /// The settings the pipeline runs.
    ///
    /// ```no_run
    /// # fn f(external: &aokit_scene::external::ExternalAo) {
    /// println!("radius {}", external.settings().radius);
    /// # }
    /// ```
    pub fn settings(&self) -> &AoSettings {
        self.pipeline.settings()
    }

    /// Uploads the normals in `encoding`.
    fn upload_normals(
        &mut self,
        gpu: &GpuContext,
        encoding: NormalEncoding,
    ) -> Result<(), GpuError> {
        let size = [self.depth.width(), self.depth.height()];
        self.normals = self
            .source_normals
            .as_deref()
            .map(|normals| {
                upload_texture_2d(
                    &gpu.device,
                    &gpu.queue,
                    "external normals",
                    size,
                    encoding.texture_format(),
                    &encode_texels(encoding, normals),
                )
            })
            .transpose()?;
        Ok(())
    }

    /// Changes the settings for later runs; the next run starts the temporal history over.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::AoSettings;
    /// for radius in [0.25, 0.5, 1.0, 2.0] {
    ///     external.set_settings(gpu, &AoSettings { radius, ..AoSettings::default() })?;
    ///     let ao = external.run(gpu, 0)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn set_settings(
        &mut self,
        gpu: &GpuContext,
        settings: &AoSettings,
    ) -> Result<(), RenderError> {
        let encoding = settings.normals.encoding;
        let reencode = encoding != self.pipeline.settings().normals.encoding;
        self.pipeline
            .set_settings(&gpu.device, &gpu.queue, settings)?;
        if reencode {
            self.upload_normals(gpu, encoding)?;
        }
        // Other settings make other AO: the temporal filter must not blend in the old runs.
        self.reset_history = true;
        Ok(())
    }

    /// Times the AO passes of later runs; `false` when the device has no timestamps.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// if external.enable_timing(gpu) {
    ///     external.run(gpu, 0)?;
    ///     for pass in external.last_times(gpu).expect("timing is on")? {
    ///         println!("{:>16} {:.3} ms", pass.name, pass.ms);
    ///     }
    /// }
    /// # Ok(()) }
    /// ```
    pub fn enable_timing(&mut self, gpu: &GpuContext) -> bool {
        self.pipeline.enable_timing(&gpu.device, &gpu.queue)
    }

    /// GPU time of each pass of the last run, when timing is on: see
    /// [`ExternalAo::enable_timing`].
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), Box<dyn std::error::Error>> {
    /// if external.enable_timing(gpu) {
    ///     external.run(gpu, 0)?;
    ///     for time in external.last_times(gpu).transpose()?.unwrap_or_default() {
    ///         println!("{}: {:.3} ms", time.name, time.ms);
    ///     }
    /// }
    /// # Ok(()) }
    /// ```
    pub fn last_times(&self, gpu: &GpuContext) -> Option<Result<Vec<PassTime>, GpuError>> {
        self.pipeline.last_pass_times(&gpu.device)
    }

    /// Runs the pipeline and reads the AO back (1 = unoccluded). Runs after the first are
    /// frames of one sequence, for the temporal filter:
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// // Let the temporal filter converge on the still passes, then keep the last frame.
    /// let mut ao = Vec::new();
    /// for frame in 0..16 {
    ///     ao = external.run(gpu, frame)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn run(&mut self, gpu: &GpuContext, frame_index: u32) -> Result<Vec<f32>, RenderError> {
        Ok(self.run_outputs(gpu, frame_index, false)?.0)
    }

    /// [`ExternalAo::run`], also reading back the bent normals where the settings compute them
    /// ([`AoSettings::bent_normals`]): per pixel the mean unoccluded direction in view space
    /// and the kernel's AO, `[x, y, z, ao]`.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// let (ao, bent) = external.run_with_bent_normals(gpu, 0)?;
    /// if let Some(bent) = bent {
    ///     let [x, y, z, _] = bent[0];
    ///     println!("AO {} towards ({x}, {y}, {z})", ao[0]);
    /// }
    /// # Ok(()) }
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn run_with_bent_normals(
        &mut self,
        gpu: &GpuContext,
        frame_index: u32,
    ) -> Result<(Vec<f32>, Option<Vec<[f32; 4]>>), RenderError> {
        self.run_outputs(gpu, frame_index, true)
    }

    #[allow(clippy::type_complexity)]
    fn run_outputs(
        &mut self,
        gpu: &GpuContext,
        frame_index: u32,
        bent: bool,
    ) -> Result<(Vec<f32>, Option<Vec<[f32; 4]>>), RenderError> {
        self.submit(gpu, frame_index, bent)?.wait(gpu)
    }

    /// Submits a run ([`ExternalAo::run`]; with `bent_normals`,
    /// [`ExternalAo::run_with_bent_normals`]) with the copies of its outputs to the CPU, and
    /// returns without waiting for the GPU. The pipeline may take the next frame's passes and
    /// submit it before this run is read: the GPU works through the frames back to back while
    /// the CPU prepares the next and reads the last, and each frame's AO is the one `run` gives.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, frames: &[aokit_scene::external::Passes<'_>])
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// use aokit::AoSettings;
    /// use aokit_scene::external::ExternalAo;
    /// let mut external = ExternalAo::new(gpu, &AoSettings::default(), &frames[0])?;
    /// let mut pending = None;
    /// for (index, passes) in frames.iter().enumerate() {
    ///     // Uploaded while the GPU still runs the frame before.
    ///     external.set_passes(gpu, passes)?;
    ///     let submitted = external.submit(gpu, index as u32, false)?;
    ///     if let Some(previous) = pending.replace(submitted) {
    ///         let (ao, _) = previous.wait(gpu)?;
    ///     }
    /// }
    /// if let Some(last) = pending {
    ///     let (ao, _) = last.wait(gpu)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn submit(
        &mut self,
        gpu: &GpuContext,
        frame_index: u32,
        bent_normals: bool,
    ) -> Result<SubmittedRun, RenderError> {
        let (device, queue) = (&gpu.device, &gpu.queue);
        let mut encoder = device.create_command_encoder(&Default::default());
        let outputs = self.pipeline.encode(
            device,
            queue,
            &mut encoder,
            &AoInputs {
                normals: self.normals.as_ref().map(Into::into),
                view_from_world: self.view_from_world,
                frame_index,
                reset_history: std::mem::take(&mut self.reset_history),
                back_depth: self.back_depth.as_ref().map(Into::into),
                guard_band: self.guard_band,
                ..AoInputs::new(&self.depth, self.projection)
            },
        )?;
        // The copies run in the same submission as the passes, so the next frame's passes,
        // which write the same output textures, cannot overwrite them first.
        let ao = TextureReadback::encode(device, &mut encoder, outputs.ao)?;
        let bent_normals = match (bent_normals, outputs.bent_normals) {
            (true, Some(texture)) => Some(TextureReadback::encode(device, &mut encoder, texture)?),
            _ => None,
        };
        let submission = queue.submit([encoder.finish()]);
        Ok(SubmittedRun {
            ao,
            bent_normals,
            submission,
        })
    }
}

/// A run of [`ExternalAo::submit`] on the GPU, its outputs not yet read.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
/// #     -> Result<(), aokit_scene::RenderError> {
/// use aokit_scene::external::SubmittedRun;
/// let submitted: SubmittedRun = external.submit(gpu, 0, false)?;
/// // ... upload and submit the next frame ...
/// let (ao, _) = submitted.wait(gpu)?;
/// # Ok(()) }
/// ```
pub struct SubmittedRun {
    ao: TextureReadback,
    bent_normals: Option<TextureReadback>,
    submission: wgpu::SubmissionIndex,
}

impl SubmittedRun {
    /// Waits for the run (not for runs submitted after it) and reads its AO back, with the
    /// bent normals where they were asked for and the settings compute them.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, external: &mut aokit_scene::external::ExternalAo)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// let (ao, bent) = external.submit(gpu, 0, true)?.wait(gpu)?;
    /// # Ok(()) }
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn wait(self, gpu: &GpuContext) -> Result<(Vec<f32>, Option<Vec<[f32; 4]>>), RenderError> {
        let device = &gpu.device;
        let ao = self.ao.f32_texels(device, Some(self.submission.clone()))?;
        let bent_normals = self
            .bent_normals
            .map(|bent| bent.rgba16f_texels(device, Some(self.submission)))
            .transpose()?;
        Ok((ao, bent_normals))
    }
}

/// One view's passes on the GPU, the normals still on the CPU for their encoding.
struct Uploaded {
    depth: wgpu::Texture,
    back_depth: Option<wgpu::Texture>,
    /// The unit normals as given.
    source_normals: Option<Vec<Vec3>>,
}

impl Uploaded {
    fn new(gpu: &GpuContext, passes: &Passes<'_>) -> Result<Self, RenderError> {
        let upload = |label, depth: &[f32]| {
            upload_texture_2d(
                &gpu.device,
                &gpu.queue,
                label,
                passes.size,
                wgpu::TextureFormat::R32Float,
                bytemuck::cast_slice(depth),
            )
        };
        if let Some(normals) = passes.normals {
            check_normals(normals, passes.linear_depth, passes.size)?;
        }
        Ok(Self {
            depth: upload("external linear depth", passes.linear_depth)?,
            back_depth: passes
                .back_depth
                .map(|back| upload("external back-face depth", back))
                .transpose()?,
            source_normals: passes
                .normals
                .map(|normals| normals.iter().map(|n| n.normalize_or(Vec3::Z)).collect()),
        })
    }
}

/// Refuses normals that are zero, NaN, infinite or far from unit length at a pixel showing a
/// surface: normalising them falls back to a normal facing the camera, which the kernels take
/// for a real one and the AO darkens without a word (the room's mean AO 0.95 to 0.28 with
/// zero normals). Pixels without a surface may hold anything. The bound is the one the
/// pipeline's decode holds normal textures to ([`aokit::normals::is_usable`]), where it falls
/// back to normals from depth instead: a file of normals is checked whole, so its errors are
/// reported rather than patched.
fn check_normals(
    normals: &[Vec3],
    linear_depth: &[f32],
    size: [u32; 2],
) -> Result<(), RenderError> {
    let mut bad = normals
        .iter()
        .zip(linear_depth)
        .enumerate()
        .filter(|(_, (n, d))| d.is_finite() && **d > 0.0 && !aokit::normals::is_usable(**n));
    let Some((first, (example, _))) = bad.next() else {
        return Ok(());
    };
    let count = 1 + bad.count();
    let width = size[0].max(1) as usize;
    Err(RenderError::Normals(format!(
        "{count} pixels showing a surface have a normal that is zero, NaN, infinite or not of \
         unit length (e.g. {example} at x {}, y {}); give unit normals, or none to reconstruct \
         them from depth",
        first % width,
        first / width
    )))
}

/// Runs the AO pipeline once on `passes` and reads the AO back (1 = unoccluded).
///
/// ```no_run
/// use aokit::{AoSettings, Projection};
/// use aokit_scene::external::{Passes, ambient_occlusion};
/// let gpu = aokit::GpuContext::headless()?;
/// // A wall facing the camera at depth 2: nothing occludes it. Normals come from depth.
/// let depth = vec![2.0f32; 64 * 64];
/// let passes = Passes {
///     size: [64, 64],
///     linear_depth: &depth,
///     normals: None,
///     back_depth: None,
///     projection: Projection::perspective(1.0, 1.0, 0.1, None),
/// };
/// let ao = ambient_occlusion(&gpu, &AoSettings::default(), &passes, 0)?;
/// assert!(ao.iter().all(|&a| a > 0.99));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn ambient_occlusion(
    gpu: &GpuContext,
    settings: &AoSettings,
    passes: &Passes<'_>,
    frame_index: u32,
) -> Result<Vec<f32>, RenderError> {
    ExternalAo::new(gpu, settings, passes)?.run(gpu, frame_index)
}
