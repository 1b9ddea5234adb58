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
    // The previous frame's camera (its jitter included), for the motion vectors; this frame's
    // own on a first frame, where nothing moved.
    previous_clip_from_world: mat4x4<f32>,
    // Target size in pixels, in xy.
    size: vec4<f32>,
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
    // Clip position in the previous frame, interpolated perspective-correctly, so the motion
    // vector is exact at every point of a triangle.
    @location(4) previous_clip: vec4<f32>,
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
    // The scene stands still: only the camera moves the surface on screen.
    out.previous_clip = frame.previous_clip_from_world * vec4<f32>(v.position, 1.0);
    return out;
}

struct PrepassOut {
    @location(0) normal: u32,
    @location(1) motion: vec2<f32>,
}

// The prepass writes reverse-Z depth and, for aokit, the view-space normal in its oct32 encoding
// (`pack_oct32` from aokit::shader::ENCODING) into an R32Uint target, and the motion vector: the
// offset in pixels (y down) from this pixel's centre to where its surface point was in the
// previous frame, the convention of `AoInputs::motion_vectors`.
@fragment
fn fs_prepass(in: VertexOut) -> PrepassOut {
    var motion = vec2<f32>(65504.0);
    // A point behind the previous camera had no pixel: an offset past any screen (the largest
    // half float) makes aokit's temporal filter reject the history there.
    if in.previous_clip.w > 0.0 {
        let ndc = in.previous_clip.xy / in.previous_clip.w;
        let previous = vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * frame.size.xy;
        // The fragment's position is its pixel centre, in the same pixel units.
        motion = previous - in.clip.xy;
    }
    return PrepassOut(pack_oct32(normalize(in.view_normal)), motion);
}
