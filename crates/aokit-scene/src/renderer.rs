//! Renders a scene through the AO pipeline and reads the results back.

use aokit::debug::{AoDebug, DebugStyle, DebugView};
use aokit::gpu::{
    create_texture_2d, read_texture, read_texture_f32, read_texture_rg16f, read_texture_rgba16f,
};
use aokit::{
    AoError, AoInputs, AoPipeline, AoSettings, GpuContext, GpuError, PassTime, Projection,
};
use glam::{Mat4, Vec2, Vec3};

use crate::camera::Camera;
use crate::composite::{CompositePass, CompositeView, LIT_FORMAT, Lighting, SpecularOcclusion};
use crate::gbuffer::{GBuffer, GBufferCamera, GBufferPass, GpuMesh};
use crate::scene::Scene;
use crate::shadow::{ShadowPass, SunView};

/// One rendered view, on the CPU, row by row from the top-left pixel.
///
/// ```no_run
/// # fn f(frame: &aokit_scene::Frame) {
/// let [width, height] = frame.size;
/// let centre = (height / 2 * width + width / 2) as usize;
/// // Depth 0 marks the sky: no surface, so no AO to speak of.
/// if frame.linear_depth[centre] > 0.0 {
///     println!("AO {} at depth {}", frame.ao[centre], frame.linear_depth[centre]);
/// }
/// let covered = frame.linear_depth.iter().filter(|&&d| d > 0.0).count();
/// # }
/// ```
#[derive(Clone, Debug)]
pub struct Frame {
    /// Width and height in pixels.
    pub size: [u32; 2],
    /// The projection used.
    pub projection: Projection,
    /// The world-to-view transform used.
    pub view_from_world: Mat4,
    /// AO, 1 = unoccluded.
    pub ao: Vec<f32>,
    /// Lit image, RGBA8, sRGB-encoded.
    pub lit: Vec<u8>,
    /// Linear view depth, 0 where nothing was drawn.
    pub linear_depth: Vec<f32>,
    /// The view-space unit normals the AO used, zero where nothing was drawn: the G-buffer's,
    /// decoded from [`NormalsSettings::encoding`](aokit::NormalsSettings::encoding) (so with its
    /// precision), or reconstructed from depth as
    /// [`NormalsSettings::source`](aokit::NormalsSettings::source) asks.
    pub normals: Vec<Vec3>,
    /// With the temporal filter on, 1 where this frame rejected its history (disocclusions,
    /// the screen's edges, a reset), 0 where it blended, at the size the filters ran at
    /// ([`AoSettings::filter_resolution`](aokit::AoSettings::filter_resolution)): `size`, or
    /// below full resolution the working size.
    pub history_rejected: Option<(Vec<f32>, [u32; 2])>,
    /// View-space bent normals, when the settings given to the [`Renderer`] ask for them (not
    /// when only the composite's GTSO turned them on).
    pub bent_normals: Option<Vec<Vec3>>,
    /// Linear view depth of the nearest back faces, 0 where none was drawn, when the settings
    /// measure VBAO's occluders from them ([`aokit::VbaoSettings::back_faces`]).
    pub back_depth: Option<Vec<f32>>,
    /// The G-buffer's motion vectors: the offset in pixels (y down) from each pixel's centre to
    /// where its surface was in the previous frame of the sequence; 0 where nothing was drawn
    /// and in a sequence's first frame.
    pub motion_vectors: Vec<Vec2>,
    /// The [`Renderer::debug_views`] asked for, each an RGBA8 image of `size`, depth shown
    /// from the nearest to the farthest surface in view.
    pub debug: Vec<(DebugView, Vec<u8>)>,
}

