//! Triangle meshes in world space, the one form every scene is flattened to.

use glam::{Mat4, Vec3};

/// An indexed triangle list with a normal and an albedo per vertex.
///
/// ```
/// use aokit_scene::mesh::Mesh;
/// use glam::Vec3;
/// // One red triangle facing +Z.
/// let mesh = Mesh {
///     positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
///     normals: vec![Vec3::Z; 3],
///     albedo: vec![Vec3::new(0.8, 0.1, 0.1); 3],
///     indices: vec![0, 1, 2],
/// };
/// mesh.validate()?;
/// assert_eq!(mesh.triangle_count(), 1);
/// # Ok::<(), String>(())
/// ```
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
///
/// ```
/// use aokit_scene::mesh::Bounds;
/// use glam::Vec3;
/// let room = Bounds { min: Vec3::new(-4.0, 0.0, -3.0), max: Vec3::new(4.0, 3.0, 3.0) };
/// assert_eq!(room.center(), Vec3::new(0.0, 1.5, 0.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest corner.
    pub min: Vec3,
    /// Largest corner.
    pub max: Vec3,
}

impl Bounds {
    /// Centre point.
    ///
    /// ```
    /// use aokit_scene::shapes::cuboid;
    /// use glam::Vec3;
    /// let table = cuboid(Vec3::new(1.0, 0.0, 1.0), Vec3::new(2.0, 0.8, 1.0), 0.0, Vec3::ONE);
    /// // Where a camera framing the table looks.
    /// let target = table.bounds().unwrap().center();
    /// assert!((target - Vec3::new(2.0, 0.4, 1.5)).length() < 1e-6);
    /// ```
    pub fn center(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// Half the diagonal: the radius of a sphere around the centre holding the box.
    ///
    /// ```
    /// use aokit_scene::mesh::Bounds;
    /// use glam::Vec3;
    /// let bounds = Bounds { min: Vec3::ZERO, max: Vec3::new(3.0, 4.0, 12.0) };
    /// assert_eq!(bounds.radius(), 6.5);
    /// // An AO radius a few hundredths of the scene's size.
    /// let radius = 0.02 * bounds.radius();
    /// ```
    pub fn radius(&self) -> f32 {
        0.5 * (self.max - self.min).length()
    }
}

impl Mesh {
    /// Number of triangles.
    ///
    /// ```
    /// use aokit_scene::shapes::cuboid;
    /// use glam::Vec3;
    /// // Six faces of two triangles each.
    /// assert_eq!(cuboid(Vec3::ZERO, Vec3::ONE, 0.0, Vec3::ONE).triangle_count(), 12);
    /// ```
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Number of triangles with a nonzero area: the ones a rasteriser draws and a ray can hit.
    ///
    /// ```
    /// use aokit_scene::mesh::Mesh;
    /// use glam::Vec3;
    /// let mesh = Mesh {
    ///     positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y, 2.0 * Vec3::X],
    ///     normals: vec![Vec3::Z; 4],
    ///     albedo: vec![Vec3::ONE; 4],
    ///     // The second triangle's corners lie on one line.
    ///     indices: vec![0, 1, 2, 0, 1, 3],
    /// };
    /// assert_eq!((mesh.triangle_count(), mesh.area_triangle_count()), (2, 1));
    /// ```
    pub fn area_triangle_count(&self) -> usize {
        self.indices
            .chunks_exact(3)
            .filter(|t| {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| self.positions[i as usize]);
                (b - a).cross(c - a) != Vec3::ZERO
            })
            .count()
    }

    /// Bounds of all vertices, `None` for an empty mesh.
    ///
    /// ```
    /// use aokit_scene::{mesh::Mesh, shapes::sphere};
    /// use glam::Vec3;
    /// let ball = sphere(Vec3::new(0.0, 1.0, 0.0), 1.0, Vec3::ONE);
    /// let bounds = ball.bounds().unwrap();
    /// assert!((bounds.min - Vec3::new(-1.0, 0.0, -1.0)).length() < 1e-5);
    /// assert!(Mesh::default().bounds().is_none());
    /// ```
    pub fn bounds(&self) -> Option<Bounds> {
        let first = *self.positions.first()?;
        let (min, max) = self
            .positions
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        Some(Bounds { min, max })
    }

