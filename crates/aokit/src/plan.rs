//! [`FramePlan`]: which passes a frame runs, in order, at which sizes, reading and writing which
//! textures. Computed from the settings and a description of the inputs, without a GPU;
//! [`AoPipeline::encode`](crate::AoPipeline::encode) makes the textures it names and records its
//! steps one by one.

use crate::passes::kernel::depth_mips::{DepthReduction, atlas_format};
use crate::settings::{
    AoSettings, FilterResolution, Method, NormalEncoding, NormalSource, NormalSpace, SpatialKind,
};

/// What the plan needs to know of a frame's inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct FrameInputs {
    /// The depth's size in pixels.
    pub size: [u32; 2],
    /// Whether the renderer hands in normals.
    pub normals: bool,
    /// Whether it hands in motion vectors.
    pub motion_vectors: bool,
    /// Whether it hands in an exclusion mask.
    pub mask: bool,
    /// Whether the projection is orthographic.
    pub orthographic: bool,
    /// Whether the depth has a guard band ([`AoInputs::guard_band`](crate::AoInputs::guard_band)):
    /// the passes after the kernel then read copies of the inner frame of aokit's own linear
    /// depth and normals, so both are made even where the renderer's would do.
    pub guard_band: bool,
}

/// A texture a pass reads or writes: the inputs, and the pipeline's intermediate textures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Target {
    /// The renderer's depth.
    InputDepth,
    /// The renderer's normals.
    InputNormals,
    /// The renderer's motion vectors, in pixels of the input.
    InputMotionVectors,
    /// Linear depth at the input's size.
    LinearDepth,
    /// oct32 view-space normals at the input's size, decoded or reconstructed.
    Normals,
    /// The downsample's linear depth, normals and motion vectors, at working size.
    WorkingLinearDepth,
    WorkingNormals,
    WorkingMotionVectors,
    /// The occluders' thickness from the back faces, at working size.
    BackThickness,
    /// The method's own depth MIP chain of the working depth.
    DepthMips,
    /// The [`AoSettings::depth_mips`] atlas of the working depth.
    DepthMipAtlas,
    /// The kernel's AO and bent normals, at working size.
    Ao,
    BentNormals,
    /// The kernel's AO and the working depth packed in one texel, for the edges kind
    /// ([`SpatialSettings::packed_input`](crate::SpatialSettings::packed_input)).
    AoAndDepth,
    /// The upsample's AO and bent normals, at the input's size.
    UpsampledAo,
    UpsampledBentNormals,
    /// The spatial filter's intermediate AO and depth, and its output.
    SpatialScratch,
    SpatialAo,
    /// The temporal filter's output: this view's history.
    History,
    /// The AO with the exclusion mask applied.
    MaskedAo,
}

/// The resolution a step dispatches over, with that size's view uniforms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum At {
    Input,
    Working,
}

/// The kernel's variant for the whole frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kernel {
    /// A per-pixel method's kernel (`common/ao_entry.wgsl` + the method's `estimate`).
    Method {
        method: Method,
        orthographic: bool,
        /// The working depth, or for `sao` and `ue4-ssao` the MIP chain whose level 0 it is.
        depth: Target,
        bent_normals: bool,
        depth_mip_atlas: bool,
        back_thickness: bool,
        /// Writes [`Target::AoAndDepth`] too.
        ao_and_depth: bool,
    },
    /// MSVO's passes, one per level of the chain, merged.
    Msvo { levels: u32 },
    /// Separable HBAO's row and column passes.
    SeparableHbao { depth: Target },
}

