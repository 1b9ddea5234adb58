//! Procedural scenes made in code, in metres with +Y up.

use glam::{Quat, Vec3};

use crate::animation::{Motion, MovingPart};
use crate::camera::Camera;
use crate::mesh::Mesh;
use crate::scene::Scene;
use crate::shapes::{cuboid, quad, sphere};

/// The built-in scenes.
///
/// ```
/// use aokit_scene::Builtin;
/// // A test over every built-in, as the CLI's `--scene` names them.
/// for builtin in Builtin::ALL {
///     assert_eq!(Builtin::from_name(builtin.name()), Some(builtin));
/// }
/// assert_eq!(Builtin::from_name("sponza"), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// A room without ceiling or front wall, with a sphere and boxes: the classic AO showcase.
    Room,
    /// A staircase between walls, with a row of blocks: steps, crevices, concave corners.
    Stairs,
    /// Thin pillars, a fence and panels in front of a wall: where screen-space AO over-occludes.
    Thin,
    /// One plane: AO must be about 1 everywhere.
    Open,
}

impl Builtin {
    /// Every built-in, the default first.
    pub const ALL: [Builtin; 4] = [Builtin::Room, Builtin::Stairs, Builtin::Thin, Builtin::Open];

    /// The name `--scene` takes.
    ///
    /// ```
    /// use aokit_scene::Builtin;
    /// let names: Vec<&str> = Builtin::ALL.iter().map(|b| b.name()).collect();
    /// assert_eq!(names, ["room", "stairs", "thin", "open"]);
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Room => "room",
            Builtin::Stairs => "stairs",
            Builtin::Thin => "thin",
            Builtin::Open => "open",
        }
    }

    /// Looks a built-in up by name.
    ///
    /// ```
    /// use aokit_scene::Builtin;
    /// assert_eq!(Builtin::from_name("stairs"), Some(Builtin::Stairs));
    /// // Names are exact, as the CLI prints them.
    /// assert_eq!(Builtin::from_name("Stairs"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }

    /// Builds the scene, its moving parts at rest.
    ///
    /// ```
    /// use aokit_scene::Builtin;
    /// let scene = Builtin::Open.build();
    /// scene.mesh.validate()?;
    /// assert!(scene.suggested_radius.is_some() && !scene.cameras.is_empty());
    /// # Ok::<(), String>(())
    /// ```
    pub fn build(self) -> Scene {
        let (assembly, cameras, radius) = match self {
            Builtin::Room => room(),
            Builtin::Stairs => stairs(),
            Builtin::Thin => thin(),
            Builtin::Open => open(),
        };
        Scene {
            moving_parts: assembly.moving_parts,
            ..Scene::new(self.name(), assembly.mesh, cameras, Some(radius))
        }
    }
}

const FLOOR: Vec3 = Vec3::new(0.62, 0.6, 0.56);
const WALL: Vec3 = Vec3::new(0.75, 0.74, 0.7);
const RED: Vec3 = Vec3::new(0.62, 0.18, 0.14);
const GREEN: Vec3 = Vec3::new(0.2, 0.5, 0.22);
const OBJECT: Vec3 = Vec3::new(0.8, 0.78, 0.74);
const WOOD: Vec3 = Vec3::new(0.55, 0.38, 0.24);

/// Which of the stairs' row of blocks slides.
const SLIDING_BLOCK: usize = 0;

/// Walls are 0.2 m thick so that the ray-traced reference sees closed solids.
const WALL_THICKNESS: f32 = 0.2;

/// A built-in's geometry as it is put together: one mesh, and which of its vertices move.
#[derive(Default)]
struct Assembly {
    mesh: Mesh,
    moving_parts: Vec<MovingPart>,
}

impl Assembly {
    /// Adds pieces that stay put.
    fn add_all(&mut self, pieces: &[Mesh]) {
        for piece in pieces {
            self.mesh.append(piece);
        }
    }

    /// Adds a piece, at rest, that moves by `motion`.
    fn add_moving(&mut self, piece: &Mesh, motion: Motion) {
        let start = self.mesh.positions.len() as u32;
        self.mesh.append(piece);
        self.moving_parts.push(MovingPart {
            vertices: start..self.mesh.positions.len() as u32,
            motion,
        });
    }
}

fn floor_slab(min_x: f32, min_z: f32, size_x: f32, size_z: f32) -> Mesh {
    cuboid(
        Vec3::new(min_x, -WALL_THICKNESS, min_z),
        Vec3::new(size_x, WALL_THICKNESS, size_z),
        0.0,
        FLOOR,
    )
}

