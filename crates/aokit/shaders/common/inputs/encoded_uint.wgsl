// requires: common/encoding.wgsl
// Binding 1 of `decode_normals` for encodings held in `R32Uint` texels.
// `ENCODING` is the override of decode_normals.wgsl, which follows.
@group(0) @binding(1) var encoded: texture_2d<u32>;
// The texel's normal. Every texel of these encodings decodes to a unit vector: they store a
// direction (two coordinates or angles), never the vector itself, so none is unusable.
fn load_normal(pixel: vec2<u32>) -> vec3<f32> {
    return decode_normal_uint(textureLoad(encoded, pixel, 0).r, ENCODING);
}