/// One pass of the frame, with what it reads and writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pass {
    /// [`Target::InputDepth`] -> [`Target::LinearDepth`].
    LinearDepth,
    /// [`Target::InputNormals`] -> [`Target::Normals`], turned into view space when `world`;
    /// reads [`Target::LinearDepth`] where a texel holds no usable normal.
    DecodeNormals {
        encoding: NormalEncoding,
        world: bool,
    },
    /// [`Target::LinearDepth`] -> [`Target::Normals`].
    NormalsFromDepth { source: NormalSource },
    /// `depth`, `normals` and (with `motion_vectors`) [`Target::InputMotionVectors`] -> the
    /// `Working*` targets.
    Downsample {
        depth: Target,
        normals: Target,
        motion_vectors: bool,
    },
    /// The renderer's back-face depth and `depth` -> [`Target::BackThickness`], `scale`
    /// input pixels to a texel.
    BackFaces { depth: Target, scale: u32 },
    /// `depth` -> [`Target::DepthMips`].
    DepthMips {
        reduction: DepthReduction,
        depth: Target,
    },
    /// `depth` -> [`Target::DepthMipAtlas`].
    DepthMipAtlas { depth: Target, orthographic: bool },
    /// The working depth and normals (and what [`Kernel`] names) -> [`Target::Ao`] (and
    /// [`Target::BentNormals`]).
    Kernel { kernel: Kernel, normals: Target },
    /// `ao` (and [`Target::BentNormals`]) -> [`Target::UpsampledAo`] (and
    /// [`Target::UpsampledBentNormals`]), guided by `depth` and `normals` at the input's size
    /// and [`Target::WorkingLinearDepth`]; writes [`Target::LinearDepth`] too when no pass
    /// before did.
    Upsample {
        depth: Target,
        normals: Target,
        ao: Target,
        bent_normals: bool,
        write_linear_depth: bool,
    },
    /// `ao`, `depth` (and `normals` for the kinds that read them) -> [`Target::SpatialScratch`]
    /// (not for `edges`) -> [`Target::SpatialAo`]; `packed` writes AO and depth together there
    /// for the temporal filter. With `ao_and_depth` the edges kind reads the two from
    /// [`Target::AoAndDepth`] instead.
    Spatial {
        kind: SpatialKind,
        ao: Target,
        depth: Target,
        normals: Target,
        packed: bool,
        ao_and_depth: bool,
    },
    /// `ao` (and `depth` unless `packed`: then `ao` holds both) and `motion_vectors` ->
    /// [`Target::History`].
    Temporal {
        ao: Target,
        depth: Target,
        motion_vectors: Option<Target>,
        packed: bool,
    },
    /// The renderer's exclusion mask over `ao` -> [`Target::MaskedAo`].
    Mask { ao: Target },
}

/// A pass and the resolution it runs at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Step {
    pub at: At,
    pub pass: Pass,
}

/// Everything one frame runs, in order, and where its results are.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct FramePlan {
    /// The input's size.
    pub size: [u32; 2],
    /// The kernel's size: `size` at full resolution.
    pub working: [u32; 2],
    /// `size / working`, rounded up: 1 at full resolution and for a 1x1 image.
    pub scale: u32,
    /// The passes, in the order they are recorded.
    pub steps: Vec<Step>,
    /// The view-space oct32 normals at the input's size.
    pub normals: Target,
    /// The linear depth and normals the kernel read.
    pub working_depth: Target,
    /// The final AO, at the input's size.
    pub ao: Target,
    /// The bent normals at the input's size, when on.
    pub bent_normals: Option<Target>,
    /// The size the spatial filter's targets are made at, when it runs.
    pub spatial_size: Option<[u32; 2]>,
    /// The format of the depth MIP atlas, when it is made.
    pub depth_mip_atlas: Option<wgpu::TextureFormat>,
}

