//! Inputs given as views (`AoTexture::view`): one layer of an array, one mip level of a chain.
//! The pipeline binds the view itself, so its AO equals the AO of plain textures holding the
//! same texels; a view described with the wrong size or format is refused.

use aokit::gpu::{read_texture, upload_texture_2d};
use aokit::{AoInputs, AoPipeline, AoSettings, AoTexture, GpuContext, InputError, Projection};
use glam::Vec3;

const SIZE: [u32; 2] = [64, 48];

fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

fn projection() -> Projection {
    Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None)
}

/// Linear view depth of a bumpy wall: creases and dents for the AO to find. `phase` makes
/// another wall, for the layers and levels the test does not read.
fn bumpy_depth(size: [u32; 2], phase: f32) -> Vec<f32> {
    (0..size[0] * size[1])
        .map(|i| {
            let (x, y) = ((i % size[0]) as f32, (i / size[0]) as f32);
            4.0 + 0.6 * (x * 0.31 + phase).sin() * (y * 0.23).cos() + 0.02 * x
        })
        .collect()
}

/// Oct32 normals tilting with `phase`, as bytes.
fn normals(size: [u32; 2], phase: f32) -> Vec<u8> {
    let directions: Vec<Vec3> = (0..size[0] * size[1])
        .map(|i| {
            let (x, y) = ((i % size[0]) as f32, (i / size[0]) as f32);
            Vec3::new((x * 0.2 + phase).sin() * 0.5, (y * 0.3).cos() * 0.4, 1.0).normalize()
        })
        .collect();
    aokit::normals::encode_texels(aokit::NormalEncoding::Oct32, &directions)
}

/// A texture of `layers` array layers and `mips` levels; `fill(layer, level)` gives each
/// subresource's texels.
fn texture(
    gpu: &GpuContext,
    format: wgpu::TextureFormat,
    layers: u32,
    mips: u32,
    fill: impl Fn(u32, u32) -> Vec<u8>,
) -> wgpu::Texture {
    let [width, height] = [SIZE[0] << (mips - 1), SIZE[1] << (mips - 1)];
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("array"),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: layers,
        },
        mip_level_count: mips,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for layer in 0..layers {
        for level in 0..mips {
            let size = [width >> level, height >> level];
            gpu.queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &texture,
                    mip_level: level,
                    origin: wgpu::Origin3d {
                        x: 0,
                        y: 0,
                        z: layer,
                    },
                    aspect: wgpu::TextureAspect::All,
                },
                &fill(layer, level),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(size[0] * 4),
                    rows_per_image: Some(size[1]),
                },
                wgpu::Extent3d {
                    width: size[0],
                    height: size[1],
                    depth_or_array_layers: 1,
                },
            );
        }
    }
    texture
}

/// The AO bytes of one frame.
fn ao(gpu: &GpuContext, inputs: &AoInputs<'_>) -> Vec<u8> {
    let (device, queue) = (&gpu.device, &gpu.queue);
    let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default()).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(device, queue, &mut encoder, inputs)
        .unwrap();
    queue.submit([encoder.finish()]);
    read_texture(device, queue, outputs.ao).unwrap()
}

#[test]
fn depth_from_an_array_layer_and_normals_from_a_mip_level_give_the_plain_textures_ao() {
    let gpu = gpu();
    let depth_bytes = |phase| bytemuck::cast_slice(&bumpy_depth(SIZE, phase)).to_vec();
    let plain_depth = upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "depth",
        SIZE,
        wgpu::TextureFormat::R32Float,
        &depth_bytes(0.0),
    )
    .unwrap();
    let plain_normals = upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "normals",
        SIZE,
        wgpu::TextureFormat::R32Uint,
        &normals(SIZE, 0.0),
    )
    .unwrap();
    let expected = ao(
        &gpu,
        &AoInputs {
            normals: Some((&plain_normals).into()),
            ..AoInputs::new(&plain_depth, projection())
        },
    );

    // Layer 1 holds the wall; layer 0 another one, which a view of the whole array would show.
    let r32 = wgpu::TextureFormat::R32Float;
    let array = texture(&gpu, r32, 2, 1, |layer, _| {
        depth_bytes(if layer == 1 { 0.0 } else { 2.0 })
    });
    let layer = array.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::D2),
        base_array_layer: 1,
        array_layer_count: Some(1),
        ..Default::default()
    });
    // Level 1 holds the normals; level 0, twice the size, others.
    let oct32 = wgpu::TextureFormat::R32Uint;
    let chain = texture(&gpu, oct32, 1, 2, |_, level| match level {
        1 => normals(SIZE, 0.0),
        _ => normals([SIZE[0] * 2, SIZE[1] * 2], 1.0),
    });
    let level = aokit::gpu::mip_view(&chain, 1);
    let from_views = ao(
        &gpu,
        &AoInputs {
            normals: Some(AoTexture::view(&level, SIZE, oct32)),
            ..AoInputs::new(AoTexture::view(&layer, SIZE, r32), projection())
        },
    );
    assert!(
        expected.iter().any(|&b| b != expected[0]),
        "the wall should have some occlusion to compare"
    );
    assert!(from_views == expected, "AO from the views differs");
}

#[test]
fn a_view_said_to_have_another_size_or_format_than_its_texture_can_is_refused() {
    let gpu = gpu();
    let r32 = wgpu::TextureFormat::R32Float;
    let array = texture(&gpu, r32, 2, 2, |_, level| {
        let size = [SIZE[0] << (1 - level), SIZE[1] << (1 - level)];
        bytemuck::cast_slice(&bumpy_depth(size, 0.0)).to_vec()
    });
    let view = array.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::D2),
        base_mip_level: 1,
        mip_level_count: Some(1),
        array_layer_count: Some(1),
        ..Default::default()
    });
    let encoding = aokit::NormalEncoding::Oct32;
    let validate = |texture| AoInputs::new(texture, projection()).validate(encoding);
    // Both levels are sizes the view may have.
    assert_eq!(validate(AoTexture::view(&view, SIZE, r32)), Ok(SIZE));
    let twice = [SIZE[0] * 2, SIZE[1] * 2];
    assert_eq!(validate(AoTexture::view(&view, twice, r32)), Ok(twice));

    let wrong = [SIZE[0] + 1, SIZE[1]];
    let error = validate(AoTexture::view(&view, wrong, r32)).unwrap_err();
    assert_eq!(
        error,
        InputError::ViewSize {
            what: "depth",
            size: wrong,
            mips: vec![twice, SIZE]
        }
    );
    assert!(error.to_string().contains("[65, 48]"), "{error}");

    let depth32 = wgpu::TextureFormat::Depth32Float;
    let error = validate(AoTexture::view(&view, SIZE, depth32)).unwrap_err();
    assert_eq!(
        error,
        InputError::ViewFormat {
            what: "depth",
            format: depth32,
            parent: r32
        }
    );
    assert!(
        error.to_string().contains("Depth32Float") && error.to_string().contains("R32Float"),
        "{error}"
    );
}
