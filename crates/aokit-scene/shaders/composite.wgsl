// Lit composite: albedo x (ambient x AO + direct sunlight), sky where nothing was drawn.
// Mirrors `CompositeUniforms`.

struct CompositeUniforms {
    // Unit direction towards the sun, in view space.
    sun_direction: vec4<f32>,
    sun_color: vec4<f32>,
    ambient_color: vec4<f32>,
    sky_color: vec4<f32>,
}

@group(0) @binding(0) var<uniform> light: CompositeUniforms;
@group(0) @binding(1) var albedo: texture_2d<f32>;
@group(0) @binding(2) var normals: texture_2d<u32>;
@group(0) @binding(3) var linear_depth: texture_2d<f32>;
@group(0) @binding(4) var ao: texture_2d<f32>;
@group(0) @binding(5) var lit_out: texture_storage_2d<rgba8unorm, write>;

fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(lit_out)) {
        return;
    }
    var color = light.sky_color.rgb;
    if textureLoad(linear_depth, id.xy, 0).r > 0.0 {
        let n = unpack_oct32(textureLoad(normals, id.xy, 0).r);
        let base = textureLoad(albedo, id.xy, 0).rgb;
        let occlusion = textureLoad(ao, id.xy, 0).r;
        let direct = light.sun_color.rgb * max(dot(n, light.sun_direction.xyz), 0.0);
        color = base * (light.ambient_color.rgb * occlusion + direct);
    }
    textureStore(lit_out, id.xy, vec4<f32>(linear_to_srgb(saturate(color)), 1.0));
}
