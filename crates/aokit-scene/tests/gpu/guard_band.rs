//! The guard band (`AoInputs::guard_band`): the AO of the inner frame from an overscan
//! G-buffer. Away from the border it is the AO without a band; in the border band it is closer
//! to the reference; at half resolution too; and bad bands are refused by name.

use crate::common;

use aokit::{
    AoError, AoInputs, AoPipeline, InputError, Method, NormalEncoding, Preset, Resolution,
};
use aokit_scene::{Builtin, Renderer};
use common::{gpu, rmse, scene_settings, trace};

const SIZE: [u32; 2] = [160, 90];
const BAND: u32 = 16;
/// The border band the error is measured in, in pixels from the image's edge.
const BORDER: u32 = 12;

/// Whether pixel `i` of a `SIZE` image lies within `px` pixels of its edge.
fn near_edge(i: usize, px: u32) -> bool {
    let (x, y) = ((i as u32) % SIZE[0], (i as u32) / SIZE[0]);
    x.min(y).min(SIZE[0] - 1 - x).min(SIZE[1] - 1 - y) < px
}

/// The AO of room's first camera at `SIZE` with `band` pixels of overscan, GTAO `high`.
fn ao(resolution: Resolution, band: u32) -> (Vec<f32>, Vec<f32>) {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let settings = aokit::AoSettings {
        resolution,
        ..scene_settings(&scene, Method::Gtao, Preset::High)
    };
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    renderer.guard_band = band;
    let frame = renderer.render(&gpu, &scene.cameras[0], SIZE, 0).unwrap();
    assert_eq!(frame.size, SIZE);
    assert_eq!(frame.ao.len(), (SIZE[0] * SIZE[1]) as usize);
    (frame.ao, frame.linear_depth)
}

fn check_band(resolution: Resolution) {
    let scene = Builtin::Room.build();
    let reference = trace(&scene, &scene.cameras[0], SIZE, 64);
    let (plain, depth) = ao(resolution, 0);
    let (banded, _) = ao(resolution, BAND);
    let surface = |i: usize| depth[i] > 0.0;
    let border = |i: usize| surface(i) && near_edge(i, BORDER);
    // Beyond the kernel's reach and the filters' from the edge, the band changes nothing but
    // rounding: the same depth, normals and noise at each pixel.
    let inner = |i: usize| surface(i) && !near_edge(i, 40);
    let inner_change = rmse(&banded, &plain, inner);
    let border_change = rmse(&banded, &plain, border);
    assert!(
        inner_change < 0.005,
        "inner frame changed by RMS {inner_change}"
    );
    assert!(
        border_change > 0.01,
        "the band changed the border by RMS {border_change} only"
    );
    let without = rmse(&plain, &reference.ao, border);
    let with = rmse(&banded, &reference.ao, border);
    assert!(
        with < 0.9 * without,
        "border-band RMSE {with} with a {BAND} px band, {without} without"
    );
}

#[test]
fn band_fixes_the_border_and_nothing_else() {
    check_band(Resolution::Full);
}

#[test]
fn band_at_half_resolution() {
    check_band(Resolution::Half);
}

#[test]
fn bad_bands_are_refused() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    let settings = scene_settings(&scene, Method::Gtao, Preset::Low);
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    let (gbuffer, projection) = renderer
        .render_gbuffer_with_guard_band(&gpu, camera, [32, 16], NormalEncoding::Oct32, 4)
        .unwrap();
    assert_eq!(gbuffer.size, [40, 24]);
    let run = |settings: &aokit::AoSettings, inputs: &AoInputs<'_>| {
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, settings).unwrap();
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        pipeline
            .encode(&gpu.device, &gpu.queue, &mut encoder, inputs)
            .map(|outputs| [outputs.ao.width(), outputs.ao.height()])
    };
    let inputs = |band| AoInputs {
        normals: Some((&gbuffer.normals).into()),
        guard_band: band,
        ..AoInputs::new(&gbuffer.depth, projection)
    };
    assert_eq!(run(&settings, &inputs(4)).unwrap(), [32, 16]);
    let err = run(&settings, &inputs(12)).unwrap_err();
    assert!(
        matches!(
            err,
            AoError::Input(InputError::GuardBandTooWide {
                band: 12,
                depth: [40, 24]
            })
        ),
        "{err}"
    );
    let quarter = aokit::AoSettings {
        resolution: Resolution::Quarter,
        ..settings
    };
    let err = run(&quarter, &inputs(2)).unwrap_err();
    assert!(
        err.to_string().contains("multiple of the scale (4)"),
        "{err}"
    );
    let moving = AoInputs {
        motion_vectors: Some((&gbuffer.motion).into()),
        ..inputs(4)
    };
    let err = run(&settings, &moving).unwrap_err();
    assert!(
        matches!(err, AoError::Input(InputError::GuardBandMotionVectors)),
        "{err}"
    );
}
