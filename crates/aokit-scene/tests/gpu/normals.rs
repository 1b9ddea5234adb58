//! Normal encodings and sources through the scene renderer, on whatever adapter exists
//! (lavapipe in CI). `measure_for_docs` prints the tables of docs/normals.md:
//! `cargo test --release -p aokit-scene --test gpu normals:: -- --ignored --nocapture`.

use crate::common;

use aokit::normals::angle_degrees;
use aokit::{AoSettings, GpuContext, NormalEncoding, NormalSource};
use aokit_eval::depth_edge_mask;
use aokit_scene::{Builtin, Camera, Frame, Renderer, Scene};
use common::gpu;

const SIZE: [u32; 2] = [192, 128];

/// Depth edges as `aokit compare` marks them: a neighbour 5% nearer or farther or no surface,
/// and the pixels within 2 of one.
const EDGE_RELATIVE_DEPTH: f32 = 0.05;
const EDGE_RADIUS: u32 = 2;

/// One view rendered with the default normals (oct32 G-buffer) and a renderer to render it
/// again with other normal settings.
struct View {
    scene: Scene,
    camera: Camera,
    renderer: Renderer,
    base: Frame,
    size: [u32; 2],
}

impl View {
    fn new(gpu: &GpuContext, scene: Scene, camera: Option<&str>, size: [u32; 2]) -> Self {
        let camera = scene.camera(camera).unwrap();
        let settings = AoSettings {
            radius: scene.suggested_radius.unwrap_or(1.0),
            ..AoSettings::default()
        };
        let mut renderer = Renderer::new(gpu, &scene, &settings).unwrap();
        let base = renderer.render(gpu, &camera, size, 0).unwrap();
        Self {
            scene,
            camera,
            renderer,
            base,
            size,
        }
    }

    fn builtin(gpu: &GpuContext, builtin: Builtin) -> Self {
        Self::new(gpu, builtin.build(), None, SIZE)
    }

    /// How the view rendered with `normals` instead of the defaults differs.
    fn difference(&mut self, gpu: &GpuContext, normals: aokit::NormalsSettings) -> Difference {
        let settings = AoSettings {
            normals,
            ..*self.renderer.settings()
        };
        self.renderer.set_settings(gpu, &settings).unwrap();
        let frame = self
            .renderer
            .render(gpu, &self.camera, self.size, 0)
            .unwrap();
        Difference::new(self, &frame)
    }

    fn name(&self) -> String {
        format!("{} / {}", self.scene.name, self.camera.name)
    }

    /// Indices of the pixels showing a surface, and whether each is near a depth edge.
    fn surface(&self) -> Vec<(usize, bool)> {
        let edges = depth_edge_mask(
            self.size,
            &self.base.linear_depth,
            EDGE_RELATIVE_DEPTH,
            EDGE_RADIUS,
        );
        (0..edges.len())
            .filter(|&i| self.base.linear_depth[i] > 0.0)
            .map(|i| (i, edges[i]))
            .collect()
    }
}

/// How one surface pixel's normal differs from the view's default rendering.
struct PixelDifference {
    /// Angle between the normals the AO used, in degrees.
    angle: f64,
    /// Whether the pixel is near a depth edge.
    edge: bool,
    /// z of the default rendering's normal: below 0 it faces away from the view axis.
    z: f32,
}

/// How a rendering differs from the view's default one, over its surface pixels.
struct Difference {
    pixels: Vec<PixelDifference>,
    /// RMSE of the AO.
    ao_rmse: f64,
}

impl Difference {
    fn new(view: &View, frame: &Frame) -> Self {
        let pixels: Vec<PixelDifference> = view
            .surface()
            .into_iter()
            .map(|(i, edge)| PixelDifference {
                angle: angle_degrees(view.base.normals[i], frame.normals[i]),
                edge,
                z: view.base.normals[i].z,
            })
            .collect();
        let squares: f64 = view
            .surface()
            .iter()
            .map(|&(i, _)| f64::from(view.base.ao[i] - frame.ao[i]).powi(2))
            .sum();
        Self {
            ao_rmse: (squares / pixels.len() as f64).sqrt(),
            pixels,
        }
    }

