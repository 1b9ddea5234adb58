// The examples' renderer: the frame's camera and light, the vertex stage and the depth prepass.
// Assembled after aokit's `shader::ENCODING` (for `pack_oct32`) and before the example's own
// lighting shader, whose entry point is `fs_lighting`. Mirrors `FrameUniforms` in mod.rs.

struct Frame {
    clip_from_world: mat4x4<f32>,
    view_from_world: mat4x4<f32>,
    // Unit direction towards the sun, in view space.
    sun_direction: vec4<f32>,
    sun_color: vec4<f32>,
    // Radiance of the uniform sky: the ambient light, and the background.
    sky_color: vec4<f32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
    @location(3) roughness: f32,
}

struct VertexOut {
    // Invariant: the lighting pass draws the geometry again and keeps only the fragments whose
    // depth equals the prepass's, which needs the very same position from both pipelines.
    @invariant @builtin(position) clip: vec4<f32>,
    @location(0) view_position: vec3<f32>,
    @location(1) view_normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
    @location(3) roughness: f32,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = frame.clip_from_world * vec4<f32>(v.position, 1.0);
    out.view_position = (frame.view_from_world * vec4<f32>(v.position, 1.0)).xyz;
    // The view transform is rigid, so it maps normals as it maps directions.
    out.view_normal = (frame.view_from_world * vec4<f32>(v.normal, 0.0)).xyz;
    out.albedo = v.albedo;
    out.roughness = v.roughness;
    return out;
}

// The prepass writes reverse-Z depth and, for aokit, the view-space normal in its oct32 encoding
// (`pack_oct32` from aokit::shader::ENCODING) into an R32Uint target.
@fragment
fn fs_prepass(in: VertexOut) -> @location(0) u32 {
    return pack_oct32(normalize(in.view_normal));
}
