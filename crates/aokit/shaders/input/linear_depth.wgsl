// requires: common/view.wgsl, common/depth_from_ndc.wgsl | common/depth_from_linear.wgsl
// Prepare pass: the renderer's depth to linear view depth (NO_SURFACE where nothing was drawn).
// The program starts with the depth binding and `input_linear_depth`, one per kind of depth
// input (`DepthInput` in passes/input/linear_depth.rs).

@group(0) @binding(2) var linear_out: texture_storage_2d<r32float, write>;

// Each thread converts a 2x2 block, as XeGTAO's depth prefilter does (Strugar 2021): a quarter
// of the threads, each with four independent loads in flight. One pixel a thread took twice
// XeGTAO's prefilter time on an H200 for a pass that does less (docs/performance.md).
const TEXELS_PER_THREAD: u32 = 2u;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let corner = id.xy * TEXELS_PER_THREAD;
    for (var i = 0u; i < TEXELS_PER_THREAD * TEXELS_PER_THREAD; i++) {
        let pixel = corner + vec2<u32>(i % TEXELS_PER_THREAD, i / TEXELS_PER_THREAD);
        if all(pixel < vec2<u32>(view.size)) {
            textureStore(linear_out, pixel, vec4<f32>(input_linear_depth(pixel), 0.0, 0.0, 0.0));
        }
    }
}
