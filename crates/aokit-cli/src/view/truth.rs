//! The CPU reference for the view on screen, traced in a background thread (`aokit-reference`,
//! on every core through rayon) while the window stays live, as `aokit reference` traces it.
//! It belongs to one camera and render size: the viewer drops it when either changes.

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::thread::JoinHandle;

use anyhow::{Result, anyhow};
use aokit_reference::{AoOptions, Falloff, ReferenceImage};
use aokit_scene::{Camera, Scene};

/// Rays per pixel when `--reference-spp` is not given: fewer on a software adapter, whose
/// rasteriser shares the CPU with the trace.
pub fn default_spp(software: bool) -> u32 {
    if software { 32 } else { 128 }
}

/// A reference traced, or being traced, for one camera at one size.
pub struct Truth {
    /// The camera traced.
    pub camera: Camera,
    /// The size traced: the size the view renders at.
    pub size: [u32; 2],
    /// The moving parts' time traced.
    pub time: f32,
    /// The options traced with (the AO radius as A had it when the trace started).
    pub options: AoOptions,
    state: State,
}

enum State {
    Tracing {
        rows_done: Arc<AtomicUsize>,
        thread: JoinHandle<Result<ReferenceImage>>,
    },
    Ready(ReferenceImage),
    Failed(String),
}

impl Truth {
    /// Starts tracing `camera`'s view of `scene` (its moving parts at `time`) at `size` with
    /// `spp` rays per pixel and AO `radius`, with the options `aokit compare` traces with (seed
    /// 0, no falloff).
    pub fn start(
        scene: Arc<Scene>,
        (camera, time): (Camera, f32),
        size: [u32; 2],
        spp: u32,
        radius: f32,
    ) -> Self {
        let options = AoOptions {
            radius,
            spp,
            seed: 0,
            falloff: Falloff::None,
        };
        let rows_done = Arc::new(AtomicUsize::new(0));
        let thread = {
            let (camera, rows_done) = (camera.clone(), rows_done.clone());
            std::thread::spawn(move || {
                let tracer = crate::reference::scene_tracer_at(&scene, time)?;
                crate::reference::trace_reporting(
                    &tracer,
                    &scene,
                    &camera,
                    size,
                    &options,
                    &|rows| rows_done.store(rows, Ordering::Relaxed),
                )
            })
        };
        Self {
            camera,
            size,
            time,
            options,
            state: State::Tracing { rows_done, thread },
        }
    }

    /// Takes the trace's result once its thread has finished; `true` when it did just now.
    pub fn poll(&mut self) -> bool {
        let finished = matches!(&self.state, State::Tracing { thread, .. } if thread.is_finished());
        if !finished {
            return false;
        }
        let State::Tracing { thread, .. } =
            std::mem::replace(&mut self.state, State::Failed(String::new()))
        else {
            return false;
        };
        self.state = match thread.join() {
            Ok(Ok(image)) => State::Ready(image),
            Ok(Err(e)) => State::Failed(format!("{e:#}")),
            Err(_) => State::Failed("the trace's thread panicked".into()),
        };
        true
    }

    /// The fraction of rows traced so far; `None` once the trace is over.
    pub fn progress(&self) -> Option<f32> {
        match &self.state {
            State::Tracing { rows_done, .. } => {
                Some(rows_done.load(Ordering::Relaxed) as f32 / self.size[1] as f32)
            }
            _ => None,
        }
    }

    /// The reference, once traced.
    pub fn image(&self) -> Option<&ReferenceImage> {
        match &self.state {
            State::Ready(image) => Some(image),
            _ => None,
        }
    }

    /// Why the trace failed.
    pub fn error(&self) -> Option<anyhow::Error> {
        match &self.state {
            State::Failed(e) => Some(anyhow!("the reference trace failed: {e}")),
            _ => None,
        }
    }

    /// Whether this reference is of `camera`'s view at `size`, the moving parts at `time`.
    pub fn is_of(&self, (camera, time): (&Camera, f32), size: [u32; 2]) -> bool {
        self.camera == *camera && self.size == size && self.time == time
    }
}
