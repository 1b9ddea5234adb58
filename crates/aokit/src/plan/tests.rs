//! Plans of the configurations that matter, checked without a GPU.

use super::*;
use crate::settings::{DepthMips, HbaoVariant, Resolution};

/// A 160x96 frame with normals and motion vectors, no mask, perspective.
const INPUTS: FrameInputs = FrameInputs {
    size: [160, 96],
    normals: true,
    motion_vectors: true,
    mask: false,
    orthographic: false,
    guard_band: false,
};

fn plan(settings: AoSettings) -> FramePlan {
    FramePlan::new(&settings, &INPUTS)
}

/// Each step as `name@size`, `size` being `i` (input) or `w` (working).
fn names(plan: &FramePlan) -> Vec<String> {
    plan.steps
        .iter()
        .map(|step| {
            let name = match step.pass {
                Pass::LinearDepth => "linear_depth",
                Pass::DecodeNormals { .. } => "decode_normals",
                Pass::NormalsFromDepth { .. } => "normals_from_depth",
                Pass::Downsample { .. } => "downsample",
                Pass::BackFaces { .. } => "back_faces",
                Pass::DepthMips { .. } => "depth_mips",
                Pass::DepthMipAtlas { .. } => "depth_mip_atlas",
                Pass::Kernel { kernel, .. } => match kernel {
                    Kernel::Method { .. } => "method",
                    Kernel::Msvo { .. } => "msvo",
                    Kernel::SeparableHbao { .. } => "separable_hbao",
                },
                Pass::Upsample { .. } => "upsample",
                Pass::Spatial { .. } => "spatial",
                Pass::Temporal { .. } => "temporal",
                Pass::Mask { .. } => "mask",
            };
            let at = match step.at {
                At::Input => "i",
                At::Working => "w",
            };
            format!("{name}@{at}")
        })
        .collect()
}

/// The default settings without the spatial filter that they run: the kernel's passes alone,
/// to which each test adds the filters it is about.
fn raw() -> AoSettings {
    let mut settings = AoSettings::default();
    settings.spatial.enabled = false;
    settings
}

fn half(settings: AoSettings) -> AoSettings {
    AoSettings {
        resolution: Resolution::Half,
        ..settings
    }
}

fn spatial(kind: SpatialKind, settings: AoSettings) -> AoSettings {
    let mut settings = settings;
    settings.spatial.enabled = true;
    settings.spatial.kind = kind;
    settings
}

fn temporal(settings: AoSettings) -> AoSettings {
    let mut settings = settings;
    settings.temporal.enabled = true;
    settings
}

fn method(method: Method) -> AoSettings {
    AoSettings { method, ..raw() }
}

/// The step running `pass`'s kind, by its name in [`names`].
fn step<'p>(plan: &'p FramePlan, name: &str) -> &'p Step {
    let i = names(plan)
        .iter()
        .position(|n| n.starts_with(&format!("{name}@")))
        .unwrap_or_else(|| panic!("no {name} in {:?}", names(plan)));
    &plan.steps[i]
}

#[test]
fn the_defaults_run_the_edges_filter_after_the_kernel() {
    let plan = plan(AoSettings::default());
    assert_eq!(names(&plan), ["linear_depth@i", "method@w", "spatial@w"]);
    assert!(matches!(
        plan.steps[2].pass,
        Pass::Spatial {
            kind: SpatialKind::Edges,
            ..
        }
    ));
}

#[test]
fn full_resolution_reads_oct32_view_space_normals_as_they_are() {
    let plan = plan(raw());
    assert_eq!(names(&plan), ["linear_depth@i", "method@w"]);
    assert_eq!((plan.scale, plan.working), (1, [160, 96]));
    assert_eq!(plan.normals, Target::InputNormals);
    assert_eq!(plan.ao, Target::Ao);
    assert_eq!(plan.working_depth, Target::LinearDepth);
    assert!(matches!(
        step(&plan, "method").pass,
        Pass::Kernel {
            normals: Target::InputNormals,
            kernel: Kernel::Method {
                depth: Target::LinearDepth,
                bent_normals: false,
                depth_mip_atlas: false,
                back_thickness: false,
                ..
            }
        }
    ));
}

