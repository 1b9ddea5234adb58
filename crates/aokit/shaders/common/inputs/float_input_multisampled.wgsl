// As float_input.wgsl, multisampled: sample 0 is read.
@group(0) @binding(1) var input_texture: texture_multisampled_2d<f32>;
fn load_input(pixel: vec2<u32>) -> f32 {
    return textureLoad(input_texture, pixel, 0).r;
}
fn input_size() -> vec2<u32> {
    return textureDimensions(input_texture);
}
