//! The passes of [`AoPipeline`](crate::AoPipeline) and how each records a [`Step`] of the
//! frame's plan, binding the textures the step names.

use std::collections::HashMap;

use crate::gpu::PairFormat;
use crate::inputs::AoInputs;
use crate::passes::PassContext;
use crate::passes::filter::edge_filter::EdgeFilterPass;
use crate::passes::filter::guided_filter::GuidedFilterPass;
use crate::passes::filter::spatial_filter::{SpatialFilterPass, SpatialOutput};
use crate::passes::filter::temporal_filter::{
    FrameMotion, History, TemporalFilterPass, TemporalInput,
};
use crate::passes::input::back_faces::BackFacesPass;
use crate::passes::input::decode_normals::DecodeNormalsPass;
use crate::passes::input::linear_depth::{DepthInput, LinearDepthPass};
use crate::passes::input::normals_from_depth::NormalsFromDepthPass;
use crate::passes::kernel::depth_mips::DepthMipsPass;
use crate::passes::kernel::method::MethodPass;
use crate::passes::kernel::msvo::MsvoPass;
use crate::passes::kernel::separable_hbao::SeparableHbaoPass;
use crate::passes::output::mask::MaskPass;
use crate::passes::resample::{DownsampleTargets, ResampleFrame, ResamplePass};
use crate::plan::{Kernel, Pass, Step, Target};
use crate::settings::{AoSettings, SpatialKind};
use crate::targets::{Targets, TextureAndView};

/// The textures of one frame by the plan's names: the inputs' views and the made targets.
pub(crate) struct Views<'v> {
    pub targets: &'v Targets,
    pub input_depth: &'v wgpu::TextureView,
    pub input_normals: Option<&'v wgpu::TextureView>,
    pub motion_vectors: Option<&'v wgpu::TextureView>,
    /// The temporal filter's output, once it ran this frame.
    pub history: Option<TextureAndView>,
}

impl Views<'_> {
    fn view(&self, target: Target) -> &wgpu::TextureView {
        match target {
            Target::InputDepth => self.input_depth,
            Target::InputNormals => self.input_normals.expect("planned with input normals"),
            Target::InputMotionVectors => self.motion_vectors.expect("planned with motion"),
            Target::History => &self.history.as_ref().expect("the temporal filter ran").1,
            made => &self.made(made).1,
        }
    }

    fn texture(&self, target: Target) -> &wgpu::Texture {
        &self.made(target).0
    }

    fn made(&self, target: Target) -> &TextureAndView {
        self.targets
            .get(target)
            .unwrap_or_else(|| panic!("the layout of the plan makes {target:?}"))
    }
}

/// Every pass the pipeline may run; the ones few settings use compile on first use.
pub(crate) struct Passes {
    pub linear_depth: LinearDepthPass,
    pub decode_normals: DecodeNormalsPass,
    pub normals_from_depth: NormalsFromDepthPass,
    /// Compiled the first time the resolution is below full.
    pub resample: Option<ResamplePass>,
    pub back_faces: BackFacesPass,
    /// Made the first time a method reads a depth MIP chain; each reduction's kernel compiles
    /// on first use.
    pub depth_mips: Option<DepthMipsPass>,
    pub method: MethodPass,
    /// Runs instead of `method`'s kernel for `hbao.variant = separable`.
    pub separable_hbao: Option<SeparableHbaoPass>,
    /// Runs instead of a single kernel for `msvo`.
    pub msvo: Option<MsvoPass>,
    pub spatial: SpatialFilterPass,
    pub guided: GuidedFilterPass,
    pub edges: EdgeFilterPass,
    /// Compiled the first time the temporal filter is on.
    pub temporal: Option<TemporalFilterPass>,
    /// Each view's temporal history, by [`AoInputs::view_id`].
    pub histories: HashMap<u32, Option<History>>,
    pub mask: MaskPass,
    /// How this device stores the two-channel targets.
    pub pair: PairFormat,
}

