// requires: common/encoding.wgsl
// Binding 1 of `decode_normals` for encodings held in unorm or float texels.
// `ENCODING` is the override of decode_normals.wgsl, which follows.
@group(0) @binding(1) var encoded: texture_2d<f32>;
// The texel's normal, or the zero vector where it holds none (`normal_texel_usable`).
fn load_normal(pixel: vec2<u32>) -> vec3<f32> {
    let texel = textureLoad(encoded, pixel, 0);
    if !normal_texel_usable(texel, ENCODING) {
        return vec3<f32>(0.0);
    }
    return decode_normal_float(texel, ENCODING);
}
