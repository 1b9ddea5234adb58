//! The depth MIP chain of the methods that read one: the working linear depth at level 0 and, at
//! each coarser level, a reduction of every 2x2 depths of the level below, so that far taps read
//! nearby texels of a coarse level instead of scattered pixels. `sao` keeps one of the four
//! (McGuire, Mara and Luebke 2012, section 2.2), `ue4-ssao` the furthest (a hierarchical Z
//! buffer, as Unreal's SSAO reads: seed 002).

use std::collections::HashMap;

use super::{ComputeKernel, PassContext, bind};
use crate::gpu::{create_texture_2d_mips, mip_view};
use crate::passes::linear_depth::LINEAR_DEPTH_FORMAT;
use crate::settings::Method;
use crate::shader;

/// How a level of the chain reduces each 2x2 block of the level below (the `REDUCTION_*` codes
/// of `depth_mips.wgsl`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum DepthReduction {
    /// SAO's rotated-grid subsample: the child at offset `(y & 1, x & 1)` of texel `(x, y)`.
    Subsample = 0,
    /// The largest linear depth of the four: the surface furthest from the eye.
    Furthest = 1,
}

impl DepthReduction {
    /// The reduction `method`'s kernel expects, or `None` for a method that reads no chain.
    pub fn of(method: Method) -> Option<Self> {
        match method {
            // MSVO's levels hold real depths too: an average across an edge would occlude.
            Method::Sao | Method::Msvo => Some(Self::Subsample),
            Method::Ue4Ssao => Some(Self::Furthest),
            _ => None,
        }
    }
}

/// Levels of the chain: the working depth and four coarser ones, as far as the kernels' taps
/// reach (`MAX_MIP_LEVEL` in `sao.wgsl` and `ue4_ssao.wgsl`), and as many as one workgroup of
/// `depth_mips.wgsl` reduces from a 16x16 block of level 0.
const LEVELS: u32 = 5;

/// Builds the chain's coarser levels from its level 0, a copy of the working depth, in one
/// dispatch (`depth_mips.wgsl`).
#[derive(Default)]
pub struct DepthMipsPass {
    /// One kernel per reduction and number of coarser levels, compiled the first time it is
    /// used.
    kernels: HashMap<(DepthReduction, u32), ComputeKernel>,
    /// Bound in place of the levels a small chain lacks; never written.
    stand_in: Option<wgpu::TextureView>,
}

impl DepthMipsPass {
    /// The chain's texture for a depth of `size`: [`LINEAR_DEPTH_FORMAT`], up to five levels
    /// (fewer where a side runs out of texels first).
    pub fn create_texture(device: &wgpu::Device, size: [u32; 2]) -> wgpu::Texture {
        let full_chain = 32 - size[0].max(size[1]).leading_zeros();
        create_texture_2d_mips(
            device,
            "aokit depth mips",
            size,
            LEVELS.min(full_chain),
            LINEAR_DEPTH_FORMAT,
            wgpu::TextureUsages::COPY_DST
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::STORAGE_BINDING,
        )
    }

    /// Records the copy of `depth` (the working linear depth, of `chain`'s size) into level 0
    /// of `chain` (made by [`DepthMipsPass::create_texture`]) and the building of its coarser
    /// levels from it by `reduction`.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        reduction: DepthReduction,
        depth: &wgpu::Texture,
        chain: &wgpu::Texture,
    ) {
        ctx.encoder.copy_texture_to_texture(
            depth.as_image_copy(),
            chain.as_image_copy(),
            depth.size(),
        );
        let coarser_levels = chain.mip_level_count() - 1;
        if coarser_levels == 0 {
            return;
        }
        let kernel = self
            .kernels
            .entry((reduction, coarser_levels))
            .or_insert_with(|| {
                ComputeKernel::with_constants(
                    ctx.device,
                    &shader::DEPTH_MIPS,
                    &[
                        bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
                        bind::storage_texture(1, LINEAR_DEPTH_FORMAT),
                        bind::storage_texture(2, LINEAR_DEPTH_FORMAT),
                        bind::storage_texture(3, LINEAR_DEPTH_FORMAT),
                        bind::storage_texture(4, LINEAR_DEPTH_FORMAT),
                    ],
                    &[
                        ("REDUCTION", f64::from(reduction as u32)),
                        ("COARSER_LEVELS", f64::from(coarser_levels)),
                    ],
                )
            });
        let stand_in = self.stand_in.get_or_insert_with(|| {
            create_texture_2d_mips(
                ctx.device,
                "aokit depth mips stand-in",
                [1, 1],
                1,
                LINEAR_DEPTH_FORMAT,
                wgpu::TextureUsages::STORAGE_BINDING,
            )
            .create_view(&Default::default())
        });
        let levels: Vec<wgpu::TextureView> = (0..LEVELS)
            .map(|level| {
                if level < chain.mip_level_count() {
                    mip_view(chain, level)
                } else {
                    stand_in.clone()
                }
            })
            .collect();
        let resources: Vec<wgpu::BindingResource<'_>> = levels
            .iter()
            .map(wgpu::BindingResource::TextureView)
            .collect();
        let level_1 = chain.size().mip_level_size(1, wgpu::TextureDimension::D2);
        let timestamps = ctx
            .timer
            .as_mut()
            .and_then(|timer| timer.pass(kernel.name()));
        kernel.dispatch(
            ctx.device,
            ctx.encoder,
            &resources,
            [level_1.width, level_1.height],
            timestamps,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduction_codes_match_wgsl_and_every_chain_method_has_one() {
        let module = shader::DEPTH_MIPS.validate().unwrap();
        for (name, reduction) in [
            ("REDUCTION_SUBSAMPLE", DepthReduction::Subsample),
            ("REDUCTION_FURTHEST", DepthReduction::Furthest),
        ] {
            assert_eq!(
                shader::u32_constant(&module, name),
                Some(reduction as u32),
                "{name}"
            );
        }
        for method in Method::ALL {
            assert_eq!(
                DepthReduction::of(method).is_some(),
                method.reads_depth_mips(),
                "{method:?}"
            );
        }
    }
}
