// The mask texture's weight in `apply_mask`.
fn mask_weight(pixel: vec2<u32>) -> f32 {
    return saturate(load_input(pixel));
}
