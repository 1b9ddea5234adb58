// One level of SAO's depth MIP chain from the level below: the rotated-grid subsample of
// McGuire, Mara and Luebke 2012 (section 2.2). Each texel keeps ONE of its 2x2 children, the
// one at offset (y & 1, x & 1), so the kept child alternates between the two diagonals in a
// checkerboard: every level holds depths of real surfaces (an average across an edge would
// invent a surface between them), spread evenly rather than always from the same corner.

@group(0) @binding(0) var finer: texture_2d<f32>;
@group(0) @binding(1) var coarser: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(coarser)) {
        return;
    }
    // An odd side has no child past the last texel below: the last one stands in.
    let child = min(2u * id.xy + vec2<u32>(id.y & 1u, id.x & 1u), textureDimensions(finer) - 1u);
    textureStore(coarser, id.xy, textureLoad(finer, child, 0));
}
