//! Normals reconstructed from linear depth, for inputs without a normal buffer.

use super::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Format of reconstructed normals: oct32, as a G-buffer would hold them.
pub const NORMALS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

/// Writes oct32 view-space normals from linear depth.
pub struct NormalsFromDepthPass {
    kernel: ComputeKernel,
}

impl NormalsFromDepthPass {
    /// Compiles the pass.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            kernel: ComputeKernel::new(
                device,
                &shader::NORMALS_FROM_DEPTH,
                &[
                    bind::uniform(0),
                    bind::texture(1, wgpu::TextureSampleType::Float { filterable: false }),
                    bind::storage_texture(2, NORMALS_FORMAT),
                ],
            ),
        }
    }

    /// Records the pass.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        linear_depth: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        ctx.dispatch(
            &self.kernel,
            &[
                wgpu::BindingResource::TextureView(linear_depth),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
