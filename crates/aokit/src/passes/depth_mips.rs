//! SAO's depth MIP chain: the working linear depth at level 0 and, at each coarser level, one of
//! every 2x2 depths of the level below (McGuire, Mara and Luebke 2012, section 2.2), so that far
//! taps read nearby texels of a coarse level instead of scattered pixels.

use super::{ComputeKernel, PassContext, bind};
use crate::passes::linear_depth::LINEAR_DEPTH_FORMAT;
use crate::shader;

/// Levels of the chain: the working depth and four coarser ones, as far as the kernel's taps
/// reach (`MAX_MIP_LEVEL` in `sao.wgsl`).
const LEVELS: u32 = 5;
/// The timer's name of the dispatch that builds each level past 0, so that `aokit bench` shows
/// one time per level.
const LEVEL_PASS_NAMES: [&str; LEVELS as usize - 1] = [
    "depth_mips_1",
    "depth_mips_2",
    "depth_mips_3",
    "depth_mips_4",
];

/// Builds the chain's coarser levels from its level 0, a copy of the working depth.
pub struct DepthMipsPass {
    kernel: ComputeKernel,
}

impl DepthMipsPass {
    /// Compiles the level kernel.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            kernel: ComputeKernel::new(
                device,
                &shader::DEPTH_MIPS,
                &[
                    bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
                    bind::storage_texture(1, LINEAR_DEPTH_FORMAT),
                ],
            ),
        }
    }

    /// The chain's texture for a depth of `size`: [`LINEAR_DEPTH_FORMAT`], up to five levels
    /// (fewer where a side runs out of texels first).
    pub fn create_texture(device: &wgpu::Device, size: [u32; 2]) -> wgpu::Texture {
        let full_chain = 32 - size[0].max(size[1]).leading_zeros();
        device.create_texture(&wgpu::TextureDescriptor {
            label: Some("aokit depth mips"),
            size: wgpu::Extent3d {
                width: size[0],
                height: size[1],
                depth_or_array_layers: 1,
            },
            mip_level_count: LEVELS.min(full_chain),
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: LINEAR_DEPTH_FORMAT,
            usage: wgpu::TextureUsages::COPY_DST
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::STORAGE_BINDING,
            view_formats: &[],
        })
    }

    /// Records the copy of `depth` (the working linear depth, of `chain`'s size) into level 0
    /// of `chain` (made by [`DepthMipsPass::create_texture`]) and the building of each coarser
    /// level from the one below.
    pub fn encode(&self, ctx: &mut PassContext<'_>, depth: &wgpu::Texture, chain: &wgpu::Texture) {
        ctx.encoder.copy_texture_to_texture(
            depth.as_image_copy(),
            chain.as_image_copy(),
            depth.size(),
        );
        let level_view = |level| {
            chain.create_view(&wgpu::TextureViewDescriptor {
                base_mip_level: level,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        for level in 1..chain.mip_level_count() {
            let size = chain
                .size()
                .mip_level_size(level, wgpu::TextureDimension::D2);
            let (finer, coarser) = (level_view(level - 1), level_view(level));
            let timestamps = ctx
                .timer
                .as_mut()
                .and_then(|timer| timer.pass(LEVEL_PASS_NAMES[level as usize - 1]));
            self.kernel.dispatch(
                ctx.device,
                ctx.encoder,
                &[
                    wgpu::BindingResource::TextureView(&finer),
                    wgpu::BindingResource::TextureView(&coarser),
                ],
                [size.width, size.height],
                timestamps,
            );
        }
    }
}
