// requires: common/ao.wgsl
// Where the texels of the subsampled depth MIP chain come from (depth_mips.wgsl's subsample,
// which SAO and msvo read): each level keeps, of the 2x2 texels below each of its texels, the
// one at offset (y & 1, x & 1), clamped to that level.

// Coarsest level the chain holds (`LEVELS` - 1 in passes/kernel/depth_mips.rs).
const CHAIN_COARSEST: u32 = 4u;

// The level-0 texel whose depth texel `t` of `level` (at most CHAIN_COARSEST) holds.
//
// The loop runs CHAIN_COARSEST times and skips the levels above `level`, a trip count the
// driver knows. Looping to `level` itself, which differs from tap to tap in SAO, took SAO
// `high`'s kernel about twice as long on an H100 once wgpu's loop bounding was off
// (docs/notes/performance-investigations.md, "Loop bounding"). Level 0 returns before the
// loop: msvo's level-0 pass, which never enters it, then takes 0.84 to 0.86 of the time.
fn subsample_source(t: vec2<u32>, level: u32) -> vec2<u32> {
    if level == 0u {
        return t;
    }
    var texel = t;
    for (var l = CHAIN_COARSEST; l > 0u; l--) {
        if l <= level {
            let below = textureDimensions(linear_depth, l - 1u);
            texel = min(2u * texel + vec2<u32>(texel.y & 1u, texel.x & 1u), below - 1u);
        }
    }
    return texel;
}
