// requires: common/view.wgsl, common/noise.wgsl, common/ao.wgsl, common/ao_entry.wgsl
// requires: common/subsample_chain.wgsl
// Scalable Ambient Obscurance (McGuire, Mara and Luebke, HPG 2012): `ao.count` taps on a
// spiral of `ao.steps` turns around the pixel (spiral.rs chooses the turns), each read from the
// depth MIP level its distance calls for, scored by the paper's obscurance estimator. Binding
// `linear_depth` holds the MIP chain (passes/kernel/depth_mips.rs), whose level 0 is the working
// depth every shared function reads.

// Taps within 2^3 = 8 pixels read level 0; each doubling of the distance beyond reads one level
// coarser (the paper's LOG_MAX_OFFSET, its q' = 8). Far taps of neighbouring pixels then land
// on the same or neighbouring texels of their level instead of pixels far apart, so a wide
// radius costs no more texture cache than a small one; the paper found 8 to 32 pixels best.
const LOG_MAX_OFFSET: i32 = 3;
// The paper's epsilon, 0.01 m^2 at its 1 m radius, here relative to r^2 so that the estimate
// does not depend on the scene's units: it keeps a tap right next to the point from dividing by
// almost nothing, which would blacken creases.
const EPSILON: f32 = 0.01;
// The paper's scale of the sum: visibility = 1 - 5 sigma / N * sum, with its intensity sigma
// = 1 (`intensity` and `power` shape the result afterwards, as for every method).
const SUM_SCALE: f32 = 5.0;

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    let count = f32(ao.count);
    let r = surface.radius;
    let r2 = r * r;
    let bias = ao.bias * surface.scale;
    let epsilon = EPSILON * r2;
    let spin = TWO_PI * noise.x;
    let coarsest = min(i32(CHAIN_COARSEST), i32(textureNumLevels(linear_depth)) - 1);
    var sum = 0.0;
    for (var i = 0u; i < ao.count; i++) {
        let alpha = (f32(i) + 0.5) / count;
        let angle = alpha * f32(ao.steps) * TWO_PI + spin;
        let distance = alpha * surface.radius_px;
        let tap = floor(surface.center + distance * vec2<f32>(cos(angle), sin(angle)));
        if any(tap < vec2<f32>(0.0)) || any(tap >= view.size) {
            continue;
        }
        // floor(log2) of at least 1 pixel, so that taps inside the pixel stay finite.
        let steps_out = i32(floor(log2(max(distance, 1.0))));
        let level = u32(clamp(steps_out - LOG_MAX_OFFSET, 0, coarsest));
        // An odd side leaves the last pixels past the coarser level's last texel.
        let texel = min(vec2<u32>(tap) >> vec2<u32>(level), textureDimensions(linear_depth, level) - 1u);
        // Levels as i32: naga's GLSL output checks a load against textureSize(image, level), which
        // takes no u32 (wgpu's GL backend).
        let depth = textureLoad(linear_depth, texel, i32(level)).r;
        if depth == NO_SURFACE {
            continue;
        }
        // Placed at the centre of the pixel the depth came from, the tap lies exactly on the
        // surface seen there, so a plane never occludes itself at any level.
        let q = view_position(vec2<f32>(subsample_source(texel, level)) + 0.5, depth);
        let v = q - surface.p;
        let vv = dot(v, v);
        // The paper's f = max(r^2 - v.v, 0)^3 max((v.n - bias) / (v.v + epsilon), 0), divided
        // by r^6 as the paper does and multiplied by r: the paper leaves the last factor in
        // inverse metres (tuned at r = 1 m), here it is in inverse radii.
        let falloff = max(1.0 - vv / r2, 0.0);
        sum += falloff * falloff * falloff * r * max((dot(v, surface.n) - bias) / (vv + epsilon), 0.0);
    }
    return Estimate(max(0.0, 1.0 - sum * SUM_SCALE / count), surface.n);
}
