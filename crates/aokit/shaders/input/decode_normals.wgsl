// requires: common/view.wgsl, common/encoding.wgsl, common/depth_normal.wgsl
// requires: common/inputs/encoded_uint.wgsl | common/inputs/encoded_float.wgsl
// A normal texture in any encoding, or in world space, to the oct32 view-space texture the AO
// kernels read. The program starts with the binding of the encoded texture and its
// `load_normal`, one per texel type (shader.rs); the `ENCODING` override picks the encoding.
// Texels are loaded, never filtered. Where a texel holds no usable normal (zero, NaN, infinite,
// far from unit length: `load_normal` returns zero), the normal comes from the depth around the
// pixel instead, as the `normals_from_depth` pass would reconstruct it: renderers hand normals
// over on the GPU, where no check on the CPU sees them. Mirrors `DecodeUniforms` in uniforms.rs.

struct DecodeUniforms {
    // Into view space: the identity for view-space normals, the camera's rotation for
    // world-space ones.
    to_view: mat3x3<f32>,
}

@group(0) @binding(2) var decoded: texture_storage_2d<r32uint, write>;
@group(0) @binding(3) var<uniform> decode: DecodeUniforms;
@group(0) @binding(4) var linear_depth: texture_2d<f32>;

// `NormalEncoding::shader_code`, one of the ENCODING_* constants.
override ENCODING: u32;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if all(id.xy < vec2<u32>(view.size)) {
        let loaded = load_normal(id.xy);
        var n: vec3<f32>;
        if all(loaded == vec3<f32>(0.0)) {
            n = normal_from_depth(vec2<i32>(id.xy));
        } else {
            n = normalize(decode.to_view * loaded);
        }
        textureStore(decoded, id.xy, vec4<u32>(pack_oct32(n), 0u, 0u, 0u));
    }
}