#[test]
fn other_encodings_and_world_space_normals_are_decoded() {
    let mut settings = raw();
    settings.normals.encoding = NormalEncoding::Oct16;
    let decoded = plan(settings);
    assert_eq!(
        names(&decoded),
        ["linear_depth@i", "decode_normals@i", "method@w"]
    );
    assert_eq!(
        step(&decoded, "decode_normals").pass,
        Pass::DecodeNormals {
            encoding: NormalEncoding::Oct16,
            world: false
        }
    );
    assert_eq!(decoded.normals, Target::Normals);
    // oct32 in world space still needs turning into view space.
    let mut settings = raw();
    settings.normals.space = NormalSpace::World;
    let world = plan(settings);
    assert_eq!(
        step(&world, "decode_normals").pass,
        Pass::DecodeNormals {
            encoding: NormalEncoding::Oct32,
            world: true
        }
    );
}

#[test]
fn normals_come_from_depth_without_a_buffer_or_when_the_settings_say_so() {
    let mut settings = raw();
    settings.normals.source = NormalSource::Depth5tap;
    let expected = ["linear_depth@i", "normals_from_depth@i", "method@w"];
    assert_eq!(names(&plan(settings)), expected);
    let no_buffer = FrameInputs {
        normals: false,
        ..INPUTS
    };
    let plan = FramePlan::new(&raw(), &no_buffer);
    assert_eq!(names(&plan), expected);
    assert_eq!(plan.normals, Target::Normals);
}

#[test]
fn below_full_resolution_with_a_normal_buffer_the_resample_reads_the_input_depth() {
    let plan = plan(half(raw()));
    // No linear depth pass: the upsample writes it.
    assert_eq!(names(&plan), ["downsample@w", "method@w", "upsample@i"]);
    assert_eq!((plan.scale, plan.working), (2, [80, 48]));
    assert_eq!(
        step(&plan, "downsample").pass,
        Pass::Downsample {
            depth: Target::InputDepth,
            normals: Target::InputNormals,
            motion_vectors: false
        }
    );
    assert_eq!(
        step(&plan, "upsample").pass,
        Pass::Upsample {
            depth: Target::InputDepth,
            normals: Target::InputNormals,
            ao: Target::Ao,
            bent_normals: false,
            write_linear_depth: true
        }
    );
    assert_eq!(plan.ao, Target::UpsampledAo);
    assert_eq!(plan.working_depth, Target::WorkingLinearDepth);
}

#[test]
fn below_full_resolution_decoded_normals_run_the_linear_depth_pass_their_fallback_reads() {
    let mut settings = half(AoSettings::default());
    settings.normals.encoding = NormalEncoding::Rgba16f;
    settings.spatial.enabled = false;
    let plan = plan(settings);
    assert_eq!(
        names(&plan),
        [
            "linear_depth@i",
            "decode_normals@i",
            "downsample@w",
            "method@w",
            "upsample@i"
        ]
    );
    assert!(matches!(
        step(&plan, "upsample").pass,
        Pass::Upsample {
            depth: Target::LinearDepth,
            write_linear_depth: false,
            ..
        }
    ));
}

#[test]
fn below_full_resolution_with_normals_from_depth_the_linear_depth_pass_runs() {
    let inputs = FrameInputs {
        normals: false,
        ..INPUTS
    };
    let settings = AoSettings {
        resolution: Resolution::Quarter,
        ..raw()
    };
    let plan = FramePlan::new(&settings, &inputs);
    let expected = [
        "linear_depth@i",
        "normals_from_depth@i",
        "downsample@w",
        "method@w",
        "upsample@i",
    ];
    assert_eq!(names(&plan), expected);
    assert_eq!((plan.scale, plan.working), (4, [40, 24]));
    assert!(matches!(
        step(&plan, "upsample").pass,
        Pass::Upsample {
            depth: Target::LinearDepth,
            normals: Target::Normals,
            write_linear_depth: false,
            ..
        }
    ));
}

