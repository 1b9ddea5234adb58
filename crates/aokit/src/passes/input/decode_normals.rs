//! Normal textures in any encoding but oct32, or in world space, decoded to the oct32
//! view-space texture the kernels read, so that the kernels stay one program per method
//! whatever the G-buffer holds. A texel that holds no usable normal (zero, NaN, infinite, far
//! from unit length) gets the normal reconstructed from depth there instead.

use std::collections::HashMap;

use glam::Mat3;

use crate::gpu::create_uniform_buffer;
use crate::passes::input::normals_from_depth::{BEST_RECONSTRUCTION, NORMALS_FORMAT};
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::NormalEncoding;
use crate::shader;
use crate::uniforms::DecodeUniforms;

/// The program that decodes `encoding` and its bindings: view uniforms, the encoded texture,
/// the oct32 normals written, the decode's settings, the linear depth the fallback reads.
pub(crate) fn program(
    encoding: NormalEncoding,
) -> (shader::ShaderSource, [wgpu::BindGroupLayoutEntry; 5]) {
    let (source, sample_type) = if encoding.is_uint() {
        (shader::DECODE_NORMALS_UINT, wgpu::TextureSampleType::Uint)
    } else {
        (
            shader::DECODE_NORMALS_FLOAT,
            wgpu::TextureSampleType::Float { filterable: false },
        )
    };
    let layout = [
        bind::uniform(0),
        bind::texture(1, sample_type),
        bind::storage_texture(2, NORMALS_FORMAT),
        bind::uniform(3),
        bind::texture(4, wgpu::TextureSampleType::Float { filterable: false }),
    ];
    (source, layout)
}

/// Decodes a normal texture to oct32 in view space.
pub struct DecodeNormalsPass {
    /// One kernel per encoding, compiled the first time it is used.
    kernels: HashMap<NormalEncoding, ComputeKernel>,
    uniforms: wgpu::Buffer,
}

impl DecodeNormalsPass {
    /// Makes the settings buffer; the kernels compile when first used.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            kernels: HashMap::new(),
            uniforms: create_uniform_buffer::<DecodeUniforms>(device, "aokit decode normals"),
        }
    }

    /// Records the decode of `input`, a texture of `encoding.texture_format()` whose vectors
    /// `to_view` turns into view space, into `output`, an oct32 storage texture
    /// ([`NORMALS_FORMAT`]) of `ctx.size`; texels without a usable normal take
    /// [`BEST_RECONSTRUCTION`]'s from `linear_depth` (`R32Float`, 0 where there is no surface).
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        queue: &wgpu::Queue,
        encoding: NormalEncoding,
        to_view: Mat3,
        input: &wgpu::TextureView,
        linear_depth: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&DecodeUniforms::new(to_view)),
        );
        let kernel = self.kernels.entry(encoding).or_insert_with(|| {
            let (source, layout) = program(encoding);
            ComputeKernel::with_constants(
                ctx.device,
                &source,
                &layout,
                &[
                    ("ENCODING", f64::from(encoding.shader_code())),
                    ("SOURCE", f64::from(BEST_RECONSTRUCTION as u32)),
                ],
            )
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(input),
                wgpu::BindingResource::TextureView(output),
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(linear_depth),
            ],
        );
    }
}
