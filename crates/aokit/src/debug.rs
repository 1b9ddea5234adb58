//! Debug views: a frame's intermediates (depth, normals, depth edges, bent normals, the AO
//! before and after filtering, the rejected history) as an image at the input's size, for
//! looking at what the passes saw.

use crate::error::AoError;
use crate::gpu::{create_texture_2d, create_uniform_buffer, upload_texture_2d};
use crate::passes::{ComputeKernel, bind};
use crate::pipeline::AoOutputs;
use crate::settings::named_enum;
use crate::shader;
use crate::uniforms::DebugUniforms;

/// Format of the debug image.
pub const DEBUG_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

named_enum! {
    /// What a debug view shows. Pixels without a surface are black, except in the AO views.
    ///
    /// ```
    /// use aokit::debug::DebugView;
    /// // A viewer's `--debug-view` flag, and a key that steps to the next view.
    /// let view: DebugView = "bent-normals".parse()?;
    /// let next = |v: DebugView| {
    ///     let i = DebugView::ALL.iter().position(|&w| w == v).unwrap();
    ///     DebugView::ALL[(i + 1) % DebugView::ALL.len()]
    /// };
    /// assert_eq!(next(view), DebugView::RawAo);
    /// assert_eq!(next(DebugView::Rejected).name(), "depth");
    /// # Ok::<(), String>(())
    /// ```
    pub enum DebugView ("debug view") {
        /// Linear depth, near white to far black on a log scale ([`DebugStyle::depth_range`]).
        #[default]
        Depth = "depth",
        /// The linear depth the kernel read: below full resolution the downsample's, one
        /// texel per block of pixels (the coarser level of the depth pyramid the pipeline
        /// builds); at full resolution the same as `depth`.
        WorkingDepth = "working-depth",
        /// The view-space normals the kernel read, `n * 0.5 + 0.5` as RGB.
        Normals = "normals",
        /// Depth discontinuities in red over the dimmed depth: how far each pixel's depth
        /// departs from the plane through its neighbours, relative to itself, full red from
        /// [`DebugStyle::edge_threshold`] on. Planes show none at any angle; silhouettes,
        /// creases and thin objects do: where the filters and the upsample must not blur.
        Edges = "edges",
        /// The bent normals, `b * 0.5 + 0.5` as RGB; needs [`AoSettings::bent_normals`].
        ///
        /// [`AoSettings::bent_normals`]: crate::AoSettings::bent_normals
        BentNormals = "bent-normals",
        /// The kernel's AO before any filter or upsample, at the working size.
        RawAo = "raw-ao",
        /// The AO the pipeline returns.
        Ao = "ao",
        /// White where the temporal filter rejected its history; needs the temporal filter.
        Rejected = "rejected",
    }
}

impl DebugView {
    /// The `VIEW_*` code of `shaders/output/debug_view.wgsl`.
    fn shader_code(self) -> u32 {
        match self {
            DebugView::Depth | DebugView::WorkingDepth => 0,
            DebugView::Normals => 1,
            DebugView::Edges => 2,
            DebugView::BentNormals => 3,
            DebugView::RawAo | DebugView::Ao | DebugView::Rejected => 4,
        }
    }
}

/// How the debug views map values to colours.
///
/// ```
/// use aokit::Projection;
/// use aokit::debug::DebugStyle;
/// // A top-down orthographic camera with the ground at depth 100 and the highest roof at 60:
/// // the greys span those depths instead of the default 0.1 to 1000.
/// let projection = Projection::orthographic(40.0, 1.0, 1.0, 200.0);
/// let style = DebugStyle {
///     depth_range: [60.0, 100.0],
///     orthographic: projection.is_orthographic(),
///     ..DebugStyle::default()
/// };
/// assert!(style.orthographic);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugStyle {
    /// Linear depths shown white and black (near, far); both positive, near below far.
    pub depth_range: [f32; 2],
    /// Relative departure from the neighbours' plane shown fully red by [`DebugView::Edges`].
    pub edge_threshold: f32,
    /// Whether the depth was rendered with an orthographic projection, where depth rather
    /// than its reciprocal is affine across a plane.
    pub orthographic: bool,
}

