// requires: common/view.wgsl, common/encoding.wgsl, resample/resample.wgsl
// requires: common/depth_from_ndc.wgsl | common/depth_from_linear.wgsl
// Depth-aware upsample (resample.wgsl): each full-resolution pixel combines the 2x2 working
// texels around its centre. A texel shows the pixel's surface when its depth d_k is within
// `threshold` of the pixel's depth d relative to d: |d_k - d| / d < threshold. With the bilinear
// weights b_k of the pixel's centre among the four texel centres:
//
//     bilateral:           w_k = same_k
//     bilateral-bilinear:  w_k = same_k * b_k
//     nearest-depth:       w_k = b_k if all four are the same surface, else 0
//
// and where every w_k is 0 (an edge for nearest-depth; a surface no texel kept, such as a pole
// thinner than a block, for the others) the one texel of smallest |d_k - d| / d alone. The AO is
// sum w_k a_k / sum w_k; the bent normals, when asked for, are combined with the same weights
// and renormalised. Pixels without a surface get AO 1; so do pixels whose four texels show none
// (nothing was sampled there), with their own normal as bent normal, as the kernels treat a
// pixel with nothing to sample.

struct UpsampleUniforms {
    // Relative depth difference below which a working texel shows the pixel's surface.
    threshold: f32,
}

// The program starts with the input's depth at binding 1 and `input_linear_depth` (one per
// kind of depth input, `DepthInput` in passes/input/linear_depth.rs), as the downsample's.
@group(0) @binding(2) var<uniform> upsample: UpsampleUniforms;
// Full-resolution oct32 normals, read only for bent normals.
@group(0) @binding(3) var normals_full: texture_2d<u32>;
@group(0) @binding(4) var depth_working: texture_2d<f32>;
@group(0) @binding(5) var ao_in: texture_2d<f32>;
// View-space bent normal in xyz and AO in w (1x1 when unused).
@group(0) @binding(6) var bent_in: texture_2d<f32>;
@group(0) @binding(7) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(8) var bent_out: texture_storage_2d<rgba16float, write>;
// Gathers the working texels; clamping repeats the edge texels, as clamped loads would.
@group(0) @binding(9) var point_clamp: sampler;
// The linear depth at full resolution, written where no pass before wrote it (1x1 otherwise).
@group(0) @binding(10) var linear_out: texture_storage_2d<r32float, write>;

// An UPSAMPLE_* code: how a pixel combines the working texels around it.
override MODE: u32;
// Upsample the bent normals too.
override BENT_NORMALS: bool;
// Write the full-resolution linear depth to linear_out: the frame had no linear depth pass.
override WRITE_LINEAR_DEPTH: bool;

fn store(pixel: vec2<u32>, ao: f32, bent: vec4<f32>) {
    textureStore(ao_out, pixel, vec4<f32>(ao, 0.0, 0.0, 0.0));
    if BENT_NORMALS {
        textureStore(bent_out, pixel, bent);
    }
}

// The 2x2 working texels around a block's pixels, in the order left-top, right-top,
// left-bottom, right-bottom; `corner` is the left-top one, which may lie one texel outside.
struct Texels {
    corner: vec2<f32>,
    depths: vec4<f32>,
    aos: vec4<f32>,
    bent: array<vec4<f32>, 4>,
}

