// requires: common/view.wgsl, common/encoding.wgsl, filter/bilateral_weights.wgsl
// Spatial filter: a separable bilateral blur of the AO (docs/denoise.md), run as two passes, one
// per axis. A program is this file plus one pass file (spatial_filter_horizontal.wgsl or
// spatial_filter_vertical.wgsl) that sets `AXIS` and the workgroup shape and defines
// `load_ao_depth` and `store_filtered` over its own textures.
//
// Each workgroup filters ACROSS neighbouring segments of LINE pixels along the axis. Its
// threads first load each segment and RADIUS pixels on each side (the apron) into workgroup
// memory, LINE texels at a time, so that each texel is read once per workgroup instead of once
// per tap. Every tap then weighs the neighbour `k` pixels away whose relative depth difference
// from the centre is `r`:
//
//     w = exp(-k^2 / (2 sigma^2)) * exp(-r^2 / (2 depth_sigma^2))     (gaussian)
//     w = exp(-k^2 / (2 sigma^2)) * (r < depth_sigma)                  (threshold)
//
// times max(0, n . n0)^normal_power when that power is above 0. The centre's own weight is 1, so
// the weight sum never vanishes. Pixels without a surface (sky, outside the image) never
// contribute, and keep AO 1.

@group(0) @binding(2) var normals: texture_2d<u32>;

// `MAX_SPATIAL_RADIUS` in Rust (a test compares them).
const MAX_RADIUS: u32 = 8u;

// Kernel radius in pixels, 1 to MAX_RADIUS, fixed per pipeline as the depth and normal weights'
// paths are (bilateral_weights.wgsl).
override RADIUS: u32;

// Threads per workgroup, one per pixel of the segment: two 32-wide or one 64-wide SIMD group,
// and long enough that the apron of a radius-8 kernel adds only 25% more loads (an 8x8 tile
// would load three texels per pixel filtered).
const LINE: u32 = 64u;
const TILE: u32 = LINE + 2u * MAX_RADIUS;

// TILE texels of each segment, interleaved: texel i of segment s at i * ACROSS + s, so that the
// threads of a SIMD group, which span the segments, read neighbouring words.
var<workgroup> tile_ao_depth: array<vec2<f32>, TILE * ACROSS>;
var<workgroup> tile_normal: array<vec3<f32>, TILE * ACROSS>;

// The weight of a neighbour `offset` pixels from the centre whose depth is `depth`, against the
// centre's normal `n0`; `relative_scale` is depth_scale over the centre's depth (> 0).
//
// One exp2 of the summed base-2 logarithms rather than an exp per factor and a pow: a special
// function unit's rate (a quarter or an eighth of the fp32 rate on GPUs) bounds a pass that
// takes 2 * RADIUS + 1 of these per pixel, and the division by the centre's depth is made once.
fn neighbour_weight(offset: f32, depth: f32, centre_depth: f32, relative_scale: f32,
                    n: vec3<f32>, n0: vec3<f32>) -> f32 {
    if depth == NO_SURFACE {
        return 0.0;
    }
    // Both differences in units of their sigma.
    let x = offset * spatial.spatial_scale;
    // The centre itself, and a neighbour at its depth, differ by 0 even where relative_scale
    // overflowed to infinity (a denormal depth): 0 * infinity would be NaN.
    let r = select(abs(depth - centre_depth) * relative_scale, 0.0, depth == centre_depth);
    var log2_w = -0.5 * LOG2_E * x * x;
    var kept = true;
    if DEPTH_WEIGHT == DEPTH_THRESHOLD {
        kept = r < 1.0;
    } else {
        log2_w -= 0.5 * LOG2_E * r * r;
    }
    var factor = 1.0;
    if NORMAL_WEIGHT {
        let facing = max(dot(n, n0), 0.0);
        // A neighbour facing away weighs nothing (log2(0) is left to the implementation).
        kept = kept && facing > 0.0;
        let normal = normal_weight(facing);
        log2_w += normal.log2;
        factor = normal.factor;
    }
    return select(0.0, exp2(log2_w) * factor, kept);
}

@compute @workgroup_size(GROUP_WIDTH, GROUP_HEIGHT)
fn main(
    @builtin(global_invocation_id) id: vec3<u32>,
    @builtin(workgroup_id) group: vec3<u32>,
    @builtin(local_invocation_id) local_id: vec3<u32>,
) {
    let radius = RADIUS;
    // The thread's place along the axis, and its segment.
    let local = dot(local_id.xy, vec2<u32>(AXIS));
    let segment = dot(local_id.xy, vec2<u32>(AXIS.yx));
    let origin = vec2<i32>(group.xy * vec2<u32>(GROUP_WIDTH, GROUP_HEIGHT));
    let first = origin + AXIS.yx * i32(segment) - AXIS * i32(radius);
    for (var i = local; i < LINE + 2u * radius; i += LINE) {
        let pixel = first + AXIS * i32(i);
        var texel = vec2<f32>(1.0, NO_SURFACE);
        var n = vec3<f32>(0.0);
        if all(pixel >= vec2<i32>(0)) && all(pixel < vec2<i32>(view.size)) {
            texel = load_ao_depth(vec2<u32>(pixel));
            if NORMAL_WEIGHT {
                n = unpack_oct32(textureLoad(normals, pixel, 0).r);
            }
        }
        tile_ao_depth[i * ACROSS + segment] = texel;
        tile_normal[i * ACROSS + segment] = n;
    }
    workgroupBarrier();

    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let centre = (local + radius) * ACROSS + segment;
    let depth = tile_ao_depth[centre].y;
    if depth == NO_SURFACE {
        store_filtered(id.xy, 1.0, NO_SURFACE);
        return;
    }
    let n0 = tile_normal[centre];
    let relative_scale = spatial.depth_scale / depth;
    var sum = 0.0;
    var weight_sum = 0.0;
    for (var k = 0u; k <= 2u * radius; k++) {
        let at = (local + k) * ACROSS + segment;
        let offset = f32(k) - f32(radius);
        let w = neighbour_weight(offset, tile_ao_depth[at].y, depth, relative_scale,
                                 tile_normal[at], n0);
        sum += w * tile_ao_depth[at].x;
        weight_sum += w;
    }
    store_filtered(id.xy, sum / weight_sum, depth);
}
