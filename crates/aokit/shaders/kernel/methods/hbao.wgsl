// requires: common/ao.wgsl, common/ao_entry.wgsl, common/slice.wgsl, common/horizon.wgsl
// Horizon-based AO (Bavoil and Sainz 2008, "Image-Space Horizon-Based Ambient Occlusion"), as
// NVIDIA's DirectX 11 SDK sample (SSAO11) builds it: the depth buffer is a height field; along
// a few screen directions the horizon's elevation above the tangent plane says how much sky that
// direction has lost.
//
//   AO = 1 - 1/N sum over directions of sum over rising samples W(r) (sin h_k - sin h_{k-1})
//
// with h_0 = t, the tangent angle (biased by angle_bias), and W(r) = 1 - r^2 / R^2 the per-sample
// attenuation. Only a sample that raises the horizon adds, and only by how much it raises it,
// which keeps distant occluders from switching on abruptly. Elevations are measured from the
// plane perpendicular to V, the vector to the eye. Samples sit exactly on each direction's slice
// (see slice_sample), so a plane seen at a grazing angle does not occlude itself; the angle bias
// is left for tessellated curved surfaces, whose interpolated normals tilt off their facets.
// One direction's march is common/horizon.wgsl's, which the separable variant
// (hbao_separable.wgsl) shares.

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    let steps = horizon_steps(surface);
    let directions = slice_count();
    var occlusion = 0.0;
    for (var d = 0u; d < directions; d++) {
        let slice = make_slice(surface, (f32(d) + noise.x) * TWO_PI / f32(directions));
        let march = begin_side(surface, slice, 1.0);
        var horizon = start_horizon(slice);
        for (var k = 0u; k < steps; k++) {
            let distance = step_distance(k, steps, noise.y, surface.radius_px);
            let sample = slice_method_sample(surface, slice, march, distance);
            if sample.w != 0.0 {
                horizon = raise_horizon(horizon, surface, sample.xyz);
            }
        }
        occlusion += horizon.occlusion;
    }
    return Estimate(1.0 - occlusion / f32(directions), surface.n);
}