impl Default for DebugStyle {
    fn default() -> Self {
        Self {
            depth_range: [0.1, 1000.0],
            // The upsample's default threshold: a step it treats as another surface.
            edge_threshold: 0.05,
            orthographic: false,
        }
    }
}

/// The bindings of `shader::DEBUG_VIEW`: its settings, the intermediates it shows, the image
/// written.
pub(crate) fn layout() -> [wgpu::BindGroupLayoutEntry; 6] {
    let unfilterable = wgpu::TextureSampleType::Float { filterable: false };
    [
        bind::uniform(0),
        bind::texture(1, unfilterable),
        bind::texture(2, wgpu::TextureSampleType::Uint),
        bind::texture(3, unfilterable),
        bind::texture(4, unfilterable),
        bind::storage_texture(5, DEBUG_FORMAT),
    ]
}

/// Draws debug views of [`AoPipeline`](crate::AoPipeline) outputs into an `Rgba8Unorm` texture
/// of the input's size, to show on screen or read back.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder,
/// #      outputs: &aokit::AoOutputs<'_>) -> Result<(), aokit::AoError> {
/// use aokit::debug::{AoDebug, DebugStyle, DebugView};
/// let mut debug = AoDebug::new(device, queue);
/// // After `pipeline.encode(...)` returned `outputs`, into the same encoder:
/// let image = debug.encode(device, queue, encoder, outputs, DebugView::Edges, &DebugStyle::default())?;
/// // ... blit `image` to the screen ...
/// # Ok(()) }
/// ```
pub struct AoDebug {
    kernel: ComputeKernel,
    uniforms: wgpu::Buffer,
    /// 1x1 textures bound where a view does not read the binding.
    stand_in_scalar: wgpu::TextureView,
    stand_in_bent: wgpu::TextureView,
    target: Option<(wgpu::Texture, wgpu::TextureView)>,
}

impl AoDebug {
    /// Compiles the debug pass.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), aokit::AoError> {
    /// use aokit::debug::{AoDebug, DebugView};
    /// // Made once next to the pipeline, so that switching views costs no compile.
    /// struct Viewer {
    ///     pipeline: aokit::AoPipeline,
    ///     debug: AoDebug,
    ///     view: Option<DebugView>,
    /// }
    /// let viewer = Viewer {
    ///     pipeline: aokit::AoPipeline::new(device, queue, &aokit::AoSettings::default())?,
    ///     debug: AoDebug::new(device, queue),
    ///     view: None,
    /// };
    /// # Ok(()) }
    /// ```
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Self {
        let stand_in = |format, bytes: &[u8]| {
            upload_texture_2d(device, queue, "aokit debug stand-in", [1, 1], format, bytes)
                .expect("a 1x1 texture")
                .create_view(&Default::default())
        };
        Self {
            kernel: ComputeKernel::new(device, &shader::DEBUG_VIEW, &layout()),
            uniforms: create_uniform_buffer::<DebugUniforms>(device, "aokit debug"),
            stand_in_scalar: stand_in(wgpu::TextureFormat::R32Float, &[0; 4]),
            stand_in_bent: stand_in(wgpu::TextureFormat::Rgba16Float, &[0; 8]),
            target: None,
        }
    }

