//! What a frame hands to the pipeline, and the checks on it.

use glam::Mat4;

use crate::input_texture::AoTexture;
use crate::passes::filter::temporal_filter::MOTION_VECTOR_FORMATS;
use crate::projection::Projection;
use crate::settings::NormalEncoding;

/// Per-frame inputs of [`AoPipeline::encode`](crate::AoPipeline::encode).
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder,
/// #      pipeline: &mut aokit::AoPipeline, depth: &wgpu::Texture, normals: &wgpu::Texture,
/// #      motion: &wgpu::Texture, projection: aokit::Projection, view_from_world: glam::Mat4,
/// #      frame: u32, camera_cut: bool) -> Result<(), aokit::AoError> {
/// // The second player's half of a split screen: view 1 keeps a temporal history apart from
/// // the first player's, and the motion vectors reproject the players' moving characters.
/// let inputs = aokit::AoInputs {
///     depth: depth.into(),
///     normals: Some(normals.into()),
///     projection,
///     view_from_world,
///     frame_index: frame,
///     view_id: 1,
///     motion_vectors: Some(motion.into()),
///     reset_history: camera_cut,
///     mask: None,
///     back_depth: None,
///     guard_band: 0,
/// };
/// let outputs = pipeline.encode(device, queue, encoder, &inputs)?;
/// // ... the second player's lighting pass binds `outputs.ao_view` ...
/// # Ok(()) }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct AoInputs<'a> {
    /// The depth buffer, with `TEXTURE_BINDING` usage: any depth format (`Depth32Float`,
    /// `Depth24Plus`, `Depth16Unorm`, with or without stencil) holding NDC depth as
    /// [`AoInputs::projection`] wrote it, or `R32Float` holding linear view depth (positive
    /// distance along the view axis; 0, negative, NaN or infinity where there is no surface).
    ///
    /// Multisampled depth is read at sample 0: each pixel gets the depth of one surface, so
    /// silhouettes stay sharp but step like the aliased image, and AO at an edge belongs to
    /// whichever side covers sample 0. A resolved depth you pass instead (single-sampled)
    /// is read as it is: resolve with min or max (or sample 0), never an average, which puts
    /// a surface between foreground and background that occludes both. docs/integration.md
    /// compares the two.
    ///
    /// Each texture here is an [`AoTexture`]: a whole texture (`texture.into()`) or a view of
    /// one mip level or array layer of one ([`AoTexture::view`]).
    pub depth: AoTexture<'a>,
    /// Unit normals, in view space or, with [`NormalsSettings::space`](crate::NormalsSettings::space)
    /// set to world, in world space, in the encoding
    /// [`NormalsSettings::encoding`](crate::NormalsSettings::encoding) names (`oct32` by default; [`shader::ENCODING`](crate::shader::ENCODING) has the WGSL to
    /// write each one), in a texture of [`NormalEncoding::texture_format`], the depth's size and
    /// `TEXTURE_BINDING` usage. `None` reconstructs them from depth, which is less precise at
    /// edges and on curved surfaces. When [`NormalsSettings::source`](crate::NormalsSettings::source)
    /// names a reconstruction from depth they are not read, but still checked.
    pub normals: Option<AoTexture<'a>>,
    /// The projection the depth was rendered with.
    pub projection: Projection,
    /// The camera's world-to-view transform this frame. The temporal filter reprojects with
    /// it and the one this view had last frame, and world-space normals are turned into view
    /// space with its rotation; nothing else reads it.
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
    pub motion_vectors: Option<AoTexture<'a>>,
    /// Start the temporal history over: the view shows something unrelated to last frame (a
    /// camera cut, a teleport).
    pub reset_history: bool,
    /// Pixels that receive no AO (characters, UI, a first-person weapon): [`AoOutputs::ao`]
    /// is 1 there. They still occlude their surroundings, since they are in the depth.
    ///
    /// [`AoOutputs::ao`]: crate::AoOutputs::ao
    pub mask: Option<AoMask<'a>>,
    /// The depth of the nearest back faces: the scene's depth drawn a second time, with the
    /// same camera and projection but front faces culled, in any format [`AoInputs::depth`]
    /// may have and of its size. With
    /// [`VbaoSettings::back_faces`](crate::VbaoSettings::back_faces) each occluder is as thick
    /// as the distance from its front face to the back face behind it; nothing else reads it.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture, back_depth: &wgpu::Texture, projection: aokit::Projection) {
    /// // The renderer drew `back_depth` with `cull_mode: Some(wgpu::Face::Front)`.
    /// let inputs = aokit::AoInputs {
    ///     back_depth: Some(back_depth.into()),
    ///     ..aokit::AoInputs::new(depth, projection)
    /// };
    /// # }
    /// ```
    pub back_depth: Option<AoTexture<'a>>,
    /// Pixels of overscan on each side of the depth, normals, motion vectors and back-face
    /// depth: the renderer drew them `2 * guard_band` pixels wider and taller than the output,
    /// with [`Projection::with_guard_band`], so that samples near the output's edges find the
    /// geometry just off screen. [`AoInputs::projection`] is the output's (the camera's) and
    /// the outputs cover only the inner frame; the kernel reads the band but computes AO for
    /// the inner frame alone (docs/integration.md measures what a band buys), and the temporal
    /// filter reads the motion vectors' inner frame. The mask is of the output's size. Below
    /// full resolution the band must be a multiple of the resolution's scale, so that the
    /// working grids of the input and of the inner frame line up. 0 is no band.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture, normals: &wgpu::Texture, camera: aokit::Projection) {
    /// // The G-buffer was drawn 32 px larger on each side, with the widened frustum.
    /// let band = 32;
    /// let _overscan = camera.with_guard_band([1920, 1080], band);
    /// let inputs = aokit::AoInputs {
    ///     normals: Some(normals.into()),
    ///     guard_band: band,
    ///     ..aokit::AoInputs::new(depth, camera)
    /// };
    /// // AO comes back 1920x1080.
    /// # }
    /// ```
    pub guard_band: u32,
}