impl FramePlan {
    /// The plan for a frame of `inputs` under `settings`, which must be valid. VBAO's back
    /// faces are planned when the settings ask for them: the pipeline refuses a frame without
    /// back-face depth before it plans one.
    pub fn new(settings: &AoSettings, inputs: &FrameInputs) -> Self {
        let size = inputs.size;
        let working = settings.resolution.working_size(size);
        // A 1x1 image is its own working image at any resolution: it runs as at full.
        let scale = if working == size {
            1
        } else {
            settings.resolution.scale()
        };
        let below_full = scale > 1;
        let mut steps = Vec::new();
        let mut step = |at, pass| steps.push(Step { at, pass });

        // Input: normals from the buffer when the settings use it, as they are when oct32 in
        // view space, else decoded; else from the linear depth.
        let buffer_normals = inputs.normals && settings.normals.source == NormalSource::Buffer;
        let world = settings.normals.space == NormalSpace::World;
        let encoding = settings.normals.encoding;
        let band = inputs.guard_band;
        let decode = buffer_normals && (encoding != NormalEncoding::Oct32 || world || band);
        // The linear depth pass runs at full resolution, and where normals are reconstructed
        // from its output (the decode falls back to them where a texel holds no normal).
        // Otherwise the downsample and the upsample read the renderer's depth themselves, and
        // the upsample writes the full-resolution linear depth: one pass less.
        let linear_pass = !below_full || !buffer_normals || decode || band;
        let depth = if linear_pass {
            step(At::Input, Pass::LinearDepth);
            Target::LinearDepth
        } else {
            Target::InputDepth
        };
        let normals = if !buffer_normals {
            let source = settings.normals.source;
            step(At::Input, Pass::NormalsFromDepth { source });
            Target::Normals
        } else if decode {
            step(At::Input, Pass::DecodeNormals { encoding, world });
            Target::Normals
        } else {
            Target::InputNormals
        };

        // Resample: the kernel's inputs at working size, with the motion the filters need there.
        // Below full resolution the filters run before the upsample, at working resolution,
        // unless the settings move them after it.
        let filter_full = below_full && settings.filter_resolution == FilterResolution::Full;
        let temporal = settings.temporal.enabled;
        let working_motion = below_full && !filter_full && temporal && inputs.motion_vectors;
        let (working_depth, working_normals) = if below_full {
            let motion_vectors = working_motion;
            step(
                At::Working,
                Pass::Downsample {
                    depth,
                    normals,
                    motion_vectors,
                },
            );
            (Target::WorkingLinearDepth, Target::WorkingNormals)
        } else {
            (Target::LinearDepth, normals)
        };
        if settings.reads_back_faces() {
            step(
                At::Working,
                Pass::BackFaces {
                    depth: working_depth,
                    scale,
                },
            );
        }
        let reduction = DepthReduction::of(settings.method);
        if let Some(reduction) = reduction {
            step(
                At::Working,
                Pass::DepthMips {
                    reduction,
                    depth: working_depth,
                },
            );
        }
        let depth_mip_atlas = atlas_format(settings);
        let orthographic = inputs.orthographic;
        if depth_mip_atlas.is_some() {
            step(
                At::Working,
                Pass::DepthMipAtlas {
                    depth: working_depth,
                    orthographic,
                },
            );
        }

        // Kernel. A per-pixel kernel packs its AO with the depth for an edges kind that
        // filters its output as it is, at its size.
        let spatial = settings.spatial.enabled;
        let packed_input = spatial
            && settings.spatial.kind == SpatialKind::Edges
            && settings.spatial.packed_input
            && !filter_full;
        let kernel = if settings.method == Method::Msvo {
            Kernel::Msvo {
                levels: settings.msvo.levels,
            }
        } else if settings.separable_hbao() {
            Kernel::SeparableHbao {
                depth: working_depth,
            }
        } else {
            Kernel::Method {
                method: settings.method,
                orthographic,
                // A method that reads a depth MIP chain binds it where the others bind the
                // working depth, which is its level 0.
                depth: reduction.map_or(working_depth, |_| Target::DepthMips),
                bent_normals: settings.bent_normals,
                depth_mip_atlas: depth_mip_atlas.is_some(),
                back_thickness: settings.reads_back_faces(),
                ao_and_depth: packed_input,
            }
        };
        let ao_and_depth = matches!(
            kernel,
            Kernel::Method {
                ao_and_depth: true,
                ..
            }
        );
        step(
            At::Working,
            Pass::Kernel {
                kernel,
                normals: working_normals,
            },
        );

        // Filters, before or after the upsample; then the mask.
        let bent_normals = settings.bent_normals;
        let upsample = |ao| Pass::Upsample {
            depth,
            normals,
            ao,
            bent_normals,
            write_linear_depth: !linear_pass,
        };
        let mut ao = Target::Ao;
        let (filter_at, filter_depth, filter_normals, filter_motion) = if filter_full {
            step(At::Input, upsample(ao));
            ao = Target::UpsampledAo;
            (
                At::Input,
                Target::LinearDepth,
                normals,
                Target::InputMotionVectors,
            )
        } else {
            let motion = match below_full {
                true => Target::WorkingMotionVectors,
                false => Target::InputMotionVectors,
            };
            (At::Working, working_depth, working_normals, motion)
        };
        let packed = spatial && settings.spatial.kind == SpatialKind::Bilateral && temporal;
        if spatial {
            step(
                filter_at,
                Pass::Spatial {
                    kind: settings.spatial.kind,
                    ao,
                    depth: filter_depth,
                    normals: filter_normals,
                    packed,
                    ao_and_depth,
                },
            );
            ao = Target::SpatialAo;
        }
        if temporal {
            let motion_vectors = match filter_motion {
                Target::WorkingMotionVectors => working_motion,
                _ => inputs.motion_vectors,
            };
            step(
                filter_at,
                Pass::Temporal {
                    ao,
                    depth: filter_depth,
                    motion_vectors: motion_vectors.then_some(filter_motion),
                    packed,
                },
            );
            ao = Target::History;
        }
        if below_full && !filter_full {
            step(At::Input, upsample(ao));
            ao = Target::UpsampledAo;
        }
        if inputs.mask {
            step(At::Input, Pass::Mask { ao });
            ao = Target::MaskedAo;
        }
        Self {
            size,
            working,
            scale,
            steps,
            normals,
            working_depth,
            ao,
            bent_normals: bent_normals.then_some(if below_full {
                Target::UpsampledBentNormals
            } else {
                Target::BentNormals
            }),
            spatial_size: spatial.then_some(if filter_full { size } else { working }),
            depth_mip_atlas,
        }
    }