    fn angles(&self, edges: Option<bool>) -> Vec<f64> {
        self.pixels
            .iter()
            .filter(|p| edges.is_none_or(|e| p.edge == e))
            .map(|p| p.angle)
            .collect()
    }
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// The value below which a fraction `q` of `values` lies.
fn quantile(values: &[f64], q: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

fn encoding(encoding: NormalEncoding) -> aokit::NormalsSettings {
    aokit::NormalsSettings {
        encoding,
        ..Default::default()
    }
}

fn source(source: NormalSource) -> aokit::NormalsSettings {
    aokit::NormalsSettings {
        source,
        ..Default::default()
    }
}

const DEPTH_SOURCES: [NormalSource; 3] = [
    NormalSource::DepthNaive,
    NormalSource::Depth3tap,
    NormalSource::Depth5tap,
];

/// `xy` mirrors normals with z < 0 to +z, off by twice their angle below the view plane: by
/// more than 1 degree below this z.
const XY_OFF_BY_A_DEGREE: f32 = -0.0087;

#[test]
fn every_encoding_renders_normals_and_ao_close_to_oct32s() {
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin] {
        let mut view = View::builtin(&gpu, builtin);
        for e in NormalEncoding::ALL {
            let difference = view.difference(&gpu, encoding(e));
            // Normals: within the encoding's worst rounding error on the hemisphere facing the
            // eye (docs/normals.md) plus oct32's (0.004), except where xy mirrors a normal
            // facing away from the view axis. AO: the slice methods' nearest read puts each
            // sample at its texel's height above the pixel's tangent plane, so the normal's
            // rounding reaches the AO about three times as strongly as through the interpolated
            // read, whose bounds these were (0.003 for oct16, 0.001 for the others): measured
            // worst, on the stairs, oct16 0.0060, oct20 0.0029, oct24 and rgb10a2 0.0028,
            // rgba16f 0.0011.
            let (worst_rounding, ao_bound) = match e {
                NormalEncoding::Oct16 => (0.95, 0.009),
                NormalEncoding::Oct20 => (0.24, 0.004),
                NormalEncoding::Oct24 => (0.06, 0.004),
                NormalEncoding::Rgb10a2 => (0.1, 0.004),
                NormalEncoding::Rgba16f => (0.023, 0.002),
                // Mirrored normals on the stairs' risers move the AO visibly.
                NormalEncoding::Xy => (0.34, 0.03),
                NormalEncoding::Oct32
                | NormalEncoding::Spherical
                | NormalEncoding::Stereographic
                | NormalEncoding::Lambert => (0.01, 0.001),
            };
            let worst = difference
                .pixels
                .iter()
                .filter(|p| e != NormalEncoding::Xy || p.z >= 0.0)
                .map(|p| p.angle)
                .fold(0.0, f64::max);
            let mirrored_elsewhere = difference
                .pixels
                .iter()
                .filter(|p| p.angle > 1.0 && p.z >= XY_OFF_BY_A_DEGREE)
                .count();
            assert!(
                worst <= worst_rounding + 0.004 && mirrored_elsewhere == 0,
                "{} with {e:?}: normals off by up to {worst} degrees; {mirrored_elsewhere} \
                 off by over a degree that xy would not mirror",
                view.name()
            );
            assert!(
                difference.ao_rmse <= ao_bound,
                "{} with {e:?}: AO differs from oct32's by an RMSE of {}",
                view.name(),
                difference.ao_rmse
            );
        }
    }
}

#[test]
fn normals_from_depth_match_the_gbuffer_away_from_depth_edges_best_with_five_taps() {
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin, Builtin::Open] {
        let mut view = View::builtin(&gpu, builtin);
        let means = DEPTH_SOURCES.map(|s| {
            let inner = view.difference(&gpu, source(s)).angles(Some(false));
            let (mean, p90) = (mean(&inner), quantile(&inner, 0.9));
            // Planes come out exact but for rounding, so 90% of the pixels are within a
            // hundredth of a degree. The mean is that of the pixels the edge mask misses:
            // creases (the stairs' steps), where depth is continuous but the naive and 3-tap
            // reconstructions take a tangent across, and the room's sphere.
            let mean_bound = match s {
                NormalSource::Depth5tap => 0.15,
                _ => 3.0,
            };
            assert!(
                mean <= mean_bound && p90 <= 0.01,
                "{} with {s:?}: away from edges the normals are off by {mean} degrees on \
                 average, {p90} at the 90th percentile",
                view.name()
            );
            mean
        });
        // The fallback of `buffer` without a normal texture must be the best.
        assert!(
            means[2] <= means[0] && means[2] <= means[1],
            "{}: mean errors {means:?} (naive, 3-tap, 5-tap)",
            view.name()
        );
    }
}

