//! The soak: frame after frame of the scene renderer and the AO pipeline while methods,
//! presets, resolutions, filters, image sizes (down to 1x1), masks, bent normals and lighting
//! modes change at random. Every frame is checked for NaN, AO outside [0, 1] and wgpu
//! validation errors; at the end, process memory and wgpu's live resource counts must be where
//! they were after the warm-up.
//!
//! The frames cycle through a list of random configurations drawn from a seed: the first cycle
//! is the warm-up (each configuration compiles what it needs once, kept for later frames), and
//! the counts are taken after whole cycles, each time with the cycle's last configuration
//! rendered, so that a leak-free run shows identical counts. `AOKIT_SOAK_FRAMES` sets the
//! number of frames (default: three cycles, about 10 s in debug on lavapipe),
//! `AOKIT_SOAK_CONFIGS` the configurations in a cycle (default 16) and `AOKIT_SOAK_SEED` the
//! seed; `scripts/soak.sh` runs 10,000 frames of 250 configurations in release.
//! docs/reliability.md has the results.

use std::sync::{Arc, Mutex};

use aokit::gpu::{read_texture_f32, read_texture_rgba16f, upload_texture_2d};
use aokit::{
    AoInputs, AoMask, AoPipeline, AoSettings, FilterResolution, GpuContext, Method, Preset,
    Resolution, SpatialKind,
};
use aokit_scene::composite::{MultiBounce, SpecularOcclusion};
use aokit_scene::{Builtin, CameraPath, Renderer, Scene};

use crate::common::gpu;

/// Configurations per cycle, unless `AOKIT_SOAK_CONFIGS` says otherwise.
const CYCLE: usize = 16;
/// Sizes drawn from: 1x1 and thin strips as well as ordinary small images.
const SIZES: [[u32; 2]; 8] = [
    [1, 1],
    [64, 48],
    [33, 17],
    [1, 40],
    [40, 1],
    [96, 54],
    [7, 5],
    [50, 50],
];
/// Process memory may grow this much between the end of the warm-up and the end, for the
/// allocator's own bookkeeping; a leak of the composite's kind (0.5 MB a frame) passes it in
/// under 10 frames.
const RSS_SLACK_KB: i64 = 4 * 1024;

/// SplitMix64: a seeded generator, so that a failing run can be repeated.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    fn coin(&mut self) -> bool {
        self.next() & 1 == 1
    }
}

/// What one frame runs.
#[derive(Clone, Debug)]
struct Config {
    settings: AoSettings,
    size: [u32; 2],
    /// A mask texture's value at every pixel: the frame runs the AO pipeline alone on the
    /// renderer's G-buffer (the renderer takes no mask); `None` renders a whole frame.
    mask: Option<u8>,
    multi_bounce: MultiBounce,
    specular_occlusion: SpecularOcclusion,
}

fn random_config(rng: &mut Rng, scene: &Scene) -> Config {
    let method = rng.pick(&Method::ALL);
    let mut settings = AoSettings {
        radius: scene.suggested_radius.unwrap_or(1.0),
        resolution: rng.pick(&Resolution::ALL),
        filter_resolution: rng.pick(&FilterResolution::ALL),
        bent_normals: method.has_bent_normals() && rng.coin(),
        ..AoSettings::preset(method, rng.pick(&Preset::ALL))
    };
    settings.spatial.enabled = rng.coin();
    settings.spatial.kind = rng.pick(&SpatialKind::ALL);
    settings.temporal.enabled = rng.coin();
    Config {
        settings,
        size: rng.pick(&SIZES),
        mask: rng.coin().then(|| rng.pick(&[0, 128, 255])),
        multi_bounce: rng.pick(&MultiBounce::ALL),
        specular_occlusion: rng.pick(&SpecularOcclusion::ALL),
    }
}

/// Resident memory of this process in KiB (Linux; 0 elsewhere, where only the counts are
/// compared).
fn resident_kb() -> i64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|status| {
            let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
            line.split_whitespace().nth(1)?.parse().ok()
        })
        .unwrap_or(0)
}

