//! Every depth convention the pipeline accepts gives the AO of the same scene: perspective with
//! an infinite far plane in reverse-Z, standard Z with a finite far plane, orthographic; depth
//! as `Depth32Float`, `Depth24Plus`, `Depth16Unorm` or `R32Float` linear depth, single-sampled
//! or 4x multisampled (read at sample 0); normals in view or world space. Each is scored
//! against the reference traced through the same camera, with one tolerance, and against the
//! `Depth32Float` AO of its camera.

mod common;

use aokit::gpu::{read_texture, read_texture_f32, upload_texture_2d};
use aokit::normals::{encode_texels, unpack_oct32};
use aokit::{
    AoInputs, AoPipeline, AoSettings, Method, NormalEncoding, NormalSpace, NormalsSettings, Preset,
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
    let settings = AoSettings {
        radius,
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
                normals: Some(&gbuffer.normals),
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
                normals: Some(&texture),
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
