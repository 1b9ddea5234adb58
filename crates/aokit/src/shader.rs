//! WGSL programs assembled from shared snippets.
//!
//! WGSL has no `#include`, so every pass is the concatenation of the snippets it uses and its own
//! file, each a file under `shaders/`. A file's `// requires:` header names the files it is
//! written against, which every program holding it holds too (a test holds the headers to what
//! the files declare and use). The snippets are public so that renderers (aokit-scene, or
//! yours) can encode normals exactly as aokit decodes them.

mod bindings;
#[cfg(test)]
mod files;

use wgpu::naga;

use crate::settings::Method;

pub use bindings::check_bindings;

/// Camera conventions, the `ViewUniforms` binding and position reconstruction.
pub const VIEW: &str = include_str!("../shaders/common/view.wgsl");
/// Normal encodings (`pack_oct32`, `unpack_oct32`, ...).
///
/// ```
/// use aokit::shader::{self, ShaderSource};
/// // A G-buffer pass that writes normals exactly as the pipeline decodes them: oct32, into an
/// // `R32Uint` target.
/// const GBUFFER: ShaderSource = ShaderSource {
///     name: "gbuffer",
///     parts: &[shader::ENCODING, "
/// struct Surface {
///     @builtin(position) position: vec4<f32>,
///     @location(0) view_normal: vec3<f32>,
/// }
///
/// @fragment
/// fn fs_main(surface: Surface) -> @location(0) u32 {
///     return pack_oct32(normalize(surface.view_normal));
/// }"],
/// };
/// let module = GBUFFER.validate()?;
/// // aokit's snippet and the pass are one module: the pass's entry point is in it.
/// let entry = module.entry_points.iter().find(|e| e.name == "fs_main").unwrap();
/// assert_eq!(entry.stage, wgpu::naga::ShaderStage::Fragment);
/// # Ok::<(), String>(())
/// ```
pub const ENCODING: &str = include_str!("../shaders/common/encoding.wgsl");
/// Per-pixel noise.
pub const NOISE: &str = include_str!("../shaders/common/noise.wgsl");
/// The interface of the AO method kernels: `AoUniforms`, their bindings, the shaded surface and
/// the shaping of the result.
pub const AO: &str = include_str!("../shaders/common/ao.wgsl");
/// The per-pixel kernels' entry point `main` and their `Estimate`, after [`AO`]; a method's
/// file supplies `estimate`. Kernels of another shape (separable HBAO) leave it out.
pub const AO_ENTRY: &str = include_str!("../shaders/common/ao_entry.wgsl");
/// Slices of the hemisphere through the view vector, for the slice-based methods.
pub const SLICE: &str = include_str!("../shaders/common/slice.wgsl");
/// HBAO's horizon term along one direction, after [`AO`] and [`SLICE`]: the per-pixel kernel
/// ([`HBAO`]) and the separable passes ([`HBAO_ROWS`], [`HBAO_COLUMNS`]) share it.
///
/// ```
/// use aokit::shader;
/// // Both HBAO variants march their directions with the same function.
/// for program in [shader::HBAO, shader::HBAO_ROWS, shader::HBAO_COLUMNS] {
///     assert!(program.parts.contains(&shader::HORIZON), "{}", program.name);
///     assert!(program.source().contains("horizon = raise_horizon("), "{}", program.name);
/// }
/// ```
pub const HORIZON: &str = include_str!("../shaders/common/horizon.wgsl");
/// Multi-bounce AO and specular occlusion for lighting passes; see [`crate::occlusion`].
pub const OCCLUSION: &str = include_str!("../shaders/common/occlusion.wgsl");

/// One WGSL program: the snippets it needs followed by its own file.
///
/// ```
/// use aokit::shader::{self, ShaderSource};
/// // A companion crate's overlay of the normals the kernel read, darkened by the AO: aokit's
/// // view uniforms (binding 0) and oct32 decoding are pasted in, not copied.
/// const NORMALS_OVERLAY: ShaderSource = ShaderSource {
///     name: "normals_overlay",
///     parts: &[shader::VIEW, shader::ENCODING, "
/// @group(0) @binding(1) var normals: texture_2d<u32>;
/// @group(0) @binding(2) var ao: texture_2d<f32>;
/// @group(0) @binding(3) var overlay: texture_storage_2d<rgba8unorm, write>;
///
/// @compute @workgroup_size(8, 8)
/// fn main(@builtin(global_invocation_id) id: vec3<u32>) {
///     if any(vec2<f32>(id.xy) >= view.size) {
///         return;
///     }
///     let n = unpack_oct32(textureLoad(normals, id.xy, 0).r);
///     let a = textureLoad(ao, id.xy, 0).r;
///     textureStore(overlay, id.xy, vec4<f32>((n * 0.5 + 0.5) * a, 1.0));
/// }"],
/// };
/// // naga finds WGSL errors in a unit test, before any device exists.
/// let module = NORMALS_OVERLAY.validate()?;
/// // One compute entry point, its workgroup as declared.
/// assert_eq!(module.entry_points.len(), 1);
/// assert_eq!(module.entry_points[0].workgroup_size, [8, 8, 1]);
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct ShaderSource {
    /// Name of the pass, used as the module label.
    pub name: &'static str,
    /// Source pieces, concatenated in order.
    pub parts: &'static [&'static str],
}

