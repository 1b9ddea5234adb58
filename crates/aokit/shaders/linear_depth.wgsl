// Prepare pass: hardware depth -> linear view depth (NO_SURFACE where nothing was drawn). The
// program starts with the depth binding and its `load_ndc`, one per sample count (shader.rs).

@group(0) @binding(2) var linear_out: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let ndc = load_ndc(id.xy);
    let linear = linearize_depth(ndc);
    // Written as a positive test so NaN, infinity and the far plane all land on NO_SURFACE.
    let surface = ndc != view.far_ndc_depth && linear > 0.0 && linear < MAX_DEPTH;
    textureStore(linear_out, id.xy, vec4<f32>(select(NO_SURFACE, linear, surface), 0.0, 0.0, 0.0));
}
