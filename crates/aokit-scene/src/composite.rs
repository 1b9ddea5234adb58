//! The lit composite: albedo x (ambient x AO + direct sunlight).

use aokit::Projection;
use aokit::gpu::create_uniform_buffer;
use aokit::passes::{ComputeKernel, bind};
use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec3};

use crate::gbuffer::GBuffer;
use crate::shaders;
use crate::shadow::SunView;

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
            // Sun 70 degrees high: it still reaches the floor of Sponza's narrow atrium, and
            // casts short shadows from +X+Z in the built-in scenes.
            sun_direction: Vec3::new(0.3, 1.0, 0.15).normalize(),
            sun_color: Vec3::new(1.0, 0.94, 0.84) * 0.8,
            // Ambient strong enough that AO reads clearly in shade, where it is all the light.
            ambient_color: Vec3::new(0.62, 0.67, 0.78),
            sky_color: Vec3::new(0.42, 0.55, 0.75),
        }
    }
}

/// Mirrors `CompositeUniforms` in `shaders/composite.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct CompositeUniforms {
    view_from_clip: [[f32; 4]; 4],
    light_clip_from_view: [[f32; 4]; 4],
    sun_direction: [f32; 4],
    sun_color: [f32; 4],
    ambient_color: [f32; 4],
    sky_color: [f32; 4],
    far_ndc_depth: f32,
    shadow_normal_offset: f32,
    _pad: [f32; 2],
}

/// Where and how the frame was seen, for the composite.
pub struct CompositeView<'a> {
    /// The camera's projection.
    pub projection: &'a Projection,
    /// The camera's world-to-view transform.
    pub view_from_world: Mat4,
    /// The sun's shadow view.
    pub sun: &'a SunView,
}

/// Writes the lit image from the G-buffer and the AO.
pub struct CompositePass {
    kernel: ComputeKernel,
    uniforms: wgpu::Buffer,
    shadow_sampler: wgpu::Sampler,
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
                bind::texture(3, wgpu::TextureSampleType::Depth),
                bind::texture(4, float),
                bind::texture(5, wgpu::TextureSampleType::Depth),
                bind::sampler(6, wgpu::SamplerBindingType::Comparison),
                bind::storage_texture(7, LIT_FORMAT),
            ],
        );
        let shadow_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow comparison"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        let uniforms = create_uniform_buffer::<CompositeUniforms>(device, "composite uniforms");
        Self {
            kernel,
            uniforms,
            shadow_sampler,
        }
    }

    /// Records the composite into `output` (a [`LIT_FORMAT`] storage texture).
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        lighting: &Lighting,
        view: &CompositeView<'_>,
        gbuffer: &GBuffer,
        ao: &wgpu::Texture,
        shadow_map: &wgpu::Texture,
        output: &wgpu::Texture,
    ) {
        let sun = view
            .view_from_world
            .transform_vector3(lighting.sun_direction)
            .normalize();
        let uniforms = CompositeUniforms {
            view_from_clip: view
                .projection
                .clip_from_view()
                .inverse()
                .to_cols_array_2d(),
            light_clip_from_view: (view.sun.light_clip_from_world * view.view_from_world.inverse())
                .to_cols_array_2d(),
            sun_direction: sun.extend(0.0).to_array(),
            sun_color: lighting.sun_color.extend(0.0).to_array(),
            ambient_color: lighting.ambient_color.extend(0.0).to_array(),
            sky_color: lighting.sky_color.extend(0.0).to_array(),
            far_ndc_depth: view.projection.far_ndc_depth(),
            // Two texels clear the map's quantisation on slopes up to about 60 degrees.
            shadow_normal_offset: 2.0 * view.sun.texel_size,
            _pad: [0.0; 2],
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let color = |t: &wgpu::Texture| t.create_view(&Default::default());
        let depth_only = |t: &wgpu::Texture| {
            t.create_view(&wgpu::TextureViewDescriptor {
                aspect: wgpu::TextureAspect::DepthOnly,
                ..Default::default()
            })
        };
        let (albedo, normals, depth, ao, shadow, output) = (
            color(&gbuffer.albedo),
            color(&gbuffer.normals),
            depth_only(&gbuffer.depth),
            color(ao),
            depth_only(shadow_map),
            color(output),
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
                wgpu::BindingResource::TextureView(&shadow),
                wgpu::BindingResource::Sampler(&self.shadow_sampler),
                wgpu::BindingResource::TextureView(&output),
            ],
            gbuffer.size,
            None,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(CompositeUniforms {
            view_from_clip,
            light_clip_from_view,
            sun_direction,
            sun_color,
            ambient_color,
            sky_color,
            far_ndc_depth,
            shadow_normal_offset,
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
