//! The temporal filter over frame sequences, on whatever adapter exists (lavapipe in CI).

use aokit::gpu::{read_texture_f32, upload_texture_2d};
use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, Preset};
use aokit_reference::AoOptions;
use aokit_scene::{Builtin, Camera, CameraPath, Frame, Renderer, Scene, reference};

const SIZE: [u32; 2] = [160, 96];

fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

fn settings(scene: &Scene, temporal: bool) -> AoSettings {
    let mut s = AoSettings {
        radius: scene.suggested_radius.unwrap(),
        ..AoSettings::preset(Method::Gtao, Preset::High)
    };
    s.temporal.enabled = temporal;
    s
}

/// `frames` frames of `camera` moving along `path`.
fn sequence(
    gpu: &GpuContext,
    scene: &Scene,
    path: CameraPath,
    frames: u32,
    temporal: bool,
) -> Vec<Frame> {
    let camera = &scene.cameras[0];
    let mut renderer = Renderer::new(gpu, scene, &settings(scene, temporal)).unwrap();
    (0..frames)
        .map(|i| {
            let t = i as f32 / (frames - 1) as f32;
            renderer.render(gpu, &path.at(camera, t), SIZE, i).unwrap()
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

/// RMSE of `frame` against a ray-traced reference of `camera`.
fn rmse(scene: &Scene, camera: &Camera, frame: &Frame) -> f64 {
    let options = AoOptions {
        radius: scene.suggested_radius.unwrap(),
        spp: 128,
        ..Default::default()
    };
    let traced = reference::tracer(scene)
        .unwrap()
        .render(
            &reference::pixel_camera(scene, camera, SIZE),
            &options,
            &|_| {},
        )
        .unwrap();
    let errors: Vec<f64> = frame
        .ao
        .iter()
        .zip(&traced.ao)
        .zip(&traced.linear_depth)
        .filter(|(_, d)| **d > 0.0)
        .map(|((a, r), _)| f64::from(a - r).powi(2))
        .collect();
    (errors.iter().sum::<f64>() / errors.len() as f64).sqrt()
}

#[test]
fn a_moving_camera_stays_closer_to_the_reference_than_single_frames() {
    let gpu = gpu();
    let scene = Builtin::Stairs.build();
    for path in [CameraPath::Orbit, CameraPath::Strafe, CameraPath::Dolly] {
        let raw = sequence(&gpu, &scene, path, 10, false);
        let filtered = sequence(&gpu, &scene, path, 10, true);
        let last = path.at(&scene.cameras[0], 1.0);
        let (raw, filtered) = (
            rmse(&scene, &last, &raw[9]),
            rmse(&scene, &last, &filtered[9]),
        );
        // Trailing history would put yesterday's shadows in today's pixels and raise the error.
        assert!(
            filtered < raw,
            "{}: RMSE {filtered} filtered, {raw} raw",
            path.name()
        );
    }
}

#[test]
fn disocclusions_and_resets_reject_the_history() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let frames = sequence(&gpu, &scene, CameraPath::Orbit, 6, true);
    let rejected = |frame: &Frame| {
        let mask = frame
            .history_rejected
            .as_ref()
            .expect("temporal filter is on");
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
        .map(|f| {
            upload_texture_2d(
                &gpu.device,
                &gpu.queue,
                "depth",
                SIZE,
                wgpu::TextureFormat::R32Float,
                bytemuck::cast_slice(&f.linear_depth),
            )
            .unwrap()
        })
        .collect();
    let run = |pipeline: &mut AoPipeline, view: usize, frame: u32| -> Vec<f32> {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        let outputs = pipeline
            .encode(
                &gpu.device,
                &gpu.queue,
                &mut encoder,
                &AoInputs {
                    view_from_world: views[view].view_from_world,
                    frame_index: frame,
                    view_id: view as u32,
                    ..AoInputs::new(&depth[view], views[view].projection)
                },
            )
            .unwrap();
        gpu.queue.submit([encoder.finish()]);
        read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap()
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
