//! What a frame hands to the pipeline, and the checks on it.

use crate::projection::Projection;
use crate::settings::NormalEncoding;

/// Per-frame inputs of [`AoPipeline::encode`](crate::AoPipeline::encode).
#[derive(Clone, Copy, Debug)]
pub struct AoInputs<'a> {
    /// The depth buffer, single-sampled, with `TEXTURE_BINDING` usage: any depth format
    /// (`Depth32Float`, `Depth24Plus`, `Depth16Unorm`, with or without stencil) holding NDC depth
    /// as [`AoInputs::projection`] wrote it, or `R32Float` holding linear view depth (positive
    /// distance along the view axis; 0, negative, NaN or infinity where there is no surface).
    pub depth: &'a wgpu::Texture,
    /// View-space unit normals in the encoding [`NormalsSettings::encoding`](crate::NormalsSettings::encoding)
    /// names (`oct32` by default; [`shader::ENCODING`](crate::shader::ENCODING) has the WGSL to
    /// write each one), in a texture of [`NormalEncoding::texture_format`], the depth's size and
    /// `TEXTURE_BINDING` usage. `None` reconstructs them from depth, which is less precise at
    /// edges and on curved surfaces. When [`NormalsSettings::source`](crate::NormalsSettings::source)
    /// names a reconstruction from depth they are not read, but still checked.
    pub normals: Option<&'a wgpu::Texture>,
    /// The projection the depth was rendered with.
    pub projection: Projection,
    /// Frame counter; it moves the sampling noise from frame to frame.
    pub frame_index: u32,
}

/// Why the inputs cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InputError {
    /// The depth texture is neither a depth format nor `R32Float`.
    #[error("depth texture format {0:?} is neither a depth format nor R32Float linear depth")]
    DepthFormat(wgpu::TextureFormat),
    /// The normals texture's format is not the one its encoding is stored in.
    #[error(
        "normals texture format {format:?} cannot hold the `{}` normal encoding the settings \
         name, which is stored as {:?}",
        encoding.name(),
        encoding.texture_format()
    )]
    NormalsFormat {
        /// The normals texture's format.
        format: wgpu::TextureFormat,
        /// The encoding the settings name.
        encoding: NormalEncoding,
    },
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
    /// The resolution the inputs describe, after checking formats (the normals' against
    /// `encoding`), usages and sizes.
    pub fn validate(&self, encoding: NormalEncoding) -> Result<[u32; 2], InputError> {
        let depth = self.depth;
        if !(depth.format().has_depth_aspect() || depth.format() == wgpu::TextureFormat::R32Float) {
            return Err(InputError::DepthFormat(depth.format()));
        }
        check_readable("depth", depth)?;
        let size = [depth.width(), depth.height()];
        if let Some(normals) = self.normals {
            if normals.format() != encoding.texture_format() {
                return Err(InputError::NormalsFormat {
                    format: normals.format(),
                    encoding,
                });
            }
            check_readable("normals", normals)?;
            let normals_size = [normals.width(), normals.height()];
            if size != normals_size {
                return Err(InputError::SizeMismatch {
                    depth: size,
                    normals: normals_size,
                });
            }
        }
        Ok(size)
    }
}

fn check_readable(name: &'static str, texture: &wgpu::Texture) -> Result<(), InputError> {
    if texture.sample_count() > 1 {
        return Err(InputError::Multisampled(name));
    }
    if !texture
        .usage()
        .contains(wgpu::TextureUsages::TEXTURE_BINDING)
    {
        return Err(InputError::NotBindable(name));
    }
    Ok(())
}