#[test]
fn a_1x1_image_runs_as_at_full_resolution() {
    let inputs = FrameInputs {
        size: [1, 1],
        ..INPUTS
    };
    let settings = temporal(spatial(SpatialKind::Bilateral, half(raw())));
    let plan = FramePlan::new(&settings, &inputs);
    let expected = ["linear_depth@i", "method@w", "spatial@w", "temporal@w"];
    assert_eq!(names(&plan), expected);
    assert_eq!((plan.scale, plan.working), (1, [1, 1]));
    assert!(!plan.writes(Target::WorkingLinearDepth));
}

#[test]
fn filters_run_at_working_resolution_before_the_upsample() {
    let plan = plan(temporal(spatial(SpatialKind::Bilateral, half(raw()))));
    let expected = [
        "downsample@w",
        "method@w",
        "spatial@w",
        "temporal@w",
        "upsample@i",
    ];
    assert_eq!(names(&plan), expected);
    // The bilateral kind hands the temporal filter AO and depth packed in one texture.
    assert_eq!(
        step(&plan, "spatial").pass,
        Pass::Spatial {
            kind: SpatialKind::Bilateral,
            ao: Target::Ao,
            depth: Target::WorkingLinearDepth,
            normals: Target::WorkingNormals,
            packed: true,
            ao_and_depth: false
        }
    );
    assert_eq!(
        step(&plan, "temporal").pass,
        Pass::Temporal {
            ao: Target::SpatialAo,
            depth: Target::WorkingLinearDepth,
            motion_vectors: Some(Target::WorkingMotionVectors),
            packed: true
        }
    );
    assert!(matches!(
        step(&plan, "downsample").pass,
        Pass::Downsample {
            motion_vectors: true,
            ..
        }
    ));
    assert!(matches!(
        step(&plan, "upsample").pass,
        Pass::Upsample {
            ao: Target::History,
            ..
        }
    ));
    assert_eq!(plan.spatial_size, Some([80, 48]));
}

#[test]
fn filter_resolution_full_moves_the_filters_after_the_upsample() {
    let mut settings = temporal(spatial(SpatialKind::Guided, half(raw())));
    settings.filter_resolution = FilterResolution::Full;
    let plan = plan(settings);
    let expected = [
        "downsample@w",
        "method@w",
        "upsample@i",
        "spatial@i",
        "temporal@i",
    ];
    assert_eq!(names(&plan), expected);
    assert_eq!(
        step(&plan, "spatial").pass,
        Pass::Spatial {
            kind: SpatialKind::Guided,
            ao: Target::UpsampledAo,
            depth: Target::LinearDepth,
            normals: Target::InputNormals,
            packed: false,
            ao_and_depth: false
        }
    );
    // The input's motion vectors, so the downsample writes none.
    assert_eq!(
        step(&plan, "temporal").pass,
        Pass::Temporal {
            ao: Target::SpatialAo,
            depth: Target::LinearDepth,
            motion_vectors: Some(Target::InputMotionVectors),
            packed: false
        }
    );
    assert!(!plan.writes(Target::WorkingMotionVectors));
    assert_eq!(plan.ao, Target::History);
    assert_eq!(plan.spatial_size, Some([160, 96]));
}

#[test]
fn filter_resolution_full_at_full_resolution_changes_nothing() {
    let mut settings = spatial(SpatialKind::Edges, raw());
    let working = plan(settings);
    settings.filter_resolution = FilterResolution::Full;
    assert_eq!(plan(settings), working);
    assert_eq!(names(&working), ["linear_depth@i", "method@w", "spatial@w"]);
    assert_eq!(step(&working, "spatial").pass.writes(), [Target::SpatialAo]);
}

