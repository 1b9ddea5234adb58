//! AO below full resolution through the whole pipeline, on whatever adapter exists (lavapipe in
//! CI): every combination of resolution, downsample, upsample and filter placement, motion
//! vectors at working resolution, and the distance to full-resolution AO on the built-in scenes.

use crate::common;

use aokit::gpu::{read_texture_f32, read_texture_rgba16f, upload_texture_2d};
use aokit::normals::pack_oct32;
use aokit::projection::pixel_to_ndc;
use aokit::{
    AoInputs, AoPipeline, AoSettings, Downsample, FilterResolution, GpuContext, Method, Preset,
    Resolution, Upsample,
};
use aokit_scene::{Builtin, Camera, CameraPath, Frame, Renderer, Scene};
use common::{
    DepthCopy, copy_depth, encode_frame, gpu, linear_depth_texture, mean_abs_difference, rmse,
    trace,
};
use glam::{Vec2, Vec3};

/// A frame's depth, normals and motion vectors as a renderer hands them to the pipeline.
struct Inputs {
    frame: Frame,
    depth: wgpu::Texture,
    normals: wgpu::Texture,
    motion_vectors: Option<wgpu::Texture>,
}

impl Inputs {
    /// `frame`'s linear depth (`R32Float`) and oct32 normals, and `motion_vectors` (pixels to
    /// where each pixel's surface was last frame) when given.
    fn new(gpu: &GpuContext, frame: Frame, motion_vectors: Option<&[Vec2]>) -> Self {
        let upload = |format, bytes: &[u8]| {
            upload_texture_2d(&gpu.device, &gpu.queue, "input", frame.size, format, bytes).unwrap()
        };
        let normals: Vec<u32> = frame
            .normals
            .iter()
            .map(|&n| pack_oct32(if n == Vec3::ZERO { Vec3::Z } else { n }))
            .collect();
        Self {
            depth: linear_depth_texture(gpu, frame.size, &frame.linear_depth),
            normals: upload(wgpu::TextureFormat::R32Uint, bytemuck::cast_slice(&normals)),
            motion_vectors: motion_vectors
                .map(|m| upload(wgpu::TextureFormat::Rg32Float, bytemuck::cast_slice(m))),
            frame,
        }
    }
}

/// What one encode produced, read back.
struct Output {
    ao: Vec<f32>,
    raw_ao: Vec<f32>,
    working_size: [u32; 2],
    bent_normals: Option<Vec<[f32; 4]>>,
    history_rejected: Option<Vec<f32>>,
}

fn run(gpu: &GpuContext, pipeline: &mut AoPipeline, inputs: &Inputs, frame_index: u32) -> Output {
    let frame = AoInputs {
        normals: Some((&inputs.normals).into()),
        view_from_world: inputs.frame.view_from_world,
        frame_index,
        motion_vectors: inputs.motion_vectors.as_ref().map(Into::into),
        ..AoInputs::new(&inputs.depth, inputs.frame.projection)
    };
    encode_frame(gpu, pipeline, &frame, |outputs| {
        let read = |texture| read_texture_f32(&gpu.device, &gpu.queue, texture).unwrap();
        Output {
            ao: read(outputs.ao),
            raw_ao: read(outputs.raw_ao),
            working_size: outputs.working_size,
            bent_normals: outputs
                .bent_normals
                .map(|t| read_texture_rgba16f(&gpu.device, &gpu.queue, t).unwrap()),
            history_rejected: outputs.history_rejected.map(read),
        }
    })
}

/// Frames of the scene's first camera along `path`, with the renderer's own AO off the point.
fn frames(
    gpu: &GpuContext,
    scene: &Scene,
    path: CameraPath,
    count: u32,
    size: [u32; 2],
) -> Vec<Frame> {
    let mut renderer = Renderer::new(gpu, scene, &AoSettings::default()).unwrap();
    (0..count)
        .map(|i| {
            let t = i as f32 / (count - 1).max(1) as f32;
            renderer
                .render(gpu, &path.at(&scene.cameras[0], t), size, i)
                .unwrap()
        })
        .collect()
}