/// Where [`AoInputs::mask`] takes the pixels that receive no AO from. Multisampled masks are
/// read at sample 0, as the depth is.
///
/// ```no_run
/// # fn f(depth_stencil: &wgpu::Texture, projection: aokit::Projection) {
/// // The renderer drew its characters with stencil reference 1 in the low bit.
/// let inputs = aokit::AoInputs {
///     mask: Some(aokit::AoMask::Stencil {
///         texture: depth_stencil.into(),
///         reference: 1,
///         read_mask: 0x01,
///     }),
///     ..aokit::AoInputs::new(depth_stencil, projection)
/// };
/// # }
/// ```
#[derive(Clone, Copy, Debug)]
pub enum AoMask<'a> {
    /// A single-channel `R8Unorm`, `R16Float` or `R32Float` texture of the depth's size with
    /// `TEXTURE_BINDING` usage: 1 receives no AO, 0 receives all of it, and values between
    /// blend (`ao' = ao + (1 - ao) * mask`, the mask clamped to [0, 1]), for soft edges.
    Texture(AoTexture<'a>),
    /// The stencil aspect of a texture of the depth's size (often the depth texture itself):
    /// pixels whose `stencil & read_mask` equals `reference & read_mask` receive no AO.
    Stencil {
        /// `Stencil8`, `Depth24PlusStencil8` or `Depth32FloatStencil8`, with
        /// `TEXTURE_BINDING` usage; a view of one shows the `StencilOnly` aspect.
        texture: AoTexture<'a>,
        /// The stencil value of the pixels to leave unoccluded.
        reference: u8,
        /// The stencil bits compared.
        read_mask: u8,
    },
}

/// Formats an [`AoMask::Texture`] may have.
///
/// ```
/// use aokit::inputs::MASK_TEXTURE_FORMATS;
/// // The smallest target a renderer's mask pass can draw into.
/// assert!(MASK_TEXTURE_FORMATS.contains(&wgpu::TextureFormat::R8Unorm));
/// // Single-channel only, even where the first channel would hold the mask.
/// assert!(!MASK_TEXTURE_FORMATS.contains(&wgpu::TextureFormat::Rg8Unorm));
/// ```
pub const MASK_TEXTURE_FORMATS: [wgpu::TextureFormat; 3] = [
    wgpu::TextureFormat::R8Unorm,
    wgpu::TextureFormat::R16Float,
    wgpu::TextureFormat::R32Float,
];

impl AoMask<'_> {
    /// The mask's texture.
    ///
    /// ```no_run
    /// # fn f(mask: &aokit::AoMask<'_>, depth: &wgpu::Texture) {
    /// // Whichever kind of mask it is, a window resize must remake it with the depth.
    /// let size = [depth.width(), depth.height()];
    /// debug_assert_eq!(mask.texture().size(), size, "mask left at the old size");
    /// # }
    /// ```
    pub fn texture(&self) -> AoTexture<'_> {
        match *self {
            AoMask::Texture(texture) | AoMask::Stencil { texture, .. } => texture,
        }
    }
}