fn room() -> (Assembly, Vec<Camera>, f32) {
    let t = WALL_THICKNESS;
    let mut room = Assembly::default();
    room.add_all(&[
        floor_slab(-4.0, -4.0, 8.0, 8.0),
        cuboid(
            Vec3::new(-4.0 - t, -t, -4.0 - t),
            Vec3::new(8.0 + 2.0 * t, 3.0 + t, t),
            0.0,
            WALL,
        ),
        cuboid(
            Vec3::new(-4.0 - t, -t, -4.0),
            Vec3::new(t, 3.0 + t, 8.0),
            0.0,
            RED,
        ),
        cuboid(
            Vec3::new(4.0, -t, -4.0),
            Vec3::new(t, 3.0 + t, 8.0),
            0.0,
            GREEN,
        ),
    ]);
    // The sphere rolls 0.8 m towards the box: its contact shadow travels, the floor behind it
    // comes into view, and the gap to the box closes.
    let center = Vec3::new(-1.5, 1.0, -1.2);
    room.add_moving(
        &sphere(center, 1.0, OBJECT),
        Motion::roll(center, 1.0, Vec3::new(0.8, 0.0, 0.0), Vec3::Y),
    );
    room.add_all(&[
        cuboid(
            Vec3::new(0.9, 0.0, -2.4),
            Vec3::new(1.4, 1.4, 1.4),
            25.0,
            OBJECT,
        ),
        // A low bench in the back-left corner: a step against two walls.
        cuboid(
            Vec3::new(-4.0, 0.0, -4.0),
            Vec3::new(2.2, 0.45, 0.7),
            0.0,
            WOOD,
        ),
    ]);
    let cameras = vec![
        Camera::perspective(
            "front",
            Vec3::new(0.0, 2.4, 6.5),
            Vec3::new(0.0, 0.9, -1.2),
            60.0,
        ),
        Camera::perspective(
            "corner",
            Vec3::new(2.6, 1.7, 1.8),
            Vec3::new(-3.5, 0.3, -3.6),
            55.0,
        ),
    ];
    (room, cameras, 1.0)
}

fn stairs() -> (Assembly, Vec<Camera>, f32) {
    let t = WALL_THICKNESS;
    let mut stairs = Assembly::default();
    stairs.add_all(&[
        floor_slab(-4.0, -5.0, 8.0, 10.0),
        cuboid(
            Vec3::new(-4.0, -t, -5.0 - t),
            Vec3::new(8.0, 4.0 + t, t),
            0.0,
            WALL,
        ),
        // Side wall along the left of the flight: a concave corner at every step.
        cuboid(
            Vec3::new(-1.2 - t, 0.0, -5.0),
            Vec3::new(t, 2.6, 3.2),
            0.0,
            WALL,
        ),
    ]);
    // Eight steps climbing towards the back wall, 0.25 m rise, 0.4 m run.
    for i in 0..8 {
        let z_front = -1.8 - 0.4 * i as f32;
        stairs.add_all(&[cuboid(
            Vec3::new(-1.2, 0.0, z_front - 0.4),
            Vec3::new(2.4, 0.25 * (i + 1) as f32, 0.4),
            0.0,
            OBJECT,
        )]);
    }
    // Blocks 6 cm apart: narrow crevices that stay dark. The first slides 0.5 m forwards out
    // of the row, opening its crevice and showing the side of its neighbour.
    for i in 0..5 {
        let block = cuboid(
            Vec3::new(1.6 + 0.56 * i as f32, 0.0, -3.2),
            Vec3::new(0.5, 0.8, 0.5),
            0.0,
            WOOD,
        );
        if i == SLIDING_BLOCK {
            stairs.add_moving(&block, Motion::slide(Vec3::new(0.0, 0.0, 0.5)));
        } else {
            stairs.add_all(&[block]);
        }
    }
    // A plinth against the back wall with a smaller step on top.
    stairs.add_all(&[
        cuboid(
            Vec3::new(1.6, 0.0, -5.0),
            Vec3::new(2.2, 0.5, 0.9),
            0.0,
            WALL,
        ),
        cuboid(
            Vec3::new(1.9, 0.5, -5.0),
            Vec3::new(1.2, 0.35, 0.5),
            0.0,
            WALL,
        ),
    ]);
    let cameras = vec![
        Camera::perspective(
            "side",
            Vec3::new(2.5, 2.3, 0.6),
            Vec3::new(-0.1, 0.8, -3.3),
            60.0,
        ),
        Camera::perspective(
            "steps",
            Vec3::new(0.2, 1.4, 0.8),
            Vec3::new(-0.4, 1.2, -4.0),
            60.0,
        ),
    ];
    (stairs, cameras, 0.5)
}

