//! Using AO in shading: multi-bounce diffuse occlusion and specular occlusion.
//!
//! AO is the cosine-weighted visibility of the hemisphere: right for diffuse light that arrives
//! from every direction and reaches nothing else. Two corrections make it usable in a lit image:
//!
//! - [`multi_bounce_gtao`] and [`multi_bounce_closed_form`]: occluded directions are not black in
//!   a real scene, they show nearby surfaces that reflect light; bright surfaces should lose less
//!   light to occlusion than dark ones. The first is a fit to path-traced data, the second an
//!   analytic model; `docs/composite.md` plots them against each other.
//! - [`specular_occlusion_frostbite`] and [`specular_occlusion_gtso`]: the specular lobe is
//!   narrow and points along the reflection vector, so its visibility differs from AO's.
//!
//! These CPU functions are the reference for the WGSL versions in
//! [`shader::OCCLUSION`](crate::shader::OCCLUSION) (same names, same arithmetic), which a GPU test
//! keeps equal to them. Vectors are in any one space (aokit uses view space). `docs/composite.md`
//! has the derivations and tables of values.
//!
//! ```
//! use aokit::occlusion::{
//!     multi_bounce_closed_form, multi_bounce_gtao, specular_occlusion_frostbite,
//!     specular_occlusion_gtso,
//! };
//! use glam::Vec3;
//!
//! // A white wall keeps more of its light than a black one at the same AO.
//! let white = multi_bounce_gtao(0.5, Vec3::ONE);
//! let black = multi_bounce_gtao(0.5, Vec3::ZERO);
//! assert!(white.x > 0.75 && (black.x - 0.5).abs() < 1e-4);
//! // The closed form agrees for black surroundings and, here, gives white ones all of it back.
//! assert_eq!(multi_bounce_closed_form(0.5, Vec3::ZERO).x, 0.5);
//! assert_eq!(multi_bounce_closed_form(0.5, Vec3::ONE).x, 1.0);
//!
//! // Specular occlusion: an unoccluded point keeps all of its reflection...
//! assert_eq!(specular_occlusion_frostbite(0.7, 1.0, 0.3), 1.0);
//! let n = Vec3::Z;
//! assert_eq!(specular_occlusion_gtso(n, n, 1.0, 0.3), 1.0);
//! // ...and a reflection pointing away from the open directions is hidden.
//! assert_eq!(specular_occlusion_gtso(n, -n, 0.8, 0.3), 0.0);
//! ```

use glam::Vec3;

/// Fraction of the specular lobe's energy that [`specular_occlusion_gtso`]'s cone holds. 0.75
/// keeps the cone about as wide as the lobe looks (its bright core and most of its skirt) while
/// leaving out the long tail, which would make rough cones wider than the hemisphere.
pub const SPECULAR_CONE_ENERGY: f32 = 0.75;

/// Largest cosine of the specular cone's half-angle (about 0.8 degrees): a mirror's cone has no
/// width, and its solid angle `2 pi (1 - cos)` would be 0 and lose every digit in `f32`.
pub const MAX_SPECULAR_CONE_COS: f32 = 1.0 - 1e-4;

/// Clamps to `[0, 1]`, mapping NaN to 0 (`f32::clamp` would keep the NaN).
fn saturate(x: f32) -> f32 {
    if x >= 0.0 { x.min(1.0) } else { 0.0 }
}

/// Multi-bounce AO: the visibility a surface of `albedo` effectively has once light bouncing
/// between it and its occluders is counted, per colour channel, in `[visibility, 1]`.
///
/// The cubic fit of Jimenez, Wu, Pesce and Jarabo, *Practical Real-Time Strategies for Accurate
/// Indirect Occlusion* (SIGGRAPH 2016 course), made against path-traced
/// interreflections: `max(x, ((a x + b) x + c) x)` with `a`, `b`, `c` linear in albedo. `albedo`
/// is clamped to `[0, 1]`, the range it was fitted on. Black albedo gives `visibility` back
/// (within 1e-5); the fit reaches 1.0001 at `visibility` 1 with white albedo, so the result is
/// clamped to 1: an unoccluded pixel keeps exactly its lighting.
///
/// ```
/// use aokit::occlusion::multi_bounce_gtao;
/// use glam::Vec3;
/// // Ambient light on a red wall in a corner: the red channel bounces, green and blue barely.
/// let (ao, albedo, ambient) = (0.6, Vec3::new(0.8, 0.1, 0.1), Vec3::splat(0.5));
/// let visibility = multi_bounce_gtao(ao, albedo);
/// let diffuse = ambient * albedo * visibility;
/// assert!(visibility.x > 0.7 && (visibility.y - ao).abs() < 0.02);
/// ```
pub fn multi_bounce_gtao(visibility: f32, albedo: Vec3) -> Vec3 {
    let x = saturate(visibility);
    let albedo = albedo.map(saturate);
    // Jimenez et al. 2016, the fit's coefficients as published.
    let a = 2.0404 * albedo - 0.3324;
    let b = -4.7951 * albedo + 0.6417;
    let c = 2.7552 * albedo + 0.6903;
    (((a * x + b) * x + c) * x)
        .max(Vec3::splat(x))
        .min(Vec3::ONE)
}

