// Levels 1 to 4 of a depth MIP chain from its level 0, in one pass, each texel reducing the 2x2
// texels below it by the reduction the `REDUCTION` override names (passes/depth_mips.rs,
// `DepthReduction`, mirrors the codes):
//
// - SUBSAMPLE (`sao`, `msvo`): the rotated-grid subsample of McGuire, Mara and Luebke 2012
//   (section 2.2). Each texel keeps ONE of its 2x2 children, the one at offset (y & 1, x & 1),
//   so the kept child alternates between the two diagonals in a checkerboard: every level holds
//   depths of real surfaces (an average across an edge would invent a surface between them),
//   spread evenly rather than always from the same corner.
// - FURTHEST (`ue4-ssao`): the largest linear depth of the 2x2 children, a hierarchical Z
//   buffer like the one Unreal's SSAO reads (`GetHZBDepth`, seed 002). Each texel of level k
//   then holds the furthest depth of its 2^k x 2^k block of level 0; ue4_ssao.wgsl says why
//   furthest rather than nearest. NO_SURFACE is 0, below every surface, so a block with any
//   surface keeps one.
//
// A workgroup reduces one 16x16 block of level 0: each of its 8x8 threads makes a texel of level
// 1, then a quarter of them those of level 2 from level 1's in workgroup memory, and so on to
// level 4, so the chain takes one dispatch instead of one per level. Children are clamped to
// the last texel of their level as a pass per level would read them (an odd side has no child
// past it), which keeps every child inside the workgroup's block: each level is exactly the
// reduction of the level below as stored.

const REDUCTION_SUBSAMPLE: u32 = 0u;
const REDUCTION_FURTHEST: u32 = 1u;
override REDUCTION: u32;
// Levels past 0 the chain holds, 1 to 4: a small image runs out of texels sooner, and the
// bindings of the levels it lacks hold a stand-in that is never written.
override COARSER_LEVELS: u32;

@group(0) @binding(0) var level_0: texture_2d<f32>;
@group(0) @binding(1) var level_1: texture_storage_2d<r32float, write>;
@group(0) @binding(2) var level_2: texture_storage_2d<r32float, write>;
@group(0) @binding(3) var level_3: texture_storage_2d<r32float, write>;
@group(0) @binding(4) var level_4: texture_storage_2d<r32float, write>;

// This workgroup's texels of levels 1, 2 and 3, row by row.
var<workgroup> block_1: array<f32, 64>;
var<workgroup> block_2: array<f32, 16>;
var<workgroup> block_3: array<f32, 4>;

// The texel at `texel` of a coarser level from its children at offsets (0, 0), (1, 0), (0, 1)
// and (1, 1), in that order.
fn reduce(texel: vec2<u32>, children: vec4<f32>) -> f32 {
    if REDUCTION == REDUCTION_SUBSAMPLE {
        return children[(texel.y & 1u) + 2u * (texel.x & 1u)];
    }
    return max(max(children.x, children.y), max(children.z, children.w));
}

// Child `k` (0 to 3, in reduce's order) of `texel`, clamped to the level below's last texel.
fn child(texel: vec2<u32>, k: u32, last: vec2<u32>) -> vec2<u32> {
    return min(2u * texel + vec2<u32>(k & 1u, k >> 1u), last);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_id) local: vec3<u32>) {
    // Level 1: every thread, from level 0.
    let last_0 = textureDimensions(level_0) - 1u;
    let texel_1 = group.xy * 8u + local.xy;
    var children: vec4<f32>;
    for (var k = 0u; k < 4u; k++) {
        children[k] = textureLoad(level_0, child(texel_1, k, last_0), 0).r;
    }
    let depth_1 = reduce(texel_1, children);
    if all(texel_1 < textureDimensions(level_1)) {
        textureStore(level_1, texel_1, vec4<f32>(depth_1, 0.0, 0.0, 0.0));
    }
    block_1[local.y * 8u + local.x] = depth_1;
    workgroupBarrier();

    // Level 2: 4x4 threads, from level 1's 8x8.
    if COARSER_LEVELS >= 2u && all(local.xy < vec2<u32>(4u)) {
        let last = textureDimensions(level_1) - 1u;
        let texel = group.xy * 4u + local.xy;
        for (var k = 0u; k < 4u; k++) {
            let at = child(texel, k, last) - group.xy * 8u;
            children[k] = block_1[at.y * 8u + at.x];
        }
        let depth = reduce(texel, children);
        if all(texel < textureDimensions(level_2)) {
            textureStore(level_2, texel, vec4<f32>(depth, 0.0, 0.0, 0.0));
        }
        block_2[local.y * 4u + local.x] = depth;
    }
    workgroupBarrier();

    // Level 3: 2x2 threads, from level 2's 4x4.
    if COARSER_LEVELS >= 3u && all(local.xy < vec2<u32>(2u)) {
        let last = textureDimensions(level_2) - 1u;
        let texel = group.xy * 2u + local.xy;
        for (var k = 0u; k < 4u; k++) {
            let at = child(texel, k, last) - group.xy * 4u;
            children[k] = block_2[at.y * 4u + at.x];
        }
        let depth = reduce(texel, children);
        if all(texel < textureDimensions(level_3)) {
            textureStore(level_3, texel, vec4<f32>(depth, 0.0, 0.0, 0.0));
        }
        block_3[local.y * 2u + local.x] = depth;
    }
    workgroupBarrier();

    // Level 4: one thread, from level 3's 2x2.
    if COARSER_LEVELS >= 4u && all(local.xy == vec2<u32>(0u)) {
        let last = textureDimensions(level_3) - 1u;
        let texel = group.xy;
        for (var k = 0u; k < 4u; k++) {
            let at = child(texel, k, last) - group.xy * 2u;
            children[k] = block_3[at.y * 2u + at.x];
        }
        if all(texel < textureDimensions(level_4)) {
            textureStore(level_4, texel, vec4<f32>(reduce(texel, children), 0.0, 0.0, 0.0));
        }
    }
}