/// Every resolution, downsample, upsample and filter placement: full resolution once, since
/// the others do not apply there.
fn every_combination() -> Vec<AoSettings> {
    let mut all = vec![AoSettings::default()];
    for resolution in [Resolution::Half, Resolution::Quarter] {
        for downsample in Downsample::ALL {
            for upsample in Upsample::ALL {
                for filter_resolution in FilterResolution::ALL {
                    all.push(AoSettings {
                        resolution,
                        downsample,
                        upsample,
                        filter_resolution,
                        ..AoSettings::default()
                    });
                }
            }
        }
    }
    all
}

#[test]
fn every_combination_runs_every_method_without_nan_and_sky_stays_one() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    // Odd sides: the last working texels hang over the image's edge at both scales.
    let size = [67, 41];
    let [first, second]: [Frame; 2] = frames(&gpu, &scene, CameraPath::Orbit, 2, size)
        .try_into()
        .unwrap();
    // Motion vectors of any value exercise the downsample's; these point nowhere in particular.
    let motion: Vec<Vec2> = (0..size[0] * size[1])
        .map(|i| Vec2::new((i % 3) as f32 - 1.0, 0.5))
        .collect();
    let inputs = [
        Inputs::new(&gpu, first, Some(&motion)),
        Inputs::new(&gpu, second, Some(&motion)),
    ];
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default()).unwrap();
    for method in Method::ALL {
        for base in every_combination() {
            let mut settings = AoSettings {
                radius: scene.suggested_radius.unwrap(),
                bent_normals: method.has_bent_normals(),
                ..AoSettings::preset(method, Preset::Medium)
            };
            settings.resolution = base.resolution;
            settings.downsample = base.downsample;
            settings.upsample = base.upsample;
            settings.filter_resolution = base.filter_resolution;
            settings.spatial.enabled = true;
            settings.temporal.enabled = true;
            pipeline
                .set_settings(&gpu.device, &gpu.queue, &settings)
                .unwrap();
            let label = format!(
                "{} {} {} {} {}",
                method.name(),
                settings.resolution.name(),
                settings.downsample.name(),
                settings.upsample.name(),
                settings.filter_resolution.name()
            );
            // The second frame blends with the first one's history.
            for (frame_index, inputs) in inputs.iter().enumerate() {
                let out = run(&gpu, &mut pipeline, inputs, frame_index as u32);
                let working = settings.resolution.working_size(size);
                assert_eq!(out.working_size, working, "{label}");
                assert_eq!(
                    out.raw_ao.len(),
                    (working[0] * working[1]) as usize,
                    "{label}"
                );
                let filtered_len = match settings.filter_resolution {
                    FilterResolution::Full => out.ao.len(),
                    FilterResolution::Working => out.raw_ao.len(),
                };
                assert_eq!(
                    out.history_rejected.map(|r| r.len()),
                    Some(filtered_len),
                    "{label}"
                );
                let depth = &inputs.frame.linear_depth;
                assert_eq!(out.ao.len(), depth.len(), "{label}");
                for (i, (&ao, &d)) in out.ao.iter().zip(depth).enumerate() {
                    if d == 0.0 {
                        assert_eq!(ao, 1.0, "{label}: sky pixel {i}");
                    } else {
                        assert!((0.0..=1.0).contains(&ao), "{label}: pixel {i} reads {ao}");
                    }
                }
                for (i, (b, &d)) in out.bent_normals.iter().flatten().zip(depth).enumerate() {
                    let length = Vec3::new(b[0], b[1], b[2]).length();
                    let unit = (length - 1.0).abs() < 0.01;
                    assert!(
                        if d == 0.0 {
                            b[3] == 1.0
                        } else {
                            unit && (0.0..=1.0).contains(&b[3])
                        },
                        "{label}: bent normal {b:?} at pixel {i}"
                    );
                }
            }
        }
    }
}

