//! camera.json as `aokit ao --camera` reads it: parse, then the projection and the view
//! transform. An accepted file gives a projection that validates with finite matrices.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(file) = serde_json::from_slice::<aokit_scene::CameraFile>(data) else {
        return;
    };
    let _ = file.view_from_world();
    if let Ok(projection) = file.projection() {
        projection
            .validate()
            .expect("an accepted projection validates");
        assert!(projection.near.is_finite() && projection.near > 0.0);
        assert!(projection.aspect.is_finite() && projection.aspect > 0.0);
        // What the pipeline's uniforms are made of.
        let matrix = projection.clip_from_view();
        assert!(matrix.is_finite(), "clip_from_view {matrix} of {file:?}");
        let linearize = projection.linearize_coefficients();
        assert!(linearize.is_finite(), "linearize {linearize} of {file:?}");
        let scale = projection.ndc_to_view_scale();
        assert!(scale.is_finite(), "ndc_to_view_scale {scale} of {file:?}");
    }
});
