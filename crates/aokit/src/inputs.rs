//! What a frame hands to the pipeline, and the checks on it.

use crate::projection::Projection;

/// Per-frame inputs of [`AoPipeline::encode`](crate::AoPipeline::encode).
#[derive(Clone, Copy, Debug)]
pub struct AoInputs<'a> {
    /// The depth buffer, any depth format (`Depth32Float`, `Depth24Plus`, `Depth16Unorm`, with
    /// or without stencil), single-sampled, with `TEXTURE_BINDING` usage.
    pub depth: &'a wgpu::Texture,
    /// View-space normals in the `oct32` encoding (see [`shader::ENCODING`](crate::shader::ENCODING)):
    /// an `R32Uint` texture of the depth buffer's size, with `TEXTURE_BINDING` usage.
    pub normals: &'a wgpu::Texture,
    /// The projection the depth buffer was rendered with.
    pub projection: Projection,
    /// Frame counter; it moves the sampling noise from frame to frame.
    pub frame_index: u32,
}

/// Why the inputs cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InputError {
    /// The depth texture has no depth aspect.
    #[error("depth texture format {0:?} is not a depth format")]
    DepthFormat(wgpu::TextureFormat),
    /// The normals texture is not `R32Uint`.
    #[error("normals texture format {0:?} is not R32Uint (oct32-encoded normals)")]
    NormalsFormat(wgpu::TextureFormat),
    /// A texture is multisampled.
    #[error("the {0} texture is multisampled; resolve it or pass a single-sampled copy")]
    Multisampled(&'static str),
    /// A texture cannot be bound for reading.
    #[error("the {0} texture lacks TEXTURE_BINDING usage")]
    NotBindable(&'static str),
    /// Depth and normals differ in size.
    #[error("depth is {depth:?} pixels but normals are {normals:?}")]
    SizeMismatch {
        /// Depth texture size.
        depth: [u32; 2],
        /// Normals texture size.
        normals: [u32; 2],
    },
}

impl AoInputs<'_> {
    /// The resolution the inputs describe, after checking formats, usages and sizes.
    pub fn validate(&self) -> Result<[u32; 2], InputError> {
        let depth = self.depth;
        let normals = self.normals;
        if !depth.format().has_depth_aspect() {
            return Err(InputError::DepthFormat(depth.format()));
        }
        if normals.format() != wgpu::TextureFormat::R32Uint {
            return Err(InputError::NormalsFormat(normals.format()));
        }
        for (name, texture) in [("depth", depth), ("normals", normals)] {
            if texture.sample_count() > 1 {
                return Err(InputError::Multisampled(name));
            }
            if !texture
                .usage()
                .contains(wgpu::TextureUsages::TEXTURE_BINDING)
            {
                return Err(InputError::NotBindable(name));
            }
        }
        let size = [depth.width(), depth.height()];
        let normals_size = [normals.width(), normals.height()];
        if size != normals_size {
            return Err(InputError::SizeMismatch {
                depth: size,
                normals: normals_size,
            });
        }
        Ok(size)
    }
}
