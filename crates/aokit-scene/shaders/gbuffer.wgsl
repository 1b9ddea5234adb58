// G-buffer raster: depth, view-space normals in the encoding `ENCODING` names, albedo and motion
// vectors. Mirrors `GBufferUniforms`. Normal targets are R32Uint or a unorm/float format, so there
// is one fragment entry point per kind of target.

struct GBufferUniforms {
    clip_from_world: mat4x4<f32>,
    view_from_world: mat4x4<f32>,
    // The previous frame's camera, which saw the previous positions.
    previous_clip_from_world: mat4x4<f32>,
    // Target size in pixels.
    size: vec2<f32>,
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
    // Where this point was in the previous frame: the position itself unless its part moves.
    @location(3) previous_position: vec3<f32>,
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) view_position: vec3<f32>,
    @location(1) view_normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
    // Clip position in the previous frame, interpolated perspective-correctly, so it is exact
    // for every point of the triangle, not only its corners.
    @location(3) previous_clip: vec4<f32>,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = frame.clip_from_world * vec4<f32>(v.position, 1.0);
    out.view_position = (frame.view_from_world * vec4<f32>(v.position, 1.0)).xyz;
    // Scenes are flattened to world space without scaling, so the rotation part maps normals.
    out.view_normal = (frame.view_from_world * vec4<f32>(v.normal, 0.0)).xyz;
    out.albedo = v.albedo;
    out.previous_clip = frame.previous_clip_from_world * vec4<f32>(v.previous_position, 1.0);
    return out;
}

struct GBufferUintOut {
    @location(0) normal: u32,
    @location(1) albedo: vec4<f32>,
    @location(2) motion: vec2<f32>,
}

struct GBufferFloatOut {
    @location(0) normal: vec4<f32>,
    @location(1) albedo: vec4<f32>,
    @location(2) motion: vec2<f32>,
}

// Offset in pixels from this fragment to where its surface point was in the previous frame, with
// pixel y growing downwards, as the AO pipeline reads it.
fn motion(in: VertexOut) -> vec2<f32> {
    if in.previous_clip.w <= 0.0 {
        // Behind the previous camera the point had no pixel: an offset past any screen (the
        // largest half float) makes the temporal filter reject the history there.
        return vec2<f32>(65504.0);
    }
    let ndc = in.previous_clip.xy / in.previous_clip.w;
    let previous = vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * frame.size;
    // The fragment's position is its pixel centre, in the same pixel units.
    return previous - in.clip.xy;
}

// The interpolated normal, turned to the side of the surface the eye is on: open sheets are seen
// from both sides. It is turned only where both the triangle and the normal face away from the
// eye. The triangle's facing alone would turn the normals of back faces that win the depth test
// against the front faces they share a silhouette edge with, whose interpolated normals still
// face the eye; the normal's alone would turn those that tilt just past grazing on front faces
// near a silhouette. GpuMesh winds every triangle towards its normals, so the rasteriser's
// facing, exact however thin the triangle is on screen, means the same in every file.
fn shading_normal(in: VertexOut, front_facing: bool) -> vec3<f32> {
    let to_eye = mix(-in.view_position, vec3<f32>(0.0, 0.0, 1.0), frame.orthographic);
    let n = normalize(in.view_normal);
    return select(n, -n, !front_facing && dot(n, to_eye) < 0.0);
}

@fragment
fn fs_uint(in: VertexOut, @builtin(front_facing) front_facing: bool) -> GBufferUintOut {
    return GBufferUintOut(encode_normal_uint(shading_normal(in, front_facing), ENCODING), vec4<f32>(in.albedo, 1.0), motion(in));
}

@fragment
fn fs_float(in: VertexOut, @builtin(front_facing) front_facing: bool) -> GBufferFloatOut {
    return GBufferFloatOut(encode_normal_float(shading_normal(in, front_facing), ENCODING), vec4<f32>(in.albedo, 1.0), motion(in));
}
