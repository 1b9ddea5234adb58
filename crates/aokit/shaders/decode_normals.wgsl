// A normal texture in any encoding but oct32 to the oct32 texture the AO kernels read. The program
// starts with the binding of the encoded texture and its `load_normal`, one per texel type
// (shader.rs); the `ENCODING` override picks the encoding. Texels are loaded, never filtered.

@group(0) @binding(2) var decoded: texture_storage_2d<r32uint, write>;

// `NormalEncoding::shader_code`, one of the ENCODING_* constants.
override ENCODING: u32;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if all(id.xy < vec2<u32>(view.size)) {
        textureStore(decoded, id.xy, vec4<u32>(pack_oct32(load_normal(id.xy)), 0u, 0u, 0u));
    }
}
