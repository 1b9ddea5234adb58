//! An input the pipeline reads: a whole texture, or the caller's view of one mip level or
//! array layer of one.

use crate::inputs::InputError;

/// A texture [`AoInputs`](crate::AoInputs) hands to the pipeline: a whole `wgpu::Texture`
/// (`From<&wgpu::Texture>`, what a plain render target is), or a view the renderer already
/// holds of one mip level or one array layer of one (a G-buffer array, a depth pyramid).
///
/// wgpu tells the parent texture of a view but not the view's size, format or subresource,
/// so [`AoTexture::view`] takes the size and format the view was made with; the pipeline
/// binds that view as it is and checks what it can against the parent: the usage, the size
/// against the parent's mip sizes and the format against the parent's.
///
/// ```no_run
/// # fn f(depth_array: &wgpu::Texture, normals: &wgpu::Texture, projection: aokit::Projection) {
/// use aokit::{AoInputs, AoTexture};
/// // Layer 1 of a two-layer depth array (the right eye of a stereo pair).
/// let right_eye = depth_array.create_view(&wgpu::TextureViewDescriptor {
///     dimension: Some(wgpu::TextureViewDimension::D2),
///     aspect: wgpu::TextureAspect::DepthOnly,
///     base_array_layer: 1,
///     array_layer_count: Some(1),
///     ..Default::default()
/// });
/// let size = [depth_array.width(), depth_array.height()];
/// let inputs = AoInputs {
///     // A whole texture converts as before.
///     normals: Some(normals.into()),
///     ..AoInputs::new(
///         AoTexture::view(&right_eye, size, depth_array.format()),
///         projection,
///     )
/// };
/// # }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct AoTexture<'a> {
    texture: &'a wgpu::Texture,
    /// The caller's view, bound as it is; `None` binds the whole texture.
    view: Option<&'a wgpu::TextureView>,
    size: [u32; 2],
    format: wgpu::TextureFormat,
}

impl<'a> From<&'a wgpu::Texture> for AoTexture<'a> {
    fn from(texture: &'a wgpu::Texture) -> Self {
        Self {
            texture,
            view: None,
            size: [texture.width(), texture.height()],
            format: texture.format(),
        }
    }
}

impl<'a> AoTexture<'a> {
    /// The caller's `view`, `size` pixels in `format`, as it was created. It must show one 2D
    /// subresource (`dimension: Some(D2)`, one mip level, one array layer) and, for a
    /// depth-stencil format, one aspect: `DepthOnly` for depth, `StencilOnly` for an
    /// [`AoMask::Stencil`](crate::AoMask::Stencil). `format` is the parent's format (or its
    /// sRGB twin, or the aspect's own format, such as `Depth24Plus` for the depth of
    /// `Depth24PlusStencil8`).
    ///
    /// ```no_run
    /// # fn f(gbuffer: &wgpu::Texture) {
    /// // Mip 1 of a G-buffer's normals: half its size.
    /// let half = gbuffer.create_view(&wgpu::TextureViewDescriptor {
    ///     base_mip_level: 1,
    ///     mip_level_count: Some(1),
    ///     ..Default::default()
    /// });
    /// let size = [gbuffer.width() / 2, gbuffer.height() / 2];
    /// let normals = aokit::AoTexture::view(&half, size, gbuffer.format());
    /// assert_eq!(normals.size(), size);
    /// # }
    /// ```
    pub fn view(view: &'a wgpu::TextureView, size: [u32; 2], format: wgpu::TextureFormat) -> Self {
        Self {
            texture: view.texture(),
            view: Some(view),
            size,
            format,
        }
    }

    /// The whole texture, or the parent of the view.
    ///
    /// ```no_run
    /// # fn f(view: &wgpu::TextureView, texture: &wgpu::Texture) {
    /// let input = aokit::AoTexture::view(view, [640, 360], wgpu::TextureFormat::R32Float);
    /// // A resize remakes the texture; a view kept from before still points at the old one.
    /// assert!(*input.texture() == *texture, "view of a stale texture");
    /// # }
    /// ```
    pub fn texture(&self) -> &'a wgpu::Texture {
        self.texture
    }

    /// Width and height in pixels.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture) {
    /// let input = aokit::AoTexture::from(depth);
    /// assert_eq!(input.size(), [depth.width(), depth.height()]);
    /// # }
    /// ```
    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    /// The format the pipeline reads.
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture) {
    /// // Hardware depth is linearised with the projection; R32Float is read as linear already.
    /// let hardware = aokit::AoTexture::from(depth).format().has_depth_aspect();
    /// # }
    /// ```
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// Samples per pixel (a view has its parent's).
    ///
    /// ```no_run
    /// # fn f(depth: &wgpu::Texture) {
    /// // Multisampled depth is read at sample 0.
    /// let msaa = aokit::AoTexture::from(depth).sample_count() > 1;
    /// # }
    /// ```
    pub fn sample_count(&self) -> u32 {
        self.texture.sample_count()
    }

    /// The view to bind: the caller's, or a view of the whole texture showing `aspect`.
    pub(crate) fn bind(&self, aspect: wgpu::TextureAspect) -> wgpu::TextureView {
        match self.view {
            Some(view) => view.clone(),
            None => self.texture.create_view(&wgpu::TextureViewDescriptor {
                aspect,
                ..Default::default()
            }),
        }
    }

    /// Checks a view's stated size and format against its parent, and the usage.
    pub(crate) fn check(&self, what: &'static str) -> Result<(), InputError> {
        let texture = self.texture;
        if !texture
            .usage()
            .contains(wgpu::TextureUsages::TEXTURE_BINDING)
        {
            return Err(InputError::NotBindable(what));
        }
        if self.view.is_none() {
            return Ok(());
        }
        let parent = texture.format();
        // A view may add or drop sRGB (the parent's `view_formats`) or show one aspect.
        let same_format = self.format.remove_srgb_suffix() == parent.remove_srgb_suffix()
            || self.format.is_depth_stencil_component(parent);
        if !same_format {
            return Err(InputError::ViewFormat {
                what,
                format: self.format,
                parent,
            });
        }
        let mips = mip_sizes(texture);
        if !mips.contains(&self.size) {
            return Err(InputError::ViewSize {
                what,
                size: self.size,
                mips,
            });
        }
        Ok(())
    }
}

/// The sizes of `texture`'s mip levels, the largest first.
fn mip_sizes(texture: &wgpu::Texture) -> Vec<[u32; 2]> {
    let [width, height] = [texture.width(), texture.height()];
    (0..texture.mip_level_count())
        .map(|level| [(width >> level).max(1), (height >> level).max(1)])
        .collect()
}
