//! Cameras: placement, lens and depth convention, and the `camera.json` file format.

use aokit::{Projection, ProjectionKind};
use glam::{Mat4, Vec3};
use serde::{Deserialize, Serialize};

use crate::mesh::Bounds;

/// What the camera sees through.
///
/// ```
/// use aokit::ProjectionKind;
/// use aokit_scene::{Camera, Lens, mesh::Bounds};
/// use glam::Vec3;
/// // A plan view of a 20 m floor plan.
/// let plan = Camera {
///     lens: Lens::Orthographic { height: 20.0 },
///     up: Vec3::NEG_Z,
///     ..Camera::perspective("plan", Vec3::new(0.0, 50.0, 0.0), Vec3::ZERO, 60.0)
/// };
/// plan.validate()?;
/// // 20 units tall whatever the distance, with planes fitted around the floor, 50 units down.
/// let floor = Bounds { min: Vec3::new(-10.0, 0.0, -10.0), max: Vec3::new(10.0, 3.0, 10.0) };
/// let projection = plan.projection(1.0, &floor);
/// assert_eq!(projection.kind, ProjectionKind::Orthographic { height: 20.0 });
/// assert!(projection.near < 47.0 && projection.far.unwrap() > 50.0);
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lens {
    /// Pinhole with a vertical field of view in degrees.
    Perspective {
        /// Full vertical field of view, degrees.
        fov_y_deg: f32,
    },
    /// Parallel projection `height` world units tall.
    Orthographic {
        /// Visible height in world units.
        height: f32,
    },
}

/// A named camera placed by eye, target and up.
///
/// ```
/// use aokit_scene::Camera;
/// use glam::Vec3;
/// let mut camera = Camera::perspective("close-up", Vec3::new(1.0, 1.5, 3.0), Vec3::ZERO, 45.0);
/// // Fixed clipping planes instead of ones fitted to the scene.
/// camera.near = Some(0.05);
/// camera.far = Some(100.0);
/// camera.validate()?;
/// // The planes are used as given, whatever the scene's bounds.
/// let bounds = aokit_scene::mesh::Bounds { min: Vec3::splat(-500.0), max: Vec3::splat(500.0) };
/// let projection = camera.projection(1.5, &bounds);
/// assert_eq!((projection.near, projection.far), (0.05, Some(100.0)));
/// // A far plane before the near one is refused.
/// camera.far = Some(0.01);
/// assert!(camera.validate().is_err());
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    /// Name used by `--camera`.
    pub name: String,
    /// Eye position.
    pub eye: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Approximate up direction.
    pub up: Vec3,
    /// Lens.
    pub lens: Lens,
    /// Near plane; `None` picks one from the scene size.
    pub near: Option<f32>,
    /// Far plane; `None` is an infinite far plane (perspective) or one just past the scene
    /// (orthographic).
    pub far: Option<f32>,
    /// Reverse-Z depth (near = 1, far = 0), the precise choice for float depth.
    pub reverse_z: bool,
}

impl Camera {
    /// A perspective camera with +Y up, reverse-Z and an infinite far plane.
    ///
    /// ```
    /// use aokit_scene::Camera;
    /// use glam::Vec3;
    /// let (eye, target) = (Vec3::new(0.0, 1.6, 5.0), Vec3::new(0.0, 1.0, 0.0));
    /// let camera = Camera::perspective("front", eye, target, 60.0);
    /// assert!(camera.reverse_z && camera.far.is_none());
    /// ```
    pub fn perspective(name: &str, eye: Vec3, target: Vec3, fov_y_deg: f32) -> Self {
        Self {
            name: name.to_string(),
            eye,
            target,
            up: Vec3::Y,
            lens: Lens::Perspective { fov_y_deg },
            near: None,
            far: None,
            reverse_z: true,
        }
    }