/// wgpu's live objects and memory by kind (its `counters` feature). Textures are left out:
/// wgpu-hal 30's Vulkan backend counts their destruction but not their creation; their
/// memory is counted. So are command encoders, which wgpu keeps in a pool for reuse: see
/// [`ENCODER_POOL_SLACK`].
fn live_counts(gpu: &GpuContext) -> Vec<(&'static str, isize)> {
    let counters = gpu.device.get_internal_counters().hal;
    vec![
        ("buffers", counters.buffers.read()),
        ("buffer_memory", counters.buffer_memory.read()),
        ("texture_memory", counters.texture_memory.read()),
        ("texture_views", counters.texture_views.read()),
        ("bind_groups", counters.bind_groups.read()),
        ("bind_group_layouts", counters.bind_group_layouts.read()),
        ("compute_pipelines", counters.compute_pipelines.read()),
        ("render_pipelines", counters.render_pipelines.read()),
        ("pipeline_layouts", counters.pipeline_layouts.read()),
        ("shader_modules", counters.shader_modules.read()),
        ("samplers", counters.samplers.read()),
        ("query_sets", counters.query_sets.read()),
    ]
}

/// wgpu keeps finished command encoders for reuse, as many as were ever in use at once: a few.
/// Here the pool went from 5 to 6 within the first cycles and stayed there for 10,000 frames.
const ENCODER_POOL_SLACK: isize = 4;

fn pooled_encoders(gpu: &GpuContext) -> isize {
    gpu.device
        .get_internal_counters()
        .hal
        .command_encoders
        .read()
}

/// Renders one frame of `config`, returning a description of anything wrong with it.
fn run_frame(
    gpu: &GpuContext,
    scene: &Scene,
    renderer: &mut Renderer,
    pipeline: &mut AoPipeline,
    config: &Config,
    frame: u32,
) -> Result<(), String> {
    let camera = CameraPath::Orbit.at(&scene.cameras[0], (frame % 50) as f32 / 49.0);
    let (ao, bent_normals) = match config.mask {
        None => {
            renderer.lighting.multi_bounce = config.multi_bounce;
            renderer.lighting.specular_occlusion = config.specular_occlusion;
            renderer
                .set_settings(gpu, &config.settings)
                .map_err(|e| format!("set_settings: {e}"))?;
            let time = (frame % 20) as f32 / 19.0;
            let rendered = renderer
                .render_at(gpu, &camera, config.size, frame, time)
                .map_err(|e| format!("render: {e}"))?;
            let bent: Option<Vec<f32>> = rendered
                .bent_normals
                .map(|b| b.iter().flat_map(|v| v.to_array()).collect());
            (rendered.ao, bent)
        }
        Some(value) => {
            let (device, queue) = (&gpu.device, &gpu.queue);
            pipeline
                .set_settings(device, queue, &config.settings)
                .map_err(|e| format!("set_settings: {e}"))?;
            let (gbuffer, projection) = renderer
                .render_gbuffer(gpu, &camera, config.size, config.settings.normals.encoding)
                .map_err(|e| format!("render_gbuffer: {e}"))?;
            let [width, height] = config.size;
            let texels = vec![value; (width * height) as usize];
            let mask = upload_texture_2d(
                device,
                queue,
                "soak mask",
                config.size,
                wgpu::TextureFormat::R8Unorm,
                &texels,
            )
            .map_err(|e| format!("mask upload: {e}"))?;
            let inputs = AoInputs {
                normals: Some((&gbuffer.normals).into()),
                view_from_world: camera.view_from_world(),
                frame_index: frame,
                mask: Some(AoMask::Texture((&mask).into())),
                back_depth: gbuffer.back_depth.as_ref().map(Into::into),
                ..AoInputs::new(&gbuffer.depth, projection)
            };
            let mut encoder = device.create_command_encoder(&Default::default());
            let outputs = pipeline
                .encode(device, queue, &mut encoder, &inputs)
                .map_err(|e| format!("encode: {e}"))?;
            queue.submit([encoder.finish()]);
            let ao = read_texture_f32(device, queue, outputs.ao).map_err(|e| e.to_string())?;
            let bent = outputs
                .bent_normals
                .map(|b| read_texture_rgba16f(device, queue, b))
                .transpose()
                .map_err(|e| e.to_string())?
                .map(|texels| texels.into_iter().flatten().collect());
            (ao, bent)
        }
    };
    let [width, height] = config.size;
    if ao.len() != (width * height) as usize {
        return Err(format!("{} AO values for {width}x{height}", ao.len()));
    }
    if let Some(i) = ao.iter().position(|a| !(0.0..=1.0).contains(a)) {
        return Err(format!("AO {} at pixel {i}", ao[i]));
    }
    if let Some(bent) = bent_normals
        && let Some(i) = bent.iter().position(|v: &f32| !v.is_finite())
    {
        return Err(format!("bent normal component {} at {i}", bent[i]));
    }
    Ok(())
}

