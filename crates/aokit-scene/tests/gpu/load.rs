//! Scene files: glTF and OBJ written here, and the Sponza shipped in `scenes/`.

use std::path::{Path, PathBuf};

use aokit::{AoSettings, GpuContext};
use aokit_scene::{Lens, Renderer, Scene, SceneError};
use glam::Vec3;

fn open(path: &Path) -> Result<Scene, SceneError> {
    Scene::open(path.to_str().unwrap())
}

fn sponza_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/sponza.obj")
}

#[test]
fn gltf_meshes_materials_transforms_and_cameras_load() {
    let dir = tempfile::tempdir().unwrap();
    let positions: [[f32; 3]; 4] = [
        [-1.0, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    let indices: [u16; 6] = [0, 1, 2, 0, 2, 3];
    let mut bin: Vec<u8> = bytemuck::cast_slice(&positions).to_vec();
    bin.extend_from_slice(bytemuck::cast_slice(&indices));
    std::fs::write(dir.path().join("quad.bin"), &bin).unwrap();
    let gltf_json = |buffer: &str| {
        format!(
            r#"{{
  "asset": {{"version": "2.0"}},
  "scene": 0,
  "scenes": [{{"nodes": [0, 1]}}],
  "nodes": [
    {{"mesh": 0, "translation": [0, 0, -5]}},
    {{"camera": 0, "name": "cam", "translation": [0, 1, 3]}}
  ],
  "cameras": [{{"type": "perspective", "perspective": {{"yfov": 0.8, "znear": 0.1}}}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1, "material": 0}}]}}],
  "materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}}}],
  "buffers": [{buffer}],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
    {{"buffer": 0, "byteOffset": 48, "byteLength": 12}}
  ],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "min": [-1, -1, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}}
  ]
}}"#
        )
    };
    let path = dir.path().join("quad.gltf");
    let external = format!(r#"{{"byteLength": {}, "uri": "quad.bin"}}"#, bin.len());
    std::fs::write(&path, gltf_json(&external)).unwrap();
    let glb_path = dir.path().join("quad.glb");
    let embedded = format!(r#"{{"byteLength": {}}}"#, bin.len());
    std::fs::write(&glb_path, glb(&gltf_json(&embedded), &bin)).unwrap();
    assert_eq!(
        open(&glb_path).unwrap().mesh.positions,
        open(&path).unwrap().mesh.positions
    );
    let scene = open(&path).unwrap();
    assert_eq!(scene.mesh.triangle_count(), 2);
    assert!(scene.mesh.positions.iter().all(|p| p.z == -5.0));
    assert!(
        scene
            .mesh
            .normals
            .iter()
            .all(|n| (*n - Vec3::Z).length() < 1e-6)
    );
    assert!(
        scene
            .mesh
            .albedo
            .iter()
            .all(|a| (*a - Vec3::new(0.2, 0.4, 0.6)).length() < 1e-6)
    );
    let camera = scene.camera(Some("cam")).unwrap();
    assert_eq!(camera.eye, Vec3::new(0.0, 1.0, 3.0));
    assert_eq!(camera.target, Vec3::new(0.0, 1.0, 2.0));
    assert_eq!(
        camera.lens,
        Lens::Perspective {
            fov_y_deg: 0.8f32.to_degrees()
        }
    );
    assert_eq!(camera.near, Some(0.1));
    assert_eq!(camera.far, None);

    std::fs::remove_file(dir.path().join("quad.bin")).unwrap();
    let err = open(&path).unwrap_err().to_string();
    assert!(err.contains("quad.gltf"), "{err}");
}

/// A binary glTF: header, JSON chunk padded with spaces, BIN chunk padded with zeros.
fn glb(json: &str, bin: &[u8]) -> Vec<u8> {
    let mut json = json.as_bytes().to_vec();
    json.resize(json.len().next_multiple_of(4), b' ');
    let mut bin = bin.to_vec();
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

#[test]
fn obj_with_normals_and_a_camera_sidecar_loads() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tri.obj");
    std::fs::write(
        &path,
        "v 0 0 0\nv 1 0 0\nv 0 0 -1\nvn 0 1 0\nf 1//1 2//1 3//1\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("tri-cameras.json"),
        r#"{"suggested_ao_radius": 0.25,
            "cameras": [{"name": "top", "eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 40}]}"#,
    )
    .unwrap();
    let scene = open(&path).unwrap();
    assert_eq!(scene.mesh.triangle_count(), 1);
    assert_eq!(scene.mesh.normals, vec![Vec3::Y; 3]);
    assert_eq!(scene.suggested_radius, Some(0.25));
    let camera = scene.camera(Some("0")).unwrap();
    assert_eq!((camera.name.as_str(), camera.up), ("top", Vec3::NEG_Z));
    let err = scene.camera(Some("side")).unwrap_err().to_string();
    assert!(err.contains("0: top"), "{err}");

    std::fs::write(
        dir.path().join("tri-cameras.json"),
        r#"{"cameras": [{"name": "x"}]}"#,
    )
    .unwrap();
    let err = open(&path).unwrap_err().to_string();
    assert!(err.contains("tri-cameras.json"), "{err}");
}

#[test]
fn malformed_files_are_refused_with_their_name() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("bad.obj", "v 0 0 0\nf 1 2 3\n"),
        ("empty.obj", "# nothing\n"),
        ("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n"),
        ("bad.gltf", "{\"asset\": "),
        ("bad.glb", "glTF but not really"),
        ("notes.txt", "hello"),
    ];
    for (name, contents) in cases {
        let path = dir.path().join(name);
        std::fs::write(&path, contents).unwrap();
        let err = open(&path).unwrap_err().to_string();
        assert!(err.contains(name), "{name}: {err}");
    }
}

#[test]
fn sponza_loads_with_its_named_cameras_and_renders() {
    let scene = open(&sponza_path()).unwrap();
    assert_eq!(scene.mesh.triangle_count(), 279_163);
    assert_eq!(scene.suggested_radius, Some(6.0));
    let names: Vec<&str> = scene.cameras.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["atrium", "arcade", "gallery", "floor"]);

    let gpu = GpuContext::headless().unwrap();
    let settings = AoSettings {
        radius: 6.0,
        ..AoSettings::default()
    };
    let mut renderer = Renderer::new(&gpu, &scene, &settings).unwrap();
    for camera in &scene.cameras {
        let frame = renderer.render(&gpu, camera, [96, 64], 0).unwrap();
        let covered = frame.linear_depth.iter().filter(|&&d| d > 0.0).count();
        assert!(
            covered > 96 * 64 * 9 / 10,
            "{}: only {covered} pixels covered",
            camera.name
        );
        assert!(
            frame.ao.iter().all(|a| (0.0..=1.0).contains(a)),
            "{}",
            camera.name
        );
        let mean = frame.ao.iter().sum::<f32>() / frame.ao.len() as f32;
        assert!(mean > 0.5 && mean < 0.99, "{}: mean AO {mean}", camera.name);
    }
}

