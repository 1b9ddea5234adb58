// requires: common/view.wgsl, resample/resample.wgsl
// requires: common/formats/pair_rg32float.wgsl | common/formats/pair_rgba32float.wgsl
// requires: common/depth_from_ndc.wgsl | common/depth_from_linear.wgsl
// Downsample (resample.wgsl): each working texel takes the linear depth of one input pixel of
// its SCALE x SCALE block, and that pixel's normal and motion, so that depth, normal and
// motion describe one surface point. Which pixel:
//
//     point:         a fixed one, the top-left of the block's central 2x2 (the choice of
//                    ybniaobu's Unity YPipeline)
//     min / max:     the nearest / farthest surface; no surface counts as farthest of all
//     checkerboard:  min where x + y of the working texel is even, max where it is odd
//
// Depths are loaded, never averaged: an average invents surfaces between foreground and
// background at every edge. Blocks past the image's last row or column repeat it.

// The program starts with the input's depth at binding 1 and `input_linear_depth` (one per
// kind of depth input, `DepthInput` in passes/input/linear_depth.rs): the renderer's depth, or the
// linear depth pass's output where that ran at full resolution anyway.
// Full-resolution oct32 normals and motion vectors (1x1 when unused).
@group(0) @binding(2) var normals_in: texture_2d<u32>;
@group(0) @binding(3) var motion_in: texture_2d<f32>;
@group(0) @binding(4) var depth_out: texture_storage_2d<r32float, write>;
@group(0) @binding(5) var normals_out: texture_storage_2d<r32uint, write>;
// In working texels (1x1 when unused).
@group(0) @binding(6) var motion_out: pair_storage;

// A DOWNSAMPLE_* code: which pixel of each block the working texel takes.
override MODE: u32;
// Downsample the motion vectors too (the temporal filter runs at working resolution).
override MOTION_VECTORS: bool;

// Depth ordered with "no surface" (sky) beyond every surface, so that `min` keeps a surface
// whenever the block has one.
fn distance_key(depth: f32) -> f32 {
    return select(depth, MAX_DEPTH, depth == NO_SURFACE);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let last = textureDimensions(normals_in) - 1u;
    let first = id.xy * SCALE;
    var mode = MODE;
    if mode == DOWNSAMPLE_CHECKERBOARD {
        mode = select(DOWNSAMPLE_MIN, DOWNSAMPLE_MAX, ((id.x + id.y) & 1u) == 1u);
    }
    var chosen = point_pixel(id.xy, last);
    if mode != DOWNSAMPLE_POINT {
        var best = distance_key(input_linear_depth(first));
        chosen = first;
        for (var i = 1u; i < SCALE * SCALE; i++) {
            let pixel = min(first + vec2<u32>(i % SCALE, i / SCALE), last);
            let key = distance_key(input_linear_depth(pixel));
            // Strict comparisons: ties keep the first pixel in row order.
            if select(key > best, key < best, mode == DOWNSAMPLE_MIN) {
                best = key;
                chosen = pixel;
            }
        }
    }
    textureStore(depth_out, id.xy, vec4<f32>(input_linear_depth(chosen), 0.0, 0.0, 0.0));
    textureStore(normals_out, id.xy, vec4<u32>(textureLoad(normals_in, chosen, 0).r, 0u, 0u, 0u));
    if MOTION_VECTORS {
        let motion = textureLoad(motion_in, chosen, 0).xy / f32(SCALE);
        textureStore(motion_out, id.xy, vec4<f32>(motion, 0.0, 0.0));
    }
}
