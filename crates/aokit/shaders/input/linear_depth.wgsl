// requires: common/view.wgsl, common/depth_from_ndc.wgsl | common/depth_from_linear.wgsl
// Prepare pass: the renderer's depth to linear view depth (NO_SURFACE where nothing was drawn).
// The program starts with the depth binding and `input_linear_depth`, one per kind of depth
// input (`DepthInput` in passes/input/linear_depth.rs).

@group(0) @binding(2) var linear_out: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    textureStore(linear_out, id.xy, vec4<f32>(input_linear_depth(id.xy), 0.0, 0.0, 0.0));
}
