// One level of a depth MIP chain from the level below, by the reduction the `REDUCTION` override
// names (passes/depth_mips.rs, `DepthReduction`, mirrors the codes):
//
// - SUBSAMPLE (`sao`): the rotated-grid subsample of McGuire, Mara and Luebke 2012 (section
//   2.2). Each texel keeps ONE of its 2x2 children, the one at offset (y & 1, x & 1), so the
//   kept child alternates between the two diagonals in a checkerboard: every level holds depths
//   of real surfaces (an average across an edge would invent a surface between them), spread
//   evenly rather than always from the same corner.
// - FURTHEST (`ue4-ssao`): the largest linear depth of the 2x2 children, a hierarchical Z
//   buffer like the one Unreal's SSAO reads (`GetHZBDepth`, seed 002). Each texel of level k
//   then holds the furthest depth of its 2^k x 2^k block of level 0; ue4_ssao.wgsl says why
//   furthest rather than nearest. NO_SURFACE is 0, below every surface, so a block with any
//   surface keeps one.

const REDUCTION_SUBSAMPLE: u32 = 0u;
const REDUCTION_FURTHEST: u32 = 1u;
override REDUCTION: u32;

@group(0) @binding(0) var finer: texture_2d<f32>;
@group(0) @binding(1) var coarser: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(coarser)) {
        return;
    }
    // An odd side has no child past the last texel below: the last one stands in.
    let last = textureDimensions(finer) - 1u;
    if REDUCTION == REDUCTION_SUBSAMPLE {
        let child = min(2u * id.xy + vec2<u32>(id.y & 1u, id.x & 1u), last);
        textureStore(coarser, id.xy, textureLoad(finer, child, 0));
        return;
    }
    var furthest = 0.0;
    for (var dy = 0u; dy < 2u; dy++) {
        for (var dx = 0u; dx < 2u; dx++) {
            let child = min(2u * id.xy + vec2<u32>(dx, dy), last);
            furthest = max(furthest, textureLoad(finer, child, 0).r);
        }
    }
    textureStore(coarser, id.xy, vec4<f32>(furthest, 0.0, 0.0, 0.0));
}