/// Why a frame could not be rendered.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
/// #      camera: &aokit_scene::Camera) {
/// use aokit_scene::RenderError;
/// match renderer.render(gpu, camera, [100_000, 100], 0) {
///     Err(RenderError::Size { reason, .. }) => eprintln!("pick a smaller image: {reason}"),
///     Err(other) => eprintln!("{other}"),
///     Ok(frame) => println!("{} pixels", frame.ao.len()),
/// }
/// # }
/// ```
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The resolution is empty or beyond the device.
    #[error("resolution {width}x{height} is not usable: {reason}")]
    Size {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
        /// Why not.
        reason: String,
    },
    /// The camera is degenerate.
    #[error("{0}")]
    Camera(String),
    /// Normals handed in on the CPU are unusable where there is a surface.
    #[error("normals: {0}")]
    Normals(String),
    /// The AO pipeline refused its inputs or settings.
    #[error(transparent)]
    Ao(#[from] AoError),
    /// Reading back failed.
    #[error(transparent)]
    Gpu(#[from] GpuError),
}

/// A scene on the GPU with the passes to render it.
///
/// A moving sequence, where the temporal filter and the motion vectors carry from frame to
/// frame:
///
/// ```no_run
/// use aokit::AoSettings;
/// use aokit_scene::{CameraPath, Renderer, Scene};
/// let gpu = aokit::GpuContext::headless()?;
/// let scene = Scene::open("room")?;
/// let start = scene.camera(Some("front"))?;
/// let mut settings = AoSettings::default();
/// settings.temporal.enabled = true;
/// let mut renderer = Renderer::new(&gpu, &scene, &settings)?;
/// let frames = 8;
/// for frame in 0..frames {
///     let t = frame as f32 / (frames - 1) as f32;
///     let camera = CameraPath::Orbit.at(&start, t);
///     let image = renderer.render_at(&gpu, &camera, [480, 270], frame, t)?;
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Renderer {
    mesh: GpuMesh,
    bounds: crate::mesh::Bounds,
    gbuffer_pass: GBufferPass,
    shadow_pass: ShadowPass,
    composite: CompositePass,
    ao: AoPipeline,
    /// The AO settings as the caller gave them; the pipeline may run them with bent normals on
    /// (see [`Renderer::pipeline_settings`]).
    settings: AoSettings,
    /// Lighting of the lit composite. [`SpecularOcclusion::Gtso`] makes the next frames compute
    /// bent normals when the method can (see [`Renderer::pipeline_settings`]).
    pub lighting: Lighting,
    /// Hand the G-buffer's motion vectors to the temporal filter (the default). Off, it
    /// reprojects by depth and the camera alone, which does not follow moving parts; for
    /// comparisons (docs/denoise.md measures both).
    pub use_motion_vectors: bool,
    /// Debug views to draw with every frame into [`Frame::debug`].
    pub debug_views: Vec<DebugView>,
    /// Pixels of overscan the AO reads on each side ([`AoInputs::guard_band`]): with more
    /// than 0 each frame also draws a G-buffer that much larger, through the widened frustum
    /// ([`Projection::with_guard_band`](aokit::Projection::with_guard_band)), for the AO
    /// pipeline (its motion vectors too); the frame's images and the lit composite stay the
    /// camera's own.
    pub guard_band: u32,
    /// Compiled the first time a debug view is asked for.
    debug: Option<AoDebug>,
    /// Start the temporal history over at the next frame.
    reset_history: bool,
    /// Camera (clip from world) and scene time of the last frame, for motion vectors; `None`
    /// before the first frame of a sequence.
    previous: Option<(Mat4, f32)>,
}

impl Renderer {
    /// Uploads `scene` and compiles the passes for `settings`.
    ///
    /// ```no_run
    /// use aokit::{AoSettings, Method, Preset};
    /// use aokit_scene::{Renderer, Scene};
    /// let gpu = aokit::GpuContext::headless()?;
    /// let scene = Scene::open("stairs")?;
    /// let mut settings = AoSettings::preset(Method::Hbao, Preset::Medium);
    /// // The scene's own scale, rather than the default of one unit.
    /// settings.radius = scene.suggested_radius.unwrap_or(settings.radius);
    /// let renderer = Renderer::new(&gpu, &scene, &settings)?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new(
        gpu: &GpuContext,
        scene: &Scene,
        settings: &AoSettings,
    ) -> Result<Self, RenderError> {
        let lighting = Lighting::default();
        Ok(Self {
            mesh: GpuMesh::new(&gpu.device, &scene.mesh, &scene.moving_parts),
            bounds: scene.bounds,
            gbuffer_pass: GBufferPass::new(&gpu.device),
            shadow_pass: ShadowPass::new(&gpu.device),
            composite: CompositePass::new(&gpu.device),
            ao: AoPipeline::new(
                &gpu.device,
                &gpu.queue,
                &pipeline_settings(settings, &lighting),
            )?,
            settings: *settings,
            lighting,
            use_motion_vectors: true,
            debug_views: Vec::new(),
            guard_band: 0,
            debug: None,
            reset_history: false,
            previous: None,
        })
    }

    /// Makes the next frame start a new sequence, as after a camera cut: the temporal filter's
    /// history starts over and the frame has no motion. Frames rendered one after the other are
    /// otherwise taken as a sequence: each reprojects the previous one, and its motion vectors
    /// lead there.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      scene: &aokit_scene::Scene) -> Result<(), Box<dyn std::error::Error>> {
    /// // One image per camera of the scene: each is a cut, not a move.
    /// for (i, camera) in scene.cameras.iter().enumerate() {
    ///     renderer.reset_history();
    ///     let frame = renderer.render(gpu, camera, [640, 360], i as u32)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn reset_history(&mut self) {
        self.reset_history = true;
    }

    /// The AO settings as given to [`Renderer::new`] or [`Renderer::set_settings`].
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer)
    /// #     -> Result<(), aokit_scene::RenderError> {
    /// // Halve the radius, keeping everything else.
    /// let mut settings = *renderer.settings();
    /// settings.radius *= 0.5;
    /// renderer.set_settings(gpu, &settings)?;
    /// # Ok(()) }
    /// ```
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// The settings the AO pipeline runs: [`Renderer::settings`], with
    /// [`AoSettings::bent_normals`] turned on when the composite uses
    /// [`SpecularOcclusion::Gtso`] and the method has bent normals. The caller's settings are
    /// left as they were, and [`Frame::bent_normals`] follows them.
    ///
    /// ```no_run
    /// # fn f(renderer: &mut aokit_scene::Renderer) {
    /// use aokit_scene::composite::SpecularOcclusion;
    /// renderer.lighting.specular_occlusion = SpecularOcclusion::Gtso;
    /// let running = renderer.pipeline_settings();
    /// // GTSO needs bent normals, which only the slice methods compute.
    /// assert_eq!(running.bent_normals,
    ///            renderer.settings().bent_normals || running.method.has_bent_normals());
    /// # }
    /// ```
    pub fn pipeline_settings(&self) -> AoSettings {
        pipeline_settings(&self.settings, &self.lighting)
    }

    /// Times the AO passes of later frames; `false` when the device has no timestamps.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), aokit_scene::RenderError> {
    /// if !renderer.enable_timing(gpu) {
    ///     eprintln!("{} has no GPU timestamps", gpu.describe());
    /// }
    /// renderer.render(gpu, camera, [1920, 1080], 0)?;
    /// if let Some(times) = renderer.last_ao_times(gpu) {
    ///     let total: f64 = times?.iter().map(|t| t.ms).sum();
    ///     println!("AO took {total:.2} ms");
    /// }
    /// # Ok(()) }
    /// ```
    pub fn enable_timing(&mut self, gpu: &GpuContext) -> bool {
        self.ao.enable_timing(&gpu.device, &gpu.queue)
    }

    /// GPU time of each AO pass of the last frame, when timing is on: see
    /// [`Renderer::enable_timing`].
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), Box<dyn std::error::Error>> {
    /// if renderer.enable_timing(gpu) {
    ///     renderer.render(gpu, camera, [640, 360], 0)?;
    ///     let total: f64 = renderer.last_ao_times(gpu).transpose()?.unwrap_or_default()
    ///         .iter().map(|time| time.ms).sum();
    ///     println!("AO: {total:.3} ms");
    /// }
    /// # Ok(()) }
    /// ```
    pub fn last_ao_times(&self, gpu: &GpuContext) -> Option<Result<Vec<PassTime>, GpuError>> {
        self.ao.last_pass_times(&gpu.device)
    }

    /// Changes the AO settings for later frames.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), aokit_scene::RenderError> {
    /// use aokit::{AoSettings, Method, Preset};
    /// // The same view with each method; the kernels compile once, on first use.
    /// for method in Method::ALL {
    ///     renderer.set_settings(gpu, &AoSettings::preset(method, Preset::Medium))?;
    ///     renderer.reset_history();
    ///     let frame = renderer.render(gpu, camera, [640, 360], 0)?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn set_settings(
        &mut self,
        gpu: &GpuContext,
        settings: &AoSettings,
    ) -> Result<(), RenderError> {
        self.ao.set_settings(
            &gpu.device,
            &gpu.queue,
            &pipeline_settings(settings, &self.lighting),
        )?;
        self.settings = *settings;
        Ok(())
    }

    /// The projection `camera` gets at `size`, near and far planes fitted to the scene; the
    /// reference tracer's [`pixel_camera`](crate::reference::pixel_camera) uses the same.
    ///
    /// ```no_run
    /// # fn f(renderer: &aokit_scene::Renderer, camera: &aokit_scene::Camera) {
    /// // Turn a pixel's linear depth into a view-space position, as the AO kernels see it.
    /// let size = [640, 360];
    /// let projection = renderer.projection(camera, size);
    /// let ndc = aokit::projection::pixel_to_ndc(glam::Vec2::new(320.0, 180.0),
    ///                                           glam::Vec2::new(640.0, 360.0));
    /// let point = projection.view_position_from_linear(ndc, 4.0);
    /// # }
    /// ```
    pub fn projection(&self, camera: &Camera, size: [u32; 2]) -> Projection {
        camera.projection(size[0] as f32 / size[1] as f32, &self.bounds)
    }

    /// [`Renderer::projection`], after checking that `size` fits the device and that the camera
    /// and its projection are usable.
    fn checked_projection(
        &self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
    ) -> Result<Projection, RenderError> {
        self.checked_size(gpu, size)?;
        camera.validate().map_err(RenderError::Camera)?;
        let projection = self.projection(camera, size);
        projection
            .validate()
            .map_err(|e| RenderError::Camera(format!("camera `{}`: {e}", camera.name)))?;
        Ok(projection)
    }

    /// Checks that an image of `size` fits the device and the pixel budget.
    fn checked_size(&self, gpu: &GpuContext, size: [u32; 2]) -> Result<(), RenderError> {
        let max = gpu.device.limits().max_texture_dimension_2d;
        let [width, height] = size;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(RenderError::Size {
                width,
                height,
                reason: format!("each side must be between 1 and {max} pixels on this device"),
            });
        }
        // Checked before the G-buffer is made: a device may allow 16384 per side, but not
        // the memory of that many pixels.
        aokit::inputs::check_size(size).map_err(|e| RenderError::Size {
            width,
            height,
            reason: e.to_string(),
        })
    }

    /// Records the G-buffer of the mesh as placed, seen by `camera`, into a new [`GBuffer`].
    fn draw_gbuffer(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        size: [u32; 2],
        encoding: aokit::NormalEncoding,
        back_faces: bool,
        camera: &GBufferCamera<'_>,
    ) -> GBuffer {
        let mut gbuffer = GBuffer::new(&gpu.device, size, encoding);
        if back_faces {
            gbuffer = gbuffer.with_back_depth(&gpu.device);
        }
        self.gbuffer_pass
            .encode(gpu, encoder, &self.mesh, camera, &gbuffer);
        gbuffer
    }

    /// Rasterises only the G-buffer of `camera` at `size`, normals in `encoding`, with the
    /// scene at rest and standing still (motion vectors 0), and its back faces' depth (for
    /// any settings with [`aokit::VbaoSettings::back_faces`]), and submits it; returns it with
    /// the projection it was drawn with. No AO, shadow or lighting pass runs, and the
    /// sequence [`Renderer::render`] keeps (history, previous camera) is left as it was.
    ///
    /// For running an [`AoPipeline`] of one's own on the G-buffer: `aokit bench` does, to time
    /// the AO passes alone, on [`GBuffer::depth`], [`GBuffer::normals`] and
    /// [`GBuffer::motion`] with the returned projection and `camera.view_from_world()`.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), Box<dyn std::error::Error>> {
    /// use aokit::{AoInputs, AoPipeline, AoSettings, NormalEncoding};
    /// let (gbuffer, projection) =
    ///     renderer.render_gbuffer(gpu, camera, [1920, 1080], NormalEncoding::Oct32)?;
    /// let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default())?;
    /// let mut encoder = gpu.device.create_command_encoder(&Default::default());
    /// let outputs = pipeline.encode(&gpu.device, &gpu.queue, &mut encoder, &AoInputs {
    ///     normals: Some((&gbuffer.normals).into()),
    ///     view_from_world: camera.view_from_world(),
    ///     ..AoInputs::new(&gbuffer.depth, projection)
    /// })?;
    /// gpu.queue.submit([encoder.finish()]);
    /// let ao = aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, outputs.ao)?;
    /// # Ok(()) }
    /// ```
    pub fn render_gbuffer(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        encoding: aokit::NormalEncoding,
    ) -> Result<(GBuffer, Projection), RenderError> {
        self.render_gbuffer_with_guard_band(gpu, camera, size, encoding, 0)
    }

    /// [`Renderer::render_gbuffer`] with `band` pixels of overscan on each side: the G-buffer
    /// is `size` plus twice `band` each way, drawn through the frustum widened so that its
    /// inner `size` pixels are the camera's image, as [`AoInputs::guard_band`] reads it. The
    /// projection returned is the camera's, for [`AoInputs::projection`].
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), Box<dyn std::error::Error>> {
    /// use aokit::{AoInputs, AoPipeline, AoSettings, NormalEncoding};
    /// let (gbuffer, projection) = renderer.render_gbuffer_with_guard_band(
    ///     gpu, camera, [1280, 720], NormalEncoding::Oct32, 32)?;
    /// assert_eq!(gbuffer.size, [1344, 784]);
    /// let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default())?;
    /// let mut encoder = gpu.device.create_command_encoder(&Default::default());
    /// let outputs = pipeline.encode(&gpu.device, &gpu.queue, &mut encoder, &AoInputs {
    ///     normals: Some((&gbuffer.normals).into()),
    ///     guard_band: 32,
    ///     ..AoInputs::new(&gbuffer.depth, projection)
    /// })?;
    /// assert_eq!(outputs.ao.width(), 1280);
    /// # Ok(()) }
    /// ```
    pub fn render_gbuffer_with_guard_band(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        encoding: aokit::NormalEncoding,
        band: u32,
    ) -> Result<(GBuffer, Projection), RenderError> {
        let projection = self.checked_projection(gpu, camera, size)?;
        let full = overscan_size(size, band);
        self.checked_size(gpu, full)?;
        let widened = projection.with_guard_band(size, band);
        let view_from_world = camera.view_from_world();
        // Standing still: the previous frame is this one.
        let previous_clip_from_world = widened.clip_from_view() * view_from_world;
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        self.mesh.place(&gpu.queue, 0.0, 0.0);
        let gbuffer = self.draw_gbuffer(
            gpu,
            &mut encoder,
            full,
            encoding,
            true,
            &GBufferCamera {
                view_from_world,
                projection: &widened,
                previous_clip_from_world,
            },
        );
        gpu.queue.submit([encoder.finish()]);
        Ok((gbuffer, projection))
    }

    /// Renders G-buffer, AO and lit image for `camera` at `size` with the scene at rest, and
    /// reads them back: [`Renderer::render_at`] at time 0.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      scene: &aokit_scene::Scene) -> Result<(), Box<dyn std::error::Error>> {
    /// let camera = scene.camera(Some("corner"))?;
    /// let frame = renderer.render(gpu, &camera, [1280, 720], 0)?;
    /// // `lit` is RGBA8, sRGB-encoded: ready for an image file.
    /// assert_eq!(frame.lit.len(), 1280 * 720 * 4);
    /// # Ok(()) }
    /// ```
    pub fn render(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        frame_index: u32,
    ) -> Result<Frame, RenderError> {
        self.render_at(gpu, camera, size, frame_index, 0.0)
    }

    /// Renders G-buffer, AO and lit image for `camera` at `size` with the scene's moving parts
    /// where they are at `time` (0 to 1 over a sequence, see
    /// [`Scene::mesh_at`](crate::Scene::mesh_at)), and reads them back. The motion vectors
    /// lead to the previous frame's camera and time.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), aokit_scene::RenderError> {
    /// // The still camera watches the scene's parts move over 12 frames.
    /// for frame in 0..12 {
    ///     let time = frame as f32 / 11.0;
    ///     let image = renderer.render_at(gpu, camera, [640, 360], frame, time)?;
    ///     let fastest = image.motion_vectors.iter().map(|m| m.length()).fold(0.0, f32::max);
    ///     println!("frame {frame}: parts move up to {fastest:.1} pixels");
    /// }
    /// # Ok(()) }
    /// ```
    pub fn render_at(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        frame_index: u32,
        time: f32,
    ) -> Result<Frame, RenderError> {
        Ok(self
            .render_sides(gpu, camera, size, frame_index, time, None)?
            .0)
    }

    /// [`Renderer::render_at`], and `second`, a pipeline of the caller's with other settings,
    /// run on the same G-buffer: the second frame holds its AO, lit image, debug views and
    /// history, the G-buffer's images (depth, normals, motion) as the first. For showing two
    /// configurations side by side (`aokit view --split`). `second` runs its settings as given
    /// (its bent normals are not turned on for [`SpecularOcclusion::Gtso`]); the G-buffer's
    /// normals are in this renderer's [`aokit::NormalsSettings::encoding`], which `second`'s
    /// settings must name too.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
    /// #      camera: &aokit_scene::Camera) -> Result<(), Box<dyn std::error::Error>> {
    /// use aokit::{AoPipeline, AoSettings, Method, Preset};
    /// let hbao = AoSettings::preset(Method::Hbao, Preset::Medium);
    /// let mut second = AoPipeline::new(&gpu.device, &gpu.queue, &hbao)?;
    /// let (first, hbao_frame) = renderer.render_pair_at(gpu, camera, [640, 360], 0, 0.0,
    ///                                                   &mut second)?;
    /// assert_eq!(first.linear_depth, hbao_frame.linear_depth);
    /// # Ok(()) }
    /// ```
    pub fn render_pair_at(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        frame_index: u32,
        time: f32,
        second: &mut AoPipeline,
    ) -> Result<(Frame, Frame), RenderError> {
        let (first, second) =
            self.render_sides(gpu, camera, size, frame_index, time, Some(second))?;
        Ok((
            first,
            second.expect("a second pipeline renders a second frame"),
        ))
    }

    /// Renders the frame of [`Renderer::render_at`], and with `second`, that pipeline's frame
    /// of the same G-buffer.
    fn render_sides(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        size: [u32; 2],
        frame_index: u32,
        time: f32,
        second: Option<&mut AoPipeline>,
    ) -> Result<(Frame, Option<Frame>), RenderError> {
        let projection = self.checked_projection(gpu, camera, size)?;
        let view_from_world = camera.view_from_world();
        let (device, queue) = (&gpu.device, &gpu.queue);
        // `lighting` is a public field, changed at any time: follow its need for bent normals.
        let wanted = self.pipeline_settings();
        if *self.ao.settings() != wanted {
            self.ao.set_settings(device, queue, &wanted)?;
        }

        let reset_history = std::mem::take(&mut self.reset_history);
        let clip_from_world = projection.clip_from_view() * view_from_world;
        let (previous_clip_from_world, previous_time) = self
            .previous
            .filter(|_| !reset_history)
            .unwrap_or((clip_from_world, time));
        self.mesh.place(queue, time, previous_time);

        let back_faces = |s: &AoSettings| s.method == aokit::Method::Vbao && s.vbao.back_faces;
        let mut encoder = device.create_command_encoder(&Default::default());
        let gbuffer = self.draw_gbuffer(
            gpu,
            &mut encoder,
            size,
            self.settings.normals.encoding,
            back_faces(&wanted) || second.as_ref().is_some_and(|p| back_faces(p.settings())),
            &GBufferCamera {
                view_from_world,
                projection: &projection,
                previous_clip_from_world,
            },
        );
        // With a guard band the AO reads a G-buffer of its own, drawn larger through the
        // widened frustum; the composite and the frame's images keep the camera's.
        let band = self.guard_band;
        let overscan = if band > 0 {
            let full = overscan_size(size, band);
            self.checked_size(gpu, full)?;
            let widened = projection.with_guard_band(size, band);
            // The widened frustum scales clip x and y by the frame's size over the overscan's
            // (Projection::with_guard_band), last frame's camera as this one's, so that the
            // overscan's motion vectors are the frame's, shifted by the band.
            let [frame, overscan] = [size, full].map(|s| Vec2::new(s[0] as f32, s[1] as f32));
            let to_overscan = Mat4::from_scale((frame / overscan).extend(1.0));
            Some(self.draw_gbuffer(
                gpu,
                &mut encoder,
                full,
                self.settings.normals.encoding,
                back_faces(&wanted) || second.as_ref().is_some_and(|p| back_faces(p.settings())),
                &GBufferCamera {
                    view_from_world,
                    projection: &widened,
                    previous_clip_from_world: to_overscan * previous_clip_from_world,
                },
            ))
        } else {
            None
        };
        let sun = SunView::new(self.lighting.sun_direction, &self.bounds);
        self.shadow_pass
            .encode(queue, &mut encoder, &self.mesh, &sun);
        let ao_gbuffer = overscan.as_ref().unwrap_or(&gbuffer);
        let inputs = AoInputs {
            normals: Some((&ao_gbuffer.normals).into()),
            view_from_world,
            frame_index,
            motion_vectors: self
                .use_motion_vectors
                .then_some((&ao_gbuffer.motion).into()),
            reset_history,
            back_depth: ao_gbuffer.back_depth.as_ref().map(Into::into),
            guard_band: band,
            ..AoInputs::new(&ao_gbuffer.depth, projection)
        };
        let shading = Shading {
            gpu,
            size,
            inputs: &inputs,
            gbuffer: &gbuffer,
            lighting: &self.lighting,
            view: CompositeView {
                projection: &projection,
                view_from_world,
                sun: &sun,
            },
            shadow_map: &self.shadow_pass.map,
        };
        let (outputs, lit) =
            shading.encode(&mut encoder, &mut self.ao, &mut self.composite, "lit")?;
        queue.submit([encoder.finish()]);
        self.previous = Some((clip_from_world, time));

        let linear_depth = read_texture_f32(device, queue, outputs.linear_depth)?;
        let style = DebugStyle {
            depth_range: depth_range(&linear_depth),
            orthographic: projection.is_orthographic(),
            ..DebugStyle::default()
        };
        let mut sides = SideReader {
            gpu,
            style: &style,
            debug_views: &self.debug_views,
            debug: &mut self.debug,
        };
        let first = sides.read(&outputs, &lit, self.settings.bent_normals)?;
        let back_depth = gbuffer
            .back_depth
            .as_ref()
            .map(|texture| read_texture_f32(device, queue, texture))
            .transpose()?
            .map(|ndc| ndc.iter().map(|&d| projection.surface_depth(d)).collect());
        let motion_vectors = read_texture_rg16f(device, queue, &gbuffer.motion)?
            .into_iter()
            .map(Vec2::from_array)
            .collect();
        let packed: Vec<u32> =
            bytemuck::pod_collect_to_vec(&read_texture(device, queue, outputs.normals)?);
        let normals = packed
            .iter()
            .zip(&linear_depth)
            .map(|(&bits, &depth)| {
                if depth > 0.0 {
                    aokit::normals::unpack_oct32(bits)
                } else {
                    Vec3::ZERO
                }
            })
            .collect();
        let frame = first.into_frame(Frame {
            size,
            projection,
            view_from_world,
            ao: Vec::new(),
            lit: Vec::new(),
            linear_depth,
            normals,
            history_rejected: None,
            bent_normals: None,
            back_depth,
            motion_vectors,
            debug: Vec::new(),
        });
        let Some(second) = second else {
            return Ok((frame, None));
        };
        // A submission of its own: the composite's uniforms (whether there are bent normals)
        // may differ from the first side's.
        let mut encoder = device.create_command_encoder(&Default::default());
        let second_bent_normals = second.settings().bent_normals;
        let (outputs, second_lit) =
            shading.encode(&mut encoder, second, &mut self.composite, "lit (second)")?;
        queue.submit([encoder.finish()]);
        let side = sides.read(&outputs, &second_lit, second_bent_normals)?;
        let second_frame = side.into_frame(frame.clone());
        Ok((frame, Some(second_frame)))
    }
}

