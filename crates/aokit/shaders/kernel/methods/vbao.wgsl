// requires: common/view.wgsl, common/ao.wgsl, common/ao_entry.wgsl, common/slice.wgsl
// Visibility bitmask ambient occlusion (Therrien, Levesque and Gilet 2023, "Screen Space
// Indirect Lighting with Visibility Bitmask"), on GTAO's slices.
//
// A horizon method treats the depth buffer as a height field: whatever rises above the horizon
// hides everything behind it. Here every sample is an occluder of finite thickness instead: it
// hides the angles between its front face (the depth buffer) and its back face (the same point
// `thickness` further along its view ray). Each slice keeps 32 sectors of the normal's hemisphere
// as bits; a sample sets the bits its span covers, and light passes through the gaps, behind
// thin pillars and fences. Samples on one continuous surface also occlude the angles between
// them (see side_bits), so solids stay as dark as GTAO makes them with few samples.

const SECTORS: u32 = 32u;
// How far, in sectors, a span may reach into the hemisphere from its edge and still occlude
// nothing (span_bits). Samples on an open plane lie at its edge, the tangent, but come out up
// to about a quarter of a sector inside it (0.1 left the `open` scene at RMSE 0.0011, 0.25 at
// 0), and outward rounding made each of them occlude a whole sector: AO 0.997 on open ground
// where GTAO, whose clamped horizons weigh such errors by the cosine, gives 1.
const EDGE: f32 = 0.25;

// Bit of `ao.flags` for `vbao.back_faces` (uniforms.rs, `flags::BACK_FACES`).
const FLAG_BACK_FACES: u32 = 8u;

// With FLAG_BACK_FACES, each working texel's measured occluder thickness (back_faces.wgsl):
// MAX_DEPTH where the occluder is solid, 0 where nothing was measured. A 1x1 stand-in
// otherwise, never read.
@group(0) @binding(10) var back_thickness: texture_2d<f32>;

// Antiderivative of cos(t - n) |sin t| that is 0 at t = 0: arc_integral signed by the side.
fn arc_measure(t: f32, n: f32) -> f32 {
    return select(-1.0, 1.0, t >= 0.0) * arc_integral(t, n);
}

// Antiderivatives of cos(t) and sin(t) times cos(t - n) |sin t| (see bent_in_slice in gtao),
// signed by the side like arc_measure, for the mean unoccluded direction.
fn bent_measure(t: f32, n: f32) -> vec2<f32> {
    let cn = cos(n);
    let sn = sin(n);
    let c = cos(t);
    let s = sin(t);
    let a = (-cn * c * c * c + sn * s * s * s) / 3.0 + cn / 3.0;
    let b = cn * s * s * s / 3.0 + sn * (c * c * c / 3.0 - c) + 2.0 * sn / 3.0;
    return select(-1.0, 1.0, t >= 0.0) * vec2<f32>(a, b);
}

// Sector bits that the angle span [a, b] (radians from V) touches, sectors being equal angles of
// the hemisphere [lo, lo + pi]. Rounding outwards, as the paper does, makes every sample occlude
// at least one sector: with a few samples per slice that balances the light that leaks between
// them. A span reaching less than EDGE into the hemisphere from either edge touches nothing.
fn span_bits(a: f32, b: f32, lo: f32) -> u32 {
    let x0 = (min(a, b) - lo) / PI * f32(SECTORS);
    let x1 = (max(a, b) - lo) / PI * f32(SECTORS);
    let first = i32(floor(select(x0, f32(SECTORS), x0 > f32(SECTORS) - EDGE)));
    let last = i32(ceil(select(x1, 0.0, x1 < EDGE))) - 1;
    let start = clamp(first, 0, i32(SECTORS));
    let end = clamp(last + 1, 0, i32(SECTORS));
    if end <= start {
        return 0u;
    }
    let count = u32(end - start);
    return select((1u << count) - 1u, 0xffffffffu, count == SECTORS) << u32(start);
}