/// A one-triangle GLB; `nodes`, `index` (the third index), `index_count` (the index accessor's
/// count) and `position_fields` (more fields of the POSITION accessor) vary per test.
fn triangle_glb(nodes: &str, index: u16, index_count: u32, position_fields: &str) -> Vec<u8> {
    let positions: [[f32; 3]; 3] = [[0.0, 0.0, -2.0], [1.0, 0.0, -2.0], [0.0, 1.0, -2.0]];
    let indices: [u16; 3] = [0, 1, index];
    let mut bin: Vec<u8> = bytemuck::cast_slice(&positions).to_vec();
    bin.extend_from_slice(bytemuck::cast_slice(&indices));
    let json = format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "scene": 0,
  "scenes": [{{"nodes": [0]}}],
  "nodes": {nodes},
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
  "buffers": [{{"byteLength": {}}}],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": 36}},
    {{"buffer": 0, "byteOffset": 36, "byteLength": 6}}
  ],
  "accessors": [
    {{"bufferView": 0, {position_fields}"componentType": 5126, "count": 3, "type": "VEC3",
      "min": [0, 0, -2], "max": [1, 1, -2]}},
    {{"bufferView": 1, "componentType": 5123, "count": {index_count}, "type": "SCALAR"}}
  ]
}}"#,
        bin.len()
    );
    glb(&json, &bin)
}

