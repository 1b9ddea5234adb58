//! Wavefront OBJ, with diffuse colours from its MTL file when there is one, and named cameras
//! from a `<stem>-cameras.json` file beside it (the format of Sponza's in `shared/scenes`).

use std::path::{Path, PathBuf};

use glam::Vec3;
use serde::Deserialize;

use super::DEFAULT_ALBEDO;
use crate::camera::{Camera, Lens};
use crate::mesh::{Mesh, with_generated_normals};
use crate::scene::{Scene, SceneError};

/// Normals are smoothed across edges shallower than this when the file has none: curved
/// surfaces come out smooth, architectural edges stay sharp.
const CREASE_DEGREES: f32 = 35.0;

/// Loads an OBJ file and its camera sidecar.
///
/// ```
/// use std::fs;
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("ramp.obj");
/// // A ramp without normals or materials: the loader fills both in and says so.
/// fs::write(&path, "v 0 0 0\nv 2 0 0\nv 2 1 -2\nv 0 1 -2\nf 1 2 3 4\n")?;
/// fs::write(dir.path().join("ramp-cameras.json"), r#"{"suggested_ao_radius": 0.3,
///     "cameras": [{"name": "side", "eye": [5, 1, 0], "target": [1, 0.5, -1],
///                  "fov_y_deg": 50}]}"#)?;
/// let scene = aokit_scene::load::obj::load(&path)?;
/// assert_eq!((scene.name.as_str(), scene.mesh.triangle_count()), ("ramp", 2));
/// assert_eq!(scene.suggested_radius, Some(0.3));
/// assert_eq!(scene.cameras[0].name, "side");
/// assert!(scene.notes.iter().any(|note| note.contains("no normals")));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let obj = std::fs::read(path).map_err(|e| SceneError::Parse {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })?;
    let sidecar = match sidecar_path(path) {
        Some(sidecar) => {
            let text = std::fs::read(&sidecar).map_err(|e| SceneError::Parse {
                path: sidecar.clone(),
                reason: e.to_string(),
            })?;
            Some((sidecar, text))
        }
        None => None,
    };
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    load_parts(
        path,
        &obj,
        |mtl| tobj::load_mtl(folder.join(mtl)),
        sidecar
            .as_ref()
            .map(|(p, text)| (p.as_path(), text.as_slice())),
    )
}

/// Loads an OBJ held in memory, with the text of its camera sidecar when there is one: what
/// [`load`] does with the files, without a file system. `name` stands for the file in messages
/// and gives the scene its name (its stem); a `mtllib` the OBJ names is not read (there is no
/// folder to read it from), so every surface is grey and a note says so.
///
/// ```
/// let obj = b"v 0 0 0\nv 2 0 0\nv 2 1 -2\nv 0 1 -2\nf 1 2 3 4\n";
/// let sidecar = br#"{"suggested_ao_radius": 0.3, "cameras": []}"#;
/// let scene = aokit_scene::load::obj::load_slice("ramp.obj", obj, Some(sidecar))?;
/// assert_eq!((scene.name.as_str(), scene.mesh.triangle_count()), ("ramp", 2));
/// assert_eq!(scene.suggested_radius, Some(0.3));
/// // A sidecar that does not parse is named as `<stem>-cameras.json`.
/// let err = aokit_scene::load::obj::load_slice("ramp.obj", obj, Some(b"{")).unwrap_err();
/// assert!(err.to_string().contains("ramp-cameras.json"));
/// # Ok::<(), aokit_scene::SceneError>(())
/// ```
pub fn load_slice(name: &str, obj: &[u8], sidecar: Option<&[u8]>) -> Result<Scene, SceneError> {
    let path = Path::new(name);
    let sidecar_name = sidecar_name(path);
    load_parts(
        path,
        obj,
        |_| Err(tobj::LoadError::OpenFileFailed),
        sidecar.map(|text| (sidecar_name.as_path(), text)),
    )
}

