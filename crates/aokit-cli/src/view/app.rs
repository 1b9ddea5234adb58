//! The event loop: the window, input to the camera, one frame per redraw (scene, AO, panel),
//! and the screenshot mode (`--frames N --screenshot FILE`).

use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use anyhow::{Context, Result, anyhow};
use aokit::{AdapterKind, AoPipeline};
use aokit_scene::composite::Lighting;
use aokit_scene::{Camera, Renderer, Scene};
use glam::Vec3;
use winit::application::ApplicationHandler;
use winit::event::{ElementState, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{KeyCode, PhysicalKey};
use winit::window::{Window, WindowId};

use super::camera::{CameraMode, ViewCamera};
use super::frame::{self, DisplayMode, Timings};
use super::gpu::WindowGpu;
use super::motion::Motion;
use super::truth::{self, Truth};
use super::ui::{self, Action, Config, Split, TruthView, ViewState};

/// What the viewer starts with, from the flags.
pub struct Start {
    /// The scene.
    pub scene: Scene,
    /// The camera the flags picked.
    pub camera: Camera,
    /// The settings the flags give, and the preset they name (the panel's "copy as flags"
    /// compares with it).
    pub config: Config,
    /// The A/B split `--split` opens with.
    pub split: Option<Split>,
    /// The moving parts and the camera path.
    pub motion: Motion,
    /// The lit image's lighting (`--sun`, `--multi-bounce`, `--specular-occlusion`,
    /// `--roughness`).
    pub lighting: Lighting,
    /// Trace the reference of the starting view (and, with a screenshot, wait for it).
    pub reference: bool,
    /// Rays per pixel of the reference; `None`: [`truth::default_spp`].
    pub reference_spp: Option<u32>,
    /// What to show.
    pub mode: DisplayMode,
    /// Window size in pixels.
    pub window_size: [u32; 2],
    /// Internal render scale; `None`: 1 on a GPU, [`SOFTWARE_SCALE`] on a software adapter.
    pub scale: Option<f32>,
    /// Pixels of overscan the AO reads on each side.
    pub guard_band: u32,
    /// Show the side panel.
    pub panel: bool,
    /// Exit after this many frames.
    pub frames: Option<u32>,
    /// Write the window's content here after the last frame.
    pub screenshot: Option<PathBuf>,
}

/// The internal scale on a software adapter unless `--scale` says otherwise.
pub const SOFTWARE_SCALE: f32 = 0.5;

/// Opens the window and runs until it closes, or until the frames asked for are done.
pub fn run(start: Start) -> Result<()> {
    let event_loop = EventLoop::new().map_err(|e| {
        anyhow!(
            "cannot open a window ({e}): `aokit view` needs a display (X11; under no display, \
             run it in `xvfb-run -a`)"
        )
    })?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut app = App {
        start: Some(start),
        running: None,
        result: Ok(()),
    };
    event_loop.run_app(&mut app)?;
    app.result
}

struct App {
    start: Option<Start>,
    running: Option<Running>,
    result: Result<()>,
}

impl App {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        self.result = Err(error);
        event_loop.exit();
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        let Some(start) = self.start.take() else {
            return;
        };
        match Running::new(event_loop, start) {
            Ok(running) => self.running = Some(running),
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(running) = &mut self.running else {
            return;
        };
        match running.window_event(event) {
            Ok(true) => {}
            Ok(false) => event_loop.exit(),
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn about_to_wait(&mut self, _: &ActiveEventLoop) {
        if let Some(running) = &self.running {
            running.window.request_redraw();
        }
    }
}

/// Keys held over the view (mouse drags and the wheel reach the camera through egui: see
/// `ui::draw`).
#[derive(Default)]
struct Input {
    keys: HashSet<KeyCode>,
}

impl Input {
    /// Right, up, forward from WASD, Q/E (down/up) and the arrow keys.
    fn direction(&self) -> Vec3 {
        let held = |keys: &[KeyCode]| keys.iter().any(|k| self.keys.contains(k));
        let axis = |minus: &[KeyCode], plus: &[KeyCode]| {
            f32::from(u8::from(held(plus))) - f32::from(u8::from(held(minus)))
        };
        Vec3::new(
            axis(
                &[KeyCode::KeyA, KeyCode::ArrowLeft],
                &[KeyCode::KeyD, KeyCode::ArrowRight],
            ),
            axis(&[KeyCode::KeyQ], &[KeyCode::KeyE]),
            axis(
                &[KeyCode::KeyS, KeyCode::ArrowDown],
                &[KeyCode::KeyW, KeyCode::ArrowUp],
            ),
        )
    }

    fn fast(&self) -> bool {
        self.keys.contains(&KeyCode::ShiftLeft) || self.keys.contains(&KeyCode::ShiftRight)
    }
}

struct Running {
    window: Arc<Window>,
    wgpu: WindowGpu,
    renderer: Renderer,
    egui_state: egui_winit::State,
    egui_renderer: egui_wgpu::Renderer,
    /// The images the central area draws: A's, and B's in the split.
    textures: [Option<egui::TextureHandle>; 2],
    /// B's AO pipeline, made when the split first shows.
    b_pipeline: Option<AoPipeline>,
    view: ViewState,
    /// The scene, for the reference's tracer.
    scene: Arc<Scene>,
    /// The reference of the view, traced or being traced.
    truth: Option<Truth>,
    /// Rays per pixel of the reference.
    reference_spp: u32,
    /// Trace the reference once the layout has measured the view (`--reference`).
    trace_at_start: bool,
    /// Count `--frames` only once the reference is traced (`--reference --screenshot`).
    wait_for_reference: bool,
    input: Input,
    last: Instant,
    frame_index: u32,
    /// Redraws of the window so far (`--frames` counts these).
    drawn: u32,
    frames: Option<u32>,
    screenshot: Option<PathBuf>,
    /// What the last rendered frame showed ([`scene_key`]), and how many frames have shown it.
    last_key: Option<String>,
    repeats: u32,
}

/// Frames rendered after the view last changed before the viewer stops rendering the scene
/// (the window keeps redrawing the panel): enough for the temporal filter's history to settle.
/// Rendering the same view again gives the same image, so an idle window spends no GPU (or,
/// on a software adapter, CPU) time.
pub const SETTLE_FRAMES: u32 = 32;

/// Everything the rendered images depend on, as text: camera, settings (B's too in the split),
/// mode, scale, size, and whether the reference is there.
fn scene_key(view: &ViewState) -> String {
    let camera = &view.camera;
    format!(
        "{:?} {:?} {:?} {:?} {:?} {} {:?} {:?} {:?} {} {:?}",
        camera.eye,
        camera.forward,
        view.a.settings,
        view.split.as_ref().map(|split| split.b.settings),
        view.mode,
        view.scale,
        view.multi_bounce,
        view.specular_occlusion,
        view.area,
        view.truth.ready,
        view.motion
    )
}

impl Running {
    fn new(event_loop: &ActiveEventLoop, start: Start) -> Result<Self> {
        let [width, height] = start.window_size;
        let attributes = Window::default_attributes()
            .with_title(format!("aokit view: {}", start.scene.name))
            .with_inner_size(winit::dpi::PhysicalSize::new(width, height));
        let window = Arc::new(
            event_loop
                .create_window(attributes)
                .context("cannot open the window")?,
        );
        let wgpu = WindowGpu::new(window.clone())?;
        let gpu = &wgpu.gpu;
        let software = gpu.adapter_kind() == AdapterKind::Software;
        let scale = start
            .scale
            .unwrap_or(if software { SOFTWARE_SCALE } else { 1.0 });
        let software_note = software.then(|| {
            format!(
                "software adapter ({}): rendering at {:.0}% of the view's pixels{}",
                gpu.adapter_info.name,
                scale * 100.0,
                if start.scale.is_none() {
                    " by default (--scale 1 for full)"
                } else {
                    ""
                }
            )
        });
        if let Some(note) = &software_note {
            eprintln!("note: {note}");
        }
        let mut renderer = Renderer::new(gpu, &start.scene, &start.config.settings)?;
        renderer.lighting = start.lighting;
        let timestamps = renderer.enable_timing(gpu);
        let egui_ctx = egui::Context::default();
        let egui_state = egui_winit::State::new(
            egui_ctx,
            egui::ViewportId::ROOT,
            &window,
            Some(window.scale_factor() as f32),
            None,
            Some(gpu.device.limits().max_texture_dimension_2d as usize),
        );
        let egui_renderer =
            egui_wgpu::Renderer::new(&gpu.device, wgpu.config.format, Default::default());
        let radius = start.scene.bounds.radius();
        let view = ViewState {
            camera: ViewCamera::new(&start.camera, radius),
            start_camera: start.camera,
            bookmarks: start.scene.cameras.clone(),
            scene_name: start.scene.name.clone(),
            suggested_radius: start.scene.suggested_radius,
            a: start.config,
            split: start.split,
            mode: start.mode,
            scale,
            guard_band: start.guard_band,
            multi_bounce: renderer.lighting.multi_bounce,
            specular_occlusion: renderer.lighting.specular_occlusion,
            panel: start.panel,
            timings: Timings::default(),
            timestamps,
            adapter: gpu.describe(),
            software_note,
            area: start.window_size,
            continuous: false,
            idle: false,
            render_size: [0, 0],
            truth: TruthView::default(),
            motion: start.motion,
            message: None,
            error: None,
        };
        Ok(Self {
            window,
            wgpu,
            renderer,
            egui_state,
            egui_renderer,
            textures: [None, None],
            b_pipeline: None,
            view,
            scene: Arc::new(start.scene),
            truth: None,
            reference_spp: start.reference_spp.unwrap_or(truth::default_spp(software)),
            trace_at_start: start.reference,
            wait_for_reference: start.reference && start.screenshot.is_some(),
            input: Input::default(),
            last: Instant::now(),
            frame_index: 0,
            drawn: 0,
            frames: start.frames,
            screenshot: start.screenshot,
            last_key: None,
            repeats: 0,
        })
    }

    /// Handles one event; `Ok(false)` ends the loop.
    fn window_event(&mut self, event: WindowEvent) -> Result<bool> {
        let response = self.egui_state.on_window_event(&self.window, &event);
        match event {
            WindowEvent::CloseRequested => return Ok(false),
            WindowEvent::Resized(size) => self.wgpu.resize(size.width, size.height),
            WindowEvent::RedrawRequested => return self.redraw(),
            WindowEvent::Focused(false) => self.input.keys.clear(),
            WindowEvent::KeyboardInput { event, .. } if !response.consumed => {
                let PhysicalKey::Code(code) = event.physical_key else {
                    return Ok(true);
                };
                match event.state {
                    ElementState::Pressed => {
                        if !event.repeat && !self.key_pressed(code) {
                            return Ok(false);
                        }
                        self.input.keys.insert(code);
                    }
                    ElementState::Released => {
                        self.input.keys.remove(&code);
                    }
                }
            }
            WindowEvent::KeyboardInput { event, .. } => {
                // egui took the key (a text field has focus): forget it as held.
                if let PhysicalKey::Code(code) = event.physical_key {
                    self.input.keys.remove(&code);
                }
            }
            _ => {}
        }
        Ok(true)
    }

    /// A key pressed over the view; `false` to quit.
    fn key_pressed(&mut self, code: KeyCode) -> bool {
        match code {
            KeyCode::Escape => return false,
            KeyCode::KeyP => self.act(Action::CopyPose),
            KeyCode::KeyM => self.view.mode = self.view.mode.next(),
            KeyCode::Tab => self.view.panel = !self.view.panel,
            KeyCode::KeyF => self.view.camera.mode = CameraMode::Fly,
            KeyCode::KeyO => self.view.camera.mode = CameraMode::Orbit,
            KeyCode::KeyR => self.act(Action::Reset),
            KeyCode::KeyT => self.act(Action::TraceReference),
            KeyCode::Space => self.view.motion.playing = !self.view.motion.playing,
            KeyCode::Period => self.act(Action::Step(1)),
            KeyCode::Comma => self.act(Action::Step(-1)),
            KeyCode::KeyB => {
                self.view.split = match self.view.split {
                    Some(_) => None,
                    None => Some(Split {
                        b: self.view.a.clone(),
                        divider: 0.5,
                    }),
                }
            }
            _ => {}
        }
        true
    }

    /// Does what the panel or a key asked for.
    fn act(&mut self, action: Action) {
        let ctx = self.egui_state.egui_ctx().clone();
        match action {
            Action::CopyPose => {
                let flags = self.view.camera.flags();
                outln!("{flags}");
                ctx.copy_text(flags);
                self.view.message = Some("camera pose printed and copied".into());
            }
            Action::Copy(text) => {
                outln!("{text}");
                ctx.copy_text(text);
                self.view.message = Some("printed and copied".into());
            }
            Action::Bookmark(i) => {
                if let Some(camera) = self.view.bookmarks.get(i).cloned() {
                    self.view.camera.jump_to(&camera);
                    self.renderer.reset_history();
                }
            }
            Action::Reset => {
                let camera = self.view.start_camera.clone();
                self.view.camera.jump_to(&camera);
                self.renderer.reset_history();
            }
            Action::Step(by) => {
                self.view.motion.playing = false;
                if self.view.motion.step(by) {
                    self.renderer.reset_history();
                }
            }
            Action::TraceReference => {
                let size = frame::internal_size(self.view.area, self.view.scale);
                let truth = Truth::start(
                    self.scene.clone(),
                    self.view.shown(),
                    size,
                    self.reference_spp,
                    self.view.a.settings.radius,
                );
                self.view.truth = TruthView {
                    note: Some(format!(
                        "{}x{}, {} rays per pixel, radius {}",
                        size[0], size[1], truth.options.spp, truth.options.radius
                    )),
                    ..TruthView::default()
                };
                self.truth = Some(truth);
            }
        }
    }

    /// Follows the reference's trace: takes its result, drops it when the camera or the size
    /// rendered changed, and starts the one `--reference` asks for once the layout has measured
    /// the view. A failed trace is an error with `--reference --screenshot`, and a note in the
    /// panel otherwise.
    fn update_truth(&mut self) -> Result<()> {
        if std::mem::take(&mut self.trace_at_start) {
            self.act(Action::TraceReference);
        }
        let Some(truth) = &mut self.truth else {
            return Ok(());
        };
        truth.poll();
        let size = frame::internal_size(self.view.area, self.view.scale);
        let (camera, time) = self.view.shown();
        if !truth.is_of((&camera, time), size) {
            self.truth = None;
            self.view.truth = TruthView::default();
            self.view.message = Some("reference dropped: the view changed".into());
            // A screenshot waits for a reference of the view it shows: trace that one.
            self.trace_at_start = self.wait_for_reference;
            return Ok(());
        }
        if let Some(error) = truth.error() {
            if self.wait_for_reference {
                return Err(error);
            }
            self.view.error = Some(format!("{error:#}"));
            self.truth = None;
            self.view.truth = TruthView::default();
            return Ok(());
        }
        self.view.truth.progress = truth.progress();
        self.view.truth.ready = truth.image().is_some();
        Ok(())
    }

    /// Renders the scene at the view's size, then draws the panel over it and presents.
    fn redraw(&mut self) -> Result<bool> {
        let now = Instant::now();
        let seconds = (now - self.last).as_secs_f32().min(0.25);
        self.last = now;
        let direction = self.input.direction();
        if direction != Vec3::ZERO {
            self.view.camera.fly(direction, seconds, self.input.fast());
        }
        // After the first frame: its layout measured the view the reference is traced for.
        if self.drawn > 0 || !self.trace_at_start {
            self.update_truth()?;
        }
        let key = scene_key(&self.view);
        if self.last_key.as_ref() == Some(&key) {
            self.repeats += 1;
        } else {
            self.last_key = Some(key);
            self.repeats = 0;
        }
        let temporal = self.view.a.settings.temporal.enabled
            || (self.view.split.as_ref()).is_some_and(|split| split.b.settings.temporal.enabled);
        let settle = if temporal { SETTLE_FRAMES } else { 1 };
        let moving = self.view.motion.playing && self.view.motion.active();
        self.view.idle = !self.view.continuous && !moving && self.repeats >= settle;
        if !self.view.idle {
            self.render_scene();
        }
        let waiting = self.wait_for_reference && !self.view.truth.ready;
        if !waiting || self.drawn == 0 {
            self.drawn += 1;
        }

        let raw_input = self.egui_state.take_egui_input(&self.window);
        let ctx = self.egui_state.egui_ctx().clone();
        let mut actions = Vec::new();
        let mut output = ctx.run_ui(raw_input, |ui| {
            let [a, b] = &self.textures;
            actions = ui::draw(ui, &mut self.view, [a.as_ref(), b.as_ref()]);
        });
        for action in actions {
            self.act(action);
        }
        self.egui_state
            .handle_platform_output(&self.window, output.platform_output);
        let jobs = ctx.tessellate(output.shapes, output.pixels_per_point);
        let surface_texture = match self.wgpu.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t)
            | wgpu::CurrentSurfaceTexture::Suboptimal(t) => Some(t),
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                let size = self.window.inner_size();
                self.wgpu.resize(size.width, size.height);
                None
            }
            _ => None,
        };
        let gpu = &self.wgpu.gpu;
        // Drained as they are applied: egui checks that none is dropped unapplied.
        let mut textures = std::mem::take(&mut output.textures_delta);
        for (id, deltas) in textures.set.drain() {
            for delta in &deltas {
                self.egui_renderer
                    .update_texture(&gpu.device, &gpu.queue, id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [self.wgpu.config.width, self.wgpu.config.height],
            pixels_per_point: output.pixels_per_point,
        };
        let last_frame = self.frames.is_some_and(|frames| self.drawn >= frames);
        let capture = (last_frame && self.screenshot.is_some()).then(|| self.wgpu.capture_target());
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        let commands = self.egui_renderer.update_buffers(
            &gpu.device,
            &gpu.queue,
            &mut encoder,
            &jobs,
            &screen,
        );
        let targets = surface_texture
            .iter()
            .map(|t| &t.texture)
            .chain(capture.as_ref());
        for target in targets {
            let view = target.create_view(&Default::default());
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("aokit view egui"),
                    color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                        view: &view,
                        depth_slice: None,
                        resolve_target: None,
                        ops: wgpu::Operations {
                            load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                            store: wgpu::StoreOp::Store,
                        },
                    })],
                    ..Default::default()
                })
                .forget_lifetime();
            self.egui_renderer.render(&mut pass, &jobs, &screen);
        }
        gpu.queue
            .submit(commands.into_iter().chain([encoder.finish()]));
        if let Some(texture) = surface_texture {
            self.window.pre_present_notify();
            gpu.queue.present(texture);
        }
        for id in textures.free.drain() {
            self.egui_renderer.free_texture(&id);
        }
        if let (Some(target), Some(path)) = (&capture, &self.screenshot) {
            let rgba = self.wgpu.read_rgba(target)?;
            let size = [target.width(), target.height()];
            aokit_eval::write_rgba_png(path, size, &rgba)
                .with_context(|| format!("cannot write {}", path.display()))?;
            outln!(
                "wrote {} ({}x{}, frame {}, {} at {:.0}% scale: {}x{})",
                path.display(),
                size[0],
                size[1],
                self.drawn,
                self.view.mode.name(),
                self.view.scale * 100.0,
                self.view.render_size[0],
                self.view.render_size[1]
            );
            if let Some(truth) = &self.truth {
                let mut labels = vec![("A", self.view.a.label(self.view.suggested_radius))];
                if let Some(split) = &self.view.split {
                    labels.push(("B", split.b.label(self.view.suggested_radius)));
                }
                for ((side, label), rmse) in labels.into_iter().zip(self.view.truth.rmse) {
                    if let Some(rmse) = rmse {
                        outln!(
                            "rmse {side} {rmse:.6} ({label}, {}x{}, {} rays per pixel)",
                            truth.size[0],
                            truth.size[1],
                            truth.options.spp
                        );
                    }
                }
            }
        }
        Ok(!last_frame)
    }

    /// Applies changed settings, renders one frame of the scene at the view's size and scale
    /// (A and, in the split, B on the same G-buffer), and puts the images the display mode shows
    /// into the textures the central area draws.
    fn render_scene(&mut self) {
        let gpu = &self.wgpu.gpu;
        if self.view.a.settings != *self.renderer.settings()
            && let Err(e) = self.renderer.set_settings(gpu, &self.view.a.settings)
        {
            self.view.error = Some(format!("settings refused: {e}"));
            self.view.a.settings = *self.renderer.settings();
        }
        let size = frame::internal_size(self.view.area, self.view.scale);
        self.view.render_size = size;
        self.renderer.debug_views = self.view.mode.debug_view().into_iter().collect();
        self.renderer.lighting.multi_bounce = self.view.multi_bounce;
        self.renderer.lighting.specular_occlusion = self.view.specular_occlusion;
        self.renderer.guard_band = self.view.guard_band;
        // The frame after the last one rendered, while the motion plays (the panel names the
        // frame on screen).
        if self.frame_index > 0 && self.view.motion.advance() {
            // From the loop's end back to its start: a cut.
            self.renderer.reset_history();
        }
        let (camera, time) = self.view.shown();
        let started = Instant::now();
        let result = match &mut self.view.split {
            None => {
                // The split off: B starts afresh when it comes back, without a stale history.
                self.b_pipeline = None;
                self.renderer
                    .render_at(gpu, &camera, size, self.frame_index, time)
                    .map(|frame| (frame, None))
                    .map_err(|e| e.to_string())
            }
            Some(split) => match b_pipeline(&mut self.b_pipeline, gpu, &mut split.b) {
                Ok(pipeline) => self
                    .renderer
                    .render_pair_at(gpu, &camera, size, self.frame_index, time, pipeline)
                    .map(|(a, b)| (a, Some(b)))
                    .map_err(|e| e.to_string()),
                Err(e) => Err(e),
            },
        };
        self.frame_index += 1;
        let (frame, b_frame) = match result {
            Ok(frames) => frames,
            Err(e) => {
                self.view.error = Some(format!("{} view: {e}", self.view.mode.name()));
                return;
            }
        };
        let passes = if self.view.timestamps {
            self.renderer.last_ao_times(gpu).and_then(Result::ok)
        } else {
            None
        };
        self.view.timings.add(started.elapsed(), passes.as_deref());
        self.view.error = None;
        let names = ["aokit scene", "aokit scene B"];
        // Of this frame's view only: the motion may have stepped since the trace.
        let reference = (self.truth.as_ref())
            .filter(|truth| truth.is_of((&camera, time), size))
            .and_then(Truth::image);
        for (i, frame) in [Some(&frame), b_frame.as_ref()].into_iter().enumerate() {
            self.view.truth.rmse[i] = frame
                .zip(reference)
                .filter(|(frame, reference)| frame.size == reference.size)
                .map(|(frame, reference)| crate::compare::surface_error(reference, &frame.ao).rmse);
            let Some(frame) = frame else { continue };
            let Some(rgba) = frame::image_of(frame, self.view.mode, reference) else {
                self.view.error = Some(if self.view.mode.needs_reference() {
                    format!(
                        "no reference of this view yet for the {} mode: trace it (T)",
                        self.view.mode.name()
                    )
                } else {
                    format!("no {} image this frame", self.view.mode.name())
                });
                return;
            };
            let image = egui::ColorImage::from_rgba_unmultiplied(
                [frame.size[0] as usize, frame.size[1] as usize],
                &rgba,
            );
            match &mut self.textures[i] {
                Some(texture) => texture.set(image, egui::TextureOptions::LINEAR),
                None => {
                    self.textures[i] = Some(self.egui_state.egui_ctx().load_texture(
                        names[i],
                        image,
                        egui::TextureOptions::LINEAR,
                    ))
                }
            }
        }
    }
}

/// B's pipeline, made on first use and given B's settings when they changed; a refused change
/// puts B's settings back to the ones it runs.
fn b_pipeline<'a>(
    pipeline: &'a mut Option<AoPipeline>,
    gpu: &aokit::GpuContext,
    b: &mut Config,
) -> Result<&'a mut AoPipeline, String> {
    let pipeline = match pipeline {
        Some(pipeline) => pipeline,
        None => pipeline.insert(
            AoPipeline::new(&gpu.device, &gpu.queue, &b.settings)
                .map_err(|e| format!("B's settings refused: {e}"))?,
        ),
    };
    if b.settings != *pipeline.settings()
        && let Err(e) = pipeline.set_settings(&gpu.device, &gpu.queue, &b.settings)
    {
        b.settings = *pipeline.settings();
        return Err(format!("B's settings refused: {e}"));
    }
    Ok(pipeline)
}