/// Multi-bounce AO in closed form: the visibility a surface of `albedo` effectively has when the
/// occluded directions show surfaces like itself, per colour channel, in `[visibility, 1]`:
///
/// ```text
/// k' = k / (1 - albedo (1 - k))
/// ```
///
/// The interreflection correction of *Real-Time Rendering*, 4th ed. (Akenine-Möller et al.
/// 2018), chapter 11, in its section on ambient occlusion. In a Lambertian scene under uniform
/// light, the surfaces a point sees tend to have about its own radiance; taking the radiance of the
/// occluded fraction `1 - k` of the hemisphere to be the point's outgoing radiance `albedo E / pi`
/// gives `E = pi k L + albedo (1 - k) E`, whose solution is the sky's share `pi k L` times the
/// geometric series of bounces `sum_n (albedo (1 - k))^n`.
///
/// Unlike [`multi_bounce_gtao`] nothing is fitted, so it is exact where its assumption holds,
/// and it grows quickly towards 1 as `albedo` nears 1: white surroundings lose nothing after
/// infinitely many bounces. `visibility` and `albedo` are clamped to `[0, 1]` (NaN to 0);
/// `visibility` 0 gives 0 for any albedo (no light gets in to bounce).
///
/// ```
/// use aokit::occlusion::multi_bounce_closed_form;
/// use glam::Vec3;
/// let albedo = Vec3::new(0.8, 0.5, 0.1);
/// // Unoccluded points keep their lighting; black surroundings return nothing.
/// assert_eq!(multi_bounce_closed_form(1.0, albedo), Vec3::ONE);
/// assert_eq!(multi_bounce_closed_form(0.3, Vec3::ZERO), Vec3::splat(0.3));
/// // Bounced light only ever adds, and more of it for brighter channels.
/// let k = multi_bounce_closed_form(0.3, albedo);
/// assert!(k.cmpge(Vec3::splat(0.3)).all() && k.x > k.y && k.y > k.z);
/// // 0.3 / (1 - 0.5 x 0.7) = 0.4615...
/// assert!((k.y - 0.3 / 0.65).abs() < 1e-6);
/// ```
pub fn multi_bounce_closed_form(visibility: f32, albedo: Vec3) -> Vec3 {
    let k = saturate(visibility);
    let albedo = albedo.map(saturate);
    // (1 - a) + a k rather than 1 - a (1 - k): for white albedo and tiny k the latter cancels to
    // 0 in f32. It is >= k, so the quotient is at most 1 but for rounding; the floor only guards
    // 0 / 0 (k = 0, white albedo), which gives 0.
    let denominator = ((Vec3::ONE - albedo) + albedo * k).max(Vec3::splat(f32::MIN_POSITIVE));
    (Vec3::splat(k) / denominator)
        .max(Vec3::splat(k))
        .min(Vec3::ONE)
}

