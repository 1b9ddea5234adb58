//! The guard band (`AoInputs::guard_band`): the AO of the inner frame from an overscan
//! G-buffer. Away from the border it is the AO without a band; in the border band it is closer
//! to the reference; at half resolution too; motion vectors are read at the band's offset;
//! and bad bands are refused by name.

use crate::common;

use aokit::gpu::{read_texture_f32, upload_texture_2d};
use aokit::{
    AoError, AoInputs, AoPipeline, InputError, Method, NormalEncoding, Preset, Resolution,
};
use aokit_scene::{Builtin, Renderer};
use common::{encode_frame, gpu, rmse, scene_settings, trace};

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
}

/// With a band the temporal filter reads each pixel's motion at the band's offset in the
/// overscan's motion vectors (at full resolution) or in their downsample cut to the frame
/// (below it): motion vectors of 3 px in the frame and nonsense in the band give the AO of 3 px
/// everywhere, and another AO than 0 px (they are read at all).
#[test]
fn motion_vectors_are_read_at_the_bands_offset() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let (size, band) = ([48, 32], 8);
    let full = size.map(|side| side + 2 * band);
    let low = scene_settings(&scene, Method::Gtao, Preset::Low);
    let mut renderer = Renderer::new(&gpu, &scene, &low).unwrap();
    let (gbuffer, projection) = renderer
        .render_gbuffer_with_guard_band(&gpu, &scene.cameras[0], size, NormalEncoding::Oct32, band)
        .unwrap();
    let motion = |in_frame: f32, in_band: f32| {
        let texels: Vec<[f32; 2]> = (0..full[0] * full[1])
            .map(|i| {
                let (x, y) = (i % full[0], i / full[0]);
                let inside =
                    (band..band + size[0]).contains(&x) && (band..band + size[1]).contains(&y);
                [if inside { in_frame } else { in_band }, 0.0]
            })
            .collect();
        upload_texture_2d(
            &gpu.device,
            &gpu.queue,
            "motion",
            full,
            wgpu::TextureFormat::Rg32Float,
            bytemuck::cast_slice(&texels),
        )
        .unwrap()
    };
    let (moved, nonsense, still) = (motion(3.0, 3.0), motion(3.0, 1000.0), motion(0.0, 0.0));
    for resolution in [Resolution::Full, Resolution::Half] {
        let mut settings = aokit::AoSettings { resolution, ..low };
        settings.temporal.enabled = true;
        let run = |motion: &wgpu::Texture| {
            let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
            // The second frame reprojects the first: its noise differs, so the history counts.
            (0..2)
                .map(|frame_index| {
                    let inputs = AoInputs {
                        normals: Some((&gbuffer.normals).into()),
                        motion_vectors: Some(motion.into()),
                        frame_index,
                        guard_band: band,
                        ..AoInputs::new(&gbuffer.depth, projection)
                    };
                    encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
                        read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap()
                    })
                })
                .last()
                .unwrap()
        };
        let expected = run(&moved);
        assert_eq!(expected.len(), (size[0] * size[1]) as usize);
        assert!(
            run(&nonsense) == expected,
            "{resolution:?}: the band's motion vectors reached the frame"
        );
        assert!(
            run(&still) != expected,
            "{resolution:?}: the frame's motion vectors were not read"
        );
    }
}
