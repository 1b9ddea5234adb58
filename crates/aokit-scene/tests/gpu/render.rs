//! GPU tests on whatever adapter exists (lavapipe in CI), at small sizes.

use crate::common;

use aokit::{AoSettings, GpuContext, Preset, Projection};
use aokit_scene::external::{self, ExternalAo, Passes};
use aokit_scene::{Builtin, Camera, Frame, Lens, Renderer, Scene};
use common::{gpu, mean_abs_difference};
use glam::{Vec2, Vec3};

const SIZE: [u32; 2] = [192, 128];

fn settings_for(scene: &Scene) -> AoSettings {
    AoSettings {
        radius: scene.suggested_radius.unwrap(),
        ..AoSettings::preset(aokit::Method::Gtao, Preset::High)
    }
}

fn render(gpu: &GpuContext, scene: &Scene, camera: &Camera) -> Frame {
    let mut renderer = Renderer::new(gpu, scene, &settings_for(scene)).unwrap();
    renderer.render(gpu, camera, SIZE, 0).unwrap()
}

/// Pixel index of a world point, checking that the point is the visible surface there.
fn visible_pixel(frame: &Frame, world: Vec3) -> usize {
    let view = frame.view_from_world.transform_point3(world);
    let clip = frame.projection.clip_from_view() * view.extend(1.0);
    let ndc = Vec2::new(clip.x, clip.y) / clip.w;
    let size = Vec2::new(frame.size[0] as f32, frame.size[1] as f32);
    let pixel = Vec2::new((ndc.x + 1.0) * 0.5, (1.0 - ndc.y) * 0.5) * size;
    assert!(
        pixel.cmpge(Vec2::ZERO).all() && pixel.cmplt(size).all(),
        "{world} is off screen"
    );
    let index = pixel.y as usize * frame.size[0] as usize + pixel.x as usize;
    let depth = frame.linear_depth[index];
    assert!(
        (depth + view.z).abs() < 0.02 * depth,
        "{world} is hidden (depth {depth}, point {})",
        -view.z
    );
    index
}

#[test]
fn open_plane_is_unoccluded_everywhere() {
    let gpu = gpu();
    let scene = Builtin::Open.build();
    // Two sizes: sample positions, and with them the rounding cases, differ between them.
    for size in [SIZE, [640, 360]] {
        for camera in &scene.cameras {
            let mut renderer = Renderer::new(&gpu, &scene, &settings_for(&scene)).unwrap();
            let frame = renderer.render(&gpu, camera, size, 0).unwrap();
            let covered: Vec<f32> = frame
                .ao
                .iter()
                .zip(&frame.linear_depth)
                .filter(|&(_, &d)| d > 0.0)
                .map(|(&ao, _)| ao)
                .collect();
            assert!(
                covered.len() > frame.ao.len() / 3,
                "the plane should fill much of the view"
            );
            let worst = covered.iter().copied().fold(1.0f32, f32::min);
            assert!(
                worst >= 0.98,
                "camera {} at {size:?}: lowest AO on an open plane is {worst}",
                camera.name
            );
        }
    }
}

#[test]
fn room_corners_are_darker_than_open_floor() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let frame = render(&gpu, &scene, &scene.cameras[0]);
    let open_floor = frame.ao[visible_pixel(&frame, Vec3::new(-0.3, 0.0, 2.5))];
    let corner = frame.ao[visible_pixel(&frame, Vec3::new(3.96, 0.04, -3.96))];
    let wall_foot = frame.ao[visible_pixel(&frame, Vec3::new(0.0, 0.03, -3.97))];
    let under_sphere = frame.ao[visible_pixel(&frame, Vec3::new(-1.5, 0.0, -0.75))];
    assert!(open_floor > 0.95, "open floor AO {open_floor}");
    for (name, ao) in [
        ("corner", corner),
        ("wall foot", wall_foot),
        ("sphere contact", under_sphere),
    ] {
        assert!(
            ao < open_floor - 0.2,
            "{name} AO {ao} vs open floor {open_floor}"
        );
    }
    assert!(
        corner < wall_foot,
        "a three-plane corner ({corner}) must be darker than an edge ({wall_foot})"
    );
}