fn upsample_pixel(pixel: vec2<u32>, texels: Texels) {
    let depth = input_linear_depth(pixel);
    if WRITE_LINEAR_DEPTH {
        textureStore(linear_out, pixel, vec4<f32>(depth, 0.0, 0.0, 0.0));
    }
    if depth == NO_SURFACE {
        store(pixel, 1.0, vec4<f32>(0.0, 0.0, 0.0, 1.0));
        return;
    }
    // The pixel's centre on the working grid, whose texel centres lie at integers + 0.5.
    let f = (vec2<f32>(pixel) + 0.5) / f32(SCALE) - 0.5 - texels.corner;
    // No surface never matches: |0 - d| / d = 1 would pass a threshold of 1 or more.
    let none = texels.depths == vec4<f32>(NO_SURFACE);
    let distance = select(abs(texels.depths - depth) / depth, vec4<f32>(MAX_DEPTH), none);
    let bilinear = vec4<f32>((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    if all(distance == vec4<f32>(MAX_DEPTH)) {
        let normal = unpack_oct32(textureLoad(normals_full, pixel, 0).r);
        store(pixel, 1.0, vec4<f32>(normal, 1.0));
        return;
    }
    let same = distance < vec4<f32>(upsample.threshold);
    var weights: vec4<f32>;
    switch MODE {
        case UPSAMPLE_BILATERAL: {
            weights = select(vec4<f32>(0.0), vec4<f32>(1.0), same);
        }
        case UPSAMPLE_BILATERAL_BILINEAR: {
            weights = select(vec4<f32>(0.0), bilinear, same);
        }
        default: {
            weights = select(vec4<f32>(0.0), bilinear, all(same));
        }
    }
    if dot(weights, vec4<f32>(1.0)) == 0.0 {
        var nearest = 0;
        for (var k = 1; k < 4; k++) {
            if distance[k] < distance[nearest] {
                nearest = k;
            }
        }
        weights = vec4<f32>(0.0);
        weights[nearest] = 1.0;
    }
    let total = dot(weights, vec4<f32>(1.0));
    // Offsets from one contributing texel's AO are summed rather than the AO itself, so that
    // equal AO comes out exactly equal instead of rounded through the weighted sum.
    var base = 0.0;
    for (var k = 3; k >= 0; k--) {
        if weights[k] > 0.0 {
            base = texels.aos[k];
        }
    }
    let ao = base + dot(weights, texels.aos - base) / total;
    var bent = vec4<f32>(0.0);
    if BENT_NORMALS {
        for (var k = 0; k < 4; k++) {
            bent += weights[k] * texels.bent[k];
        }
        let b = bent.xyz;
        bent = vec4<f32>(select(b, normalize(b), dot(b, b) > 1e-12), bent.w / total);
    }
    store(pixel, ao, bent);
}

// The 2x2 working texels that the pixels of block `block` combine: the pixels whose centres lie
// between the centres of texels `block - 1` and `block` along each axis (SCALE x SCALE of them).
// Blocks of the first row and column reach one texel before the image, clamped to its edge, as
// the last ones reach past it.
fn block_texels(block: vec2<u32>) -> Texels {
    var texels: Texels;
    texels.corner = vec2<f32>(block) - 1.0;
    // Gathered at the texels' shared corner, two fetches where loads took eight (on an H100 the
    // pass took 0.60 to 0.68 of its time with loads, with identical output). Gather order is
    // (left, bottom), (right, bottom), (right, top), (left, top), "top" the smaller row, and
    // .wzxy puts them in Texels' order. The corner lies half a texel from any rounding
    // boundary, so the footprint is exactly the texels it names.
    let uv = vec2<f32>(block) / vec2<f32>(textureDimensions(depth_working));
    texels.depths = textureGather(0, depth_working, point_clamp, uv).wzxy;
    texels.aos = textureGather(0, ao_in, point_clamp, uv).wzxy;
    if BENT_NORMALS {
        let last = vec2<i32>(textureDimensions(depth_working)) - 1;
        for (var k = 0; k < 4; k++) {
            let texel = clamp(vec2<i32>(texels.corner) + vec2<i32>(k & 1, k >> 1u), vec2<i32>(0), last);
            texels.bent[k] = textureLoad(bent_in, texel, 0);
        }
    }
    return texels;
}

// One invocation per pixel. One per block, fetching the block's texels once for all its
// pixels, took a fifth off the pass on lavapipe but made it 1.6 (half resolution) to 3.5
// (quarter, 3840x2160) times as long on an H100: a quarter or a sixteenth as many invocations
// to hide the latency, and each one's stores SCALE pixels apart
// (docs/notes/performance-investigations.md).
@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    upsample_pixel(id.xy, block_texels((id.xy + SCALE / 2u) / SCALE));
}
