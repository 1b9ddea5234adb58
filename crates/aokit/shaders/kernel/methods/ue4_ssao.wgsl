// requires: common/view.wgsl, common/ao.wgsl, common/ao_entry.wgsl
// Unreal Engine 4's legacy SSAO (PostProcessAmbientOcclusion.usf, Epic Games): despite the name it
// works like HBAO. Each of `ao.count` pairs takes two depth samples mirrored about the pixel
// along one screen direction, and the pair occludes by how far the angle it spans at the pixel
// closes below a straight line (`WedgeNoNormal`). Samples read a hierarchical depth buffer
// (`GetHZBDepth`): binding `linear_depth` holds the furthest-depth MIP chain
// (passes/kernel/depth_mips.rs), whose level 0 is the working depth every shared function reads.
//
// View space here is right-handed with the eye looking down -z (Unreal's code is
// left-handed, +z forward); `depth` is linear depth, -z. For the pixel P and the sample
// positions L and R, with dL = L - P and dR = R - P:
//
//   depth-only:  o = 1 - acos(dL.dR / (|dL| |dR|)) / pi          (Unreal's NormAngle, 0..1)
//                o = 0 when (L.z - P.z) + (R.z - P.z) < bias      (flat-surface bias, "fix
//                                                                  concave case")
//   normal:      o = (asin(sat(n.dL / |dL|)) + asin(sat(n.dR / |dR|))) / pi
//   weight:      w(S) = sat(1 - (S.z - P.z) / r), shaped by our falloff (1: exactly this)
//   visibility = 1 - sum over pairs of w o / count
//
// `shape_ao` then applies intensity and power as for every method.

// Bit of `ao.flags` for the normal version (uniforms.rs, `flags::UE4_SSAO_NORMALS`).
const FLAG_UE4_SSAO_NORMALS: u32 = 4u;
// Samples within 2^3 = 8 pixels read level 0; each doubling of the distance beyond reads one
// level coarser, as in sao.wgsl. A level-k texel then spans at most 1/8 of the sample's
// distance from the pixel, so the furthest depth of that block moves the sample by no more than
// the surface's depth change over an eighth of the way: a small error in the pair's angle,
// while neighbouring pixels' far samples share texels and the cache.
const LOG_MAX_OFFSET: i32 = 3;
// Coarsest level the chain holds.
const MAX_MIP_LEVEL: i32 = 4;

// One sample of a pair: the view-space position it reconstructs, and whether there is one (on
// screen, with a surface).
struct Sample {
    q: vec3<f32>,
    found: bool,
}

// The sample `offset` pixels from the pixel, read from the level its distance calls for. The chain
// keeps the furthest depth of each block, which Unreal's hierarchical Z read (`GetHZBDepth`) itself
// leaves open between furthest and nearest. Furthest, because a depth can only push the sample away
// from the eye: on a plane the two samples of a pair then lie on or behind it at every level (depth
// is convex along screen lines across a plane, so the furthest depth of a block is at least the
// plane's depth at any pixel in it), and the flat-surface test and the tangent plane keep planes
// unoccluded however coarse the level. The nearest depth would pull the samples of a sloped floor
// up out of it and make it occlude itself; furthest loses thin occluders at coarse levels instead.
fn pair_sample(s: Surface, offset: vec2<i32>, distance: f32, coarsest: i32) -> Sample {
    let tap = vec2<i32>(s.pixel) + offset;
    if any(tap < vec2<i32>(0)) || any(vec2<f32>(tap) >= view.size) {
        return Sample(vec3<f32>(0.0), false);
    }
    // floor(log2) of at least 1 pixel, so that samples next to the pixel stay finite.
    let steps_out = i32(floor(log2(max(distance, 1.0))));
    let level = u32(clamp(steps_out - LOG_MAX_OFFSET, 0, coarsest));
    // An odd side leaves the last pixels past the coarser level's last texel.
    let texel = min(vec2<u32>(tap) >> vec2<u32>(level), textureDimensions(linear_depth, level) - 1u);
    // Levels as i32: naga's GLSL output checks a load against textureSize(image, level), which
    // takes no u32 (wgpu's GL backend).
    let depth = textureLoad(linear_depth, texel, i32(level)).r;
    // Placed at the sample's own pixel, as Unreal's ReconstructCSPos(AbsL, ScreenSpacePosL):
    // the two samples stay mirrored about the pixel at every level.
    return Sample(view_position(vec2<f32>(tap) + 0.5, depth), depth != NO_SURFACE);
}

