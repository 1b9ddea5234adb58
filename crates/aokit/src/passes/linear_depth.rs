//! Prepare pass: the renderer's depth buffer to linear view depth.

use super::{ComputeKernel, bind};
use crate::shader;

/// Format of the linear depth the AO kernels read.
pub const LINEAR_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// Converts any depth buffer to positive linear view depth, 0 where nothing was drawn.
pub struct LinearDepthPass {
    kernel: ComputeKernel,
}

impl LinearDepthPass {
    /// Compiles the pass.
    pub fn new(device: &wgpu::Device) -> Self {
        let kernel = ComputeKernel::new(
            device,
            &shader::LINEAR_DEPTH,
            &[
                bind::uniform(0),
                bind::texture(1, wgpu::TextureSampleType::Depth),
                bind::storage_texture(2, LINEAR_DEPTH_FORMAT),
            ],
        );
        Self { kernel }
    }

    /// Records the pass. `depth` must be a depth-only view.
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        view_uniforms: &wgpu::Buffer,
        depth: &wgpu::TextureView,
        output: &wgpu::TextureView,
        size: [u32; 2],
    ) {
        self.kernel.dispatch(
            device,
            encoder,
            &[
                view_uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(depth),
                wgpu::BindingResource::TextureView(output),
            ],
            size,
        );
    }
}
