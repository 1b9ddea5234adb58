// requires: common/view.wgsl, resample/resample.wgsl
// requires: common/inputs/float_input.wgsl | common/inputs/float_input_multisampled.wgsl
// requires: common/depth_from_ndc.wgsl | common/depth_from_linear.wgsl
// Prepare pass for `vbao.back_faces`: each working texel's occluder thickness, the view-depth
// distance from its front face (the working depth) to the nearest back face behind it (the
// back-face depth, read at the pixel the point downsample takes: the texel itself at full
// resolution). vbao.wgsl reads it as
//
//     MAX_DEPTH   no back face behind the front one: a closed boundary or a one-sided sheet,
//                 solid as far as anything in the image can tell
//     d > 0       the back face lies d behind the front one
//     0           nothing to measure: no front surface, or a back face in front of it (the
//                 block's point pixel saw another surface than the downsample kept); the
//                 constant thickness holds
//
// The program starts with resample.wgsl (SCALE, point_pixel), then the back-face depth at
// binding 1, `input_linear_depth` and `input_size` (one per kind of depth input, `DepthInput`
// in passes/input/linear_depth.rs).

@group(0) @binding(2) var working_depth: texture_2d<f32>;
@group(0) @binding(3) var thickness_out: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let front = textureLoad(working_depth, id.xy, 0).r;
    let back = input_linear_depth(point_pixel(id.xy, input_size() - 1u));
    var thickness = 0.0;
    if front != NO_SURFACE {
        thickness = select(select(0.0, back - front, back > front), MAX_DEPTH, back == NO_SURFACE);
    }
    textureStore(thickness_out, id.xy, vec4<f32>(thickness, 0.0, 0.0, 0.0));
}