    /// Appends `other`, transformed by `transform` (normals by its inverse transpose).
    ///
    /// ```
    /// use aokit_scene::{mesh::Mesh, shapes::cuboid};
    /// use glam::{Mat4, Vec3};
    /// // A row of five pillars from one instance.
    /// let pillar = cuboid(Vec3::ZERO, Vec3::new(0.2, 2.0, 0.2), 0.0, Vec3::ONE);
    /// let mut row = Mesh::default();
    /// for i in 0..5 {
    ///     row.append_transformed(&pillar, Mat4::from_translation(Vec3::new(i as f32, 0.0, 0.0)));
    /// }
    /// assert_eq!(row.triangle_count(), 5 * pillar.triangle_count());
    /// assert!((row.bounds().unwrap().max.x - 4.2).abs() < 1e-6);
    /// ```
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
    ///
    /// ```
    /// use aokit_scene::shapes::{quad, sphere};
    /// use glam::Vec3;
    /// let mut mesh = quad(Vec3::new(-2.0, 0.0, 2.0), 4.0 * Vec3::X, -4.0 * Vec3::Z, Vec3::ONE);
    /// let ball = sphere(Vec3::new(0.0, 0.5, 0.0), 0.5, Vec3::ONE);
    /// mesh.append(&ball);
    /// mesh.validate()?;
    /// // The ball's triangles follow the quad's two, their indices shifted past its vertices.
    /// assert_eq!(mesh.triangle_count(), 2 + ball.triangle_count());
    /// let bounds = mesh.bounds().unwrap();
    /// assert_eq!((bounds.min.y, bounds.max.y), (0.0, 1.0));
    /// # Ok::<(), String>(())
    /// ```
    pub fn append(&mut self, other: &Mesh) {
        self.append_transformed(other, Mat4::IDENTITY);
    }

    /// Checks that every index is in range and every position finite, naming what is wrong.
    ///
    /// ```
    /// use aokit_scene::shapes::quad;
    /// use glam::Vec3;
    /// let mut mesh = quad(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE);
    /// mesh.indices.extend([0, 2, 9]);
    /// assert_eq!(mesh.validate().unwrap_err(), "index 9 out of range for 4 vertices");
    /// ```
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
        // Each position finite, but the extent past what f32 measures (about 1e19: a length
        // squares it): the bounds' radius, the framing camera and the reference's ray offsets
        // would all be infinite.
        if let Some(bounds) = self.bounds()
            && !bounds.radius().is_finite()
        {
            return Err(format!(
                "the positions span from {} to {}, farther than 32-bit floats can measure",
                bounds.min, bounds.max
            ));
        }
        Ok(())
    }
}

/// Builds shading normals for a triangle soup given as positions and indices, returning a mesh
/// with one vertex per triangle corner. A corner's normal averages the area-weighted normals of
/// the triangles around its vertex that lie within `crease_degrees` of its own triangle, so
/// curved surfaces come out smooth while box edges stay sharp; 0 gives flat shading.
///
/// ```
/// use aokit_scene::mesh::with_generated_normals;
/// use glam::Vec3;
/// // Two faces of a box meeting at a right angle along the x axis.
/// let positions = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 0.0, 1.0),
///                  Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, -1.0, 0.0)];
/// let indices = [0, 3, 2, 0, 2, 1, 0, 1, 4, 0, 4, 5];
/// let mesh = with_generated_normals(&positions, &indices, Vec3::splat(0.7), 30.0);
/// // 90 degrees is past the crease angle: each face keeps its own normal.
/// assert_eq!(mesh.normals[0], Vec3::Y);
/// assert_eq!(mesh.normals[6], Vec3::NEG_Z);
/// assert_eq!(mesh.positions.len(), indices.len());
/// ```
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