#[test]
fn every_builtin_gives_finite_ao_in_range_and_a_lit_image() {
    let gpu = gpu();
    for builtin in Builtin::ALL {
        let scene = builtin.build();
        let frame = render(&gpu, &scene, &scene.cameras[0]);
        assert!(
            frame.ao.iter().all(|a| (0.0..=1.0).contains(a)),
            "{}",
            scene.name
        );
        assert_eq!(frame.lit.len(), (SIZE[0] * SIZE[1] * 4) as usize);
        let covered = frame.linear_depth.iter().filter(|&&d| d > 0.0).count();
        assert!(covered > 0, "{} drew nothing", scene.name);
        let sky = frame.linear_depth.iter().position(|&d| d == 0.0);
        if let Some(i) = sky {
            assert_eq!(frame.ao[i], 1.0, "sky pixels are unoccluded");
        }
    }
}

/// Depth along each pixel's ray to the plane y = 0, computed on the CPU.
fn plane_depths(frame: &Frame) -> Vec<Option<f32>> {
    let world_from_view = frame.view_from_world.inverse();
    let size = Vec2::new(frame.size[0] as f32, frame.size[1] as f32);
    (0..frame.size[1])
        .flat_map(|y| (0..frame.size[0]).map(move |x| Vec2::new(x as f32, y as f32)))
        .map(|pixel| {
            let ndc = aokit::projection::pixel_to_ndc(pixel, size);
            let near = frame.projection.view_position_from_linear(ndc, 1.0);
            let far = frame.projection.view_position_from_linear(ndc, 2.0);
            let (a, b) = (
                world_from_view.transform_point3(near),
                world_from_view.transform_point3(far),
            );
            // Linear depth grows linearly along the ray from a (depth 1) to b (depth 2).
            let t = a.y / (a.y - b.y);
            let hit = a + t * (b - a);
            (t > -1.0 && hit.x.abs() < 19.9 && hit.z.abs() < 19.9).then_some(1.0 + t)
        })
        .collect()
}

#[test]
fn linear_depth_matches_ray_casts_for_every_depth_convention() {
    let gpu = gpu();
    let scene = Builtin::Open.build();
    let base = scene.cameras[0].clone();
    let variants = [
        ("reverse-z infinite", Camera { ..base.clone() }),
        (
            "standard-z finite",
            Camera {
                far: Some(100.0),
                reverse_z: false,
                ..base.clone()
            },
        ),
        (
            "reverse-z finite",
            Camera {
                far: Some(100.0),
                ..base.clone()
            },
        ),
        (
            "standard-z infinite",
            Camera {
                reverse_z: false,
                near: Some(0.5),
                ..base.clone()
            },
        ),
        (
            "orthographic",
            Camera {
                lens: Lens::Orthographic { height: 12.0 },
                ..base.clone()
            },
        ),
        (
            "orthographic standard-z",
            Camera {
                lens: Lens::Orthographic { height: 12.0 },
                reverse_z: false,
                ..base.clone()
            },
        ),
    ];
    for (name, camera) in variants {
        let frame = render(&gpu, &scene, &camera);
        let expected = plane_depths(&frame);
        let mut checked = 0;
        for (i, want) in expected.iter().enumerate() {
            let got = frame.linear_depth[i];
            match want {
                Some(want) => {
                    assert!(
                        (got - want).abs() <= 1e-3 * want,
                        "{name}: pixel {i} depth {got}, ray {want}"
                    );
                    checked += 1;
                }
                None => assert!(
                    got == 0.0 || got > 30.0,
                    "{name}: pixel {i} should be sky, got {got}"
                ),
            }
        }
        assert!(checked > 1000, "{name}: only {checked} pixels on the plane");
        let worst = frame.ao.iter().copied().fold(1.0f32, f32::min);
        assert!(
            worst >= 0.98,
            "{name}: lowest AO on the open plane is {worst}"
        );
    }
}

#[test]
fn ao_does_not_depend_on_the_depth_convention() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let base = scene.cameras[0].clone();
    let reference = render(&gpu, &scene, &base);
    let standard = render(
        &gpu,
        &scene,
        &Camera {
            far: Some(50.0),
            reverse_z: false,
            near: Some(0.1),
            ..base
        },
    );
    let mean_diff = mean_abs_difference(&reference.ao, &standard.ao);
    assert!(
        mean_diff < 0.01,
        "mean AO difference between depth conventions {mean_diff}"
    );
}

