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
    let bytes = std::fs::read(path).map_err(|e| SceneError::Parse {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })?;
    // Buffers in other files are read from beside this one.
    load_from(path, &bytes, path.parent())
}

/// Loads a self-contained glTF held in memory: a `.glb`, or `.gltf` JSON whose buffers are
/// `data:` URIs. A buffer in another file is refused (there is no folder to read it from).
/// `name` stands for the file in messages and gives the scene its name (its stem).
///
/// ```no_run
/// // A GLB that came over the network or out of an archive, never written to disk.
/// let bytes = std::fs::read("assets/Sponza.glb")?;
/// let scene = aokit_scene::load::gltf::load_slice("Sponza.glb", &bytes)?;
/// assert_eq!(scene.name, "Sponza");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_slice(name: &str, bytes: &[u8]) -> Result<Scene, SceneError> {
    load_from(Path::new(name), bytes, None)
}

/// The glTF `bytes`, named `path`, its external buffers read from `folder` (none: refused).
fn load_from(path: &Path, bytes: &[u8], folder: Option<&Path>) -> Result<Scene, SceneError> {
    let parse = |reason: String| SceneError::Parse {
        path: path.to_path_buf(),
        reason,
    };
    // Parsed, then checked for what the gltf crate's validation indexes without a check, then
    // validated.
    // A GLB whose header gives a length under the header's own 12 bytes: the gltf crate
    // subtracts 12 from it unchecked (a panic where overflow checks are on; found by fuzzing).
    if bytes.starts_with(b"glTF")
        && let Some(length) = bytes.get(8..12)
        && u32::from_le_bytes([length[0], length[1], length[2], length[3]]) < 12
    {
        return Err(parse(format!(
            "the GLB header gives a length of {} bytes, less than the header's own 12",
            u32::from_le_bytes([length[0], length[1], length[2], length[3]])
        )));
    }
    let parsed =
        ::gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| parse(e.to_string()))?;
    check_position_accessors(parsed.document.as_json()).map_err(parse)?;
    check_buffer_uris(parsed.document.as_json()).map_err(parse)?;
    let gltf = ::gltf::Gltf {
        document: ::gltf::Document::from_json(parsed.document.into_json())
            .map_err(|e| parse(e.to_string()))?,
        blob: parsed.blob,
    };
    let buffers = ::gltf::import_buffers(&gltf.document, folder, gltf.blob.clone())
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
    state.visit_tree(scene.nodes()).map_err(parse)?;
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
    /// Visits the trees under `roots` depth first, in document order. The walk keeps its own
    /// stack rather than recursing, and refuses a node that is its own ancestor: the JSON can
    /// describe cycles (a node listed among its own children), which the specification forbids
    /// and which would otherwise recurse until the stack overflows.
    fn visit_tree<'a>(
        &mut self,
        roots: impl Iterator<Item = ::gltf::Node<'a>>,
    ) -> Result<(), String> {
        // Each entry: the node, its parent's world transform and its depth in the tree.
        let mut stack: Vec<(::gltf::Node<'a>, Mat4, usize)> =
            roots.map(|node| (node, Mat4::IDENTITY, 0)).collect();
        stack.reverse();
        // The node indices from the root down to the node being visited.
        let mut path: Vec<usize> = Vec::new();
        while let Some((node, parent, depth)) = stack.pop() {
            path.truncate(depth);
            if path.contains(&node.index()) {
                return Err(format!(
                    "node {} is its own ancestor (the node hierarchy has a cycle: {} -> {})",
                    node.index(),
                    path.iter()
                        .map(usize::to_string)
                        .collect::<Vec<_>>()
                        .join(" -> "),
                    node.index()
                ));
            }
            path.push(node.index());
            let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
            if let Some(mesh) = node.mesh() {
                for primitive in mesh.primitives() {
                    self.add_primitive(&primitive, world)?;
                }
            }
            if let Some(camera) = node.camera() {
                self.add_camera(&node, &camera, world);
            }
            let children: Vec<_> = node.children().collect();
            stack.extend(
                children
                    .into_iter()
                    .rev()
                    .map(|child| (child, world, depth + 1)),
            );
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
        // The reader silently yields nothing for an accessor that runs past its data, which
        // would read as "no indices" (every vertex in order) or "no normals": check first.
        if let Some(indices) = primitive.indices() {
            check_accessor(&indices, "indices", self.buffers)?;
            // The reader panics ("unreachable") on other types, which the specification
            // forbids for indices but the parser lets through.
            use ::gltf::accessor::{DataType, Dimensions};
            if !matches!(
                indices.data_type(),
                DataType::U8 | DataType::U16 | DataType::U32
            ) || indices.dimensions() != Dimensions::Scalar
            {
                return Err(format!(
                    "accessor {} (indices) holds {:?} {:?}, not unsigned byte, short or int scalars",
                    indices.index(),
                    indices.data_type(),
                    indices.dimensions()
                ));
            }
        }
        for (semantic, accessor) in primitive.attributes() {
            if matches!(
                semantic,
                ::gltf::Semantic::Positions | ::gltf::Semantic::Normals
            ) {
                check_accessor(&accessor, &semantic.to_string(), self.buffers)?;
                // The reader takes them as f32 triples whatever they hold: another type reads
                // as garbage (or trips a debug assertion; found by fuzzing).
                use ::gltf::accessor::{DataType, Dimensions};
                if accessor.data_type() != DataType::F32
                    || accessor.dimensions() != Dimensions::Vec3
                {
                    return Err(format!(
                        "accessor {} ({}) holds {:?} {:?}, not float VEC3",
                        accessor.index(),
                        semantic.to_string(),
                        accessor.data_type(),
                        accessor.dimensions()
                    ));
                }
            }
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
        // An index past the vertices would panic when normals are generated below (and is
        // refused by `Mesh::validate` otherwise): refuse it here, as the OBJ loader does.
        if let Some(&i) = indices.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(format!(
                "index {i} is out of range for a primitive of {} vertices",
                positions.len()
            ));
        }
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

/// Refuses a buffer whose relative URI percent-decodes to bytes that are not UTF-8: the gltf
/// crate's import unwraps that decoding, and panics (found by fuzzing).
fn check_buffer_uris(root: &::gltf::json::Root) -> Result<(), String> {
    for (i, buffer) in root.buffers.iter().enumerate() {
        let Some(uri) = buffer.uri.as_deref() else {
            continue;
        };
        if uri.contains(':') {
            continue; // data:, file: or a scheme the import refuses itself
        }
        let bytes = uri.as_bytes();
        let mut decoded = Vec::with_capacity(bytes.len());
        let mut at = 0;
        while at < bytes.len() {
            let hex = bytes
                .get(at + 1..at + 3)
                .and_then(|h| std::str::from_utf8(h).ok())
                .and_then(|h| u8::from_str_radix(h, 16).ok());
            match (bytes[at], hex) {
                (b'%', Some(byte)) => {
                    decoded.push(byte);
                    at += 3;
                }
                (byte, _) => {
                    decoded.push(byte);
                    at += 1;
                }
            }
        }
        if std::str::from_utf8(&decoded).is_err() {
            return Err(format!(
                "buffer {i}: URI {uri:?} percent-decodes to bytes that are not UTF-8"
            ));
        }
    }
    Ok(())
}

/// Refuses a primitive whose POSITION accessor does not exist: the gltf crate's validation
/// reads that accessor before it checks the index, and panics (found by fuzzing: a file whose
/// `accessors` key was misspelt).
fn check_position_accessors(root: &::gltf::json::Root) -> Result<(), String> {
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let position = ::gltf::json::validation::Checked::Valid(::gltf::Semantic::Positions);
            if let Some(index) = primitive.attributes.get(&position)
                && index.value() >= root.accessors.len()
            {
                return Err(format!(
                    "mesh {m}, primitive {p}: POSITION names accessor {}, but the file has {} \
                     accessors",
                    index.value(),
                    root.accessors.len()
                ));
            }
        }
    }
    Ok(())
}

/// Checks what the gltf crate's reader takes on trust before it slices the data: at least one
/// element (it computes `count - 1`; 0 overflows, a panic where overflow checks are on, found by
/// fuzzing), and the elements of the accessor and of its sparse indices and values inside their
/// buffer views, the views inside their buffers. An accessor without a view reads as zeros.
fn check_accessor(
    accessor: &::gltf::Accessor<'_>,
    what: &str,
    buffers: &[::gltf::buffer::Data],
) -> Result<(), String> {
    let name = format!("accessor {} ({what})", accessor.index());
    let count = accessor.count();
    if count == 0 {
        return Err(format!(
            "{name}: count 0; glTF requires at least one element"
        ));
    }
    if let Some(view) = accessor.view() {
        check_elements(
            &name,
            &view,
            accessor.offset(),
            count,
            accessor.size(),
            buffers,
        )?;
    }
    if let Some(sparse) = accessor.sparse() {
        let count = sparse.count();
        if count == 0 {
            return Err(format!(
                "{name}: sparse count 0; glTF requires at least one element"
            ));
        }
        let indices = sparse.indices();
        let index_size = indices.index_type().size();
        let what = format!("{name}, sparse indices");
        check_elements(
            &what,
            &indices.view(),
            indices.offset(),
            count,
            index_size,
            buffers,
        )?;
        let values = sparse.values();
        let what = format!("{name}, sparse values");
        check_elements(
            &what,
            &values.view(),
            values.offset(),
            count,
            accessor.size(),
            buffers,
        )?;
    }
    Ok(())
}

/// Checks that `count` elements of `element` bytes from `offset` in `view` lie inside it, at its
/// stride, and the view inside its buffer.
fn check_elements(
    name: &str,
    view: &::gltf::buffer::View<'_>,
    offset: usize,
    count: usize,
    element: usize,
    buffers: &[::gltf::buffer::Data],
) -> Result<(), String> {
    let buffer_len = buffers.get(view.buffer().index()).map_or(0, |d| d.0.len());
    let view_end = view.offset().checked_add(view.length());
    if view_end.is_none_or(|end| end > buffer_len) {
        return Err(format!(
            "{name}: buffer view {} ends past the {buffer_len} bytes of buffer {}",
            view.index(),
            view.buffer().index()
        ));
    }
    let stride = view.stride().unwrap_or(element);
    if stride < element {
        return Err(format!(
            "{name}: buffer view {} has a stride of {stride} bytes, less than an element's {element}",
            view.index()
        ));
    }
    let needed = stride
        .checked_mul(count - 1)
        .and_then(|bytes| bytes.checked_add(offset))
        .and_then(|bytes| bytes.checked_add(element));
    if needed.is_none_or(|needed| needed > view.length()) {
        let needed = needed.map_or("more than 2^64".to_string(), |n| n.to_string());
        return Err(format!(
            "{name}: {count} elements need {needed} bytes, past the {} bytes of buffer view {}",
            view.length(),
            view.index()
        ));
    }
    Ok(())
}
