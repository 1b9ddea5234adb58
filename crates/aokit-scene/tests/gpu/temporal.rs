//! The temporal filter over frame sequences, on whatever adapter exists (lavapipe in CI).

use crate::common;

use aokit::gpu::read_texture_f32;
use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, Preset};
use aokit_reference::ReferenceImage;
use aokit_scene::{Builtin, CameraPath, Frame, Renderer, Scene};
use common::{encode_frame, gpu, linear_depth_texture, trace_at};

const SIZE: [u32; 2] = [160, 96];

/// GTAO `high` with the temporal filter on or off, and without the spatial filter the preset
/// runs: these tests are about the temporal filter alone, on the kernel's AO.
fn settings(scene: &Scene, temporal: bool) -> AoSettings {
    let mut s = AoSettings {
        radius: scene.suggested_radius.unwrap(),
        ..AoSettings::preset(Method::Gtao, Preset::High)
    };
    s.spatial.enabled = false;
    s.temporal.enabled = temporal;
    s
}

/// `frames` frames of the scene's first camera moving along `path`.
fn sequence(
    gpu: &GpuContext,
    scene: &Scene,
    path: CameraPath,
    frames: u32,
    temporal: bool,
) -> Vec<Frame> {
    let mut renderer = Renderer::new(gpu, scene, &settings(scene, temporal)).unwrap();
    render_sequence(gpu, &mut renderer, scene, path, frames, false)
}

/// `frames` frames through `renderer` of the scene's first camera moving along `path`, and of
/// its moving parts moving when `animate`.
fn render_sequence(
    gpu: &GpuContext,
    renderer: &mut Renderer,
    scene: &Scene,
    path: CameraPath,
    frames: u32,
    animate: bool,
) -> Vec<Frame> {
    let camera = &scene.cameras[0];
    (0..frames)
        .map(|i| {
            let t = i as f32 / (frames - 1) as f32;
            let time = if animate { t } else { 0.0 };
            renderer
                .render_at(gpu, &path.at(camera, t), SIZE, i, time)
                .unwrap()
        })
        .collect()
}

/// Mean absolute change of AO between consecutive frames over the pixels with a surface.
fn flicker(frames: &[Frame]) -> f64 {
    let pairs = frames.windows(2).map(|w| {
        let changes: Vec<f64> = w[0]
            .ao
            .iter()
            .zip(&w[1].ao)
            .zip(&w[1].linear_depth)
            .filter(|(_, d)| **d > 0.0)
            .map(|((a, b), _)| f64::from((a - b).abs()))
            .collect();
        changes.iter().sum::<f64>() / changes.len() as f64
    });
    pairs.clone().sum::<f64>() / pairs.count() as f64
}

#[test]
fn a_still_camera_flickers_at_least_five_times_less() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let raw = flicker(&sequence(&gpu, &scene, CameraPath::Still, 12, false));
    // The history needs a few frames to fill: score the second half.
    let filtered = flicker(&sequence(&gpu, &scene, CameraPath::Still, 12, true)[6..]);
    assert!(
        raw > 5.0 * filtered,
        "flicker {raw} raw, {filtered} filtered"
    );
}

/// RMSE of `frame` against `traced` over the pixels with a surface that `keep` keeps.
fn rmse(frame: &Frame, traced: &ReferenceImage, keep: impl Fn(usize) -> bool) -> f64 {
    common::rmse(&frame.ao, &traced.ao, |i| {
        traced.linear_depth[i] > 0.0 && keep(i)
    })
}

#[test]
fn a_moving_camera_stays_closer_to_the_reference_than_single_frames() {
    let gpu = gpu();
    let scene = Builtin::Stairs.build();
    for path in [CameraPath::Orbit, CameraPath::Strafe, CameraPath::Dolly] {
        let raw = sequence(&gpu, &scene, path, 10, false);
        let filtered = sequence(&gpu, &scene, path, 10, true);
        let traced = trace_at(&scene, 0.0, &path.at(&scene.cameras[0], 1.0), SIZE, 128);
        let (raw, filtered) = (
            rmse(&raw[9], &traced, |_| true),
            rmse(&filtered[9], &traced, |_| true),
        );
        // Trailing history would put yesterday's shadows in today's pixels and raise the error.
        assert!(
            filtered < raw,
            "{}: RMSE {filtered} filtered, {raw} raw",
            path.name()
        );
    }
}

/// Pixels near where the picture's geometry changed over the last `frames` frames of
/// `sequence`: a relative depth change beyond 1%, grown by `grow` pixels to take in the AO the
/// change casts around it. Where a moving part would leave a trail.
fn changed_region(sequence: &[Frame], frames: usize, grow: i32) -> Vec<bool> {
    let (last, earlier) = (
        &sequence[sequence.len() - 1],
        &sequence[sequence.len() - 1 - frames],
    );
    let [w, h] = SIZE.map(|side| side as i32);
    let changed: Vec<bool> = last
        .linear_depth
        .iter()
        .zip(&earlier.linear_depth)
        .map(|(&a, &b)| (a - b).abs() > 0.01 * a.max(b))
        .collect();
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            (-grow..=grow).any(|dy| {
                (-grow..=grow).any(|dx| {
                    let (u, v) = (x + dx, y + dy);
                    (0..w).contains(&u) && (0..h).contains(&v) && changed[(v * w + u) as usize]
                })
            })
        })
        .collect()
}

