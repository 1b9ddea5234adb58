// requires: common/ao.wgsl, kernel/separable_hbao/hbao_separable.wgsl
// First pass of separable HBAO (hbao_separable.wgsl): along rows, the +x and -x directions'
// occlusion, summed and unshaped, for the columns pass to finish.

const AXIS = vec2<i32>(1, 0);

@group(0) @binding(9) var row_occlusion_out: texture_storage_2d<r32float, write>;

fn store_line(s: Surface, occlusion: f32) {
    textureStore(row_occlusion_out, s.pixel, vec4<f32>(occlusion, 0.0, 0.0, 0.0));
}

// The columns pass stores AO 1 for these pixels itself; 0 keeps the texture defined everywhere.
fn store_unsampled(s: Surface) {
    store_line(s, 0.0);
}
