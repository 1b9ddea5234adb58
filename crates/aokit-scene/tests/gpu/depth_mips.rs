//! The depth MIP chain the marching and point kernels read far samples from
//! (`AoSettings::depth_mips`): its stacked levels against a CPU mirror in both precisions, the
//! kernels unchanged where no sample reaches a coarser level, their error against the
//! reference with it on, and the error a device without fp16 storage gets.

use crate::common;

use aokit::{
    AoError, AoInputs, AoPipeline, AoSettings, DepthMips, Method, Preset, Projection, SampleDepth,
};
use aokit_scene::Builtin;
use common::{
    encode_frame, gpu, linear_depth_texture, reduce_level, reference_errors, scene_settings,
};

/// The methods whose kernels read the chain.
const READERS: [Method; 6] = [
    Method::Gtao,
    Method::Vbao,
    Method::Hbao,
    Method::HbaoPlus,
    Method::Ssao,
    Method::SsaoCrytek,
];

/// The level above `finer` (of `size`): each texel from its 2x2 children (clamped to the finer
/// level), their mean of 1 / depth (of depth when `orthographic`) where all lie within 10% of
/// each other, else the furthest.
fn coarser_level(finer: &[f32], size: [u32; 2], orthographic: bool) -> (Vec<f32>, [u32; 2]) {
    reduce_level(finer, size, |_, children| {
        let nearest = children.into_iter().fold(f32::INFINITY, f32::min);
        let furthest = children.into_iter().fold(0.0, f32::max);
        if nearest > 0.0 && furthest <= nearest * 1.1 {
            if orthographic {
                children.iter().sum::<f32>() / 4.0
            } else {
                4.0 / children.iter().map(|d| 1.0 / d).sum::<f32>()
            }
        } else {
            furthest
        }
    })
}

/// A tilted plane with a step a third of its depth (edges at which blocks keep the furthest
/// depth) and a few pixels of sky.
fn stepped_plane(size: [u32; 2]) -> Vec<f32> {
    (0..size[1])
        .flat_map(|y| (0..size[0]).map(move |x| (x, y)))
        .map(|(x, y)| {
            let plane = 2.0 + 0.021 * x as f32 + 0.013 * y as f32;
            if y == 0 && x < 3 {
                0.0
            } else if x > size[0] / 2 + y / 3 {
                plane * 1.35
            } else {
                plane
            }
        })
        .collect()
}

/// Settings of `method` at `high` with the chain on in `precision`, reading it from `offset`.
fn with_chain(method: Method, precision: DepthMips, offset: f32) -> AoSettings {
    AoSettings {
        depth_mips: precision,
        depth_mip_offset: offset,
        ..AoSettings::preset(method, Preset::High)
    }
}

/// The precisions this device can build: fp16 where it can write R16Float storage.
fn precisions(gpu: &aokit::GpuContext) -> Vec<DepthMips> {
    let fp16 = gpu
        .device
        .features()
        .contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);
    eprintln!("fp16 storage on {}: {fp16}", gpu.describe());
    let mut precisions = vec![DepthMips::Fp32];
    if fp16 {
        precisions.push(DepthMips::Fp16);
    }
    precisions
}

#[test]
fn the_atlas_stacks_the_mean_of_one_surface_and_the_furthest_depth_at_edges() {
    // fp32: level 0, an exact copy of the working depth, at the origin and the coarser levels
    // stacked in a column right of it, within its height; fp16: the coarser levels alone.
    let gpu = gpu();
    let precisions = precisions(&gpu);
    // Odd sides, so that the clamp at a level's last texel matters; sizes that hold 3, 2 and
    // 4 levels of at least 2 texels a side.
    for (size, orthographic, levels) in [
        ([37, 23], false, 3),
        ([40, 8], true, 2),
        ([64, 64], false, 4),
    ] {
        let depth = stepped_plane(size);
        let texture = linear_depth_texture(&gpu, size, &depth);
        let aspect = size[0] as f32 / size[1] as f32;
        let projection = if orthographic {
            Projection::orthographic(4.0, aspect, 0.1, 100.0)
        } else {
            Projection::perspective(1.0, aspect, 0.1, None)
        };
        let inputs = AoInputs::new(&texture, projection);
        for &precision in &precisions {
            let settings = with_chain(Method::Gtao, precision, 3.0);
            let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
            let (working, atlas, atlas_size) = encode_frame(&gpu, &mut pipeline, &inputs, |o| {
                let atlas = o.depth_mip_atlas.expect("gtao reads the chain");
                let read = |t| aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, t).unwrap();
                (
                    read(o.working_linear_depth),
                    read(atlas),
                    [atlas.width(), atlas.height()],
                )
            });
            let level_0 = precision == DepthMips::Fp32;
            if level_0 {
                for y in 0..size[1] {
                    let start = (y * atlas_size[0]) as usize;
                    assert_eq!(
                        atlas[start..start + size[0] as usize],
                        working[(y * size[0]) as usize..((y + 1) * size[0]) as usize],
                        "{size:?}: level 0, row {y}"
                    );
                }
            }
            let column = if level_0 { size[0] } else { 0 };
            let mut finer = (working, size);
            let mut bottom = 0;
            for level in 1..=levels {
                // Level k starts at row H - (H >> (k - 1)), below the level before it.
                let row = size[1] - (size[1] >> (level - 1));
                assert!(
                    row >= bottom,
                    "{size:?}: level {level} overlaps the one above"
                );
                let (expected, level_size) = coarser_level(&finer.0, finer.1, orthographic);
                for y in 0..level_size[1] {
                    for x in 0..level_size[0] {
                        let want = expected[(y * level_size[0] + x) as usize];
                        let got = atlas[((row + y) * atlas_size[0] + column + x) as usize];
                        // fp16 keeps 11 bits of mantissa.
                        let tolerance = if precision == DepthMips::Fp16 {
                            1e-3
                        } else {
                            1e-6
                        };
                        assert!(
                            (got - want).abs() <= tolerance * want,
                            "{size:?} {precision:?}, level {level} texel ({x}, {y}): {got}, \
                             expected {want}"
                        );
                    }
                }
                bottom = row + level_size[1];
                finer = (expected, level_size);
            }
            let height = if level_0 { size[1] } else { bottom };
            assert_eq!(
                atlas_size,
                [column + size[0] / 2, height],
                "{size:?} {precision:?}: {levels} levels"
            );
        }
    }
}

