//! Depth MIP chains: the working linear depth at level 0 and, at each coarser level, a reduction
//! of every 2x2 depths of the level below, so that far taps read nearby texels of a coarse level
//! instead of scattered pixels. The methods built on a chain read their own, as a texture's MIP
//! levels: `sao` keeps one of the four (McGuire, Mara and Luebke 2012, section 2.2), `ue4-ssao`
//! the furthest (a hierarchical Z buffer, as Unreal's SSAO reads: `GetHZBDepth` in Unreal Engine
//! 4's PostProcessAmbientOcclusion.usf, Epic Games). The marching and point kernels read far
//! samples from the levels of [`AoSettings::depth_mips`], stacked in one texture so that they can
//! gather any level.

use std::collections::HashMap;

use crate::gpu::{create_texture_2d, create_texture_2d_mips, mip_view, stand_in_view};
use crate::passes::input::linear_depth::LINEAR_DEPTH_FORMAT;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{AoSettings, DepthMips, Method};
use crate::shader;

/// How a level of the chain reduces each 2x2 block of the level below (the `REDUCTION_*` codes
/// of `depth_mips.wgsl`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum DepthReduction {
    /// SAO's rotated-grid subsample: the child at offset `(y & 1, x & 1)` of texel `(x, y)`.
    Subsample = 0,
    /// The largest linear depth of the four: the surface furthest from the eye.
    Furthest = 1,
    /// The mean of the four where they lie on one surface (of 1 / depth, or of depth with an
    /// orthographic projection), else the furthest.
    MeanOrFurthest = 2,
}

impl DepthReduction {
    /// The reduction `method`'s kernel expects, or `None` for a method that reads no chain.
    pub fn of(method: Method) -> Option<Self> {
        crate::methods::spec(method).depth_mips
    }
}

/// Levels of a method's own chain: the working depth and four coarser ones, as far as the
/// kernels' taps reach (`MAX_MIP_LEVEL` in `sao.wgsl` and `ue4_ssao.wgsl`), and as many as one
/// workgroup of `depth_mips.wgsl` reduces from a 16x16 block of level 0.
const LEVELS: u32 = 5;

/// The coarser levels of the [`AoSettings::depth_mips`] chain for a working depth of `size`: up
/// to 4, each at least 2 texels on a side, so that a 2x2 gather fits inside it (`mip_levels`
/// in `common/ao.wgsl`).
pub(crate) fn atlas_levels(size: [u32; 2]) -> u32 {
    let shorter = size[0].min(size[1]).max(1);
    (31 - shorter.leading_zeros())
        .saturating_sub(1)
        .min(LEVELS - 1)
}

/// The format of the [`AoSettings::depth_mips`] chain the settings ask the kernel to read,
/// `None` when it reads none: the setting is off, or the method reads a chain of its own or
/// (the separable `hbao`) none.
pub(crate) fn atlas_format(settings: &AoSettings) -> Option<wgpu::TextureFormat> {
    let reads = !settings.method.reads_depth_mips() && !settings.separable_hbao();
    match settings.depth_mips {
        DepthMips::Off => None,
        DepthMips::Fp32 => reads.then_some(LINEAR_DEPTH_FORMAT),
        DepthMips::Fp16 => reads.then_some(wgpu::TextureFormat::R16Float),
    }
}

/// Whether the [`AoSettings::depth_mips`] atlas of `format` holds level 0 too: in `fp32` it is
/// an exact copy of the working depth, and the kernels read every level from the atlas without
/// a branch; `fp16` would round the nearest samples' depths far more than their distance to
/// the shaded point can take, so those read the working depth (`DEPTH_MIPS_*` in
/// `common/ao.wgsl`).
pub(crate) fn atlas_holds_level_0(format: wgpu::TextureFormat) -> bool {
    format == LINEAR_DEPTH_FORMAT
}