/// Specular occlusion from AO alone, Lagarde and de Rousiers, *Moving Frostbite to Physically
/// Based Rendering 3.0* (SIGGRAPH 2014 course notes):
/// `saturate((n.v + ao)^(2^(-16 roughness - 1)) - 1 + ao)`.
///
/// An empirical fit: 1 when `ao` is 1, 0 when `ao` is 0, close to `ao` for rough surfaces, and
/// darker than `ao` for smooth surfaces seen at grazing angles (small `n_dot_v`), where the
/// reflection skims the occluders. Inputs are clamped to `[0, 1]`, NaN to 0.
///
/// ```
/// use aokit::occlusion::specular_occlusion_frostbite;
/// let ao = 0.6;
/// // Rough surfaces: close to the AO.
/// assert!((specular_occlusion_frostbite(0.9, ao, 1.0) - ao).abs() < 0.05);
/// // Smooth ones seen at a grazing angle lose more of their reflection.
/// assert!(specular_occlusion_frostbite(0.05, ao, 0.0) < ao - 0.15);
/// ```
pub fn specular_occlusion_frostbite(n_dot_v: f32, ao: f32, roughness: f32) -> f32 {
    let n_dot_v = saturate(n_dot_v);
    let ao = saturate(ao);
    let roughness = saturate(roughness);
    // The floor keeps pow's base positive (pow(0, y) is log2-based on GPUs); it cannot change the
    // result, which is then at most 1e-6^k - 1 <= 0 and saturates to 0 either way.
    let base = (n_dot_v + ao).max(1e-6);
    saturate(base.powf((-16.0 * roughness - 1.0).exp2()) - 1.0 + ao)
}

/// Ground-truth based specular occlusion (GTSO, Jimenez et al. 2016), as the
/// fraction of the specular cone that lies inside the visibility cone.
///
/// - **Visibility cone**: around `bent_normal`, with the half-angle `a_v` whose cosine-weighted
///   visibility equals `ao`. A cone of half-angle `a` sees `1/pi * integral_0^2pi integral_0^a
///   cos t sin t dt dphi = sin^2 a` of the cosine-weighted hemisphere, so `sin a_v = sqrt(ao)`.
/// - **Specular cone**: around `reflection`, holding [`SPECULAR_CONE_ENERGY`] of the lobe. GGX
///   with `alpha = roughness^2` is close to a normalised Phong lobe `cos^p` with
///   `p = 2 / alpha^2 - 2` (Walter et al. 2007); the fraction of that lobe within angle `a` of
///   its axis is `1 - cos^(p+1) a`, so the cone holding a fraction `f` has
///   `cos a_s = (1 - f)^(1 / (p + 1))`, where `1 / (p + 1) = alpha^2 / (2 - alpha^2)`. The cosine
///   is capped at [`MAX_SPECULAR_CONE_COS`]; `a_s` stays below 76 degrees (roughness 1).
/// - **Intersection** (Oat and Sander 2007, *Ambient Aperture Lighting*): with `d` the angle
///   between the axes, the smaller cone entirely when `d <= |a_v - a_s|`, nothing when
///   `d >= a_v + a_s`, and in between the smaller cone's solid angle times
///   `smoothstep(0, 1, (a_v + a_s - d) / (a_v + a_s - |a_v - a_s|))`.
///
/// The result is intersection / specular cone solid angle, where a cone's solid angle is
/// `2 pi (1 - cos a)`: `min(1, (1 - cos a_v) / (1 - cos a_s)) * smoothstep(..)`, in `[0, 1]`.
///
/// Degenerate inputs give a finite value in `[0, 1]`: `ao` and `roughness` are clamped (NaN to
/// 0), and when either vector is zero or not finite the direction is unknown, so the cones are
/// taken as coaxial (`d = 0`) and only their sizes count.
///
/// ```
/// use aokit::occlusion::specular_occlusion_gtso;
/// use glam::Vec3;
/// // The open side of a half-occluded surface leans towards +x (the bent normal).
/// let (bent, ao, roughness) = (Vec3::new(0.5, 0.0, 0.866), 0.5, 0.3);
/// let towards = Vec3::new(0.5, 0.0, 0.866);
/// let away = Vec3::new(-0.7, 0.0, 0.714);
/// // A reflection into the opening is kept; one into the occluder is hidden.
/// assert_eq!(specular_occlusion_gtso(bent, towards, ao, roughness), 1.0);
/// assert!(specular_occlusion_gtso(bent, away, ao, roughness) < 0.05);
/// ```
pub fn specular_occlusion_gtso(
    bent_normal: Vec3,
    reflection: Vec3,
    ao: f32,
    roughness: f32,
) -> f32 {
    let ao = saturate(ao);
    let roughness = saturate(roughness);
    // Half-angles as atan2(sin, cos): accurate near 0 and pi/2, where acos and asin are not.
    let cos_v = (1.0 - ao).sqrt();
    let angle_v = ao.sqrt().atan2(cos_v);
    let alpha2 = roughness * roughness * roughness * roughness;
    let cos_s = (1.0 - SPECULAR_CONE_ENERGY)
        .powf(alpha2 / (2.0 - alpha2))
        .min(MAX_SPECULAR_CONE_COS);
    let angle_s = (1.0 - cos_s * cos_s).sqrt().atan2(cos_s);
    let (lb, lr) = (bent_normal.length(), reflection.length());
    // `lb > 1e-6` is false for NaN too; an infinite length would make the division NaN.
    let axis_angle = if lb > 1e-6 && lr > 1e-6 && lb.is_finite() && lr.is_finite() {
        let (b, r) = (bent_normal / lb, reflection / lr);
        b.cross(r).length().atan2(b.dot(r))
    } else {
        0.0
    };
    let smaller_cone = ((1.0 - cos_v) / (1.0 - cos_s)).min(1.0);
    let lo = (angle_v - angle_s).abs();
    let hi = angle_v + angle_s;
    // hi - lo = 2 min(a_v, a_s) is 0 only when ao is 0, where smaller_cone is 0 too.
    let overlap = smoothstep((hi - axis_angle) / (hi - lo).max(1e-6));
    saturate(smaller_cone * overlap)
}

