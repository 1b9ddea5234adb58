//! The intermediate textures a [`FramePlan`] names, made for its [`Layout`] and kept while the
//! layout stays the same.

use crate::gpu::{PairFormat, create_texture_2d};
use crate::passes::input::back_faces::THICKNESS_FORMAT;
use crate::passes::input::linear_depth::LINEAR_DEPTH_FORMAT;
use crate::passes::input::normals_from_depth::NORMALS_FORMAT;
use crate::passes::kernel::depth_mips::DepthMipsPass;
use crate::passes::kernel::method::{AO_AND_DEPTH_FORMAT, AO_FORMAT, BENT_NORMALS_FORMAT};
use crate::plan::{FramePlan, Pass, Target};

/// A texture and the view the passes bind.
pub(crate) type TextureAndView = (wgpu::Texture, wgpu::TextureView);

/// What the intermediate textures are made for; any change remakes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Layout {
    /// The input's size.
    size: [u32; 2],
    /// The kernel's size: `size` at full resolution.
    working: [u32; 2],
    bent_normals: bool,
    /// Whether the kernel packs its AO with the depth for the edges kind.
    ao_and_depth: bool,
    /// Size of the spatial filter's textures, when it is on.
    spatial: Option<[u32; 2]>,
    /// Whether the spatial filter hands the temporal filter its AO and depth packed in one
    /// texture (the bilateral kind with the temporal filter on).
    spatial_packed: bool,
    /// Whether the downsample writes motion vectors, for a temporal filter at working
    /// resolution.
    working_motion: bool,
    /// Whether an exclusion mask is applied.
    mask: bool,
    /// Whether the method reads a depth MIP chain.
    depth_mips: bool,
    /// The format of the [`AoSettings::depth_mips`](crate::AoSettings::depth_mips) atlas, when
    /// the kernel reads one.
    depth_mip_atlas: Option<wgpu::TextureFormat>,
    /// Whether VBAO measures its occluders from the back faces.
    back_faces: bool,
}

impl Layout {
    /// The textures `plan` writes.
    pub fn of(plan: &FramePlan) -> Self {
        Self {
            size: plan.size,
            working: plan.working,
            bent_normals: plan.bent_normals.is_some(),
            ao_and_depth: plan.writes(Target::AoAndDepth),
            spatial: plan.spatial_size,
            spatial_packed: plan
                .steps
                .iter()
                .any(|step| matches!(step.pass, Pass::Spatial { packed: true, .. })),
            working_motion: plan.writes(Target::WorkingMotionVectors),
            mask: plan.writes(Target::MaskedAo),
            depth_mips: plan.writes(Target::DepthMips),
            depth_mip_atlas: plan.depth_mip_atlas,
            back_faces: plan.writes(Target::BackThickness),
        }
    }
}

impl Layout {
    /// With a guard band, the textures of the steps through the kernel, which run on the whole
    /// input: none of the filters' or the mask's.
    pub fn through_kernel(self) -> Self {
        Self {
            spatial: None,
            spatial_packed: false,
            mask: false,
            ..self
        }
    }

    /// With a guard band, the textures of the steps after the kernel, which run on the inner
    /// frame: none of the kernel's depth chains or back-face thickness.
    pub fn after_kernel(self) -> Self {
        Self {
            depth_mips: false,
            depth_mip_atlas: None,
            back_faces: false,
            ..self
        }
    }
}

/// The intermediate textures.
pub(crate) struct Targets {
    pub layout: Layout,
    /// Linear depth at the input's size.
    pub linear_depth: TextureAndView,
    /// oct32 normals decoded from the input or reconstructed from depth, at the input's size.
    pub normals: TextureAndView,
    /// Below full resolution, the kernel's inputs at working size and the upsampled outputs.
    working: Option<WorkingTargets>,
    /// The kernel's AO, at working size.
    pub ao: TextureAndView,
    /// The kernel's bent normals, at working size.
    bent_normals: Option<TextureAndView>,
    /// The kernel's AO and depth packed, at working size.
    ao_and_depth: Option<TextureAndView>,
    /// The spatial filter's textures, when it is on.
    spatial: Option<SpatialTargets>,
    /// The AO with the exclusion mask applied, at the input's size.
    masked_ao: Option<TextureAndView>,
    /// The working depth's MIP chain, for a method that reads one; its view shows every level.
    depth_mips: Option<TextureAndView>,
    /// The [`AoSettings::depth_mips`](crate::AoSettings::depth_mips) chain, for a kernel that
    /// reads far samples from it.
    depth_mip_atlas: Option<TextureAndView>,
    /// The occluders' thickness from the back faces, at working size.
    back_thickness: Option<TextureAndView>,
}