impl<'a> AoInputs<'a> {
    /// Inputs for one frame of view 0 with everything optional left out: no normals (they are
    /// reconstructed), an identity camera transform, frame 0, no motion vectors.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture, normals: &wgpu::Texture, view: glam::Mat4, frame: u32) {
    /// let projection = aokit::Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
    /// let inputs = aokit::AoInputs {
    ///     normals: Some(normals.into()),
    ///     view_from_world: view,
    ///     frame_index: frame,
    ///     ..aokit::AoInputs::new(depth, projection)
    /// };
    /// # }
    /// ```
    pub fn new(depth: impl Into<AoTexture<'a>>, projection: Projection) -> Self {
        Self {
            depth: depth.into(),
            normals: None,
            projection,
            view_from_world: Mat4::IDENTITY,
            frame_index: 0,
            view_id: 0,
            motion_vectors: None,
            reset_history: false,
            mask: None,
            back_depth: None,
            guard_band: 0,
        }
    }
}

/// Why the inputs cannot be used.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline,
/// #      inputs: &aokit::AoInputs<'_>) -> Result<(), aokit::AoError> {
/// use aokit::{AoError, InputError};
/// let mut encoder = device.create_command_encoder(&Default::default());
/// match pipeline.encode(device, queue, &mut encoder, inputs) {
///     Ok(outputs) => { /* ... bind `outputs.ao_view` in the lighting pass ... */ }
///     // The renderer resized its depth but not yet its other targets: light this frame
///     // without AO rather than stop.
///     Err(AoError::Input(InputError::SizeMismatch { what, depth, other })) => {
///         eprintln!("no AO this frame: depth is {depth:?}, {what} {other:?}");
///     }
///     Err(e) => return Err(e),
/// }
/// queue.submit([encoder.finish()]);
/// # Ok(()) }
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InputError {
    /// The image has more pixels than [`MAX_PIXELS`].
    #[error(
        "{}x{} is {pixels} pixels, more than the {MAX_PIXELS} (8192x8192) aokit works on",
        size[0],
        size[1]
    )]
    TooManyPixels {
        /// Width and height.
        size: [u32; 2],
        /// Their product.
        pixels: u64,
    },
    /// World-space normals (`normals.space = world`) with an
    /// [`AoInputs::view_from_world`] whose rotation part is degenerate or not finite: every
    /// normal would turn into zero or NaN.
    #[error(
        "view_from_world's 3x3 part has determinant {determinant}: it cannot turn the world-space \
         normals (normals.space = world) into view space; pass the camera's world-to-view matrix"
    )]
    ViewFromWorld {
        /// The determinant of its 3x3 part.
        determinant: f32,
    },
    /// The depth (or back-face depth) texture is neither a depth format nor `R32Float`.
    #[error("{0} texture format {1:?} is neither a depth format nor R32Float linear depth")]
    DepthFormat(&'static str, wgpu::TextureFormat),
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
    /// An [`AoMask::Texture`] is not single-channel `R8Unorm`, `R16Float` or `R32Float`.
    #[error("mask texture format {0:?} is none of R8Unorm, R16Float and R32Float")]
    MaskFormat(wgpu::TextureFormat),
    /// [`AoInputs::guard_band`] leaves no inner frame: the band on both sides covers the depth.
    #[error(
        "a guard band of {band} px on each side leaves nothing of the {}x{} depth; the depth \
         must be larger than the output by twice the band",
        depth[0],
        depth[1]
    )]
    GuardBandTooWide {
        /// The band, in pixels on each side.
        band: u32,
        /// The depth's size.
        depth: [u32; 2],
    },
    /// A [`AoInputs::guard_band`] below full resolution that is not a multiple of the
    /// resolution's scale (or leaves an inner frame of one texel): the working grids of the
    /// input and of the inner frame would not line up.
    #[error(
        "a guard band of {band} px does not fit the working resolution: below full resolution \
         it must be a multiple of the scale ({scale}) and leave more than one pixel each way"
    )]
    GuardBandResolution {
        /// The band, in pixels on each side.
        band: u32,
        /// The resolution's scale.
        scale: u32,
    },
    /// An [`AoMask::Stencil`] texture has no stencil aspect.
    #[error("mask texture format {0:?} has no stencil aspect to compare with the reference")]
    MaskNoStencil(wgpu::TextureFormat),
    /// An [`AoTexture::view`]'s format is neither its texture's nor a form a view of it can
    /// take (the sRGB twin, one aspect of a depth-stencil format).
    #[error(
        "the {what} view is said to be {format:?}, which a view of a {parent:?} texture cannot be"
    )]
    ViewFormat {
        /// Which input.
        what: &'static str,
        /// The format given with the view.
        format: wgpu::TextureFormat,
        /// Its texture's format.
        parent: wgpu::TextureFormat,
    },
    /// An [`AoTexture::view`]'s size is none of its texture's mip level sizes.
    #[error(
        "the {what} view is said to be {size:?} pixels, but its texture's mip levels are {mips:?}"
    )]
    ViewSize {
        /// Which input.
        what: &'static str,
        /// The size given with the view.
        size: [u32; 2],
        /// Its texture's mip level sizes, the largest first.
        mips: Vec<[u32; 2]>,
    },
}