/// Binding 1 of a program reading depth, and of `apply_mask` with a mask texture: a
/// single-sampled float texture and `load_input`.
const FLOAT_INPUT: &str = include_str!("../shaders/common/inputs/float_input.wgsl");

/// As [`FLOAT_INPUT`], multisampled: sample 0 is read.
const FLOAT_INPUT_MULTISAMPLED: &str =
    include_str!("../shaders/common/inputs/float_input_multisampled.wgsl");

/// `input_linear_depth` from hardware depth over [`FLOAT_INPUT`] or [`FLOAT_INPUT_MULTISAMPLED`].
const DEPTH_FROM_NDC: &str = include_str!("../shaders/common/depth_from_ndc.wgsl");
/// `input_linear_depth` from linear depth over [`FLOAT_INPUT`] or
/// [`FLOAT_INPUT_MULTISAMPLED`].
const DEPTH_FROM_LINEAR: &str = include_str!("../shaders/common/depth_from_linear.wgsl");

/// One program per kind of depth input, in the order hardware depth, multisampled hardware
/// depth, linear `R32Float` depth, multisampled linear depth: the parts before, the input's
/// binding 1 and `input_linear_depth`, the parts after.
macro_rules! per_depth_input {
    ($name:literal, [$($before:expr),*], [$($after:expr),*]) => {
        [
            ShaderSource {
                name: $name,
                parts: &[$($before,)* FLOAT_INPUT, DEPTH_FROM_NDC, $($after),*],
            },
            ShaderSource {
                name: $name,
                parts: &[$($before,)* FLOAT_INPUT_MULTISAMPLED, DEPTH_FROM_NDC, $($after),*],
            },
            ShaderSource {
                name: $name,
                parts: &[$($before,)* FLOAT_INPUT, DEPTH_FROM_LINEAR, $($after),*],
            },
            ShaderSource {
                name: $name,
                parts: &[$($before,)* FLOAT_INPUT_MULTISAMPLED, DEPTH_FROM_LINEAR, $($after),*],
            },
        ]
    };
}

/// The renderer's depth to linear view depth: hardware depth, multisampled hardware depth,
/// linear `R32Float` depth (sanitised), multisampled linear depth.
pub const LINEAR_DEPTH: [ShaderSource; 4] = per_depth_input!(
    "linear_depth",
    [VIEW],
    [include_str!("../shaders/input/linear_depth.wgsl")]
);

/// Each working texel's occluder thickness from the back faces' depth, for
/// `vbao.back_faces`, per kind of depth input.
pub const BACK_FACES: [ShaderSource; 4] = per_depth_input!(
    "back_faces",
    [VIEW, RESAMPLE],
    [include_str!("../shaders/input/back_faces.wgsl")]
);

/// `normal_from_depth`, the reconstruction of a normal from linear depth that
/// [`NORMALS_FROM_DEPTH`] writes and the normal decode falls back to.
const DEPTH_NORMAL: &str = include_str!("../shaders/common/depth_normal.wgsl");

/// Normals reconstructed from linear depth.
pub const NORMALS_FROM_DEPTH: ShaderSource = ShaderSource {
    name: "normals_from_depth",
    parts: &[
        VIEW,
        ENCODING,
        DEPTH_NORMAL,
        include_str!("../shaders/input/normals_from_depth.wgsl"),
    ],
};

/// Binding 1 of `decode_normals` for encodings held in `R32Uint` texels.
const ENCODED_UINT: &str = include_str!("../shaders/common/inputs/encoded_uint.wgsl");

/// Binding 1 of `decode_normals` for encodings held in unorm or float texels.
const ENCODED_FLOAT: &str = include_str!("../shaders/common/inputs/encoded_float.wgsl");

/// A normal texture in an `R32Uint` encoding other than oct32 to oct32.
pub const DECODE_NORMALS_UINT: ShaderSource = ShaderSource {
    name: "decode_normals",
    parts: &[
        VIEW,
        ENCODING,
        DEPTH_NORMAL,
        ENCODED_UINT,
        include_str!("../shaders/input/decode_normals.wgsl"),
    ],
};

/// A normal texture in a unorm or float encoding to oct32.
pub const DECODE_NORMALS_FLOAT: ShaderSource = ShaderSource {
    name: "decode_normals",
    parts: &[
        VIEW,
        ENCODING,
        DEPTH_NORMAL,
        ENCODED_FLOAT,
        include_str!("../shaders/input/decode_normals.wgsl"),
    ],
};

