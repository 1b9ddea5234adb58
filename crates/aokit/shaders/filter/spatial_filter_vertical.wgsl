// requires: filter/spatial_filter.wgsl
// requires: common/formats/pair_rg32float.wgsl | common/formats/pair_rgba32float.wgsl
// Second pass of the spatial filter (spatial_filter.wgsl): along columns, from the horizontal
// pass's packed AO and depth to the filtered AO, or with PACKED_OUTPUT to the filtered AO and
// the depth packed again, for the temporal filter after it (temporal_filter.wgsl, PACKED_INPUT).

const AXIS = vec2<i32>(0, 1);
// Four columns side by side: a SIMD group then reads rows of four neighbouring texels, where
// one column alone read a single texel from each of 32 rows.
const ACROSS: u32 = 4u;
const GROUP_WIDTH: u32 = ACROSS;
const GROUP_HEIGHT: u32 = LINE;

// Write (AO, depth) to packed_out rather than AO to ao_out; the other is a 1x1 stand-in.
override PACKED_OUTPUT: bool;

@group(0) @binding(3) var packed_in: texture_2d<f32>;
@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(5) var packed_out: pair_storage;

fn load_ao_depth(pixel: vec2<u32>) -> vec2<f32> {
    return textureLoad(packed_in, pixel, 0).rg;
}

fn store_filtered(pixel: vec2<u32>, ao: f32, depth: f32) {
    if PACKED_OUTPUT {
        textureStore(packed_out, pixel, vec4<f32>(ao, depth, 0.0, 0.0));
    } else {
        textureStore(ao_out, pixel, vec4<f32>(ao, 0.0, 0.0, 0.0));
    }
}