    /// A camera that shows all of `bounds` from above and to the side.
    ///
    /// ```
    /// use aokit_scene::{Camera, shapes};
    /// use glam::Vec3;
    /// let ball = shapes::sphere(Vec3::new(3.0, 1.0, 0.0), 1.0, Vec3::ONE);
    /// let camera = Camera::framing(&ball.bounds().unwrap());
    /// assert_eq!(camera.target, Vec3::new(3.0, 1.0, 0.0));
    /// assert!(camera.eye.y > camera.target.y);
    /// ```
    pub fn framing(bounds: &Bounds) -> Self {
        let fov_y_deg = 50.0f32;
        let direction = Vec3::new(0.6, 0.5, 1.0).normalize();
        // Distance at which the bounding sphere fits the vertical field of view, with a margin.
        let distance = 1.1 * bounds.radius() / (0.5 * fov_y_deg.to_radians()).sin();
        let center = bounds.center();
        Self::perspective("framing", center + direction * distance, center, fov_y_deg)
    }

    /// Checks the placement and lens, naming what is wrong.
    ///
    /// ```
    /// use aokit_scene::Camera;
    /// use glam::Vec3;
    /// // Looking straight down with +Y up leaves the image's orientation undefined.
    /// let top_down = Camera::perspective("top", Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, 60.0);
    /// let message = top_down.validate().unwrap_err();
    /// assert!(message.contains("parallel"));
    /// ```
    pub fn validate(&self) -> Result<(), String> {
        let forward = self.target - self.eye;
        if !(self.eye.is_finite() && self.target.is_finite() && self.up.is_finite()) {
            return Err(format!(
                "camera `{}` has a non-finite eye, target or up",
                self.name
            ));
        }
        // The length squares each coordinate: past ~1e19 it overflows to infinity, and the
        // normalised direction becomes zero, which the parallel check below would misreport.
        if !forward.length().is_finite() {
            return Err(format!(
                "camera `{}`: eye {} and target {} are too far apart (their distance overflows \
                 32-bit floats)",
                self.name, self.eye, self.target
            ));
        }
        if forward.length() < 1e-6 {
            return Err(format!(
                "camera `{}`: eye and target are the same point",
                self.name
            ));
        }
        if !(self.up.length() > 1e-6 && self.up.length().is_finite()) {
            return Err(format!(
                "camera `{}`: up {} has no direction (zero length)",
                self.name, self.up
            ));
        }
        // Explicit planes are checked here, before any work: the projection would refuse them
        // only once it is built (after a reference was traced, or by `aokit ao` reading the
        // camera.json written with them).
        if let Some(near) = self.near
            && !(near.is_finite() && near > 0.0)
        {
            return Err(format!(
                "camera `{}`: near plane {near} must be positive and finite",
                self.name
            ));
        }
        if let Some(far) = self.far
            && !(far.is_finite() && far > self.near.unwrap_or(0.0))
        {
            return Err(format!(
                "camera `{}`: far plane {far} must be finite and greater than the near plane{}",
                self.name,
                self.near.map(|n| format!(" ({n})")).unwrap_or_default()
            ));
        }
        if forward
            .normalize()
            .cross(self.up.normalize_or_zero())
            .length()
            < 1e-4
        {
            return Err(format!(
                "camera `{}`: up {} is parallel to the view direction",
                self.name, self.up
            ));
        }
        match self.lens {
            Lens::Perspective { fov_y_deg } if !(fov_y_deg > 0.0 && fov_y_deg < 180.0) => {
                Err(format!(
                    "camera `{}`: vertical field of view {fov_y_deg} is not in (0, 180) degrees",
                    self.name
                ))
            }
            Lens::Orthographic { height } if !(height.is_finite() && height > 0.0) => Err(format!(
                "camera `{}`: orthographic height {height} is not positive",
                self.name
            )),
            _ => Ok(()),
        }
    }

