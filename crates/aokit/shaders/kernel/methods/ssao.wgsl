// requires: common/view.wgsl, common/noise.wgsl, common/ao.wgsl, common/ao_entry.wgsl
// Normal-oriented hemisphere SSAO (after Chapman 2013, "SSAO Tutorial", with the cosine-weighted
// directions of ybniaobu's Unity YPipeline): cosine-weighted points in the hemisphere of the
// normal, each tested against the depth buffer. With directions drawn with density cos(theta) / pi,
// the fraction of unoccluded points estimates the cosine-weighted visibility directly.

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    // A per-pixel random rotation of the tangent frame about the normal.
    let frame = tangent_frame(surface.n);
    let angle = TWO_PI * noise.x;
    let tangent = cos(angle) * frame[0] + sin(angle) * frame[1];
    let bitangent = cross(surface.n, tangent);
    var visible = 0.0;
    var total = 0.0;
    for (var i = 0u; i < ao.count; i++) {
        let local = cosine_hemisphere(sobol_2d(i));
        // Lengths r = xi^2 crowd samples near the point, where occluders matter most: an
        // implicit distance falloff.
        let xi = fract(halton_3(i + 1u) + noise.y);
        let offset = xi * xi * (local.x * tangent + local.y * bitangent + local.z * surface.n);
        // The weight of the SSAO shader of the UnityCrytekSponza-master2019 project
        // (Graphic-researcher, GitHub): a sample that projects (almost) onto the pixel itself
        // compares the surface with itself and says nothing.
        let weight = smoothstep(0.0, 0.2, length(offset.xy));
        total += weight;
        let sample = surface.p + surface.radius * offset;
        if view.orthographic < 0.5 && sample.z >= 0.0 {
            visible += weight;
            continue;
        }
        let at = pixel_of(sample);
        let occluder = depth_at(at, mip_level(length(at - surface.center)));
        let sample_depth = -sample.z;
        // Occluded when the depth buffer lies in front of the point by more than the bias
        // (self-occlusion of a plane stored at finite precision), and within range of it.
        let blocked = occluder != NO_SURFACE && occluder + ao.bias * surface.scale < sample_depth;
        let occlusion = select(0.0, falloff_weight(surface, sample_depth - occluder), blocked);
        visible += weight * (1.0 - occlusion);
    }
    return Estimate(select(1.0, visible / total, total > 0.0), surface.n);
}
