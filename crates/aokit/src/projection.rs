//! Camera projection and depth conventions.
//!
//! View space is right-handed with the camera looking down -Z, as in glam and wgpu. NDC depth is
//! in `[0, 1]`; *linear depth* is the positive distance along the view axis, `-view.z`.
//!
//! One [`Projection`] covers perspective and orthographic cameras, standard and reverse-Z depth,
//! and finite or infinite far planes. Every depth mapping used here has the shape
//! `ndc = A * view.z + B` over `w = -view.z` (perspective) or `w = 1` (orthographic), so linear
//! depth comes back from NDC depth as a ratio of two linear functions, which the shaders evaluate
//! with four coefficients ([`Projection::linearize_coefficients`]).

use glam::{Mat4, Vec2, Vec3, Vec4};
use serde::{Deserialize, Serialize};

/// The shape of the view volume.
///
/// ```
/// use aokit::{Projection, ProjectionKind};
/// let p = Projection::perspective(50f32.to_radians(), 1.5, 0.1, None);
/// let description = match p.kind {
///     ProjectionKind::Perspective { fov_y } => format!("{:.0} degree lens", fov_y.to_degrees()),
///     ProjectionKind::Orthographic { height } => format!("{height} units tall"),
/// };
/// assert_eq!(description, "50 degree lens");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum ProjectionKind {
    /// Pinhole camera with a vertical field of view in radians.
    Perspective {
        /// Full vertical field of view, radians, in `(0, pi)`.
        fov_y: f32,
    },
    /// Parallel projection showing `height` world units vertically.
    Orthographic {
        /// Height of the view volume in world units.
        height: f32,
    },
}

/// A camera projection with its depth convention.
///
/// ```
/// use aokit::Projection;
/// let p = Projection::perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, None);
/// assert!(p.reverse_z);
/// let d = p.ndc_depth(25.0);
/// assert!((p.linear_depth(d) - 25.0).abs() < 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Projection {
    /// Perspective or orthographic, with its extent.
    pub kind: ProjectionKind,
    /// Width over height of the viewport.
    pub aspect: f32,
    /// Distance to the near plane (positive).
    pub near: f32,
    /// Distance to the far plane, or `None` for an infinite far plane (perspective only).
    pub far: Option<f32>,
    /// `true` when the near plane maps to depth 1 and the far plane to depth 0.
    pub reverse_z: bool,
    /// Where the view axis (-Z) meets the image, in NDC: zero for a centred view volume. A
    /// rasteriser that jitters its projection for temporal anti-aliasing, or draws a headset's
    /// eye through an off-centre frustum, offsets it; aokit must know, or every view position it
    /// reconstructs from depth is off by as much. Absent from older settings and camera files,
    /// where it reads as zero.
    #[serde(default)]
    pub ndc_offset: Vec2,
}

/// Why a [`Projection`] cannot be used.
///
/// ```
/// use aokit::{Projection, ProjectionError};
/// // Degrees where radians were meant.
/// let p = Projection::perspective(60.0, 16.0 / 9.0, 0.1, None);
/// assert!(matches!(p.validate(), Err(ProjectionError::FieldOfView(_))));
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProjectionError {
    /// The near plane is not a positive finite number.
    #[error("projection near plane must be positive and finite, got {0}")]
    Near(f32),
    /// The far plane is not beyond the near plane.
    #[error("projection far plane ({far}) must be finite and greater than the near plane ({near})")]
    Far {
        /// The near plane asked for.
        near: f32,
        /// The far plane asked for.
        far: f32,
    },
    /// The vertical field of view is outside `(0, pi)`.
    #[error("perspective vertical field of view must be in (0, 180) degrees, got {0} degrees")]
    FieldOfView(f32),
    /// The orthographic height is not positive.
    #[error("orthographic height must be positive and finite, got {0}")]
    OrthoHeight(f32),
    /// The aspect ratio is not positive.
    #[error("aspect ratio must be positive and finite, got {0}")]
    Aspect(f32),
    /// Orthographic depth is linear in distance, so it needs a finite far plane.
    #[error("an orthographic projection needs a finite far plane")]
    InfiniteOrthographic,
    /// The NDC offset of the view axis is not finite.
    #[error("projection NDC offset must be finite, got {0}")]
    NdcOffset(Vec2),
    /// A matrix given to [`Projection::from_matrix`] is not a perspective or orthographic
    /// projection of the shape it reads.
    #[error("not a projection matrix aokit can read: {0}")]
    Matrix(String),
}

