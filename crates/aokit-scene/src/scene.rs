//! A scene: one world-space mesh, the parts of it that move, its cameras and a suggested AO
//! radius.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use crate::animation::MovingPart;
use crate::builtin::Builtin;
use crate::camera::Camera;
use crate::load;
use crate::mesh::{Bounds, Mesh};

/// Everything the renderer and the reference tracer need to know about a scene.
///
/// ```
/// let scene = aokit_scene::Scene::open("stairs")?;
/// for note in &scene.notes {
///     eprintln!("{}: {note}", scene.name);
/// }
/// println!("{} triangles, {} cameras", scene.mesh.triangle_count(), scene.cameras.len());
/// // A built-in scene comes with geometry and at least one camera to look at it through.
/// assert!(scene.mesh.triangle_count() > 0 && !scene.cameras.is_empty());
/// # Ok::<(), aokit_scene::SceneError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene {
    /// Built-in name or file stem.
    pub name: String,
    /// All geometry, flattened to world space, with the moving parts at rest (time 0).
    pub mesh: Mesh,
    /// Parts of [`Scene::mesh`] that move over a sequence ([`Scene::mesh_at`]): some built-ins
    /// have them, files have none.
    pub moving_parts: Vec<MovingPart>,
    /// Cameras from the file or the built-in, in order.
    pub cameras: Vec<Camera>,
    /// A radius in scene units that suits the scene's scale, if the scene names one.
    pub suggested_radius: Option<f32>,
    /// Bounds of the mesh at rest. The built-ins' moving parts stay inside them (their tests
    /// check it), so the clipping planes and the sun's shadow map fit every frame.
    pub bounds: Bounds,
    /// Things the loader skipped or assumed, for the user to read.
    pub notes: Vec<String>,
}

/// Why a scene could not be opened.
///
/// ```
/// use aokit_scene::{Scene, SceneError};
/// match Scene::open("sponza.fbx") {
///     Err(SceneError::Unknown(spec)) => assert_eq!(spec, "sponza.fbx"),
///     other => panic!("{other:?}"),
/// }
/// // The message lists what would have worked.
/// let message = Scene::open("rooom").unwrap_err().to_string();
/// assert!(message.contains("room, stairs"));
/// ```
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// Neither a built-in name nor an existing file.
    #[error("unknown scene `{0}`: not a built-in ({builtins}) and no such file", builtins = builtin_names())]
    Unknown(String),
    /// The file extension is not one aokit reads.
    #[error("cannot load `{}`: unsupported extension (expected .gltf, .glb or .obj)", .0.display())]
    Extension(PathBuf),
    /// The file could not be parsed.
    #[error("cannot load `{}`: {reason}", path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        reason: String,
    },
    /// The file holds no triangles, or none with any area.
    #[error("`{}` contains no triangles with a nonzero area", .0.display())]
    Empty(PathBuf),
    /// `--camera` named no camera of the scene.
    #[error("scene `{scene}` has no camera `{wanted}` (cameras: {available})")]
    NoCamera {
        /// The scene's name.
        scene: String,
        /// What was asked for.
        wanted: String,
        /// Names and indices on offer.
        available: String,
    },
}

fn builtin_names() -> String {
    Builtin::ALL.map(Builtin::name).join(", ")
}

impl Scene {
    /// Assembles a scene; bounds come from the mesh.
    ///
    /// # Panics
    /// If the mesh is empty: built-ins never are, and loaders check first.
    ///
    /// ```
    /// use aokit_scene::{Camera, Scene, shapes};
    /// use glam::Vec3;
    /// let floor_corner = Vec3::new(-3.0, 0.0, 3.0);
    /// let mut mesh = shapes::quad(floor_corner, 6.0 * Vec3::X, -6.0 * Vec3::Z, Vec3::ONE);
    /// mesh.append(&shapes::sphere(Vec3::new(0.0, 0.5, 0.0), 0.5, Vec3::new(0.8, 0.3, 0.2)));
    /// let camera = Camera::perspective("front", Vec3::new(0.0, 1.0, 3.0), Vec3::ZERO, 50.0);
    /// let scene = Scene::new("ball on a floor", mesh, vec![camera], Some(0.25));
    /// assert_eq!(scene.bounds.max.y, 1.0);
    /// ```
    pub fn new(
        name: &str,
        mesh: Mesh,
        cameras: Vec<Camera>,
        suggested_radius: Option<f32>,
    ) -> Self {
        let bounds = mesh.bounds().expect("scene mesh has vertices");
        Self {
            name: name.to_string(),
            mesh,
            moving_parts: Vec::new(),
            cameras,
            suggested_radius,
            bounds,
            notes: Vec::new(),
        }
    }

