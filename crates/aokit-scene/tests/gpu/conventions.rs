//! Every depth convention the pipeline accepts gives the AO of the same scene: perspective with
//! an infinite far plane in reverse-Z, standard Z with a finite far plane, orthographic; depth
//! as `Depth32Float`, `Depth24Plus`, `Depth16Unorm` or `R32Float` linear depth, single-sampled
//! or 4x multisampled (read at sample 0); normals in view or world space. Each is scored
//! against the reference traced through the same camera, with one tolerance, and against the
//! `Depth32Float` AO of its camera.

use crate::common;

use aokit::gpu::{read_texture, read_texture_f32, upload_texture_2d};
use aokit::normals::{encode_texels, unpack_oct32};
use aokit::{
    AoInputs, AoPipeline, AoSettings, Method, NormalEncoding, NormalSpace, NormalsSettings, Preset,
    SampleDepth,
};
use aokit_scene::{Builtin, Camera, Lens, Renderer};
use common::{DepthCopy, copy_depth, encode_frame, gpu, linear_depth_texture, rmse, trace};
use glam::Vec3;

const SIZE: [u32; 2] = [160, 96];
/// Largest RMSE against the reference, for every convention (GTAO `high` on `room`).
const TOLERANCE: f64 = 0.08;

/// Samples per pixel of the multisampled inputs.
const MSAA: u32 = 4;

#[test]
fn every_depth_convention_scores_alike_against_the_reference() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let base = scene.cameras[0].clone();
    let radius = scene.suggested_radius.unwrap();
    // The interpolated read, so that the formats' rounding is all that differs: the nearest
    // read takes each texel's rounding undamped (Depth24Plus 0.0014 from Depth32Float).
    let settings = AoSettings {
        radius,
        sample_depth: SampleDepth::Interpolated,
        ..AoSettings::preset(Method::Gtao, Preset::High)
    };
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    let cameras = [
        Camera {
            name: "reverse-z, infinite far".into(),
            ..base.clone()
        },
        // Standard-Z float depth loses precision as (depth / near): a renderer using it picks
        // a near plane well away from the eye.
        Camera {
            name: "standard-z, far 60".into(),
            reverse_z: false,
            near: Some(0.5),
            far: Some(60.0),
            ..base.clone()
        },
        // From the front, an orthographic lens sees the side walls edge-on: no screen-space
        // method can see them occlude the corners (every method's RMSE triples). From above
        // and to the side, every surface shows.
        Camera {
            name: "orthographic".into(),
            eye: Vec3::new(4.0, 4.0, 7.0),
            target: Vec3::new(0.0, 0.8, 0.0),
            lens: Lens::Orthographic { height: 8.0 },
            ..base.clone()
        },
    ];
    for camera in &cameras {
        let (gbuffer, projection) = renderer
            .render_gbuffer(&gpu, camera, SIZE, NormalEncoding::Oct32)
            .unwrap();
        let traced = trace(&scene, camera, SIZE, 128);
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let mut ao_of = |depth: &wgpu::Texture| {
            let inputs = AoInputs {
                normals: Some((&gbuffer.normals).into()),
                ..AoInputs::new(depth, projection)
            };
            encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
                let read = |t| read_texture_f32(&gpu.device, &gpu.queue, t).unwrap();
                (read(outputs.ao), read(outputs.linear_depth))
            })
        };
        let (baseline, linear_depth) = ao_of(&gbuffer.depth);
        let covered: Vec<bool> = linear_depth.iter().map(|&d| d > 0.0).collect();
        let linear = linear_depth_texture(&gpu, SIZE, &linear_depth);
        let copy = |format, samples| {
            copy_depth(
                &gpu,
                &gbuffer.depth,
                &DepthCopy {
                    format,
                    samples,
                    stencil: None,
                },
            )
        };
        use wgpu::TextureFormat::{Depth16Unorm, Depth24Plus, Depth32Float};
        let inputs = [
            ("Depth32Float", gbuffer.depth.clone()),
            ("Depth24Plus", copy(Depth24Plus, 1)),
            ("Depth16Unorm", copy(Depth16Unorm, 1)),
            ("Depth32Float 4x MSAA", copy(Depth32Float, MSAA)),
            ("Depth24Plus 4x MSAA", copy(Depth24Plus, MSAA)),
            (
                "R32Float 4x MSAA linear depth",
                copy_depth(
                    &gpu,
                    &linear,
                    &DepthCopy {
                        format: wgpu::TextureFormat::R32Float,
                        samples: MSAA,
                        stencil: None,
                    },
                ),
            ),
            ("R32Float linear depth", linear),
        ];
        for (format, depth) in &inputs {
            let (ao, _) = ao_of(depth);
            let (error, apart) = (
                rmse(&ao, &traced.ao, |i| covered[i]),
                rmse(&ao, &baseline, |i| covered[i]),
            );
            eprintln!(
                "{} / {format}: RMSE {error:.4} against the reference, {apart:.5} against Depth32Float",
                camera.name
            );
            assert!(
                ao.iter().all(|a| (0.0..=1.0).contains(a)),
                "{} / {format}",
                camera.name
            );
            assert!(
                error < TOLERANCE,
                "{} / {format}: RMSE {error}",
                camera.name
            );
            // 16 bits hold reverse-Z depth coarsely: 0.026 measured, within the tolerance.
            let bound = if *format == "Depth16Unorm" {
                0.05
            } else {
                1e-3
            };
            assert!(
                apart < bound,
                "{} / {format}: {apart} from Depth32Float",
                camera.name
            );
        }

        // The same normals in world space, as oct32 and as half floats, turned back into view
        // space by the pipeline with the camera's rotation.
        let view_from_world = camera.view_from_world();
        let view_normals: Vec<u32> = bytemuck::pod_collect_to_vec(
            &read_texture(&gpu.device, &gpu.queue, &gbuffer.normals).unwrap(),
        );
        let world_normals: Vec<Vec3> = view_normals
            .iter()
            .map(|&bits| {
                view_from_world
                    .inverse()
                    .transform_vector3(unpack_oct32(bits))
            })
            .collect();
        for encoding in [NormalEncoding::Oct32, NormalEncoding::Rgba16f] {
            let texture = upload_texture_2d(
                &gpu.device,
                &gpu.queue,
                "world normals",
                SIZE,
                encoding.texture_format(),
                &encode_texels(encoding, &world_normals),
            )
            .unwrap();
            let world_settings = AoSettings {
                normals: NormalsSettings {
                    encoding,
                    space: NormalSpace::World,
                    ..settings.normals
                },
                ..settings
            };
            let inputs = AoInputs {
                normals: Some((&texture).into()),
                view_from_world,
                ..AoInputs::new(&gbuffer.depth, projection)
            };
            let ao_with = |settings: &AoSettings| {
                let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, settings).unwrap();
                encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
                    read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap()
                })
            };
            let what = format!("{} / world-space {}", camera.name, encoding.name());
            let ao = ao_with(&world_settings);
            // Read as view space, the same normals give other AO wherever the camera turns
            // away from the world's axes: the rotation is what makes them agree.
            let (axis, angle) = glam::Quat::from_mat4(&view_from_world).to_axis_angle();
            if angle.abs() > 0.3 {
                let as_view = AoSettings {
                    normals: NormalsSettings {
                        space: NormalSpace::View,
                        ..world_settings.normals
                    },
                    ..world_settings
                };
                let wrong = rmse(&ao_with(&as_view), &baseline, |i| covered[i]);
                eprintln!("{what}: {wrong:.4} from view-space oct32 when read as view space");
                assert!(
                    wrong > 0.01,
                    "{} turned {angle} about {axis}: {wrong}",
                    camera.name
                );
            }
            let (error, apart) = (
                rmse(&ao, &traced.ao, |i| covered[i]),
                rmse(&ao, &baseline, |i| covered[i]),
            );
            eprintln!(
                "{what}: RMSE {error:.4} against the reference, {apart:.5} against view-space oct32"
            );
            assert!(error < TOLERANCE, "{what}: RMSE {error}");
            assert!(apart < 2e-3, "{what}: {apart} from view-space oct32");
        }
    }
}

