// requires: filter/spatial_filter.wgsl
// requires: common/formats/pair_rg32float.wgsl | common/formats/pair_rgba32float.wgsl
// First pass of the spatial filter (spatial_filter.wgsl): along rows, from the method's AO and
// the linear depth to both packed in one texel, so that the vertical pass reads one texture.

const AXIS = vec2<i32>(1, 0);
const ACROSS: u32 = 1u;
const GROUP_WIDTH: u32 = LINE;
const GROUP_HEIGHT: u32 = ACROSS;

@group(0) @binding(3) var ao_in: texture_2d<f32>;
@group(0) @binding(4) var depth_in: texture_2d<f32>;
@group(0) @binding(5) var packed_out: pair_storage;

fn load_ao_depth(pixel: vec2<u32>) -> vec2<f32> {
    return vec2<f32>(textureLoad(ao_in, pixel, 0).r, textureLoad(depth_in, pixel, 0).r);
}

fn store_filtered(pixel: vec2<u32>, ao: f32, depth: f32) {
    textureStore(packed_out, pixel, vec4<f32>(ao, depth, 0.0, 0.0));
}
