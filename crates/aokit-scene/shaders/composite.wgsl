// Lit composite, sky where nothing was drawn; elsewhere, with F the ambient Fresnel term:
//   albedo x (ambient x (1 - F) x diffuse occlusion + shadowed sunlight)
//     + ambient x F x specular occlusion
// AO darkens only the ambient terms: direct light has its own visibility, the shadow map.
// Diffuse occlusion is the AO, or a multi-bounce form of it (GTAO's fit or the closed form);
// specular occlusion is 1, GTSO or Frostbite's (functions from aokit's occlusion.wgsl).
// docs/composite.md has the details.
// Mirrors `CompositeUniforms`.

// Values of `MULTI_BOUNCE`, as `MultiBounce::code` writes them.
const MB_NONE: u32 = 0u;
const MB_GTAO: u32 = 1u;
const MB_CLOSED_FORM: u32 = 2u;

// Values of `SPECULAR_OCCLUSION`, as `SpecularOcclusion::code` writes them.
const SO_NONE: u32 = 0u;
const SO_GTSO: u32 = 1u;
const SO_FROSTBITE: u32 = 2u;

// The lighting modes are pipeline constants, one pipeline per combination, not uniforms:
// Mesa's lavapipe (22.3) inlines uniform values that alone decide a branch and recompiles the
// shader at every dispatch, keeping each compile (0.5 MB a frame, `CompositePass`).
// One of the MB_* constants.
override MULTI_BOUNCE: u32 = MB_GTAO;
// One of the SO_* constants.
override SPECULAR_OCCLUSION: u32 = SO_FROSTBITE;
// 1 when `bent_normals` holds the AO pipeline's bent normals; 0 when it only fills the slot.
override HAS_BENT_NORMALS: u32 = 0u;

struct CompositeUniforms {
    // NDC (x, y, depth, 1) to homogeneous view position: the inverse projection.
    view_from_clip: mat4x4<f32>,
    // View position to the shadow map's clip space.
    light_clip_from_view: mat4x4<f32>,
    // Unit direction towards the sun, in view space.
    sun_direction: vec4<f32>,
    sun_color: vec4<f32>,
    // Radiance of the uniform sky that lights the ambient terms.
    ambient_color: vec4<f32>,
    sky_color: vec4<f32>,
    // F0, reflectance at normal incidence.
    specular_color: vec4<f32>,
    far_ndc_depth: f32,
    // Distance surfaces are pushed along their normal before the shadow lookup, against acne.
    shadow_normal_offset: f32,
    // 1 for orthographic, 0 for perspective, for the view direction.
    orthographic: f32,
    // Perceptual roughness of every surface.
    roughness: f32,
}

@group(0) @binding(0) var<uniform> light: CompositeUniforms;
@group(0) @binding(1) var albedo: texture_2d<f32>;
// The oct32 view-space normals the AO pipeline used.
@group(0) @binding(2) var normals: texture_2d<u32>;
// Hardware depth, bound as an unfilterable float texture as the AO passes bind it.
@group(0) @binding(3) var depth: texture_2d<f32>;
@group(0) @binding(4) var ao: texture_2d<f32>;
@group(0) @binding(5) var shadow_map: texture_depth_2d;
@group(0) @binding(6) var shadow_sampler: sampler_comparison;
@group(0) @binding(7) var lit_out: texture_storage_2d<rgba8unorm, write>;
// View-space bent normal in xyz.
@group(0) @binding(8) var bent_normals: texture_2d<f32>;

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

// Fresnel of the ambient reflection: Schlick's approximation at N.V with the grazing value
// lowered for rough surfaces, whose lobes average in less grazing reflection (Lagarde 2011,
// "Adopting a physically based shading model"; used for image-based lighting since).
fn ambient_fresnel(n_dot_v: f32) -> vec3<f32> {
    let f0 = light.specular_color.rgb;
    let grazing = max(vec3<f32>(1.0 - saturate(light.roughness)), f0);
    return f0 + (grazing - f0) * pow(1.0 - n_dot_v, 5.0);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(lit_out);
    if any(id.xy >= size) {
        return;
    }
    var color = light.sky_color.rgb;
    let d = textureLoad(depth, id.xy, 0).r;
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

        // Towards the eye: from the point for perspective, +Z for orthographic cameras.
        let v = normalize(mix(-p, vec3<f32>(0.0, 0.0, 1.0), light.orthographic));
        // Silhouette normals can face slightly away from the eye: clamp rather than go negative.
        let n_dot_v = saturate(dot(n, v));
        let fresnel = ambient_fresnel(n_dot_v);

        var diffuse_occlusion: vec3<f32>;
        switch MULTI_BOUNCE {
            case MB_GTAO: {
                diffuse_occlusion = multi_bounce_gtao(occlusion, base);
            }
            case MB_CLOSED_FORM: {
                diffuse_occlusion = multi_bounce_closed_form(occlusion, base);
            }
            case MB_NONE, default: {
                diffuse_occlusion = vec3<f32>(occlusion);
            }
        }
        var specular_occlusion: f32;
        switch SPECULAR_OCCLUSION {
            case SO_GTSO: {
                // Without the pipeline's bent normals the G-buffer normal stands in: the cone
                // sizes still follow the AO, the direction of the openings is lost.
                var bent = n;
                if HAS_BENT_NORMALS != 0u {
                    bent = textureLoad(bent_normals, id.xy, 0).xyz;
                }
                let r = reflect(-v, n);
                specular_occlusion = specular_occlusion_gtso(bent, r, occlusion, light.roughness);
            }
            case SO_FROSTBITE: {
                let r = light.roughness;
                specular_occlusion = specular_occlusion_frostbite(n_dot_v, occlusion, r);
            }
            case SO_NONE, default: {
                specular_occlusion = 1.0;
            }
        }

        let ambient = light.ambient_color.rgb;
        // Light the Fresnel term sends into the specular lobe does not also reach the diffuse.
        let diffuse = base * (ambient * (1.0 - fresnel) * diffuse_occlusion + direct);
        let specular = ambient * fresnel * specular_occlusion;
        color = diffuse + specular;
    }
    textureStore(lit_out, id.xy, vec4<f32>(linear_to_srgb(saturate(color)), 1.0));
}