/// Pixels from each pixel of `current` to where its surface was in `previous`, for a still
/// scene and a moving camera: what a renderer's motion vectors hold.
fn camera_motion(previous: &Frame, current: &Frame) -> Vec<Vec2> {
    let size = Vec2::new(current.size[0] as f32, current.size[1] as f32);
    let to_previous = previous.view_from_world * current.view_from_world.inverse();
    let clip_from_view = previous.projection.clip_from_view();
    (0..current.size[0] * current.size[1])
        .map(|i| {
            let depth = current.linear_depth[i as usize];
            if depth == 0.0 {
                return Vec2::ZERO;
            }
            let pixel = Vec2::new((i % current.size[0]) as f32, (i / current.size[0]) as f32);
            let p = current
                .projection
                .view_position_from_linear(pixel_to_ndc(pixel, size), depth);
            let clip = clip_from_view * to_previous.transform_point3(p).extend(1.0);
            let ndc = Vec2::new(clip.x, clip.y) / clip.w;
            Vec2::new(ndc.x + 1.0, 1.0 - ndc.y) * 0.5 * size - (pixel + 0.5)
        })
        .collect()
}

#[test]
fn motion_vectors_at_working_resolution_reproject_as_the_camera_does() {
    let gpu = gpu();
    let scene = Builtin::Stairs.build();
    let size = [160, 96];
    let frames = frames(&gpu, &scene, CameraPath::Strafe, 6, size);
    for resolution in [Resolution::Half, Resolution::Quarter] {
        let mut settings = AoSettings {
            radius: scene.suggested_radius.unwrap(),
            resolution,
            ..AoSettings::preset(Method::Gtao, Preset::High)
        };
        settings.temporal.enabled = true;
        // The same frames filtered with the camera's reprojection and with motion vectors.
        let mut by_camera = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let mut by_motion = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let mut outputs = Vec::new();
        for (i, frame) in frames.iter().enumerate() {
            let motion = camera_motion(&frames[i.saturating_sub(1)], frame);
            let camera = run(
                &gpu,
                &mut by_camera,
                &Inputs::new(&gpu, frame.clone(), None),
                i as u32,
            );
            let inputs = Inputs::new(&gpu, frame.clone(), Some(&motion));
            outputs.push((camera, run(&gpu, &mut by_motion, &inputs, i as u32)));
        }
        let (camera, motion) = outputs.last().unwrap();
        let rejected = |o: &Output| {
            let r = o.history_rejected.as_ref().unwrap();
            r.iter().sum::<f32>() / r.len() as f32
        };
        let mean_difference = mean_abs_difference(&camera.ao, &motion.ao);
        // Both reproject each working texel's surface to the same place, up to rounding; motion
        // vectors left in input pixels would land twice or four times too far and reject.
        assert!(
            (rejected(camera) - rejected(motion)).abs() < 0.01 && mean_difference < 1e-3,
            "{}: rejected {} by camera, {} by motion vectors; AO differs by {mean_difference}",
            resolution.name(),
            rejected(camera),
            rejected(motion)
        );
    }
}

/// RMSE between `a` and `b` over the pixels where `depth` shows a surface.
/// Surface pixels within 2 pixels of a depth step (a neighbour more than 10% nearer or
/// farther, or without a surface): where an upsample has to choose a side.
fn near_depth_edges(depth: &[f32], size: [u32; 2]) -> Vec<bool> {
    let [w, h] = size.map(|s| s as i32);
    let at = |x: i32, y: i32| depth[(x.clamp(0, w - 1) + y.clamp(0, h - 1) * w) as usize];
    let step = |x: i32, y: i32| {
        let d = at(x, y);
        [(1, 0), (0, 1)].iter().any(|(dx, dy)| {
            let n = at(x + dx, y + dy);
            (d > 0.0) != (n > 0.0) || (d - n).abs() > 0.1 * d.max(n)
        })
    };
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            depth[i as usize] > 0.0 && (-2..=2).any(|dy| (-2..=2).any(|dx| step(x + dx, y + dy)))
        })
        .collect()
}

