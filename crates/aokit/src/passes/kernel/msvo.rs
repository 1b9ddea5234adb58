//! Multi-scale volumetric obscurance (`msvo`): the obscurance of each level of the depth MIP
//! chain (`shaders/kernel/msvo/msvo_obscurance.wgsl`), then the levels merged from the coarsest up,
//! each level's own obscurance times the depth-aware upsample of the merged level below it
//! (`shaders/kernel/msvo/msvo_merge.wgsl`). The approach is Microsoft MiniEngine's SSAO as Unity
//! PostProcessing ships it (Post-processing Stack v2, Multi-scale Volumetric Obscurance);
//! docs/methods/msvo.md has the formula and its failures.

use crate::gpu::create_texture_2d;
use crate::passes::kernel::method::{MethodPass, layout};
use crate::passes::{ComputeKernel, PassContext, bind};
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

/// The bindings of `shader::MSVO_MERGE`: every AO kernel's, the level's obscurance at 9 and
/// the coarser level's merged obscurance at 10.
pub(crate) fn merge_layout() -> Vec<wgpu::BindGroupLayoutEntry> {
    let level_input = |binding| {
        bind::texture(
            binding,
            wgpu::TextureSampleType::Float { filterable: false },
        )
    };
    [&layout()[..], &[level_input(9), level_input(10)]].concat()
}

/// The two kernels and their intermediate textures, which follow the depth chain's size.
pub struct MsvoPass {
    obscurance: ComputeKernel,
    merge: ComputeKernel,
    /// Made for the chain's size and level count of the last frame.
    targets: Option<LevelTargets>,
}

/// The intermediate textures for one size and level count of the depth chain: a texture per
/// level, not the levels of one texture, since wgpu's GL backend emulates a view of one MIP
/// level with its texture's base level, which two views of one texture bound at once (a
/// level's obscurance and the next one's, in the merge) cannot both have.
struct LevelTargets {
    size: [u32; 2],
    levels: u32,
    /// Each level's own obscurance, when there are two or more levels (one level alone is
    /// written straight into the method's AO).
    own: Vec<wgpu::TextureView>,
    /// The merged levels 1 to `levels - 2`: level 0's merge writes the method's AO, and the
    /// coarsest level's merged obscurance is its own.
    merged: Vec<wgpu::TextureView>,
}

impl LevelTargets {
    fn new(device: &wgpu::Device, size: [u32; 2], levels: u32) -> Self {
        // Levels `range` of a chain of `size`, as MIP levels are sized.
        let textures = |label, range: std::ops::Range<u32>| -> Vec<wgpu::TextureView> {
            let usage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING;
            range
                .map(|level| {
                    let level_size = size.map(|side| (side >> level).max(1));
                    create_texture_2d(device, label, level_size, LEVEL_FORMAT, usage)
                        .create_view(&Default::default())
                })
                .collect()
        };
        Self {
            size,
            levels,
            own: textures(
                "aokit msvo obscurance",
                if levels > 1 { 0..levels } else { 0..0 },
            ),
            merged: textures("aokit msvo merged", 1..levels.saturating_sub(1)),
        }
    }
}

impl MsvoPass {
    /// Compiles both kernels: the bindings of every AO kernel, and for the merge the level's
    /// obscurance (binding 9) and the coarser level's merged obscurance (binding 10).
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            obscurance: ComputeKernel::new(device, &shader::MSVO_OBSCURANCE, &layout()),
            merge: ComputeKernel::new(device, &shader::MSVO_MERGE, &merge_layout()),
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
        if self
            .targets
            .as_ref()
            .is_none_or(|t| t.size != size || t.levels != levels)
        {
            self.targets = Some(LevelTargets::new(ctx.device, size, levels));
        }
        let LevelTargets { own, merged, .. } = self.targets.as_ref().expect("made just above");
        let chain_view = chain.create_view(&Default::default());
        // One level alone is the method's AO; otherwise each level's obscurance is kept for
        // its merge.
        for level in 0..levels {
            let target = own.get(level as usize).unwrap_or(ao);
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
        for level in (0..levels.saturating_sub(1)).rev() {
            let coarser = if level + 1 == levels - 1 {
                &own[level as usize + 1]
            } else {
                &merged[level as usize]
            };
            let target = if level == 0 {
                ao
            } else {
                &merged[level as usize - 1]
            };
            self.dispatch(
                ctx,
                &self.merge,
                method,
                &chain_view,
                normals,
                target,
                &[
                    wgpu::BindingResource::TextureView(&own[level as usize]),
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
