//! The raster G-buffer and the reference tracer see the same scene through the same pixels, so
//! that an AO error measured later belongs to the method, not to the harness.

use std::path::Path;

use aokit::{AoSettings, GpuContext, Method, Preset};
use aokit_reference::{AoOptions, PixelCamera, Tracer};
use aokit_scene::{Builtin, Camera, Lens, Renderer, Scene, reference};

const SIZE: [u32; 2] = [192, 128];
/// Linear depth agreement required on every pixel.
const RELATIVE_DEPTH: f32 = 1e-4;
/// Rasterisers snap vertex positions to a sub-pixel grid (8 fractional bits in lavapipe and
/// most GPUs), which moves edges, and the depth of surfaces seen at grazing angles, by up to this
/// much. Where the raster's depth differs from the tracer's at the pixel centre, it must be a
/// depth the tracer sees within this distance of the centre, or a plane seen there carried that
/// distance further (the snapped triangle may reach past the true one's edge).
const SUBPIXEL: f64 = 1.0 / 256.0;

fn close(a: f32, b: f32) -> bool {
    (a - b).abs() <= RELATIVE_DEPTH * a.max(b)
}

/// Linear depth of the first surface through image point `(px, py)`, 0 for none.
fn depth_through(tracer: &Tracer, camera: &PixelCamera, px: f64, py: f64) -> f32 {
    let ray = camera.ray_through(px, py);
    tracer
        .closest_hit(ray.origin, ray.direction, ray.t_min, ray.t_max)
        .map_or(0.0, |hit| hit.t * ray.depth_per_t)
}

/// Linear depth of the first back face through image point `(px, py)`, 0 for none.
fn back_depth_through(tracer: &Tracer, camera: &PixelCamera, px: f64, py: f64) -> f32 {
    let ray = camera.ray_through(px, py);
    tracer
        .closest_back_face(ray.origin, ray.direction, ray.t_min, ray.t_max)
        .map_or(0.0, |t| t * ray.depth_per_t)
}

/// Checks the depths of `scene` at `time` of a sequence, seen by `camera`.
fn check_at(gpu: &GpuContext, scene: &Scene, camera: &Camera, time: f32) {
    let view = format!("{} / {} at time {time}", scene.name, camera.name);
    let mut renderer = Renderer::new(gpu, scene, &AoSettings::default()).unwrap();
    let frame = renderer.render_at(gpu, camera, SIZE, 0, time).unwrap();
    let tracer = reference::tracer_at(scene, time).unwrap();
    let pixel_camera = reference::pixel_camera(scene, camera, SIZE);
    // One AO ray per pixel: only the primary hits are compared.
    let options = AoOptions {
        spp: 1,
        ..Default::default()
    };
    let traced = tracer.render(&pixel_camera, &options, &|_| {}).unwrap();
    let covered = compare_depths(&view, &frame.linear_depth, &traced.linear_depth, |x, y| {
        depth_through(&tracer, &pixel_camera, x, y)
    });
    assert!(covered > 1000, "{view}: only {covered} pixels drawn");
}

/// Checks the raster's depth image against the traced one, pixel by pixel; `through(px, py)`
/// traces the depth through any point of the image. Returns how many pixels the raster drew.
fn compare_depths(
    view: &str,
    raster: &[f32],
    traced: &[f32],
    through: impl Fn(f64, f64) -> f32,
) -> usize {
    let (mut covered, mut subpixel) = (0, 0);
    for (i, (&raster, &ray)) in raster.iter().zip(traced).enumerate() {
        covered += usize::from(raster > 0.0);
        if close(raster, ray) {
            continue;
        }
        let (x, y) = (
            (i % SIZE[0] as usize) as f64 + 0.5,
            (i / SIZE[0] as usize) as f64 + 0.5,
        );
        let around: Vec<f32> = (0..8)
            .map(|k| {
                let angle = f64::from(k) * std::f64::consts::FRAC_PI_4;
                let (dy, dx) = angle.sin_cos();
                through(x + dx * SUBPIXEL, y + dy * SUBPIXEL)
            })
            .collect();
        let hits = around.iter().copied().filter(|&d| d > 0.0);
        let (lo, hi) = hits.fold((f32::INFINITY, 0.0f32), |(lo, hi), d| {
            (lo.min(d), hi.max(d))
        });
        // Over a circle of radius SUBPIXEL a plane's depth spans 2 * slope * SUBPIXEL; carried
        // SUBPIXEL further it moves by half that span.
        let reach = 0.5 * (hi - lo);
        let seen_nearby = around.iter().any(|&d| close(d, raster))
            || (raster > 0.0
                && lo - reach <= raster * (1.0 + RELATIVE_DEPTH)
                && raster * (1.0 - RELATIVE_DEPTH) <= hi + reach);
        assert!(
            seen_nearby,
            "{view}: pixel ({x}, {y}) raster depth {raster}, traced {ray}, \
             traced {SUBPIXEL} px around it {around:?}"
        );
        subpixel += 1;
    }
    eprintln!("{view}: {covered} pixels drawn, {subpixel} differ within sub-pixel snapping");
    assert!(
        subpixel * 1000 <= covered,
        "{view}: {subpixel} pixels differ"
    );
    covered
}

