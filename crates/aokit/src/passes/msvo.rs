//! Multi-scale volumetric obscurance (`msvo`): the obscurance of each level of the depth MIP
//! chain (`shaders/msvo_obscurance.wgsl`), then the levels merged from the coarsest up, each
//! level's own obscurance times the depth-aware upsample of the merged level below it
//! (`shaders/msvo_merge.wgsl`). The approach is Microsoft MiniEngine's SSAO as Unity
//! PostProcessing ships it (seed 003); docs/methods.md has the formula and its failures.

use super::method::{MethodPass, layout};
use super::{ComputeKernel, PassContext, bind};
use crate::gpu::{create_texture_2d_mips, mip_view};
use crate::settings::MSVO_MAX_LEVELS;
use crate::shader;

/// Format of the per-level obscurance and merged textures: the AO kernels' own, since
/// `R32Float` is the one single-channel float format every adapter can write as storage.
pub const LEVEL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The timer's names of each level's obscurance dispatch, so that `aokit bench` shows one
/// time per level.
const OBSCURANCE_PASS_NAMES: [&str; MSVO_MAX_LEVELS as usize] = [
    "msvo_obscurance_0",
    "msvo_obscurance_1",
    "msvo_obscurance_2",
    "msvo_obscurance_3",
    "msvo_obscurance_4",
];
/// The timer's names of each merge, by the level it writes.
const MERGE_PASS_NAMES: [&str; MSVO_MAX_LEVELS as usize - 1] = [
    "msvo_merge_0",
    "msvo_merge_1",
    "msvo_merge_2",
    "msvo_merge_3",
];

/// The two kernels and their intermediate textures, which follow the depth chain's size.
pub struct MsvoPass {
    obscurance: ComputeKernel,
    merge: ComputeKernel,
    /// Each level's own obscurance, the chain's size and levels, when there are two or more
    /// (one level alone is written straight into the method's AO); and the merged levels 1
    /// and up, from half the chain's size (level 0's merge writes the method's AO).
    targets: Option<(Option<wgpu::Texture>, Option<wgpu::Texture>)>,
}

impl MsvoPass {
    /// Compiles both kernels: the bindings of every AO kernel, and for the merge the level's
    /// obscurance (binding 9) and the coarser level's merged obscurance (binding 10).
    pub fn new(device: &wgpu::Device) -> Self {
        let level_input = |binding| {
            bind::texture(
                binding,
                wgpu::TextureSampleType::Float { filterable: false },
            )
        };
        Self {
            obscurance: ComputeKernel::new(device, &shader::MSVO_OBSCURANCE, &layout()),
            merge: ComputeKernel::new(
                device,
                &shader::MSVO_MERGE,
                &[&layout()[..], &[level_input(9), level_input(10)]].concat(),
            ),
            targets: None,
        }
    }

    /// Records `levels` obscurance passes over the levels of `chain` (the depth MIP chain,
    /// fewer where it has fewer) and the merges into `ao` (`R32Float`, the chain's level-0
    /// size), with the settings buffer of `method`, which was given the settings that chose
    /// `msvo`.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        method: &MethodPass,
        chain: &wgpu::Texture,
        normals: &wgpu::TextureView,
        ao: &wgpu::TextureView,
        levels: u32,
    ) {
        let levels = levels.min(chain.mip_level_count());
        let size = [chain.width(), chain.height()];
        // A texture of `mips` levels from `size` where `wanted`, and none elsewhere.
        let stale = |texture: &Option<wgpu::Texture>, size: [u32; 2], mips: u32, wanted: bool| {
            match texture {
                Some(t) => {
                    !wanted || [t.width(), t.height()] != size || t.mip_level_count() != mips
                }
                None => wanted,
            }
        };
        if self.targets.as_ref().is_none_or(|(own, merged)| {
            stale(own, size, levels, levels > 1)
                || stale(merged, half(size), levels.saturating_sub(2), levels > 2)
        }) {
            let own = (levels > 1)
                .then(|| level_texture(ctx.device, "aokit msvo obscurance", size, levels));
            let merged = (levels > 2)
                .then(|| level_texture(ctx.device, "aokit msvo merged", half(size), levels - 2));
            self.targets = Some((own, merged));
        }
        let (own, merged) = self.targets.as_ref().expect("made just above");
        let chain_view = chain.create_view(&Default::default());
        // One level alone is the method's AO; otherwise each level's obscurance is kept for
        // its merge.
        let own_levels: Vec<wgpu::TextureView> = own
            .iter()
            .flat_map(|own| (0..levels).map(|l| mip_view(own, l)))
            .collect();
        for level in 0..levels {
            let target = own_levels.get(level as usize).unwrap_or(ao);
            self.dispatch(
                ctx,
                &self.obscurance,
                method,
                &chain_view,
                normals,
                target,
                &[],
                level,
                OBSCURANCE_PASS_NAMES[level as usize],
            );
        }
        // Merged level l (1 <= l <= levels - 2) is mip l - 1 of `merged`; the coarsest level's
        // merged obscurance is its own.
        let merged_levels: Vec<wgpu::TextureView> = merged
            .iter()
            .flat_map(|m| (0..levels - 2).map(|l| mip_view(m, l)))
            .collect();
        for level in (0..levels.saturating_sub(1)).rev() {
            let coarser = if level + 1 == levels - 1 {
                &own_levels[level as usize + 1]
            } else {
                &merged_levels[level as usize]
            };
            let target = if level == 0 {
                ao
            } else {
                &merged_levels[level as usize - 1]
            };
            self.dispatch(
                ctx,
                &self.merge,
                method,
                &chain_view,
                normals,
                target,
                &[
                    wgpu::BindingResource::TextureView(&own_levels[level as usize]),
                    wgpu::BindingResource::TextureView(coarser),
                ],
                level,
                MERGE_PASS_NAMES[level as usize],
            );
        }
    }

    /// Dispatches `kernel` over `level` of the chain, writing `target`, timed as `name`.
    #[allow(clippy::too_many_arguments)]
    fn dispatch(
        &self,
        ctx: &mut PassContext<'_>,
        kernel: &ComputeKernel,
        method: &MethodPass,
        chain: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        target: &wgpu::TextureView,
        extra: &[wgpu::BindingResource<'_>],
        level: u32,
        name: &'static str,
    ) {
        // MSVO has no bent normals: the settings refuse them, and the placeholder is bound.
        let shared = method.bindings(chain, normals, target, None, None);
        let mut resources = vec![ctx.view_uniforms.as_entire_binding()];
        resources.extend_from_slice(&shared);
        resources.extend_from_slice(extra);
        let size = [(ctx.size[0] >> level).max(1), (ctx.size[1] >> level).max(1)];
        let timestamps = ctx.timer.as_mut().and_then(|timer| timer.pass(name));
        kernel.dispatch(ctx.device, ctx.encoder, &resources, size, timestamps);
    }
}

/// Half of `size`, as the next MIP level's: rounded down, at least 1.
fn half(size: [u32; 2]) -> [u32; 2] {
    size.map(|side| (side / 2).max(1))
}

/// A texture of `levels` MIP levels from `size`, written as storage and read as a texture.
fn level_texture(device: &wgpu::Device, label: &str, size: [u32; 2], levels: u32) -> wgpu::Texture {
    let usage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING;
    create_texture_2d_mips(device, label, size, levels, LEVEL_FORMAT, usage)
}
