//! The exclusion mask: a mask texture or a stencil reference leaves its pixels at AO 1, blends
//! fractional mask values, changes nothing elsewhere, and stays exact with every filter on and
//! below full resolution, since it is the frame's last pass.

use crate::common;

use aokit::gpu::{create_texture_2d, read_texture_f32};
use aokit::{
    AoError, AoInputs, AoMask, AoPipeline, AoSettings, InputError, Method, NormalEncoding, Preset,
    Resolution,
};
use aokit_scene::{Builtin, Renderer};
use common::{DepthCopy, copy_depth, encode_frame, gpu, r8_texture};

const SIZE: [u32; 2] = [96, 64];
/// The stencil rectangle `[x, y, width, height]`.
const RECT: [u32; 4] = [20, 10, 40, 30];

fn in_rect(i: usize) -> bool {
    let (x, y) = ((i % SIZE[0] as usize) as u32, (i / SIZE[0] as usize) as u32);
    (RECT[0]..RECT[0] + RECT[2]).contains(&x) && (RECT[1]..RECT[1] + RECT[3]).contains(&y)
}

#[test]
fn masked_pixels_keep_ao_1_and_the_others_are_untouched() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let scene = Builtin::Room.build();
    let mut settings = AoSettings {
        radius: scene.suggested_radius.unwrap(),
        resolution: Resolution::Half,
        ..AoSettings::preset(Method::Gtao, Preset::High)
    };
    settings.spatial.enabled = true;
    settings.temporal.enabled = true;
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    let (gbuffer, projection) = renderer
        .render_gbuffer(&gpu, &scene.cameras[0], SIZE, NormalEncoding::Oct32)
        .unwrap();
    let ao_with = |mask: Option<AoMask<'_>>, depth: &wgpu::Texture| {
        // A fresh pipeline per run, so that every run sees the same temporal history.
        let mut pipeline = AoPipeline::new(device, queue, &settings).unwrap();
        let inputs = AoInputs {
            normals: Some((&gbuffer.normals).into()),
            mask,
            ..AoInputs::new(depth, projection)
        };
        encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
            read_texture_f32(device, queue, outputs.ao).unwrap()
        })
    };
    let unmasked = ao_with(None, &gbuffer.depth);
    let occluded = unmasked.iter().filter(|&&a| a < 0.9).count();
    assert!(occluded > 500, "only {occluded} occluded pixels to mask");

    // A mask texture: 1 in the left third, 0.5 in the middle third, 0 in the right third.
    let width = SIZE[0] as usize;
    let third = |i: usize| (i % width) * 3 / width;
    let weights: Vec<u8> = (0..unmasked.len())
        .map(|i| [255, 128, 0][third(i)])
        .collect();
    let mask = r8_texture(&gpu, SIZE, &weights);
    let masked = ao_with(Some(AoMask::Texture((&mask).into())), &gbuffer.depth);
    for (i, (&m, &u)) in masked.iter().zip(&unmasked).enumerate() {
        let expected = match third(i) {
            0 => 1.0,
            1 => u + (1.0 - u) * (128.0 / 255.0),
            _ => u,
        };
        assert!((m - expected).abs() < 1e-5, "pixel {i}: {m} for {expected}");
    }

    // A stencil: 0x23 inside the rectangle, 0 outside; the low four bits are compared, so
    // reference 0x13 matches it.
    for samples in [1, 4] {
        let depth_stencil = copy_depth(
            &gpu,
            &gbuffer.depth,
            &DepthCopy {
                format: wgpu::TextureFormat::Depth24PlusStencil8,
                samples,
                stencil: Some((0x23, RECT)),
            },
        );
        let mask = AoMask::Stencil {
            texture: (&depth_stencil).into(),
            reference: 0x13,
            read_mask: 0x0f,
        };
        // 24-bit depth moves the AO a little: the baseline is this depth's own.
        let unmasked = ao_with(None, &depth_stencil);
        let masked = ao_with(Some(mask), &depth_stencil);
        for (i, (&m, &u)) in masked.iter().zip(&unmasked).enumerate() {
            let expected = if in_rect(i) { 1.0 } else { u };
            assert_eq!(m, expected, "{samples} samples, pixel {i}");
        }
    }
}

#[test]
fn masks_the_pipeline_cannot_use_are_refused_naming_the_problem() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let texture = |format, size| {
        create_texture_2d(
            device,
            "mask",
            size,
            format,
            wgpu::TextureUsages::TEXTURE_BINDING,
        )
    };
    let depth = texture(wgpu::TextureFormat::Depth32Float, SIZE);
    let rgba = texture(wgpu::TextureFormat::Rgba8Unorm, SIZE);
    let small = texture(wgpu::TextureFormat::R8Unorm, [SIZE[0] / 2, SIZE[1]]);
    let projection = aokit::Projection::perspective(1.0, 1.5, 0.1, None);
    let cases = [
        (
            AoMask::Texture((&rgba).into()),
            InputError::MaskFormat(wgpu::TextureFormat::Rgba8Unorm),
            "Rgba8Unorm",
        ),
        (
            AoMask::Stencil {
                texture: (&depth).into(),
                reference: 1,
                read_mask: 0xff,
            },
            InputError::MaskNoStencil(wgpu::TextureFormat::Depth32Float),
            "stencil",
        ),
        (
            AoMask::Texture((&small).into()),
            InputError::SizeMismatch {
                what: "mask",
                depth: SIZE,
                other: [SIZE[0] / 2, SIZE[1]],
            },
            "mask",
        ),
    ];
    let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default()).unwrap();
    for (mask, expected, named) in cases {
        let inputs = AoInputs {
            mask: Some(mask),
            ..AoInputs::new(&depth, projection)
        };
        let mut encoder = device.create_command_encoder(&Default::default());
        match pipeline.encode(device, queue, &mut encoder, &inputs) {
            Err(AoError::Input(error)) => {
                assert!(error.to_string().contains(named), "{error}");
                assert_eq!(error, expected);
            }
            other => panic!("{:?}", other.map(|_| ())),
        }
    }
}