#[test]
fn each_spatial_kind_alone_writes_the_ao_unpacked() {
    for kind in [
        SpatialKind::Bilateral,
        SpatialKind::Guided,
        SpatialKind::Edges,
    ] {
        let plan = plan(spatial(kind, half(raw())));
        assert!(matches!(
            step(&plan, "spatial").pass,
            Pass::Spatial {
                packed: false,
                ao: Target::Ao,
                ..
            }
        ));
        assert!(matches!(
            step(&plan, "upsample").pass,
            Pass::Upsample {
                ao: Target::SpatialAo,
                ..
            }
        ));
    }
    // Only the bilateral kind packs for the temporal filter.
    let guided = plan(temporal(spatial(SpatialKind::Guided, raw())));
    assert!(matches!(
        step(&guided, "temporal").pass,
        Pass::Temporal { packed: false, .. }
    ));
}

/// Whether `plan`'s kernel packs its AO with the depth, and whether its spatial filter reads
/// them so.
fn packs(plan: &FramePlan) -> (bool, bool) {
    let kernel = plan.writes(Target::AoAndDepth);
    let filter = plan.steps.iter().any(|step| {
        matches!(
            step.pass,
            Pass::Spatial {
                ao_and_depth: true,
                ..
            }
        )
    });
    (kernel, filter)
}

#[test]
fn the_edges_kind_reads_the_ao_and_depth_a_per_pixel_kernel_packs() {
    let edges = spatial(SpatialKind::Edges, raw());
    // At full and half resolution, with the temporal filter after it too.
    for settings in [edges, half(edges), temporal(half(edges))] {
        let plan = plan(settings);
        assert_eq!(packs(&plan), (true, true), "{:?}", names(&plan));
        // The kernel's AO is still written: it is the frame's raw AO.
        assert!(step(&plan, "method").pass.writes().contains(&Target::Ao));
    }
    let mut off = edges;
    off.spatial.packed_input = false;
    let mut after_upsample = half(edges);
    after_upsample.filter_resolution = FilterResolution::Full;
    let unpacked = [
        off,
        after_upsample,
        spatial(SpatialKind::Bilateral, raw()),
        spatial(SpatialKind::Guided, raw()),
        AoSettings {
            method: Method::Msvo,
            ..edges
        },
        {
            let mut separable = AoSettings {
                method: Method::Hbao,
                ..edges
            };
            separable.hbao.variant = HbaoVariant::Separable;
            separable
        },
    ];
    for settings in unpacked {
        let plan = plan(settings);
        assert_eq!(packs(&plan), (false, false), "{:?}", names(&plan));
    }
}

#[test]
fn the_temporal_filter_alone_reads_the_kernels_ao_and_what_motion_there_is() {
    let plan = plan(temporal(raw()));
    assert_eq!(names(&plan), ["linear_depth@i", "method@w", "temporal@w"]);
    assert_eq!(
        step(&plan, "temporal").pass,
        Pass::Temporal {
            ao: Target::Ao,
            depth: Target::LinearDepth,
            motion_vectors: Some(Target::InputMotionVectors),
            packed: false
        }
    );
    let still = FrameInputs {
        motion_vectors: false,
        ..INPUTS
    };
    let settings = temporal(half(raw()));
    let plan = FramePlan::new(&settings, &still);
    assert!(matches!(
        step(&plan, "temporal").pass,
        Pass::Temporal {
            motion_vectors: None,
            ..
        }
    ));
    assert!(!plan.writes(Target::WorkingMotionVectors));
}

#[test]
fn methods_reading_depth_mips_bind_the_chain() {
    for (m, reduction) in [
        (Method::Sao, DepthReduction::Subsample),
        (Method::Ue4Ssao, DepthReduction::Furthest),
    ] {
        let plan = plan(half(method(m)));
        let expected = ["downsample@w", "depth_mips@w", "method@w", "upsample@i"];
        assert_eq!(names(&plan), expected);
        assert_eq!(
            step(&plan, "depth_mips").pass,
            Pass::DepthMips {
                reduction,
                depth: Target::WorkingLinearDepth
            }
        );
        assert!(matches!(
            step(&plan, "method").pass,
            Pass::Kernel {
                kernel: Kernel::Method {
                    depth: Target::DepthMips,
                    ..
                },
                ..
            }
        ));
    }
}

