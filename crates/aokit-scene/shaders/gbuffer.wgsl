// G-buffer raster: depth, view-space normals in the encoding `ENCODING` names, albedo. Mirrors
// `GBufferUniforms`. Normal targets are R32Uint or a unorm/float format, so there is one fragment
// entry point per kind of target.

struct GBufferUniforms {
    clip_from_world: mat4x4<f32>,
    view_from_world: mat4x4<f32>,
    // 1 for orthographic cameras: the eye direction is then +Z everywhere.
    orthographic: f32,
}

@group(0) @binding(0) var<uniform> frame: GBufferUniforms;

// The normal encoding: `NormalEncoding::shader_code`, one of the ENCODING_* constants.
override ENCODING: u32;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) view_position: vec3<f32>,
    @location(1) view_normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = frame.clip_from_world * vec4<f32>(v.position, 1.0);
    out.view_position = (frame.view_from_world * vec4<f32>(v.position, 1.0)).xyz;
    // Scenes are flattened to world space without scaling, so the rotation part maps normals.
    out.view_normal = (frame.view_from_world * vec4<f32>(v.normal, 0.0)).xyz;
    out.albedo = v.albedo;
    return out;
}

struct GBufferUintOut {
    @location(0) normal: u32,
    @location(1) albedo: vec4<f32>,
}

struct GBufferFloatOut {
    @location(0) normal: vec4<f32>,
    @location(1) albedo: vec4<f32>,
}

fn shading_normal(in: VertexOut) -> vec3<f32> {
    // Files mix windings and double-sided sheets, so the facing is decided geometrically: the
    // shading normal goes to the side of the surface the eye is on.
    let geometric = cross(dpdx(in.view_position), dpdy(in.view_position));
    let to_eye = mix(-in.view_position, vec3<f32>(0.0, 0.0, 1.0), frame.orthographic);
    let eye_side = select(-1.0, 1.0, dot(geometric, to_eye) >= 0.0) * geometric;
    var n = normalize(in.view_normal);
    if dot(n, eye_side) < 0.0 {
        n = -n;
    }
    return n;
}

@fragment
fn fs_uint(in: VertexOut) -> GBufferUintOut {
    return GBufferUintOut(encode_normal_uint(shading_normal(in), ENCODING), vec4<f32>(in.albedo, 1.0));
}

@fragment
fn fs_float(in: VertexOut) -> GBufferFloatOut {
    return GBufferFloatOut(encode_normal_float(shading_normal(in), ENCODING), vec4<f32>(in.albedo, 1.0));
}