// Unreal's distance weight: 1 for a sample level with or behind the pixel, fading linearly to 0 as
// it rises towards the eye by the radius, so that a foreground object far in front does not draw a
// halo on what is behind it ("to avoid halos around objects"). Unreal's fade distance is its own
// AmbientOcclusionDistance; ours is the radius, so that one length bounds the effect as for every
// method, and `falloff` shapes it as it does theirs (at the preset's 1 the ramp runs over the whole
// radius, as Unreal's does).
fn rise_weight(s: Surface, q: vec3<f32>) -> f32 {
    return falloff_weight(s, max(q.z - s.p.z, 0.0));
}

// Elevation of the sample above the tangent plane of `n`, radians in [0, pi/2]: a sample below
// the plane (a ridge, or a plane's own samples) does not occlude.
fn elevation(s: Surface, d: vec3<f32>) -> f32 {
    return asin(saturate(dot(d, s.n) * inverseSqrt(max(dot(d, d), 1e-30))));
}

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    let count = f32(ao.count);
    let normals = (ao.flags & FLAG_UE4_SSAO_NORMALS) != 0u;
    // Unreal's FlatSurfaceBias (5 units), here the `bias` setting in world units,
    // scaled like the radius where the pixel clamps widened or narrowed it.
    let flat_bias = ao.bias * surface.scale;
    let coarsest = min(MAX_MIP_LEVEL, i32(textureNumLevels(linear_depth)) - 1);
    var occlusion = 0.0;
    for (var i = 0u; i < ao.count; i++) {
        // Unreal's samples lie on a ring of directions rotated per pixel by a random vector
        // (OcclusionSamplesOffsets, RandomNormalTexture), in "spiral order and distance", with
        // even steps. A pair covers its direction and the opposite one, so the directions split
        // the half circle evenly, and the distance grows with them in even steps: both jittered
        // by the pixel's noise.
        let angle = PI * (f32(i) + noise.x) / count;
        let distance = max(surface.radius_px * (f32(i) + noise.y) / count, 1.0);
        // Rounded once and mirrored, so both samples sit at exactly opposite pixels. At least
        // one pixel away: max(|cos|, |sin|) >= 0.7 rounds to 1 in one coordinate.
        let offset = vec2<i32>(round(distance * vec2<f32>(cos(angle), sin(angle))));
        let left = pair_sample(surface, offset, distance, coarsest);
        let right = pair_sample(surface, -offset, distance, coarsest);
        let dl = left.q - surface.p;
        let dr = right.q - surface.p;
        if normals {
            // Not a port of Unreal's normal version (WedgeWithNormal). Ours measures each side's
            // angle from the tangent plane instead of from the other sample, the HBAO form (Bavoil
            // and Sainz 2008: sin(S) - sin(T), with T in the tangent plane), kept as an angle so
            // that a pair spanning a crease scores as in the depth-only version: a side rising to
            // the normal closes a quarter turn, half the pair's half turn. A side without a sample
            // closes nothing.
            if left.found {
                occlusion += rise_weight(surface, left.q) * elevation(surface, dl) / PI;
            }
            if right.found {
                occlusion += rise_weight(surface, right.q) * elevation(surface, dr) / PI;
            }
            continue;
        }
        // The depth-only version needs both sides to span an angle.
        if !(left.found && right.found) {
            continue;
        }
        // Not 100% correct but simple, as Unreal's comment says: the angle alone cannot tell a
        // crease (occluding) from a ridge (not), and a plane spans exactly a half turn only with
        // exact depths. The pair occludes only where its samples together rise towards the eye
        // by more than the bias above the pixel; on a plane their rises sum to at most 0
        // (depth is convex along the line between them), on a ridge they are negative.
        if (left.q.z - surface.p.z) + (right.q.z - surface.p.z) < flat_bias {
            continue;
        }
        // Unreal's NormAngle: the angle at the pixel between the two samples over pi, 1 for a
        // straight line through the pixel, 0 for both samples in the same direction.
        let cosine = dot(dl, dr) * inverseSqrt(max(dot(dl, dl) * dot(dr, dr), 1e-30));
        let norm_angle = acos(clamp(cosine, -1.0, 1.0)) / PI;
        // Unreal multiplies the two samples' weights into the pair's.
        let weight = rise_weight(surface, left.q) * rise_weight(surface, right.q);
        occlusion += weight * (1.0 - norm_angle);
    }
    // Unreal returns (occlusion / (weight + 0.001), weight) per pair to its caller; ours
    // counts a faded pair as unoccluded, so that a halo fades out instead of the
    // remaining pairs' occlusion growing to fill it.
    return Estimate(saturate(1.0 - occlusion / count), surface.n);
}
