// requires: common/view.wgsl
// requires: common/inputs/float_input.wgsl | common/inputs/float_input_multisampled.wgsl
// The input's linear view depth at `pixel` from hardware depth (`load_input`, which the program's
// depth binding defines), NO_SURFACE where nothing was drawn.
fn input_linear_depth(pixel: vec2<u32>) -> f32 {
    let ndc = load_input(pixel);
    let linear = linearize_depth(ndc);
    // Written as a positive test so NaN, infinity and the far plane all land on NO_SURFACE.
    let surface = ndc != view.far_ndc_depth && linear > 0.0 && linear < MAX_DEPTH;
    return select(NO_SURFACE, linear, surface);
}