    /// World to view transform (right-handed, looking down -Z).
    ///
    /// ```
    /// use aokit_scene::Camera;
    /// use glam::Vec3;
    /// let camera = Camera::perspective("c", Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, 60.0);
    /// let target = camera.view_from_world().transform_point3(camera.target);
    /// assert!((target - Vec3::new(0.0, 0.0, -4.0)).length() < 1e-6);
    /// ```
    pub fn view_from_world(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye, self.target, self.up)
    }

    /// The projection for a viewport of `aspect` (width / height), with near and far planes
    /// chosen from `bounds` where the camera leaves them open.
    ///
    /// ```
    /// use aokit_scene::Scene;
    /// let scene = Scene::open("room").unwrap();
    /// let camera = scene.camera(None)?;
    /// let projection = camera.projection(16.0 / 9.0, &scene.bounds);
    /// projection.validate().unwrap();
    /// // The fitted near plane is a small fraction of the scene.
    /// assert!(projection.near < 0.01 * scene.bounds.radius());
    /// # Ok::<(), aokit_scene::SceneError>(())
    /// ```
    pub fn projection(&self, aspect: f32, bounds: &Bounds) -> Projection {
        let to_center = (bounds.center() - self.eye).length();
        let radius = bounds.radius().max(1e-3);
        let (kind, near, far) = match self.lens {
            Lens::Perspective { fov_y_deg } => (
                ProjectionKind::Perspective {
                    fov_y: fov_y_deg.to_radians(),
                },
                // Reverse-Z float depth is precise at any near plane; a thousandth of the scene
                // keeps close-up geometry from being clipped.
                self.near.unwrap_or(1e-3 * radius),
                self.far,
            ),
            Lens::Orthographic { height } => {
                let near = self.near.unwrap_or((to_center - radius).max(1e-3 * radius));
                let far = self.far.unwrap_or((to_center + radius).max(near * 2.0));
                (ProjectionKind::Orthographic { height }, near, Some(far))
            }
        };
        Projection {
            kind,
            aspect,
            near,
            far,
            reverse_z: self.reverse_z,
            ndc_offset: glam::Vec2::ZERO,
        }
    }
}

/// The `camera.json` written beside G-buffer exports: everything needed to turn the depth and
/// normal images back into view-space geometry. See docs/camera-json.md.
///
/// ```
/// use aokit::Projection;
/// use aokit_scene::CameraFile;
/// use glam::Vec3;
/// use glam::camera::rh::view::look_at_mat4;
/// let projection = Projection::perspective(1.0, 4.0 / 3.0, 0.1, None);
/// let view = look_at_mat4(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y);
/// let json = serde_json::to_string_pretty(&CameraFile::new(&projection, view, [640, 480]))?;
/// // A tool reading the export back gets the same camera.
/// let file: CameraFile = serde_json::from_str(&json)?;
/// assert_eq!(file.projection()?, projection);
/// assert_eq!(file.view_from_world(), view);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraFile {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// `perspective` or `orthographic`.
    pub projection: String,
    /// Vertical field of view in degrees (perspective only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fov_y_deg: Option<f32>,
    /// Visible height in world units (orthographic only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ortho_height: Option<f32>,
    /// Near plane distance.
    pub near: f32,
    /// Far plane distance, `null` for an infinite far plane.
    pub far: Option<f32>,
    /// Whether depth is reverse-Z.
    pub reverse_z: bool,
    /// Where the view axis met the image, in NDC ([`Projection::ndc_offset`]): the frame's
    /// jitter or an off-centre frustum. Written only when not zero; absent reads as zero.
    #[serde(
        default,
        skip_serializing_if = "is_zero",
        deserialize_with = "ndc_offset_entries"
    )]
    pub ndc_offset: [f32; 2],
    /// World-to-view matrix, row-major (`view_from_world[row][column]`).
    #[serde(deserialize_with = "matrix_entries")]
    pub view_from_world: [[f32; 4]; 4],
    /// Pixels of overscan on each side of the images beside it (`aokit render --gbuffer
    /// --guard-band`): the depth and normals are `width + 2 * guard_band` by `height + 2 *
    /// guard_band`, drawn through the widened frustum
    /// ([`Projection::with_guard_band`](aokit::Projection::with_guard_band)), while `width`,
    /// `height` and the projection stay the camera's, the inner frame's. Written only when not
    /// zero; absent reads as zero.
    #[serde(default, skip_serializing_if = "is_zero_band")]
    pub guard_band: u32,
}

fn is_zero_band(band: &u32) -> bool {
    *band == 0
}

/// `ndc_offset` as a list checked for length: serde_json reports a fixed-size array with an
/// entry too many as "trailing characters", which names neither the field nor the count.
fn ndc_offset_entries<'de, D: serde::Deserializer<'de>>(d: D) -> Result<[f32; 2], D::Error> {
    let entries = Vec::<f32>::deserialize(d)?;
    <[f32; 2]>::try_from(entries.as_slice()).map_err(|_| {
        serde::de::Error::custom(format!(
            "ndc_offset must have 2 entries (x, y), got {}",
            entries.len()
        ))
    })
}

