//! Watertight ray/triangle intersection (Woop, Benthin and Wald 2013, "Watertight Ray/Triangle
//! Intersection", JCGT 2(1)). A ray that lands exactly on the edge two triangles share hits one
//! of them: pixel-centre rays of symmetric views fall on the diagonals of quads, and AO rays
//! from points on a mesh graze its edges.
//!
//! The triangle is moved into a frame where the ray runs along +z from the origin (a
//! translation and a shear, no division per triangle), and the ray passes through it when the
//! three 2D edge functions about the origin share a sign; the distance then comes from the
//! triangle's plane. The edge functions of a shared edge
//! are computed from the same two vertices in the same order whichever triangle asks, so the
//! two triangles cannot both miss; an edge function of exactly zero is recomputed in double
//! precision, where single precision could have rounded a hit to the edge.

use glam::{DVec2, Vec3, Vec3A};
use obvhs::ray::Ray;
use obvhs::triangle::Triangle;

/// A ray's shear into the frame where it runs along +z: computed once per ray.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shear {
    origin: Vec3A,
    direction: Vec3,
    /// The axis the ray is most aligned with (the new z), and the other two (new x and y),
    /// ordered so that the frame keeps its handedness.
    kz: usize,
    kx: usize,
    ky: usize,
    /// direction[kx] / direction[kz] and direction[ky] / direction[kz].
    sx: f32,
    sy: f32,
}

impl Shear {
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        let abs = direction.abs();
        let kz = if abs.x > abs.y && abs.x > abs.z {
            0
        } else if abs.y > abs.z {
            1
        } else {
            2
        };
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        if direction[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        Self {
            origin: origin.into(),
            direction,
            kz,
            kx,
            ky,
            sx: direction[kx] / direction[kz],
            sy: direction[ky] / direction[kz],
        }
    }

    /// Distance along the ray to `triangle`, within the ray's `[tmin, tmax]`, or infinity.
    /// Both faces count.
    pub fn intersect(&self, triangle: &Triangle, ray: &Ray) -> f32 {
        let (kx, ky, kz) = (self.kx, self.ky, self.kz);
        let a = triangle.v0 - self.origin;
        let b = triangle.v1 - self.origin;
        let c = triangle.v2 - self.origin;
        // The vertices sheared so that the ray is the +z axis through the origin.
        let sheared = |p: Vec3A| (p[kx] - self.sx * p[kz], p[ky] - self.sy * p[kz]);
        let (ax, ay) = sheared(a);
        let (bx, by) = sheared(b);
        let (cx, cy) = sheared(c);
        // Twice the signed areas the origin makes with each edge.
        let edge = |(px, py): (f32, f32), (qx, qy): (f32, f32)| {
            let e = px * qy - py * qx;
            if e == 0.0 {
                let (p, q) = (
                    DVec2::new(f64::from(px), f64::from(py)),
                    DVec2::new(f64::from(qx), f64::from(qy)),
                );
                (p.x * q.y - p.y * q.x) as f32
            } else {
                e
            }
        };
        let u = edge((cx, cy), (bx, by));
        let v = edge((ax, ay), (cx, cy));
        let w = edge((bx, by), (ax, ay));
        if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
            return f32::INFINITY;
        }
        if u + v + w == 0.0 {
            return f32::INFINITY;
        }
        // The distance from the plane, as Möller and Trumbore take it, rather than from the
        // sheared z the paper interpolates: that sums terms as large as the triangle, and on a
        // plane 10^4 wide it misplaces a point 10^-6 above it to the other side.
        let normal = (triangle.v1 - triangle.v0).cross(triangle.v2 - triangle.v0);
        let t = normal.dot(a) / normal.dot(Vec3A::from(self.direction));
        if t >= ray.tmin && t <= ray.tmax {
            t
        } else {
            f32::INFINITY
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle(v: [Vec3; 3]) -> Triangle {
        Triangle {
            v0: v[0].into(),
            v1: v[1].into(),
            v2: v[2].into(),
        }
    }

    fn cast(origin: Vec3, direction: Vec3, t: &Triangle) -> f32 {
        let ray = Ray::new(origin.into(), direction.into(), 0.0, f32::INFINITY);
        Shear::new(origin, direction).intersect(t, &ray)
    }

    #[test]
    fn rays_on_a_shared_edge_hit_one_of_its_triangles() {
        // A unit quad split along its diagonal, in both windings and every orientation.
        let corners = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 1.0),
            Vec3::new(0.0, 0.0, 1.0),
        ];
        for flip in [false, true] {
            let (first, second) = if flip {
                ([0, 2, 1], [0, 3, 2])
            } else {
                ([0, 1, 2], [0, 2, 3])
            };
            let tris = [
                triangle(first.map(|i| corners[i])),
                triangle(second.map(|i| corners[i])),
            ];
            for s in 1..20 {
                // Points inside the diagonal, from above, below and at a slant. (On the quad's
                // outer edges a slanted ray may round to either side: nothing lies beyond.)
                let f = s as f32 / 20.0;
                let point = Vec3::new(f, 0.0, f);
                for (origin, direction) in [
                    (point + Vec3::Y * 3.0, Vec3::NEG_Y),
                    (point - Vec3::Y * 2.0, Vec3::Y),
                    (
                        point + Vec3::new(0.3, 1.0, 0.2),
                        -Vec3::new(0.3, 1.0, 0.2).normalize(),
                    ),
                ] {
                    let hits: Vec<f32> = tris.iter().map(|t| cast(origin, direction, t)).collect();
                    assert!(
                        hits.iter().any(|t| t.is_finite()),
                        "{point} from {origin}: {hits:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn distances_match_the_geometry_and_misses_miss() {
        let t = triangle([
            Vec3::new(-1.0, -1.0, -2.0),
            Vec3::new(1.0, -1.0, -2.0),
            Vec3::new(0.0, 1.0, -2.0),
        ]);
        assert_eq!(cast(Vec3::ZERO, Vec3::NEG_Z, &t), 2.0);
        // From behind (both faces count).
        assert_eq!(cast(Vec3::new(0.0, 0.0, -5.0), Vec3::Z, &t), 3.0);
        assert_eq!(
            cast(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_Z, &t),
            f32::INFINITY
        );
        // Parallel to the triangle's plane.
        assert_eq!(cast(Vec3::new(0.0, 0.0, -2.0), Vec3::X, &t), f32::INFINITY);
        // Outside the ray's range.
        let short = Ray::new(Vec3A::ZERO, Vec3A::NEG_Z, 0.0, 1.5);
        assert_eq!(
            Shear::new(Vec3::ZERO, Vec3::NEG_Z).intersect(&t, &short),
            f32::INFINITY
        );
        let oblique = Vec3::new(0.1, 0.2, -1.0).normalize();
        let d = cast(Vec3::ZERO, oblique, &t);
        assert!(((oblique * d).z + 2.0).abs() < 1e-6, "{d}");
    }
}