impl Passes {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: &AoSettings) -> Self {
        let pair = PairFormat::of(device);
        Self {
            linear_depth: LinearDepthPass::default(),
            decode_normals: DecodeNormalsPass::new(device),
            normals_from_depth: NormalsFromDepthPass::new(device),
            resample: None,
            back_faces: BackFacesPass::default(),
            depth_mips: None,
            method: MethodPass::new(device, queue, settings),
            separable_hbao: None,
            msvo: None,
            spatial: SpatialFilterPass::new(device, queue, &settings.spatial, pair),
            guided: GuidedFilterPass::new(device, queue, &settings.spatial, pair),
            edges: EdgeFilterPass::new(device, queue, &settings.spatial),
            temporal: None,
            histories: HashMap::new(),
            mask: MaskPass::default(),
            pair,
        }
    }

    /// Passes the settings' uniforms to the passes that keep them.
    pub fn set_settings(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, s: &AoSettings) {
        self.method.set_settings(device, queue, s);
        self.spatial.set_settings(device, queue, &s.spatial);
        self.guided.set_settings(device, queue, &s.spatial);
        self.edges.set_settings(device, queue, &s.spatial);
        if let Some(temporal) = &mut self.temporal {
            temporal.set_settings(&s.temporal);
        }
    }

    /// Records `step` at `ctx`'s resolution.
    pub fn record(
        &mut self,
        ctx: &mut PassContext<'_>,
        queue: &wgpu::Queue,
        settings: &AoSettings,
        frame: &AoInputs<'_>,
        step: &Step,
        views: &Views<'_>,
    ) {
        let device = ctx.device;
        let view = |target| views.view(target);
        match step.pass {
            Pass::LinearDepth => {
                let output = view(Target::LinearDepth);
                self.linear_depth.encode(ctx, &frame.depth, output);
            }
            Pass::DecodeNormals { encoding, world } => {
                let to_view = if world {
                    glam::Mat3::from_mat4(frame.view_from_world)
                } else {
                    glam::Mat3::IDENTITY
                };
                let (input, output) = (view(Target::InputNormals), view(Target::Normals));
                let depth = view(Target::LinearDepth);
                self.decode_normals
                    .encode(ctx, queue, encoding, to_view, input, depth, output);
            }
            Pass::NormalsFromDepth { source } => {
                let (depth, output) = (view(Target::LinearDepth), view(Target::Normals));
                self.normals_from_depth.encode(ctx, source, depth, output);
            }
            Pass::Downsample {
                depth,
                normals,
                motion_vectors,
            } => {
                let pass = self
                    .resample
                    .get_or_insert_with(|| ResamplePass::new(device, self.pair));
                // Both kernels are chosen here; the upsample writes the linear depth exactly
                // when no pass before it did.
                pass.prepare(
                    device,
                    queue,
                    settings,
                    ResampleFrame {
                        input: match depth {
                            Target::InputDepth => DepthInput::of(&frame.depth),
                            _ => DepthInput::Linear,
                        },
                        motion_vectors,
                        bent_normals: settings.bent_normals,
                        write_linear_depth: depth == Target::InputDepth,
                    },
                );
                pass.downsample(
                    ctx,
                    view(depth),
                    view(normals),
                    motion_vectors.then(|| view(Target::InputMotionVectors)),
                    &DownsampleTargets {
                        linear_depth: view(Target::WorkingLinearDepth),
                        normals: view(Target::WorkingNormals),
                        motion_vectors: motion_vectors.then(|| view(Target::WorkingMotionVectors)),
                    },
                );
            }
            Pass::BackFaces { depth, scale } => {
                let back_depth = frame.back_depth.expect("checked before planning");
                let output = view(Target::BackThickness);
                self.back_faces
                    .encode(ctx, scale, &back_depth, view(depth), output);
            }
            Pass::DepthMips { reduction, depth } => {
                let chain = views.texture(Target::DepthMips);
                self.depth_mips
                    .get_or_insert_with(DepthMipsPass::default)
                    .encode(ctx, reduction, views.texture(depth), chain);
            }
            Pass::DepthMipAtlas {
                depth,
                orthographic,
            } => {
                let atlas = views.texture(Target::DepthMipAtlas);
                self.depth_mips
                    .get_or_insert_with(DepthMipsPass::default)
                    .encode_atlas(ctx, views.texture(depth), atlas, orthographic);
            }
            Pass::Kernel { kernel, normals } => self.kernel(ctx, kernel, view(normals), views),
            Pass::Upsample {
                depth,
                normals,
                ao,
                bent_normals,
                write_linear_depth,
            } => {
                let pass = self.resample.as_ref().expect("the downsample ran first");
                pass.upsample(
                    ctx,
                    view(depth),
                    view(normals),
                    view(Target::WorkingLinearDepth),
                    view(ao),
                    view(Target::UpsampledAo),
                    bent_normals.then(|| {
                        let from = view(Target::BentNormals);
                        (from, view(Target::UpsampledBentNormals))
                    }),
                    write_linear_depth.then(|| view(Target::LinearDepth)),
                );
            }
            Pass::Spatial {
                kind,
                ao,
                depth,
                normals,
                packed,
                ao_and_depth,
            } => {
                let (ao, depth, normals) = (view(ao), view(depth), view(normals));
                let ao_and_depth = ao_and_depth.then(|| view(Target::AoAndDepth));
                let (scratch, output) = (view(Target::SpatialScratch), view(Target::SpatialAo));
                match kind {
                    SpatialKind::Bilateral => {
                        let output = match packed {
                            true => SpatialOutput::AoAndDepth(output),
                            false => SpatialOutput::Ao(output),
                        };
                        self.spatial
                            .encode(ctx, ao, depth, normals, scratch, output);
                    }
                    SpatialKind::Guided => self.guided.encode(ctx, ao, depth, scratch, output),
                    SpatialKind::Edges => {
                        self.edges
                            .encode(ctx, ao, depth, normals, ao_and_depth, output);
                    }
                }
            }
            Pass::Temporal {
                ao,
                depth,
                motion_vectors,
                packed,
            } => {
                let history = self.histories.entry(frame.view_id).or_insert(None);
                let temporal = self.temporal.get_or_insert_with(|| {
                    TemporalFilterPass::new(device, &settings.temporal, self.pair)
                });
                let input = match packed {
                    true => TemporalInput::Packed(view(ao)),
                    false => TemporalInput::Separate {
                        ao: view(ao),
                        linear_depth: view(depth),
                    },
                };
                let motion = FrameMotion {
                    view_from_world: frame.view_from_world,
                    projection: frame.projection,
                    // The input's motion vectors cover the guard band too; the working
                    // ones were cut to the frame.
                    motion_vectors: motion_vectors.map(|target| {
                        let offset = match target {
                            Target::InputMotionVectors => frame.guard_band,
                            _ => 0,
                        };
                        (view(target), offset)
                    }),
                    reset: frame.reset_history,
                };
                temporal.encode(ctx, queue, history, &motion, input);
            }
            Pass::Mask { ao } => {
                let mask = frame.mask.as_ref().expect("planned with a mask");
                let output = view(Target::MaskedAo);
                self.mask.encode(ctx, mask, view(ao), output);
            }
        }
    }

    /// Records the kernel: MSVO and separable HBAO are passes of their own writing the same
    /// AO texture as the per-pixel methods.
    fn kernel(
        &mut self,
        ctx: &mut PassContext<'_>,
        kernel: Kernel,
        normals: &wgpu::TextureView,
        views: &Views<'_>,
    ) {
        let device = ctx.device;
        let ao = views.view(Target::Ao);
        match kernel {
            Kernel::Msvo { levels } => {
                let chain = views.texture(Target::DepthMips);
                self.msvo
                    .get_or_insert_with(|| MsvoPass::new(device))
                    .encode(ctx, &self.method, chain, normals, ao, levels);
            }
            Kernel::SeparableHbao { depth } => {
                self.separable_hbao
                    .get_or_insert_with(|| SeparableHbaoPass::new(device))
                    .encode(ctx, &self.method, views.view(depth), normals, ao);
            }
            Kernel::Method {
                method,
                orthographic,
                depth,
                bent_normals,
                depth_mip_atlas,
                back_thickness,
                ao_and_depth,
            } => self.method.encode(
                ctx,
                method,
                orthographic,
                views.view(depth),
                normals,
                ao,
                bent_normals.then(|| views.view(Target::BentNormals)),
                depth_mip_atlas.then(|| views.view(Target::DepthMipAtlas)),
                back_thickness.then(|| views.view(Target::BackThickness)),
                ao_and_depth.then(|| views.view(Target::AoAndDepth)),
            ),
        }
    }
}