/// `view_from_world` as rows checked for length, for the same reason.
fn matrix_entries<'de, D: serde::Deserializer<'de>>(d: D) -> Result<[[f32; 4]; 4], D::Error> {
    let rows = Vec::<Vec<f32>>::deserialize(d)?;
    let bad = || {
        serde::de::Error::custom(format!(
            "view_from_world must be 4 rows of 4 numbers, got {} rows of {:?}",
            rows.len(),
            rows.iter().map(Vec::len).collect::<Vec<_>>()
        ))
    };
    let mut matrix = [[0.0; 4]; 4];
    if rows.len() != 4 {
        return Err(bad());
    }
    for (row, entries) in matrix.iter_mut().zip(&rows) {
        *row = <[f32; 4]>::try_from(entries.as_slice()).map_err(|_| bad())?;
    }
    Ok(matrix)
}

fn is_zero(offset: &[f32; 2]) -> bool {
    *offset == [0.0; 2]
}

impl CameraFile {
    /// Describes a rendered image.
    ///
    /// ```
    /// use aokit::Projection;
    /// use aokit_scene::CameraFile;
    /// use glam::Mat4;
    /// let projection = Projection::orthographic(10.0, 2.0, 1.0, 50.0);
    /// let file = CameraFile::new(&projection, Mat4::IDENTITY, [800, 400]);
    /// assert_eq!(file.projection, "orthographic");
    /// assert_eq!((file.ortho_height, file.fov_y_deg), (Some(10.0), None));
    /// ```
    pub fn new(projection: &Projection, view_from_world: Mat4, size: [u32; 2]) -> Self {
        let (name, fov_y_deg, ortho_height) = match projection.kind {
            ProjectionKind::Perspective { fov_y } => {
                ("perspective", Some(fov_y.to_degrees()), None)
            }
            ProjectionKind::Orthographic { height } => ("orthographic", None, Some(height)),
        };
        Self {
            width: size[0],
            height: size[1],
            projection: name.to_string(),
            fov_y_deg,
            ortho_height,
            near: projection.near,
            far: projection.far,
            reverse_z: projection.reverse_z,
            ndc_offset: projection.ndc_offset.to_array(),
            view_from_world: view_from_world.transpose().to_cols_array_2d(),
            guard_band: 0,
        }
    }

    /// The projection described, checked.
    ///
    /// ```
    /// use aokit_scene::CameraFile;
    /// let json = r#"{"width": 640, "height": 480, "projection": "perspective",
    ///     "near": 0.1, "far": null, "reverse_z": true,
    ///     "view_from_world": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}"#;
    /// let file: CameraFile = serde_json::from_str(json).unwrap();
    /// // A hand-written file that forgot the field of view.
    /// assert!(file.projection().unwrap_err().contains("fov_y_deg"));
    /// ```
    pub fn projection(&self) -> Result<Projection, String> {
        let kind = match (self.projection.as_str(), self.fov_y_deg, self.ortho_height) {
            ("perspective", Some(fov), _) => ProjectionKind::Perspective {
                fov_y: fov.to_radians(),
            },
            ("orthographic", _, Some(height)) => ProjectionKind::Orthographic { height },
            ("perspective", None, _) => {
                return Err("perspective camera.json lacks fov_y_deg".into());
            }
            ("orthographic", _, None) => {
                return Err("orthographic camera.json lacks ortho_height".into());
            }
            (other, _, _) => {
                return Err(format!(
                    "camera.json projection `{other}` is neither perspective nor orthographic"
                ));
            }
        };
        if self.width == 0 || self.height == 0 {
            return Err(format!(
                "camera.json size {}x{} is empty",
                self.width, self.height
            ));
        }
        let projection = Projection {
            kind,
            aspect: self.width as f32 / self.height as f32,
            near: self.near,
            far: self.far,
            reverse_z: self.reverse_z,
            ndc_offset: glam::Vec2::from(self.ndc_offset),
        };
        projection.validate().map_err(|e| e.to_string())?;
        Ok(projection)
    }