#[test]
fn moving_parts_leave_no_trail() {
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin] {
        let scene = builtin.build();
        let run = |temporal: bool, motion_vectors: bool| {
            let mut renderer = Renderer::new(&gpu, &scene, &settings(&scene, temporal)).unwrap();
            renderer.use_motion_vectors = motion_vectors;
            render_sequence(&gpu, &mut renderer, &scene, CameraPath::Still, 10, true)
        };
        let (raw, filtered, camera_only) = (run(false, true), run(true, true), run(true, false));
        let traced = trace_at(&scene, 1.0, &scene.cameras[0], SIZE, 128);
        // The camera stands still, so the pixels with motion show the moving part. Around it,
        // over the history's length of about 1 / (1 - blend) = 5 frames, lies where a trail
        // would be.
        let part: Vec<bool> = filtered[9]
            .motion_vectors
            .iter()
            .map(|m| m.length() > 0.1)
            .collect();
        let region = changed_region(&filtered, 5, 4);
        let trail: Vec<bool> = region.iter().zip(&part).map(|(&r, &p)| r && !p).collect();
        let masks = [vec![true; part.len()], trail, part];
        let score = |frames: &[Frame]| {
            masks
                .each_ref()
                .map(|m| rmse(&frames[9], &traced, |i| m[i]))
        };
        let (raw, filtered, camera_only) = (score(&raw), score(&filtered), score(&camera_only));
        let share = |mask: &[bool]| mask.iter().filter(|&&m| m).count() as f64 / mask.len() as f64;
        eprintln!(
            "{}: RMSE of the last frame, all pixels / around the moving part ({:.1}%) / on it \
             ({:.1}%): single frames {:.4} / {:.4} / {:.4}, filtered {:.4} / {:.4} / {:.4}, \
             filtered without motion vectors {:.4} / {:.4} / {:.4}",
            scene.name,
            100.0 * share(&masks[1]),
            100.0 * share(&masks[2]),
            raw[0],
            raw[1],
            raw[2],
            filtered[0],
            filtered[1],
            filtered[2],
            camera_only[0],
            camera_only[1],
            camera_only[2],
        );
        assert!(share(&masks[2]) > 0.01, "{}: nothing moved", scene.name);
        assert!(
            filtered[0] < raw[0] && filtered[1] <= raw[1],
            "{}: {filtered:?} filtered, {raw:?} single frames",
            scene.name
        );
    }
}

/// With and without a guard band: the overscan's motion vectors, drawn through the widened
/// frustum, are the frame's, and the filter reads them at the band's offset.
#[test]
fn motion_vectors_of_a_still_scene_change_nothing() {
    let gpu = gpu();
    let scene = Builtin::Stairs.build();
    for band in [0, 16] {
        for path in [CameraPath::Strafe, CameraPath::Orbit] {
            let run = |motion_vectors: bool| {
                let mut renderer = Renderer::new(&gpu, &scene, &settings(&scene, true)).unwrap();
                renderer.use_motion_vectors = motion_vectors;
                renderer.guard_band = band;
                render_sequence(&gpu, &mut renderer, &scene, path, 10, false)
            };
            let (with, without) = (run(true), run(false));
            let differences: Vec<f32> = with[9]
                .ao
                .iter()
                .zip(&without[9].ao)
                .map(|(a, b)| (a - b).abs())
                .collect();
            let mean = differences.iter().sum::<f32>() / differences.len() as f32;
            let largest = differences.iter().copied().fold(0.0, f32::max);
            eprintln!(
                "{}, {band} px band: AO with and without motion vectors differ by {mean:.2e} on \
                 average, {largest:.4} at most",
                path.name()
            );
            assert!(
                mean < 1e-3 && largest < 0.05,
                "{}, {band} px band: {mean} {largest}",
                path.name()
            );
        }
    }
}