/// The program that stores levels of `format` (`R32Float` or `R16Float`) and its bindings:
/// level 0, then levels 1 to 4 written.
pub(crate) fn program(
    format: wgpu::TextureFormat,
) -> (shader::ShaderSource, [wgpu::BindGroupLayoutEntry; 5]) {
    let source = if format == LINEAR_DEPTH_FORMAT {
        shader::DEPTH_MIPS
    } else {
        shader::DEPTH_MIPS_FP16
    };
    let layout = [
        bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(1, format),
        bind::storage_texture(2, format),
        bind::storage_texture(3, format),
        bind::storage_texture(4, format),
    ];
    (source, layout)
}

/// What a compiled `depth_mips.wgsl` is specialised for.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
struct KernelKey {
    reduction: DepthReduction,
    coarser_levels: u32,
    atlas: bool,
    orthographic: bool,
    format: wgpu::TextureFormat,
}

/// Builds a chain's coarser levels from its level 0 in one dispatch (`depth_mips.wgsl`).
#[derive(Default)]
pub struct DepthMipsPass {
    /// One kernel per specialisation, compiled the first time it is used.
    kernels: HashMap<KernelKey, ComputeKernel>,
    /// Bound in place of the levels a chain lacks, by format; never written.
    stand_ins: HashMap<wgpu::TextureFormat, wgpu::TextureView>,
}

impl DepthMipsPass {
    /// A method's own chain for a depth of `size`: [`LINEAR_DEPTH_FORMAT`], up to five levels
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

