//! Debug views: each shows what the frame computed (the AO, the normals, the depth order),
//! edges mark silhouettes and creases but not planes, and views the outputs cannot give are
//! refused naming the setting.

use crate::common;

use aokit::debug::{AoDebug, DebugStyle, DebugView};
use aokit::{AoInputs, AoPipeline, AoSettings, Method, NormalEncoding, Preset, Resolution};
use aokit_scene::{Builtin, Renderer};
use common::{encode_frame, gpu};

const SIZE: [u32; 2] = [160, 96];

/// Channel `c` of pixel `i` of an RGBA8 image, in [0, 1].
fn channel(image: &[u8], i: usize, c: usize) -> f32 {
    f32::from(image[4 * i + c]) / 255.0
}

#[test]
fn every_view_shows_what_the_frame_computed() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let mut settings = AoSettings {
        radius: scene.suggested_radius.unwrap(),
        bent_normals: true,
        resolution: Resolution::Half,
        ..AoSettings::preset(Method::Gtao, Preset::Medium)
    };
    settings.temporal.enabled = true;
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    renderer.debug_views = DebugView::ALL.to_vec();
    let frame = renderer.render(&gpu, &scene.cameras[0], SIZE, 0).unwrap();
    let views: Vec<DebugView> = frame.debug.iter().map(|(view, _)| *view).collect();
    assert_eq!(views, DebugView::ALL);
    let image = |view| &frame.debug.iter().find(|(v, _)| *v == view).unwrap().1;
    let pixels = frame.ao.len();
    for (view, rgba) in &frame.debug {
        assert_eq!(rgba.len(), 4 * pixels, "{}", view.name());
    }
    let covered: Vec<usize> = (0..pixels)
        .filter(|&i| frame.linear_depth[i] > 0.0)
        .collect();
    assert!(covered.len() > pixels / 2);

    // The AO view is the AO; the normals view the normals, as n * 0.5 + 0.5.
    let ao = image(DebugView::Ao);
    for i in 0..pixels {
        assert!(
            (channel(ao, i, 0) - frame.ao[i]).abs() <= 0.5 / 255.0 + 1e-6,
            "pixel {i}"
        );
    }
    let normals = image(DebugView::Normals);
    for &i in &covered {
        for c in 0..3 {
            let expected = frame.normals[i][c] * 0.5 + 0.5;
            assert!(
                (channel(normals, i, c) - expected).abs() < 1.0 / 255.0,
                "pixel {i}"
            );
        }
    }
    // Nearer is brighter in the depth view.
    let depth = image(DebugView::Depth);
    let nearest = *covered
        .iter()
        .min_by(|&&a, &&b| frame.linear_depth[a].total_cmp(&frame.linear_depth[b]))
        .unwrap();
    let farthest = *covered
        .iter()
        .max_by(|&&a, &&b| frame.linear_depth[a].total_cmp(&frame.linear_depth[b]))
        .unwrap();
    assert!(channel(depth, nearest, 0) > 0.95 && channel(depth, farthest, 0) < 0.05);
    // Below full resolution the working depth comes in 2x2 blocks.
    let working = image(DebugView::WorkingDepth);
    let width = SIZE[0] as usize;
    let blocky = covered
        .iter()
        .filter(|&&i| (i % width).is_multiple_of(2) && (i / width).is_multiple_of(2))
        .all(|&i| {
            working[4 * i] == working[4 * (i + 1)] && working[4 * i] == working[4 * (i + width)]
        });
    assert!(blocky);
    // Edges: silhouettes and creases, a small part of the image; the open floor has none.
    let edges = image(DebugView::Edges);
    let red = |i: usize| channel(edges, i, 0) > 0.9 && channel(edges, i, 1) < 0.1;
    let edge_pixels = covered.iter().filter(|&&i| red(i)).count();
    assert!(
        edge_pixels > covered.len() / 200 && edge_pixels < covered.len() / 10,
        "{edge_pixels} edge pixels of {}",
        covered.len()
    );
    let bottom_row = (SIZE[1] as usize - 1) * width;
    assert!((bottom_row + width / 4..bottom_row + width * 3 / 4).all(|i| !red(i)));
    // The rejected-history mask, at the working size, over the 2x2 pixels of each texel.
    let rejected = image(DebugView::Rejected);
    let (mask, mask_size) = frame.history_rejected.as_ref().unwrap();
    for i in 0..pixels {
        let texel = (i / width / 2) * mask_size[0] as usize + i % width / 2;
        assert_eq!(channel(rejected, i, 0), mask[texel], "pixel {i}");
    }
    let bent = image(DebugView::BentNormals);
    assert!(
        covered
            .iter()
            .all(|&i| bent[4 * i..4 * i + 3].iter().any(|&b| b > 0))
    );
}

#[test]
fn views_the_outputs_lack_and_bad_styles_are_refused_naming_the_setting() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let scene = Builtin::Room.build();
    let settings = AoSettings::preset(Method::Hbao, Preset::Low);
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    let (gbuffer, projection) = renderer
        .render_gbuffer(&gpu, &scene.cameras[0], SIZE, NormalEncoding::Oct32)
        .unwrap();
    let mut pipeline = AoPipeline::new(device, queue, &settings).unwrap();
    let mut debug = AoDebug::new(device, queue);
    let inputs = AoInputs::new(&gbuffer.depth, projection);
    let results: Vec<String> = encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
        let mut encoder = device.create_command_encoder(&Default::default());
        let mut attempt = |view, style: &DebugStyle| {
            debug
                .encode(device, queue, &mut encoder, outputs, view, style)
                .map(|_| ())
                .unwrap_err()
                .to_string()
        };
        let fine = DebugStyle::default();
        vec![
            attempt(DebugView::BentNormals, &fine),
            attempt(DebugView::Rejected, &fine),
            attempt(
                DebugView::Depth,
                &DebugStyle {
                    depth_range: [10.0, 1.0],
                    ..fine
                },
            ),
            attempt(
                DebugView::Edges,
                &DebugStyle {
                    edge_threshold: f32::NAN,
                    ..fine
                },
            ),
        ]
    });
    for (message, named) in results.iter().zip([
        "bent_normals",
        "temporal.enabled",
        "depth_range",
        "edge_threshold",
    ]) {
        assert!(message.contains(named), "{message}");
    }
}
