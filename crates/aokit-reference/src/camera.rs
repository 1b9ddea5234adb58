//! The pixel grid of a camera: one primary ray through each pixel centre.

use glam::{DVec3, Mat4, Vec3};

/// What the camera sees through.
///
/// ```
/// use aokit_reference::{Lens, PixelCamera};
/// use glam::Vec3;
/// // A top-down map view, 10 world units tall, from 100 units up.
/// let camera = PixelCamera {
///     size: [64, 64],
///     lens: Lens::Orthographic { height: 10.0 },
///     view_from_world: glam::camera::rh::view::look_at_mat4(
///         Vec3::new(0.0, 100.0, 0.0), Vec3::ZERO, Vec3::NEG_Z),
///     near: 1.0,
///     far: Some(200.0),
/// };
/// // Parallel rays: every pixel looks straight down.
/// assert!((camera.ray(0, 0).direction - Vec3::NEG_Y).length() < 1e-6);
/// assert!((camera.ray(63, 40).direction - Vec3::NEG_Y).length() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lens {
    /// Pinhole with a full vertical field of view in radians.
    Perspective {
        /// Vertical field of view, radians, in `(0, pi)`.
        fov_y: f32,
    },
    /// Parallel projection `height` world units tall.
    Orthographic {
        /// Visible height in world units.
        height: f32,
    },
}

/// A camera as a grid of pixels, matching a rasteriser's: pixel `(x, y)` counts from the top
/// left and is sampled at its centre `(x + 0.5, y + 0.5)`; view space is right-handed with the
/// camera looking down -Z; geometry nearer than `near` or beyond `far` is clipped.
///
/// ```
/// use aokit_reference::{Lens, PixelCamera};
/// use glam::{Mat4, Vec3};
/// let camera = PixelCamera {
///     size: [320, 180],
///     lens: Lens::Perspective { fov_y: 60f32.to_radians() },
///     view_from_world: Mat4::IDENTITY,
///     near: 0.1,
///     far: None,
/// };
/// assert_eq!(camera.pixel_count(), 320 * 180);
/// // Pixel (0, 0) is the top-left one: its ray leans left and up.
/// let corner = camera.ray(0, 0).direction;
/// assert!(corner.x < 0.0 && corner.y > 0.0 && corner.z < 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelCamera {
    /// Width and height in pixels.
    pub size: [u32; 2],
    /// Lens.
    pub lens: Lens,
    /// World-to-view transform.
    pub view_from_world: Mat4,
    /// Near clipping distance along the view axis.
    pub near: f32,
    /// Far clipping distance along the view axis, `None` for none.
    pub far: Option<f32>,
}

/// A primary ray in world space.
///
/// ```
/// use aokit_reference::{Lens, PixelCamera, Tracer};
/// use glam::{Mat4, Vec3};
/// // A wall 4 units in front of the eye.
/// let wall = [Vec3::new(-9.0, -9.0, -4.0), Vec3::new(9.0, -9.0, -4.0),
///             Vec3::new(9.0, 9.0, -4.0), Vec3::new(-9.0, 9.0, -4.0)];
/// let tracer = Tracer::new(&wall, &[0, 1, 2, 0, 2, 3])?;
/// let camera = PixelCamera {
///     size: [16, 16],
///     lens: Lens::Perspective { fov_y: 1.0 },
///     view_from_world: Mat4::IDENTITY,
///     near: 0.1,
///     far: None,
/// };
/// let ray = camera.ray(2, 13);
/// let hit = tracer.closest_hit(ray.origin, ray.direction, ray.t_min, ray.t_max).unwrap();
/// // Off-centre rays travel farther than the depth the rasteriser stores.
/// assert!(hit.t > 4.0);
/// assert!((hit.t * ray.depth_per_t - 4.0).abs() < 1e-4);
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PrimaryRay {
    /// World-space origin.
    pub origin: Vec3,
    /// World-space unit direction.
    pub direction: Vec3,
    /// First `t` inside the view volume (the near plane).
    pub t_min: f32,
    /// Last `t` inside the view volume (the far plane, or infinity).
    pub t_max: f32,
    /// Linear view depth at `t` is `t * depth_per_t`: both lenses start rays in the eye's plane.
    pub depth_per_t: f32,
}