/// Linear depth of a room corner (floor at y = -1, back wall at z = -6, side wall at x = 2) at
/// each pixel of `size` through `projection` from the origin.
fn corner_depth(projection: &aokit::Projection, size: [u32; 2]) -> Vec<f32> {
    let dims = glam::Vec2::new(size[0] as f32, size[1] as f32);
    (0..size[1])
        .flat_map(|y| (0..size[0]).map(move |x| glam::Vec2::new(x as f32, y as f32)))
        .map(|pixel| {
            let ndc = aokit::projection::pixel_to_ndc(pixel, dims);
            // The view ray at depth 1: its depth along -Z is the distance t below.
            let ray = projection.view_position_from_linear(ndc, 1.0);
            let mut depth = 6.0_f32;
            if ray.y < 0.0 {
                depth = depth.min(-1.0 / ray.y);
            }
            if ray.x > 0.0 {
                depth = depth.min(2.0 / ray.x);
            }
            depth
        })
        .collect()
}

#[test]
fn an_off_centre_view_sees_the_ao_of_the_centred_view_it_is_cut_from() {
    // The right half of a 2:1 view, drawn on its own as a 1:1 image whose left edge is the
    // full view's axis: a headset's eye, or a tile. Its AO must be the full view's there,
    // away from the cut, where the full view sees samples the half cannot. Measured: a mean
    // difference of 0.0014 over 13289 pixels, and 0.1272 with the half read as centred.
    let gpu = gpu();
    let fov = 90f32.to_radians();
    let full = aokit::Projection::perspective(fov, 2.0, 0.1, None);
    let half = aokit::Projection::perspective(fov, 1.0, 0.1, None)
        .with_ndc_offset(glam::Vec2::new(-1.0, 0.0));
    let [width, height] = [256, 128];
    // Converged GTAO, so that the pixels' different noise does not matter.
    let mut settings = AoSettings::preset(Method::Gtao, Preset::High);
    settings.gtao.slice_count = 32;
    settings.gtao.steps_per_side = 16;
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
    let mut ao = |projection: aokit::Projection, size: [u32; 2]| {
        let depth = linear_depth_texture(&gpu, size, &corner_depth(&projection, size));
        let inputs = AoInputs::new(&depth, projection);
        encode_frame(&gpu, &mut pipeline, &inputs, |o| {
            read_texture_f32(&gpu.device, &gpu.queue, o.ao).unwrap()
        })
    };
    let whole = ao(full, [width, height]);
    let cut = ao(half, [width / 2, height]);
    let centred = ao(half.with_ndc_offset(glam::Vec2::ZERO), [width / 2, height]);
    let depth = corner_depth(&half, [width / 2, height]);
    // Pixels whose radius (64 pixels at depth 1) stays clear of the cut.
    let mut compared = 0;
    let (mut error, mut ignored) = (0.0, 0.0);
    for y in 0..height {
        for x in 0..width / 2 {
            let i = (y * width / 2 + x) as usize;
            if (x as f32) < 64.0 / depth[i] + 2.0 {
                continue;
            }
            let reference = whole[(y * width + width / 2 + x) as usize];
            error += f64::from((cut[i] - reference).abs());
            ignored += f64::from((centred[i] - reference).abs());
            compared += 1;
        }
    }
    let (error, ignored) = (error / compared as f64, ignored / compared as f64);
    eprintln!(
        "{compared} pixels: mean |AO difference| {error:.4} with the offset, {ignored:.4} \
         read as centred"
    );
    assert!(compared > 4000, "{compared} pixels compared");
    assert!(error < 0.01, "with the offset: {error}");
    assert!(
        ignored > 5.0 * error,
        "without it: {ignored}, with it {error}"
    );
}