/// The target: with both filters settled on a still camera, GTAO `high` at half
/// resolution stays within 10% of full resolution's RMSE against the reference, and within
/// 1.5x of its RMSE near depth edges.
#[test]
fn half_resolution_with_both_filters_stays_close_to_full_resolution() {
    let gpu = gpu();
    let size = [640, 360];
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin] {
        let scene = builtin.build();
        let camera: &Camera = &scene.cameras[0];
        let frame = frames(&gpu, &scene, CameraPath::Still, 1, size).remove(0);
        let inputs = Inputs::new(&gpu, frame, None);
        let traced = trace(&scene, camera, size, 256);
        let ao = |resolution, filtered: bool| {
            let mut settings = AoSettings {
                radius: scene.suggested_radius.unwrap(),
                resolution,
                ..AoSettings::preset(Method::Gtao, Preset::High)
            };
            settings.spatial.enabled = filtered;
            settings.temporal.enabled = filtered;
            let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
            let frames = if filtered { SETTLE_FRAMES } else { 1 };
            (0..frames)
                .map(|i| run(&gpu, &mut pipeline, &inputs, i).ao)
                .last()
                .unwrap()
        };
        let depth = &inputs.frame.linear_depth;
        let edges = near_depth_edges(depth, size);
        let surface = |i: usize| depth[i] > 0.0;
        let name = builtin.name();
        let (full, half) = (ao(Resolution::Full, false), ao(Resolution::Half, false));
        let apart = rmse(&full, &half, surface);
        assert!(
            apart < BOUND_TO_FULL,
            "{name}: half differs from full by {apart}"
        );
        let (full, half) = (ao(Resolution::Full, true), ao(Resolution::Half, true));
        let error = |ao: &[f32], keep: &dyn Fn(usize) -> bool| rmse(ao, &traced.ao, keep);
        let (full_error, half_error) = (error(&full, &surface), error(&half, &surface));
        let (full_edges, half_edges) = (error(&full, &|i| edges[i]), error(&half, &|i| edges[i]));
        eprintln!(
            "{name}: unfiltered half vs full {apart:.4}; filtered RMSE {full_error:.4} full, \
             {half_error:.4} half; near edges {full_edges:.4} full, {half_edges:.4} half"
        );
        assert!(
            half_error < 1.1 * full_error,
            "{name}: RMSE {half_error} at half, {full_error} at full"
        );
        assert!(
            half_edges < 1.5 * full_edges,
            "{name}: edge RMSE {half_edges} at half, {full_edges} at full"
        );
    }
}

/// Largest RMSE between half- and full-resolution AO without filters: mostly the two
/// resolutions' different noise (0.035 to 0.078 measured on these scenes at 320x180).
const BOUND_TO_FULL: f64 = 0.1;
/// Frames the temporal filter gets to settle: its blend of 0.8 averages about 5.
const SETTLE_FRAMES: u32 = 12;

