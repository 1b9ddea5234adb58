//! Rays against a triangle mesh through a bounding volume hierarchy.

use std::time::Duration;

use glam::{Vec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray, RayHit};
use obvhs::triangle::Triangle;

use crate::ReferenceError;
use crate::watertight::Shear;

/// The closest surface along a ray.
///
/// ```
/// use aokit_reference::{AoOptions, PixelSampler, Tracer};
/// use glam::Vec3;
/// let floor = [Vec3::new(-9.0, 0.0, -9.0), Vec3::new(9.0, 0.0, -9.0),
///              Vec3::new(9.0, 0.0, 9.0), Vec3::new(-9.0, 0.0, 9.0)];
/// let tracer = Tracer::new(&floor, &[0, 1, 2, 0, 2, 3])?;
/// let (eye, target) = (Vec3::new(0.0, 2.0, 3.0), Vec3::new(1.0, 0.0, -2.0));
/// let hit = tracer.closest_hit(eye, (target - eye).normalize(), 0.0, f32::INFINITY).unwrap();
/// // AO is taken where the primary ray lands, about the normal facing the eye.
/// assert!(hit.point.distance(target) < 1e-5 && hit.normal == Vec3::Y);
/// let ao = tracer.ambient_occlusion(hit.point, hit.normal, &AoOptions::default(),
///                                   &PixelSampler::new(0, 0));
/// assert_eq!(ao, 1.0);
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the (unit) ray direction.
    pub t: f32,
    /// The hit point, stepped along the ray and then moved onto the triangle's plane, so that
    /// it lies on the surface to single precision however far the ray travelled.
    pub point: Vec3,
    /// Unit geometric normal, turned to face the ray's origin.
    pub normal: Vec3,
}

/// A triangle mesh ready for ray queries.
///
/// ```
/// use aokit_reference::Tracer;
/// use glam::Vec3;
/// let quad = [Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, -1.0),
///             Vec3::new(1.0, 0.0, 1.0), Vec3::new(-1.0, 0.0, 1.0)];
/// let tracer = Tracer::new(&quad, &[0, 2, 1, 0, 3, 2])?;
/// let hit = tracer.closest_hit(Vec3::new(0.2, 3.0, 0.1), Vec3::NEG_Y, 0.0, f32::INFINITY).unwrap();
/// assert!((hit.t - 3.0).abs() < 1e-6 && hit.normal == Vec3::Y);
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
pub struct Tracer {
    bvh: CwBvh,
    /// Triangles in the BVH's leaf order, so a leaf index needs no indirection.
    triangles: Vec<Triangle>,
}

impl Tracer {
    /// Builds the hierarchy over the triangles of an indexed list. Triangles of zero area are
    /// dropped: they cannot block a ray.
    ///
    /// ```
    /// use aokit_reference::{ReferenceError, Tracer};
    /// use glam::Vec3;
    /// let positions = [Vec3::ZERO, Vec3::X, Vec3::Y];
    /// // The second triangle repeats a vertex: it has no area.
    /// let tracer = Tracer::new(&positions, &[0, 1, 2, 0, 0, 1])?;
    /// assert_eq!(tracer.triangle_count(), 1);
    /// let bad = Tracer::new(&positions, &[0, 1, 3]);
    /// assert!(matches!(bad, Err(ReferenceError::Index { index: 3, .. })));
    /// # Ok::<(), ReferenceError>(())
    /// ```
    pub fn new(positions: &[Vec3], indices: &[u32]) -> Result<Self, ReferenceError> {
        if !indices.len().is_multiple_of(3) {
            return Err(ReferenceError::PartialTriangle(indices.len()));
        }
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            return Err(ReferenceError::NonFinite(i));
        }
        let mut triangles = Vec::with_capacity(indices.len() / 3);
        for (triangle, corners) in indices.chunks_exact(3).enumerate() {
            let vertex = |index: u32| {
                positions
                    .get(index as usize)
                    .map(|&p| Vec3A::from(p))
                    .ok_or(ReferenceError::Index {
                        triangle,
                        index,
                        vertices: positions.len(),
                    })
            };
            let tri = Triangle {
                v0: vertex(corners[0])?,
                v1: vertex(corners[1])?,
                v2: vertex(corners[2])?,
            };
            if (tri.v1 - tri.v0).cross(tri.v2 - tri.v0).length_squared() > 0.0 {
                triangles.push(tri);
            }
        }
        if triangles.is_empty() {
            return Err(ReferenceError::Empty);
        }
        let bvh = build_cwbvh_from_tris(
            &triangles,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        let triangles = bvh
            .primitive_indices
            .iter()
            .map(|&i| triangles[i as usize])
            .collect();
        Ok(Self { bvh, triangles })
    }