#[test]
fn a_jittered_history_is_reprojected_through_its_own_offset() {
    // A still camera whose projection moves by a few pixels between two frames, as a large
    // TAA jitter would: the second frame's history must be the first frame's AO at the same
    // surface points, so that blending it in changes little. Measured: a mean difference from
    // the second frame alone of 0.0017, and 0.0074 when the first frame's jitter is withheld.
    let gpu = gpu();
    let size = [128, 64];
    let base = aokit::Projection::perspective(90f32.to_radians(), 2.0, 0.1, None);
    let [first, second] = [glam::Vec2::new(2.0, 1.0), glam::Vec2::new(-2.0, -1.0)]
        .map(|pixels| base.with_jitter(pixels, size));
    let mut settings = AoSettings::preset(Method::Gtao, Preset::High);
    settings.gtao.slice_count = 32;
    settings.gtao.steps_per_side = 16;
    // With the nearest read the AO at a surface point moves with the texel grid, by 0.0076
    // between these frames, enough to hide a misplaced history.
    settings.sample_depth = SampleDepth::Interpolated;
    let single = {
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let depth = linear_depth_texture(&gpu, size, &corner_depth(&second, size));
        encode_frame(&gpu, &mut pipeline, &AoInputs::new(&depth, second), |o| {
            read_texture_f32(&gpu.device, &gpu.queue, o.ao).unwrap()
        })
    };
    // Mostly history, and no clipping to the current neighbourhood to hide a misplaced one.
    settings.temporal.enabled = true;
    settings.temporal.blend = 0.9;
    settings.temporal.variance_gamma = 100.0;
    // The second frame blended with the first, told it was drawn through `told`.
    let blended = |told: aokit::Projection| {
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
        let mut ao = Vec::new();
        for (frame, (drawn, declared)) in [(first, told), (second, second)].into_iter().enumerate()
        {
            let depth = linear_depth_texture(&gpu, size, &corner_depth(&drawn, size));
            let inputs = AoInputs {
                frame_index: frame as u32,
                ..AoInputs::new(&depth, declared)
            };
            ao = encode_frame(&gpu, &mut pipeline, &inputs, |o| {
                read_texture_f32(&gpu.device, &gpu.queue, o.ao).unwrap()
            });
        }
        // Away from the borders, where history falls off screen.
        let mut total = 0.0;
        let mut count = 0;
        for y in 8..size[1] - 8 {
            for x in 8..size[0] - 8 {
                let i = (y * size[0] + x) as usize;
                total += f64::from((ao[i] - single[i]).abs());
                count += 1;
            }
        }
        total / f64::from(count)
    };
    let with_offset = blended(first);
    let without = blended(base);
    eprintln!("mean |history - frame| {with_offset:.4} with its offset, {without:.4} without");
    assert!(with_offset < 0.004, "{with_offset}");
    assert!(
        without > 3.0 * with_offset,
        "without {without}, with {with_offset}"
    );
}
