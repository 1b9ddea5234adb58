//! Helpers the GPU tests share: each test module uses some of them.
#![allow(dead_code)]

use aokit::gpu::upload_texture_2d;
use aokit::{AoInputs, AoOutputs, AoPipeline, AoSettings, GpuContext, Method, Preset};
use aokit_scene::{Camera, Frame, Renderer, Scene};

pub fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

/// `method` at `preset`, with the scene's suggested radius (1 where it suggests none).
pub fn scene_settings(scene: &Scene, method: Method, preset: Preset) -> AoSettings {
    AoSettings {
        radius: scene.suggested_radius.unwrap_or(1.0),
        ..AoSettings::preset(method, preset)
    }
}

/// The first frame a fresh renderer with `settings` draws of `scene` from `camera`.
pub fn render_frame(
    gpu: &GpuContext,
    scene: &Scene,
    camera: &Camera,
    settings: &AoSettings,
    size: [u32; 2],
) -> Frame {
    Renderer::new(gpu, scene, settings)
        .unwrap()
        .render(gpu, camera, size, 0)
        .unwrap()
}

/// An `R8Unorm` texture of one byte per texel, as `AoMask::Texture` accepts.
pub fn r8_texture(gpu: &GpuContext, size: [u32; 2], texels: &[u8]) -> wgpu::Texture {
    upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "mask",
        size,
        wgpu::TextureFormat::R8Unorm,
        texels,
    )
    .unwrap()
}

/// Linear view depth as the `R32Float` texture `AoInputs::depth` accepts.
pub fn linear_depth_texture(gpu: &GpuContext, size: [u32; 2], depth: &[f32]) -> wgpu::Texture {
    upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "linear depth",
        size,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(depth),
    )
    .unwrap()
}

/// Records one frame of `pipeline` on `inputs`, submits it and returns what `read` takes from
/// the outputs (read back after the submit).
pub fn encode_frame<T>(
    gpu: &GpuContext,
    pipeline: &mut AoPipeline,
    inputs: &AoInputs<'_>,
    read: impl FnOnce(&AoOutputs<'_>) -> T,
) -> T {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(&gpu.device, &gpu.queue, &mut encoder, inputs)
        .unwrap();
    gpu.queue.submit([encoder.finish()]);
    read(&outputs)
}

/// Mean of `|a - b|` over every pixel.
pub fn mean_abs_difference(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f32>() / a.len() as f32
}

/// RMSE of `a` against `b` over the pixels `keep` selects.
pub fn rmse(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool) -> f64 {
    let errors: Vec<f64> = (0..a.len())
        .filter(|&i| keep(i))
        .map(|i| f64::from(a[i] - b[i]).powi(2))
        .collect();
    (errors.iter().sum::<f64>() / errors.len() as f64).sqrt()
}

/// Fullscreen passes that copy each pixel of a texture to every sample of a target, as a
/// renderer drawing into that target would have: `Depth32Float` into a depth attachment, or
/// `R32Float` linear depth into a colour attachment.
const COPY_DEPTH: &str = r#"
@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}
"#;
const TO_DEPTH: &str = r#"
@group(0) @binding(0) var source: texture_depth_2d;
@fragment
fn fs(@builtin(position) position: vec4<f32>) -> @builtin(frag_depth) f32 {
    return textureLoad(source, vec2<i32>(position.xy), 0);
}
"#;
const TO_COLOUR: &str = r#"
@group(0) @binding(0) var source: texture_2d<f32>;
@fragment
fn fs(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return textureLoad(source, vec2<i32>(position.xy), 0);
}
"#;

/// What [`copy_depth`] makes.
pub struct DepthCopy {
    /// A depth format (from a `Depth32Float` source), or `R32Float` (from an `R32Float` one).
    pub format: wgpu::TextureFormat,
    pub samples: u32,
    /// Stencil `reference` written inside `[x, y, width, height]`, 0 elsewhere (the format
    /// must have stencil).
    pub stencil: Option<(u32, [u32; 4])>,
}