    /// Number of triangles traced (after dropping degenerate ones, before any splitting).
    ///
    /// ```
    /// use aokit_reference::Tracer;
    /// use glam::Vec3;
    /// let quad = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    /// let tracer = Tracer::new(&quad, &[0, 1, 2, 0, 2, 3])?;
    /// println!("tracing {} triangles", tracer.triangle_count());
    /// assert_eq!(tracer.triangle_count(), 2);
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The closest surface along `origin + t * direction` with `t` in `[t_min, t_max]`.
    /// `direction` must be a unit vector.
    ///
    /// ```
    /// use aokit_reference::Tracer;
    /// use glam::Vec3;
    /// // Two walls facing each other along z.
    /// let wall = |z: f32| {
    ///     [Vec3::new(-1.0, -1.0, z), Vec3::new(1.0, -1.0, z), Vec3::new(0.0, 1.0, z)]
    /// };
    /// let tracer = Tracer::new(&[wall(0.0), wall(-2.0)].concat(), &[0, 1, 2, 3, 4, 5])?;
    /// let origin = Vec3::new(0.0, 0.0, 1.0);
    /// let first = tracer.closest_hit(origin, Vec3::NEG_Z, 0.0, f32::INFINITY).unwrap();
    /// assert_eq!(first.t, 1.0);
    /// // A near plane at t = 2 skips the first wall.
    /// let behind = tracer.closest_hit(origin, Vec3::NEG_Z, 2.0, f32::INFINITY).unwrap();
    /// assert_eq!(behind.t, 3.0);
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn closest_hit(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
    ) -> Option<Hit> {
        let ray = Ray::new(origin.into(), direction.into(), t_min, t_max);
        let shear = Shear::new(origin, direction);
        let mut hit = RayHit::none();
        if !self.bvh.ray_traverse(ray, &mut hit, |ray, i| {
            shear.intersect(&self.triangles[i], ray)
        }) {
            return None;
        }
        let tri = &self.triangles[hit.primitive_id as usize];
        let normal = Vec3::from(tri.compute_normal());
        let stepped = origin + hit.t * direction;
        let point = stepped - normal * normal.dot(stepped - Vec3::from(tri.v0));
        let normal = if normal.dot(direction) > 0.0 {
            -normal
        } else {
            normal
        };
        Some(Hit {
            t: hit.t,
            point,
            normal,
        })
    }

    /// Distance to the closest back face along `origin + t * direction` with `t` in
    /// `[t_min, t_max]`: the closest triangle whose front side (counter-clockwise winding, as
    /// a rasteriser sees it by default) faces away from the ray, the surface a rasteriser
    /// culling front faces keeps. `direction` must be a unit vector.
    ///
    /// ```
    /// use aokit_reference::Tracer;
    /// use glam::Vec3;
    /// // A slab one unit thick: its top faces +y, its bottom -y.
    /// let quad = |y: f32, up: bool| {
    ///     let q = [Vec3::new(-5.0, y, -5.0), Vec3::new(5.0, y, -5.0),
    ///              Vec3::new(5.0, y, 5.0), Vec3::new(-5.0, y, 5.0)];
    ///     if up { [q[0], q[2], q[1]] } else { [q[0], q[1], q[2]] }
    /// };
    /// let tracer = Tracer::new(&[quad(1.0, true), quad(0.0, false)].concat(),
    ///                          &[0, 1, 2, 3, 4, 5])?;
    /// let down = Vec3::NEG_Y;
    /// let origin = Vec3::new(1.0, 3.0, -1.0);
    /// assert_eq!(tracer.closest_hit(origin, down, 0.0, f32::INFINITY).unwrap().t, 2.0);
    /// assert_eq!(tracer.closest_back_face(origin, down, 0.0, f32::INFINITY), Some(3.0));
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn closest_back_face(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
    ) -> Option<f32> {
        let ray = Ray::new(origin.into(), direction.into(), t_min, t_max);
        let shear = Shear::new(origin, direction);
        let toward = Vec3A::from(direction);
        let mut hit = RayHit::none();
        self.bvh
            .ray_traverse(ray, &mut hit, |ray, i| {
                let triangle = &self.triangles[i];
                let normal = (triangle.v1 - triangle.v0).cross(triangle.v2 - triangle.v0);
                if normal.dot(toward) > 0.0 {
                    shear.intersect(triangle, ray)
                } else {
                    f32::INFINITY
                }
            })
            .then_some(hit.t)
    }