#[test]
fn bad_sizes_and_cameras_are_refused_with_a_reason() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let mut renderer = Renderer::new(&gpu, &scene, &settings_for(&scene)).unwrap();
    let camera = scene.cameras[0].clone();
    let err = renderer
        .render(&gpu, &camera, [0, 10], 0)
        .unwrap_err()
        .to_string();
    assert!(err.contains("0x10"), "{err}");
    let err = renderer
        .render(&gpu, &camera, [100_000, 10], 0)
        .unwrap_err()
        .to_string();
    assert!(err.contains("100000x10"), "{err}");
    let flat = Camera {
        target: camera.eye,
        ..camera
    };
    assert!(
        renderer
            .render(&gpu, &flat, SIZE, 0)
            .unwrap_err()
            .to_string()
            .contains("same point")
    );
}

#[test]
fn passes_from_the_cpu_give_the_same_ao_as_the_raster() {
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Thin] {
        let scene = builtin.build();
        let frame = render(&gpu, &scene, &scene.cameras[0]);
        let passes = Passes {
            size: frame.size,
            linear_depth: &frame.linear_depth,
            normals: Some(&frame.normals),
            back_depth: None,
            projection: frame.projection,
        };
        let ao = external::ambient_occlusion(&gpu, &settings_for(&scene), &passes, 0).unwrap();
        let worst = ao
            .iter()
            .zip(&frame.ao)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f32, f32::max);
        assert!(
            worst < 1e-5,
            "{}: AO from uploaded passes differs by up to {worst}",
            scene.name
        );
    }
}

/// Frames submitted before the one before them is read back ([`ExternalAo::submit`], as
/// Python's `ao_batch` runs them) give each frame the AO and bent normals that running it alone
/// gives: each run's outputs are copied before the next run writes them.
#[test]
fn frames_submitted_ahead_read_back_what_each_run_gives() {
    let gpu = gpu();
    let frames: Vec<Frame> = [(Builtin::Room, SIZE), (Builtin::Thin, [96, 64])]
        .into_iter()
        .map(|(builtin, size)| {
            let scene = builtin.build();
            let mut renderer = Renderer::new(&gpu, &scene, &settings_for(&scene)).unwrap();
            renderer.render(&gpu, &scene.cameras[0], size, 0).unwrap()
        })
        .collect();
    let passes: Vec<Passes<'_>> = frames
        .iter()
        .map(|frame| Passes {
            size: frame.size,
            linear_depth: &frame.linear_depth,
            normals: Some(&frame.normals),
            back_depth: None,
            projection: frame.projection,
        })
        .collect();
    let settings = AoSettings {
        bent_normals: true,
        ..settings_for(&Builtin::Room.build())
    };
    let alone: Vec<_> = passes
        .iter()
        .enumerate()
        .map(|(index, passes)| {
            ExternalAo::new(&gpu, &settings, passes)
                .unwrap()
                .run_with_bent_normals(&gpu, index as u32)
                .unwrap()
        })
        .collect();
    let mut external = ExternalAo::new(&gpu, &settings, &passes[0]).unwrap();
    let first = external.submit(&gpu, 0, true).unwrap();
    external.set_passes(&gpu, &passes[1]).unwrap();
    let second = external.submit(&gpu, 1, true).unwrap();
    let ahead = [first.wait(&gpu).unwrap(), second.wait(&gpu).unwrap()];
    for (index, ((ao, bent), (ao_alone, bent_alone))) in ahead.iter().zip(&alone).enumerate() {
        assert_eq!(ao.len(), frames[index].linear_depth.len(), "frame {index}");
        assert!(
            ao == ao_alone,
            "frame {index}: the AO differs from its run alone"
        );
        assert!(bent.is_some(), "frame {index}: no bent normals");
        assert!(bent == bent_alone, "frame {index}: the bent normals differ");
    }
    // The frames differ, so a read-back of the wrong run could not pass.
    assert!(ahead[0].0[..ahead[1].0.len()] != ahead[1].0[..]);
}