/// The storage type of a two-channel float target, one part per
/// [`PairFormat`](crate::gpu::PairFormat) in its order: a program that writes one declares it
/// `pair_storage`.
const PAIR_STORAGE: [&str; 2] = [
    include_str!("../shaders/common/formats/pair_rg32float.wgsl"),
    include_str!("../shaders/common/formats/pair_rgba32float.wgsl"),
];

/// One program per [`PairFormat`](crate::gpu::PairFormat), indexed by it: the parts with
/// `pair_storage` declared.
macro_rules! per_pair_format {
    ($name:literal, [$($part:expr),*]) => {
        [
            ShaderSource {
                name: $name,
                parts: &[$($part,)* PAIR_STORAGE[0]],
            },
            ShaderSource {
                name: $name,
                parts: &[$($part,)* PAIR_STORAGE[1]],
            },
        ]
    };
}

/// The spatial filter's tile, weights and entry point; each pass file adds its axis, workgroup
/// shape and textures.
const SPATIAL_FILTER: &str = include_str!("../shaders/filter/spatial_filter.wgsl");

/// The bilateral weights' settings buffer and code paths, which the bilateral and edges kinds
/// of the spatial filter share.
const BILATERAL_WEIGHTS: &str = include_str!("../shaders/filter/bilateral_weights.wgsl");

/// First pass of the spatial filter: along rows, AO and linear depth in, both packed out; per
/// [`PairFormat`](crate::gpu::PairFormat).
pub const SPATIAL_FILTER_HORIZONTAL: [ShaderSource; 2] = per_pair_format!(
    "spatial_filter_horizontal",
    [
        VIEW,
        ENCODING,
        BILATERAL_WEIGHTS,
        SPATIAL_FILTER,
        include_str!("../shaders/filter/spatial_filter_horizontal.wgsl")
    ]
);

/// Second pass of the spatial filter: along columns, packed AO and depth in, AO (or AO and
/// depth packed, for the temporal filter) out; per [`PairFormat`](crate::gpu::PairFormat).
pub const SPATIAL_FILTER_VERTICAL: [ShaderSource; 2] = per_pair_format!(
    "spatial_filter_vertical",
    [
        VIEW,
        ENCODING,
        BILATERAL_WEIGHTS,
        SPATIAL_FILTER,
        include_str!("../shaders/filter/spatial_filter_vertical.wgsl")
    ]
);

/// The AO and linear depth packed in one `R32Uint` texel, which the per-pixel kernels write for
/// the edges kind to read ([`SpatialSettings::packed_input`](crate::SpatialSettings::packed_input)).
const AO_AND_DEPTH: &str = include_str!("../shaders/common/ao_and_depth.wgsl");

/// The spatial filter's `edges` kind: one 3x3 edge-aware pass, AO, linear depth (or the two
/// packed) and normals in, AO out.
pub const EDGE_FILTER: ShaderSource = ShaderSource {
    name: "edge_filter",
    parts: &[
        VIEW,
        ENCODING,
        BILATERAL_WEIGHTS,
        AO_AND_DEPTH,
        include_str!("../shaders/filter/edge_filter.wgsl"),
    ],
};

/// The guided filter's settings, tile and indexing; each pass file adds its textures and entry
/// point.
const GUIDED_FILTER: &str = include_str!("../shaders/filter/guided_filter.wgsl");

/// First pass of the guided filter: AO and linear depth in, each window's line (slope and value
/// at its centre) out; per [`PairFormat`](crate::gpu::PairFormat).
pub const GUIDED_FILTER_COEFFICIENTS: [ShaderSource; 2] = per_pair_format!(
    "guided_filter_coefficients",
    [
        VIEW,
        GUIDED_FILTER,
        include_str!("../shaders/filter/guided_filter_coefficients.wgsl")
    ]
);

/// Second pass of the guided filter: the windows' lines and linear depth in, AO out.
pub const GUIDED_FILTER_OUTPUT: ShaderSource = ShaderSource {
    name: "guided_filter_output",
    parts: &[
        VIEW,
        GUIDED_FILTER,
        include_str!("../shaders/filter/guided_filter_output.wgsl"),
    ],
};

/// The temporal filter, per [`PairFormat`](crate::gpu::PairFormat).
pub const TEMPORAL_FILTER: [ShaderSource; 2] = per_pair_format!(
    "temporal_filter",
    [VIEW, include_str!("../shaders/filter/temporal_filter.wgsl")]
);

/// The mask texture's weight in `apply_mask`, after [`FLOAT_INPUT`] or its multisampled form.
const MASK_TEXTURE_WEIGHT: &str = include_str!("../shaders/common/mask/texture_weight.wgsl");

