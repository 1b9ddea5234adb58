//! A renderer's frame loop with aokit's temporal filter: a camera that moves each frame, TAA
//! jitter, motion vectors, a camera cut and a window resize.
//!
//! ```sh
//! cargo run -p aokit --example frame_loop -- out.png [WIDTHxHEIGHT]   # default frame_loop.png
//! ```
//!
//! The renderer is the `forward` example's (`common/mod.rs`); its prepass writes motion vectors
//! too. The loop draws 24 frames: the camera turns about the scene, the window shrinks to 5/6 by
//! 3/4 of its size for frames 8 to 15 and comes back, and at frame 20 the view cuts back to where
//! it started and holds still. The PNG is the last frame's AO over the sky. What aokit needs lies
//! between the `aokit: begin` and `aokit: end` comments; docs/integration.md has the conventions.

mod common;

use std::path::Path;

use aokit::{AoInputs, AoOutputs, AoPipeline, AoSettings, GpuContext, Method, Preset};
use common::{Camera, Renderer, Result, Stats};
use glam::{Mat4, Vec2};

/// The lighting pass shows the AO itself, grey on the surfaces, so the PNG is the AO.
const LIGHTING: &str = r#"
@group(1) @binding(0) var ao_texture: texture_2d<f32>;

@fragment
fn fs_lighting(in: VertexOut) -> @location(0) vec4<f32> {
    let ao = textureLoad(ao_texture, vec2<u32>(in.clip.xy), 0).r;
    // The target encodes to sRGB on write: decode first, so that the PNG's byte is 255 * AO.
    let linear = select(pow((ao + 0.055) / 1.055, 2.4), ao / 12.92, ao <= 0.04045);
    return vec4<f32>(vec3<f32>(linear), 1.0);
}
"#;

/// Frames the loop draws.
const FRAMES: u32 = 24;
/// How far the camera turns about the scene each frame, in degrees.
const TURN: f32 = 1.5;

fn main() -> Result<()> {
    common::main("frame_loop", run)
}

/// One frame of the loop: the window's size, the camera's turn about the scene, and whether the
/// view cuts there (shows something unrelated to the frame before).
#[derive(Clone, Copy, Debug)]
struct Shot {
    size: [u32; 2],
    degrees: f32,
    cut: bool,
}

/// The frames [`run`] draws for a window of `size`.
fn shots(size: [u32; 2]) -> Vec<Shot> {
    let small = [size[0] * 5 / 6, size[1] * 3 / 4];
    (0..FRAMES)
        .map(|frame| Shot {
            size: if (8..16).contains(&frame) {
                small
            } else {
                size
            },
            // From frame 20 on, back to the first view, held still.
            degrees: if frame < 20 { TURN * frame as f32 } else { 0.0 },
            cut: frame == 20,
        })
        .collect()
}

/// What the loop hands aokit as motion vectors.
#[derive(Clone, Copy, Debug)]
enum Motion {
    /// The prepass's: what a renderer does.
    Prepass,
    /// Zeros, as a broken motion-vector target would give (the tests' comparison).
    #[cfg_attr(not(test), expect(dead_code))]
    Zero,
    /// None: aokit reprojects by depth and the camera alone, right for a still scene (the tests'
    /// comparison).
    #[cfg_attr(not(test), expect(dead_code))]
    Camera,
}

/// Draws the frames of [`shots`] and writes the last one's AO to `out` as PNG. (`cargo test`
/// runs it too: see `common::tests`.)
fn run(gpu: &GpuContext, out: &Path, size: [u32; 2]) -> Result<Stats> {
    let shots = shots(size);
    let mut frames = FrameLoop::new(gpu, size, &settings())?;
    let (last, before) = shots.split_last().ok_or("no frames")?;
    for &shot in before {
        frames.frame(gpu, shot, Motion::Prepass, |_, encoder, _| {
            gpu.queue.submit([encoder.finish()]);
            Ok(())
        })?;
    }
    frames.frame(gpu, *last, Motion::Prepass, |renderer, encoder, outputs| {
        renderer.finish(gpu, encoder, outputs, out)
    })
}

/// The AO settings: GTAO at High as in `forward`, with the temporal filter on.
fn settings() -> AoSettings {
    // --- aokit: begin (once) ---
    let mut settings = AoSettings::preset(Method::Gtao, Preset::High);
    settings.radius = 0.75;
    settings.spatial.enabled = true;
    // Blends each frame with the history reprojected from the frames before.
    settings.temporal.enabled = true;
    // --- aokit: end ---
    settings
}

/// The renderer, the AO pipeline, and what the loop carries from frame to frame.
struct FrameLoop {
    renderer: Renderer,
    ao: AoPipeline,
    ao_layout: wgpu::BindGroupLayout,
    frame_index: u32,
    /// The camera matrix the last frame was drawn with, jitter included.
    previous_clip_from_world: Option<Mat4>,
}