/// Reconstructs normals from the frame's depth and reads them back.
fn reconstructed_normals(gpu: &GpuContext, frame: &Frame) -> Vec<Vec3> {
    let (device, queue) = (&gpu.device, &gpu.queue);
    let depth = aokit::gpu::upload_texture_2d(
        device,
        queue,
        "depth",
        frame.size,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(&frame.linear_depth),
    )
    .unwrap();
    let mut pipeline = aokit::AoPipeline::new(device, queue, &AoSettings::default()).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(
            device,
            queue,
            &mut encoder,
            &aokit::AoInputs::new(&depth, frame.projection),
        )
        .unwrap();
    queue.submit([encoder.finish()]);
    let bytes = aokit::gpu::read_texture(device, queue, outputs.normals).unwrap();
    bytemuck::pod_collect_to_vec::<u8, u32>(&bytes)
        .into_iter()
        .map(aokit::normals::unpack_oct32)
        .collect()
}

#[test]
fn normals_reconstructed_from_depth_match_the_gbuffer() {
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Open] {
        let scene = builtin.build();
        let frame = render(&gpu, &scene, &scene.cameras[0]);
        let reconstructed = reconstructed_normals(&gpu, &frame);
        let errors: Vec<f32> = frame
            .normals
            .iter()
            .zip(&reconstructed)
            .zip(&frame.linear_depth)
            .filter(|&(_, &d)| d > 0.0)
            .map(|((a, b), _)| a.angle_between(*b).to_degrees())
            .collect();
        let within_a_degree =
            errors.iter().filter(|&&e| e < 1.0).count() as f32 / errors.len() as f32;
        // Curved surfaces (the room's sphere) and one-pixel-wide features miss by more.
        assert!(
            within_a_degree > 0.9,
            "{}: only {within_a_degree} of normals within 1 degree",
            scene.name
        );
    }
}

/// The room's sphere (radius 1 about (-1.5, 1, -1.2)) has outward G-buffer normals at every pixel
/// that shows it, silhouettes included: a normal turned into a surface reads as a fully occluded
/// pixel. At 480x270 a back face of the sphere wins the depth test on its silhouette, where the
/// facing once taken from screen derivatives turned its normal inwards.
#[test]
fn gbuffer_normals_point_out_of_the_sphere_at_its_silhouette() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let size = [480, 270];
    let frame = common::render_frame(&gpu, &scene, &scene.cameras[0], &settings_for(&scene), size);
    let world_from_view = frame.view_from_world.inverse();
    let centre = Vec3::new(-1.5, 1.0, -1.2);
    let mut on_sphere = 0;
    for (i, (&depth, &normal)) in frame.linear_depth.iter().zip(&frame.normals).enumerate() {
        let pixel = Vec2::new((i % 480) as f32 + 0.5, (i / 480) as f32 + 0.5);
        let ndc = Vec2::new(pixel.x / 240.0 - 1.0, 1.0 - pixel.y / 135.0);
        let world = world_from_view
            .transform_point3(frame.projection.view_position_from_linear(ndc, depth));
        // The facets lie up to a few hundredths inside the sphere, which touches the floor.
        if depth > 0.0 && ((world - centre).length() - 1.0).abs() < 0.05 && world.y > 0.1 {
            on_sphere += 1;
            let outward = world_from_view
                .transform_vector3(normal)
                .dot(world - centre);
            assert!(
                outward > 0.0,
                "pixel {pixel}: normal {normal} points into the sphere"
            );
        }
    }
    assert!(on_sphere > 1000, "only {on_sphere} pixels show the sphere");
}

