// requires: common/view.wgsl, common/noise.wgsl, common/ao.wgsl, common/ao_entry.wgsl
// Crytek's screen-space AO (Mittring 2007, "Finding Next Gen: CryEngine 2"), as the
// UnityCrytekSponza-master2019 project (Graphic-researcher, GitHub) builds it: points spread
// through a sphere around the shaded point, each tested against the depth buffer. Normals are not
// used. Half of a sphere centred on a flat surface lies behind it, so a flat wall reads about 0.5:
// the grey look of 2007, kept as it was.

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    // A per-pixel rotation of the kernel about the view axis.
    let rotation = vec2<f32>(cos(TWO_PI * noise.x), sin(TWO_PI * noise.x));
    var occlusion = 0.0;
    for (var i = 0u; i < ao.count; i++) {
        // Uniform directions over the sphere, lengths from 0.1 to 1 of the radius with more
        // samples near the centre (the quadratic kernel of Chapman 2013, "SSAO Tutorial").
        let u = sobol_2d(i);
        let z = 1.0 - 2.0 * u.x;
        let phi = TWO_PI * u.y;
        let r_xy = sqrt(max(1.0 - z * z, 0.0));
        let d = vec3<f32>(r_xy * cos(phi), r_xy * sin(phi), z);
        let rotated = vec3<f32>(rotation.x * d.x - rotation.y * d.y, rotation.y * d.x + rotation.x * d.y, d.z);
        let t = fract(halton_3(i + 1u) + noise.y);
        let sample = surface.p + surface.radius * mix(0.1, 1.0, t * t) * rotated;
        if view.orthographic < 0.5 && sample.z >= 0.0 {
            continue;
        }
        let at = pixel_of(sample);
        let occluder = depth_at(at, mip_level(length(at - surface.center)));
        if occluder == NO_SURFACE {
            continue;
        }
        // Range check: a surface far in front of the sample, an object in the foreground, is not
        // inside the sphere and does not shadow the point. The UnityCrytekSponza-master2019 shader
        // measures that distance from the shaded point's depth instead, which on a plane seen at a
        // grazing angle rejects the plane's own far half and lightens it.
        let sample_depth = -sample.z;
        let blocked = occluder + ao.bias * surface.scale < sample_depth;
        occlusion += select(0.0, falloff_weight(surface, sample_depth - occluder), blocked);
    }
    return Estimate(1.0 - occlusion / f32(ao.count), surface.n);
}
