// requires: common/ao.wgsl
// What msvo's two passes share (msvo_obscurance.wgsl, msvo_merge.wgsl): each runs once per level
// of the depth MIP chain and finds its level from the texture it writes.

// The chain level whose texture `ao_out` is (passes/kernel/msvo.rs keeps one per level): the one of
// the same size (the chain's levels all differ in size, its level count stops before two would
// not).
fn output_level() -> u32 {
    let size = textureDimensions(ao_out);
    for (var level = 1u; level < textureNumLevels(linear_depth); level++) {
        if all(textureDimensions(linear_depth, level) == size) {
            return level;
        }
    }
    return 0u;
}