/// `source` drawn into a new texture as `copy` says.
pub fn copy_depth(gpu: &GpuContext, source: &wgpu::Texture, copy: &DepthCopy) -> wgpu::Texture {
    let device = &gpu.device;
    let format = copy.format;
    let to_depth = format.has_depth_aspect();
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("depth copy"),
        size: source.size(),
        mip_level_count: 1,
        sample_count: copy.samples,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("copy depth"),
        source: wgpu::ShaderSource::Wgsl(
            format!(
                "{COPY_DEPTH}{}",
                if to_depth { TO_DEPTH } else { TO_COLOUR }
            )
            .into(),
        ),
    });
    // Explicit: a derived layout would take R32Float for filterable.
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: if to_depth {
                    wgpu::TextureSampleType::Depth
                } else {
                    wgpu::TextureSampleType::Float { filterable: false }
                },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        }],
    });
    let replace = wgpu::StencilFaceState {
        compare: wgpu::CompareFunction::Always,
        fail_op: wgpu::StencilOperation::Keep,
        depth_fail_op: wgpu::StencilOperation::Keep,
        pass_op: wgpu::StencilOperation::Replace,
    };
    let colour_targets = [Some(format.into())];
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("copy depth"),
        layout: Some(
            &device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            }),
        ),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: to_depth.then(|| wgpu::DepthStencilState {
            format,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: if copy.stencil.is_some() {
                wgpu::StencilState {
                    front: replace,
                    back: replace,
                    read_mask: 0xff,
                    write_mask: 0xff,
                }
            } else {
                Default::default()
            },
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState {
            count: copy.samples,
            ..Default::default()
        },
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: if to_depth { &[] } else { &colour_targets },
        }),
        multiview_mask: None,
        cache: None,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&source.create_view(&Default::default())),
        }],
    });
    let view = target.create_view(&Default::default());
    let colour_attachment = [Some(wgpu::RenderPassColorAttachment {
        view: &view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
            store: wgpu::StoreOp::Store,
        },
    })];
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("copy depth"),
            color_attachments: if to_depth { &[] } else { &colour_attachment },
            depth_stencil_attachment: to_depth.then(|| wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: copy.stencil.map(|_| wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0),
                    store: wgpu::StoreOp::Store,
                }),
            }),
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.draw(0..3, 0..1);
        if let Some((reference, [x, y, width, height])) = copy.stencil {
            pass.set_stencil_reference(reference);
            pass.set_scissor_rect(x, y, width, height);
            pass.draw(0..3, 0..1);
        }
    }
    gpu.queue.submit([encoder.finish()]);
    target
}

/// The ray-traced reference of `camera`'s view of `scene` at `time` (see
/// [`aokit_scene::Scene::mesh_at`]), at `size` with `spp` rays per pixel and the scene's
/// suggested radius.
pub fn trace_at(
    scene: &aokit_scene::Scene,
    time: f32,
    camera: &aokit_scene::Camera,
    size: [u32; 2],
    spp: u32,
) -> aokit_reference::ReferenceImage {
    let options = aokit_reference::AoOptions {
        radius: scene.suggested_radius.unwrap(),
        spp,
        ..Default::default()
    };
    aokit_scene::reference::tracer_at(scene, time)
        .unwrap()
        .render(
            &aokit_scene::reference::pixel_camera(scene, camera, size),
            &options,
            &|_| {},
        )
        .unwrap()
}

/// [`trace_at`] with the scene at rest.
pub fn trace(
    scene: &aokit_scene::Scene,
    camera: &aokit_scene::Camera,
    size: [u32; 2],
    spp: u32,
) -> aokit_reference::ReferenceImage {
    trace_at(scene, 0.0, camera, size, spp)
}