/// Below full resolution with a normal buffer no linear depth pass runs: the downsample and
/// the upsample read the renderer's depth themselves, of every kind, and the upsample writes
/// the full-resolution linear depth. That depth must be what the pass writes at full
/// resolution, and the four kinds of one depth buffer must give the same AO.
#[test]
fn every_kind_of_depth_is_read_below_full_resolution_without_a_linear_depth_pass() {
    const SIZE: [u32; 2] = [96, 54];
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let scene = Builtin::Stairs.build();
    let settings = common::scene_settings(&scene, Method::Gtao, Preset::Low);
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    let (gbuffer, projection) = renderer
        .render_gbuffer(&gpu, &scene.cameras[0], SIZE, aokit::NormalEncoding::Oct32)
        .unwrap();
    let mut pipeline = AoPipeline::new(device, queue, &settings).unwrap();
    let timed = pipeline.enable_timing(device, queue);
    let mut frame = |depth: &wgpu::Texture, resolution| {
        pipeline
            .set_settings(
                device,
                queue,
                &AoSettings {
                    resolution,
                    ..settings
                },
            )
            .unwrap();
        let inputs = AoInputs {
            normals: Some((&gbuffer.normals).into()),
            ..AoInputs::new(depth, projection)
        };
        let (ao, linear_depth) = encode_frame(&gpu, &mut pipeline, &inputs, |o| {
            let read = |t| read_texture_f32(device, queue, t).unwrap();
            (read(o.ao), read(o.linear_depth))
        });
        let passes: Vec<&str> = pipeline
            .last_pass_times(device)
            .map(|times| times.unwrap().iter().map(|t| t.name).collect())
            .unwrap_or_default();
        (ao, linear_depth, passes)
    };
    let (_, linear_depth, passes) = frame(&gbuffer.depth, Resolution::Full);
    assert!(!timed || passes.contains(&"linear_depth"), "{passes:?}");
    assert!(linear_depth.iter().any(|&d| d > 0.0) && linear_depth.contains(&0.0));
    let linear = linear_depth_texture(&gpu, SIZE, &linear_depth);
    let copy = |source, format| {
        let copy = DepthCopy {
            format,
            samples: 4,
            stencil: None,
        };
        copy_depth(&gpu, source, &copy)
    };
    let depths = [
        ("Depth32Float", gbuffer.depth.clone()),
        (
            "Depth32Float 4x MSAA",
            copy(&gbuffer.depth, wgpu::TextureFormat::Depth32Float),
        ),
        ("R32Float linear", linear.clone()),
        (
            "R32Float linear 4x MSAA",
            copy(&linear, wgpu::TextureFormat::R32Float),
        ),
    ];
    for resolution in [Resolution::Half, Resolution::Quarter] {
        let mut first_ao = None;
        for (name, depth) in &depths {
            let (ao, written, passes) = frame(depth, resolution);
            let at = format!("{name} at {resolution:?}");
            assert!(written == linear_depth, "{at}: the linear depth differs");
            if timed {
                assert!(!passes.contains(&"linear_depth"), "{at}: {passes:?}");
                assert!(passes.contains(&"upsample"), "{at}: {passes:?}");
            }
            assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)), "{at}");
            match &first_ao {
                None => first_ao = Some(ao),
                Some(first) => assert!(&ao == first, "{at}: the AO differs from Depth32Float's"),
            }
        }
    }
}

#[test]
fn a_one_pixel_image_runs_below_full_resolution_as_at_full() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let frame = frames(&gpu, &scene, CameraPath::Orbit, 1, [1, 1]).remove(0);
    assert!(frame.linear_depth[0] > 0.0, "the pixel shows the room");
    let inputs = Inputs::new(&gpu, frame, None);
    let outputs = |settings: AoSettings| {
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let frame = AoInputs {
            normals: Some((&inputs.normals).into()),
            ..AoInputs::new(&inputs.depth, inputs.frame.projection)
        };
        encode_frame(&gpu, &mut pipeline, &frame, |outputs| {
            let read = |texture| read_texture_f32(&gpu.device, &gpu.queue, texture).unwrap();
            (
                read(outputs.ao),
                read(outputs.linear_depth),
                outputs.working_size,
            )
        })
    };
    let filtered = |settings: AoSettings| AoSettings {
        spatial: aokit::SpatialSettings {
            enabled: true,
            ..settings.spatial
        },
        temporal: aokit::TemporalSettings {
            enabled: true,
            ..settings.temporal
        },
        ..settings
    };
    let full = outputs(filtered(AoSettings::default()));
    // No coarser grid than one texel: every resolution is the image itself, where the frame
    // once skipped its linear depth (AO 1 and depth 0) or panicked with the filters after the
    // upsample.
    for settings in every_combination() {
        let name = format!("{:?} {:?}", settings.resolution, settings.filter_resolution);
        let (ao, depth, working) = outputs(filtered(settings));
        assert_eq!(working, [1, 1], "{name}");
        assert_eq!(depth, full.1, "{name}: linear depth");
        assert_eq!(ao, full.0, "{name}: AO");
    }
}
