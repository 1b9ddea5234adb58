//! Moving parts: rigid motions over a sequence, so that the raster and the reference tracer
//! place the same triangles at any point of it.
//!
//! Time runs from 0 (the first frame) to 1 (the last), as along a
//! [`CameraPath`](crate::CameraPath). At time 0 every part is where the scene's mesh holds it,
//! so a single frame, or a sequence rendered without animation, shows the scene as it always was.

use std::ops::Range;

use glam::{Mat4, Vec3};

/// A rigid motion at constant speed: by time `t` the part has turned `t * degrees` about `axis`
/// through `pivot`, and the pivot has moved by `t * translation`. Constant speed means the part
/// is still moving at the last frame, where sequences are scored.
///
/// ```
/// use aokit_scene::Motion;
/// use glam::Vec3;
/// // A part that slides 2 units along +x while turning half a turn about its own centre.
/// let centre = Vec3::new(0.0, 1.0, 0.0);
/// let motion =
///     Motion { pivot: centre, axis: Vec3::Y, degrees: 180.0, translation: 2.0 * Vec3::X };
/// let halfway = motion.transform_at(0.5);
/// assert!((halfway.transform_point3(centre) - Vec3::new(1.0, 1.0, 0.0)).length() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// The point the part turns about, where it rests.
    pub pivot: Vec3,
    /// Unit axis of the turn (right-handed).
    pub axis: Vec3,
    /// The whole turn, in degrees.
    pub degrees: f32,
    /// The pivot's whole move.
    pub translation: Vec3,
}

impl Motion {
    /// A move by `translation` without turning.
    ///
    /// ```
    /// use aokit_scene::Motion;
    /// use glam::Vec3;
    /// let drawer = Motion::slide(Vec3::new(0.0, 0.0, 0.4));
    /// let handle = Vec3::new(0.3, 0.8, 0.0);
    /// let open = drawer.transform_at(1.0).transform_point3(handle);
    /// assert!((open - Vec3::new(0.3, 0.8, 0.4)).length() < 1e-6);
    /// ```
    pub fn slide(translation: Vec3) -> Self {
        Self {
            pivot: Vec3::ZERO,
            axis: Vec3::Y,
            degrees: 0.0,
            translation,
        }
    }

    /// A turn of `degrees` about `axis` through `pivot`: a door on its hinge.
    ///
    /// ```
    /// use aokit_scene::Motion;
    /// use glam::Vec3;
    /// let hinge = Vec3::new(2.0, 0.0, 0.0);
    /// let door = Motion::swing(hinge, Vec3::Y, 90.0);
    /// // The hinge stays put while the far edge swings round.
    /// let at_end = door.transform_at(1.0);
    /// assert!((at_end.transform_point3(hinge) - hinge).length() < 1e-6);
    /// let edge = at_end.transform_point3(hinge + Vec3::X);
    /// assert!((edge - (hinge + Vec3::NEG_Z)).length() < 1e-6);
    /// ```
    pub fn swing(pivot: Vec3, axis: Vec3, degrees: f32) -> Self {
        Self {
            pivot,
            axis: axis.normalize(),
            degrees,
            translation: Vec3::ZERO,
        }
    }

    /// A ball of `radius` centred at `center` rolling by `translation` over a floor facing
    /// `up`, without slipping: the point touching the floor stands still, so the ball turns
    /// about `up x translation` by the distance over the radius.
    ///
    /// ```
    /// use aokit_scene::Motion;
    /// use glam::Vec3;
    /// let (centre, radius) = (Vec3::new(0.0, 0.5, 0.0), 0.5);
    /// let ball = Motion::roll(centre, radius, Vec3::new(1.0, 0.0, 0.0), Vec3::Y);
    /// // Rolling one unit on a radius of 0.5 turns the ball by 2 radians.
    /// assert!((ball.degrees - 2f32.to_degrees()).abs() < 1e-3);
    /// assert_eq!(ball.axis, Vec3::NEG_Z);
    /// ```
    pub fn roll(center: Vec3, radius: f32, translation: Vec3, up: Vec3) -> Self {
        Self {
            pivot: center,
            axis: up.cross(translation).normalize(),
            degrees: (translation.length() / radius).to_degrees(),
            translation,
        }
    }

