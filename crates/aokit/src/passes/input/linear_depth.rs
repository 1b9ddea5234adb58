//! Prepare pass: the renderer's depth to linear view depth, 0 where there is no surface; and
//! the kinds of depth input every pass that reads the renderer's depth accepts.

use std::collections::HashMap;

use crate::input_texture::AoTexture;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Format of the linear depth the AO kernels read.
pub const LINEAR_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The kinds of depth texture [`AoInputs::depth`](crate::AoInputs::depth) may be. The passes
/// that read it (the linear depth pass, and below full resolution the downsample and upsample)
/// are compiled once per kind; multisampled depth contributes its sample 0, the depth of one
/// surface, as a resolve that averages would not give at silhouettes. `as usize` indexes
/// [`shader::LINEAR_DEPTH`] and the other programs with one variant per kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthInput {
    /// Hardware depth (any depth format), single-sampled.
    Ndc,
    /// Hardware depth, multisampled.
    NdcMultisampled,
    /// Linear view depth in an `R32Float` texture, single-sampled.
    Linear,
    /// Linear view depth, multisampled.
    LinearMultisampled,
}

impl DepthInput {
    /// The kind of `texture`: hardware depth when its format has a depth aspect, else linear.
    pub fn of(texture: &AoTexture<'_>) -> Self {
        match (
            texture.format().has_depth_aspect(),
            texture.sample_count() > 1,
        ) {
            (true, false) => Self::Ndc,
            (true, true) => Self::NdcMultisampled,
            (false, false) => Self::Linear,
            (false, true) => Self::LinearMultisampled,
        }
    }

    /// Whether the texture has more than one sample per pixel.
    pub fn is_multisampled(self) -> bool {
        matches!(self, Self::NdcMultisampled | Self::LinearMultisampled)
    }

    /// The layout entry of a texture of this kind at `binding`.
    pub fn layout_entry(self, binding: u32) -> wgpu::BindGroupLayoutEntry {
        // Hardware depth too, as `texture_2d<f32>` (`FLOAT_INPUT` in shader.rs).
        bind::texture_with_samples(
            binding,
            wgpu::TextureSampleType::Float { filterable: false },
            self.is_multisampled(),
        )
    }

    /// A view of `texture` the passes can bind: the caller's view, else the depth aspect
    /// alone of a depth-stencil format.
    pub fn view(texture: &AoTexture<'_>) -> wgpu::TextureView {
        texture.bind(if texture.format().has_depth_aspect() {
            wgpu::TextureAspect::DepthOnly
        } else {
            wgpu::TextureAspect::All
        })
    }
}

/// The bindings of `shader::LINEAR_DEPTH[input as usize]`: view uniforms, the depth, the
/// linear depth written.
pub(crate) fn layout(input: DepthInput) -> [wgpu::BindGroupLayoutEntry; 3] {
    [
        bind::uniform(0),
        input.layout_entry(1),
        bind::storage_texture(2, LINEAR_DEPTH_FORMAT),
    ]
}

/// Converts hardware depth or linear depth (`R32Float`, sanitised: NaN, infinity and values
/// <= 0 become 0), single-sampled or multisampled, to the linear depth the kernels read.
#[derive(Default)]
pub struct LinearDepthPass {
    /// One kernel per [`DepthInput`], compiled the first time such a depth comes in.
    kernels: HashMap<DepthInput, ComputeKernel>,
}

impl LinearDepthPass {
    /// Records the pass for `depth`, a depth texture or an `R32Float` linear-depth texture,
    /// single-sampled or multisampled.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        depth: &AoTexture<'_>,
        output: &wgpu::TextureView,
    ) {
        let input = DepthInput::of(depth);
        let device = ctx.device;
        let kernel = self.kernels.entry(input).or_insert_with(|| {
            ComputeKernel::new(
                device,
                &shader::LINEAR_DEPTH[input as usize],
                &layout(input),
            )
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(&DepthInput::view(depth)),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
