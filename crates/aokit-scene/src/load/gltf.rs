//! glTF 2.0 (`.gltf` with its buffers, or `.glb`): triangle meshes of the default scene with
//! their base colour factors, and the cameras placed in it.

use std::path::Path;

use glam::{Mat4, Vec3};

use super::DEFAULT_ALBEDO;
use crate::camera::{Camera, Lens};
use crate::mesh::{Mesh, with_generated_normals};
use crate::scene::{Scene, SceneError};

/// Loads a glTF file. Textures are not read: albedo is each material's base colour factor.
///
/// ```no_run
/// use std::path::Path;
/// let scene = aokit_scene::load::gltf::load(Path::new("assets/Sponza.glb"))?;
/// // The file's own cameras, in document order, for `--camera`.
/// for (i, camera) in scene.cameras.iter().enumerate() {
///     println!("{i}: {}", camera.name);
/// }
/// # Ok::<(), aokit_scene::SceneError>(())
/// ```
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let parse = |reason: String| SceneError::Parse {
        path: path.to_path_buf(),
        reason,
    };
    let gltf = ::gltf::Gltf::open(path).map_err(|e| parse(e.to_string()))?;
    let buffers = ::gltf::import_buffers(&gltf.document, path.parent(), gltf.blob.clone())
        .map_err(|e| parse(e.to_string()))?;
    let document = &gltf.document;
    let scene = document
        .default_scene()
        .or_else(|| document.scenes().next())
        .ok_or_else(|| parse("the file has no scene".to_string()))?;

    let mut state = State {
        buffers: &buffers,
        mesh: Mesh::default(),
        cameras: Vec::new(),
        notes: Vec::new(),
    };
    for node in scene.nodes() {
        state.visit(&node, Mat4::IDENTITY).map_err(parse)?;
    }
    if state.mesh.triangle_count() == 0 {
        return Err(SceneError::Empty(path.to_path_buf()));
    }
    state.mesh.validate().map_err(parse)?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut out = Scene::new(&name, state.mesh, state.cameras, None);
    out.notes = state.notes;
    Ok(out)
}

struct State<'a> {
    buffers: &'a [::gltf::buffer::Data],
    mesh: Mesh,
    cameras: Vec<Camera>,
    notes: Vec<String>,
}

impl State<'_> {
    fn visit(&mut self, node: &::gltf::Node<'_>, parent: Mat4) -> Result<(), String> {
        let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
        if let Some(mesh) = node.mesh() {
            for primitive in mesh.primitives() {
                self.add_primitive(&primitive, world)?;
            }
        }
        if let Some(camera) = node.camera() {
            self.add_camera(node, &camera, world);
        }
        for child in node.children() {
            self.visit(&child, world)?;
        }
        Ok(())
    }

    fn add_primitive(
        &mut self,
        primitive: &::gltf::Primitive<'_>,
        world: Mat4,
    ) -> Result<(), String> {
        if primitive.mode() != ::gltf::mesh::Mode::Triangles {
            self.notes.push(format!(
                "skipped a {:?} primitive: only triangle lists are rendered",
                primitive.mode()
            ));
            return Ok(());
        }
        let reader = primitive.reader(|buffer| self.buffers.get(buffer.index()).map(|d| &d.0[..]));
        let positions: Vec<Vec3> = reader
            .read_positions()
            .ok_or("a primitive has no POSITION attribute")?
            .map(Vec3::from)
            .collect();
        let indices: Vec<u32> = match reader.read_indices() {
            Some(indices) => indices.into_u32().collect(),
            None => (0..positions.len() as u32).collect(),
        };
        let factor = primitive
            .material()
            .pbr_metallic_roughness()
            .base_color_factor();
        let albedo = if primitive.material().index().is_some() {
            Vec3::new(factor[0], factor[1], factor[2])
        } else {
            DEFAULT_ALBEDO
        };
        let local = match reader.read_normals() {
            Some(normals) => Mesh {
                normals: normals.map(Vec3::from).collect(),
                albedo: vec![albedo; positions.len()],
                positions,
                indices,
            },
            // The glTF specification asks for flat normals when a primitive has none.
            None => with_generated_normals(&positions, &indices, albedo, 0.0),
        };
        local.validate()?;
        self.mesh.append_transformed(&local, world);
        Ok(())
    }

    fn add_camera(&mut self, node: &::gltf::Node<'_>, camera: &::gltf::Camera<'_>, world: Mat4) {
        // glTF cameras look down their local -Z with +Y up.
        let eye = world.transform_point3(Vec3::ZERO);
        let forward = world.transform_vector3(Vec3::NEG_Z).normalize_or_zero();
        let up = world.transform_vector3(Vec3::Y).normalize_or_zero();
        let (lens, near, far) = match camera.projection() {
            ::gltf::camera::Projection::Perspective(p) => (
                Lens::Perspective {
                    fov_y_deg: p.yfov().to_degrees(),
                },
                p.znear(),
                p.zfar(),
            ),
            ::gltf::camera::Projection::Orthographic(o) => (
                Lens::Orthographic {
                    height: 2.0 * o.ymag(),
                },
                o.znear(),
                Some(o.zfar()),
            ),
        };
        let name = camera
            .name()
            .or(node.name())
            .map(str::to_string)
            .unwrap_or_else(|| format!("camera{}", self.cameras.len()));
        self.cameras.push(Camera {
            name,
            eye,
            target: eye + forward,
            up,
            lens,
            near: (near > 0.0).then_some(near),
            far,
            reverse_z: true,
        });
    }
}
