//! Moving a ray's origin off the surface it starts on.

use glam::Vec3;

/// Below this magnitude a coordinate's float spacing is so fine that a fixed step is used.
const NEAR_ORIGIN: f32 = 1.0 / 32.0;
/// The fixed step near the origin, in world units.
const FIXED_STEP: f32 = 1.0 / 65536.0;
/// The step elsewhere, in units in the last place of each coordinate.
const ULP_STEP: f32 = 256.0;

/// `point` moved off its surface along the geometric normal `normal`, far enough that a ray
/// leaving it does not hit the surface again through rounding, and close enough that contact in
/// corners is kept. The step is a fixed number of float spacings of each coordinate, so it scales
/// with the coordinate's magnitude (Wächter and Binder, "A Fast and Robust Method for Avoiding
/// Self-Intersection", Ray Tracing Gems, 2019, whose three constants these are).
///
/// ```
/// use aokit_reference::{Tracer, offset_origin};
/// use glam::Vec3;
/// let floor = [Vec3::new(-1e3, 0.0, -1e3), Vec3::new(1e3, 0.0, -1e3),
///              Vec3::new(1e3, 0.0, 1e3), Vec3::new(-1e3, 0.0, 1e3)];
/// let tracer = Tracer::new(&floor, &[0, 1, 2, 0, 2, 3])?;
/// // A hit far from the origin: its position is only as precise as its large coordinates.
/// let hit = tracer.closest_hit(Vec3::new(700.3, 5.0, -411.7), Vec3::NEG_Y, 0.0, 10.0).unwrap();
/// let origin = offset_origin(hit.point, hit.normal);
/// assert!(origin.y > 0.0);
/// // A ray leaving along the surface no longer finds the surface it starts on.
/// let along = Vec3::new(1.0, 1e-4, 0.0).normalize();
/// assert!(!tracer.occluded(origin, along, 1.0));
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
pub fn offset_origin(point: Vec3, normal: Vec3) -> Vec3 {
    let nudge = |p: f32, n: f32| {
        if p.abs() < NEAR_ORIGIN {
            return p + FIXED_STEP * n;
        }
        let ulps = (ULP_STEP * n) as i32;
        // Moving away from zero grows the magnitude bits; toward zero shrinks them.
        let ulps = if p < 0.0 { -ulps } else { ulps };
        f32::from_bits((p.to_bits() as i32).wrapping_add(ulps) as u32)
    };
    Vec3::new(
        nudge(point.x, normal.x),
        nudge(point.y, normal.y),
        nudge(point.z, normal.z),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_move_to_the_normal_side_by_a_small_relative_step() {
        for p in [Vec3::ZERO, Vec3::new(1000.0, -3.0, 0.01), Vec3::splat(-1e5)] {
            for n in [Vec3::Y, -Vec3::X, Vec3::new(0.6, 0.0, -0.8)] {
                let q = offset_origin(p, n);
                let moved = (q - p).dot(n);
                assert!(moved > 0.0, "{p} {n}");
                assert!(
                    (q - p).length() <= 1e-4 * p.length().max(1.0),
                    "{p} {n} -> {q}"
                );
            }
        }
    }
}
