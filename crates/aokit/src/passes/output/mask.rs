//! The exclusion mask: AO 1 on the pixels the caller marked (characters, a first-person
//! weapon), the last pass of the frame.

use std::collections::HashMap;

use crate::inputs::AoMask;
use crate::passes::kernel::method::AO_FORMAT;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Which program a mask needs: its kind, sample count and, for a stencil, the comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Variant {
    multisampled: bool,
    /// `(reference, read_mask)` of a stencil mask; `None` for a mask texture.
    stencil: Option<(u8, u8)>,
}

/// The program for a mask texture or stencil, multisampled or not, and its bindings: view
/// uniforms, the mask, the AO, the masked AO written.
pub(crate) fn program(
    multisampled: bool,
    stencil: bool,
) -> (shader::ShaderSource, [wgpu::BindGroupLayoutEntry; 4]) {
    let (source, sample_type) = match (stencil, multisampled) {
        (false, false) => (
            shader::APPLY_MASK_TEXTURE,
            wgpu::TextureSampleType::Float { filterable: false },
        ),
        (false, true) => (
            shader::APPLY_MASK_TEXTURE_MULTISAMPLED,
            wgpu::TextureSampleType::Float { filterable: false },
        ),
        (true, false) => (shader::APPLY_MASK_STENCIL, wgpu::TextureSampleType::Uint),
        (true, true) => (
            shader::APPLY_MASK_STENCIL_MULTISAMPLED,
            wgpu::TextureSampleType::Uint,
        ),
    };
    let layout = [
        bind::uniform(0),
        bind::texture_with_samples(1, sample_type, multisampled),
        bind::texture(2, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(3, AO_FORMAT),
    ];
    (source, layout)
}

/// Applies an [`AoMask`] to the AO.
#[derive(Default)]
pub struct MaskPass {
    /// One kernel per variant, compiled the first time it is used.
    kernels: HashMap<Variant, ComputeKernel>,
}

impl MaskPass {
    /// Records `output = mix(ao, 1, mask)` at the input's size.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        mask: &AoMask<'_>,
        ao: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        let texture = mask.texture();
        let variant = Variant {
            multisampled: texture.sample_count() > 1,
            stencil: match *mask {
                AoMask::Texture(_) => None,
                AoMask::Stencil {
                    reference,
                    read_mask,
                    ..
                } => Some((reference, read_mask)),
            },
        };
        let kernel = self.kernels.entry(variant).or_insert_with(|| {
            let (source, layout) = program(variant.multisampled, variant.stencil.is_some());
            let constants = match variant.stencil {
                None => vec![],
                Some((reference, read_mask)) => vec![
                    ("STENCIL_REFERENCE", f64::from(reference)),
                    ("STENCIL_READ_MASK", f64::from(read_mask)),
                ],
            };
            ComputeKernel::with_constants(ctx.device, &source, &layout, &constants)
        });
        let mask_view = texture.bind(if variant.stencil.is_some() {
            wgpu::TextureAspect::StencilOnly
        } else {
            wgpu::TextureAspect::All
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(&mask_view),
                wgpu::BindingResource::TextureView(ao),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
