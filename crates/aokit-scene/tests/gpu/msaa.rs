//! Multisampled depth: which depth a pixel should hand to the pipeline. A G-buffer rendered at
//! twice the size stands in for 4x MSAA (its 2x2 blocks are a pixel's four samples). Each way
//! of resolving the samples to one depth (and the normal of the sample it picks) is scored
//! against what the resolved image shows: the reference traced through the four samples,
//! averaged over those with a surface; over all pixels and over the pixels whose samples
//! disagree (the edges). Sample 0, which `AoInputs::depth` reads from a multisampled texture,
//! and a min or max resolve keep one sample's surface; an averaged resolve puts a surface
//! between foreground and background. The test prints the table docs/integration.md quotes,
//! checks that every resolve stays within the conventions' tolerance over all pixels, and that
//! a min resolve beats an averaged one at the edges.

use crate::common;

use aokit::gpu::{read_texture, read_texture_f32, upload_texture_2d};
use aokit::{AoInputs, AoPipeline, AoSettings, Method, NormalEncoding, Preset};
use aokit_scene::{Builtin, Renderer};
use common::{encode_frame, gpu, linear_depth_texture, rmse, trace};

const SIZE: [u32; 2] = [160, 96];
/// The conventions test's tolerance.
const TOLERANCE: f64 = 0.08;

/// Relative depth spread above which a pixel's samples show different surfaces.
const EDGE: f32 = 0.1;

/// The four samples' linear depths (0: no surface) resolved to one, with the sample whose
/// normal goes with it.
type Resolve = fn(&[f32; 4]) -> (f32, usize);

fn sample_0(s: &[f32; 4]) -> (f32, usize) {
    (s[0], 0)
}

/// The nearest surface, by the depth test's `min` (reverse-Z: the largest NDC).
fn nearest(s: &[f32; 4]) -> (f32, usize) {
    (0..4)
        .filter(|&i| s[i] > 0.0)
        .min_by(|&a, &b| s[a].total_cmp(&s[b]))
        .map_or((0.0, 0), |i| (s[i], i))
}

/// The farthest: no surface when any sample has none.
fn farthest(s: &[f32; 4]) -> (f32, usize) {
    match (0..4).find(|&i| s[i] == 0.0) {
        Some(i) => (0.0, i),
        None => (0..4)
            .max_by(|&a, &b| s[a].total_cmp(&s[b]))
            .map(|i| (s[i], i))
            .unwrap(),
    }
}

/// The mean of reverse-Z NDC depth (near / depth, 0 without a surface), back to linear: what
/// an averaging resolve of the depth buffer gives, with sample 0's normal.
fn averaged(s: &[f32; 4]) -> (f32, usize) {
    let ndc = s
        .iter()
        .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
        .sum::<f32>()
        / 4.0;
    (if ndc > 0.0 { 1.0 / ndc } else { 0.0 }, 0)
}

/// The four samples of pixel `i` of an image twice `SIZE`.
fn block<T: Copy>(fine: &[T], i: usize) -> [T; 4] {
    let width = SIZE[0] as usize;
    let (x, y) = (i % width * 2, i / width * 2);
    let at = |dx: usize, dy: usize| fine[(y + dy) * width * 2 + x + dx];
    [at(0, 0), at(1, 0), at(0, 1), at(1, 1)]
}

#[test]
fn every_depth_resolve_stays_within_the_tolerance() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let fine_size = [SIZE[0] * 2, SIZE[1] * 2];
    let pixels = (SIZE[0] * SIZE[1]) as usize;
    for builtin in [Builtin::Room, Builtin::Stairs] {
        let scene = builtin.build();
        let camera = &scene.cameras[0];
        assert!(
            camera.reverse_z && camera.far.is_none(),
            "averaged() assumes it"
        );
        let radius = scene.suggested_radius.unwrap();
        let settings = AoSettings {
            radius,
            ..AoSettings::preset(Method::Gtao, Preset::High)
        };
        let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
        let mut pipeline = AoPipeline::new(device, queue, &settings).unwrap();
        let (gbuffer, _) = renderer
            .render_gbuffer(&gpu, camera, fine_size, NormalEncoding::Oct32)
            .unwrap();
        let (_, projection) = renderer
            .render_gbuffer(&gpu, camera, SIZE, NormalEncoding::Oct32)
            .unwrap();
        let fine_depth = encode_frame(
            &gpu,
            &mut pipeline,
            &AoInputs::new(&gbuffer.depth, projection),
            |o| read_texture_f32(device, queue, o.linear_depth).unwrap(),
        );
        let fine_normals: Vec<u32> =
            bytemuck::cast_slice(&read_texture(device, queue, &gbuffer.normals).unwrap()).to_vec();
        let traced = trace(&scene, camera, fine_size, 64);
        // What the resolved image shows: the mean AO of the samples that have a surface.
        let target: Vec<f32> = (0..pixels)
            .map(|i| {
                let (ao, depth) = (block(&traced.ao, i), block(&traced.linear_depth, i));
                let seen: Vec<f32> = (0..4).filter(|&k| depth[k] > 0.0).map(|k| ao[k]).collect();
                seen.iter().sum::<f32>() / seen.len().max(1) as f32
            })
            .collect();
        let samples: Vec<[f32; 4]> = (0..pixels).map(|i| block(&fine_depth, i)).collect();
        let covered = |i: usize| samples[i].iter().any(|&d| d > 0.0);
        let edge = |i: usize| {
            let s = &samples[i];
            let (near, far) = (nearest(s).0, farthest(s).0);
            covered(i) && (far == 0.0 || far > near * (1.0 + EDGE))
        };
        let edges = (0..pixels).filter(|&i| edge(i)).count();
        eprintln!("{builtin:?}: {edges} edge pixels of {pixels}");
        let mut edge_errors = Vec::new();
        for (name, resolve) in [
            ("sample 0", sample_0 as Resolve),
            ("min", nearest),
            ("max", farthest),
            ("average", averaged),
        ] {
            let (depth, picked): (Vec<f32>, Vec<usize>) = samples.iter().map(resolve).unzip();
            let normals: Vec<u32> = (0..pixels)
                .map(|i| block(&fine_normals, i)[picked[i]])
                .collect();
            let depth_texture = linear_depth_texture(&gpu, SIZE, &depth);
            let normal_texture = upload_texture_2d(
                device,
                queue,
                "resolved normals",
                SIZE,
                wgpu::TextureFormat::R32Uint,
                bytemuck::cast_slice(&normals),
            )
            .unwrap();
            let inputs = AoInputs {
                normals: Some((&normal_texture).into()),
                ..AoInputs::new(&depth_texture, projection)
            };
            let ao = encode_frame(&gpu, &mut pipeline, &inputs, |o| {
                read_texture_f32(device, queue, o.ao).unwrap()
            });
            let (all, at_edges) = (rmse(&ao, &target, covered), rmse(&ao, &target, edge));
            eprintln!("{builtin:?} / {name}: RMSE {all:.4}, edges {at_edges:.4}");
            assert!(all < TOLERANCE, "{builtin:?} / {name}: RMSE {all}");
            edge_errors.push(at_edges);
        }
        // The advice docs/integration.md gives: resolve with min, not with an average.
        assert!(
            edge_errors[1] < edge_errors[3],
            "{builtin:?}: {edge_errors:?}"
        );
    }
}