/// The stencil test of `apply_mask`, after its binding, with the reference and read mask as
/// override constants.
const MASK_STENCIL_TEST: &str = include_str!("../shaders/common/mask/stencil_test.wgsl");

/// Binding 1 of `apply_mask`: a stencil aspect.
const MASK_STENCIL: &str = include_str!("../shaders/common/inputs/stencil.wgsl");

/// Binding 1 of `apply_mask`: sample 0 of a multisampled stencil aspect.
const MASK_STENCIL_MULTISAMPLED: &str =
    include_str!("../shaders/common/inputs/stencil_multisampled.wgsl");

const APPLY_MASK_PASS: &str = include_str!("../shaders/output/apply_mask.wgsl");

/// AO 1 where a mask texture says so.
pub const APPLY_MASK_TEXTURE: ShaderSource = ShaderSource {
    name: "apply_mask",
    parts: &[VIEW, FLOAT_INPUT, MASK_TEXTURE_WEIGHT, APPLY_MASK_PASS],
};

/// AO 1 where sample 0 of a multisampled mask texture says so.
pub const APPLY_MASK_TEXTURE_MULTISAMPLED: ShaderSource = ShaderSource {
    name: "apply_mask",
    parts: &[
        VIEW,
        FLOAT_INPUT_MULTISAMPLED,
        MASK_TEXTURE_WEIGHT,
        APPLY_MASK_PASS,
    ],
};

/// AO 1 where the stencil equals the reference.
pub const APPLY_MASK_STENCIL: ShaderSource = ShaderSource {
    name: "apply_mask",
    parts: &[VIEW, MASK_STENCIL, MASK_STENCIL_TEST, APPLY_MASK_PASS],
};

/// AO 1 where sample 0 of a multisampled stencil equals the reference.
pub const APPLY_MASK_STENCIL_MULTISAMPLED: ShaderSource = ShaderSource {
    name: "apply_mask",
    parts: &[
        VIEW,
        MASK_STENCIL_MULTISAMPLED,
        MASK_STENCIL_TEST,
        APPLY_MASK_PASS,
    ],
};

/// Debug views of a frame's intermediates.
pub const DEBUG_VIEW: ShaderSource = ShaderSource {
    name: "debug_view",
    parts: &[ENCODING, include_str!("../shaders/output/debug_view.wgsl")],
};

/// The settings the downsample and the upsample share; each pass file adds its textures and
/// entry point.
const RESAMPLE: &str = include_str!("../shaders/resample/resample.wgsl");

/// Linear depth, normals and motion vectors from the input's resolution to the working one,
/// per [`PairFormat`](crate::gpu::PairFormat) and kind of depth input.
pub const DOWNSAMPLE: [[ShaderSource; 4]; 2] = [
    per_depth_input!(
        "downsample",
        [VIEW, RESAMPLE, PAIR_STORAGE[0]],
        [include_str!("../shaders/resample/downsample.wgsl")]
    ),
    per_depth_input!(
        "downsample",
        [VIEW, RESAMPLE, PAIR_STORAGE[1]],
        [include_str!("../shaders/resample/downsample.wgsl")]
    ),
];

/// AO and bent normals from the working resolution to the input's, guided by depth, per kind
/// of depth input.
pub const UPSAMPLE: [ShaderSource; 4] = per_depth_input!(
    "upsample",
    [VIEW, ENCODING, RESAMPLE],
    [include_str!("../shaders/resample/upsample.wgsl")]
);

/// A program on the AO kernels' interface ([`AO`] and what it needs), then `snippets`, then
/// its own file. The multi-pass methods bring entry points of their own; the per-pixel ones
/// are [`method_program`]s.
macro_rules! ao_program {
    ($dir:literal, $name:literal $(, $snippet:expr)*) => {
        ShaderSource {
            name: $name,
            parts: &[
                VIEW,
                ENCODING,
                NOISE,
                AO,
                $($snippet,)*
                include_str!(concat!("../shaders/", $dir, "/", $name, ".wgsl")),
            ],
        }
    };
}

/// A per-pixel method kernel: [`ao_program`] with [`AO_ENTRY`] and the packed AO and depth it
/// can write, then `snippets` and `kernel/methods/<name>.wgsl`, which supplies `estimate`.
macro_rules! method_program {
    ($name:literal $(, $snippet:expr)*) => {
        ao_program!("kernel/methods", $name, AO_ENTRY, AO_AND_DEPTH $(, $snippet)*)
    };
}