    /// The transform from the part's rest pose to its pose at time `t`; exactly the identity
    /// at 0.
    ///
    /// ```
    /// use aokit_scene::animation::Motion;
    /// use glam::Vec3;
    /// let ball = Motion::roll(Vec3::Y, 1.0, Vec3::new(std::f32::consts::PI, 0.0, 0.0), Vec3::Y);
    /// let top = Vec3::new(0.0, 2.0, 0.0);
    /// // Half a turn later the top of the ball touches the floor.
    /// let moved = ball.transform_at(1.0).transform_point3(top);
    /// assert!((moved - Vec3::new(std::f32::consts::PI, 0.0, 0.0)).length() < 1e-5);
    /// assert_eq!(ball.transform_at(0.0).transform_point3(top), top);
    /// ```
    pub fn transform_at(&self, t: f32) -> Mat4 {
        Mat4::from_translation(self.pivot + t * self.translation)
            * Mat4::from_axis_angle(self.axis, (t * self.degrees).to_radians())
            * Mat4::from_translation(-self.pivot)
    }
}

/// A rigid part of a scene's mesh that moves over a sequence.
///
/// ```
/// use aokit_scene::{Motion, MovingPart, Scene, shapes};
/// use glam::Vec3;
/// let floor_corner = Vec3::new(-5.0, 0.0, 5.0);
/// let mut mesh = shapes::quad(floor_corner, 10.0 * Vec3::X, -10.0 * Vec3::Z, Vec3::ONE);
/// // The box's vertices come after the floor's: those are the ones that move.
/// let first = mesh.positions.len() as u32;
/// mesh.append(&shapes::cuboid(Vec3::ZERO, Vec3::ONE, 0.0, Vec3::ONE));
/// let mut scene = Scene::new("sliding box", mesh, Vec::new(), Some(0.5));
/// scene.moving_parts.push(MovingPart {
///     vertices: first..scene.mesh.positions.len() as u32,
///     motion: Motion::slide(Vec3::new(2.0, 0.0, 0.0)),
/// });
/// let end = scene.mesh_at(1.0);
/// assert_eq!(end.positions[0], scene.mesh.positions[0]);
/// assert_eq!(end.positions[first as usize].x, scene.mesh.positions[first as usize].x + 2.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct MovingPart {
    /// Its vertices in [`Scene::mesh`](crate::Scene::mesh), which holds them at rest (time 0).
    /// The part's triangles use these vertices only, and no other part's.
    pub vertices: Range<u32>,
    /// How it moves.
    pub motion: Motion,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rolling_ball_does_not_slip() {
        let (center, radius) = (Vec3::new(1.0, 0.5, -2.0), 0.5);
        let ball = Motion::roll(center, radius, Vec3::new(0.0, 0.0, 0.8), Vec3::Y);
        let contact = center - radius * Vec3::Y;
        let dt = 1e-3;
        for t in [0.0, 0.5, 1.0 - dt] {
            // The material point touching the floor at time t has no velocity there.
            let touching = ball
                .transform_at(t)
                .inverse()
                .transform_point3(contact + t * ball.translation);
            let a = ball.transform_at(t).transform_point3(touching);
            let b = ball.transform_at(t + dt).transform_point3(touching);
            assert!((b - a).length() / dt < 1e-2, "slips at {t}: {a} -> {b}");
            // The centre moves with the translation.
            let c = ball.transform_at(t).transform_point3(center);
            assert!((c - center - t * ball.translation).length() < 1e-5);
        }
    }

    #[test]
    fn slides_and_swings_move_as_named() {
        let slide = Motion::slide(Vec3::new(0.0, 0.0, 0.6));
        let p = Vec3::new(3.0, 0.4, -3.0);
        let moved = slide.transform_at(0.5).transform_point3(p);
        assert!((moved - Vec3::new(3.0, 0.4, -2.7)).length() < 1e-6);
        let hinge = Vec3::new(1.7, 0.0, -2.5);
        let door = Motion::swing(hinge, Vec3::Y, 90.0);
        let edge = door
            .transform_at(1.0)
            .transform_point3(hinge + Vec3::new(0.8, 1.0, 0.0));
        // A quarter turn about +Y takes +X to -Z.
        assert!(
            (edge - (hinge + Vec3::new(0.0, 1.0, -0.8))).length() < 1e-5,
            "{edge}"
        );
    }
}