/// The default [`triangle_glb`] with the bytes `from` replaced by `to`, of the same length so
/// that the GLB's chunk lengths still hold.
fn triangle_patched(from: &[u8], to: &[u8]) -> Vec<u8> {
    assert_eq!(from.len(), to.len());
    let mut bytes = triangle_glb(r#"[{"mesh": 0}]"#, 2, 3, "");
    let at = bytes.windows(from.len()).position(|w| w == from).unwrap();
    bytes[at..at + from.len()].copy_from_slice(to);
    bytes
}

/// The error loading the glTF `bytes` under the file name `name` gives.
fn gltf_error(name: &str, bytes: &[u8]) -> String {
    aokit_scene::load::gltf::load_slice(name, bytes)
        .unwrap_err()
        .to_string()
}

/// [`triangle_glb`] written to `dir/name`.
fn triangle_gltf(dir: &Path, name: &str, nodes: &str, index: u16, index_count: u32) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, triangle_glb(nodes, index, index_count, "")).unwrap();
    path
}

#[test]
fn gltf_index_past_the_vertices_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let nodes = r#"[{"mesh": 0}]"#;
    assert_eq!(
        open(&triangle_gltf(dir.path(), "ok.glb", nodes, 2, 3))
            .unwrap()
            .mesh
            .triangle_count(),
        1
    );
    // Index 7 of 3 vertices: a panic while generating normals before the fix.
    let path = triangle_gltf(dir.path(), "bad-index.glb", nodes, 7, 3);
    let err = open(&path).unwrap_err().to_string();
    assert!(err.contains("bad-index.glb"), "{err}");
    assert!(err.contains("index 7 is out of range"), "{err}");
}

#[test]
fn gltf_node_cycle_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // Node 0 is its own child; then a longer cycle 0 -> 1 -> 0.
    for (name, nodes) in [
        ("self.glb", r#"[{"mesh": 0, "children": [0]}]"#),
        (
            "loop.glb",
            r#"[{"children": [1]}, {"mesh": 0, "children": [0]}]"#,
        ),
    ] {
        let path = triangle_gltf(dir.path(), name, nodes, 2, 3);
        let err = open(&path).unwrap_err().to_string();
        assert!(err.contains(name), "{err}");
        assert!(err.contains("cycle"), "{err}");
    }
}

#[test]
fn gltf_accessor_past_its_buffer_view_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // Six indices in a view that holds three: read as "no indices" before the fix.
    let path = triangle_gltf(dir.path(), "long.glb", r#"[{"mesh": 0}]"#, 2, 6);
    let err = open(&path).unwrap_err().to_string();
    assert!(err.contains("long.glb"), "{err}");
    assert!(
        err.contains("accessor 1 (indices): 6 elements need 12 bytes"),
        "{err}"
    );
}

#[test]
fn sidecar_with_a_bad_radius_is_refused_with_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tri.obj");
    std::fs::write(&path, "v 0 0 0\nv 1 0 0\nv 0 0 -1\nf 1 2 3\n").unwrap();
    // Before, the radius reached the settings, whose message cannot name the file.
    std::fs::write(
        dir.path().join("tri-cameras.json"),
        r#"{"suggested_ao_radius": -0.5}"#,
    )
    .unwrap();
    let err = open(&path).unwrap_err().to_string();
    assert!(
        err.contains("tri-cameras.json") && err.contains("suggested_ao_radius -0.5"),
        "{err}"
    );
}