/// The OBJ `obj` (named `path`), its materials from `mtl` and its sidecar (named, and its
/// bytes) when there is one.
fn load_parts(
    path: &Path,
    obj: &[u8],
    mtl: impl Fn(&Path) -> tobj::MTLLoadResult,
    sidecar: Option<(&Path, &[u8])>,
) -> Result<Scene, SceneError> {
    let parse = |reason: String| SceneError::Parse {
        path: path.to_path_buf(),
        reason,
    };
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    check_face_indices(obj).map_err(parse)?;
    let (models, materials) = tobj::load_obj_buf(&mut std::io::BufReader::new(obj), &options, mtl)
        .map_err(|e| parse(e.to_string()))?;
    let mut notes = Vec::new();
    let materials = materials.unwrap_or_else(|e| {
        notes.push(format!("materials not loaded ({e}); using grey albedo"));
        Vec::new()
    });
    let mut mesh = Mesh::default();
    let mut generated = false;
    for model in &models {
        let m = &model.mesh;
        let positions: Vec<Vec3> = m
            .positions
            .chunks_exact(3)
            .map(|p| Vec3::new(p[0], p[1], p[2]))
            .collect();
        let albedo = m
            .material_id
            .and_then(|id| materials.get(id))
            .and_then(|mat| mat.diffuse)
            .map(Vec3::from)
            .unwrap_or(DEFAULT_ALBEDO);
        let part = if m.normals.len() == m.positions.len() && !m.normals.is_empty() {
            Mesh {
                normals: m
                    .normals
                    .chunks_exact(3)
                    .map(|n| Vec3::new(n[0], n[1], n[2]).normalize_or_zero())
                    .collect(),
                albedo: vec![albedo; positions.len()],
                positions,
                indices: m.indices.clone(),
            }
        } else {
            generated = true;
            with_generated_normals(&positions, &m.indices, albedo, CREASE_DEGREES)
        };
        part.validate().map_err(parse)?;
        mesh.append(&part);
    }
    if generated {
        notes.push(format!(
            "the file has no normals: generated them, smooth across edges under {CREASE_DEGREES} degrees"
        ));
    }
    if mesh.triangle_count() == 0 {
        return Err(SceneError::Empty(path.to_path_buf()));
    }
    // Each part is checked above; their extent together is checked here.
    mesh.validate().map_err(parse)?;
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let (cameras, radius) = match sidecar {
        Some((sidecar, text)) => read_sidecar(sidecar, text)?,
        None => (Vec::new(), None),
    };
    let mut scene = Scene::new(&stem, mesh, cameras, radius);
    scene.notes = notes;
    Ok(scene)
}

/// Refuses a face whose texture-coordinate or normal index lies outside the ones defined
/// before it (relative indices, `-1` for the last, included). tobj multiplies such an index
/// without a check: a panic on overflow where overflow checks are on (debug builds, the fuzz
/// targets), a wrapped index, or another vertex's normal, where they are off. Positions it
/// checks itself; they are checked here too, for one message.
fn check_face_indices(obj: &[u8]) -> Result<(), String> {
    const KINDS: [&str; 3] = ["position", "texture coordinate", "normal"];
    let mut counts = [0usize; 3];
    for (number, line) in obj.split(|&b| b == b'\n').enumerate() {
        let Ok(line) = std::str::from_utf8(line) else {
            continue; // tobj refuses it
        };
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f") => {
                for corner in words {
                    for (kind, index) in corner.split('/').enumerate().take(3) {
                        let Ok(index) = index.parse::<i64>() else {
                            continue; // empty (`1//2`), or refused by tobj
                        };
                        let count = counts[kind] as i64;
                        let within = if index < 0 {
                            -index <= count
                        } else {
                            (1..=count).contains(&index)
                        };
                        if !within {
                            return Err(format!(
                                "line {}: face {} index {index} is out of range for the {count} \
                                 {}s before it",
                                number + 1,
                                KINDS[kind],
                                KINDS[kind]
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

fn sidecar_path(obj: &Path) -> Option<PathBuf> {
    let candidate = sidecar_name(obj);
    (obj.file_stem().is_some() && candidate.exists()).then_some(candidate)
}

/// `<stem>-cameras.json` beside `obj`.
fn sidecar_name(obj: &Path) -> PathBuf {
    let stem = obj.file_stem().unwrap_or_default().to_string_lossy();
    obj.with_file_name(format!("{stem}-cameras.json"))
}

#[derive(Deserialize)]
struct Sidecar {
    #[serde(default)]
    suggested_ao_radius: Option<f32>,
    #[serde(default)]
    cameras: Vec<SidecarCamera>,
}

#[derive(Deserialize)]
struct SidecarCamera {
    name: String,
    eye: [f32; 3],
    target: [f32; 3],
    #[serde(default = "default_up")]
    up: [f32; 3],
    fov_y_deg: f32,
}

fn default_up() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}

/// Reads named cameras and the suggested radius from the text of a `<stem>-cameras.json` file.
fn read_sidecar(path: &Path, text: &[u8]) -> Result<(Vec<Camera>, Option<f32>), SceneError> {
    let parse = |reason: String| SceneError::Parse {
        path: path.to_path_buf(),
        reason,
    };
    let sidecar: Sidecar = serde_json::from_slice(text).map_err(|e| parse(e.to_string()))?;
    let cameras = sidecar
        .cameras
        .into_iter()
        .map(|c| {
            let camera = Camera {
                up: Vec3::from(c.up),
                lens: Lens::Perspective {
                    fov_y_deg: c.fov_y_deg,
                },
                ..Camera::perspective(
                    &c.name,
                    Vec3::from(c.eye),
                    Vec3::from(c.target),
                    c.fov_y_deg,
                )
            };
            camera.validate().map_err(parse)?;
            Ok(camera)
        })
        .collect::<Result<Vec<_>, SceneError>>()?;
    // Checked here, where the file is known: the radius is otherwise refused only by the
    // settings' validation, whose message cannot name this file.
    if let Some(radius) = sidecar.suggested_ao_radius
        && !(radius.is_finite() && radius > 0.0)
    {
        return Err(parse(format!(
            "suggested_ao_radius {radius} must be positive and finite"
        )));
    }
    Ok((cameras, sidecar.suggested_ao_radius))
}