/// Crytek's sphere-sampling SSAO.
pub const SSAO_CRYTEK: ShaderSource = method_program!("ssao_crytek");
/// Normal-oriented hemisphere SSAO.
pub const SSAO: ShaderSource = method_program!("ssao");
/// Horizon-based AO.
pub const HBAO: ShaderSource = method_program!("hbao", SLICE, HORIZON);
/// HBAO+'s normal-based estimator.
pub const HBAO_PLUS: ShaderSource = method_program!("hbao_plus", SLICE);
/// Ground-truth based AO.
pub const GTAO: ShaderSource = method_program!("gtao", SLICE);
/// Visibility bitmask AO.
pub const VBAO: ShaderSource = method_program!("vbao", SLICE);
/// Scalable Ambient Obscurance.
pub const SAO: ShaderSource = method_program!("sao", SUBSAMPLE_CHAIN);
/// Unreal Engine 4's legacy SSAO: mirrored sample pairs scored by the angle between them.
pub const UE4_SSAO: ShaderSource = method_program!("ue4_ssao");

/// Where the texels of the subsampled depth MIP chain that `sao` and `msvo` read come from.
pub(crate) const SUBSAMPLE_CHAIN: &str = include_str!("../shaders/common/subsample_chain.wgsl");

/// What `msvo`'s two passes share.
const MSVO: &str = include_str!("../shaders/kernel/msvo/msvo.wgsl");

/// `msvo`'s obscurance at one level of the depth MIP chain: the kernels' interface without
/// their entry point, then its own, one thread per texel of the level.
///
/// ```
/// use aokit::{Method, shader};
/// // What `shader::method` gives for `msvo`; the merge of the levels is its second program.
/// assert_eq!(shader::method(Method::Msvo).name, shader::MSVO_OBSCURANCE.name);
/// assert!(shader::MSVO_MERGE.source().contains("fn shape_ao("));
/// ```
pub const MSVO_OBSCURANCE: ShaderSource =
    ao_program!("kernel/msvo", "msvo_obscurance", MSVO, SUBSAMPLE_CHAIN);

/// `msvo`'s merge of one level: its obscurance times the depth-aware upsample of the merged
/// level below it, shaped at the working level into the method's AO.
pub const MSVO_MERGE: ShaderSource = ao_program!("kernel/msvo", "msvo_merge", MSVO);

/// Levels 1 to 4 of a depth MIP chain from its level 0, by the reduction its `REDUCTION`
/// override names (SAO's subsample, `ue4-ssao`'s furthest depth, or the mean on one surface
/// that `depth_mips` reads), stored as `R32Float`.
pub const DEPTH_MIPS: ShaderSource = ShaderSource {
    name: "depth_mips",
    parts: &[
        include_str!("../shaders/common/formats/level_r32float.wgsl"),
        include_str!("../shaders/kernel/depth_mips.wgsl"),
    ],
};

/// [`DEPTH_MIPS`] stored as `R16Float`, for `depth_mips = fp16`.
pub const DEPTH_MIPS_FP16: ShaderSource = ShaderSource {
    name: "depth_mips",
    parts: &[
        include_str!("../shaders/common/formats/level_r16float.wgsl"),
        include_str!("../shaders/kernel/depth_mips.wgsl"),
    ],
};

/// The kernel of `method`.
///
/// ```
/// use aokit::{AoSettings, Method, shader};
/// // The WGSL behind the settings, for a bug report or a shader debugger.
/// let settings = AoSettings::preset(Method::HbaoPlus, aokit::Preset::High);
/// let program = shader::method(settings.method);
/// assert_eq!(program.name, "hbao_plus");
/// assert!(program.source().contains(shader::SLICE));
/// ```
pub fn method(method: Method) -> ShaderSource {
    // For `msvo`, per level; `MSVO_MERGE` combines the levels.
    crate::methods::spec(method).shader
}

/// Separable HBAO's tile, line lookup, march and entry point; each pass file adds its axis and
/// textures.
const HBAO_SEPARABLE: &str = include_str!("../shaders/kernel/separable_hbao/hbao_separable.wgsl");

/// First pass of separable HBAO (`hbao.variant = separable`): the +x and -x horizons of every
/// pixel from its row of linear depth in workgroup memory, their occlusion summed into an
/// `R32Float` texture.
///
/// ```
/// use aokit::shader;
/// // One workgroup per 128-pixel segment of a row: a 1920x1080 image takes 15 x 1080.
/// let [x, y, _] = shader::HBAO_ROWS.workgroup_size()?;
/// assert_eq!([1920u32.div_ceil(x), 1080u32.div_ceil(y)], [15, 1080]);
/// # Ok::<(), String>(())
/// ```
pub const HBAO_ROWS: ShaderSource = ao_program!(
    "kernel/separable_hbao",
    "hbao_rows",
    SLICE,
    HORIZON,
    HBAO_SEPARABLE
);

