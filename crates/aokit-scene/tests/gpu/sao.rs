//! Scalable Ambient Obscurance: its depth MIP chain against a CPU mirror, and its error
//! against the ray-traced reference, on whatever adapter exists (lavapipe in CI). The checks
//! every method shares (range, sky, open plane, corners, clamps) are in methods.rs.

use crate::common;

use aokit::{AoInputs, AoPipeline, AoSettings, Method, Preset, Projection};
use aokit_scene::Builtin;
use common::{
    encode_frame, gpu, linear_depth_texture, read_level, reduce_level, reference_errors,
    scene_settings,
};

/// The level above `finer` (of `size`) as the paper's rotated-grid subsample builds it: texel
/// `(x, y)` keeps child `(2x + (y & 1), 2y + (x & 1))`, clamped to the finer level.
fn coarser_level(finer: &[f32], size: [u32; 2]) -> (Vec<f32>, [u32; 2]) {
    reduce_level(finer, size, |[x, y], children| {
        children[((y & 1) + 2 * (x & 1)) as usize]
    })
}

#[test]
fn the_depth_mip_chain_keeps_real_depths_picked_by_a_checkerboard() {
    let gpu = gpu();
    let settings = AoSettings::preset(Method::Sao, Preset::High);
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
    // Odd sides, so that the clamp at the last texel matters, and every depth distinct, so
    // that a wrong pick or an average cannot match by chance. 37 pixels hold six levels and
    // the chain stops at the five the taps read (3 x 2 workgroups of 16x16 pixels, the last
    // ones partly outside); 6x3 holds three (the levels it lacks are never written); 40 pixels
    // by 1 five again, with a one-texel side at every level.
    for (size, expected_levels) in [([37, 23], 5), ([6, 3], 3), ([40, 1], 5)] {
        let depth: Vec<f32> = (0..size[0] * size[1])
            .map(|i| 2.0 + (i as f32 * 0.618_034).fract() * 5.0 + i as f32 * 1e-4)
            .collect();
        let texture = linear_depth_texture(&gpu, size, &depth);
        let aspect = size[0] as f32 / size[1] as f32;
        let inputs = AoInputs::new(&texture, Projection::perspective(1.0, aspect, 0.1, None));
        let (working, levels) = encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
            let chain = outputs.depth_mips.expect("sao reads a depth MIP chain");
            let working =
                aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, outputs.working_linear_depth)
                    .unwrap();
            let levels: Vec<_> = (0..chain.mip_level_count())
                .map(|level| read_level(&gpu, chain, level))
                .collect();
            (working, levels)
        });
        assert_eq!(levels.len(), expected_levels, "{size:?}");
        assert_eq!(levels[0], (working, size));
        for level in 1..levels.len() {
            let expected = coarser_level(&levels[level - 1].0, levels[level - 1].1);
            assert_eq!(levels[level], expected, "{size:?}, level {level}");
            for d in &levels[level].0 {
                assert!(
                    depth.contains(d),
                    "{size:?}, level {level}: {d} is no input depth"
                );
            }
        }
    }

    // The other methods do not build one.
    let texture = linear_depth_texture(&gpu, [37, 23], &[3.0; 37 * 23]);
    let inputs = AoInputs::new(&texture, Projection::perspective(1.0, 1.6, 0.1, None));
    let mut gtao = AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default()).unwrap();
    assert!(encode_frame(&gpu, &mut gtao, &inputs, |o| o
        .depth_mips
        .is_none()));
}

const SIZE: [u32; 2] = [160, 96];

#[test]
fn sao_error_against_the_reference_at_high_is_recorded_and_bounded() {
    let gpu = gpu();
    // Measured at 160x96 with 128 reference rays (docs/methods/sao.md has the tables at 480x270):
    // room 0.117, stairs 0.164, where AO 1 everywhere, a kernel that finds no occlusion,
    // scores 0.160 and 0.212, and a black one far more. The paper's estimator darkens creases
    // to 0 and fades out far occluders, so it stays well above the horizon methods.
    for (builtin, bound) in [(Builtin::Room, 0.13), (Builtin::Stairs, 0.18)] {
        let scene = builtin.build();
        let settings = scene_settings(&scene, Method::Sao, Preset::High);
        let (errors, unoccluded) = reference_errors(&gpu, &scene, &[settings], SIZE);
        let sao = errors[0];
        eprintln!(
            "{}: SAO RMSE {sao:.4}, AO 1 everywhere {unoccluded:.4}",
            scene.name
        );
        assert!(sao < bound, "{}: SAO RMSE {sao}", scene.name);
        assert!(
            sao < 0.9 * unoccluded,
            "{}: SAO {sao}, no AO {unoccluded}",
            scene.name
        );
    }
}
