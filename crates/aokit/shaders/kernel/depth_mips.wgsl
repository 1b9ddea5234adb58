// requires: common/formats/level_r32float.wgsl | common/formats/level_r16float.wgsl
// Levels 1 to 4 of a depth MIP chain from its level 0, in one pass, each texel reducing the 2x2
// texels below it by the reduction the `REDUCTION` override names (passes/kernel/depth_mips.rs,
// `DepthReduction`, mirrors the codes):
//
// - SUBSAMPLE (`sao`, `msvo`): the rotated-grid subsample of McGuire, Mara and Luebke 2012
//   (section 2.2). Each texel keeps ONE of its 2x2 children, the one at offset (y & 1, x & 1),
//   so the kept child alternates between the two diagonals in a checkerboard: every level holds
//   depths of real surfaces (an average across an edge would invent a surface between them),
//   spread evenly rather than always from the same corner.
// - FURTHEST (`ue4-ssao`): the largest linear depth of the 2x2 children, a hierarchical Z
//   buffer like the one Unreal's SSAO reads (`GetHZBDepth`, PostProcessAmbientOcclusion.usf,
//   Epic Games). Each texel of level k
//   then holds the furthest depth of its 2^k x 2^k block of level 0; ue4_ssao.wgsl says why
//   furthest rather than nearest. NO_SURFACE is 0, below every surface, so a block with any
//   surface keeps one.
//
// - MEAN_OR_FURTHEST (`depth_mips`, the chain the marching and point kernels read far samples
//   from): where the four children lie on one surface (the kernels' DEPTH_EDGE test in
//   common/ao.wgsl), their mean in the quantity that is affine on a plane, 1 / depth or depth
//   (orthographic), so that a coarser texel is exact at its centre on a plane; else the
//   furthest, so that a coarse read at an edge keeps the background and does not invent a
//   surface between the two (docs/depth-mips.md measured the four candidate reductions).
//
// The levels go either to a texture's MIP levels 1 to 4 (`level_1` to `level_4`) or, with
// ATLAS, all to `level_1`, stacked one below the other, which lets a kernel gather 2x2 texels
// of any level (WGSL gathers level 0 only). With ATLAS_LEVEL_0 the atlas holds level 0 too,
// at its origin, and the coarser levels in a column to its right (see atlas_origin), so that
// a kernel reads every level from one texture without a branch.
//
// A workgroup reduces one 16x16 block of level 0: each of its 8x8 threads makes a texel of level
// 1, then a quarter of them those of level 2 from level 1's in workgroup memory, and so on to
// level 4, so the chain takes one dispatch instead of one per level. Children are clamped to
// the last texel of their level as a pass per level would read them (an odd side has no child
// past it), which keeps every child inside the workgroup's block: each level is exactly the
// reduction of the level below as stored.

const REDUCTION_SUBSAMPLE: u32 = 0u;
const REDUCTION_FURTHEST: u32 = 1u;
const REDUCTION_MEAN_OR_FURTHEST: u32 = 2u;
override REDUCTION: u32;
// MEAN_OR_FURTHEST: whether depth (orthographic) or 1 / depth (perspective) is affine on a
// plane.
override ORTHOGRAPHIC: bool = false;
// Whether every level goes to `level_1`, stacked, and whether level 0 goes there too (see
// above).
override ATLAS: bool = false;
override ATLAS_LEVEL_0: bool = false;
// common/ao.wgsl's DEPTH_EDGE: the relative spread of one surface.
const ONE_SURFACE: f32 = 0.1;
// Levels past 0 the chain holds, 1 to 4: a small image runs out of texels sooner, and the
// bindings of the levels it lacks hold a stand-in that is never written.
override COARSER_LEVELS: u32;

@group(0) @binding(0) var level_0: texture_2d<f32>;
@group(0) @binding(1) var level_1: LevelTexture;
@group(0) @binding(2) var level_2: LevelTexture;
@group(0) @binding(3) var level_3: LevelTexture;
@group(0) @binding(4) var level_4: LevelTexture;

// This workgroup's texels of levels 1 (8x8), 2 (4x4), 3 (2x2) and 4 (1x1), each level row by
// row from its offset in OFFSETS (indexed by level - 1), so that a level is read while the next
// is written.
const OFFSETS = array<u32, 4>(0u, 64u, 80u, 84u);
var<workgroup> block: array<f32, 85>;