/// RMSE against a 128-ray reference of `scene`'s first camera at `size`, over the pixels that
/// show a surface: of the frame each of `settings` renders, and of AO 1 everywhere (a kernel
/// that finds no occlusion), which any method worth its samples must beat.
pub fn reference_errors(
    gpu: &GpuContext,
    scene: &Scene,
    settings: &[AoSettings],
    size: [u32; 2],
) -> (Vec<f64>, f64) {
    let camera = &scene.cameras[0];
    let traced = trace(scene, camera, size, 128);
    let surface = |i: usize| traced.linear_depth[i] > 0.0;
    let errors = settings
        .iter()
        .map(|s| {
            rmse(
                &render_frame(gpu, scene, camera, s, size).ao,
                &traced.ao,
                surface,
            )
        })
        .collect();
    let ones = vec![1.0; traced.ao.len()];
    (errors, rmse(&ones, &traced.ao, surface))
}

/// Pixel index where the world point `world` is the visible surface of `frame`.
pub fn pixel_of(frame: &aokit_scene::Frame, world: glam::Vec3) -> usize {
    use glam::Vec2;
    let view = frame.view_from_world.transform_point3(world);
    let clip = frame.projection.clip_from_view() * view.extend(1.0);
    let ndc = Vec2::new(clip.x, clip.y) / clip.w;
    let size = Vec2::new(frame.size[0] as f32, frame.size[1] as f32);
    let pixel = Vec2::new((ndc.x + 1.0) * 0.5, (1.0 - ndc.y) * 0.5) * size;
    let index = pixel.y as usize * frame.size[0] as usize + pixel.x as usize;
    assert!(
        (frame.linear_depth[index] + view.z).abs() < 0.02 * -view.z,
        "{world} is not the visible surface"
    );
    index
}

/// The AO of the pixels of `frame` that show a surface.
pub fn covered(frame: &aokit_scene::Frame) -> impl Iterator<Item = f32> + '_ {
    frame
        .ao
        .iter()
        .zip(&frame.linear_depth)
        .filter(|&(_, &d)| d > 0.0)
        .map(|(&ao, _)| ao)
}

/// Every AO value of `frame` is finite and in [0, 1], and 1 where there is no surface.
pub fn assert_in_range_with_sky_at_one(frame: &aokit_scene::Frame, view: &str) {
    for (ao, depth) in frame.ao.iter().zip(&frame.linear_depth) {
        assert!((0.0..=1.0).contains(ao), "{view}: AO {ao}");
        if *depth == 0.0 {
            assert_eq!(*ao, 1.0, "{view}: sky pixel AO {ao}");
        }
    }
}

/// Level `level` of `texture`, read back through a one-level copy.
pub fn read_level(gpu: &GpuContext, texture: &wgpu::Texture, level: u32) -> (Vec<f32>, [u32; 2]) {
    let size = texture
        .size()
        .mip_level_size(level, wgpu::TextureDimension::D2);
    let copy = aokit::gpu::create_texture_2d(
        &gpu.device,
        "level copy",
        [size.width, size.height],
        texture.format(),
        wgpu::TextureUsages::COPY_DST | wgpu::TextureUsages::COPY_SRC,
    );
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: level,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        copy.as_image_copy(),
        size,
    );
    gpu.queue.submit([encoder.finish()]);
    let texels = aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, &copy).unwrap();
    (texels, [size.width, size.height])
}

/// The level above `finer` (of `size`) as `depth_mips.wgsl` builds it: texel `(x, y)` is
/// `reduce((x, y), children)` of its 2x2 children of the finer level in the order (0, 0),
/// (1, 0), (0, 1), (1, 1), each clamped to the finer level's last texel.
pub fn reduce_level(
    finer: &[f32],
    size: [u32; 2],
    reduce: impl Fn([u32; 2], [f32; 4]) -> f32,
) -> (Vec<f32>, [u32; 2]) {
    let coarse = size.map(|side| (side / 2).max(1));
    let mut out = Vec::with_capacity((coarse[0] * coarse[1]) as usize);
    for y in 0..coarse[1] {
        for x in 0..coarse[0] {
            let children = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(dx, dy)| {
                let cx = (2 * x + dx).min(size[0] - 1);
                let cy = (2 * y + dy).min(size[1] - 1);
                finer[(cy * size[0] + cx) as usize]
            });
            out.push(reduce([x, y], children));
        }
    }
    (out, coarse)
}
