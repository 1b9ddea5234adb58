//! Primitive builders for the built-in scenes.

use glam::{Mat4, Quat, Vec3};

use crate::mesh::Mesh;

/// A parallelogram from `corner` spanned by `u` and `v`; its front faces `u x v`.
///
/// ```
/// use aokit_scene::shapes::quad;
/// use glam::Vec3;
/// // A 4 m wall along x, 3 m high, facing +z.
/// let wall = quad(Vec3::new(-2.0, 0.0, 0.0), 4.0 * Vec3::X, 3.0 * Vec3::Y, Vec3::splat(0.75));
/// assert!(wall.normals.iter().all(|&n| n == Vec3::Z));
/// assert_eq!(wall.triangle_count(), 2);
/// ```
pub fn quad(corner: Vec3, u: Vec3, v: Vec3, albedo: Vec3) -> Mesh {
    let normal = u.cross(v).normalize();
    Mesh {
        positions: vec![corner, corner + u, corner + u + v, corner + v],
        normals: vec![normal; 4],
        albedo: vec![albedo; 4],
        indices: vec![0, 1, 2, 0, 2, 3],
    }
}

/// A box with flat faces, given by its minimum corner and size, turned `yaw_degrees` about the
/// vertical axis through its centre.
///
/// ```
/// use aokit_scene::shapes::cuboid;
/// use glam::Vec3;
/// // A crate 1 m on a side on the floor, turned 30 degrees.
/// let wood = Vec3::new(0.55, 0.38, 0.24);
/// let crate_box = cuboid(Vec3::new(-0.5, 0.0, -0.5), Vec3::ONE, 30.0, wood);
/// let bounds = crate_box.bounds().unwrap();
/// // Turning about the vertical axis keeps it standing on the floor.
/// assert!(bounds.min.y.abs() < 1e-6 && (bounds.max.y - 1.0).abs() < 1e-6);
/// ```
pub fn cuboid(min: Vec3, size: Vec3, yaw_degrees: f32, albedo: Vec3) -> Mesh {
    let half = 0.5 * size;
    let mut local = Mesh::default();
    for axis in 0..3 {
        let (e_u, e_v) = (Vec3::AXES[(axis + 1) % 3], Vec3::AXES[(axis + 2) % 3]);
        let e_n = Vec3::AXES[axis];
        for sign in [1.0f32, -1.0] {
            // Swapping the edges for the negative face keeps u x v pointing outwards.
            let (u, v) = if sign > 0.0 { (e_u, e_v) } else { (e_v, e_u) };
            let (u, v) = (u * 2.0 * half.dot(u), v * 2.0 * half.dot(v));
            let corner = e_n * sign * half.dot(e_n) - 0.5 * (u + v);
            local.append(&quad(corner, u, v, albedo));
        }
    }
    let mut mesh = Mesh::default();
    let transform = Mat4::from_rotation_translation(
        Quat::from_rotation_y(yaw_degrees.to_radians()),
        min + half,
    );
    mesh.append_transformed(&local, transform);
    mesh
}

/// A UV sphere with smooth normals, fine enough that its facets stay under a pixel of depth
/// error at the sizes the built-in scenes show it.
///
/// ```
/// use aokit_scene::shapes::sphere;
/// use glam::Vec3;
/// let centre = Vec3::new(0.0, 0.5, 0.0);
/// let ball = sphere(centre, 0.5, Vec3::ONE);
/// // Smooth shading: each normal points away from the centre.
/// for (p, n) in ball.positions.iter().zip(&ball.normals) {
///     assert!(((*p - centre) * 2.0 - *n).length() < 1e-5);
/// }
/// ```
pub fn sphere(center: Vec3, radius: f32, albedo: Vec3) -> Mesh {
    const SEGMENTS: u32 = 96;
    const RINGS: u32 = 48;
    let mut mesh = Mesh::default();
    for ring in 0..=RINGS {
        let theta = std::f32::consts::PI * ring as f32 / RINGS as f32;
        for segment in 0..=SEGMENTS {
            let phi = std::f32::consts::TAU * segment as f32 / SEGMENTS as f32;
            let n = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                -theta.sin() * phi.sin(),
            );
            mesh.positions.push(center + radius * n);
            mesh.normals.push(n);
            mesh.albedo.push(albedo);
        }
    }
    let row = SEGMENTS + 1;
    for ring in 0..RINGS {
        for segment in 0..SEGMENTS {
            let a = ring * row + segment;
            let (b, c, d) = (a + row, a + row + 1, a + 1);
            mesh.indices.extend([a, b, c, a, c, d]);
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every triangle's winding must agree with its vertex normals.
    fn assert_front_faces_outwards(mesh: &Mesh) {
        for tri in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [0, 1, 2].map(|i| mesh.positions[tri[i] as usize]);
            let geometric = (b - a).cross(c - a);
            if geometric.length() < 1e-6 {
                continue; // pole triangles of the sphere are degenerate
            }
            assert!(
                geometric.dot(mesh.normals[tri[0] as usize]) > 0.0,
                "{tri:?} {a} {b} {c} {geometric}"
            );
        }
    }

    #[test]
    fn cuboid_faces_point_outwards_and_fill_its_bounds() {
        let mesh = cuboid(
            Vec3::new(1.0, 0.0, -2.0),
            Vec3::new(2.0, 1.0, 0.5),
            0.0,
            Vec3::ONE,
        );
        assert_front_faces_outwards(&mesh);
        let bounds = mesh.bounds().unwrap();
        assert!((bounds.min - Vec3::new(1.0, 0.0, -2.0)).length() < 1e-6);
        assert!((bounds.max - Vec3::new(3.0, 1.0, -1.5)).length() < 1e-6);
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            assert!((*p - bounds.center()).dot(*n) > 0.0);
        }
    }

    #[test]
    fn sphere_winding_matches_its_normals() {
        let mesh = sphere(Vec3::ZERO, 2.0, Vec3::ONE);
        assert_front_faces_outwards(&mesh);
        mesh.validate().unwrap();
    }
}