// Occluded sectors from the samples on one side of a slice (side = +1 or -1).
//
// With a few samples per side, spans of finite thickness leave gaps in front of solid surfaces:
// the foot of a wall between a floor sample and a wall sample stays open. Where two consecutive
// samples (the first with the shaded point) lie less than a thickness apart in depth, the
// surface between them is taken as continuous and the angles between them are occluded too, as
// a height field would have it; a depth jump of more than a thickness, a thin object in front of
// what lies behind it, keeps its gaps.
fn side_bits(s: Surface, slice: Slice, side: f32, jitter: f32, lo: f32) -> u32 {
    var bits = 0u;
    // The hemisphere's edge on this side, and the shaded point as the chain's first link.
    var previous_angle = slice.angle_n + side * HALF_PI;
    var previous_depth = s.depth;
    let measured = (ao.flags & FLAG_BACK_FACES) != 0u;
    let march = begin_side(s, slice, side);
    let steps = step_count();
    for (var step = 0u; step < steps; step++) {
        let distance_px = step_distance(step, steps, jitter, s.radius_px);
        let sample = slice_method_sample(s, slice, march, distance_px);
        if sample.w == 0.0 || dot(sample.xyz, sample.xyz) >= s.radius * s.radius {
            previous_depth = -1.0;
            continue;
        }
        let front = s.p + sample.xyz;
        let front_depth = -front.z;
        var thickness = ao.thickness * s.scale + ao.thickness_growth * front_depth;
        if measured {
            let texel = vec2<u32>(side_position(s, slice, side, distance_px));
            thickness = max(thickness, textureLoad(back_thickness, texel, 0).r);
        }
        // The back face lies further along the ray from the eye through the front face; a
        // solid occluder's lies at the end of that ray, seen in the ray's own direction.
        let back = select(front * ((front_depth + thickness) / front_depth),
                          front - vec3<f32>(0.0, 0.0, thickness), view.orthographic > 0.5);
        let ray = select(normalize(front), vec3<f32>(0.0, 0.0, -1.0), view.orthographic > 0.5);
        let to_back = select(back - s.p, ray, thickness == MAX_DEPTH);
        // Cosines from inverse square roots, not length() and a division: one special
        // function each where those take two.
        let front_cos = dot(sample.xyz, s.v) * inverseSqrt(dot(sample.xyz, sample.xyz));
        let back_cos = dot(to_back, s.v) * inverseSqrt(dot(to_back, to_back));
        let front_angle = side * fast_acos(front_cos);
        let back_angle = side * fast_acos(back_cos);
        bits |= span_bits(front_angle, back_angle, lo);
        if abs(front_depth - previous_depth) < thickness {
            bits |= span_bits(previous_angle, front_angle, lo);
        }
        previous_angle = front_angle;
        previous_depth = front_depth;
    }
    return bits;
}

fn estimate(surface: Surface, noise: vec2<f32>) -> Estimate {
    let bent_wanted = BENT_NORMALS;

    var visible = 0.0;
    var unoccluded = 0.0;
    var bent = vec3<f32>(0.0);
    let slices = slice_count();
    for (var i = 0u; i < slices; i++) {
        let slice = make_slice(surface, (f32(i) + noise.x) * PI / f32(slices));
        let n = slice.angle_n;
        let lo = n - HALF_PI;
        let jitter = fract(noise.y + f32(i) * GOLDEN_FRACTION);
        let occluded = side_bits(surface, slice, 1.0, jitter, lo)
            | side_bits(surface, slice, -1.0, fract(jitter + 0.5), lo);
        unoccluded += slice.n_len * (arc_measure(lo + PI, n) - arc_measure(lo, n));
        if bent_wanted {
            // Only the occluded part's direction is taken from the slice; see open_bent.
            let d = bent_measure(lo, n) - bent_measure(lo + PI, n);
            bent += slice.n_len * (d.x * surface.v + d.y * slice.tangent);
        }
        // Integrate the runs of visible sectors in closed form, one run per loop.
        var open = ~occluded;
        while open != 0u {
            let start = countTrailingZeros(open);
            let run = countTrailingZeros(~(open >> start));
            let end = start + run;
            let a = lo + f32(start) * PI / f32(SECTORS);
            let b = lo + f32(end) * PI / f32(SECTORS);
            visible += slice.n_len * (arc_measure(b, n) - arc_measure(a, n));
            if bent_wanted {
                let d = bent_measure(b, n) - bent_measure(a, n);
                bent += slice.n_len * (d.x * surface.v + d.y * slice.tangent);
            }
            open = select(open & ~(((1u << run) - 1u) << start), open & ~(0xffffffffu << start), end == SECTORS);
        }
    }
    return Estimate(select(1.0, visible / unoccluded, unoccluded > 0.0), bent + open_bent(surface.n, unoccluded));
}