#[test]
fn kernels_whose_samples_stay_near_read_full_resolution_exactly_as_with_the_chain_off() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    let size = [96, 54];
    let precisions = precisions(&gpu);
    for method in READERS {
        let off = scene_settings(&scene, method, Preset::High);
        let render =
            |settings: &AoSettings| common::render_frame(&gpu, &scene, camera, settings, size).ao;
        let base = render(&off);
        for &depth_mips in &precisions {
            // From 2^17 pixels out: no sample of a 256-pixel radius reads a coarser level
            // (fp32 reads level 0 from the atlas's copy, fp16 from the working depth).
            let near = AoSettings {
                depth_mips,
                depth_mip_offset: 16.0,
                ..off
            };
            assert_eq!(render(&near), base, "{method:?} {depth_mips:?}");
            // From 2 pixels out: far samples read coarser levels, and the AO moves, in range.
            let far = AoSettings {
                depth_mip_offset: 0.0,
                ..near
            };
            let ao = render(&far);
            assert_ne!(
                ao, base,
                "{method:?} {depth_mips:?}: no sample read the chain"
            );
            assert!(
                ao.iter().all(|a| (0.0..=1.0).contains(a)),
                "{method:?} {depth_mips:?}: AO out of [0, 1] or NaN"
            );
        }
    }
}

#[test]
fn the_chain_costs_little_error_against_the_reference() {
    let gpu = gpu();
    // Measured at 160x96 with 128 reference rays, off and at offset 1 (samples from 4 pixels
    // out read coarser levels): gtao on room 0.0491 and 0.0514, ssao 0.0950 and 0.0958, vbao
    // on thin 0.0816 and 0.0708. A level or row read from the wrong place puts other
    // surfaces' depths into the samples and moves these by far more.
    for (builtin, method) in [
        (Builtin::Room, Method::Gtao),
        (Builtin::Room, Method::Ssao),
        (Builtin::Thin, Method::Vbao),
    ] {
        let scene = builtin.build();
        // The interpolated read, as the chain's error tables were measured (docs/depth-mips.md):
        // the nearest read places a coarse texel's depth at the texel's centre, 2^level pixels
        // wide, and at offset 1 moves gtao on room from 0.0557 to 0.0657.
        let off = AoSettings {
            sample_depth: SampleDepth::Interpolated,
            ..scene_settings(&scene, method, Preset::High)
        };
        let on = AoSettings {
            depth_mips: DepthMips::Fp32,
            depth_mip_offset: 1.0,
            ..off
        };
        let (errors, _) = reference_errors(&gpu, &scene, &[off, on], [160, 96]);
        eprintln!(
            "{} {method:?}: RMSE {:.4} off, {:.4} with the chain",
            scene.name, errors[0], errors[1]
        );
        assert!(
            errors[1] < errors[0] + 0.005,
            "{} {method:?}: {errors:?}",
            scene.name
        );
    }
}

#[test]
fn fp16_on_a_device_without_half_float_storage_is_refused_by_name() {
    let instance = wgpu::Instance::default();
    let adapter = pollster::block_on(instance.request_adapter(&Default::default()))
        .expect("tests need a wgpu adapter");
    // A device with no optional features: R16Float storage is not in WebGPU's core.
    let (device, queue) = pollster::block_on(adapter.request_device(&Default::default())).unwrap();
    let fp16 = with_chain(Method::Gtao, DepthMips::Fp16, 3.0);
    let error = AoPipeline::new(&device, &queue, &fp16)
        .err()
        .expect("fp16 refused");
    assert!(
        matches!(error, AoError::Fp16DepthMipsUnsupported),
        "{error}"
    );
    assert!(
        error.to_string().contains("use depth_mips = fp32"),
        "{error}"
    );
    let mut pipeline = AoPipeline::new(
        &device,
        &queue,
        &with_chain(Method::Gtao, DepthMips::Fp32, 3.0),
    )
    .unwrap();
    assert!(pipeline.set_settings(&device, &queue, &fp16).is_err());
    // Methods with a chain of their own do not read this one, so fp16 asks nothing of them.
    AoPipeline::new(
        &device,
        &queue,
        &with_chain(Method::Sao, DepthMips::Fp16, 3.0),
    )
    .unwrap();
}