    /// How many steps come before those after the kernel: with a guard band, the steps up to
    /// the kernel run on the whole input and the rest on the inner frame.
    pub fn through_kernel(&self) -> usize {
        let kernel = self
            .steps
            .iter()
            .position(|step| matches!(step.pass, Pass::Kernel { .. }))
            .expect("every plan runs a kernel");
        kernel + 1
    }

    /// Whether a step writes `target`.
    pub fn writes(&self, target: Target) -> bool {
        self.steps
            .iter()
            .any(|step| step.pass.writes().contains(&target))
    }
}

impl Pass {
    /// The intermediate textures this pass writes.
    pub fn writes(&self) -> Vec<Target> {
        use Target::*;
        match *self {
            Pass::LinearDepth => vec![LinearDepth],
            Pass::DecodeNormals { .. } | Pass::NormalsFromDepth { .. } => vec![Normals],
            Pass::Downsample { motion_vectors, .. } => {
                let mut writes = vec![WorkingLinearDepth, WorkingNormals];
                writes.extend(motion_vectors.then_some(WorkingMotionVectors));
                writes
            }
            Pass::BackFaces { .. } => vec![BackThickness],
            Pass::DepthMips { .. } => vec![DepthMips],
            Pass::DepthMipAtlas { .. } => vec![DepthMipAtlas],
            Pass::Kernel { kernel, .. } => match kernel {
                Kernel::Method {
                    bent_normals,
                    ao_and_depth,
                    ..
                } => {
                    let mut writes = vec![Ao];
                    writes.extend(bent_normals.then_some(BentNormals));
                    writes.extend(ao_and_depth.then_some(AoAndDepth));
                    writes
                }
                _ => vec![Ao],
            },
            Pass::Upsample {
                bent_normals,
                write_linear_depth,
                ..
            } => {
                let mut writes = vec![UpsampledAo];
                writes.extend(bent_normals.then_some(UpsampledBentNormals));
                writes.extend(write_linear_depth.then_some(LinearDepth));
                writes
            }
            Pass::Spatial { kind, .. } => match kind {
                SpatialKind::Edges => vec![SpatialAo],
                _ => vec![SpatialScratch, SpatialAo],
            },
            Pass::Temporal { .. } => vec![History],
            Pass::Mask { .. } => vec![MaskedAo],
        }
    }
}

#[cfg(test)]
mod tests;
