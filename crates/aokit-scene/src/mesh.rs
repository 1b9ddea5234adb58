//! Triangle meshes in world space, the one form every scene is flattened to.

use glam::{Mat4, Vec3};

/// An indexed triangle list with a normal and an albedo per vertex.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    /// World-space positions.
    pub positions: Vec<Vec3>,
    /// Unit shading normals.
    pub normals: Vec<Vec3>,
    /// Linear RGB albedo.
    pub albedo: Vec<Vec3>,
    /// Three indices per triangle, counter-clockwise seen from the front.
    pub indices: Vec<u32>,
}

/// Axis-aligned bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest corner.
    pub min: Vec3,
    /// Largest corner.
    pub max: Vec3,
}

impl Bounds {
    /// Centre point.
    pub fn center(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// Half the diagonal: the radius of a sphere around the centre holding the box.
    pub fn radius(&self) -> f32 {
        0.5 * (self.max - self.min).length()
    }
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Bounds of all vertices, `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Bounds> {
        let first = *self.positions.first()?;
        let (min, max) = self
            .positions
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        Some(Bounds { min, max })
    }

    /// Appends `other`, transformed by `transform` (normals by its inverse transpose).
    pub fn append_transformed(&mut self, other: &Mesh, transform: Mat4) {
        let base = self.positions.len() as u32;
        let normal_matrix = transform.inverse().transpose();
        // A mirroring transform turns counter-clockwise triangles clockwise.
        let flip = transform.determinant() < 0.0;
        self.positions.extend(
            other
                .positions
                .iter()
                .map(|&p| transform.transform_point3(p)),
        );
        self.normals.extend(
            other
                .normals
                .iter()
                .map(|&n| normal_matrix.transform_vector3(n).normalize_or_zero()),
        );
        self.albedo.extend_from_slice(&other.albedo);
        for tri in other.indices.chunks_exact(3) {
            let [a, b, c] = [tri[0] + base, tri[1] + base, tri[2] + base];
            if flip {
                self.indices.extend([a, c, b]);
            } else {
                self.indices.extend([a, b, c]);
            }
        }
    }

    /// Appends `other` unchanged.
    pub fn append(&mut self, other: &Mesh) {
        self.append_transformed(other, Mat4::IDENTITY);
    }

    /// Checks that every index is in range and every position finite, naming what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        let n = self.positions.len();
        if self.normals.len() != n || self.albedo.len() != n {
            return Err(format!(
                "{n} positions but {} normals and {} albedos",
                self.normals.len(),
                self.albedo.len()
            ));
        }
        if !self.indices.len().is_multiple_of(3) {
            return Err(format!(
                "{} indices is not a whole number of triangles",
                self.indices.len()
            ));
        }
        if let Some(i) = self.indices.iter().find(|&&i| i as usize >= n) {
            return Err(format!("index {i} out of range for {n} vertices"));
        }
        if let Some(p) = self.positions.iter().find(|p| !p.is_finite()) {
            return Err(format!("non-finite vertex position {p}"));
        }
        Ok(())
    }
}

/// Builds shading normals for a triangle soup given as positions and indices, returning a mesh
/// with one vertex per triangle corner. A corner's normal averages the area-weighted normals of
/// the triangles around its vertex that lie within `crease_degrees` of its own triangle, so
/// curved surfaces come out smooth while box edges stay sharp; 0 gives flat shading.
pub fn with_generated_normals(
    positions: &[Vec3],
    indices: &[u32],
    albedo: Vec3,
    crease_degrees: f32,
) -> Mesh {
    let triangles: Vec<[usize; 3]> = indices
        .chunks_exact(3)
        .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
        .collect();
    // Area-weighted face normals: the cross product's length is twice the area.
    let face: Vec<Vec3> = triangles
        .iter()
        .map(|&[a, b, c]| (positions[b] - positions[a]).cross(positions[c] - positions[a]))
        .collect();
    let mut incident: Vec<Vec<u32>> = vec![Vec::new(); positions.len()];
    if crease_degrees > 0.0 {
        for (t, tri) in triangles.iter().enumerate() {
            for &v in tri {
                incident[v].push(t as u32);
            }
        }
    }
    let cos_crease = crease_degrees.to_radians().cos();
    let mut mesh = Mesh::default();
    for (t, tri) in triangles.iter().enumerate() {
        let own = face[t].normalize_or_zero();
        for &v in tri {
            let smooth: Vec3 = incident[v]
                .iter()
                .map(|&o| face[o as usize])
                .filter(|n| n.normalize_or_zero().dot(own) >= cos_crease)
                .sum();
            let normal = if smooth == Vec3::ZERO {
                own
            } else {
                smooth.normalize_or_zero()
            };
            mesh.indices.push(mesh.positions.len() as u32);
            mesh.positions.push(positions[v]);
            mesh.normals.push(if normal == Vec3::ZERO {
                Vec3::Y
            } else {
                normal
            });
            mesh.albedo.push(albedo);
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crease_angle_keeps_cube_edges_sharp_and_smooths_shallow_folds() {
        // Two triangles folded by 20 degrees along the x axis.
        let fold = 20f32.to_radians();
        let positions = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(0.0, -fold.sin(), fold.cos()),
        ];
        let indices = [0, 1, 2, 0, 3, 1];
        let smooth = with_generated_normals(&positions, &indices, Vec3::ONE, 30.0);
        // The shared vertex 0 gets the same normal in both triangles.
        assert!((smooth.normals[0] - smooth.normals[3]).length() < 1e-6);
        let flat = with_generated_normals(&positions, &indices, Vec3::ONE, 10.0);
        assert!(flat.normals[0].angle_between(flat.normals[3]) > 19f32.to_radians());
        assert_eq!(flat.normals[0], Vec3::Y);
    }

    #[test]
    fn mirrored_transforms_keep_triangles_front_facing() {
        let tri = Mesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
            normals: vec![Vec3::Z; 3],
            albedo: vec![Vec3::ONE; 3],
            indices: vec![0, 1, 2],
        };
        let mut out = Mesh::default();
        out.append_transformed(&tri, Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)));
        let [a, b, c] = [0, 1, 2].map(|i| out.positions[out.indices[i] as usize]);
        let geometric = (b - a).cross(c - a).normalize();
        assert!(geometric.dot(out.normals[0]) > 0.99);
        out.validate().unwrap();
    }
}