#[test]
#[ignore = "prints the tables of docs/normals.md; run with --release --ignored --nocapture"]
fn measure_for_docs() {
    let gpu = gpu();
    let sponza = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/sponza.obj");
    // The views and size of the `aokit compare` runs in docs/normals.md.
    let mut views: Vec<View> = ["room", "stairs", "thin"]
        .into_iter()
        .map(|name| View::new(&gpu, Scene::open(name).unwrap(), None, [480, 270]))
        .collect();
    views.push(View::new(
        &gpu,
        Scene::open(sponza.to_str().unwrap()).unwrap(),
        Some("atrium"),
        [480, 270],
    ));

    println!("\nVisible normals facing away from the view axis (z < 0):\n");
    println!("| view | z < 0 | xy off by > 1 degree | lowest z |");
    println!("|---|---:|---:|---:|");
    for view in &views {
        let z: Vec<f32> = view
            .surface()
            .iter()
            .map(|&(i, _)| view.base.normals[i].z)
            .collect();
        let fraction =
            |below: f32| z.iter().filter(|&&z| z < below).count() as f64 / z.len() as f64;
        println!(
            "| {} | {:.4} | {:.4} | {:.3} |",
            view.name(),
            fraction(0.0),
            fraction(XY_OFF_BY_A_DEGREE),
            z.iter().copied().fold(1.0, f32::min)
        );
    }

    println!("\nEncodings against oct32 (normal error in degrees, AO RMSE):\n");
    println!("| encoding | view | mean normal error | max normal error | AO RMSE vs oct32 |");
    println!("|---|---|---:|---:|---:|");
    for e in NormalEncoding::ALL {
        for view in &mut views {
            let difference = view.difference(&gpu, encoding(e));
            let angles = difference.angles(None);
            println!(
                "| `{}` | {} | {:.4} | {:.3} | {:.5} |",
                e.name(),
                view.name(),
                mean(&angles),
                angles.iter().copied().fold(0.0, f64::max),
                difference.ao_rmse
            );
        }
    }

    println!("\nNormals from depth against the G-buffer's (degrees; AO RMSE):\n");
    println!(
        "| source | view | mean | 95th percentile | mean at edges | AO RMSE vs G-buffer normals |"
    );
    println!("|---|---|---:|---:|---:|---:|");
    for s in DEPTH_SOURCES {
        for view in &mut views {
            let difference = view.difference(&gpu, source(s));
            let inner = difference.angles(Some(false));
            println!(
                "| `{}` | {} | {:.3} | {:.3} | {:.2} | {:.4} |",
                s.name(),
                view.name(),
                mean(&inner),
                quantile(&inner, 0.95),
                mean(&difference.angles(Some(true))),
                difference.ao_rmse
            );
        }
    }
}
