// Lit composite: albedo x (ambient x AO + shadowed sunlight), sky where nothing was drawn.
// AO darkens only the ambient term: direct light has its own visibility, the shadow map.
// Mirrors `CompositeUniforms`.

struct CompositeUniforms {
    // NDC (x, y, depth, 1) to homogeneous view position: the inverse projection.
    view_from_clip: mat4x4<f32>,
    // View position to the shadow map's clip space.
    light_clip_from_view: mat4x4<f32>,
    // Unit direction towards the sun, in view space.
    sun_direction: vec4<f32>,
    sun_color: vec4<f32>,
    ambient_color: vec4<f32>,
    sky_color: vec4<f32>,
    far_ndc_depth: f32,
    // Distance surfaces are pushed along their normal before the shadow lookup, against acne.
    shadow_normal_offset: f32,
}

@group(0) @binding(0) var<uniform> light: CompositeUniforms;
@group(0) @binding(1) var albedo: texture_2d<f32>;
@group(0) @binding(2) var normals: texture_2d<u32>;
@group(0) @binding(3) var depth: texture_depth_2d;
@group(0) @binding(4) var ao: texture_2d<f32>;
@group(0) @binding(5) var shadow_map: texture_depth_2d;
@group(0) @binding(6) var shadow_sampler: sampler_comparison;
@group(0) @binding(7) var lit_out: texture_storage_2d<rgba8unorm, write>;

fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}

// Fraction of the sun visible from `p`: 3x3 bilinear comparison taps soften the map's texels.
fn sun_visibility(p: vec3<f32>, n: vec3<f32>) -> f32 {
    let clip = light.light_clip_from_view * vec4<f32>(p + n * light.shadow_normal_offset, 1.0);
    let ndc = clip.xyz / clip.w;
    let uv = vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
    let texel = 1.0 / vec2<f32>(textureDimensions(shadow_map));
    var lit = 0.0;
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            let offset = vec2<f32>(f32(x), f32(y)) * texel;
            lit += textureSampleCompareLevel(shadow_map, shadow_sampler, uv + offset, ndc.z);
        }
    }
    return lit / 9.0;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(lit_out);
    if any(id.xy >= size) {
        return;
    }
    var color = light.sky_color.rgb;
    let d = textureLoad(depth, id.xy, 0);
    if d != light.far_ndc_depth {
        let uv = (vec2<f32>(id.xy) + 0.5) / vec2<f32>(size);
        let clip = vec4<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, d, 1.0);
        let h = light.view_from_clip * clip;
        let p = h.xyz / h.w;
        let n = unpack_oct32(textureLoad(normals, id.xy, 0).r);
        let base = textureLoad(albedo, id.xy, 0).rgb;
        let occlusion = textureLoad(ao, id.xy, 0).r;
        let n_dot_l = max(dot(n, light.sun_direction.xyz), 0.0);
        let direct = light.sun_color.rgb * n_dot_l * sun_visibility(p, n);
        color = base * (light.ambient_color.rgb * occlusion + direct);
    }
    textureStore(lit_out, id.xy, vec4<f32>(linear_to_srgb(saturate(color)), 1.0));
}
