// requires: common/view.wgsl, common/encoding.wgsl, filter/bilateral_weights.wgsl
// requires: common/ao_and_depth.wgsl
// Spatial filter, `edges` kind: one pass of a 3x3 edge-aware blur (docs/denoise.md), the shape
// of XeGTAO's denoiser (Strugar 2021, https://github.com/GameTechDev/XeGTAO): where the
// bilateral kind spends two passes and a workgroup tile on a 7-tap line each way, this reads
// the 3x3 neighbourhood straight from the textures, nine texels a pixel, with no barrier. Each
// neighbour `k` pixels away (k^2 = 1 or 2) whose relative depth difference from the centre is
// `r` weighs
//
//     w = exp(-k^2 / (2 sigma^2)) * exp(-r^2 / (2 depth_sigma^2))     (gaussian)
//     w = exp(-k^2 / (2 sigma^2)) * (r < depth_sigma)                  (threshold)
//
// with the bilateral kind's settings; the centre weighs 1. When normal_power is above 0, the
// four neighbours sharing an edge also weigh max(0, n . n0)^normal_power, how far each faces the
// centre's way; the diagonal ones do not, so two gathers bring every normal read (edge_facings).
// Pixels without a surface, and texels outside the image, never contribute; a pixel without a
// surface keeps AO 1. With PACKED_INPUT the AO and depth come from the one texture the kernel
// packed them into (common/ao_and_depth.wgsl) instead of ao_in and linear_depth.

@group(0) @binding(2) var ao_in: texture_2d<f32>;
@group(0) @binding(3) var linear_depth: texture_2d<f32>;
@group(0) @binding(4) var normals: texture_2d<u32>;
@group(0) @binding(5) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(6) var point_clamp: sampler;
// With PACKED_INPUT, the kernel's AO and depth packed; a 1x1 stand-in otherwise, never read.
@group(0) @binding(7) var ao_and_depth: texture_2d<u32>;
override PACKED_INPUT: bool = false;

// The 3x3 neighbourhoods are read in four gathers each, at the corners the centre texel shares
// with its neighbours, rather than nine loads (XeGTAO's denoiser gathers too). A gather at the
// corner `corner` (in pixels) returns x = (left, bottom), y = (right, bottom), z = (right,
// top), w = (left, top) of the 2x2 texels around it; the taps come out row by row from the top
// left. Texels outside the image read as the edge (the sampler clamps); their weight drops them.
fn gather_3x3(t: texture_2d<f32>, corner: vec2<f32>) -> array<f32, 9> {
    return taps_3x3(textureGather(0, t, point_clamp, gather_at(corner, 0.0, 0.0)),
                    textureGather(0, t, point_clamp, gather_at(corner, 1.0, 0.0)),
                    textureGather(0, t, point_clamp, gather_at(corner, 0.0, 1.0)),
                    textureGather(0, t, point_clamp, gather_at(corner, 1.0, 1.0)));
}

// The texture coordinates of the gather at `corner` plus (x, y) pixels.
fn gather_at(corner: vec2<f32>, x: f32, y: f32) -> vec2<f32> {
    return (corner + vec2<f32>(x, y)) * view.inv_size;
}

// The nine taps, row by row from the top left, of the gathers at the corner (a), one pixel
// right of it (b), one below (c) and both (d).
fn taps_3x3(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>, d: vec4<f32>) -> array<f32, 9> {
    return array<f32, 9>(a.w, a.z, b.z, a.x, a.y, b.y, c.x, c.y, d.y);
}

// The 3x3 neighbourhood's AO and depth.
struct Neighbourhood {
    ao: array<f32, 9>,
    depth: array<f32, 9>,
}

// gather_3x3 of AO and depth at once from their packed texture (PACKED_INPUT).
fn gather_packed_3x3(corner: vec2<f32>) -> Neighbourhood {
    let a = textureGather(0, ao_and_depth, point_clamp, gather_at(corner, 0.0, 0.0));
    let b = textureGather(0, ao_and_depth, point_clamp, gather_at(corner, 1.0, 0.0));
    let c = textureGather(0, ao_and_depth, point_clamp, gather_at(corner, 0.0, 1.0));
    let d = textureGather(0, ao_and_depth, point_clamp, gather_at(corner, 1.0, 1.0));
    return Neighbourhood(
        taps_3x3(unpacked_ao(a), unpacked_ao(b), unpacked_ao(c), unpacked_ao(d)),
        taps_3x3(unpacked_depth(a), unpacked_depth(b), unpacked_depth(c), unpacked_depth(d)));
}