impl AoInputs<'_> {
    /// The output's resolution (the depth's, less [`AoInputs::guard_band`] on each side),
    /// after checking formats (the normals' against `encoding`), usages and sizes.
    ///
    /// ```no_run
    /// # fn f(inputs: &aokit::AoInputs<'_>, settings: &aokit::AoSettings) {
    /// use aokit::InputError;
    /// // Checked once when the G-buffer is made, rather than by every frame's `encode`.
    /// match inputs.validate(settings.normals.encoding) {
    ///     Ok([width, height]) => println!("AO at {width}x{height}"),
    ///     Err(InputError::NormalsFormat { format, encoding }) => panic!(
    ///         "the G-buffer's normals are {format:?}, but normals.encoding = {} needs {:?}",
    ///         encoding.name(),
    ///         encoding.texture_format()
    ///     ),
    ///     Err(e) => panic!("{e}"),
    /// }
    /// # }
    /// ```
    pub fn validate(&self, encoding: NormalEncoding) -> Result<[u32; 2], InputError> {
        let depth = self.depth;
        check_depth("depth", depth)?;
        let size = depth.size();
        check_size(size)?;
        let output = self.output_size()?;
        if let Some(back) = self.back_depth {
            check_depth("back-face depth", back)?;
            same_size("back-face depth", size, back)?;
        }
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
        if let Some(mask) = &self.mask {
            let format = mask.texture().format();
            match mask {
                AoMask::Texture(_) if !MASK_TEXTURE_FORMATS.contains(&format) => {
                    return Err(InputError::MaskFormat(format));
                }
                AoMask::Stencil { .. } if !format.has_stencil_aspect() => {
                    return Err(InputError::MaskNoStencil(format));
                }
                _ => {}
            }
            mask.texture().check("mask")?;
            same_size("mask", output, mask.texture())?;
        }
        Ok(output)
    }

    /// The output's size: the depth's less [`AoInputs::guard_band`] on each side, or
    /// [`InputError::GuardBandTooWide`] when nothing is left.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture, camera: aokit::Projection) -> Result<(), aokit::InputError> {
    /// // A 1984x1144 overscan depth with a 32 px band holds a 1920x1080 frame.
    /// let inputs = aokit::AoInputs { guard_band: 32, ..aokit::AoInputs::new(depth, camera) };
    /// assert_eq!(inputs.output_size()?, [depth.width() - 64, depth.height() - 64]);
    /// # Ok(()) }
    /// ```
    pub fn output_size(&self) -> Result<[u32; 2], InputError> {
        let depth = self.depth.size();
        let band = self.guard_band;
        let inner = depth.map(|side| side.saturating_sub(band.saturating_mul(2)));
        if inner.contains(&0) {
            return Err(InputError::GuardBandTooWide { band, depth });
        }
        Ok(inner)
    }
}

/// The most pixels an image may have: 8192x8192, the largest side every wgpu device supports,
/// squared. A limit on each side alone let 16384x16384 (268 million pixels) through, and
/// `aokit render` grew past 5 GB on it; this budget is a quarter of that.
pub const MAX_PIXELS: u64 = 8192 * 8192;

/// Checks `size` against [`MAX_PIXELS`]. [`AoInputs::validate`] runs it, and callers that
/// allocate images of their own (the scene renderer, the CLI's `--size`) run it before they do.
///
/// ```
/// assert!(aokit::inputs::check_size([7680, 4320]).is_ok());
/// let err = aokit::inputs::check_size([16384, 16384]).unwrap_err();
/// assert!(err.to_string().contains("268435456 pixels"), "{err}");
/// ```
pub fn check_size(size: [u32; 2]) -> Result<(), InputError> {
    let pixels = u64::from(size[0]) * u64::from(size[1]);
    if pixels > MAX_PIXELS {
        return Err(InputError::TooManyPixels { size, pixels });
    }
    Ok(())
}

/// A depth texture or `R32Float` linear depth the passes can bind.
fn check_depth(name: &'static str, texture: AoTexture<'_>) -> Result<(), InputError> {
    let format = texture.format();
    if !(format.has_depth_aspect() || format == wgpu::TextureFormat::R32Float) {
        return Err(InputError::DepthFormat(name, format));
    }
    texture.check(name)
}

fn same_size(
    what: &'static str,
    depth: [u32; 2],
    texture: AoTexture<'_>,
) -> Result<(), InputError> {
    let other = texture.size();
    if depth == other {
        Ok(())
    } else {
        Err(InputError::SizeMismatch { what, depth, other })
    }
}

/// A single-sampled texture the passes can bind.
fn check_readable(name: &'static str, texture: AoTexture<'_>) -> Result<(), InputError> {
    if texture.sample_count() > 1 {
        return Err(InputError::Multisampled(name));
    }
    texture.check(name)
}
