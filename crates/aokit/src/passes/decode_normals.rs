//! Normal textures in any encoding but oct32 decoded to the oct32 texture the kernels read, so
//! that the kernels stay one program per method whatever the G-buffer holds.

use std::collections::HashMap;

use super::normals_from_depth::NORMALS_FORMAT;
use super::{ComputeKernel, PassContext, bind};
use crate::settings::NormalEncoding;
use crate::shader;

/// Decodes a normal texture to oct32.
#[derive(Default)]
pub struct DecodeNormalsPass {
    /// One kernel per encoding, compiled the first time it is used.
    kernels: HashMap<NormalEncoding, ComputeKernel>,
}

impl DecodeNormalsPass {
    /// Records the decode of `input`, a texture of `encoding.texture_format()`, into `output`,
    /// an oct32 storage texture ([`NORMALS_FORMAT`]) of `ctx.size`.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        encoding: NormalEncoding,
        input: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        let kernel = self.kernels.entry(encoding).or_insert_with(|| {
            let (source, sample_type) = if encoding.is_uint() {
                (shader::DECODE_NORMALS_UINT, wgpu::TextureSampleType::Uint)
            } else {
                (
                    shader::DECODE_NORMALS_FLOAT,
                    wgpu::TextureSampleType::Float { filterable: false },
                )
            };
            ComputeKernel::with_constants(
                ctx.device,
                &source,
                &[
                    bind::uniform(0),
                    bind::texture(1, sample_type),
                    bind::storage_texture(2, NORMALS_FORMAT),
                ],
                &[("ENCODING", f64::from(encoding.shader_code()))],
            )
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(input),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