/// Second pass of separable HBAO: the +y and -y horizons from each column in workgroup memory,
/// added to the rows pass's occlusion and stored as the AO, shaped as every method's is.
///
/// ```
/// use aokit::shader;
/// // Segments of 128 pixels, laid along x as the rows pass's are: the pass runs on the
/// // transposed grid, a 1920x1080 image in 9 x 1920 workgroups.
/// let [x, y, _] = shader::HBAO_COLUMNS.workgroup_size()?;
/// assert_eq!([1080u32.div_ceil(x), 1920u32.div_ceil(y)], [9, 1920]);
/// // The AO is stored by the same code as every method kernel's.
/// assert!(shader::HBAO_COLUMNS.source().contains("fn store_ao("));
/// # Ok::<(), String>(())
/// ```
pub const HBAO_COLUMNS: ShaderSource = ao_program!(
    "kernel/separable_hbao",
    "hbao_columns",
    SLICE,
    HORIZON,
    HBAO_SEPARABLE
);

/// The shading helpers of [`OCCLUSION`] alone: no entry point, validated so that the snippet
/// renderers paste into their own shaders is known to compile.
pub const OCCLUSION_FUNCTIONS: ShaderSource = ShaderSource {
    name: "occlusion",
    parts: &[OCCLUSION],
};

/// A depth texture into an `R32Float` one, for [`read_texture`](crate::gpu::read_texture) on a
/// device that copies no depth texture to a buffer.
pub const DEPTH_TO_FLOAT: ShaderSource = ShaderSource {
    name: "depth_to_float",
    parts: &[include_str!("../shaders/depth_to_float.wgsl")],
};

/// Every program the library compiles or validates.
pub const ALL: &[ShaderSource] = &[
    LINEAR_DEPTH[0],
    LINEAR_DEPTH[1],
    LINEAR_DEPTH[2],
    LINEAR_DEPTH[3],
    BACK_FACES[0],
    BACK_FACES[1],
    BACK_FACES[2],
    BACK_FACES[3],
    NORMALS_FROM_DEPTH,
    DECODE_NORMALS_UINT,
    DECODE_NORMALS_FLOAT,
    SSAO_CRYTEK,
    SSAO,
    HBAO,
    HBAO_PLUS,
    GTAO,
    VBAO,
    SAO,
    UE4_SSAO,
    MSVO_OBSCURANCE,
    MSVO_MERGE,
    DEPTH_MIPS,
    DEPTH_MIPS_FP16,
    HBAO_ROWS,
    HBAO_COLUMNS,
    SPATIAL_FILTER_HORIZONTAL[0],
    SPATIAL_FILTER_HORIZONTAL[1],
    SPATIAL_FILTER_VERTICAL[0],
    SPATIAL_FILTER_VERTICAL[1],
    GUIDED_FILTER_COEFFICIENTS[0],
    GUIDED_FILTER_COEFFICIENTS[1],
    GUIDED_FILTER_OUTPUT,
    EDGE_FILTER,
    TEMPORAL_FILTER[0],
    TEMPORAL_FILTER[1],
    DOWNSAMPLE[0][0],
    DOWNSAMPLE[0][1],
    DOWNSAMPLE[0][2],
    DOWNSAMPLE[0][3],
    DOWNSAMPLE[1][0],
    DOWNSAMPLE[1][1],
    DOWNSAMPLE[1][2],
    DOWNSAMPLE[1][3],
    UPSAMPLE[0],
    UPSAMPLE[1],
    UPSAMPLE[2],
    UPSAMPLE[3],
    DEPTH_TO_FLOAT,
    APPLY_MASK_TEXTURE,
    APPLY_MASK_TEXTURE_MULTISAMPLED,
    APPLY_MASK_STENCIL,
    APPLY_MASK_STENCIL_MULTISAMPLED,
    DEBUG_VIEW,
    OCCLUSION_FUNCTIONS,
];

impl ShaderSource {
    /// The assembled WGSL text.
    ///
    /// ```
    /// // A driver reported an error at line 120 of `gtao`: lines count from the first snippet.
    /// let wgsl = aokit::shader::GTAO.source();
    /// let line = wgsl.lines().nth(120 - 1).expect("gtao is longer than 120 lines");
    /// eprintln!("gtao:120: {line}");
    /// // Line 1 is the first snippet's first line; the snippets follow each other on new lines.
    /// let parts = aokit::shader::GTAO.parts;
    /// assert_eq!(wgsl.lines().next(), parts[0].lines().next());
    /// assert!(wgsl.lines().count() >= parts.iter().map(|p| p.lines().count()).sum::<usize>());
    /// ```
    pub fn source(&self) -> String {
        self.parts.join("\n")
    }