    /// The world-to-view matrix.
    ///
    /// ```
    /// use aokit::Projection;
    /// use aokit_scene::CameraFile;
    /// use glam::{Mat4, Vec3};
    /// let view = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
    /// let file = CameraFile::new(&Projection::perspective(1.0, 1.0, 0.1, None), view, [8, 8]);
    /// // Stored row-major: the translation ends each row.
    /// assert_eq!(file.view_from_world[0][3], 1.0);
    /// assert_eq!(file.view_from_world(), view);
    /// ```
    pub fn view_from_world(&self) -> Mat4 {
        Mat4::from_cols_array_2d(&self.view_from_world).transpose()
    }

    /// The projection ([`CameraFile::projection`]) and the world-to-view matrix, checked: what
    /// `aokit ao` and the Python package refuse a camera.json for.
    ///
    /// ```
    /// use aokit::Projection;
    /// use aokit_scene::CameraFile;
    /// use glam::Mat4;
    /// let projection = Projection::perspective(1.0, 1.0, 0.1, None);
    /// let mut file = CameraFile::new(&projection, Mat4::IDENTITY, [8, 8]);
    /// assert_eq!(file.checked()?, (projection, Mat4::IDENTITY));
    /// file.view_from_world[1][2] = f32::NAN;
    /// assert!(file.checked().unwrap_err().contains("non-finite"));
    /// # Ok::<(), String>(())
    /// ```
    pub fn checked(&self) -> Result<(Projection, Mat4), String> {
        let projection = self.projection()?;
        let view_from_world = self.view_from_world();
        if !view_from_world.is_finite() {
            return Err("view_from_world has non-finite entries".into());
        }
        Ok((projection, view_from_world))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_file_round_trips_through_json() {
        let camera = Camera::perspective("c", Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO, 60.0);
        let bounds = Bounds {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
        };
        let projection = camera.projection(1.5, &bounds);
        let file = CameraFile::new(&projection, camera.view_from_world(), [300, 200]);
        let json = serde_json::to_string(&file).unwrap();
        assert!(json.contains("\"far\":null"));
        let back: CameraFile = serde_json::from_str(&json).unwrap();
        assert_eq!(back.projection().unwrap(), projection);
        let view = back.view_from_world();
        // Row-major: the translation sits in the last column of each row.
        assert_eq!(file.view_from_world[0][3], view.w_axis.x);
        assert!((view.transform_point3(camera.eye)).length() < 1e-5);
        // Centred: no offset key, as files written before it existed. A jittered one keeps it.
        assert!(!json.contains("ndc_offset"));
        let jittered = projection.with_jitter(glam::Vec2::new(0.5, 0.25), [300, 200]);
        let file = CameraFile::new(&jittered, camera.view_from_world(), [300, 200]);
        let back: CameraFile =
            serde_json::from_str(&serde_json::to_string(&file).unwrap()).unwrap();
        assert_eq!(back.projection().unwrap(), jittered);
    }

    #[test]
    fn framing_camera_sees_the_whole_box() {
        let bounds = Bounds {
            min: Vec3::new(-5.0, 0.0, -2.0),
            max: Vec3::new(5.0, 3.0, 2.0),
        };
        let camera = Camera::framing(&bounds);
        camera.validate().unwrap();
        let clip = camera.projection(1.0, &bounds).clip_from_view() * camera.view_from_world();
        for corner in 0..8 {
            let p = Vec3::new(
                if corner & 1 == 0 {
                    bounds.min.x
                } else {
                    bounds.max.x
                },
                if corner & 2 == 0 {
                    bounds.min.y
                } else {
                    bounds.max.y
                },
                if corner & 4 == 0 {
                    bounds.min.z
                } else {
                    bounds.max.z
                },
            );
            let c = clip * p.extend(1.0);
            let ndc = c.truncate() / c.w;
            assert!(ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0, "{p} -> {ndc}");
        }
    }

    #[test]
    fn degenerate_cameras_are_refused() {
        let mut camera = Camera::perspective("c", Vec3::ONE, Vec3::ONE, 60.0);
        assert!(camera.validate().unwrap_err().contains("same point"));
        camera.target = Vec3::new(1.0, 5.0, 1.0);
        assert!(camera.validate().unwrap_err().contains("parallel"));
    }
}