impl Projection {
    /// A perspective projection, reverse-Z (the precise choice for float depth buffers).
    ///
    /// ```
    /// use aokit::Projection;
    /// // 60 degrees vertically, 16:9, near plane 10 cm, no far plane.
    /// let p = Projection::perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, None);
    /// p.validate()?;
    /// // Reverse-Z: the near plane is at depth 1.
    /// assert!((p.ndc_depth(0.1) - 1.0).abs() < 1e-6);
    /// # Ok::<(), aokit::ProjectionError>(())
    /// ```
    pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: Option<f32>) -> Self {
        Self {
            kind: ProjectionKind::Perspective { fov_y },
            aspect,
            near,
            far,
            reverse_z: true,
            ndc_offset: Vec2::ZERO,
        }
    }

    /// An orthographic projection `height` world units tall, reverse-Z.
    ///
    /// ```
    /// use aokit::Projection;
    /// // A top-down view of a 40 m level, camera 100 m up.
    /// let p = Projection::orthographic(40.0, 1.0, 1.0, 200.0);
    /// // Linear in depth: halfway to the far plane is halfway in NDC.
    /// assert!((p.ndc_depth(100.5) - 0.5).abs() < 1e-6);
    /// ```
    pub fn orthographic(height: f32, aspect: f32, near: f32, far: f32) -> Self {
        Self {
            kind: ProjectionKind::Orthographic { height },
            aspect,
            near,
            far: Some(far),
            reverse_z: true,
            ndc_offset: Vec2::ZERO,
        }
    }

    /// The projection of a renderer's clip-from-view matrix, in wgpu's clip space (depth 0 to 1,
    /// y up, as glam's `camera::rh::proj::directx` functions make it, and as Direct3D and Metal
    /// use): perspective or orthographic (told by its last row), standard or reverse-Z
    /// (by which way depth runs), a finite or infinite far plane, and an off-centre or
    /// jittered view axis ([`Projection::ndc_offset`]). The result is checked
    /// ([`Projection::validate`]) and must give back `matrix`; a matrix with a rotation, a
    /// skew or a depth that does not run between the planes is an error naming the reason.
    ///
    /// An OpenGL-convention matrix (depth -1 to 1) reads as one with the same far plane and a
    /// near plane about twice its own: the projection of the same depth buffer, had wgpu kept
    /// the depths that its clip space puts below 0.
    ///
    /// ```
    /// use aokit::{Projection, ProjectionKind};
    /// // The matrix a renderer already has, here an infinite reverse-Z perspective.
    /// let matrix = glam::camera::rh::proj::directx::perspective_infinite_reverse(1.0, 16.0 / 9.0, 0.1);
    /// let p = Projection::from_matrix(matrix)?;
    /// assert!(p.reverse_z && p.far.is_none());
    /// assert!((p.near - 0.1).abs() < 1e-6 && (p.aspect - 16.0 / 9.0).abs() < 1e-5);
    /// assert!(matches!(p.kind, ProjectionKind::Perspective { fov_y } if (fov_y - 1.0).abs() < 1e-5));
    /// // A view matrix by mistake.
    /// let view = glam::camera::rh::view::look_at_mat4(glam::Vec3::ONE, glam::Vec3::ZERO, glam::Vec3::Y);
    /// assert!(Projection::from_matrix(view).is_err());
    /// # Ok::<(), aokit::ProjectionError>(())
    /// ```
    pub fn from_matrix(matrix: Mat4) -> Result<Self, ProjectionError> {
        let bad = |why: &str| ProjectionError::Matrix(why.to_string());
        if !matrix.is_finite() {
            return Err(bad("it holds a NaN or an infinity"));
        }
        let [c0, c1, c2, c3] = matrix.to_cols_array_2d().map(Vec4::from_array);
        let (x_scale, y_scale) = (c0.x, c1.y);
        if x_scale == 0.0 || y_scale == 0.0 {
            return Err(bad("it scales x or y by 0"));
        }
        let aspect = y_scale / x_scale;
        // Perspective: clip w = -view z (last row 0, 0, -1, 0); orthographic: w = 1.
        let (kind, a, b, ndc_offset) = if c2.w == -1.0 && c3.w == 0.0 {
            let fov_y = 2.0 * (1.0 / y_scale).atan();
            let kind = ProjectionKind::Perspective { fov_y };
            (kind, c2.z, c3.z, -Vec2::new(c2.x, c2.y))
        } else if c2.w == 0.0 && c3.w == 1.0 {
            let kind = ProjectionKind::Orthographic {
                height: 2.0 / y_scale,
            };
            (kind, c2.z, c3.z, Vec2::new(c3.x, c3.y))
        } else {
            return Err(bad(
                "its last row is neither (0, 0, -1, 0) (perspective) nor (0, 0, 0, 1) \
                 (orthographic); pass the projection alone, not view times projection",
            ));
        };
        // Depth is ndc = a * z + b over w (depth_terms); which of the planes reads 0 tells
        // the direction.
        let (reverse_z, near, far) = match kind {
            ProjectionKind::Perspective { .. } => {
                // ndc = b / d - a at distance d: it falls with distance when b > 0.
                let reverse_z = b > 0.0;
                let (near, far) = if reverse_z {
                    (b / (1.0 + a), b / a)
                } else {
                    (b / a, b / (1.0 + a))
                };
                (reverse_z, near, Some(far).filter(|f| f.is_finite()))
            }
            ProjectionKind::Orthographic { .. } => {
                let reverse_z = a > 0.0;
                let (near, far) = if reverse_z {
                    ((b - 1.0) / a, b / a)
                } else {
                    (b / a, (b - 1.0) / a)
                };
                (reverse_z, near, Some(far))
            }
        };
        let projection = Self {
            kind,
            aspect,
            near,
            far,
            reverse_z,
            ndc_offset,
        };
        projection.validate()?;
        let rebuilt = projection.clip_from_view();
        let tolerance = 1e-4 * matrix.abs().to_cols_array().into_iter().fold(1.0, f32::max);
        if !rebuilt.abs_diff_eq(matrix, tolerance) {
            return Err(bad(
                "it has terms a projection of a view-space point does not (a rotation, a skew \
                 or a translation; pass the projection alone, not view times projection)",
            ));
        }
        Ok(projection)
    }

    /// The same projection with the given depth direction.
    ///
    /// ```
    /// use aokit::Projection;
    /// // A renderer with a conventional depth buffer: near 0, far 1.
    /// let p = Projection::perspective(1.0, 1.0, 0.1, Some(500.0)).with_reverse_z(false);
    /// assert_eq!(p.far_ndc_depth(), 1.0);
    /// ```
    pub fn with_reverse_z(self, reverse_z: bool) -> Self {
        Self { reverse_z, ..self }
    }

    /// The same projection with the view axis meeting the image at `ndc_offset` (see
    /// [`Projection::ndc_offset`]).
    ///
    /// ```
    /// use aokit::Projection;
    /// use glam::{Vec2, Vec3};
    /// // The right half of a 90-degree, 2:1 view, drawn on its own as a 1:1 image: its left
    /// // edge (NDC x = -1) is where the full view's axis was.
    /// let right_half = Projection::perspective(90f32.to_radians(), 1.0, 0.1, None)
    ///     .with_ndc_offset(Vec2::new(-1.0, 0.0));
    /// let point = right_half.view_position_from_linear(Vec2::new(-1.0, 0.0), 3.0);
    /// assert!((point - Vec3::new(0.0, 0.0, -3.0)).length() < 1e-6);
    /// ```
    pub fn with_ndc_offset(self, ndc_offset: Vec2) -> Self {
        Self { ndc_offset, ..self }
    }

    /// The same projection jittered by `pixels` (x right, y down) on an image of `size`
    /// pixels, as temporal anti-aliasing moves it each frame: the offset in NDC is
    /// `(2 x / width, -2 y / height)`, added to any offset it had.
    ///
    /// ```
    /// use aokit::Projection;
    /// use glam::Vec2;
    /// let p = Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
    /// // This frame's sub-pixel jitter, as the renderer's TAA applied it to its matrix.
    /// let jittered = p.with_jitter(Vec2::new(0.25, -0.5), [1920, 1080]);
    /// assert_eq!(jittered.ndc_offset, Vec2::new(0.5 / 1920.0, 1.0 / 1080.0));
    /// ```
    pub fn with_jitter(self, pixels: Vec2, size: [u32; 2]) -> Self {
        let per_pixel = Vec2::new(2.0 / size[0] as f32, -2.0 / size[1] as f32);
        self.with_ndc_offset(self.ndc_offset + pixels * per_pixel)
    }

    /// The projection of the same camera drawn `band` pixels larger on each side of an image of
    /// `size` pixels: the frustum widened so that the inner `size` pixels see exactly what this
    /// projection sees, as a renderer draws the overscan of [`AoInputs::guard_band`]. The view
    /// axis stays where it was in the image (a jitter or an off-centre offset keeps its pixels).
    ///
    /// [`AoInputs::guard_band`]: crate::AoInputs::guard_band
    ///
    /// ```
    /// use aokit::Projection;
    /// use aokit::projection::pixel_to_ndc;
    /// use glam::Vec2;
    /// let camera = Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
    /// let overscan = camera.with_guard_band([160, 90], 8);
    /// // Pixel (0, 0) of the output is pixel (8, 8) of the overscan image: the same ray.
    /// let inner = camera.view_position_from_linear(pixel_to_ndc(Vec2::ZERO, Vec2::new(160.0, 90.0)), 2.0);
    /// let outer = overscan.view_position_from_linear(pixel_to_ndc(Vec2::splat(8.0), Vec2::new(176.0, 106.0)), 2.0);
    /// assert!((inner - outer).length() < 1e-5);
    /// ```
    pub fn with_guard_band(self, size: [u32; 2], band: u32) -> Self {
        let [w, h] = size.map(|side| side as f32);
        let grow = Vec2::new(w + 2.0 * band as f32, h + 2.0 * band as f32) / Vec2::new(w, h);
        let kind = match self.kind {
            ProjectionKind::Perspective { fov_y } => ProjectionKind::Perspective {
                fov_y: 2.0 * ((0.5 * fov_y).tan() * grow.y).atan(),
            },
            ProjectionKind::Orthographic { height } => ProjectionKind::Orthographic {
                height: height * grow.y,
            },
        };
        Self {
            kind,
            aspect: self.aspect * grow.x / grow.y,
            ndc_offset: self.ndc_offset / grow,
            ..self
        }
    }

    /// Checks every parameter, naming the first one that is unusable.
    ///
    /// ```
    /// use aokit::Projection;
    /// let p = Projection::perspective(1.0, 1.0, 1.0, Some(0.5));
    /// let message = p.validate().unwrap_err().to_string();
    /// assert!(message.contains("far plane"), "{message}");
    /// ```
    pub fn validate(&self) -> Result<(), ProjectionError> {
        if !(self.near.is_finite() && self.near > 0.0) {
            return Err(ProjectionError::Near(self.near));
        }
        if !(self.aspect.is_finite() && self.aspect > 0.0) {
            return Err(ProjectionError::Aspect(self.aspect));
        }
        if !self.ndc_offset.is_finite() {
            return Err(ProjectionError::NdcOffset(self.ndc_offset));
        }
        if let Some(far) = self.far
            && !(far.is_finite() && far > self.near)
        {
            return Err(ProjectionError::Far {
                near: self.near,
                far,
            });
        }
        match self.kind {
            ProjectionKind::Perspective { fov_y } => {
                if !(fov_y > 0.0 && fov_y < std::f32::consts::PI) {
                    return Err(ProjectionError::FieldOfView(fov_y.to_degrees()));
                }
            }
            ProjectionKind::Orthographic { height } => {
                if !(height.is_finite() && height > 0.0) {
                    return Err(ProjectionError::OrthoHeight(height));
                }
                if self.far.is_none() {
                    return Err(ProjectionError::InfiniteOrthographic);
                }
            }
        }
        Ok(())
    }

    /// `true` for orthographic projections.
    ///
    /// ```
    /// use aokit::Projection;
    /// assert!(Projection::orthographic(10.0, 1.0, 0.1, 100.0).is_orthographic());
    /// assert!(!Projection::perspective(1.0, 1.0, 0.1, None).is_orthographic());
    /// ```
    pub fn is_orthographic(&self) -> bool {
        matches!(self.kind, ProjectionKind::Orthographic { .. })
    }

    /// Half extent of the view volume at linear depth 1 (perspective) or anywhere (orthographic).
    fn half_extent(&self) -> Vec2 {
        let half_height = match self.kind {
            ProjectionKind::Perspective { fov_y } => (0.5 * fov_y).tan(),
            ProjectionKind::Orthographic { height } => 0.5 * height,
        };
        Vec2::new(half_height * self.aspect, half_height)
    }

    /// `(A, B)` of `ndc_z * w = A * view.z + B`.
    fn depth_terms(&self) -> (f32, f32) {
        let n = self.near;
        match (self.kind, self.far, self.reverse_z) {
            (ProjectionKind::Perspective { .. }, Some(f), false) => (f / (n - f), n * f / (n - f)),
            (ProjectionKind::Perspective { .. }, Some(f), true) => (n / (f - n), n * f / (f - n)),
            (ProjectionKind::Perspective { .. }, None, false) => (-1.0, -n),
            (ProjectionKind::Perspective { .. }, None, true) => (0.0, n),
            (ProjectionKind::Orthographic { .. }, far, false) => {
                let f = far.unwrap_or(f32::INFINITY);
                (-1.0 / (f - n), -n / (f - n))
            }
            (ProjectionKind::Orthographic { .. }, far, true) => {
                let f = far.unwrap_or(f32::INFINITY);
                (1.0 / (f - n), f / (f - n))
            }
        }
    }

    /// The clip-from-view matrix (wgpu clip space, depth in `[0, 1]`).
    ///
    /// ```
    /// use aokit::Projection;
    /// use glam::Vec3;
    /// let p = Projection::perspective(1.2, 16.0 / 9.0, 0.1, None);
    /// // The vertex shader's matrix, for exactly the depth the AO pipeline then reads.
    /// let eye = Vec3::new(0.0, 2.0, 5.0);
    /// let view_from_world = glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y);
    /// let clip_from_world = p.clip_from_view() * view_from_world;
    /// let ndc = clip_from_world.project_point3(Vec3::ZERO);
    /// assert!(ndc.x.abs() < 1e-6 && ndc.y.abs() < 1e-6);
    /// assert!((p.linear_depth(ndc.z) - 29f32.sqrt()).abs() < 1e-4);
    /// ```
    pub fn clip_from_view(&self) -> Mat4 {
        let e = self.half_extent();
        let (a, b) = self.depth_terms();
        // NDC xy gain the offset: clip xy gain it times clip w, which is 1 (orthographic) or
        // -z (perspective).
        let o = self.ndc_offset;
        if self.is_orthographic() {
            Mat4::from_cols(
                Vec4::new(1.0 / e.x, 0.0, 0.0, 0.0),
                Vec4::new(0.0, 1.0 / e.y, 0.0, 0.0),
                Vec4::new(0.0, 0.0, a, 0.0),
                Vec4::new(o.x, o.y, b, 1.0),
            )
        } else {
            Mat4::from_cols(
                Vec4::new(1.0 / e.x, 0.0, 0.0, 0.0),
                Vec4::new(0.0, 1.0 / e.y, 0.0, 0.0),
                Vec4::new(-o.x, -o.y, a, -1.0),
                Vec4::new(0.0, 0.0, b, 0.0),
            )
        }
    }

    /// Coefficients `c` with `linear = (c.x * ndc + c.y) / (c.z * ndc + c.w)`.
    ///
    /// ```
    /// use aokit::Projection;
    /// // Four numbers for a shader's uniforms cover every kind of projection.
    /// let p = Projection::perspective(1.0, 1.0, 0.5, Some(100.0)).with_reverse_z(false);
    /// let c = p.linearize_coefficients();
    /// let linear = |ndc: f32| (c.x * ndc + c.y) / (c.z * ndc + c.w);
    /// assert!((linear(0.0) - 0.5).abs() < 1e-5);
    /// assert!((linear(1.0) - 100.0).abs() < 1e-2);
    /// ```
    pub fn linearize_coefficients(&self) -> Vec4 {
        let (a, b) = self.depth_terms();
        if self.is_orthographic() {
            // ndc = -a * linear + b
            Vec4::new(-1.0 / a, b / a, 0.0, 1.0)
        } else {
            // ndc = -a + b / linear
            Vec4::new(0.0, b, 1.0, a)
        }
    }

    /// Linear view depth (distance along -Z) of an NDC depth value.
    ///
    /// ```
    /// use aokit::Projection;
    /// let p = Projection::perspective(1.0, 1.0, 0.1, None);
    /// // A depth buffer value read back, in world units from the camera.
    /// assert!((p.linear_depth(0.01) - 10.0).abs() < 1e-4);
    /// ```
    pub fn linear_depth(&self, ndc_depth: f32) -> f32 {
        let c = self.linearize_coefficients();
        (c.x * ndc_depth + c.y) / (c.z * ndc_depth + c.w)
    }

    /// [`Projection::linear_depth`] of a depth-buffer value as the pipeline reads it: 0, no
    /// surface, where the buffer holds the far plane's clear value or the value gives no finite
    /// positive depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// let p = Projection::perspective(1.0, 1.0, 0.1, None);
    /// // A depth buffer read back: a surface 10 units away, and the cleared sky.
    /// assert!((p.surface_depth(0.01) - 10.0).abs() < 1e-4);
    /// assert_eq!(p.surface_depth(p.far_ndc_depth()), 0.0);
    /// ```
    pub fn surface_depth(&self, ndc_depth: f32) -> f32 {
        let linear = self.linear_depth(ndc_depth);
        // Written as a positive test, as depth_from_ndc.wgsl's, so that NaN is no surface too.
        let surface = ndc_depth != self.far_ndc_depth() && linear > 0.0 && linear < f32::MAX;
        if surface { linear } else { 0.0 }
    }

    /// NDC depth of a point at the given linear view depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// // A synthetic depth buffer: a wall 4 units away, as the rasteriser would write it.
    /// let p = Projection::perspective(1.0, 1.0, 0.1, None);
    /// let depth = vec![p.ndc_depth(4.0); 64 * 64];
    /// assert!((p.linear_depth(depth[0]) - 4.0).abs() < 1e-4);
    /// ```
    pub fn ndc_depth(&self, linear_depth: f32) -> f32 {
        let (a, b) = self.depth_terms();
        if self.is_orthographic() {
            -a * linear_depth + b
        } else {
            -a + b / linear_depth
        }
    }

    /// The depth buffer value of empty pixels: the far plane's NDC depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// let p = Projection::perspective(1.0, 1.0, 0.1, None);
    /// // The clear value of the depth attachment, so that untouched pixels read as sky.
    /// let clear = wgpu::LoadOp::Clear(p.far_ndc_depth());
    /// assert_eq!(p.far_ndc_depth(), 0.0);
    /// ```
    pub fn far_ndc_depth(&self) -> f32 {
        if self.reverse_z { 0.0 } else { 1.0 }
    }

    /// View-space position of a point with NDC `xy` and the given linear depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// use glam::{Vec2, Vec3};
    /// // 90 degrees vertically: the top edge of the image at depth 2 is 2 units up.
    /// let p = Projection::perspective(90f32.to_radians(), 1.0, 0.1, None);
    /// let top = p.view_position_from_linear(Vec2::new(0.0, 1.0), 2.0);
    /// assert!((top - Vec3::new(0.0, 2.0, -2.0)).length() < 1e-5);
    /// ```
    pub fn view_position_from_linear(&self, ndc_xy: Vec2, linear_depth: f32) -> Vec3 {
        let e = self.half_extent();
        let scale = if self.is_orthographic() {
            1.0
        } else {
            linear_depth
        };
        ((ndc_xy - self.ndc_offset) * e * scale).extend(-linear_depth)
    }

    /// View-space position of a point with NDC `xy` and NDC depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// use aokit::projection::pixel_to_ndc;
    /// use glam::Vec2;
    /// let p = Projection::perspective(1.0, 640.0 / 480.0, 0.1, None);
    /// // Pixel (320, 100) of a 640x480 depth buffer holding 0.02, back in view space.
    /// let ndc = pixel_to_ndc(Vec2::new(320.0, 100.0), Vec2::new(640.0, 480.0));
    /// let point = p.view_position(ndc, 0.02);
    /// assert!((point.z + 5.0).abs() < 1e-4 && point.y > 0.0);
    /// ```
    pub fn view_position(&self, ndc_xy: Vec2, ndc_depth: f32) -> Vec3 {
        self.view_position_from_linear(ndc_xy, self.linear_depth(ndc_depth))
    }

    /// Multiplier from NDC `xy` to view `xy`; perspective results are then scaled by linear depth.
    ///
    /// ```
    /// use aokit::Projection;
    /// use glam::Vec2;
    /// let p = Projection::perspective(1.0, 2.0, 0.1, None);
    /// // The half extent of the view at depth 1: tan(fov / 2), times the aspect across.
    /// let scale = p.ndc_to_view_scale();
    /// assert!((scale - Vec2::new(2.0 * 0.5f32.tan(), 0.5f32.tan())).length() < 1e-6);
    /// ```
    pub fn ndc_to_view_scale(&self) -> Vec2 {
        self.half_extent()
    }

    /// Pixels covered by one world unit at linear depth 1 (perspective) or at any depth
    /// (orthographic), for a viewport `height_px` pixels tall.
    ///
    /// ```
    /// use aokit::Projection;
    /// let p = Projection::perspective(90f32.to_radians(), 16.0 / 9.0, 0.1, None);
    /// // How many pixels an AO radius of 0.5 spans at depth 10 on a 1080p screen.
    /// let pixels = 0.5 * p.pixels_per_unit(1080.0) / 10.0;
    /// assert!((pixels - 27.0).abs() < 1e-3);
    /// ```
    pub fn pixels_per_unit(&self, height_px: f32) -> f32 {
        0.5 * height_px / self.half_extent().y
    }
}