/// `size` with `band` pixels more on each side, saturating (the size check then refuses it).
fn overscan_size(size: [u32; 2], band: u32) -> [u32; 2] {
    size.map(|side| side.saturating_add(band.saturating_mul(2)))
}

/// What differs between two AO pipelines' frames of the same G-buffer.
struct Side {
    ao: Vec<f32>,
    lit: Vec<u8>,
    history_rejected: Option<(Vec<f32>, [u32; 2])>,
    bent_normals: Option<Vec<Vec3>>,
    debug: Vec<(DebugView, Vec<u8>)>,
}

impl Side {
    /// `frame` with this side's images.
    fn into_frame(self, frame: Frame) -> Frame {
        Frame {
            ao: self.ao,
            lit: self.lit,
            history_rejected: self.history_rejected,
            bent_normals: self.bent_normals,
            debug: self.debug,
            ..frame
        }
    }
}

/// What one AO pipeline's side of a frame is drawn from: the frame's G-buffer, inputs, lights
/// and shadow map, shared by both sides of a split.
struct Shading<'a> {
    gpu: &'a GpuContext,
    size: [u32; 2],
    inputs: &'a AoInputs<'a>,
    gbuffer: &'a GBuffer,
    lighting: &'a Lighting,
    view: CompositeView<'a>,
    shadow_map: &'a wgpu::Texture,
}

