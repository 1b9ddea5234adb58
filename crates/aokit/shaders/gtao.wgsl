// Ground-truth based ambient occlusion (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion"), in aokit's right-handed, -Z forward view space.
//
// Per pixel: a few slices (half-planes through the view vector V), each with a horizon search on
// both sides, then the cosine-weighted visible arc between the horizons integrated in closed form.

struct GtaoUniforms {
    // World-space radius.
    radius: f32,
    // Sample weight = saturate(distance * falloff_mul + falloff_add): 1 inside, 0 at the radius.
    falloff_mul: f32,
    falloff_add: f32,
    intensity: f32,
    power: f32,
    slice_count: u32,
    steps_per_side: u32,
    // 1: divide by the unoccluded slice integrals (see below); 0: plain average.
    normalize_slices: u32,
}

@group(0) @binding(1) var<uniform> gtao: GtaoUniforms;
@group(0) @binding(2) var linear_depth: texture_2d<f32>;
@group(0) @binding(3) var normals: texture_2d<u32>;
@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(5) var point_clamp: sampler;

const PI: f32 = 3.14159265;
const HALF_PI: f32 = 1.57079633;

// acos from a first-order polynomial times sqrt (Eberly 2014, as the GTAO paper uses it): at most
// 0.009 rad off, and no transcendental call. Errors vanish to first order in the result because
// the cosine weight is zero at the hemisphere's edge, where clamped horizons sit.
fn fast_acos(x: f32) -> f32 {
    let a = abs(x);
    let r = (HALF_PI - 0.156583 * a) * sqrt(1.0 - a);
    return select(PI - r, r, x >= 0.0);
}

// Integral of cos(theta - n) |sin(theta)| from 0 to h (for h < 0 the same expression is the
// integral from h to 0): the cosine-weighted visible arc on one side of V.
fn arc_integral(h: f32, n: f32) -> f32 {
    return 0.25 * (-cos(2.0 * h - n) + cos(n) + 2.0 * h * sin(n));
}

// Relative depth spread above which a 2x2 footprint is taken to straddle a depth edge. A plane
// seen 2 degrees from grazing spreads about 10% per pixel at 60 degrees field of view.
const DEPTH_EDGE: f32 = 0.1;

// Offset from `p` to the surface seen at continuous pixel position `q`, placed in the slice
// plane; w = 0 when there is no surface there.
//
// A sample must lie in the slice: texel centres sit up to half a texel off it, and on surfaces
// seen at grazing angles that sideways step is long in view space and runs towards the eye, so an
// open plane would occlude itself. Inside one surface, 1 / depth (perspective) or depth
// (orthographic) is affine in screen space across a plane, so interpolating it bilinearly at `q`
// gives a point exactly on the slice. Across a depth edge interpolation would invent a surface
// between foreground and background; there the nearest texel is read instead and slid within
// the pixel's tangent plane into the slice, which keeps its height above that plane, the part
// that occludes.
fn slice_sample(q: vec2<f32>, p: vec3<f32>, axis: vec3<f32>, slide: vec3<f32>) -> vec4<f32> {
    // The 2x2 texels around `q`, gathered at their shared corner: a coordinate there cannot
    // round into a neighbouring footprint the way `q` itself can near texel centres, so `f`
    // weights exactly the texels read. In the outermost half texel the footprint stays inside
    // the image and `f` extrapolates, which is exact on a plane where clamping is not. Gather
    // order: x = (left, bottom), y = (right, bottom), z = (right, top), w = (left, top), with
    // "top" the smaller row index.
    let corner = clamp(floor(q - 0.5) + 1.0, vec2<f32>(1.0), view.size - 1.0);
    let depths = textureGather(0, linear_depth, point_clamp, corner * view.inv_size);
    let f = q - 0.5 - (corner - 1.0);
    let lowest = min(min(depths.x, depths.y), min(depths.z, depths.w));
    let highest = max(max(depths.x, depths.y), max(depths.z, depths.w));
    if lowest > 0.0 && highest <= lowest * (1.0 + DEPTH_EDGE) {
        let ortho = view.orthographic > 0.5;
        let w = select(1.0 / depths, depths, ortho);
        let b = mix(mix(w.w, w.z, f.x), mix(w.x, w.y, f.x), f.y);
        return vec4<f32>(view_position(q, select(1.0 / b, b, ortho)) - p, 1.0);
    }
    let right = f.x >= 0.5;
    let bottom = f.y >= 0.5;
    let depth = select(select(depths.w, depths.z, right), select(depths.x, depths.y, right), bottom);
    if depth == NO_SURFACE {
        return vec4<f32>(0.0);
    }
    let texel_center = corner + select(vec2<f32>(-0.5), vec2<f32>(0.5), vec2<bool>(right, bottom));
    let off_slice = view_position(texel_center, depth) - p;
    return vec4<f32>(off_slice - dot(off_slice, axis) * slide, 1.0);
}