#[test]
fn methods_sizes_and_filters_switched_at_random_leak_nothing() {
    let number = |name: &str, default: usize| -> usize {
        std::env::var(name)
            .map(|v| {
                v.parse()
                    .unwrap_or_else(|_| panic!("{name} must be a number, got {v}"))
            })
            .unwrap_or(default)
    };
    let cycle = number("AOKIT_SOAK_CONFIGS", CYCLE).max(1);
    let frames = number("AOKIT_SOAK_FRAMES", 3 * cycle);
    let seed = number("AOKIT_SOAK_SEED", 29) as u64;
    assert!(
        frames >= 2 * cycle,
        "AOKIT_SOAK_FRAMES: at least {} frames, a warm-up cycle and one to compare",
        2 * cycle
    );
    let gpu = gpu();
    let errors = Arc::new(Mutex::new(Vec::<String>::new()));
    let sink = errors.clone();
    gpu.device.on_uncaptured_error(Arc::new(move |error| {
        sink.lock().unwrap().push(error.to_string());
    }));
    let scene = Builtin::Room.build();
    let mut rng = Rng(seed);
    let configs: Vec<Config> = (0..cycle)
        .map(|_| random_config(&mut rng, &scene))
        .collect();
    let mut renderer = Renderer::new(&gpu, &scene, &configs[0].settings).unwrap();
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &configs[0].settings).unwrap();

    // Compared from the end of the warm-up cycle to the end of the last whole cycle.
    let last = frames / cycle * cycle;
    let mut baseline = None;
    let started = std::time::Instant::now();
    for frame in 0..last {
        let config = &configs[frame % cycle];
        let result = run_frame(
            &gpu,
            &scene,
            &mut renderer,
            &mut pipeline,
            config,
            frame as u32,
        );
        let validation = std::mem::take(&mut *errors.lock().unwrap());
        if let Err(problem) = result.and_then(|()| match validation.first() {
            Some(error) => Err(format!("wgpu error: {error}")),
            None => Ok(()),
        }) {
            panic!("frame {frame} (seed {seed}) with {config:?}: {problem}");
        }
        if (frame + 1) % cycle == 0 {
            let (rss, counts) = (resident_kb(), live_counts(&gpu));
            if frame + 1 == cycle {
                baseline = Some((rss, counts.clone(), pooled_encoders(&gpu)));
            }
            if (frame + 1) % 1000 < cycle || frame + 1 == cycle || frame + 1 == last {
                eprintln!(
                    "soak: frame {} of {last}, {:.1} s, resident {} MiB, pooled encoders {}, {counts:?}",
                    frame + 1,
                    started.elapsed().as_secs_f64(),
                    rss / 1024,
                    pooled_encoders(&gpu)
                );
            }
        }
    }
    let (rss_start, counts_start, encoders_start) = baseline.expect("a warm-up cycle ran");
    let (rss_end, counts_end, encoders_end) =
        (resident_kb(), live_counts(&gpu), pooled_encoders(&gpu));
    eprintln!(
        "soak: {last} frames of {cycle} configurations, seed {seed}, resident {rss_start} KiB \
         after the warm-up, {rss_end} KiB at the end, {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert_eq!(
        counts_start, counts_end,
        "wgpu's live objects after the warm-up (left) and at the end (right)"
    );
    assert!(
        encoders_end - encoders_start <= ENCODER_POOL_SLACK,
        "wgpu's pool of command encoders grew from {encoders_start} to {encoders_end}"
    );
    assert!(
        rss_end - rss_start < RSS_SLACK_KB,
        "resident memory grew from {rss_start} KiB to {rss_end} KiB over {} frames",
        last - cycle
    );
}
