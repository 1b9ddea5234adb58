// requires: common/view.wgsl
// requires: common/inputs/float_input.wgsl | common/inputs/float_input_multisampled.wgsl
// The input's linear view depth at `pixel` from linear depth handed in directly (`load_input`,
// which the program's depth binding defines), e.g. passes exported by another renderer: NaN,
// infinity and values <= 0 mark pixels without a surface, NO_SURFACE here.
fn input_linear_depth(pixel: vec2<u32>) -> f32 {
    let depth = load_input(pixel);
    // Written as a positive test so NaN lands on NO_SURFACE too.
    let surface = depth > 0.0 && depth < MAX_DEPTH;
    return select(NO_SURFACE, depth, surface);
}
