//! The G-buffer's motion vectors against their CPU expectation: where each pixel's surface point
//! was in the previous frame, for the camera's motion and a moving part's, on whatever adapter
//! exists (lavapipe in CI).

use aokit::projection::pixel_to_ndc;
use aokit::{AoSettings, GpuContext};
use aokit_scene::{Builtin, CameraPath, Frame, Renderer, Scene};
use glam::{Vec2, Vec3};

const SIZE: [u32; 2] = [160, 96];

/// Allowed difference between a motion vector and its expectation: the half float's rounding
/// (1/2048 of the offset) and the depth buffer's precision, which moves the unprojected point.
fn tolerance(expected: Vec2) -> f32 {
    0.02 + expected.length() / 1000.0
}

/// Two consecutive frames of `scene`'s first camera: at `times[0]` and `times[1]` of `path`,
/// with the moving parts at the same times when `animate`, else at rest.
fn two_frames(scene: &Scene, path: CameraPath, times: [f32; 2], animate: bool) -> [Frame; 2] {
    let gpu = GpuContext::headless().expect("tests need a wgpu adapter");
    let mut renderer = Renderer::new(&gpu, scene, &AoSettings::default()).unwrap();
    let camera = &scene.cameras[0];
    times.map(|t| {
        let time = if animate { t } else { 0.0 };
        renderer
            .render_at(&gpu, &path.at(camera, t), SIZE, 0, time)
            .unwrap()
    })
}

/// For each pixel of `frame` showing a surface, the offset in pixels from its centre to where
/// the previous frame's camera saw its surface point, which `before` takes from its world
/// position now to its world position then (`None` skips the pixel).
fn expected_motion(
    previous: &Frame,
    frame: &Frame,
    before: impl Fn(Vec3) -> Option<Vec3>,
) -> Vec<Option<Vec2>> {
    let size = Vec2::new(SIZE[0] as f32, SIZE[1] as f32);
    let world_from_view = frame.view_from_world.inverse();
    let previous_clip_from_world = previous.projection.clip_from_view() * previous.view_from_world;
    (0..SIZE[0] * SIZE[1])
        .map(|i| {
            let depth = frame.linear_depth[i as usize];
            if depth <= 0.0 {
                return None;
            }
            let pixel = Vec2::new((i % SIZE[0]) as f32, (i / SIZE[0]) as f32);
            let view = frame
                .projection
                .view_position_from_linear(pixel_to_ndc(pixel, size), depth);
            let then = before(world_from_view.transform_point3(view))?;
            let clip = previous_clip_from_world * then.extend(1.0);
            let ndc = Vec2::new(clip.x, clip.y) / clip.w;
            let at = Vec2::new(ndc.x + 1.0, 1.0 - ndc.y) * 0.5 * size;
            Some(at - (pixel + 0.5))
        })
        .collect()
}

/// Compares the frame's motion vectors with `expected` where it has a value, returning how many
/// pixels were compared and their mean expected length.
fn compare(frame: &Frame, expected: &[Option<Vec2>], what: &str) -> (usize, f32) {
    let (mut count, mut length, mut worst) = (0, 0.0, 0.0f32);
    for (i, (got, want)) in frame.motion_vectors.iter().zip(expected).enumerate() {
        let Some(want) = want else { continue };
        let error = (*got - *want).length();
        assert!(
            error <= tolerance(*want),
            "{what}: pixel {} of row {}: motion {got}, expected {want}",
            i % SIZE[0] as usize,
            i / SIZE[0] as usize
        );
        count += 1;
        length += want.length();
        worst = worst.max(error);
    }
    eprintln!(
        "{what}: {count} pixels, mean motion {:.3} px, largest error {worst:.5} px",
        length / count as f32
    );
    (count, length / count.max(1) as f32)
}

#[test]
fn a_still_scene_moves_with_the_camera() {
    let scene = Builtin::Stairs.build();
    for path in [CameraPath::Strafe, CameraPath::Orbit, CameraPath::Dolly] {
        let [previous, frame] = two_frames(&scene, path, [0.4, 0.5], false);
        let expected = expected_motion(&previous, &frame, Some);
        let (count, mean) = compare(&frame, &expected, path.name());
        assert!(count > 10_000, "{count} pixels compared");
        assert!(mean > 1.0, "{}: the camera barely moved", path.name());
    }
    // Nothing moves, nothing has motion: a still camera, or a sequence's first frame. What is
    // left is the raster's snapping of vertices to 1/256 of a pixel.
    let [first, still] = two_frames(&scene, CameraPath::Still, [0.0, 0.0], false);
    for frame in [&first, &still] {
        assert!(frame.motion_vectors.iter().all(|m| m.length() < 0.01));
    }
}

#[test]
fn a_moving_part_adds_its_own_motion_to_the_camera() {
    let scene = Builtin::Room.build();
    let times = [0.2, 0.6];
    let [previous, frame] = two_frames(&scene, CameraPath::Strafe, times, true);
    let sphere = &scene.moving_parts[0];
    let [then, now] = times.map(|t| sphere.motion.transform_at(t));
    let center = now.transform_point3(sphere.motion.pivot);
    // The sphere (radius 1) and everything else, told apart by the distance from its centre;
    // pixels of the floor where it touches are both, and are left out.
    let distance = |p: Vec3| (p.distance(center) - 1.0).abs();
    let on_sphere = |p: Vec3| distance(p) < 0.01 && p.y > 0.05;
    let sphere_now_to_then = then * now.inverse();
    let expected = expected_motion(&previous, &frame, |p| {
        on_sphere(p).then(|| sphere_now_to_then.transform_point3(p))
    });
    let (count, _) = compare(&frame, &expected, "rolling sphere, strafing camera");
    assert!(count > 300, "{count} sphere pixels compared");
    let camera_only = expected_motion(&previous, &frame, |p| on_sphere(p).then_some(p));
    let own: f32 = expected
        .iter()
        .zip(&camera_only)
        .filter_map(|(a, b)| Some((a.as_ref()? - b.as_ref()?).length()))
        .sum::<f32>()
        / count as f32;
    assert!(own > 2.0, "the sphere's own motion is {own} px");
    let still = expected_motion(&previous, &frame, |p| (distance(p) > 0.05).then_some(p));
    compare(&frame, &still, "static parts, strafing camera");
}