#[test]
fn disocclusions_and_resets_reject_the_history() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let frames = sequence(&gpu, &scene, CameraPath::Orbit, 6, true);
    let rejected = |frame: &Frame| {
        let (mask, mask_size) = frame
            .history_rejected
            .as_ref()
            .expect("temporal filter is on");
        assert_eq!(*mask_size, frame.size, "at full resolution");
        let covered = frame.linear_depth.iter().filter(|&&d| d > 0.0).count();
        let hits = mask
            .iter()
            .zip(&frame.linear_depth)
            .filter(|(r, d)| **r > 0.5 && **d > 0.0)
            .count();
        hits as f64 / covered as f64
    };
    assert_eq!(rejected(&frames[0]), 1.0, "the first frame has no history");
    // An orbit step reveals a little at the screen's edge and behind objects, not more.
    let moving = rejected(&frames[5]);
    assert!(
        moving > 0.0 && moving < 0.2,
        "{moving} of the pixels rejected while orbiting"
    );

    let mut renderer = Renderer::new(&gpu, &scene, &settings(&scene, true)).unwrap();
    renderer.render(&gpu, &scene.cameras[0], SIZE, 0).unwrap();
    let kept = renderer.render(&gpu, &scene.cameras[0], SIZE, 1).unwrap();
    assert_eq!(rejected(&kept), 0.0, "a still camera keeps all its history");
    renderer.reset_history();
    let reset = renderer.render(&gpu, &scene.cameras[0], SIZE, 2).unwrap();
    assert_eq!(rejected(&reset), 1.0, "a reset starts over");
}

#[test]
fn each_view_keeps_its_own_history() {
    let gpu = gpu();
    let scene = Builtin::Stairs.build();
    let cameras = [scene.cameras[0].clone(), scene.cameras[1].clone()];
    // Linear depth of each view from the scene renderer, handed to the pipeline as R32Float.
    let mut renderer = Renderer::new(&gpu, &scene, &settings(&scene, false)).unwrap();
    let views: Vec<Frame> = cameras
        .iter()
        .map(|c| renderer.render(&gpu, c, SIZE, 0).unwrap())
        .collect();
    let depth: Vec<wgpu::Texture> = views
        .iter()
        .map(|f| linear_depth_texture(&gpu, SIZE, &f.linear_depth))
        .collect();
    let run = |pipeline: &mut AoPipeline, view: usize, frame: u32| -> Vec<f32> {
        let inputs = AoInputs {
            view_from_world: views[view].view_from_world,
            frame_index: frame,
            view_id: view as u32,
            ..AoInputs::new(&depth[view], views[view].projection)
        };
        encode_frame(&gpu, pipeline, &inputs, |outputs| {
            read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap()
        })
    };
    let s = settings(&scene, true);
    let mut shared = AoPipeline::new(&gpu.device, &gpu.queue, &s).unwrap();
    let mut alone = [
        AoPipeline::new(&gpu.device, &gpu.queue, &s).unwrap(),
        AoPipeline::new(&gpu.device, &gpu.queue, &s).unwrap(),
    ];
    for frame in 0..4 {
        for (view, alone) in alone.iter_mut().enumerate() {
            let interleaved = run(&mut shared, view, frame);
            let separate = run(alone, view, frame);
            assert_eq!(interleaved, separate, "view {view}, frame {frame}");
        }
    }
}

/// With `temporal.filter_current`, a frame without history shows the mean of each pixel's 3x3
/// neighbours on the same surface (relative depth difference within the threshold).
#[test]
fn a_filtered_current_value_is_the_same_surface_mean() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let mut renderer = Renderer::new(&gpu, &scene, &settings(&scene, false)).unwrap();
    let frame = renderer.render(&gpu, &scene.cameras[0], SIZE, 0).unwrap();
    let depth = linear_depth_texture(&gpu, SIZE, &frame.linear_depth);
    let mut s = settings(&scene, true);
    s.temporal.filter_current = true;
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &s).unwrap();
    let inputs = AoInputs::new(&depth, frame.projection);
    let (filtered, raw) = encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
        let read = |texture| read_texture_f32(&gpu.device, &gpu.queue, texture).unwrap();
        (read(outputs.ao), read(outputs.raw_ao))
    });
    let d = &frame.linear_depth;
    let [w, h] = SIZE.map(|s| s as i32);
    let threshold = s.temporal.depth_threshold;
    let mut differs = 0;
    for y in 0..h {
        for x in 0..w {
            let i = (x + y * w) as usize;
            if d[i] <= 0.0 {
                assert_eq!(filtered[i], 1.0, "sky at ({x}, {y})");
                continue;
            }
            let same: Vec<f32> = (-1..=1)
                .flat_map(|dy| (-1..=1).map(move |dx| (dx, dy)))
                .map(|(dx, dy)| ((x + dx).clamp(0, w - 1) + (y + dy).clamp(0, h - 1) * w) as usize)
                .filter(|&j| d[j] > 0.0 && (d[j] - d[i]).abs() <= threshold * d[j].min(d[i]))
                .map(|j| raw[j])
                .collect();
            let mean = same.iter().sum::<f32>() / same.len() as f32;
            assert!(
                (filtered[i] - mean).abs() < 1e-5,
                "({x}, {y}): {} against the mean {mean}",
                filtered[i]
            );
            differs += usize::from(filtered[i] != raw[i]);
        }
    }
    assert!(differs > 0, "the filter changed nothing");
}
