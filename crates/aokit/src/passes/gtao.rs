//! The GTAO kernel: linear depth and normals in, AO out.

use super::{ComputeKernel, PassContext, bind};
use crate::gpu::create_uniform_buffer;
use crate::settings::AoSettings;
use crate::shader;
use crate::uniforms::GtaoUniforms;

/// Format of the AO the kernels write: 1 = unoccluded.
pub const AO_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// Ground-truth based AO with its own settings buffer.
pub struct GtaoPass {
    kernel: ComputeKernel,
    uniforms: wgpu::Buffer,
    point_clamp: wgpu::Sampler,
}

impl GtaoPass {
    /// Compiles the kernel.
    pub fn new(device: &wgpu::Device) -> Self {
        let kernel = ComputeKernel::new(
            device,
            &shader::GTAO,
            &[
                bind::uniform(0),
                bind::uniform(1),
                bind::texture(2, wgpu::TextureSampleType::Float { filterable: false }),
                bind::texture(3, wgpu::TextureSampleType::Uint),
                bind::storage_texture(4, AO_FORMAT),
                bind::sampler(5, wgpu::SamplerBindingType::NonFiltering),
            ],
        );
        // Only gathered, never filtered: clamping repeats edge depths instead of wrapping.
        let point_clamp = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("gtao point clamp"),
            ..Default::default()
        });
        let uniforms = create_uniform_buffer::<GtaoUniforms>(device, "gtao settings");
        Self {
            kernel,
            uniforms,
            point_clamp,
        }
    }

    /// Uploads validated settings; they apply to every later `encode`.
    pub fn set_settings(&self, queue: &wgpu::Queue, settings: &AoSettings) {
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&GtaoUniforms::new(settings)),
        );
    }

    /// Records the kernel.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        linear_depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        ctx.dispatch(
            &self.kernel,
            &[
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(linear_depth),
                wgpu::BindingResource::TextureView(normals),
                wgpu::BindingResource::TextureView(output),
                wgpu::BindingResource::Sampler(&self.point_clamp),
            ],
        );
    }
}