/// Found by the `obj` fuzz target (fuzz/): a face's relative normal index before the first
/// normal (`-5` with one normal) made tobj multiply a wrapped index: a panic where overflow
/// checks are on, another vertex's normal or a wrapped read where they are off.
#[test]
fn obj_face_index_outside_its_normals_is_refused() {
    let crash: &[u8] = b"g tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-5 -2 -1//-1\ns 1\n\
        l 1 2\np 3\nri\nmtllib cube.mtl\nuse -0.5\nv 0 0 1\nd -3//-0 -2 -1//-";
    let err = aokit_scene::load::obj::load_slice("crash.obj", crash, None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("crash.obj")
            && err.contains("line 6: face normal index -5 is out of range for the 1 normals"),
        "{err}"
    );
    // The same past the end, counting from 1, and 0, for texture coordinates and positions.
    for (face, message) in [
        (
            "f 1/1 2/1 3/9",
            "face texture coordinate index 9 is out of range for the 1",
        ),
        (
            "f 1//1 2//1 3//0",
            "face normal index 0 is out of range for the 1",
        ),
        ("f 1 2 4", "face position index 4 is out of range for the 3"),
    ] {
        let obj = format!("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n{face}\n");
        let err = aokit_scene::load::obj::load_slice("tri.obj", obj.as_bytes(), None)
            .unwrap_err()
            .to_string();
        assert!(err.contains(message), "{face}: {err}");
    }
    // Relative indices within range still load.
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf -3/-1/-1 -2/-1/-1 -1/-1/-1\n";
    let scene = aokit_scene::load::obj::load_slice("tri.obj", obj, None).unwrap();
    assert_eq!(scene.mesh.triangle_count(), 1);
}

/// Found by the `obj` fuzz target: finite positions 5.6e32 apart gave an infinite bounding
/// radius, and so a framing camera at infinity ("non-finite eye"). The loaders refuse such an
/// extent, naming it; every part of an OBJ may be finite on its own.
#[test]
fn positions_too_far_apart_for_f32_are_refused() {
    let crash =
        b"v 0 0 0\nv 2 0 0\nv 2 0 -555555555555555555555555555555552\nv 0 1 -2\nf 1 2 3 4\n";
    let err = aokit_scene::load::obj::load_slice("far.obj", crash, None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("far.obj") && err.contains("farther than 32-bit floats can measure"),
        "{err}"
    );
    let two_parts = b"o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\
        o b\nv 3e19 0 0\nv 3e19 1 0\nv 3e19 0 1\nf 4 5 6\n";
    let err = aokit_scene::load::obj::load_slice("parts.obj", two_parts, None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("farther than 32-bit floats can measure"),
        "{err}"
    );
}

/// Found by the `gltf` fuzz target (fuzz/): indices of signed shorts (componentType 5122),
/// which the specification forbids and the parser lets through, hit an `unreachable!()` in the
/// gltf crate's reader. They are refused, naming the accessor.
#[test]
fn gltf_indices_of_a_signed_type_are_refused() {
    let err = gltf_error("signed.glb", &triangle_patched(b"5123", b"5122"));
    assert!(
        err.contains("signed.glb") && err.contains("accessor 1 (indices) holds I16 Scalar"),
        "{err}"
    );
    // Unsigned shorts, as written, load.
    let bytes = triangle_glb(r#"[{"mesh": 0}]"#, 2, 3, "");
    assert!(aokit_scene::load::gltf::load_slice("tri.glb", &bytes).is_ok());
}

/// Found by the `gltf` fuzz target (fuzz/): with its `accessors` key misspelt (`accessOrs`),
/// a file's POSITION named an accessor that does not exist, and the gltf crate's own
/// validation indexed it: a panic. It is refused, naming the mesh and primitive.
#[test]
fn gltf_position_naming_a_missing_accessor_is_refused() {
    let crash = r#"{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}], "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessOrs": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36, "uri": "data:applicataon/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}"#;
    let err = aokit_scene::load::gltf::load_slice("crash.gltf", crash.as_bytes())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("crash.gltf")
            && err.contains("mesh 0, primitive 0: POSITION names accessor 0, but the file has 0"),
        "{err}"
    );
    // Spelt right, it loads.
    let fixed = crash.replace("accessOrs", "accessors");
    assert!(aokit_scene::load::gltf::load_slice("fixed.gltf", fixed.as_bytes()).is_ok());
}