// How far the edge neighbours face the centre's way, max(0, n . n0) of the top, left, right and
// bottom one in x, y, z, w: the oct32 normals of the two gathers at the centre texel's
// top-left and bottom-right corners, which both hold the centre. The diagonals' normals as well
// would take four gathers and nine decodes, for no lower error
// (docs/notes/performance-investigations.md, "The edge filter's inputs").
fn edge_facings(corner: vec2<f32>) -> vec4<f32> {
    let a = textureGather(0, normals, point_clamp, gather_at(corner, 0.0, 0.0));
    let d = textureGather(0, normals, point_clamp, gather_at(corner, 1.0, 1.0));
    let n0 = unpack_oct32(a.y);
    let facing = vec4<f32>(dot(unpack_oct32(a.z), n0), dot(unpack_oct32(a.x), n0),
                           dot(unpack_oct32(d.z), n0), dot(unpack_oct32(d.x), n0));
    return max(facing, vec4<f32>(0.0));
}

// What every tap's weight takes from the centre pixel.
struct Centre {
    pixel: vec2<i32>,
    depth: f32,
    // depth_scale / depth: a relative depth difference in units of depth_sigma.
    relative_scale: f32,
    // The spatial factor of a neighbour sharing an edge; a diagonal one's is its square (k^2 =
    // 2). The same for every pixel, so a tap takes only its depth's (and normal's) exp2.
    edge_weight: f32,
}

// The neighbour `offset` away (depth `d`, AO `ao`, facing the centre's way as far as `facing`
// says; 1 for the centre and the diagonals): its weighted AO and its weight.
fn tap(c: Centre, offset: vec2<i32>, d: f32, ao: f32, facing: f32) -> vec2<f32> {
    let at = c.pixel + offset;
    // 0 at the centre's depth even where relative_scale overflowed to infinity (a denormal
    // depth): 0 * infinity would be NaN.
    let r = select(abs(d - c.depth) * c.relative_scale, 0.0, d == c.depth);
    let spatial_weight =
        select(1.0, c.edge_weight, offset.x != 0) * select(1.0, c.edge_weight, offset.y != 0);
    var log2_w = 0.0;
    var kept = all(at >= vec2<i32>(0)) && all(at < vec2<i32>(view.size)) && d != NO_SURFACE;
    if DEPTH_WEIGHT == DEPTH_THRESHOLD {
        kept = kept && r < 1.0;
    } else {
        log2_w -= 0.5 * LOG2_E * r * r;
    }
    var w = spatial_weight;
    if NORMAL_WEIGHT {
        // A neighbour facing away weighs nothing (log2(0) is left to the implementation).
        kept = kept && facing > 0.0;
        let normal = normal_weight(facing);
        log2_w += normal.log2;
        w *= normal.factor;
    }
    if DEPTH_WEIGHT != DEPTH_THRESHOLD || (NORMAL_WEIGHT && NORMAL_SQUARINGS < 0) {
        w *= exp2(log2_w);
    }
    w = select(0.0, w, kept);
    return vec2<f32>(w * ao, w);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let centre = vec2<i32>(id.xy);
    let corner = vec2<f32>(id.xy);
    var taps: Neighbourhood;
    if PACKED_INPUT {
        taps = gather_packed_3x3(corner);
    } else {
        taps.depth = gather_3x3(linear_depth, corner);
    }
    let depths = taps.depth;
    let depth = depths[4];
    if depth == NO_SURFACE {
        textureStore(ao_out, centre, vec4<f32>(1.0, 0.0, 0.0, 0.0));
        return;
    }
    if !PACKED_INPUT {
        taps.ao = gather_3x3(ao_in, corner);
    }
    let aos = taps.ao;
    // Top, left, right, bottom.
    var f = vec4<f32>(1.0);
    if NORMAL_WEIGHT {
        f = edge_facings(corner);
    }
    let c = Centre(centre, depth, spatial.depth_scale / depth,
                   exp2(-0.5 * LOG2_E * spatial.spatial_scale * spatial.spatial_scale));
    // The nine taps written out, row by row from the top left as gather_3x3 returns them, so
    // that every index into the arrays is a constant: a loop's index is one at run time, which
    // takes a bounds check a read and keeps the arrays in memory (on lavapipe the pass took
    // about three times as long that way).
    let sums = tap(c, vec2<i32>(-1, -1), depths[0], aos[0], 1.0)
        + tap(c, vec2<i32>(0, -1), depths[1], aos[1], f.x)
        + tap(c, vec2<i32>(1, -1), depths[2], aos[2], 1.0)
        + tap(c, vec2<i32>(-1, 0), depths[3], aos[3], f.y)
        + tap(c, vec2<i32>(0, 0), depths[4], aos[4], 1.0)
        + tap(c, vec2<i32>(1, 0), depths[5], aos[5], f.z)
        + tap(c, vec2<i32>(-1, 1), depths[6], aos[6], 1.0)
        + tap(c, vec2<i32>(0, 1), depths[7], aos[7], f.w)
        + tap(c, vec2<i32>(1, 1), depths[8], aos[8], 1.0);
    // Clamped: where a division is a reciprocal and a product (GL on llvmpipe), nine taps of
    // AO 1, which the packed input's rounding makes common, came out at 1 + 1 ulp.
    textureStore(ao_out, centre, vec4<f32>(saturate(sums.x / sums.y), 0.0, 0.0, 0.0));
}
