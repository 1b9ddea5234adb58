//! Camera paths: a camera moved over a sequence of frames, for temporal filtering and its tests.

use glam::{Mat3, Vec3};

use crate::camera::Camera;

/// How a camera moves over a sequence of frames.
///
/// ```
/// use aokit_scene::{Camera, CameraPath};
/// use glam::Vec3;
/// let path: CameraPath = "orbit".parse()?;
/// let camera = Camera::perspective("c", Vec3::new(0.0, 2.0, 6.0), Vec3::ZERO, 60.0);
/// // The cameras of a 5-frame sequence.
/// let cameras: Vec<Camera> = (0..5).map(|i| path.at(&camera, i as f32 / 4.0)).collect();
/// // An orbit keeps its distance to the target.
/// assert!(cameras.iter().all(|c| (c.eye.distance(c.target) - camera.eye.length()).abs() < 1e-4));
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPath {
    /// The camera does not move: what is left changing is the sampling noise (flicker).
    Still,
    /// The eye circles the target about the up axis, 40 degrees in all, centred on the camera.
    Orbit,
    /// The eye moves towards the target, 30% of the way.
    Dolly,
    /// Eye and target move sideways together, 40% of the eye's distance to the target in all.
    Strafe,
}

impl CameraPath {
    /// Every path, as the CLI lists them.
    pub const ALL: [CameraPath; 4] = [
        CameraPath::Still,
        CameraPath::Orbit,
        CameraPath::Dolly,
        CameraPath::Strafe,
    ];

    /// The name used on the command line.
    ///
    /// ```
    /// use aokit_scene::CameraPath;
    /// let help = CameraPath::ALL.map(CameraPath::name).join(", ");
    /// assert_eq!(help, "still, orbit, dolly, strafe");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            CameraPath::Still => "still",
            CameraPath::Orbit => "orbit",
            CameraPath::Dolly => "dolly",
            CameraPath::Strafe => "strafe",
        }
    }

    /// `camera` at point `t` of the path, `t` from 0 (start) to 1 (end).
    ///
    /// ```
    /// use aokit_scene::{Camera, CameraPath};
    /// use glam::Vec3;
    /// let camera = Camera::perspective("c", Vec3::new(0.0, 1.0, 5.0), Vec3::ZERO, 60.0);
    /// let start = CameraPath::Dolly.at(&camera, 0.0);
    /// let end = CameraPath::Dolly.at(&camera, 1.0);
    /// assert_eq!(start, camera);
    /// assert!(end.eye.distance(end.target) < camera.eye.distance(camera.target));
    /// ```
    pub fn at(self, camera: &Camera, t: f32) -> Camera {
        let forward = camera.target - camera.eye;
        let up = camera.up.normalize_or(Vec3::Y);
        let (eye, target) = match self {
            CameraPath::Still => (camera.eye, camera.target),
            CameraPath::Orbit => {
                let angle = (t - 0.5) * 40f32.to_radians();
                (
                    camera.target - Mat3::from_axis_angle(up, angle) * forward,
                    camera.target,
                )
            }
            CameraPath::Dolly => (camera.eye + 0.3 * t * forward, camera.target),
            CameraPath::Strafe => {
                let right = forward.cross(up).normalize_or(Vec3::X);
                let shift = (t - 0.5) * 0.4 * forward.length() * right;
                (camera.eye + shift, camera.target + shift)
            }
        };
        Camera {
            eye,
            target,
            ..camera.clone()
        }
    }
}

impl std::str::FromStr for CameraPath {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        CameraPath::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                let known: Vec<&str> = CameraPath::ALL.iter().map(|p| p.name()).collect();
                format!("unknown camera path `{s}` (known: {})", known.join(", "))
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_keep_the_distance_or_move_as_described() {
        let camera = Camera::perspective(
            "c",
            Vec3::new(2.0, 3.0, 6.0),
            Vec3::new(0.0, 1.0, 0.0),
            50.0,
        );
        let distance = camera.eye.distance(camera.target);
        for t in [0.0, 0.25, 1.0] {
            let orbit = CameraPath::Orbit.at(&camera, t);
            assert!((orbit.eye.distance(orbit.target) - distance).abs() < 1e-4);
            assert!(
                (orbit.eye.y - camera.eye.y).abs() < 1e-4,
                "orbits about the up axis"
            );
            assert_eq!(CameraPath::Still.at(&camera, t), camera);
        }
        let a = CameraPath::Strafe.at(&camera, 0.0);
        let b = CameraPath::Strafe.at(&camera, 1.0);
        assert!(((a.eye - b.eye).length() - 0.4 * distance).abs() < 1e-4);
        assert_eq!(a.target - a.eye, camera.target - camera.eye);
        assert!("spin".parse::<CameraPath>().unwrap_err().contains("orbit"));
    }
}