// The texel at `texel` of a coarser level from its children at offsets (0, 0), (1, 0), (0, 1)
// and (1, 1), in that order.
fn reduce(texel: vec2<u32>, children: vec4<f32>) -> f32 {
    if REDUCTION == REDUCTION_SUBSAMPLE {
        return children[(texel.y & 1u) + 2u * (texel.x & 1u)];
    }
    let furthest = max(max(children.x, children.y), max(children.z, children.w));
    let nearest = min(min(children.x, children.y), min(children.z, children.w));
    if REDUCTION == REDUCTION_MEAN_OR_FURTHEST && nearest > 0.0 && furthest <= nearest * (1.0 + ONE_SURFACE) {
        if ORTHOGRAPHIC {
            return dot(children, vec4<f32>(0.25));
        }
        return 1.0 / dot(1.0 / children, vec4<f32>(0.25));
    }
    return furthest;
}

// Child `k` (0 to 3, in reduce's order) of `texel`, clamped to the level below's last texel.
fn child(texel: vec2<u32>, k: u32, last: vec2<u32>) -> vec2<u32> {
    return min(2u * texel + vec2<u32>(k & 1u, k >> 1u), last);
}

// A level's size, as a texture's MIP level has it: halved and rounded down, at least 1.
fn level_size(level: u32) -> vec2<u32> {
    return max(textureDimensions(level_0) >> vec2<u32>(level), vec2<u32>(1u));
}

// With ATLAS, where texel (0, 0) of `level` (1 to 4) lies in `level_1`: right of level 0 with
// ATLAS_LEVEL_0, at row H - (H >> (level - 1)) for a level 0 H texels high. Level k >= 1 is
// H >> k high (at least 2 texels in an atlas), and the rows of consecutive levels differ by
// (H >> (k - 1)) - (H >> k) >= H >> k, so each starts below the one before and a kernel
// finds its row without a loop; the last ends by row H.
fn atlas_origin(level: u32) -> vec2<u32> {
    let size_0 = level_size(0u);
    return vec2<u32>(select(0u, size_0.x, ATLAS_LEVEL_0), size_0.y - (size_0.y >> (level - 1u)));
}

// Stores texel `texel` of `level` (1 to 4) and keeps it in the workgroup's block, where the
// thread at `local` makes it.
fn keep(level: u32, texel: vec2<u32>, local: vec2<u32>, depth: f32) {
    let side = 16u >> level;
    block[OFFSETS[level - 1u] + local.y * side + local.x] = depth;
    if any(texel >= level_size(level)) {
        return;
    }
    let value = vec4<f32>(depth, 0.0, 0.0, 0.0);
    if ATLAS {
        textureStore(level_1, atlas_origin(level) + texel, value);
        return;
    }
    switch level {
        case 1u: { textureStore(level_1, texel, value); }
        case 2u: { textureStore(level_2, texel, value); }
        case 3u: { textureStore(level_3, texel, value); }
        default: { textureStore(level_4, texel, value); }
    }
}

// The texel of `level` (2 to 4) that the thread at `local` of workgroup `group` makes, from the
// block of the level below.
fn next_level(level: u32, group: vec2<u32>, local: vec2<u32>) {
    let side = 16u >> level;
    let texel = group * side + local;
    let last = level_size(level - 1u) - 1u;
    var children: vec4<f32>;
    for (var k = 0u; k < 4u; k++) {
        let at = child(texel, k, last) - group * (2u * side);
        children[k] = block[OFFSETS[level - 2u] + at.y * 2u * side + at.x];
    }
    keep(level, texel, local, reduce(texel, children));
}

@compute @workgroup_size(8, 8)
fn main(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_id) local: vec3<u32>) {
    // Level 1: every thread, from level 0.
    let texel_1 = group.xy * 8u + local.xy;
    var children: vec4<f32>;
    let size_0 = level_size(0u);
    for (var k = 0u; k < 4u; k++) {
        children[k] = textureLoad(level_0, child(texel_1, k, size_0 - 1u), 0).r;
        // The pass runs one thread per 2x2 block of level 0, rounded up, so that an odd last
        // row or column of level 0 is copied too.
        let texel_0 = 2u * texel_1 + vec2<u32>(k & 1u, k >> 1u);
        if ATLAS_LEVEL_0 && all(texel_0 < size_0) {
            textureStore(level_1, texel_0, vec4<f32>(children[k], 0.0, 0.0, 0.0));
        }
    }
    if COARSER_LEVELS == 0u {
        return;
    }
    keep(1u, texel_1, local.xy, reduce(texel_1, children));
    // Levels 2 to 4: 4x4 threads, then 2x2, then one, each from the level below.
    workgroupBarrier();
    if COARSER_LEVELS >= 2u && all(local.xy < vec2<u32>(4u)) {
        next_level(2u, group.xy, local.xy);
    }
    workgroupBarrier();
    if COARSER_LEVELS >= 3u && all(local.xy < vec2<u32>(2u)) {
        next_level(3u, group.xy, local.xy);
    }
    workgroupBarrier();
    if COARSER_LEVELS >= 4u && all(local.xy == vec2<u32>(0u)) {
        next_level(4u, group.xy, local.xy);
    }
}
