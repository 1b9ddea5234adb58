//! Prepare pass for [`VbaoSettings::back_faces`](crate::VbaoSettings::back_faces): each
//! working texel's occluder thickness, from the renderer's back-face depth.

use std::collections::HashMap;

use crate::input_texture::AoTexture;
use crate::passes::input::linear_depth::DepthInput;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Format of the thickness VBAO reads: view-depth units; `MAX_DEPTH` (3.4e38, common/view.wgsl)
/// for a solid, 0 for nothing measured.
pub const THICKNESS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The bindings of `shader::BACK_FACES[input as usize]`: view uniforms, the back-face depth,
/// the working depth, the thickness written.
pub(crate) fn layout(input: DepthInput) -> [wgpu::BindGroupLayoutEntry; 4] {
    [
        bind::uniform(0),
        input.layout_entry(1),
        bind::texture(2, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(3, THICKNESS_FORMAT),
    ]
}

/// Measures how far behind each working texel's surface the nearest back face lies
/// (`shaders/input/back_faces.wgsl`).
#[derive(Default)]
pub struct BackFacesPass {
    /// By kind of back-face depth and resolution scale, compiled the first time they come in.
    kernels: HashMap<(DepthInput, u32), ComputeKernel>,
}

impl BackFacesPass {
    /// Records the pass over `ctx.size`, the working resolution, `scale` input pixels per
    /// working texel: `back_depth` as the renderer drew it, `working_depth` the linear depth
    /// the kernel reads, into `thickness` ([`THICKNESS_FORMAT`]).
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        scale: u32,
        back_depth: &AoTexture<'_>,
        working_depth: &wgpu::TextureView,
        thickness: &wgpu::TextureView,
    ) {
        let input = DepthInput::of(back_depth);
        let device = ctx.device;
        let kernel = self.kernels.entry((input, scale)).or_insert_with(|| {
            ComputeKernel::with_constants(
                device,
                &shader::BACK_FACES[input as usize],
                &layout(input),
                &[("SCALE", f64::from(scale))],
            )
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(&DepthInput::view(back_depth)),
                wgpu::BindingResource::TextureView(working_depth),
                wgpu::BindingResource::TextureView(thickness),
            ],
        );
    }
}
