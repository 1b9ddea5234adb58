//! Prepare pass: the renderer's depth to linear view depth, 0 where there is no surface.

use super::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Format of the linear depth the AO kernels read.
pub const LINEAR_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// Converts hardware depth (any depth format) or linear depth (`R32Float`) to the linear depth
/// the kernels read.
pub struct LinearDepthPass {
    from_hardware: ComputeKernel,
    from_linear: ComputeKernel,
}

impl LinearDepthPass {
    /// Compiles both variants.
    pub fn new(device: &wgpu::Device) -> Self {
        let kernel = |source, input| {
            ComputeKernel::new(
                device,
                source,
                &[
                    bind::uniform(0),
                    bind::texture(1, input),
                    bind::storage_texture(2, LINEAR_DEPTH_FORMAT),
                ],
            )
        };
        Self {
            from_hardware: kernel(&shader::LINEAR_DEPTH, wgpu::TextureSampleType::Depth),
            from_linear: kernel(
                &shader::IMPORT_DEPTH,
                wgpu::TextureSampleType::Float { filterable: false },
            ),
        }
    }

    /// Records the pass for `depth`, a depth texture or an `R32Float` linear-depth texture.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        depth: &wgpu::Texture,
        output: &wgpu::TextureView,
    ) {
        let (kernel, aspect) = if depth.format().has_depth_aspect() {
            (&self.from_hardware, wgpu::TextureAspect::DepthOnly)
        } else {
            (&self.from_linear, wgpu::TextureAspect::All)
        };
        let input = depth.create_view(&wgpu::TextureViewDescriptor {
            aspect,
            ..Default::default()
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(&input),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
