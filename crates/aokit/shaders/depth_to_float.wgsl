// Read-back of a depth texture on a device that copies none to a buffer (wgpu's GL backend):
// the depth, texel for texel, into an R32Float texture, which it does copy
// (gpu::read_texture).

@group(0) @binding(0) var depth: texture_2d<f32>;
@group(0) @binding(1) var copy: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(copy)) {
        return;
    }
    textureStore(copy, id.xy, vec4<f32>(textureLoad(depth, id.xy, 0).r, 0.0, 0.0, 0.0));
}
