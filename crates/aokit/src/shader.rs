//! WGSL programs assembled from shared snippets.
//!
//! WGSL has no `#include`, so every pass is the concatenation of the snippets it uses and its own
//! file. The snippets are public so that renderers (aokit-scene, or yours) can encode normals
//! exactly as aokit decodes them.

use wgpu::naga;

/// Camera conventions, the `ViewUniforms` binding and position reconstruction.
pub const VIEW: &str = include_str!("../shaders/common/view.wgsl");
/// Normal encodings (`pack_oct32`, `unpack_oct32`, ...).
pub const ENCODING: &str = include_str!("../shaders/common/encoding.wgsl");
/// Per-pixel noise.
pub const NOISE: &str = include_str!("../shaders/common/noise.wgsl");

/// One WGSL program: the snippets it needs followed by its own file.
#[derive(Clone, Copy, Debug)]
pub struct ShaderSource {
    /// Name of the pass, used as the module label.
    pub name: &'static str,
    /// Source pieces, concatenated in order.
    pub parts: &'static [&'static str],
}

/// Hardware depth to linear view depth.
pub const LINEAR_DEPTH: ShaderSource = ShaderSource {
    name: "linear_depth",
    parts: &[VIEW, include_str!("../shaders/linear_depth.wgsl")],
};

/// The GTAO kernel.
pub const GTAO: ShaderSource = ShaderSource {
    name: "gtao",
    parts: &[VIEW, ENCODING, NOISE, include_str!("../shaders/gtao.wgsl")],
};

/// Every program the library compiles.
pub const ALL: &[ShaderSource] = &[LINEAR_DEPTH, GTAO];

impl ShaderSource {
    /// The assembled WGSL text.
    pub fn source(&self) -> String {
        self.parts.join("\n")
    }

    /// Compiles the program on `device`.
    pub fn create_module(&self, device: &wgpu::Device) -> wgpu::ShaderModule {
        device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(self.name),
            source: wgpu::ShaderSource::Wgsl(self.source().into()),
        })
    }

    /// Parses and validates the program with naga, as wgpu does, without a device. Returns the
    /// module so tests can inspect it (e.g. struct layouts).
    pub fn validate(&self) -> Result<naga::Module, String> {
        let source = self.source();
        let module = naga::front::wgsl::parse_str(&source)
            .map_err(|e| format!("{}: {}", self.name, e.emit_to_string(&source)))?;
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .map_err(|e| format!("{}: {}", self.name, e.emit_to_string(&source)))?;
        Ok(module)
    }
}

/// Byte offsets and size of a WGSL struct as naga lays it out, for checks against the Rust mirror.
pub fn struct_layout(module: &naga::Module, name: &str) -> Option<(Vec<(String, u32)>, u32)> {
    module.types.iter().find_map(|(_, ty)| match &ty.inner {
        naga::TypeInner::Struct { members, span } if ty.name.as_deref() == Some(name) => Some((
            members
                .iter()
                .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                .collect(),
            *span,
        )),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shader_validates_with_naga() {
        for shader in ALL {
            shader.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }
}