fn check(gpu: &GpuContext, scene: &Scene, camera: &Camera) {
    check_at(gpu, scene, camera, 0.0);
}

#[test]
fn raster_and_tracer_agree_on_depth_in_every_builtin_view() {
    let gpu = GpuContext::headless().unwrap();
    for builtin in Builtin::ALL {
        let scene = builtin.build();
        for camera in &scene.cameras {
            check(&gpu, &scene, camera);
        }
    }
}

#[test]
fn raster_and_tracer_agree_on_depth_for_orthographic_and_standard_z_cameras() {
    let gpu = GpuContext::headless().unwrap();
    let scene = Builtin::Room.build();
    let base = scene.cameras[0].clone();
    for camera in [
        // Standard-Z float depth loses precision as (depth / near); a near plane of 0.5 keeps
        // it within the tolerance, as a renderer using standard Z would choose.
        Camera {
            name: "standard-z".into(),
            reverse_z: false,
            near: Some(0.5),
            far: Some(60.0),
            ..base.clone()
        },
        Camera {
            name: "orthographic".into(),
            lens: Lens::Orthographic { height: 8.0 },
            ..base.clone()
        },
    ] {
        check(&gpu, &scene, &camera);
    }
}

#[test]
fn raster_and_tracer_agree_on_depth_while_parts_move() {
    let gpu = GpuContext::headless().unwrap();
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin] {
        let scene = builtin.build();
        let camera = &scene.cameras[0];
        check_at(&gpu, &scene, camera, 1.0);
        // The check can tell: the parts at rest are somewhere else, seen by many pixels.
        let moved = reference::tracer_at(&scene, 1.0).unwrap();
        let rest = reference::tracer(&scene).unwrap();
        let pixels = reference::pixel_camera(&scene, camera, SIZE);
        let differ = (0..SIZE[0] * SIZE[1])
            .filter(|i| {
                let (x, y) = (f64::from(i % SIZE[0]) + 0.5, f64::from(i / SIZE[0]) + 0.5);
                !close(
                    depth_through(&moved, &pixels, x, y),
                    depth_through(&rest, &pixels, x, y),
                )
            })
            .count();
        assert!(differ > 200, "{}: {differ} pixels moved", scene.name);
    }
}

#[test]
fn raster_and_tracer_agree_on_depth_in_sponza() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/sponza.obj");
    let scene = Scene::open(path.to_str().unwrap()).unwrap();
    let gpu = GpuContext::headless().unwrap();
    for camera in &scene.cameras {
        check(&gpu, &scene, camera);
    }
    let covered = check_back_faces(&gpu, &scene);
    assert!(covered > 20_000, "only {covered} back-face pixels drawn");
}

/// Checks the back faces' depth of `scene` through each of its cameras; returns how many
/// pixels the raster drew.
fn check_back_faces(gpu: &GpuContext, scene: &Scene) -> usize {
    // The renderer draws the back faces for VBAO measuring its occluders from them.
    let settings = AoSettings::preset_with_back_faces(Method::Vbao, Preset::High);
    let tracer = reference::tracer(scene).unwrap();
    let mut covered = 0;
    for camera in &scene.cameras {
        let view = format!("{} / {} back faces", scene.name, camera.name);
        let mut renderer = Renderer::new(gpu, scene, &settings).unwrap();
        let frame = renderer.render(gpu, camera, SIZE, 0).unwrap();
        let pixel_camera = reference::pixel_camera(scene, camera, SIZE);
        let traced = tracer.back_depth(&pixel_camera).unwrap();
        covered += compare_depths(&view, &frame.back_depth.unwrap(), &traced, |x, y| {
            back_depth_through(&tracer, &pixel_camera, x, y)
        });
    }
    covered
}

#[test]
fn raster_and_tracer_agree_on_back_face_depth_in_every_builtin_view() {
    let gpu = GpuContext::headless().unwrap();
    let covered: usize = Builtin::ALL
        .iter()
        .map(|builtin| check_back_faces(&gpu, &builtin.build()))
        .sum();
    // Most views see the insides of closed solids' far walls behind their front ones.
    assert!(covered > 20_000, "only {covered} back-face pixels drawn");
}
