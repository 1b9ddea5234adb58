//! The viewer's camera: fly (move the eye, turn about it) and orbit (turn about a point in
//! front of the eye), as pure state the window's input drives.

use aokit_scene::{Camera, Lens};
use glam::{Quat, Vec3};

/// How mouse drags move the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraMode {
    /// WASD moves the eye; a right-button drag turns the view about the eye.
    Fly,
    /// A drag (left or right button) turns the eye about the pivot; the wheel moves nearer or
    /// farther; WASD moves eye and pivot together.
    Orbit,
}

impl CameraMode {
    /// The name the panel shows.
    pub fn name(self) -> &'static str {
        match self {
            CameraMode::Fly => "fly",
            CameraMode::Orbit => "orbit",
        }
    }
}

/// Radians the view turns per pixel of mouse movement.
const TURN_PER_PIXEL: f32 = 0.004;

/// Closest the view direction comes to straight up or down, in radians: the pose stays
/// expressible as eye/target/up without a degenerate up.
const POLE_MARGIN: f32 = 0.02;

/// A camera the user moves: the eye, the direction it looks, the distance to the orbit pivot,
/// and the lens, planes and depth convention of the scene camera it started from.
#[derive(Clone, Debug)]
pub struct ViewCamera {
    /// Eye position.
    pub eye: Vec3,
    /// Unit view direction.
    pub forward: Vec3,
    /// Unit world up the view turns about (the starting camera's up).
    pub up: Vec3,
    /// Distance from the eye to the orbit pivot (and to the target the pose prints).
    pub distance: f32,
    /// How drags move it.
    pub mode: CameraMode,
    /// Flying speed in world units per second (before the fast modifier).
    pub speed: f32,
    /// The camera this one started from: its lens, planes and depth convention are kept.
    pub base: Camera,
}

/// Which way to move, each component -1, 0 or 1: right, up, forward.
pub type MoveInput = Vec3;

impl ViewCamera {
    /// Starts at `camera`'s pose; `scene_radius` (the radius of the scene's bounding sphere)
    /// sets the flying speed: the scene is crossed in about eight seconds.
    pub fn new(camera: &Camera, scene_radius: f32) -> Self {
        let offset = camera.target - camera.eye;
        let distance = offset.length().max(1e-4);
        let up = camera.up.try_normalize().unwrap_or(Vec3::Y);
        Self {
            eye: camera.eye,
            forward: offset / distance,
            up,
            distance,
            mode: CameraMode::Fly,
            speed: speed_for(scene_radius),
            base: camera.clone(),
        }
    }

    /// Jumps to `camera`'s pose (a bookmark), keeping the mode and speed.
    pub fn jump_to(&mut self, camera: &Camera) {
        let (mode, speed) = (self.mode, self.speed);
        *self = Self {
            mode,
            speed,
            ..Self::new(camera, 1.0)
        };
    }

    /// The unit vector to the right of the view.
    pub fn right(&self) -> Vec3 {
        self.forward
            .cross(self.up)
            .try_normalize()
            .unwrap_or(Vec3::X)
    }

    /// The point the camera looks at: the orbit pivot.
    pub fn target(&self) -> Vec3 {
        self.eye + self.forward * self.distance
    }

    /// Moves by `input` (right, up, forward) for `seconds`, `fast` times four.
    pub fn fly(&mut self, input: MoveInput, seconds: f32, fast: bool) {
        let scale = self.speed * seconds * if fast { 4.0 } else { 1.0 };
        let step = self.right() * input.x + self.up * input.y + self.forward * input.z;
        self.eye += step * scale;
    }

    /// Turns by a mouse movement of `dx`, `dy` pixels: about the eye in fly mode, about the
    /// pivot in orbit mode. The view never reaches straight up or down.
    pub fn turn(&mut self, dx: f32, dy: f32) {
        let pivot = self.target();
        let yaw = Quat::from_axis_angle(self.up, -dx * TURN_PER_PIXEL);
        let forward = yaw * self.forward;
        // Pitch, limited so that the angle to the up axis stays inside (margin, pi - margin).
        let angle_to_up = forward.angle_between(self.up);
        let pitch = (-dy * TURN_PER_PIXEL).clamp(
            -(std::f32::consts::PI - POLE_MARGIN - angle_to_up),
            angle_to_up - POLE_MARGIN,
        );
        let right = forward.cross(self.up).try_normalize().unwrap_or(Vec3::X);
        self.forward = (Quat::from_axis_angle(right, pitch) * forward).normalize();
        if self.mode == CameraMode::Orbit {
            self.eye = pivot - self.forward * self.distance;
        }
    }