#[test]
fn msvo_runs_its_own_passes_over_the_chain() {
    let settings = method(Method::Msvo);
    let plan = plan(settings);
    assert_eq!(names(&plan), ["linear_depth@i", "depth_mips@w", "msvo@w"]);
    assert_eq!(
        step(&plan, "depth_mips").pass,
        Pass::DepthMips {
            reduction: DepthReduction::Subsample,
            depth: Target::LinearDepth
        }
    );
    assert_eq!(
        step(&plan, "msvo").pass,
        Pass::Kernel {
            kernel: Kernel::Msvo {
                levels: settings.msvo.levels
            },
            normals: Target::InputNormals
        }
    );
}

#[test]
fn separable_hbao_replaces_the_method_pass_and_reads_no_atlas() {
    let mut settings = method(Method::Hbao);
    settings.hbao.variant = HbaoVariant::Separable;
    settings.depth_mips = DepthMips::Fp32;
    let plan = plan(settings);
    assert_eq!(names(&plan), ["linear_depth@i", "separable_hbao@w"]);
    assert_eq!(plan.depth_mip_atlas, None);
}

#[test]
fn the_depth_mip_atlas_is_made_for_the_kernels_that_read_it() {
    for (depth_mips, format) in [
        (DepthMips::Fp32, wgpu::TextureFormat::R32Float),
        (DepthMips::Fp16, wgpu::TextureFormat::R16Float),
    ] {
        let settings = AoSettings {
            depth_mips,
            ..half(raw())
        };
        let plan = FramePlan::new(
            &settings,
            &FrameInputs {
                orthographic: true,
                ..INPUTS
            },
        );
        let expected = [
            "downsample@w",
            "depth_mip_atlas@w",
            "method@w",
            "upsample@i",
        ];
        assert_eq!(names(&plan), expected);
        assert_eq!(plan.depth_mip_atlas, Some(format));
        assert_eq!(
            step(&plan, "depth_mip_atlas").pass,
            Pass::DepthMipAtlas {
                depth: Target::WorkingLinearDepth,
                orthographic: true
            }
        );
        assert!(matches!(
            step(&plan, "method").pass,
            Pass::Kernel {
                kernel: Kernel::Method {
                    depth_mip_atlas: true,
                    orthographic: true,
                    ..
                },
                ..
            }
        ));
    }
    // Methods with a chain of their own read no atlas.
    let sao = AoSettings {
        depth_mips: DepthMips::Fp32,
        ..method(Method::Sao)
    };
    assert_eq!(plan(sao).depth_mip_atlas, None);
}

#[test]
fn vbao_back_faces_run_before_the_kernel() {
    let mut settings = half(method(Method::Vbao));
    settings.vbao.back_faces = true;
    let plan = plan(settings);
    let expected = ["downsample@w", "back_faces@w", "method@w", "upsample@i"];
    assert_eq!(names(&plan), expected);
    assert_eq!(
        step(&plan, "back_faces").pass,
        Pass::BackFaces {
            depth: Target::WorkingLinearDepth,
            scale: 2
        }
    );
    assert!(matches!(
        step(&plan, "method").pass,
        Pass::Kernel {
            kernel: Kernel::Method {
                back_thickness: true,
                ..
            },
            ..
        }
    ));
}

#[test]
fn bent_normals_are_written_by_the_kernel_and_upsampled() {
    let settings = AoSettings {
        bent_normals: true,
        ..method(Method::Gtao)
    };
    let full = plan(settings);
    assert_eq!(full.bent_normals, Some(Target::BentNormals));
    let kernel = step(&full, "method").pass;
    assert_eq!(kernel.writes(), [Target::Ao, Target::BentNormals]);
    let half = plan(half(settings));
    assert_eq!(half.bent_normals, Some(Target::UpsampledBentNormals));
    assert!(half.writes(Target::UpsampledBentNormals));
    assert_eq!(plan(method(Method::Gtao)).bent_normals, None);
}

