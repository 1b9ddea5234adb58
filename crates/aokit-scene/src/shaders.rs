//! The scene renderer's WGSL programs, sharing aokit's normal encoding.

use aokit::shader::{ENCODING, ShaderSource};

/// G-buffer raster.
pub const GBUFFER: ShaderSource = ShaderSource {
    name: "gbuffer",
    parts: &[ENCODING, include_str!("../shaders/gbuffer.wgsl")],
};

/// Lit composite.
pub const COMPOSITE: ShaderSource = ShaderSource {
    name: "composite",
    parts: &[ENCODING, include_str!("../shaders/composite.wgsl")],
};

/// Sun shadow map.
pub const SHADOW: ShaderSource = ShaderSource {
    name: "shadow",
    parts: &[include_str!("../shaders/shadow.wgsl")],
};

/// Every program of this crate.
pub const ALL: &[ShaderSource] = &[GBUFFER, COMPOSITE, SHADOW];

#[cfg(test)]
mod tests {
    #[test]
    fn every_shader_validates_with_naga() {
        for shader in super::ALL {
            shader.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }
}
