// requires: common/inputs/float_input.wgsl | common/inputs/float_input_multisampled.wgsl
// The mask texture's weight in `apply_mask`.
fn mask_weight(pixel: vec2<u32>) -> f32 {
    return saturate(load_input(pixel));
}