// Highest horizon cosine along one screen direction, starting from the normal hemisphere's edge.
fn search_horizon(center: vec2<f32>, p: vec3<f32>, v: vec3<f32>, n: vec3<f32>, axis: vec3<f32>,
                  side: vec3<f32>, step_px: vec2<f32>, radius_px: f32, jitter: f32,
                  low_cos: f32) -> f32 {
    let n_axis = dot(n, axis);
    // The tangent-plane direction that leaves the slice; its axis component is 1 - n_axis^2.
    // Where the slice is nearly tangent the slide would be long, but such slices carry a weight
    // |n_p| = sqrt(1 - n_axis^2) of at most 0.03.
    let slide = (axis - n * n_axis) / max(1.0 - n_axis * n_axis, 1e-3);
    var horizon_cos = low_cos;
    for (var step = 0u; step < gtao.steps_per_side; step++) {
        // Quadratic spacing puts more samples near the pixel, where occluders matter most;
        // starting one pixel out keeps the centre pixel from sampling itself.
        let t = (f32(step) + jitter) / f32(gtao.steps_per_side);
        let q = center + step_px * (1.0 + t * t * (radius_px - 1.0));
        if any(q < vec2<f32>(0.0)) || any(q >= view.size) {
            break;
        }
        let sample = slice_sample(q, p, axis, slide);
        // A slid sample can land past the pixel, on the other half of the slice, where it says
        // nothing about this side's horizon.
        if sample.w == 0.0 || dot(sample.xyz, side) <= 0.0 {
            continue;
        }
        let delta = sample.xyz;
        let distance = length(delta);
        let weight = saturate(distance * gtao.falloff_mul + gtao.falloff_add);
        let sample_cos = dot(delta, v) / distance;
        horizon_cos = max(horizon_cos, mix(low_cos, sample_cos, weight));
    }
    return horizon_cos;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let depth = textureLoad(linear_depth, id.xy, 0).r;
    let radius_px = pixels_at_depth(gtao.radius, depth);
    // No surface, or a radius under one pixel: nothing in the depth buffer can occlude.
    if depth == NO_SURFACE || radius_px < 1.0 {
        textureStore(ao_out, id.xy, vec4<f32>(1.0, 0.0, 0.0, 0.0));
        return;
    }
    let center = vec2<f32>(id.xy) + 0.5;
    let p = view_position(center, depth);
    let v = view_direction(p);
    let n = unpack_oct32(textureLoad(normals, id.xy, 0).r);
    let noise = pixel_noise(id.xy, view.frame_index);

    var visible = 0.0;
    var unoccluded = 0.0;
    for (var slice = 0u; slice < gtao.slice_count; slice++) {
        let phi = (f32(slice) + noise.x) * PI / f32(gtao.slice_count);
        // Screen direction (pixel y down) and the same direction in view space (y up).
        let omega = vec2<f32>(cos(phi), sin(phi));
        let direction = vec3<f32>(omega.x, -omega.y, 0.0);
        // Slice plane: spanned by V and `tangent`, the part of `direction` orthogonal to V.
        let tangent = direction - dot(direction, v) * v;
        let axis = normalize(cross(tangent, v));
        let n_proj = n - axis * dot(n, axis);
        let n_proj_len = length(n_proj);
        // Angle of the projected normal from V, positive towards +omega.
        let cos_n = saturate(dot(n_proj, v) / max(n_proj_len, 1e-6));
        let angle_n = select(-1.0, 1.0, dot(n_proj, tangent) >= 0.0) * fast_acos(cos_n);

        // Horizons start at the edge of the normal's hemisphere: cos(n + pi/2) = -sin(n) on the
        // +omega side, cos(n - pi/2) = sin(n) on the other.
        let sin_n = sin(angle_n);
        let cos_pos = search_horizon(center, p, v, n, axis, tangent, omega, radius_px, noise.y, -sin_n);
        let cos_neg = search_horizon(center, p, v, n, axis, -tangent, -omega, radius_px, noise.y, sin_n);
        // Horizon angles, clamped to the normal's hemisphere.
        let h_pos = angle_n + min(fast_acos(cos_pos) - angle_n, HALF_PI);
        let h_neg = angle_n + max(-fast_acos(cos_neg) - angle_n, -HALF_PI);

        visible += n_proj_len * (arc_integral(h_neg, angle_n) + arc_integral(h_pos, angle_n));
        // The same slice with nothing in it, h = n -+ pi/2: |n_p| (cos n + n sin n).
        unoccluded += n_proj_len * (cos(angle_n) + angle_n * sin_n);
    }

    // Each slice's unoccluded integral varies with its angle to the normal (from cos a to about
    // 1.5 for a normal tilted by a from V) and only averages to 1 over all slices, so a few random
    // slices are noisy even on an open plane. Dividing by the sum of the unoccluded integrals of
    // the same slices removes that noise; the estimate stays consistent because both sums
    // converge to their means. Backfacing normals make that sum small, where the plain average is
    // the safer estimate.
    let count = f32(gtao.slice_count);
    let use_ratio = gtao.normalize_slices != 0u && unoccluded > 0.1 * count;
    let visibility = saturate(select(visible / count, visible / unoccluded, use_ratio));
    let ao = pow(saturate(1.0 - gtao.intensity * (1.0 - visibility)), gtao.power);
    textureStore(ao_out, id.xy, vec4<f32>(ao, 0.0, 0.0, 0.0));
}
