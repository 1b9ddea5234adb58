// requires: common/view.wgsl
// Spatial filter, guided kind: He, Sun and Tang's guided filter ("Guided Image Filtering", ECCV
// 2010; TPAMI 35(6), 2013) of the AO `p` with a guide `I` made from linear depth
// (docs/denoise.md). A program is this file plus one pass file, run in this order:
//
// 1. guided_filter_coefficients.wgsl: in the window w_k of (2 radius + 1)^2 pixels around every
//    pixel k, the least-squares line p ~ a_k I + b_k with the paper's penalty epsilon a_k^2:
//        a_k = cov_k(I, p) / (var_k(I) + epsilon),    b_k = mean_k(p) - a_k mean_k(I)
// 2. guided_filter_output.wgsl: every pixel i averages the lines of the windows that hold it,
//    evaluated at its own guide:
//        q_i = mean_{k : i in w_k}(a_k I_i + b_k) = mean(a) I_i + mean(b)
//
// The guide is I = ln(linear depth). A difference of log depths is a relative depth difference
// (ln(d / d0) ~ (d - d0) / d0), so the variance that epsilon is compared with means the same at
// any distance and in any scene unit, as the bilateral kind's `|d - d0| / d0` does. Depth itself
// would make one epsilon smooth across far steps and stop at near slopes; depth relative to each
// pixel's centre cannot be used, since step 2 mixes windows whose centres differ, and the
// guide must be one image for the lines of different windows to agree about I_i.
//
// A window's line is the same line whatever origin I is measured from, so pass 1 measures it
// from the window's centre k: it sums g = ln(d / d_k) and stores the slope a_k and the line's
// value at the centre, c_k = a_k I_k + b_k; pass 2 evaluates a_k ln(d_i / d_k) + c_k. The sums
// then hold small numbers, and var = mean(g^2) - mean(g)^2 keeps its digits in f32, where
// mean(I^2) - mean(I)^2 of log depths near 9 (depths in millimetres) would cancel most of them.
//
// Pixels without a surface (sky, NO_SURFACE depth) and pixels outside the image belong to no
// window: the sums run over surface pixels only, and only windows centred on a surface pixel
// are averaged. So sky never leaks into surfaces; sky pixels keep AO 1. The centre of each
// window is a surface pixel, so no count is 0; epsilon > 0, so no division by 0; a fitted line
// can leave [0, 1] at the ends of its window's depth range, so the output is clamped.

struct GuidedUniforms {
    // Regularisation, in squared log depth (> 0).
    epsilon: f32,
}

@group(0) @binding(1) var<uniform> guided: GuidedUniforms;

// `MAX_SPATIAL_RADIUS` in Rust (a test compares them).
const MAX_RADIUS: u32 = 8u;

// Window radius in pixels, 1 to MAX_RADIUS: fixed per pipeline, as the loops' bound (why:
// resample.wgsl's header; here lavapipe compiled both passes afresh every frame while it was a
// uniform).
override RADIUS: u32;

// Workgroups of GROUP x GROUP threads, one per pixel. Both passes read every texel of the
// workgroup's block and `radius` more on each side: staged once in workgroup memory, each
// texel is loaded once per workgroup instead of once per tap ((16 + 2 radius)^2 / 256 loads
// per pixel against (2 radius + 1)^2). 16 rather than 8: on an H100 each pass took half the
// time (docs/notes/performance-investigations.md), the staging and its barrier being paid per
// workgroup.
const GROUP: u32 = 16u;
const TILE: u32 = GROUP + 2u * MAX_RADIUS;

// Side of the staged tile at the current radius.
fn tile_side() -> u32 {
    return GROUP + 2u * RADIUS;
}

@group(0) @binding(3) var depth_in: texture_2d<f32>;

// Per staged texel: 1 where there is a surface (else 0, and the rest 0 too), ln(depth), and the
// pass's two values there (`load_values`).
var<workgroup> tile: array<vec4<f32>, TILE * TILE>;

// Stages workgroup `group`'s block and `radius` texels around it, the thread of index `index`
// taking every 64th texel, and waits for the whole tile.
fn stage_tile(group: vec2<u32>, index: u32) {
    let side = tile_side();
    let origin = vec2<i32>(group * GROUP) - vec2<i32>(i32(RADIUS));
    for (var i = index; i < side * side; i += GROUP * GROUP) {
        let pixel = origin + vec2<i32>(i32(i % side), i32(i / side));
        var texel = vec4<f32>(0.0);
        if all(pixel >= vec2<i32>(0)) && all(pixel < vec2<i32>(view.size)) {
            let depth = textureLoad(depth_in, pixel, 0).r;
            if depth != NO_SURFACE {
                texel = vec4<f32>(1.0, log(depth), load_values(pixel));
            }
        }
        tile[i] = texel;
    }
    workgroupBarrier();
}

// Tile index of the texel `offset` (0 to 2 radius on each axis) from the top-left of the window
// of the thread at `local` in its workgroup.
fn tile_index(local: vec2<u32>, offset: vec2<u32>) -> u32 {
    let texel = local + offset;
    return texel.y * tile_side() + texel.x;
}