/// AoOutputs' promise to renderers that cache bind groups: the output texture stays the same
/// from frame to frame, and a new size, a setting that adds a texture or another temporal view
/// gives a new one, which the texture's identity tells.
#[test]
fn the_output_texture_changes_only_when_the_pipeline_makes_new_ones() {
    let gpu = gpu();
    let settings = AoSettings::preset(aokit::Method::Gtao, Preset::Low);
    let mut pipeline = aokit::AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
    let projection = Projection::perspective(1.0, 1.5, 0.1, None);
    let small = common::linear_depth_texture(&gpu, [24, 16], &[2.0; 24 * 16]);
    let large = common::linear_depth_texture(&gpu, [36, 24], &[2.0; 36 * 24]);
    let ao = |pipeline: &mut aokit::AoPipeline, inputs: &aokit::AoInputs<'_>| {
        common::encode_frame(&gpu, pipeline, inputs, |outputs| outputs.ao.clone())
    };
    let first = ao(&mut pipeline, &aokit::AoInputs::new(&small, projection));
    let again = ao(&mut pipeline, &aokit::AoInputs::new(&small, projection));
    assert_eq!(
        first, again,
        "the same inputs and settings reuse the output"
    );
    let resized = ao(&mut pipeline, &aokit::AoInputs::new(&large, projection));
    assert_ne!(resized, again, "a new size makes new textures");

    let temporal = AoSettings {
        temporal: aokit::TemporalSettings {
            enabled: true,
            ..settings.temporal
        },
        ..settings
    };
    pipeline
        .set_settings(&gpu.device, &gpu.queue, &temporal)
        .unwrap();
    let view = |view_id| aokit::AoInputs {
        view_id,
        ..aokit::AoInputs::new(&large, projection)
    };
    let view_0 = ao(&mut pipeline, &view(0));
    assert_ne!(view_0, resized, "the temporal filter writes its own output");
    assert_eq!(
        ao(&mut pipeline, &view(0)),
        view_0,
        "each view keeps its output"
    );
    let view_1 = ao(&mut pipeline, &view(1));
    assert_ne!(
        view_1, view_0,
        "another view has another history and output"
    );
    assert_eq!(ao(&mut pipeline, &view(0)), view_0);
}

#[test]
fn pass_times_are_reported_when_the_adapter_has_timestamps() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let frame = render(&gpu, &scene, &scene.cameras[0]);
    let (device, queue) = (&gpu.device, &gpu.queue);
    let depth = aokit::gpu::upload_texture_2d(
        device,
        queue,
        "depth",
        frame.size,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(&frame.linear_depth),
    )
    .unwrap();
    let mut pipeline = aokit::AoPipeline::new(device, queue, &AoSettings::default()).unwrap();
    let has_timestamps = device.features().contains(wgpu::Features::TIMESTAMP_QUERY);
    assert_eq!(pipeline.enable_timing(device, queue), has_timestamps);
    let mut encoder = device.create_command_encoder(&Default::default());
    pipeline
        .encode(
            device,
            queue,
            &mut encoder,
            &aokit::AoInputs::new(&depth, frame.projection),
        )
        .unwrap();
    queue.submit([encoder.finish()]);
    match pipeline.last_pass_times(device) {
        None => assert!(!has_timestamps),
        Some(times) => {
            let times = times.unwrap();
            let names: Vec<&str> = times.iter().map(|t| t.name).collect();
            assert_eq!(
                names,
                ["linear_depth", "normals_from_depth", "gtao", "edge_filter"]
            );
            assert!(times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0));
        }
    }
}

/// `render_pair_at`: the first frame is the renderer's own, the second what a renderer with the
/// second pipeline's settings renders of the same view, from the same G-buffer.
#[test]
fn a_pair_renders_each_pipeline_on_one_gbuffer() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    let gtao = settings_for(&scene);
    let hbao = common::scene_settings(&scene, aokit::Method::Hbao, Preset::Medium);
    let alone = |settings: &AoSettings| {
        let mut renderer = Renderer::new(&gpu, &scene, settings).unwrap();
        renderer.render(&gpu, camera, SIZE, 0).unwrap()
    };
    let mut renderer = Renderer::new(&gpu, &scene, &gtao).unwrap();
    let mut second = aokit::AoPipeline::new(&gpu.device, &gpu.queue, &hbao).unwrap();
    let (first, other) = renderer
        .render_pair_at(&gpu, camera, SIZE, 0, 0.0, &mut second)
        .unwrap();
    let (gtao_alone, hbao_alone) = (alone(&gtao), alone(&hbao));
    assert_eq!(first.ao, gtao_alone.ao);
    assert_eq!(first.lit, gtao_alone.lit);
    assert_eq!(other.ao, hbao_alone.ao);
    assert_eq!(other.lit, hbao_alone.lit);
    assert_eq!(other.linear_depth, first.linear_depth);
    assert!(mean_abs_difference(&first.ao, &other.ao) > 1e-3);
}