impl<'a> Shading<'a> {
    /// Records `ao`'s passes and the lit composite of their AO into a new texture named
    /// `label`.
    fn encode<'p>(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        ao: &'p mut AoPipeline,
        composite: &mut CompositePass,
        label: &str,
    ) -> Result<(aokit::AoOutputs<'p>, wgpu::Texture), RenderError>
    where
        'a: 'p,
    {
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let lit = create_texture_2d(
            device,
            label,
            self.size,
            LIT_FORMAT,
            wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        );
        let outputs = ao.encode(device, queue, encoder, self.inputs)?;
        composite.encode(
            device,
            queue,
            encoder,
            self.lighting,
            &self.view,
            self.gbuffer,
            &outputs,
            self.shadow_map,
            &lit,
        );
        Ok((outputs, lit))
    }
}

/// Reads one AO pipeline's side of a frame back, with the debug views asked for.
struct SideReader<'a> {
    gpu: &'a GpuContext,
    style: &'a DebugStyle,
    debug_views: &'a [DebugView],
    debug: &'a mut Option<AoDebug>,
}

impl SideReader<'_> {
    /// The AO, `lit`, the history and, where `bent_normals` asks, the bent normals of
    /// `outputs`, and the debug views drawn from them.
    fn read(
        &mut self,
        outputs: &aokit::AoOutputs<'_>,
        lit: &wgpu::Texture,
        bent_normals: bool,
    ) -> Result<Side, RenderError> {
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let ao = read_texture_f32(device, queue, outputs.ao)?;
        let history_rejected = outputs
            .history_rejected
            .map(|texture| {
                let extent = texture.size();
                read_texture_f32(device, queue, texture)
                    .map(|texels| (texels, [extent.width, extent.height]))
            })
            .transpose()?;
        let bent_normals = outputs
            .bent_normals
            .filter(|_| bent_normals)
            .map(|texture| read_texture_rgba16f(device, queue, texture))
            .transpose()?
            .map(|texels| texels.iter().map(|t| Vec3::new(t[0], t[1], t[2])).collect());
        let mut debug = Vec::with_capacity(self.debug_views.len());
        if !self.debug_views.is_empty() {
            let pass = self
                .debug
                .get_or_insert_with(|| AoDebug::new(device, queue));
            for &view in self.debug_views {
                let mut encoder = device.create_command_encoder(&Default::default());
                let image = pass.encode(device, queue, &mut encoder, outputs, view, self.style)?;
                queue.submit([encoder.finish()]);
                debug.push((view, read_texture(device, queue, image)?));
            }
        }
        let lit = read_texture(device, queue, lit)?;
        Ok(Side {
            ao,
            lit,
            history_rejected,
            bent_normals,
            debug,
        })
    }
}

/// `settings` with bent normals on when `lighting` needs them and the method computes them.
fn pipeline_settings(settings: &AoSettings, lighting: &Lighting) -> AoSettings {
    let gtso = lighting.specular_occlusion == SpecularOcclusion::Gtso;
    AoSettings {
        bent_normals: settings.bent_normals || (gtso && settings.method.has_bent_normals()),
        ..*settings
    }
}

/// The nearest and farthest surface depths of a frame (0: no surface), as a debug view's
/// depth range; a range any depth view accepts when there is none.
fn depth_range(linear_depth: &[f32]) -> [f32; 2] {
    let (near, far) = linear_depth
        .iter()
        .filter(|&&d| d > 0.0)
        .fold((f32::MAX, 0.0f32), |(n, f), &d| (n.min(d), f.max(d)));
    if far > near {
        [near, far]
    } else {
        DebugStyle::default().depth_range
    }
}
