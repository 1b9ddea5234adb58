// requires: common/view.wgsl, common/encoding.wgsl, common/depth_normal.wgsl
// View-space normals reconstructed from linear depth (common/depth_normal.wgsl), for renderers
// that provide none or when `normals.source` asks for them. Output is oct32, like a G-buffer's.

@group(0) @binding(1) var linear_depth: texture_2d<f32>;
@group(0) @binding(2) var normals_out: texture_storage_2d<r32uint, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if all(id.xy < vec2<u32>(view.size)) {
        let n = normal_from_depth(vec2<i32>(id.xy));
        textureStore(normals_out, id.xy, vec4<u32>(pack_oct32(n), 0u, 0u, 0u));
    }
}
