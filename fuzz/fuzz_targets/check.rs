//! What an accepted input must give, shared by the targets (each includes this file).
#![allow(dead_code)]

/// A loaded scene: indices within its vertices, finite positions and normals, finite bounds,
/// and cameras that either validate or are refused by `Camera::validate` where they are used.
pub fn scene(scene: &aokit_scene::Scene) {
    let mesh = &scene.mesh;
    mesh.validate().expect("a loaded mesh validates");
    assert!(mesh.triangle_count() > 0, "a loaded scene has triangles");
    assert!(
        mesh.normals.iter().all(|n| n.is_finite()),
        "a loaded mesh has finite normals"
    );
    assert!(
        mesh.albedo.iter().all(|a| a.is_finite()),
        "a loaded mesh has finite albedo"
    );
    assert!(
        scene.bounds.min.is_finite() && scene.bounds.max.is_finite(),
        "finite bounds"
    );
    if let Some(radius) = scene.suggested_radius {
        assert!(radius.is_finite() && radius > 0.0, "radius {radius}");
    }
    // What `aokit render` picks with no --camera: the file's first, or a framing camera. The
    // CLI validates it before use; a framing camera of a loaded scene must pass.
    if scene.cameras.is_empty() && scene.mesh.area_triangle_count() > 0 {
        let camera = scene.camera(None).expect("a default camera");
        if let Err(e) = camera.validate() {
            panic!("the framing camera of an accepted scene is invalid: {e}");
        }
    }
}

/// A read image: the size it claims, and as many samples.
pub fn image(image: &aokit_eval::FloatImage, channels: u32) {
    assert!(image.width > 0 && image.height > 0);
    assert_eq!(image.channels, channels);
    assert_eq!(
        image.data.len(),
        image.width as usize * image.height as usize * channels as usize
    );
}