    /// A wheel movement of `steps` notches: orbit moves the eye towards the pivot (positive)
    /// or away; fly changes the speed.
    pub fn wheel(&mut self, steps: f32) {
        let factor = 0.85f32.powf(steps.clamp(-10.0, 10.0));
        match self.mode {
            CameraMode::Orbit => {
                let pivot = self.target();
                self.distance = (self.distance * factor).max(1e-3);
                self.eye = pivot - self.forward * self.distance;
            }
            CameraMode::Fly => self.speed = (self.speed / factor).clamp(1e-4, 1e6),
        }
    }

    /// The camera to render: the pose with the starting camera's lens and planes.
    pub fn camera(&self) -> Camera {
        Camera {
            name: "view".to_string(),
            eye: self.eye,
            target: self.target(),
            up: self.up,
            ..self.base.clone()
        }
    }

    /// The pose as flags the other commands take: `--eye X,Y,Z --target X,Y,Z --up X,Y,Z`,
    /// then the lens where `--eye` alone would not give it (`--fov-y` other than 60,
    /// `--ortho-height`).
    pub fn flags(&self) -> String {
        let v = |v: Vec3| format!("{},{},{}", round(v.x), round(v.y), round(v.z));
        let mut flags = format!(
            "--eye {} --target {} --up {}",
            v(self.eye),
            v(self.target()),
            v(self.up)
        );
        match self.base.lens {
            Lens::Perspective { fov_y_deg } if fov_y_deg != 60.0 => {
                flags += &format!(" --fov-y {}", round(fov_y_deg));
            }
            Lens::Orthographic { height } => flags += &format!(" --ortho-height {}", round(height)),
            Lens::Perspective { .. } => {}
        }
        flags
    }
}

/// Flying speed for a scene whose bounding sphere has `radius`: its diameter in eight seconds.
pub fn speed_for(radius: f32) -> f32 {
    if radius.is_finite() && radius > 0.0 {
        radius * 0.25
    } else {
        1.0
    }
}

/// `value` to four decimals, without trailing zeros (`1.5`, `-0.1234`, `0`).
fn round(value: f32) -> String {
    let text = format!("{:.4}", value);
    let text = text.trim_end_matches('0').trim_end_matches('.');
    match text {
        "-0" | "" => "0".to_string(),
        _ => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn start() -> ViewCamera {
        let camera = Camera::perspective(
            "front",
            Vec3::new(0.0, 1.0, 5.0),
            Vec3::new(0.0, 1.0, 0.0),
            60.0,
        );
        ViewCamera::new(&camera, 4.0)
    }

    #[test]
    fn flying_forward_moves_towards_the_target_at_the_scene_speed() {
        let mut view = start();
        assert_eq!(view.speed, 1.0);
        view.fly(Vec3::Z, 2.0, false);
        assert!((view.eye - Vec3::new(0.0, 1.0, 3.0)).length() < 1e-5);
        view.fly(Vec3::X, 1.0, true);
        // Right of a camera looking down -Z is +X.
        assert!((view.eye - Vec3::new(4.0, 1.0, 3.0)).length() < 1e-5);
    }

    #[test]
    fn orbiting_keeps_the_pivot_and_distance() {
        let mut view = start();
        view.mode = CameraMode::Orbit;
        let pivot = view.target();
        view.turn(300.0, -120.0);
        assert!((view.target() - pivot).length() < 1e-4);
        assert!(((view.eye - pivot).length() - 5.0).abs() < 1e-4);
        view.wheel(2.0);
        assert!((view.target() - pivot).length() < 1e-4);
        assert!((view.eye - pivot).length() < 5.0);
    }

    #[test]
    fn the_view_stops_short_of_the_poles() {
        let mut view = start();
        view.turn(0.0, -100_000.0);
        let angle = view.forward.angle_between(view.up);
        assert!(angle >= POLE_MARGIN * 0.99, "{angle}");
        view.camera().validate().unwrap();
        view.turn(0.0, 100_000.0);
        let angle = view.forward.angle_between(-view.up);
        assert!(angle >= POLE_MARGIN * 0.99, "{angle}");
        view.camera().validate().unwrap();
    }

    #[test]
    fn the_pose_prints_as_flags_that_parse_back() {
        let mut view = start();
        assert_eq!(view.flags(), "--eye 0,1,5 --target 0,1,0 --up 0,1,0");
        view.base.lens = Lens::Perspective { fov_y_deg: 45.0 };
        view.eye = Vec3::new(-1.23456, 0.5, 2.0);
        let flags = view.flags();
        assert!(
            flags.starts_with("--eye -1.2346,0.5,2 --target "),
            "{flags}"
        );
        assert!(flags.ends_with(" --fov-y 45"), "{flags}");
        let eye = flags.split(' ').nth(1).unwrap();
        assert!(crate::camera_args::parse_vec3(eye).is_ok());
    }
}
