// Sun shadow map: depth only, orthographic from the sun. Mirrors `ShadowUniforms`.

struct ShadowUniforms {
    light_clip_from_world: mat4x4<f32>,
}

@group(0) @binding(0) var<uniform> shadow: ShadowUniforms;

@vertex
fn vs_main(@location(0) position: vec3<f32>) -> @builtin(position) vec4<f32> {
    return shadow.light_clip_from_world * vec4<f32>(position, 1.0);
}
