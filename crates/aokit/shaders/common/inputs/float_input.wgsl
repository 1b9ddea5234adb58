// Binding 1 of a program reading depth, and of `apply_mask` with a mask texture: the first
// channel of a single-sampled float texture. Hardware depth is bound as an unfilterable float
// texture too (WebGPU allows it), so one binding serves both kinds of depth.
@group(0) @binding(1) var input_texture: texture_2d<f32>;
fn load_input(pixel: vec2<u32>) -> f32 {
    return textureLoad(input_texture, pixel, 0).r;
}
fn input_size() -> vec2<u32> {
    return textureDimensions(input_texture);
}
