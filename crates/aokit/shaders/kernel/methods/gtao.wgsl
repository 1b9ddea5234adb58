// requires: common/ao.wgsl, common/ao_entry.wgsl, common/slice.wgsl
// Ground-truth based ambient occlusion (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion"), in aokit's right-handed, -Z forward view space.
//
// Per pixel: a few slices (half-planes through the view vector V), each with a horizon search on
// both sides, then the cosine-weighted visible arc between the horizons integrated in closed form.

// Highest horizon cosine on one side of a slice (side = +1 or -1), starting from the normal
// hemisphere's edge `low_cos`.
fn search_horizon(s: Surface, slice: Slice, side: f32, jitter: f32, low_cos: f32) -> f32 {
    if LEAN {
        return march_horizon(s, slice, side, jitter, low_cos);
    }
    var horizon_cos = low_cos;
    for (var step = 0u; step < ao.steps; step++) {
        let sample = side_sample(s, slice, side, step_distance(step, ao.steps, jitter, s.radius_px));
        // A sample lies off the shaded point (side_sample), so the distance is positive, but its
        // square underflows to 0 at tiny depths (1e-30): the inverse square root is then
        // infinite and the horizon NaN, which reads as AO 0. Such a sample says nothing.
        let d2 = dot(sample.xyz, sample.xyz);
        if sample.w == 0.0 || d2 == 0.0 {
            continue;
        }
        horizon_cos = raise_horizon(s, sample.xyz, d2, low_cos, horizon_cos);
    }
    return horizon_cos;
}

// search_horizon on the lean march: the same samples and the same horizon, with STEPS literal
// steps and no branch (a sample with nothing to learn leaves the horizon as it was).
fn march_horizon(s: Surface, slice: Slice, side: f32, jitter: f32, low_cos: f32) -> f32 {
    let m = begin_side(s, slice, side);
    var horizon_cos = low_cos;
    for (var step = 0u; step < STEPS; step++) {
        let distance_px = step_distance(step, STEPS, jitter, s.radius_px);
        let sample = march_sample(s, m, distance_px);
        let d2 = dot(sample.xyz, sample.xyz);
        // As in search_horizon, a squared distance that underflowed to 0 (depths near 1e-30)
        // would make the horizon NaN: such a sample leaves it as it was.
        horizon_cos = select(horizon_cos, raise_horizon(s, sample.xyz, d2, low_cos, horizon_cos),
                             sample.w > 0.0 & d2 > 0.0);
    }
    return horizon_cos;
}

// The horizon cosine `horizon_cos` after the sample at `offset` from the shaded point, of
// squared length d2 > 0.
fn raise_horizon(s: Surface, offset: vec3<f32>, d2: f32, low_cos: f32, horizon_cos: f32) -> f32 {
    // One inverse square root gives the distance and the cosine (on an H100 GTAO `high`'s
    // kernel took 0.976 to 0.989 of the time of length() and a division).
    let inverse_distance = inverseSqrt(d2);
    let distance = d2 * inverse_distance;
    // Far samples fade towards the hemisphere's edge, so the radius has no hard rim.
    let sample_cos = mix(low_cos, dot(offset, s.v) * inverse_distance, falloff_weight(s, distance));
    // Thickness heuristic (GTAO paper): a sample below the horizon pulls it back a little, as if
    // the occluder that raised it were only about as thick as it is wide. A sample above it
    // becomes the horizon: the blend never passes it, so the larger of the two is the result.
    return max(sample_cos, mix(horizon_cos, sample_cos, ao.thickness));
}

// Cosine-weighted mean direction of the visible arc [h_neg, h_pos] of a slice, in the slice's
// (V, tangent) basis: x along V, y along the tangent. With w = cos(t) V + sin(t) T weighted by
// cos(t - n) |sin t|, the antiderivatives of the two components are
//   a(t) = -cos(n) cos^3(t) / 3 + sin(n) sin^3(t) / 3
//   b(t) =  cos(n) sin^3(t) / 3 + sin(n) (cos^3(t) / 3 - cos(t)),
// and |sin t| flips the sign of the part below t = 0, so both sides add a(h) - a(0).
fn bent_in_slice(h_neg: f32, h_pos: f32, n: f32) -> vec2<f32> {
    let cn = cos(n);
    let sn = sin(n);
    let c = vec2<f32>(cos(h_neg), cos(h_pos));
    let s = vec2<f32>(sin(h_neg), sin(h_pos));
    let a = (-cn * c * c * c + sn * s * s * s) / 3.0;
    let b = cn * s * s * s / 3.0 + sn * (c * c * c / 3.0 - c);
    let a0 = -cn / 3.0;
    let b0 = -2.0 * sn / 3.0;
    return vec2<f32>(a.x + a.y - 2.0 * a0, b.x + b.y - 2.0 * b0);
}

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {

    var visible = 0.0;
    var unoccluded = 0.0;
    var bent = vec3<f32>(0.0);
    let slices = slice_count();
    for (var i = 0u; i < slices; i++) {
        let slice = make_slice(surface, (f32(i) + noise.x) * PI / f32(slices));
        let n = slice.angle_n;
        // Horizons start at the edge of the normal's hemisphere: cos(n + pi/2) = -sin(n) on the
        // +omega side, cos(n - pi/2) = sin(n) on the other.
        let sin_n = sin(n);
        let jitter = fract(noise.y + f32(i) * GOLDEN_FRACTION);
        let cos_pos = search_horizon(surface, slice, 1.0, jitter, -sin_n);
        let cos_neg = search_horizon(surface, slice, -1.0, fract(jitter + 0.5), sin_n);
        // Horizon angles, clamped to the normal's hemisphere.
        let h_pos = n + min(fast_acos(cos_pos) - n, HALF_PI);
        let h_neg = n + max(-fast_acos(cos_neg) - n, -HALF_PI);

        visible += slice.n_len * (arc_integral(h_neg, n) + arc_integral(h_pos, n));
        // The same slice with nothing in it, h = n -+ pi/2: |n_p| (cos n + n sin n).
        unoccluded += slice.n_len * (cos(n) + n * sin_n);
        if BENT_NORMALS {
            // Only the occluded part's direction is taken from the slice; see open_bent below.
            let b = bent_in_slice(h_neg, h_pos, n) - bent_in_slice(n - HALF_PI, n + HALF_PI, n);
            bent += slice.n_len * (b.x * surface.v + b.y * slice.tangent);
        }
    }

    // Each slice's unoccluded integral varies with its angle to the normal (from cos a to about
    // 1.5 for a normal tilted by a from V) and only averages to 1 over all slices, so a few random
    // slices are noisy even on an open plane. Dividing by the sum of the unoccluded integrals of
    // the same slices removes that noise; the estimate stays consistent because both sums
    // converge to their means. Backfacing normals make that sum small, where the plain average is
    // the safer estimate.
    let count = f32(slices);
    let use_ratio = (ao.flags & FLAG_NORMALIZE_SLICES) != 0u && unoccluded > 0.1 * count;
    let visibility = select(visible / count, visible / unoccluded, use_ratio);
    return Estimate(visibility, bent + open_bent(surface.n, unoccluded));
}