impl FrameLoop {
    fn new(gpu: &GpuContext, size: [u32; 2], settings: &AoSettings) -> Result<Self> {
        let ao = AoPipeline::new(&gpu.device, &gpu.queue, settings)?;
        let ao_layout = common::load_textures_layout(&gpu.device, 1);
        Ok(Self {
            renderer: Renderer::new(&gpu.device, size, &[LIGHTING], &ao_layout),
            ao,
            ao_layout,
            frame_index: 0,
            previous_clip_from_world: None,
        })
    }

    /// Records one frame (prepass, AO, lighting) and hands the encoder, unsubmitted, to `then`.
    fn frame<T>(
        &mut self,
        gpu: &GpuContext,
        shot: Shot,
        motion: Motion,
        then: impl FnOnce(&Renderer, wgpu::CommandEncoder, &AoOutputs<'_>) -> Result<T>,
    ) -> Result<T> {
        let (device, queue) = (&gpu.device, &gpu.queue);
        // A resize: the renderer makes its own targets again. aokit makes its intermediate
        // textures at the next `encode`, by itself, and starts the temporal history over (the
        // old one has the old size), so the first frames at the new size are as noisy as a
        // cut; its output is a new texture, so the lighting pass's bind group is made again.
        if shot.size != self.renderer.size {
            self.renderer.resize(device, shot.size);
        }

        // --- aokit: begin (each frame, before the prepass) ---
        // TAA: the projection is offset by this frame's sub-pixel jitter, and aokit gets the
        // jittered projection too (its `ndc_offset`), or every position it reconstructs from
        // depth is off by the jitter.
        let mut camera = Camera::orbiting(shot.degrees, shot.size);
        camera.projection = camera
            .projection
            .with_jitter(jitter(self.frame_index), shot.size);
        let (view_from_world, projection) = (camera.view_from_world, camera.projection);
        // Motion vectors from the previous frame's camera, its jitter included: they point to
        // where the surface was in that frame's (jittered) image, which is where aokit's
        // history holds it. A cut has no previous frame.
        let previous = self.previous_clip_from_world.filter(|_| !shot.cut);
        self.previous_clip_from_world = Some(camera.clip_from_world());
        // --- aokit: end ---
        self.renderer.set_camera(queue, camera, previous);

        let mut encoder = device.create_command_encoder(&Default::default());
        self.renderer.prepass(&mut encoder);
        let zeros;
        let motion_vectors = match motion {
            Motion::Prepass => Some(&self.renderer.motion),
            Motion::Zero => {
                // wgpu clears a new texture to zero before its first use.
                let usage = wgpu::TextureUsages::TEXTURE_BINDING;
                let format = common::MOTION_FORMAT;
                zeros = aokit::gpu::create_texture_2d(device, "zeros", shot.size, format, usage);
                Some(&zeros)
            }
            Motion::Camera => None,
        };

        // --- aokit: begin (each frame, between the prepass and the lighting pass) ---
        let inputs = AoInputs {
            normals: Some((&self.renderer.normals).into()),
            view_from_world,
            // Moves the sampling noise each frame, for the temporal filter to average.
            frame_index: self.frame_index,
            motion_vectors: motion_vectors.map(Into::into),
            reset_history: shot.cut,
            ..AoInputs::new(&self.renderer.depth, projection)
        };
        let outputs = self.ao.encode(device, queue, &mut encoder, &inputs)?;
        let ao_group = common::load_textures_group(device, &self.ao_layout, &[outputs.ao_view]);
        self.frame_index = self.frame_index.wrapping_add(1);
        // --- aokit: end ---

        self.renderer.lighting(&mut encoder, &ao_group);
        then(&self.renderer, encoder, &outputs)
    }
}

/// Frame `index`'s TAA jitter in pixels, in [-0.5, 0.5) on each axis: the Halton (2, 3)
/// sequence from its second point (the first is the corner), 8 points in a cycle.
fn jitter(index: u32) -> Vec2 {
    let i = index % 8 + 1;
    Vec2::new(halton(i, 2), halton(i, 3)) - 0.5
}

/// The radical inverse of `index` in `base`: the Halton sequence's point `index` on one axis.
fn halton(mut index: u32, base: u32) -> f32 {
    let (mut value, mut scale) = (0.0, 1.0);
    while index > 0 {
        scale /= base as f32;
        value += scale * (index % base) as f32;
        index /= base;
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What the tests read of a frame: the AO's size and values, and how many pixels rejected
    /// the temporal history.
    struct Frame {
        size: [u32; 2],
        ao: Vec<f32>,
        rejected: usize,
    }

    /// Draws `shots` with `motion` and `settings`, reads each frame back, and checks that wgpu
    /// reported no validation error on the way.
    fn render(shots: &[Shot], motion: Motion, settings: &AoSettings) -> Vec<Frame> {
        let gpu = GpuContext::headless().unwrap();
        let (device, queue) = (&gpu.device, &gpu.queue);
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let mut frames = FrameLoop::new(&gpu, shots[0].size, settings).unwrap();
        let read = |encoder: wgpu::CommandEncoder, outputs: &AoOutputs<'_>| {
            queue.submit([encoder.finish()]);
            let ao = aokit::gpu::read_texture_f32(device, queue, outputs.ao)?;
            let rejected = match outputs.history_rejected {
                Some(texture) => aokit::gpu::read_texture_f32(device, queue, texture)?,
                None => vec![1.0; ao.len()],
            };
            Ok(Frame {
                size: [outputs.ao.width(), outputs.ao.height()],
                ao,
                rejected: rejected.iter().filter(|&&r| r > 0.5).count(),
            })
        };
        let read = shots.iter().map(|&shot| {
            frames
                .frame(&gpu, shot, motion, |_, encoder, outputs| {
                    read(encoder, outputs)
                })
                .unwrap()
        });
        let read: Vec<Frame> = read.collect();
        assert!(pollster::block_on(scope.pop()).is_none());
        read
    }

    fn mean_abs_difference(a: &[f32], b: &[f32]) -> f32 {
        assert_eq!(a.len(), b.len());
        a.iter().zip(b).map(|(a, b)| (a - b).abs()).sum::<f32>() / a.len() as f32
    }

    /// Through the whole loop every AO value is finite and in [0, 1]; each frame's AO has its
    /// window's size, before, during and after the resize; the history starts over at the
    /// resizes and the cut, and is used everywhere else.
    #[test]
    fn loop_survives_resizes_and_a_cut() {
        let shots = shots([96, 64]);
        assert_eq!(shots[8].size, [80, 48]);
        let frames = render(&shots, Motion::Prepass, &settings());
        for (i, (shot, frame)) in shots.iter().zip(&frames).enumerate() {
            assert_eq!(frame.size, shot.size, "frame {i}");
            assert_eq!(frame.ao.len() as u32, shot.size[0] * shot.size[1]);
            assert!(
                frame.ao.iter().all(|a| (0.0..=1.0).contains(a)),
                "frame {i}"
            );
            let pixels = frame.ao.len();
            let new_history = [0, 8, 16, 20].contains(&i);
            // All the surface (the sky, about 15%, is never rejected) at a new history; else
            // what the turn newly reveals and, with jitter, steep depth such as the far ground
            // (measured: 4% to 12%).
            if new_history {
                assert!(
                    frame.rejected > pixels * 3 / 4,
                    "frame {i}: {}",
                    frame.rejected
                );
            } else {
                assert!(frame.rejected < pixels / 5, "frame {i}: {}", frame.rejected);
            }
        }
    }

    /// `count` frames of a `96x64` window, the camera turned `degrees(frame)`.
    fn path(count: u32, degrees: impl Fn(u32) -> f32) -> Vec<Shot> {
        let shot = |frame| Shot {
            size: [96, 64],
            degrees: degrees(frame),
            cut: false,
        };
        (0..count).map(shot).collect()
    }

    /// While the camera turns, the prepass's motion vectors send aokit's history where the
    /// camera reprojection would (a still scene: they are the same motion), and without them
    /// (zeros) the history lags behind the image: the last frame's AO is farther from that of
    /// the same view held still.
    #[test]
    fn motion_vectors_keep_the_history_in_place() {
        let frames = 12;
        let turning = path(frames, |frame| TURN * frame as f32);
        let last = |motion| render(&turning, motion, &settings()).pop().unwrap().ao;
        let (vectors, camera, zeros) = (
            last(Motion::Prepass),
            last(Motion::Camera),
            last(Motion::Zero),
        );
        let held = path(frames, |_| TURN * (frames - 1) as f32);
        let reference = render(&held, Motion::Prepass, &settings())
            .pop()
            .unwrap()
            .ao;
        let error = |ao: &[f32]| mean_abs_difference(ao, &reference);
        // Measured at 96x64 on lavapipe: 0.00098 from the held view with the motion vectors,
        // 0.0040 with zeros; 1.9e-6 between the motion vectors and the camera reprojection.
        assert!(mean_abs_difference(&vectors, &camera) < 1e-4);
        assert!(
            error(&zeros) > 2.0 * error(&vectors),
            "{} {}",
            error(&zeros),
            error(&vectors)
        );
    }

    /// A still view, jittered: frames 8 apart have the same jitter, so what differs between
    /// them is the sampling noise `frame_index` moves. Single frames differ by as much each
    /// time; with the temporal filter the difference shrinks as the history accumulates.
    #[test]
    fn temporal_filter_converges_on_a_still_view() {
        let still = path(16, |_| 0.0);
        let noise = |settings: &AoSettings| {
            let frames = render(&still, Motion::Prepass, settings);
            let pair = |k: usize| mean_abs_difference(&frames[k].ao, &frames[k + 8].ao);
            [pair(0), pair(7)]
        };
        let mut single_frames = settings();
        single_frames.temporal.enabled = false;
        let (single, filtered) = (noise(&single_frames), noise(&settings()));
        // Measured at 96x64 on lavapipe: single frames 0.0036 and 0.0037, filtered 0.0037
        // (frame 0 has no history) and 0.0011.
        assert!(filtered[1] < filtered[0] / 2.0, "{filtered:?}");
        assert!(filtered[1] < single[1] / 2.0, "{filtered:?} {single:?}");
    }
}