/// Found by the `gltf` fuzz target (fuzz/): a GLB header whose length field is under the
/// header's own 12 bytes made the gltf crate subtract past zero (a panic where overflow checks
/// are on). It is refused.
#[test]
fn glb_length_shorter_than_its_header_is_refused() {
    let mut glb = b"glTF\x02\x00\x00\x00\x00\x00\x00\x00".to_vec();
    glb.extend_from_slice(&[0; 24]);
    let err = aokit_scene::load::gltf::load_slice("short.glb", &glb)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("short.glb")
            && err.contains("a length of 0 bytes, less than the header's own 12"),
        "{err}"
    );
}

/// Found by the `gltf` fuzz target (fuzz/): a buffer's relative URI with `%AA`, which
/// percent-decodes to a byte that is not UTF-8, made the gltf crate's import unwrap an error
/// (a panic). It is refused, naming the buffer.
#[test]
fn gltf_buffer_uri_decoding_to_non_utf8_is_refused() {
    let json = r#"{"asset": {"version": "2.0"}, "scenes": [{"nodes": []}],
        "buffers": [{"byteLength": 4, "uri": "mesh%AA.bin"}]}"#;
    let err = aokit_scene::load::gltf::load_slice("crash.gltf", json.as_bytes())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("crash.gltf")
            && err.contains(
                r#"buffer 0: URI "mesh%AA.bin" percent-decodes to bytes that are not UTF-8"#
            ),
        "{err}"
    );
}

/// Found by the `gltf` fuzz target (fuzz/): a POSITION accessor of another type than float
/// VEC3 was read as f32 triples all the same (a debug assertion in the gltf crate, garbage
/// positions without one). It is refused, naming the accessor and its type.
#[test]
fn gltf_positions_of_another_type_are_refused() {
    // componentType 5126 (float) to 5125 (unsigned int).
    let err = gltf_error("ints.glb", &triangle_patched(b"5126", b"5125"));
    assert!(
        err.contains("ints.glb")
            && err.contains("accessor 0 (POSITION) holds U32 Vec3, not float VEC3"),
        "{err}"
    );
}

/// Found by the `gltf` fuzz target (fuzz/): an accessor of count 0, which glTF forbids, made
/// the gltf crate's reader compute `count - 1` (a panic where overflow checks are on), as a
/// sparse accessor's count 0 does. Both are refused, naming the accessor.
#[test]
fn gltf_accessors_of_no_elements_are_refused() {
    let empty = triangle_patched(
        br#""count": 3, "type": "VEC3""#,
        br#""count": 0, "type": "VEC3""#,
    );
    let err = gltf_error("empty.glb", &empty);
    assert!(
        err.contains("empty.glb") && err.contains("accessor 0 (POSITION): count 0"),
        "{err}"
    );
    let sparse = r#""sparse": {"count": 0, "indices": {"bufferView": 1, "componentType": 5123},
        "values": {"bufferView": 0}}, "#;
    let err = gltf_error(
        "sparse.glb",
        &triangle_glb(r#"[{"mesh": 0}]"#, 2, 3, sparse),
    );
    assert!(
        err.contains("sparse.glb") && err.contains("count 0"),
        "{err}"
    );
}