fn thin() -> (Assembly, Vec<Camera>, f32) {
    let t = WALL_THICKNESS;
    let mut thin = Assembly::default();
    thin.add_all(&[
        floor_slab(-4.0, -3.0, 8.0, 6.0),
        cuboid(
            Vec3::new(-4.0, -t, -3.0 - t),
            Vec3::new(8.0, 3.4 + t, t),
            0.0,
            WALL,
        ),
    ]);
    // Pillars 6 cm square, 40 cm in front of the wall.
    for i in 0..5 {
        thin.add_all(&[cuboid(
            Vec3::new(-3.3 + 0.4 * i as f32, 0.0, -2.6),
            Vec3::new(0.06, 2.4, 0.06),
            0.0,
            OBJECT,
        )]);
    }
    // A fence: 3 cm slats with 8 cm gaps, on two rails, 80 cm in front of the wall.
    for i in 0..15 {
        thin.add_all(&[cuboid(
            Vec3::new(-1.0 + 0.16 * i as f32, 0.0, -2.2),
            Vec3::new(0.08, 1.2, 0.03),
            0.0,
            WOOD,
        )]);
    }
    for y in [0.3, 1.0] {
        thin.add_all(&[cuboid(
            Vec3::new(-1.05, y, -2.17),
            Vec3::new(2.45, 0.06, 0.04),
            0.0,
            WOOD,
        )]);
    }
    // Panels 2 cm thick, one standing, one turned, one raised off the floor.
    thin.add_all(&[
        cuboid(
            Vec3::new(1.7, 0.0, -2.5),
            Vec3::new(0.8, 1.6, 0.02),
            0.0,
            OBJECT,
        ),
        cuboid(
            Vec3::new(2.7, 0.0, -2.4),
            Vec3::new(0.8, 1.6, 0.02),
            20.0,
            OBJECT,
        ),
    ]);
    // The raised panel swings 40 degrees about its left edge, like a door: it sweeps across the
    // pillars behind it, covering some and uncovering others, and its shadow turns on the floor.
    let (min, size, yaw) = (
        Vec3::new(-2.2, 0.3, -1.2),
        Vec3::new(0.7, 1.2, 0.02),
        -15.0f32,
    );
    let raised = cuboid(min, size, yaw, OBJECT);
    let hinge =
        min + 0.5 * size + Quat::from_rotation_y(yaw.to_radians()) * (-0.5 * size.x * Vec3::X);
    thin.add_moving(&raised, Motion::swing(hinge, Vec3::Y, 40.0));
    let cameras = vec![
        Camera::perspective(
            "front",
            Vec3::new(0.2, 1.4, 1.3),
            Vec3::new(0.0, 0.9, -3.0),
            60.0,
        ),
        Camera::perspective(
            "oblique",
            Vec3::new(-3.0, 1.2, 1.0),
            Vec3::new(0.5, 0.8, -2.8),
            60.0,
        ),
    ];
    (thin, cameras, 0.6)
}

fn open() -> (Assembly, Vec<Camera>, f32) {
    // A single-sided 40 m square facing up.
    let mut open = Assembly::default();
    open.add_all(&[quad(
        Vec3::new(-20.0, 0.0, 20.0),
        Vec3::new(40.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, -40.0),
        FLOOR,
    )]);
    let cameras = vec![
        Camera::perspective(
            "above",
            Vec3::new(0.0, 6.0, 10.0),
            Vec3::new(0.0, 0.0, -2.0),
            60.0,
        ),
        Camera::perspective(
            "low",
            Vec3::new(0.0, 1.5, 12.0),
            Vec3::new(0.0, 0.0, 0.0),
            60.0,
        ),
    ];
    (open, cameras, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_builtin_builds_a_valid_mesh_with_cameras() {
        for b in Builtin::ALL {
            let scene = b.build();
            scene.mesh.validate().unwrap();
            assert!(scene.mesh.triangle_count() > 0, "{}", b.name());
            assert!(!scene.cameras.is_empty());
            assert_eq!(Builtin::from_name(b.name()), Some(b));
        }
    }

    #[test]
    fn moving_parts_are_whole_and_stay_inside_the_bounds() {
        for b in Builtin::ALL {
            let scene = b.build();
            let part_of = |v: u32| {
                scene
                    .moving_parts
                    .iter()
                    .position(|p| p.vertices.contains(&v))
            };
            // A triangle shared between a part and anything else would stretch as it moves.
            for tri in scene.mesh.indices.chunks_exact(3) {
                let owner = part_of(tri[0]);
                assert!(
                    tri.iter().all(|&v| part_of(v) == owner),
                    "{}: {tri:?}",
                    b.name()
                );
            }
            // The clipping planes and the shadow map are fitted to the bounds at rest.
            let slack = Vec3::splat(1e-4);
            for step in 0..=16 {
                let mesh = scene.mesh_at(step as f32 / 16.0);
                mesh.validate().unwrap();
                let bounds = mesh.bounds().unwrap();
                assert!(
                    bounds.min.cmpge(scene.bounds.min - slack).all()
                        && bounds.max.cmple(scene.bounds.max + slack).all(),
                    "{} at step {step}: {bounds:?} outside {:?}",
                    b.name(),
                    scene.bounds
                );
            }
            let moves = scene.mesh_at(1.0).positions != scene.mesh.positions;
            assert_eq!(moves, b != Builtin::Open, "{}", b.name());
        }
    }
}