    /// The geometry at time `t` of a sequence, 0 (first frame, the parts at rest) to 1 (last
    /// frame): [`Scene::mesh`] with each moving part placed by its motion. The renderer places
    /// the parts with the same arithmetic, so the reference tracer sees the raster's triangles.
    ///
    /// ```
    /// let room = aokit_scene::Scene::open("room").unwrap();
    /// assert_eq!(room.mesh_at(0.0).positions, room.mesh.positions);
    /// assert_ne!(room.mesh_at(1.0).positions, room.mesh.positions);
    /// ```
    pub fn mesh_at(&self, t: f32) -> Cow<'_, Mesh> {
        if self.moving_parts.is_empty() {
            return Cow::Borrowed(&self.mesh);
        }
        let mut mesh = self.mesh.clone();
        for part in &self.moving_parts {
            let transform = part.motion.transform_at(t);
            let range = part.vertices.start as usize..part.vertices.end as usize;
            for p in &mut mesh.positions[range.clone()] {
                *p = transform.transform_point3(*p);
            }
            // Rigid motions turn normals as they turn directions.
            for n in &mut mesh.normals[range] {
                *n = transform.transform_vector3(*n);
            }
        }
        Cow::Owned(mesh)
    }

    /// Opens a built-in by name (`room`, `stairs`, `thin`, `open`) or a `.gltf`, `.glb` or
    /// `.obj` file by path.
    ///
    /// ```
    /// let scene = aokit_scene::Scene::open("room").unwrap();
    /// assert_eq!(scene.name, "room");
    /// assert!(aokit_scene::Scene::open("no-such-scene").is_err());
    /// ```
    pub fn open(spec: &str) -> Result<Scene, SceneError> {
        if let Some(builtin) = Builtin::from_name(spec) {
            return Ok(builtin.build());
        }
        let path = Path::new(spec);
        if !path.exists() {
            return Err(SceneError::Unknown(spec.to_string()));
        }
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let scene = match extension.as_deref() {
            Some("gltf" | "glb") => load::gltf::load(path)?,
            Some("obj") => load::obj::load(path)?,
            _ => return Err(SceneError::Extension(path.to_path_buf())),
        };
        // Triangles without area draw nothing, and all of one point leave no view to frame.
        if scene.mesh.area_triangle_count() == 0 {
            return Err(SceneError::Empty(path.to_path_buf()));
        }
        Ok(scene)
    }

    /// Picks a camera by name or index; with `None`, the first camera, or a framing camera when
    /// the scene has none.
    ///
    /// ```
    /// let scene = aokit_scene::Scene::open("room")?;
    /// // As `--camera` takes it: a name, or an index into the scene's list.
    /// assert_eq!(scene.camera(Some("corner"))?, scene.camera(Some("1"))?);
    /// assert_eq!(scene.camera(None)?.name, "front");
    /// assert!(scene.camera(Some("attic")).is_err());
    /// # Ok::<(), aokit_scene::SceneError>(())
    /// ```
    pub fn camera(&self, selector: Option<&str>) -> Result<Camera, SceneError> {
        let Some(wanted) = selector else {
            return Ok(self
                .cameras
                .first()
                .cloned()
                .unwrap_or_else(|| Camera::framing(&self.bounds)));
        };
        let by_name = self.cameras.iter().find(|c| c.name == wanted);
        let by_index = wanted
            .parse::<usize>()
            .ok()
            .and_then(|i| self.cameras.get(i));
        by_name
            .or(by_index)
            .cloned()
            .ok_or_else(|| SceneError::NoCamera {
                scene: self.name.clone(),
                wanted: wanted.to_string(),
                available: if self.cameras.is_empty() {
                    "none; omit --camera for a framing camera or give --eye/--target".to_string()
                } else {
                    self.cameras
                        .iter()
                        .enumerate()
                        .map(|(i, c)| format!("{i}: {}", c.name))
                        .collect::<Vec<_>>()
                        .join(", ")
                },
            })
    }
}