    /// Distance to the first surface within `t_max` along the unit `direction`, or `None`.
    ///
    /// ```
    /// use aokit_reference::Tracer;
    /// use glam::Vec3;
    /// let ceiling = [Vec3::new(-5.0, 2.0, -5.0), Vec3::new(5.0, 2.0, -5.0),
    ///                Vec3::new(0.0, 2.0, 5.0)];
    /// let tracer = Tracer::new(&ceiling, &[0, 1, 2])?;
    /// // For obscurance, where how far the occluder is matters, not only whether there is one.
    /// assert_eq!(tracer.hit_distance(Vec3::ZERO, Vec3::Y, 3.0), Some(2.0));
    /// assert_eq!(tracer.hit_distance(Vec3::ZERO, Vec3::Y, 1.0), None);
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn hit_distance(&self, origin: Vec3, direction: Vec3, t_max: f32) -> Option<f32> {
        let ray = Ray::new(origin.into(), direction.into(), 0.0, t_max);
        let shear = Shear::new(origin, direction);
        let mut hit = RayHit::none();
        self.bvh
            .ray_traverse(ray, &mut hit, |ray, i| {
                shear.intersect(&self.triangles[i], ray)
            })
            .then_some(hit.t)
    }

    /// Whether anything lies within `t_max` along the unit `direction`: stops at the first
    /// surface found, which is cheaper than the closest.
    ///
    /// ```
    /// use aokit_reference::Tracer;
    /// use glam::Vec3;
    /// let ceiling = [Vec3::new(-5.0, 2.0, -5.0), Vec3::new(5.0, 2.0, -5.0),
    ///                Vec3::new(0.0, 2.0, 5.0)];
    /// let tracer = Tracer::new(&ceiling, &[0, 1, 2])?;
    /// assert!(tracer.occluded(Vec3::ZERO, Vec3::Y, 3.0));
    /// // Occluders beyond the AO radius do not count.
    /// assert!(!tracer.occluded(Vec3::ZERO, Vec3::Y, 1.5));
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn occluded(&self, origin: Vec3, direction: Vec3, t_max: f32) -> bool {
        let ray = Ray::new(origin.into(), direction.into(), 0.0, t_max);
        let shear = Shear::new(origin, direction);
        !self
            .bvh
            .ray_traverse_miss(ray, |ray, i| shear.intersect(&self.triangles[i], ray))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_meshes_are_refused_with_the_reason() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let err = |r: Result<Tracer, ReferenceError>| r.err().unwrap().to_string();
        assert!(err(Tracer::new(&p, &[0, 1])).contains("whole triangles"));
        assert!(err(Tracer::new(&p, &[0, 1, 7])).contains("vertex 7"));
        assert!(err(Tracer::new(&p, &[0, 1, 1])).contains("non-zero area"));
        let nan = [Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 0.0), Vec3::Y];
        assert!(err(Tracer::new(&nan, &[0, 1, 2])).contains("vertex 1"));
    }

    #[test]
    fn closest_hit_picks_the_nearer_of_two_triangles_facing_the_ray() {
        let p = [
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(-1.0, -1.0, -2.0),
            Vec3::new(1.0, -1.0, -2.0),
            Vec3::new(0.0, 1.0, -2.0),
        ];
        let tracer = Tracer::new(&p, &[3, 4, 5, 0, 1, 2]).unwrap();
        let hit = tracer
            .closest_hit(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z, 0.0, f32::INFINITY)
            .unwrap();
        assert_eq!(hit.t, 5.0);
        assert_eq!(hit.normal, Vec3::Z);
        assert_eq!(hit.point, Vec3::ZERO);
        // From behind, the normal turns to face the ray.
        let back = tracer
            .closest_hit(Vec3::new(0.0, 0.0, -5.0), Vec3::Z, 0.0, f32::INFINITY)
            .unwrap();
        assert_eq!(back.normal, Vec3::NEG_Z);
        assert_eq!(
            tracer.hit_distance(Vec3::new(0.0, 0.0, 1.0), Vec3::NEG_Z, 10.0),
            Some(1.0)
        );
        assert!(tracer.occluded(Vec3::new(0.0, 0.0, 1.0), Vec3::NEG_Z, 1.5));
        assert!(!tracer.occluded(Vec3::new(0.0, 0.0, 1.0), Vec3::NEG_Z, 0.5));
        // t_min skips the first triangle, as a near plane would.
        let far = tracer
            .closest_hit(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z, 6.0, f32::INFINITY)
            .unwrap();
        assert_eq!(far.t, 7.0);
    }
}
