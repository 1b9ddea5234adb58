//! The lit composite: albedo x (ambient x AO + direct sunlight).

use aokit::passes::{ComputeKernel, bind};
use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec3};

use crate::gbuffer::GBuffer;
use crate::shaders;

/// Format of the lit image: sRGB-encoded by the shader (storage textures cannot be sRGB).
pub const LIT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Lighting of the composite, in world space and linear RGB.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// Direction towards the sun.
    pub sun_direction: Vec3,
    /// Sun irradiance.
    pub sun_color: Vec3,
    /// Uniform sky light, the term AO darkens.
    pub ambient_color: Vec3,
    /// Background colour.
    pub sky_color: Vec3,
}

impl Default for Lighting {
    fn default() -> Self {
        Self {
            // Sun high and to the side, so floors are lit and walls in shade keep ambient only.
            sun_direction: Vec3::new(0.45, 1.0, 0.3).normalize(),
            sun_color: Vec3::new(1.0, 0.94, 0.84) * 0.85,
            // Ambient strong enough that AO reads clearly in the lit image.
            ambient_color: Vec3::new(0.55, 0.6, 0.7),
            sky_color: Vec3::new(0.42, 0.55, 0.75),
        }
    }
}

/// Mirrors `CompositeUniforms` in `shaders/composite.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct CompositeUniforms {
    sun_direction: [f32; 4],
    sun_color: [f32; 4],
    ambient_color: [f32; 4],
    sky_color: [f32; 4],
}

/// Writes the lit image from the G-buffer and the AO.
pub struct CompositePass {
    kernel: ComputeKernel,
    uniforms: wgpu::Buffer,
}

impl CompositePass {
    /// Compiles the pass.
    pub fn new(device: &wgpu::Device) -> Self {
        let float = wgpu::TextureSampleType::Float { filterable: false };
        let kernel = ComputeKernel::new(
            device,
            &shaders::COMPOSITE,
            &[
                bind::uniform(0),
                bind::texture(1, float),
                bind::texture(2, wgpu::TextureSampleType::Uint),
                bind::texture(3, float),
                bind::texture(4, float),
                bind::storage_texture(5, LIT_FORMAT),
            ],
        );
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("composite uniforms"),
            size: std::mem::size_of::<CompositeUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self { kernel, uniforms }
    }

    /// Records the composite into `output` (a [`LIT_FORMAT`] storage texture).
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        lighting: &Lighting,
        view_from_world: Mat4,
        gbuffer: &GBuffer,
        linear_depth: &wgpu::Texture,
        ao: &wgpu::Texture,
        output: &wgpu::Texture,
    ) {
        let sun = view_from_world
            .transform_vector3(lighting.sun_direction)
            .normalize();
        let uniforms = CompositeUniforms {
            sun_direction: sun.extend(0.0).to_array(),
            sun_color: lighting.sun_color.extend(0.0).to_array(),
            ambient_color: lighting.ambient_color.extend(0.0).to_array(),
            sky_color: lighting.sky_color.extend(0.0).to_array(),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let view = |t: &wgpu::Texture| t.create_view(&Default::default());
        let (albedo, normals, depth, ao, output) = (
            view(&gbuffer.albedo),
            view(&gbuffer.normals),
            view(linear_depth),
            view(ao),
            view(output),
        );
        self.kernel.dispatch(
            device,
            encoder,
            &[
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(&albedo),
                wgpu::BindingResource::TextureView(&normals),
                wgpu::BindingResource::TextureView(&depth),
                wgpu::BindingResource::TextureView(&ao),
                wgpu::BindingResource::TextureView(&output),
            ],
            gbuffer.size,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(CompositeUniforms {
            sun_direction,
            sun_color,
            ambient_color,
            sky_color,
        });
        aokit::shader::check_layout(
            &shaders::COMPOSITE,
            "CompositeUniforms",
            fields,
            std::mem::size_of::<CompositeUniforms>(),
        )
        .unwrap();
    }
}
