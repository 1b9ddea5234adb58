// requires: common/noise.wgsl, common/ao.wgsl, common/slice.wgsl
// HBAO's horizon term along one screen direction (the formula is in hbao.wgsl), shared by the
// per-pixel kernel (hbao.wgsl) and the separable passes (hbao_separable.wgsl), which differ only
// in where a direction's samples come from: the depth texture, or a line of it in workgroup
// memory.

// One direction's march so far.
struct Horizon {
    // Sine of the highest elevation above the plane perpendicular to V so far: the tangent's
    // before the first sample that rises above it.
    sin_h: f32,
    // The sum over rising samples of W(r_k) (sin h_k - sin h_{k-1}).
    occlusion: f32,
}

// Samples per direction: never more than pixels in the radius, which would sample the same
// texels.
fn horizon_steps(s: Surface) -> u32 {
    return max(1u, min(step_count(), u32(s.radius_px)));
}

// The march along `slice` towards +omega before any sample. The projected normal lies at angle n
// from V, so the tangent on the +omega side lies at n + pi/2 from V, an elevation of -n; the
// angle bias raises it.
fn start_horizon(slice: Slice) -> Horizon {
    let tangent_angle = min(-slice.angle_n + ao.angle_bias, HALF_PI);
    return Horizon(sin(tangent_angle), 0.0);
}

// The march after the sample at `offset` from the shaded point of `s`: a sample inside the
// radius that rises above the horizon adds how much it raises it, weighed by the per-sample
// attenuation W(r) = 1 - r^2 / R^2, and becomes the horizon.
fn raise_horizon(horizon: Horizon, s: Surface, offset: vec3<f32>) -> Horizon {
    let r2 = s.radius * s.radius;
    let d2 = dot(offset, offset);
    let sin_h = dot(offset, s.v) * inverseSqrt(d2);
    if d2 < r2 && sin_h > horizon.sin_h {
        return Horizon(sin_h, horizon.occlusion + (1.0 - d2 / r2) * (sin_h - horizon.sin_h));
    }
    return horizon;
}
