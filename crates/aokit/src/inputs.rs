//! What a frame hands to the pipeline, and the checks on it.

use glam::Mat4;

use crate::passes::temporal_filter::MOTION_VECTOR_FORMATS;
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
    /// The camera's world-to-view transform this frame. The temporal filter reprojects with
    /// it and the one this view had last frame; nothing else reads it.
    pub view_from_world: Mat4,
    /// Frame counter; it moves the sampling noise from frame to frame.
    pub frame_index: u32,
    /// Which of the caller's views this is (split screen, a probe): each keeps its own
    /// temporal history in the pipeline.
    pub view_id: u32,
    /// Per-pixel motion for the temporal filter, when the renderer has it (for moving
    /// objects): `Rg16Float` or `Rg32Float` of the depth's size, the offset in pixels from each
    /// pixel to where its surface was last frame. `None` reprojects by depth and the camera
    /// alone, which is right for a still scene.
    pub motion_vectors: Option<&'a wgpu::Texture>,
    /// Start the temporal history over: the view shows something unrelated to last frame (a
    /// camera cut, a teleport).
    pub reset_history: bool,
}

impl<'a> AoInputs<'a> {
    /// Inputs for one frame of view 0 with everything optional left out: no normals (they are
    /// reconstructed), an identity camera transform, frame 0, no motion vectors.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture, normals: &wgpu::Texture, view: glam::Mat4, frame: u32) {
    /// let projection = aokit::Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
    /// let inputs = aokit::AoInputs {
    ///     normals: Some(normals),
    ///     view_from_world: view,
    ///     frame_index: frame,
    ///     ..aokit::AoInputs::new(depth, projection)
    /// };
    /// # }
    /// ```
    pub fn new(depth: &'a wgpu::Texture, projection: Projection) -> Self {
        Self {
            depth,
            normals: None,
            projection,
            view_from_world: Mat4::IDENTITY,
            frame_index: 0,
            view_id: 0,
            motion_vectors: None,
            reset_history: false,
        }
    }
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
    /// Depth and another input differ in size.
    #[error("depth is {depth:?} pixels but the {what} are {other:?}")]
    SizeMismatch {
        /// Which input.
        what: &'static str,
        /// Depth texture size.
        depth: [u32; 2],
        /// The other texture's size.
        other: [u32; 2],
    },
    /// The motion vectors are not in a format the temporal filter reads.
    #[error("motion vector texture format {0:?} is neither Rg16Float nor Rg32Float")]
    MotionVectorFormat(wgpu::TextureFormat),
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
            same_size("normals", size, normals)?;
        }
        if let Some(motion) = self.motion_vectors {
            if !MOTION_VECTOR_FORMATS.contains(&motion.format()) {
                return Err(InputError::MotionVectorFormat(motion.format()));
            }
            check_readable("motion vectors", motion)?;
            same_size("motion vectors", size, motion)?;
        }
        Ok(size)
    }
}

fn same_size(
    what: &'static str,
    depth: [u32; 2],
    texture: &wgpu::Texture,
) -> Result<(), InputError> {
    let other = [texture.width(), texture.height()];
    if depth == other {
        Ok(())
    } else {
        Err(InputError::SizeMismatch { what, depth, other })
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
