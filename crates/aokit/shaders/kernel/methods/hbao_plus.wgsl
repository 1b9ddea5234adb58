// requires: common/noise.wgsl, common/ao.wgsl, common/ao_entry.wgsl, common/slice.wgsl
// HBAO+'s estimator (NVIDIA ShadowWorks HBAO+, 2014, its ComputeAO): the same ray march as hbao,
// but every sample occludes on its own by its elevation above the tangent plane, without tracking a
// horizon:
//
//   AO = 1 - 1/(N M) sum over samples saturate(N.w - sin(angle_bias)) W(r) / (1 - sin(angle_bias))
//
// with w the unit vector to the sample and W(r) = 1 - r^2 / R^2. Cheaper than the horizon
// bookkeeping, but the directions are marched in screen space while the estimate is about the
// normal's hemisphere: for a surface seen edge-on, the screen directions all run along the
// surface and most of the hemisphere above it goes unsampled, so AO fades there.

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    // Never more steps than pixels in the radius: they would sample the same texels.
    let steps = max(1u, min(step_count(), u32(surface.radius_px)));
    let directions = slice_count();
    let r2 = surface.radius * surface.radius;
    let bias = sin(ao.angle_bias);
    var occlusion = 0.0;
    for (var d = 0u; d < directions; d++) {
        let slice = make_slice(surface, (f32(d) + noise.x) * TWO_PI / f32(directions));
        let march = begin_side(surface, slice, 1.0);
        for (var k = 0u; k < steps; k++) {
            let distance = step_distance(k, steps, noise.y, surface.radius_px);
            let sample = slice_method_sample(surface, slice, march, distance);
            if sample.w == 0.0 {
                continue;
            }
            let d2 = dot(sample.xyz, sample.xyz);
            let n_dot_w = dot(surface.n, sample.xyz) * inverseSqrt(d2);
            occlusion += saturate(n_dot_w - bias) * saturate(1.0 - d2 / r2);
        }
    }
    // Average over the samples actually taken: a radius under `steps` pixels marches fewer.
    let taken = f32(directions * steps);
    return Estimate(1.0 - occlusion / (taken * (1.0 - bias)), surface.n);
}