    /// Compiles the program on `device`.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, layout: &wgpu::PipelineLayout,
    /// #      program: &aokit::shader::ShaderSource) {
    /// // A pipeline of one's own shape (here an entry point not called `main`), where
    /// // `ComputeKernel` does not fit.
    /// let module = program.create_module(device);
    /// let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
    ///     label: Some(program.name),
    ///     layout: Some(layout),
    ///     module: &module,
    ///     entry_point: Some("reduce_rows"),
    ///     compilation_options: Default::default(),
    ///     cache: None,
    /// });
    /// # }
    /// ```
    ///
    /// aokit's own programs ([`ALL`]) are compiled without wgpu's loop bounding: wgpu counts the
    /// iterations of every loop and leaves it after 2^64 in case it would never end (an endless
    /// loop is undefined behaviour to the drivers' compilers), and on an H100 that counter costs
    /// the method kernels 6 to 9% of their time (docs/notes/performance-investigations.md, "Loop
    /// bounding"). Every other program, one's own included, keeps all of wgpu's checks.
    pub fn create_module(&self, device: &wgpu::Device) -> wgpu::ShaderModule {
        let descriptor = wgpu::ShaderModuleDescriptor {
            label: Some(self.name),
            source: wgpu::ShaderSource::Wgsl(self.source().into()),
        };
        if !self.is_own() {
            return device.create_shader_module(descriptor);
        }
        let checks = wgpu::ShaderRuntimeChecks {
            force_loop_bounding: false,
            ..wgpu::ShaderRuntimeChecks::checked()
        };
        // SAFETY: bounds checks stay on, and every loop of aokit's programs ends: each counts up
        // or down by a fixed step to a bound that is a constant, a texture's size, or a count
        // the settings' validation keeps finite, or shifts or divides an integer down to 0.
        unsafe { device.create_shader_module_trusted(descriptor, checks) }
    }

    /// Whether this is one of aokit's programs, text for text.
    fn is_own(&self) -> bool {
        ALL.iter()
            .any(|own| own.name == self.name && own.parts == self.parts)
    }

    /// The `@workgroup_size` of the program's compute entry point `main`, from parsing it.
    ///
    /// ```
    /// use aokit::shader;
    /// // Workgroups to dispatch for one thread per pixel of a 1920x1080 image, the last row
    /// // partly outside.
    /// let [x, y, _] = shader::GTAO.workgroup_size()?;
    /// assert_eq!([1920u32.div_ceil(x), 1080u32.div_ceil(y)], [120, 68]);
    /// // The spatial filter's horizontal pass runs along rows, 64 pixels a workgroup.
    /// assert_eq!(shader::SPATIAL_FILTER_HORIZONTAL[0].workgroup_size()?, [64, 1, 1]);
    /// # Ok::<(), String>(())
    /// ```
    pub fn workgroup_size(&self) -> Result<[u32; 3], String> {
        self.parse(&self.source())?
            .entry_points
            .iter()
            .find(|e| e.name == "main" && e.stage == naga::ShaderStage::Compute)
            .map(|e| e.workgroup_size)
            .ok_or_else(|| format!("{}: no compute entry point `main`", self.name))
    }

    /// The side of the square block of pixels each thread of `main` covers: the program's
    /// `const TEXELS_PER_THREAD: u32`, or 1 where it declares none. A dispatch covers the image
    /// with workgroup size times this many pixels a workgroup.
    ///
    /// ```
    /// use aokit::shader;
    /// // The linear depth pass converts 2x2 pixels a thread, the kernels one.
    /// assert_eq!(shader::LINEAR_DEPTH[0].texels_per_thread()?, 2);
    /// assert_eq!(shader::GTAO.texels_per_thread()?, 1);
    /// # Ok::<(), String>(())
    /// ```
    pub fn texels_per_thread(&self) -> Result<u32, String> {
        let module = self.parse(&self.source())?;
        let Some((_, constant)) = module
            .constants
            .iter()
            .find(|(_, c)| c.name.as_deref() == Some("TEXELS_PER_THREAD"))
        else {
            return Ok(1);
        };
        match module.global_expressions[constant.init] {
            naga::Expression::Literal(naga::Literal::U32(n)) if n > 0 => Ok(n),
            _ => Err(format!(
                "{}: TEXELS_PER_THREAD must be a positive u32 literal",
                self.name
            )),
        }
    }

    /// Parses and validates the program with naga, as wgpu does, without a device. Returns the
    /// module so tests can inspect it (e.g. struct layouts).
    ///
    /// ```
    /// use aokit::shader::{self, ShaderSource};
    /// // Every program the library compiles validates without a device...
    /// for program in shader::ALL {
    ///     program.validate()?;
    /// }
    /// // ...while one's own error names the program and quotes the offending line.
    /// const WRONG_ARGUMENT: ShaderSource = ShaderSource {
    ///     name: "wrong_argument",
    ///     parts: &[shader::ENCODING, "fn f() -> u32 { return pack_oct32(vec2<f32>(0.0)); }"],
    /// };
    /// let err = WRONG_ARGUMENT.validate().unwrap_err();
    /// assert!(err.starts_with("wrong_argument: ") && err.contains("pack_oct32"), "{err}");
    /// # Ok::<(), String>(())
    /// ```
    pub fn validate(&self) -> Result<naga::Module, String> {
        let source = self.source();
        let module = self.parse(&source)?;
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .map_err(|e| format!("{}: {}", self.name, e.emit_to_string(&source)))?;
        Ok(module)
    }