impl PixelCamera {
    /// The ray through the centre of pixel `(x, y)`.
    ///
    /// ```
    /// use aokit_reference::{Lens, PixelCamera};
    /// use glam::{Mat4, Vec3};
    /// let camera = PixelCamera {
    ///     size: [3, 3],
    ///     lens: Lens::Perspective { fov_y: 1.0 },
    ///     view_from_world: Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0)),
    ///     near: 0.5,
    ///     far: Some(50.0),
    /// };
    /// // The middle pixel of an odd-sized image looks along the view axis from the eye.
    /// let ray = camera.ray(1, 1);
    /// assert!((ray.origin - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-6);
    /// assert!((ray.direction - Vec3::NEG_Z).length() < 1e-6);
    /// assert!((ray.t_min - 0.5).abs() < 1e-6 && (ray.t_max - 50.0).abs() < 1e-4);
    /// ```
    pub fn ray(&self, x: u32, y: u32) -> PrimaryRay {
        self.ray_through(f64::from(x) + 0.5, f64::from(y) + 0.5)
    }

    /// The ray through the point `(px, py)` of the image, in pixels from the top-left corner.
    /// The camera math runs in double precision so that rays agree with the rasteriser's to
    /// the last bit of single precision.
    ///
    /// ```
    /// use aokit_reference::{Lens, PixelCamera};
    /// use glam::{Mat4, Vec3};
    /// let camera = PixelCamera {
    ///     size: [4, 2],
    ///     lens: Lens::Orthographic { height: 2.0 },
    ///     view_from_world: Mat4::IDENTITY,
    ///     near: 0.1,
    ///     far: Some(10.0),
    /// };
    /// // Sub-pixel positions, as for supersampling: the image's top-left corner.
    /// let ray = camera.ray_through(0.0, 0.0);
    /// assert!((ray.origin - Vec3::new(-2.0, 1.0, 0.0)).length() < 1e-6);
    /// ```
    pub fn ray_through(&self, px: f64, py: f64) -> PrimaryRay {
        let [w, h] = self.size.map(f64::from);
        let ndc_x = 2.0 * px / w - 1.0;
        let ndc_y = 1.0 - 2.0 * py / h;
        let aspect = w / h;
        let world_from_view = self.view_from_world.as_dmat4().inverse();
        let (origin_view, direction_view) = match self.lens {
            Lens::Perspective { fov_y } => {
                let half = (0.5 * f64::from(fov_y)).tan();
                (
                    DVec3::ZERO,
                    DVec3::new(ndc_x * half * aspect, ndc_y * half, -1.0).normalize(),
                )
            }
            Lens::Orthographic { height } => {
                let half = 0.5 * f64::from(height);
                (
                    DVec3::new(ndc_x * half * aspect, ndc_y * half, 0.0),
                    DVec3::NEG_Z,
                )
            }
        };
        let depth_per_t = -direction_view.z;
        let far = self.far.map_or(f64::INFINITY, f64::from);
        PrimaryRay {
            origin: world_from_view.transform_point3(origin_view).as_vec3(),
            direction: world_from_view
                .transform_vector3(direction_view)
                .normalize()
                .as_vec3(),
            t_min: (f64::from(self.near) / depth_per_t) as f32,
            t_max: (far / depth_per_t) as f32,
            depth_per_t: depth_per_t as f32,
        }
    }

    /// Number of pixels, `width * height`.
    pub fn pixel_count(&self) -> usize {
        self.size[0] as usize * self.size[1] as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera(lens: Lens) -> PixelCamera {
        PixelCamera {
            size: [4, 2],
            lens,
            view_from_world: glam::camera::rh::view::look_at_mat4(
                Vec3::new(0.0, 0.0, 5.0),
                Vec3::ZERO,
                Vec3::Y,
            ),
            near: 0.5,
            far: Some(50.0),
        }
    }

    #[test]
    fn perspective_rays_leave_the_eye_through_pixel_centres() {
        let c = camera(Lens::Perspective {
            fov_y: 90f32.to_radians(),
        });
        let ray = c.ray(3, 0);
        assert!((ray.origin - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-6);
        // Pixel (3, 0) of 4x2 is at NDC (0.75, 0.5); tan(45 deg) = 1 and aspect 2.
        let expected = Vec3::new(1.5, 0.5, -1.0).normalize();
        assert!(
            (ray.direction - expected).length() < 1e-6,
            "{}",
            ray.direction
        );
        assert!((ray.t_min * ray.depth_per_t - 0.5).abs() < 1e-6);
        assert!((ray.t_max * ray.depth_per_t - 50.0).abs() < 1e-4);
    }

    #[test]
    fn orthographic_rays_are_parallel() {
        let c = camera(Lens::Orthographic { height: 2.0 });
        let a = c.ray(0, 0);
        let b = c.ray(3, 1);
        assert_eq!(a.direction, b.direction);
        assert!((a.origin - Vec3::new(-1.5, 0.5, 5.0)).length() < 1e-6);
        assert!((b.origin - Vec3::new(1.5, -0.5, 5.0)).length() < 1e-6);
        assert_eq!(a.depth_per_t, 1.0);
    }
}