    /// The [`AoSettings::depth_mips`] chain for a working depth of `size`, in `format`: its
    /// [`atlas_levels`] levels past 0 stacked in one texture, level `k` at row
    /// `H - (H >> (k - 1))` (level 1 at the top), each as wide and high as a MIP level would
    /// be; with [`atlas_holds_level_0`], level 0 at the origin and the coarser levels in a
    /// column to its right. At least 1x1.
    pub fn create_atlas(
        device: &wgpu::Device,
        size: [u32; 2],
        format: wgpu::TextureFormat,
    ) -> wgpu::Texture {
        let levels = atlas_levels(size);
        let column = if levels > 0 { size[0] >> 1 } else { 0 };
        // The last level's row (`atlas_origin` in depth_mips.wgsl) and height.
        let stacked = if levels > 0 {
            size[1] - (size[1] >> (levels - 1)) + (size[1] >> levels)
        } else {
            0
        };
        let [width, height] = if atlas_holds_level_0(format) {
            [size[0] + column, size[1].max(stacked)]
        } else {
            [column, stacked]
        };
        create_texture_2d(
            device,
            "aokit depth mip atlas",
            [width.max(1), height.max(1)],
            format,
            wgpu::TextureUsages::COPY_SRC
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
        let key = KernelKey {
            reduction,
            coarser_levels: chain.mip_level_count() - 1,
            atlas: false,
            orthographic: false,
            format: LINEAR_DEPTH_FORMAT,
        };
        let levels: Vec<Option<wgpu::TextureView>> = (1..LEVELS)
            .map(|level| (level < chain.mip_level_count()).then(|| mip_view(chain, level)))
            .collect();
        self.dispatch(ctx, key, depth, &levels);
    }

    /// Records the building of `atlas` (made by [`DepthMipsPass::create_atlas`] for `depth`'s
    /// size) from `depth`, the working linear depth, seen through a projection that is
    /// `orthographic` or not.
    pub fn encode_atlas(
        &mut self,
        ctx: &mut PassContext<'_>,
        depth: &wgpu::Texture,
        atlas: &wgpu::Texture,
        orthographic: bool,
    ) {
        let key = KernelKey {
            reduction: DepthReduction::MeanOrFurthest,
            coarser_levels: atlas_levels([depth.width(), depth.height()]),
            atlas: true,
            orthographic,
            format: atlas.format(),
        };
        self.dispatch(
            ctx,
            key,
            depth,
            &[Some(atlas.create_view(&Default::default()))],
        );
    }

    /// Dispatches the kernel of `key` over `level_0`, writing `levels` (1 to 4 in order; a
    /// missing one, or the whole atlas first, is bound with stand-ins after it).
    fn dispatch(
        &mut self,
        ctx: &mut PassContext<'_>,
        key: KernelKey,
        level_0: &wgpu::Texture,
        levels: &[Option<wgpu::TextureView>],
    ) {
        let level_0_too = key.atlas && atlas_holds_level_0(key.format);
        if key.coarser_levels == 0 && !level_0_too {
            return;
        }
        let kernel = self.kernels.entry(key).or_insert_with(|| {
            let (source, layout) = program(key.format);
            ComputeKernel::with_constants(
                ctx.device,
                &source,
                &layout,
                &[
                    ("REDUCTION", f64::from(key.reduction as u32)),
                    ("COARSER_LEVELS", f64::from(key.coarser_levels)),
                    ("ATLAS", f64::from(u8::from(key.atlas))),
                    ("ATLAS_LEVEL_0", f64::from(u8::from(level_0_too))),
                    ("ORTHOGRAPHIC", f64::from(u8::from(key.orthographic))),
                ],
            )
        });
        let stand_in = self.stand_ins.entry(key.format).or_insert_with(|| {
            stand_in_view(
                ctx.device,
                "aokit depth mips stand-in",
                key.format,
                wgpu::TextureUsages::STORAGE_BINDING,
            )
        });
        // One thread per 2x2 block of level 0, a last odd row or column included.
        let threads = [level_0.width().div_ceil(2), level_0.height().div_ceil(2)];
        let level_0 = level_0.create_view(&Default::default());
        let resources: Vec<wgpu::BindingResource<'_>> = std::iter::once(&level_0)
            .chain(
                (0..LEVELS as usize - 1)
                    .map(|i| levels.get(i).and_then(Option::as_ref).unwrap_or(&*stand_in)),
            )
            .map(wgpu::BindingResource::TextureView)
            .collect();
        let timestamps = ctx
            .timer
            .as_mut()
            .and_then(|timer| timer.pass(kernel.name()));
        kernel.dispatch(ctx.device, ctx.encoder, &resources, threads, timestamps);
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
            ("REDUCTION_MEAN_OR_FURTHEST", DepthReduction::MeanOrFurthest),
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

    #[test]
    fn the_subsample_sources_walk_down_from_the_coarsest_level() {
        let coarsest = format!("const CHAIN_COARSEST: u32 = {}u;", LEVELS - 1);
        assert!(crate::shader::SUBSAMPLE_CHAIN.contains(&coarsest));
    }

    #[test]
    fn atlas_levels_keep_two_texels_a_side_and_stop_at_four() {
        for (size, levels) in [
            ([1, 1], 0),
            ([3, 100], 0),
            ([4, 4], 1),
            ([37, 23], 3),
            ([64, 64], 4),
            ([1920, 1080], 4),
        ] {
            assert_eq!(atlas_levels(size), levels, "{size:?}");
            if levels > 0 {
                assert!(size.iter().all(|side| side >> levels >= 2), "{size:?}");
            }
        }
    }

    #[test]
    fn only_the_kernels_without_a_chain_of_their_own_read_the_atlas() {
        let mut settings = AoSettings::default();
        for method in Method::ALL {
            settings.method = method;
            settings.depth_mips = DepthMips::Off;
            assert_eq!(atlas_format(&settings), None);
            settings.depth_mips = DepthMips::Fp16;
            let format = atlas_format(&settings);
            assert_eq!(format.is_none(), method.reads_depth_mips(), "{method:?}");
        }
        settings.method = Method::Hbao;
        settings.depth_mips = DepthMips::Fp32;
        assert_eq!(atlas_format(&settings), Some(LINEAR_DEPTH_FORMAT));
        settings.hbao.variant = crate::HbaoVariant::Separable;
        assert_eq!(atlas_format(&settings), None);
    }
}