    /// `source`, this program's text, parsed by naga's WGSL front end.
    fn parse(&self, source: &str) -> Result<naga::Module, String> {
        naga::front::wgsl::parse_str(source)
            .map_err(|e| format!("{}: {}", self.name, e.emit_to_string(source)))
    }
}

/// Byte offsets and size of a WGSL struct as naga lays it out.
fn struct_layout(module: &naga::Module, name: &str) -> Option<(Vec<(String, usize)>, usize)> {
    module.types.iter().find_map(|(_, ty)| match &ty.inner {
        naga::TypeInner::Struct { members, span } if ty.name.as_deref() == Some(name) => Some((
            members
                .iter()
                .map(|m| (m.name.clone().unwrap_or_default(), m.offset as usize))
                .collect(),
            *span as usize,
        )),
        _ => None,
    })
}

/// The value of the WGSL constant `name` of type `u32`, for tests that prove codes shared
/// between Rust and WGSL agree.
///
/// ```
/// use aokit::{NormalEncoding, shader};
/// // The `ENCODING_*` constants of the WGSL snippet match the Rust codes.
/// let module = shader::DECODE_NORMALS_UINT.validate()?;
/// for encoding in NormalEncoding::ALL {
///     let name = format!("ENCODING_{}", encoding.name().to_uppercase());
///     assert_eq!(shader::u32_constant(&module, &name), Some(encoding.shader_code()), "{name}");
/// }
/// assert_eq!(shader::u32_constant(&module, "NO_SUCH_CONSTANT"), None);
/// # Ok::<(), String>(())
/// ```
pub fn u32_constant(module: &naga::Module, name: &str) -> Option<u32> {
    let (_, constant) = module
        .constants
        .iter()
        .find(|(_, c)| c.name.as_deref() == Some(name))?;
    match module.global_expressions[constant.init] {
        naga::Expression::Literal(naga::Literal::U32(value)) => Some(value),
        _ => None,
    }
}

/// Checks that the WGSL struct `name` in `source` has exactly the members, offsets and size of
/// its Rust mirror, listed with [`field_offsets!`](crate::field_offsets).
///
/// ```
/// #[repr(C)]
/// struct ViewUniformsMirror { size: [f32; 2] }
/// let err = aokit::shader::check_layout(
///     &aokit::shader::LINEAR_DEPTH[0],
///     "ViewUniforms",
///     aokit::field_offsets!(ViewUniformsMirror { size }),
///     std::mem::size_of::<ViewUniformsMirror>(),
/// );
/// assert!(err.is_err()); // the real struct has more members
/// ```
pub fn check_layout(
    source: &ShaderSource,
    name: &str,
    rust_members: &[(&str, usize)],
    rust_size: usize,
) -> Result<(), String> {
    let module = source.validate()?;
    let (members, size) = struct_layout(&module, name)
        .ok_or_else(|| format!("struct {name} not found in {}", source.name))?;
    let wgsl: Vec<(&str, usize)> = members.iter().map(|(n, o)| (n.as_str(), *o)).collect();
    if wgsl != rust_members {
        return Err(format!(
            "{name}: members differ between WGSL {wgsl:?} and Rust {rust_members:?}"
        ));
    }
    if size != rust_size {
        return Err(format!(
            "{name}: WGSL size {size} but Rust size {rust_size}"
        ));
    }
    Ok(())
}

/// `[(name, offset)]` of a `#[repr(C)]` struct's fields, for [`check_layout`].
///
/// ```
/// #[repr(C)]
/// struct Pair { a: f32, b: [f32; 2] }
/// assert_eq!(aokit::field_offsets!(Pair { a, b }), &[("a", 0), ("b", 4)]);
/// ```
#[macro_export]
macro_rules! field_offsets {
    ($ty:ty { $($field:ident),* $(,)? }) => {
        &[$((stringify!($field), ::core::mem::offset_of!($ty, $field))),*]
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shader_validates_with_naga() {
        for shader in ALL {
            shader.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }

    #[test]
    fn only_aokits_own_programs_skip_loop_bounding() {
        assert!(ALL.iter().all(ShaderSource::is_own));
        for program in [GTAO, method(Method::Vbao), SPATIAL_FILTER_HORIZONTAL[0]] {
            assert!(program.is_own(), "{}", program.name);
        }
        // A program of one's own under an aokit name, or aokit's parts with one more, is
        // compiled with every check.
        let renamed = ShaderSource {
            name: "gtao",
            parts: &[VIEW, "fn f() { loop {} }"],
        };
        let extended = ShaderSource {
            name: "gtao",
            parts: &[VIEW, ENCODING, NOISE, AO, AO_ENTRY, SLICE, "fn g() {}"],
        };
        assert!(!renamed.is_own() && !extended.is_own());
    }
}