/// WGSL's `smoothstep(0, 1, t)`.
fn smoothstep(t: f32) -> f32 {
    let t = saturate(t);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    const GRID: [f32; 11] = [0.0, 0.05, 0.1, 0.2, 0.3, 0.45, 0.5, 0.7, 0.9, 0.99, 1.0];

    #[test]
    fn multi_bounce_keeps_unoccluded_pixels_and_never_darkens() {
        for albedo in GRID {
            let albedo = Vec3::splat(albedo);
            assert_eq!(multi_bounce_gtao(1.0, albedo), Vec3::ONE);
            for x in GRID {
                let m = multi_bounce_gtao(x, albedo);
                assert!(m.cmpge(Vec3::splat(x)).all() && m.cmple(Vec3::ONE).all());
            }
        }
    }

    #[test]
    fn multi_bounce_of_black_albedo_is_the_visibility() {
        for i in 0..=1000 {
            let x = i as f32 / 1000.0;
            let m = multi_bounce_gtao(x, Vec3::ZERO);
            // The fit's own error: its cubic touches x near 0.965, within 1e-5.
            assert!((m.x - x).abs() < 1e-5, "{x}: {m}");
        }
    }

    #[test]
    fn multi_bounce_brightens_with_albedo() {
        for x in [0.1, 0.3, 0.5, 0.7, 0.9] {
            let mut last = x;
            for albedo in [0.2, 0.4, 0.6, 0.8, 1.0] {
                let m = multi_bounce_gtao(x, Vec3::splat(albedo)).x;
                assert!(m > last, "visibility {x}, albedo {albedo}: {m} <= {last}");
                last = m;
            }
        }
        // Per channel: a red surface brightens its red channel only.
        let m = multi_bounce_gtao(0.5, Vec3::new(0.9, 0.0, 0.0));
        assert!(m.x > 0.6 && (m.y - 0.5).abs() < 1e-4 && (m.z - 0.5).abs() < 1e-4);
        // The fit evaluated by hand, so a typo in a coefficient shows:
        // ((1.708 * 0.5 - 4.1534) * 0.5 + 3.4455) * 0.5 = 0.89790.
        assert!((multi_bounce_gtao(0.5, Vec3::ONE).x - 0.8979).abs() < 1e-4);
    }

    #[test]
    fn closed_form_limits() {
        for albedo in GRID {
            let albedo = Vec3::splat(albedo);
            assert_eq!(multi_bounce_closed_form(1.0, albedo), Vec3::ONE);
            assert_eq!(multi_bounce_closed_form(0.0, albedo), Vec3::ZERO);
            let mut last = Vec3::ZERO;
            for x in GRID {
                let m = multi_bounce_closed_form(x, albedo);
                assert!(m.cmpge(Vec3::splat(x)).all() && m.cmple(Vec3::ONE).all());
                assert!(m.cmpge(last).all(), "not monotone in the visibility at {x}");
                last = m;
            }
        }
        for x in GRID {
            assert_eq!(multi_bounce_closed_form(x, Vec3::ZERO), Vec3::splat(x));
            // White surroundings give back everything that got in, however little.
            if x > 0.0 {
                assert_eq!(multi_bounce_closed_form(x, Vec3::ONE), Vec3::ONE);
            }
        }
        assert_eq!(multi_bounce_closed_form(1e-7, Vec3::ONE), Vec3::ONE);
        // By hand: 0.25 / (1 - 0.8 x 0.75) = 0.625; 0.5 / (1 - 0.5 x 0.5) = 2/3.
        let m = multi_bounce_closed_form(0.25, Vec3::new(0.8, 0.0, 0.0));
        assert!((m.x - 0.625).abs() < 1e-6 && m.y == 0.25);
        assert!((multi_bounce_closed_form(0.5, Vec3::splat(0.5)).x - 2.0 / 3.0).abs() < 1e-6);
    }

    #[test]
    fn closed_form_sums_the_bounces() {
        // The closed form is the limit of bouncing light around explicitly: each bounce returns
        // the fraction albedo (1 - k) of the previous one from the occluded directions.
        for x in [0.1, 0.4, 0.8] {
            for albedo in [0.2, 0.6, 0.9] {
                let (mut bounce, mut total) = (x, 0.0);
                for _ in 0..400 {
                    total += bounce;
                    bounce *= albedo * (1.0 - x);
                }
                let m = multi_bounce_closed_form(x, Vec3::splat(albedo)).x;
                assert!((m - total).abs() < 1e-5, "{x}, {albedo}: {m} vs {total}");
            }
        }
    }

    /// Largest `closed form - fit` over visibilities and albedos in steps of 0.01, albedo up to
    /// `max_albedo`, with where it happens: (difference, visibility, albedo).
    fn largest_difference(max_albedo: f32) -> (f32, f32, f32) {
        let mut worst = (0.0f32, 0.0, 0.0);
        for i in 0..=100 {
            for j in 0..=(max_albedo * 100.0).round() as i32 {
                let (x, albedo) = (i as f32 / 100.0, Vec3::splat(j as f32 / 100.0));
                let d = (multi_bounce_closed_form(x, albedo) - multi_bounce_gtao(x, albedo)).x;
                if d.abs() > worst.0.abs() {
                    worst = (d, x, albedo.x);
                }
            }
        }
        worst
    }

    #[test]
    fn closed_form_against_the_gtao_fit() {
        // Both are the visibility itself for black surroundings, within the fit's 1e-5.
        for i in 0..=1000 {
            let x = i as f32 / 1000.0;
            let d = multi_bounce_closed_form(x, Vec3::ZERO) - multi_bounce_gtao(x, Vec3::ZERO);
            assert!(d.abs().max_element() < 1e-5, "{x}: {d}");
        }
        // Up to albedo 0.5 they stay within 0.025 of each other; above, the closed form's
        // infinitely many same-albedo bounces brighten dark, bright corners far more than the
        // fitted data did. The figures docs/composite.md quotes:
        let everywhere = largest_difference(1.0);
        let up_to_08 = largest_difference(0.8);
        let up_to_05 = largest_difference(0.5);
        println!(
            "closed form - GTAO fit, largest: {everywhere:?} (albedo <= 1), \
             {up_to_08:?} (<= 0.8), {up_to_05:?} (<= 0.5)"
        );
        assert!(up_to_05.0.abs() < 0.025, "{up_to_05:?}");
        assert!((up_to_08.0 - 0.1025).abs() < 1e-3, "{up_to_08:?}");
        assert!((everywhere.0 - 0.966).abs() < 1e-3, "{everywhere:?}");
    }

    #[test]
    fn frostbite_bounds_and_monotonicity() {
        for n_dot_v in GRID {
            for roughness in GRID {
                assert_eq!(specular_occlusion_frostbite(n_dot_v, 1.0, roughness), 1.0);
                assert_eq!(specular_occlusion_frostbite(n_dot_v, 0.0, roughness), 0.0);
                let mut last = 0.0;
                for i in 0..=100 {
                    let so = specular_occlusion_frostbite(n_dot_v, i as f32 / 100.0, roughness);
                    assert!(so >= last, "n.v {n_dot_v}, roughness {roughness}");
                    last = so;
                }
            }
        }
        // Smooth surfaces at grazing angles are darker than AO, rough ones close to it.
        // sqrt(0.5) - 1 + 0.5 = 0.2071.
        assert!((specular_occlusion_frostbite(0.0, 0.5, 0.0) - 0.2071).abs() < 1e-4);
        assert!((specular_occlusion_frostbite(0.1, 0.6, 1.0) - 0.6).abs() < 1e-3);
    }

    #[test]
    fn gtso_limits() {
        let n = Vec3::new(0.3, -0.2, 0.9).normalize();
        let away = (-n + Vec3::new(0.1, 0.0, 0.0)).normalize();
        for roughness in GRID {
            assert_eq!(specular_occlusion_gtso(n, n, 1.0, roughness), 1.0);
            assert_eq!(specular_occlusion_gtso(n, n, 0.0, roughness), 0.0);
            // Continuous towards 0: the visibility cone of AO 1e-6 (1 - cos = 5e-7) still covers
            // 0.5% of the narrowest specular cone (1 - cos = 1e-4, MAX_SPECULAR_CONE_COS).
            assert!(specular_occlusion_gtso(n, n, 1e-6, roughness) < 0.01);
            for ao in GRID {
                assert_eq!(specular_occlusion_gtso(n, -n, ao, roughness), 0.0);
                assert_eq!(specular_occlusion_gtso(n, away, ao, roughness), 0.0);
            }
        }
    }

    #[test]
    fn gtso_falls_as_the_reflection_leaves_the_visibility_cone() {
        for roughness in [0.0, 0.3, 0.6, 1.0] {
            for ao in [0.2, 0.5, 0.9] {
                let mut last = f32::INFINITY;
                for degrees in 0..=180 {
                    let t = (degrees as f32).to_radians();
                    let r = Vec3::new(t.sin(), 0.0, t.cos());
                    let so = specular_occlusion_gtso(Vec3::Z, r, ao, roughness);
                    assert!(so <= last, "roughness {roughness}, ao {ao}, {degrees} deg");
                    last = so;
                }
            }
        }
    }

    #[test]
    fn rougher_surfaces_depend_less_on_the_direction() {
        // Over reflection directions across the hemisphere, a mirror's SO jumps between 1 (inside
        // the visibility cone) and 0; a rough lobe straddles the cone's edge, so SO varies less
        // steeply and stays closer to the AO value on average.
        for ao in [0.3, 0.5, 0.7] {
            let stats = |roughness: f32| {
                let values: Vec<f32> = (0..=90)
                    .map(|degrees| {
                        let t = (degrees as f32).to_radians();
                        let r = Vec3::new(t.sin(), 0.0, t.cos());
                        specular_occlusion_gtso(Vec3::Z, r, ao, roughness)
                    })
                    .collect();
                let steepest = values
                    .windows(2)
                    .map(|w| (w[0] - w[1]).abs())
                    .fold(0.0, f32::max);
                let distance = values.iter().map(|v| (v - ao).abs()).sum::<f32>();
                (steepest, distance / values.len() as f32)
            };
            let (smooth, rough) = (stats(0.1), stats(0.9));
            assert!(rough.0 < 0.5 * smooth.0, "ao {ao}: {rough:?} vs {smooth:?}");
            assert!(rough.1 < smooth.1, "ao {ao}: {rough:?} vs {smooth:?}");
        }
    }

    #[test]
    fn gtso_is_finite_and_in_range_for_degenerate_inputs() {
        let vectors = [
            Vec3::ZERO,
            Vec3::Z,
            -Vec3::Z,
            Vec3::new(1e-9, 0.0, 0.0),
            Vec3::new(3.0, -4.0, 0.5),
            Vec3::splat(f32::NAN),
            Vec3::new(f32::INFINITY, 0.0, 0.0),
        ];
        let scalars = [
            f32::NAN,
            -1.0,
            0.0,
            1e-8,
            0.5,
            1.0 - 1e-7,
            1.0,
            2.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        for b in vectors {
            for r in vectors {
                for ao in scalars {
                    for roughness in scalars {
                        let so = specular_occlusion_gtso(b, r, ao, roughness);
                        assert!((0.0..=1.0).contains(&so), "{b} {r} {ao} {roughness}: {so}");
                        let fb = specular_occlusion_frostbite(ao, roughness, ao);
                        assert!((0.0..=1.0).contains(&fb), "{ao} {roughness}: {fb}");
                        for m in [multi_bounce_gtao(ao, b), multi_bounce_closed_form(ao, b)] {
                            assert!(
                                m.is_finite()
                                    && m.cmpge(Vec3::ZERO).all()
                                    && m.cmple(Vec3::ONE).all()
                            );
                        }
                    }
                }
            }
        }
        // An unknown direction counts as coaxial cones.
        assert_eq!(specular_occlusion_gtso(Vec3::ZERO, Vec3::Z, 1.0, 0.5), 1.0);
    }
}
