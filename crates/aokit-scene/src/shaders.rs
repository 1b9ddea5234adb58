//! The scene renderer's WGSL programs, sharing aokit's normal encoding and occlusion functions.

use aokit::shader::{ENCODING, OCCLUSION, ShaderSource};

/// G-buffer raster.
pub const GBUFFER: ShaderSource = ShaderSource {
    name: "gbuffer",
    parts: &[ENCODING, include_str!("../shaders/gbuffer.wgsl")],
};

/// Lit composite.
pub const COMPOSITE: ShaderSource = ShaderSource {
    name: "composite",
    parts: &[
        ENCODING,
        OCCLUSION,
        include_str!("../shaders/composite.wgsl"),
    ],
};

/// Sun shadow map.
pub const SHADOW: ShaderSource = ShaderSource {
    name: "shadow",
    parts: &[include_str!("../shaders/shadow.wgsl")],
};

/// Every program of this crate.
///
/// ```
/// // Catches a WGSL error on the CPU, before any device is opened.
/// for shader in aokit_scene::shaders::ALL {
///     let validated = shader.validate();
///     assert!(validated.is_ok(), "{}: {}", shader.name, validated.unwrap_err());
/// }
/// ```
pub const ALL: &[ShaderSource] = &[GBUFFER, COMPOSITE, SHADOW];

#[cfg(test)]
mod tests {
    #[test]
    fn every_shader_validates_with_naga() {
        for shader in super::ALL {
            shader.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }

    #[test]
    fn every_wgsl_file_is_part_of_a_validated_program() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
        for entry in std::fs::read_dir(dir).unwrap() {
            let name = entry.unwrap().file_name().into_string().unwrap();
            let pass = name
                .strip_suffix(".wgsl")
                .expect("only WGSL files in shaders/");
            assert!(
                super::ALL.iter().any(|s| s.name == pass),
                "shaders/{name} is not in shaders::ALL, so nothing validates it"
            );
        }
    }
}
