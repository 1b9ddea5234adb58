//! Every depth convention the pipeline accepts gives the AO of the same scene: perspective with
//! an infinite far plane in reverse-Z, standard Z with a finite far plane, orthographic; depth
//! as `Depth32Float`, `Depth24Plus`, `Depth16Unorm` or `R32Float` linear depth. Each is scored
//! against the reference traced through the same camera, with one tolerance, and against the
//! `Depth32Float` AO of its camera.

mod common;

use aokit::gpu::read_texture_f32;
use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, NormalEncoding, Preset};
use aokit_reference::AoOptions;
use aokit_scene::{Builtin, Camera, Lens, Renderer, reference};
use common::{encode_frame, gpu, linear_depth_texture, rmse};
use glam::Vec3;

const SIZE: [u32; 2] = [160, 96];
/// Largest RMSE against the reference, for every convention (GTAO `high` on `room`).
const TOLERANCE: f64 = 0.08;

/// A fullscreen pass that writes the depth of a `Depth32Float` texture into a depth
/// attachment of another format, as a renderer using that format would have drawn it.
const COPY_DEPTH: &str = r#"
@group(0) @binding(0) var source: texture_depth_2d;

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn fs(@builtin(position) position: vec4<f32>) -> @builtin(frag_depth) f32 {
    return textureLoad(source, vec2<i32>(position.xy), 0);
}
"#;

fn copy_depth(
    gpu: &GpuContext,
    source: &wgpu::Texture,
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    let device = &gpu.device;
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("depth copy"),
        size: source.size(),
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("copy depth"),
        source: wgpu::ShaderSource::Wgsl(COPY_DEPTH.into()),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("copy depth"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        multiview_mask: None,
        cache: None,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&source.create_view(&Default::default())),
        }],
    });
    let view = target.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("copy depth"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
    gpu.queue.submit([encoder.finish()]);
    target
}

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
    let tracer = reference::tracer(&scene).unwrap();
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
        let traced = tracer
            .render(
                &reference::pixel_camera(&scene, camera, SIZE),
                &AoOptions {
                    radius,
                    spp: 128,
                    ..Default::default()
                },
                &|_| {},
            )
            .unwrap();
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
        let inputs = [
            ("Depth32Float", gbuffer.depth.clone()),
            (
                "Depth24Plus",
                copy_depth(&gpu, &gbuffer.depth, wgpu::TextureFormat::Depth24Plus),
            ),
            (
                "Depth16Unorm",
                copy_depth(&gpu, &gbuffer.depth, wgpu::TextureFormat::Depth16Unorm),
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
    }
}
