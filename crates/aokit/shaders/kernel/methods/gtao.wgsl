// requires: common/ao.wgsl, common/ao_entry.wgsl, common/slice.wgsl
// Ground-truth based ambient occlusion (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion"), in aokit's right-handed, -Z forward view space.
//
// Per pixel: a few slices (half-planes through the view vector V), each with a horizon search on
// both sides, then the cosine-weighted visible arc between the horizons integrated in closed form.

// Highest horizon cosines on the two sides of a slice, the +omega side in x and the -omega
// side in y, starting from the normal hemisphere's edges `low_cos`. The two sides step out to
// the same distances, so a step's distance serves both samples: with the jitter half a step
// apart between the sides (as it was), the error was no lower (GTAO `high`, seven tuning views
// 0.0749 -> 0.0747 mean RMSE filtered, ten held-out 0.0596 -> 0.0593).
fn search_horizons(s: Surface, slice: Slice, jitter: f32, low_cos: vec2<f32>) -> vec2<f32> {
    let ahead = begin_side(s, slice, 1.0);
    let behind = begin_side(s, slice, -1.0);
    let steps = step_count();
    var horizon_cos = low_cos;
    for (var step = 0u; step < steps; step++) {
        let distance_px = step_distance(step, steps, jitter, s.radius_px);
        horizon_cos = vec2<f32>(
            raise_horizon_cos(s, slice_method_sample(s, slice, ahead, distance_px), low_cos.x,
                              horizon_cos.x),
            raise_horizon_cos(s, slice_method_sample(s, slice, behind, distance_px), low_cos.y,
                              horizon_cos.y));
    }
    return horizon_cos;
}

// `ao.thickness`, compiled in as 0 where the lean march knows it is: the blend below then leaves
// the loop (the `ultra` preset's value), which keeps the larger of the horizon and the sample.
fn blend_thickness() -> f32 {
    return select(ao.thickness, 0.0, LEAN && !THICKNESS_BLEND);
}

// The horizon cosine `horizon_cos` on a side whose hemisphere edge is `low_cos`, after the
// sample `sample` (its offset from the shaded point; w = 0 for one with nothing to learn, which
// leaves the horizon as it was, without a branch).
fn raise_horizon_cos(s: Surface, sample: vec4<f32>, low_cos: f32, horizon_cos: f32) -> f32 {
    // One inverse square root gives the distance and the cosine (on an H100 GTAO `high`'s
    // kernel took 0.976 to 0.989 of the time of length() and a division).
    let d2 = dot(sample.xyz, sample.xyz);
    let inverse_distance = inverseSqrt(d2);
    let distance = d2 * inverse_distance;
    // Far samples fade towards the hemisphere's edge, so the radius has no hard rim.
    let sample_cos = mix(low_cos, dot(sample.xyz, s.v) * inverse_distance,
                         falloff_weight(s, distance));
    // Thickness heuristic (GTAO paper): a sample below the horizon pulls it back a little, as if
    // the occluder that raised it were only about as thick as it is wide. A sample above it
    // becomes the horizon: the blend never passes it, so the larger of the two is the result.
    let raised = max(sample_cos, mix(horizon_cos, sample_cos, blend_thickness()));
    // A sample lies off the shaded point, so its distance is positive, but its square
    // underflows to 0 at tiny depths (1e-30): the horizon would then be NaN, which reads as AO
    // 0. Such a sample says nothing.
    return select(horizon_cos, raised, sample.w > 0.0 & d2 > 0.0);
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
        let horizon_cos = search_horizons(surface, slice, jitter, vec2<f32>(-sin_n, sin_n));
        let cos_pos = horizon_cos.x;
        let cos_neg = horizon_cos.y;
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
