// Prepare pass for linear view depth handed in directly (R32Float), e.g. passes exported by
// another renderer: NaN, infinity and values <= 0 mark pixels without a surface. The program
// starts with the depth binding and its `load_input`, one per sample count (shader.rs).

@group(0) @binding(2) var linear_out: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let depth = load_input(id.xy);
    // Written as a positive test so NaN lands on NO_SURFACE too.
    let surface = depth > 0.0 && depth < MAX_DEPTH;
    textureStore(linear_out, id.xy, vec4<f32>(select(NO_SURFACE, depth, surface), 0.0, 0.0, 0.0));
}