#[test]
fn the_mask_is_the_last_pass() {
    let masked = FrameInputs {
        mask: true,
        ..INPUTS
    };
    let settings = temporal(spatial(SpatialKind::Bilateral, half(raw())));
    let plan = FramePlan::new(&settings, &masked);
    assert_eq!(names(&plan).last().map(String::as_str), Some("mask@i"));
    assert_eq!(
        plan.steps.last().map(|s| s.pass),
        Some(Pass::Mask {
            ao: Target::UpsampledAo
        })
    );
    assert_eq!(plan.ao, Target::MaskedAo);
}

#[test]
fn every_target_a_step_reads_is_an_input_or_written_before() {
    let mut all = Vec::new();
    for m in Method::ALL {
        for resolution in [Resolution::Full, Resolution::Half, Resolution::Quarter] {
            for filter_resolution in [FilterResolution::Working, FilterResolution::Full] {
                for kind in [
                    SpatialKind::Bilateral,
                    SpatialKind::Guided,
                    SpatialKind::Edges,
                ] {
                    let mut settings = temporal(spatial(kind, method(m)));
                    settings.resolution = resolution;
                    settings.filter_resolution = filter_resolution;
                    all.push(settings);
                }
            }
        }
    }
    for settings in all {
        for normals in [false, true] {
            let plan = FramePlan::new(&settings, &FrameInputs { normals, ..INPUTS });
            let mut written = vec![
                Target::InputDepth,
                Target::InputNormals,
                Target::InputMotionVectors,
            ];
            for step in &plan.steps {
                for read in reads(&step.pass) {
                    assert!(
                        written.contains(&read),
                        "{read:?} read before written: {plan:?}"
                    );
                }
                written.extend(step.pass.writes());
            }
            assert!(written.contains(&plan.ao));
        }
    }
}

/// The targets `pass` names as its inputs.
fn reads(pass: &Pass) -> Vec<Target> {
    match *pass {
        Pass::LinearDepth => vec![Target::InputDepth],
        Pass::DecodeNormals { .. } => vec![Target::InputNormals, Target::LinearDepth],
        Pass::NormalsFromDepth { .. } => vec![Target::LinearDepth],
        Pass::Downsample { depth, normals, .. } => vec![depth, normals],
        Pass::BackFaces { depth, .. } | Pass::DepthMips { depth, .. } => vec![depth],
        Pass::DepthMipAtlas { depth, .. } => vec![depth],
        Pass::Kernel { kernel, normals } => match kernel {
            Kernel::Method { depth, .. } | Kernel::SeparableHbao { depth } => vec![depth, normals],
            Kernel::Msvo { .. } => vec![Target::DepthMips, normals],
        },
        Pass::Upsample {
            depth, normals, ao, ..
        } => vec![depth, normals, ao],
        Pass::Spatial { ao, depth, .. } | Pass::Temporal { ao, depth, .. } => vec![ao, depth],
        Pass::Mask { ao } => vec![ao],
    }
}

#[test]
fn a_guard_band_makes_its_own_linear_depth_and_normals_for_the_inner_frame_to_copy() {
    let band = FrameInputs {
        guard_band: true,
        motion_vectors: false,
        ..INPUTS
    };
    // Below full resolution with oct32 view-space normals the renderer's textures would do
    // (the test above); with a band the steps after the kernel read copies of the inner
    // frame, which can only be cut from aokit's own targets.
    let settings = half(raw());
    let plan = FramePlan::new(&settings, &band);
    assert_eq!(
        names(&plan),
        [
            "linear_depth@i",
            "decode_normals@i",
            "downsample@w",
            "method@w",
            "upsample@i"
        ]
    );
    assert_eq!(plan.normals, Target::Normals);
    assert_eq!(
        step(&plan, "upsample").pass,
        Pass::Upsample {
            depth: Target::LinearDepth,
            normals: Target::Normals,
            ao: Target::Ao,
            bent_normals: false,
            write_linear_depth: false
        }
    );
    // The steps through the kernel run on the whole input, the rest on the inner frame.
    assert_eq!(plan.through_kernel(), 4);
    let full = FramePlan::new(&raw(), &band);
    assert_eq!(
        names(&full),
        ["linear_depth@i", "decode_normals@i", "method@w"]
    );
    assert_eq!(full.through_kernel(), 3);
}