    /// Records the debug view `view` of `outputs` into `encoder` and returns the image
    /// (`Rgba8Unorm`, the input's size), valid until the next call. Fails, naming the
    /// setting, when the outputs lack what the view shows (bent normals, the temporal
    /// filter's mask), or when `style` is out of range.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline,
    /// #      debug: &mut aokit::debug::AoDebug, inputs: &aokit::AoInputs<'_>)
    /// #      -> Result<(), Box<dyn std::error::Error>> {
    /// use aokit::debug::{DebugStyle, DebugView};
    /// let mut encoder = device.create_command_encoder(&Default::default());
    /// let outputs = pipeline.encode(device, queue, &mut encoder, inputs)?;
    /// // Into the same encoder, while the outputs still hold this frame.
    /// let image = debug.encode(device, queue, &mut encoder, &outputs, DebugView::Normals,
    ///                          &DebugStyle::default())?;
    /// queue.submit([encoder.finish()]);
    /// // RGBA, 4 bytes a pixel, row by row: ready for a PNG encoder.
    /// let rgba = aokit::gpu::read_texture(device, queue, image)?;
    /// assert_eq!(rgba.len(), 4 * (image.width() * image.height()) as usize);
    /// # Ok(()) }
    /// ```
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        outputs: &AoOutputs<'_>,
        view: DebugView,
        style: &DebugStyle,
    ) -> Result<&wgpu::Texture, AoError> {
        let [near, far] = style.depth_range;
        if !(near > 0.0 && far > near && far.is_finite()) {
            return Err(AoError::DebugStyle(format!(
                "depth_range {:?} must be two finite positive depths, near below far",
                style.depth_range
            )));
        }
        if !(style.edge_threshold > 0.0 && style.edge_threshold.is_finite()) {
            return Err(AoError::DebugStyle(format!(
                "edge_threshold {} must be a positive relative depth step",
                style.edge_threshold
            )));
        }
        let unavailable = |needs| AoError::DebugViewUnavailable {
            view: view.name(),
            needs,
        };
        let size = [outputs.linear_depth.width(), outputs.linear_depth.height()];
        let step = |texture: &wgpu::Texture| size[0].div_ceil(texture.width()).max(1);
        let depth = match view {
            DebugView::WorkingDepth => outputs.working_linear_depth,
            _ => outputs.linear_depth,
        };
        let scalar = match view {
            DebugView::RawAo => Some(outputs.raw_ao),
            DebugView::Ao => Some(outputs.ao),
            DebugView::Rejected => Some(
                outputs
                    .history_rejected
                    .ok_or_else(|| unavailable("temporal.enabled = true"))?,
            ),
            _ => None,
        };
        let bent = match view {
            DebugView::BentNormals => Some(
                outputs
                    .bent_normals_view
                    .ok_or_else(|| unavailable("bent_normals = true"))?,
            ),
            _ => None,
        };
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&DebugUniforms {
                view: view.shader_code(),
                edge_threshold: style.edge_threshold,
                log_near: near.log2(),
                inv_log_range: (far / near).log2().recip(),
                depth_step: step(depth),
                scalar_step: scalar.map_or(1, step),
                orthographic: u32::from(style.orthographic),
            }),
        );
        if self.target.as_ref().map(|(t, _)| [t.width(), t.height()]) != Some(size) {
            let texture = create_texture_2d(
                device,
                "aokit debug view",
                size,
                DEBUG_FORMAT,
                wgpu::TextureUsages::STORAGE_BINDING
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC,
            );
            let view = texture.create_view(&Default::default());
            self.target = Some((texture, view));
        }
        let (texture, target) = self.target.as_ref().expect("made above");
        let depth_view = depth.create_view(&Default::default());
        let scalar_view = scalar.map(|t| t.create_view(&Default::default()));
        self.kernel.dispatch(
            device,
            encoder,
            &[
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(&depth_view),
                wgpu::BindingResource::TextureView(outputs.normals_view),
                wgpu::BindingResource::TextureView(
                    scalar_view.as_ref().unwrap_or(&self.stand_in_scalar),
                ),
                wgpu::BindingResource::TextureView(bent.unwrap_or(&self.stand_in_bent)),
                wgpu::BindingResource::TextureView(target),
            ],
            size,
            None,
        );
        Ok(texture)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn view_codes_match_wgsl() {
        let module = shader::DEBUG_VIEW.validate().unwrap();
        for (view, name) in [
            (DebugView::Depth, "VIEW_DEPTH"),
            (DebugView::WorkingDepth, "VIEW_DEPTH"),
            (DebugView::Normals, "VIEW_NORMALS"),
            (DebugView::Edges, "VIEW_EDGES"),
            (DebugView::BentNormals, "VIEW_BENT_NORMALS"),
            (DebugView::RawAo, "VIEW_SCALAR"),
            (DebugView::Ao, "VIEW_SCALAR"),
            (DebugView::Rejected, "VIEW_SCALAR"),
        ] {
            assert_eq!(
                shader::u32_constant(&module, name),
                Some(view.shader_code()),
                "{}",
                view.name()
            );
        }
    }
}