/// NDC `xy` of the centre of pixel `(x, y)` in a `width x height` image (y down in pixels, up in
/// NDC).
///
/// ```
/// use aokit::projection::pixel_to_ndc;
/// use glam::Vec2;
/// let size = Vec2::new(1920.0, 1080.0);
/// // Pixel centres: the top-left pixel is half a pixel in from the corner (-1, 1).
/// let top_left = pixel_to_ndc(Vec2::ZERO, size);
/// assert!((top_left - Vec2::new(-1.0 + 1.0 / 1920.0, 1.0 - 1.0 / 1080.0)).length() < 1e-6);
/// ```
pub fn pixel_to_ndc(pixel: Vec2, size: Vec2) -> Vec2 {
    let uv = (pixel + 0.5) / size;
    Vec2::new(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all_projections() -> Vec<Projection> {
        let mut out = Vec::new();
        for reverse_z in [false, true] {
            for far in [Some(500.0), None] {
                out.push(Projection::perspective(1.1, 1.5, 0.05, far).with_reverse_z(reverse_z));
            }
            out.push(Projection::orthographic(20.0, 1.5, 0.05, 500.0).with_reverse_z(reverse_z));
        }
        // Off-centre: a headset's eye, and a TAA jitter.
        let centred = out.clone();
        out.extend(
            centred
                .iter()
                .map(|p| p.with_ndc_offset(Vec2::new(-0.3, 0.1))),
        );
        out.extend(
            centred
                .iter()
                .map(|p| p.with_jitter(Vec2::new(0.5, -0.25), [1920, 1080])),
        );
        out
    }

    #[test]
    fn from_matrix_gives_back_every_projection() {
        for p in all_projections() {
            let read = Projection::from_matrix(p.clip_from_view()).unwrap();
            assert!(
                read.clip_from_view()
                    .abs_diff_eq(p.clip_from_view(), 1e-4 * 2000.0),
                "{p:?} read as {read:?}"
            );
            assert_eq!(
                (read.reverse_z, read.is_orthographic(), read.far.is_some()),
                (p.reverse_z, p.is_orthographic(), p.far.is_some()),
                "{p:?} read as {read:?}"
            );
            assert!(
                (read.near - p.near).abs() < 1e-4 * p.near,
                "{p:?}: {read:?}"
            );
            if let (Some(a), Some(b)) = (read.far, p.far) {
                assert!((a - b).abs() < 1e-3 * b, "{p:?}: {read:?}");
            }
            assert!((read.aspect - p.aspect).abs() < 1e-5, "{p:?}: {read:?}");
            assert!((read.ndc_offset - p.ndc_offset).abs().max_element() < 1e-6);
        }
    }

    #[test]
    fn from_matrix_reads_glams_projections() {
        let (fov, aspect, near, far) = (1.2, 1.5, 0.1, 300.0);
        use glam::camera::rh::proj::directx;
        let cases = [
            (
                directx::perspective(fov, aspect, near, far),
                false,
                Some(far),
            ),
            (
                directx::perspective_infinite(fov, aspect, near),
                false,
                None,
            ),
            (
                directx::perspective_infinite_reverse(fov, aspect, near),
                true,
                None,
            ),
        ];
        for (matrix, reverse_z, far) in cases {
            let p = Projection::from_matrix(matrix).unwrap();
            assert_eq!(p.reverse_z, reverse_z, "{matrix}");
            assert!((p.near - near).abs() < 1e-5, "{p:?}");
            assert_eq!(p.far.is_some(), far.is_some(), "{p:?}");
            // The same linear depth back from every depth the matrix writes.
            for distance in [0.2, 1.0, 7.5, 120.0] {
                let ndc = matrix.project_point3(Vec3::new(0.0, 0.0, -distance)).z;
                assert!(
                    (p.linear_depth(ndc) - distance).abs() < 2e-3 * distance,
                    "{p:?}"
                );
            }
        }
        let ortho = directx::orthographic(-3.0, 3.0, -2.0, 2.0, 0.5, 50.0);
        let p = Projection::from_matrix(ortho).unwrap();
        assert!(p.is_orthographic() && !p.reverse_z);
        assert!((p.near - 0.5).abs() < 1e-5 && (p.far.unwrap() - 50.0).abs() < 1e-3);
        assert!(
            matches!(p.kind, ProjectionKind::Orthographic { height } if (height - 4.0).abs() < 1e-5)
        );
    }

    #[test]
    fn from_matrix_names_what_is_wrong() {
        let message = |m: Mat4| Projection::from_matrix(m).unwrap_err().to_string();
        let p = glam::camera::rh::proj::directx::perspective(1.0, 1.0, 0.1, 100.0);
        assert!(message(Mat4::IDENTITY * 0.0).contains("by 0"));
        let mut homogeneous = p;
        homogeneous.w_axis.w = 0.5;
        assert!(message(homogeneous).contains("last row"));
        // A rotation has the orthographic last row, but no plane at depth 0 in front.
        assert!(Projection::from_matrix(Mat4::from_rotation_y(0.3)).is_err());
        let view = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
        assert!(
            message(p * view).contains("view times projection"),
            "{}",
            message(p * view)
        );
        let mut skewed = p;
        skewed.y_axis.x = 0.3;
        assert!(message(skewed).contains("a skew"), "{}", message(skewed));
        let mut nan = p;
        nan.x_axis.x = f32::NAN;
        assert!(message(nan).contains("NaN"));
        // Depth 0 behind the eye: the near plane would be there.
        let mut behind = p;
        behind.w_axis.z = 0.05;
        assert!(
            message(behind).contains("near plane"),
            "{}",
            message(behind)
        );
    }

    #[test]
    fn every_combination_is_valid_except_infinite_orthographic() {
        for p in all_projections() {
            p.validate().unwrap();
        }
        let mut ortho = Projection::orthographic(20.0, 1.0, 0.1, 100.0);
        ortho.far = None;
        assert_eq!(ortho.validate(), Err(ProjectionError::InfiniteOrthographic));
    }

    #[test]
    fn view_position_round_trips_through_the_matrix() {
        let points = [
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(0.3, -0.2, -0.4),
            Vec3::new(-4.0, 2.5, -12.0),
            Vec3::new(30.0, -11.0, -90.0),
            Vec3::new(-0.01, 0.02, -0.06),
        ];
        for p in all_projections() {
            let m = p.clip_from_view();
            for v in points {
                let clip = m * v.extend(1.0);
                let ndc = clip.truncate() / clip.w;
                assert!((0.0..=1.0).contains(&ndc.z), "{p:?} {v} -> {ndc}");
                let back = p.view_position(ndc.truncate(), ndc.z);
                // Orthographic depth spends its bits evenly over [near, far]: absolute error.
                let depth_quantum = match p.far {
                    Some(far) if p.is_orthographic() => 4.0 * f32::EPSILON * (far - p.near),
                    _ => 0.0,
                };
                let err = (back - v).length();
                let tolerance = 1e-4 * v.length() + depth_quantum;
                assert!(err < tolerance, "{p:?}: {v} -> {ndc} -> {back} (err {err})");
                assert!((p.ndc_depth(-v.z) - ndc.z).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn near_and_far_planes_map_to_the_depth_range_ends() {
        for p in all_projections() {
            let (near_ndc, far_ndc) = if p.reverse_z { (1.0, 0.0) } else { (0.0, 1.0) };
            assert!((p.ndc_depth(p.near) - near_ndc).abs() < 1e-6, "{p:?}");
            let far = p.far.unwrap_or(f32::INFINITY);
            assert!((p.ndc_depth(far) - far_ndc).abs() < 1e-6, "{p:?}");
            assert_eq!(p.far_ndc_depth(), far_ndc);
        }
    }

    #[test]
    fn pixel_centres_map_inside_ndc_with_y_up() {
        let size = Vec2::new(4.0, 2.0);
        assert_eq!(pixel_to_ndc(Vec2::ZERO, size), Vec2::new(-0.75, 0.5));
        assert_eq!(
            pixel_to_ndc(Vec2::new(3.0, 1.0), size),
            Vec2::new(0.75, -0.5)
        );
    }

    #[test]
    fn bad_parameters_are_named() {
        let p = Projection::perspective(0.0, 1.0, 0.1, None);
        assert!(
            p.validate()
                .unwrap_err()
                .to_string()
                .contains("field of view")
        );
        let p = Projection::perspective(1.0, 1.0, -1.0, None);
        assert!(p.validate().unwrap_err().to_string().contains("near"));
        let p = Projection::perspective(1.0, 1.0, 1.0, Some(0.5));
        assert!(p.validate().unwrap_err().to_string().contains("far"));
        let p = Projection::perspective(1.0, 1.0, 0.1, None).with_ndc_offset(Vec2::NAN);
        assert!(p.validate().unwrap_err().to_string().contains("NDC offset"));
    }

    #[test]
    fn an_offset_shifts_where_the_view_axis_meets_the_image() {
        let p = Projection::perspective(1.0, 1.5, 0.1, None).with_ndc_offset(Vec2::new(0.2, -0.4));
        // The axis projects to the offset, and the offset's NDC back onto the axis.
        let clip = p.clip_from_view() * Vec4::new(0.0, 0.0, -7.0, 1.0);
        assert!((clip.truncate().truncate() / clip.w - p.ndc_offset).length() < 1e-6);
        let back = p.view_position_from_linear(p.ndc_offset, 7.0);
        assert!((back - Vec3::new(0.0, 0.0, -7.0)).length() < 1e-6);
    }
}