/// The downsample's and the upsample's textures.
struct WorkingTargets {
    linear_depth: TextureAndView,
    normals: TextureAndView,
    motion_vectors: Option<TextureAndView>,
    /// The AO at the input's size.
    upsampled_ao: TextureAndView,
    /// The bent normals at the input's size.
    upsampled_bent_normals: Option<TextureAndView>,
}

/// The spatial filter's AO and depth after the bilateral kind's horizontal pass (or the guided
/// kind's window lines, in the same format), and its filtered AO: `R32Float`, or with
/// `Layout::spatial_packed` the AO and depth in the pair format.
struct SpatialTargets {
    scratch: TextureAndView,
    ao: TextureAndView,
}

impl Targets {
    pub fn new(device: &wgpu::Device, layout: Layout, pair: PairFormat) -> Self {
        // COPY_DST: with a guard band the inner frame's targets are copies cut from the
        // input's.
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST;
        let make = |label, size, format| {
            let texture = create_texture_2d(device, label, size, format, usage);
            let view = texture.create_view(&Default::default());
            (texture, view)
        };
        let with_view = |texture: wgpu::Texture| {
            let view = texture.create_view(&Default::default());
            (texture, view)
        };
        let Layout { size, working, .. } = layout;
        let bent = layout.bent_normals;
        Self {
            layout,
            linear_depth: make("aokit linear depth", size, LINEAR_DEPTH_FORMAT),
            normals: make("aokit normals", size, NORMALS_FORMAT),
            working: (working != size).then(|| WorkingTargets {
                linear_depth: make("aokit working linear depth", working, LINEAR_DEPTH_FORMAT),
                normals: make("aokit working normals", working, NORMALS_FORMAT),
                motion_vectors: layout
                    .working_motion
                    .then(|| make("aokit working motion", working, pair.texture_format())),
                upsampled_ao: make("aokit upsampled ao", size, AO_FORMAT),
                upsampled_bent_normals: bent
                    .then(|| make("aokit upsampled bent normals", size, BENT_NORMALS_FORMAT)),
            }),
            ao: make("aokit ao", working, AO_FORMAT),
            bent_normals: bent.then(|| make("aokit bent normals", working, BENT_NORMALS_FORMAT)),
            ao_and_depth: layout
                .ao_and_depth
                .then(|| make("aokit ao and depth", working, AO_AND_DEPTH_FORMAT)),
            spatial: layout.spatial.map(|size| SpatialTargets {
                scratch: make(
                    "aokit spatial filter ao and depth",
                    size,
                    pair.texture_format(),
                ),
                ao: if layout.spatial_packed {
                    make(
                        "aokit spatially filtered ao and depth",
                        size,
                        pair.texture_format(),
                    )
                } else {
                    make("aokit spatially filtered ao", size, AO_FORMAT)
                },
            }),
            masked_ao: layout
                .mask
                .then(|| make("aokit masked ao", size, AO_FORMAT)),
            depth_mips: layout
                .depth_mips
                .then(|| with_view(DepthMipsPass::create_texture(device, working))),
            depth_mip_atlas: layout
                .depth_mip_atlas
                .map(|format| with_view(DepthMipsPass::create_atlas(device, working, format))),
            back_thickness: layout
                .back_faces
                .then(|| make("aokit back-face thickness", working, THICKNESS_FORMAT)),
        }
    }

    /// The texture made for `target`; `None` for the inputs and the temporal history, which
    /// are not made here, and for a target this layout does not have.
    pub fn get(&self, target: Target) -> Option<&TextureAndView> {
        let working = self.working.as_ref();
        let spatial = self.spatial.as_ref();
        match target {
            Target::InputDepth
            | Target::InputNormals
            | Target::InputMotionVectors
            | Target::History => None,
            Target::LinearDepth => Some(&self.linear_depth),
            Target::Normals => Some(&self.normals),
            Target::WorkingLinearDepth => working.map(|w| &w.linear_depth),
            Target::WorkingNormals => working.map(|w| &w.normals),
            Target::WorkingMotionVectors => working.and_then(|w| w.motion_vectors.as_ref()),
            Target::BackThickness => self.back_thickness.as_ref(),
            Target::DepthMips => self.depth_mips.as_ref(),
            Target::DepthMipAtlas => self.depth_mip_atlas.as_ref(),
            Target::Ao => Some(&self.ao),
            Target::BentNormals => self.bent_normals.as_ref(),
            Target::AoAndDepth => self.ao_and_depth.as_ref(),
            Target::UpsampledAo => working.map(|w| &w.upsampled_ao),
            Target::UpsampledBentNormals => working.and_then(|w| w.upsampled_bent_normals.as_ref()),
            Target::SpatialScratch => spatial.map(|s| &s.scratch),
            Target::SpatialAo => spatial.map(|s| &s.ao),
            Target::MaskedAo => self.masked_ao.as_ref(),
        }
    }
}
