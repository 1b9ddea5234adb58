// Using AO in shading: multi-bounce diffuse occlusion and specular occlusion.
// The same arithmetic as aokit::occlusion (crates/aokit/src/occlusion.rs), which documents each
// function and is the reference a GPU test holds these to. Derivations: docs/composite.md.
// Self-contained: usable by any program, with or without the AO kernels' snippets.

// Fraction of the specular lobe's energy inside GTSO's specular cone (see the Rust constant).
const OCCLUSION_SPECULAR_CONE_ENERGY: f32 = 0.75;
// Largest cosine of the specular cone's half-angle: a mirror's cone would have no solid angle.
const OCCLUSION_MAX_SPECULAR_CONE_COS: f32 = 0.9999;

// Multi-bounce AO, the cubic fit of Jimenez et al. 2016 ("Practical Real-Time Strategies for
// Accurate Indirect Occlusion", SIGGRAPH 2016); coefficients as published. Per colour channel, in
// [visibility, 1]; clamped to 1 because the fit reaches 1.0001 for white albedo.
fn multi_bounce_gtao(visibility: f32, albedo: vec3<f32>) -> vec3<f32> {
    let x = saturate(visibility);
    let rho = saturate(albedo);
    let a = 2.0404 * rho - 0.3324;
    let b = -4.7951 * rho + 0.6417;
    let c = 2.7552 * rho + 0.6903;
    return min(max(vec3<f32>(x), ((a * x + b) * x + c) * x), vec3<f32>(1.0));
}

// Multi-bounce AO in closed form (Akenine-Moller et al. 2018, Real-Time Rendering 4th ed., ch. 11):
// occluded directions are taken to show surfaces of the same albedo and outgoing radiance as the
// shaded point, which sums the bounces as a geometric series, k / (1 - albedo (1 - k)). Per colour
// channel, in [visibility, 1]. The denominator is written (1 - a) + a k so that white albedo keeps
// small visibilities exact (they give 1), and the floor only guards k = 0 with white albedo, 0 / 0,
// where no light enters and the result is 0.
fn multi_bounce_closed_form(visibility: f32, albedo: vec3<f32>) -> vec3<f32> {
    let k = saturate(visibility);
    let rho = saturate(albedo);
    let denominator = max((1.0 - rho) + rho * k, vec3<f32>(1.17549435e-38));
    return min(max(vec3<f32>(k), vec3<f32>(k) / denominator), vec3<f32>(1.0));
}

// Specular occlusion from AO alone: Lagarde and de Rousiers 2014, "Moving Frostbite to PBR".
fn specular_occlusion_frostbite(n_dot_v: f32, ao: f32, roughness: f32) -> f32 {
    let nv = saturate(n_dot_v);
    let visible = saturate(ao);
    let r = saturate(roughness);
    // pow is exp2(y * log2(x)) on GPUs: keep its base positive. The floor cannot change the
    // result, which is <= 0 and saturates to 0 whenever it applies.
    let base = max(nv + visible, 1e-6);
    return saturate(pow(base, exp2(-16.0 * r - 1.0)) - 1.0 + visible);
}

// GTSO (Jimenez et al. 2016) as the fraction of the specular cone around `reflection` inside the
// visibility cone around `bent_normal`, intersected as in Oat and Sander 2007.
fn specular_occlusion_gtso(
    bent_normal: vec3<f32>,
    reflection: vec3<f32>,
    ao: f32,
    roughness: f32,
) -> f32 {
    let visible = saturate(ao);
    let r = saturate(roughness);
    // Visibility cone: a cone of half-angle a has cosine-weighted visibility sin^2 a.
    let cos_v = sqrt(1.0 - visible);
    let angle_v = atan2(sqrt(visible), cos_v);
    // Specular cone: GGX alpha = r^2 as Phong exponent p = 2 / alpha^2 - 2; the cone holding a
    // fraction f of the lobe has cos = (1 - f)^(1 / (p + 1)), with
    // 1 / (p + 1) = alpha^2 / (2 - alpha^2).
    let alpha2 = r * r * r * r;
    let cos_s = min(pow(1.0 - OCCLUSION_SPECULAR_CONE_ENERGY, alpha2 / (2.0 - alpha2)),
                    OCCLUSION_MAX_SPECULAR_CONE_COS);
    let angle_s = atan2(sqrt(1.0 - cos_s * cos_s), cos_s);
    // Angle between the axes; an unknown direction (a zero vector) counts as coaxial cones.
    let lb = length(bent_normal);
    let lr = length(reflection);
    var axis_angle = 0.0;
    if lb > 1e-6 && lr > 1e-6 {
        let b = bent_normal / lb;
        let q = reflection / lr;
        axis_angle = atan2(length(cross(b, q)), dot(b, q));
    }
    // Intersection over the specular cone's solid angle 2 pi (1 - cos a_s).
    let smaller_cone = min((1.0 - cos_v) / (1.0 - cos_s), 1.0);
    let lo = abs(angle_v - angle_s);
    let hi = angle_v + angle_s;
    let overlap = smoothstep(0.0, 1.0, (hi - axis_angle) / max(hi - lo, 1e-6));
    return saturate(smaller_cone * overlap);
}
