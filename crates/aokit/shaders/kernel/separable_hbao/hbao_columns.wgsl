// requires: common/ao.wgsl, kernel/separable_hbao/hbao_separable.wgsl
// Second pass of separable HBAO (hbao_separable.wgsl): along columns, the +y and -y directions'
// occlusion, added to the rows pass's, averaged over the four directions as hbao.wgsl averages
// its directions, and shaped and stored as every method's AO is (common/ao.wgsl).

const AXIS = vec2<i32>(0, 1);

// The rows pass's output: the +x and -x directions' occlusion.
@group(0) @binding(9) var row_occlusion: texture_2d<f32>;

fn store_line(s: Surface, occlusion: f32) {
    let total = occlusion + textureLoad(row_occlusion, s.pixel, 0).r;
    store_ao(s, 1.0 - total / 4.0, s.n);
}

fn store_unsampled(s: Surface) {
    store_unoccluded(s);
}
