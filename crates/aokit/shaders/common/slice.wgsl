// requires: common/view.wgsl, common/encoding.wgsl, common/ao.wgsl
// Slices, shared by the slice-based methods (GTAO, VBAO): half-planes through the view vector V
// at a screen angle, samples placed exactly in them, and the cosine-weighted arc integral.

// acos from a first-order polynomial times sqrt (Eberly 2014, as the GTAO paper uses it): at most
// 0.009 rad off, and no transcendental call. Errors vanish to first order in the result because
// the cosine weight is zero at the hemisphere's edge, where clamped horizons sit. Cosines a
// rounding step past 1 are taken as 1.
fn fast_acos(x: f32) -> f32 {
    let a = min(abs(x), 1.0);
    let r = (HALF_PI - 0.156583 * a) * sqrt(1.0 - a);
    return select(PI - r, r, x >= 0.0);
}

// Integral of cos(theta - n) |sin(theta)| from 0 to h (for h < 0 the same expression is the
// integral from h to 0): the cosine-weighted visible arc on one side of V.
fn arc_integral(h: f32, n: f32) -> f32 {
    return 0.25 * (-cos(2.0 * h - n) + cos(n) + 2.0 * h * sin(n));
}

// How slice samples read the depth they land on (AoSettings::sample_depth), compiled into each
// kernel like DEPTH_MIPS: true reads the texel a sample lands in (nearest_surface), false
// interpolates inside its 2x2 footprint (surface_at).
override NEAREST_DEPTH: bool = false;

// Offset from `p` to the surface seen at continuous pixel position `q` (read at MIP level
// `level`, see surface_at), placed in the slice plane; w = 0 when there is no surface there.
//
// A sample must lie in the slice: texel centres sit up to half a texel off it, and on surfaces
// seen at grazing angles that sideways step is long in view space and runs towards the eye, so an
// open plane would occlude itself. surface_at interpolates inside one surface, which places the
// sample exactly on the slice. The nearest texel (across a depth edge, or every sample with
// NEAREST_DEPTH) is moved onto the view ray through `q`, which lies in the slice, at the same
// height above the pixel's tangent plane: the height is the part that occludes, and a plane seen
// at any angle stays unoccluded. (Sliding it within the tangent plane into the slice, the way
// before, keeps the height too, but can shorten its distance to p many times over where the
// texel lies mostly beside the slice: single pixels of a grazing open plane then read 0.89.)
// The nearest read is the default: on an H100 GTAO `high`'s frame takes 0.81 to 0.87 of the
// interpolated read's time with it, for about 1% more error (docs/methods.md#sample-depth).
fn slice_sample(q: vec2<f32>, level: u32, p: vec3<f32>, n: vec3<f32>) -> vec4<f32> {
    var seen: SeenSurface;
    if NEAREST_DEPTH {
        seen = nearest_surface(q, level);
    } else {
        seen = surface_at(q, level);
    }
    return place_sample(seen, q, p, n);
}

// slice_sample's placement of the surface `seen` at `q`: the offset from `p`, w = 0 where
// there is no surface.
fn place_sample(seen: SeenSurface, q: vec2<f32>, p: vec3<f32>, n: vec3<f32>) -> vec4<f32> {
    if seen.depth == NO_SURFACE {
        return vec4<f32>(0.0);
    }
    let seen_at = view_position(seen.at, seen.depth);
    if seen.exact {
        return vec4<f32>(seen_at - p, 1.0);
    }
    // The view ray through q, near + d * along for linear depth d, lies in the slice; the
    // sample is where it meets the plane through the texel's point parallel to the tangent
    // plane at p.
    let near = view_position(q, 0.0);
    let along = view_position(q, 1.0) - near;
    let crossing = dot(seen_at - near, n) / dot(along, n);
    // A crossing far in front of the texel means the texel lies on no surface parallel to the
    // pixel's (the background behind a silhouette, which the ray would bring up to the pixel
    // as an occluder), so the point comes at most DEPTH_EDGE closer than the texel. On a plane
    // the crossing lies within a texel's depth step of it. A ray nearly parallel to the tangent
    // plane crosses it far off or nowhere (a zero or infinite quotient): twice the texel's
    // depth is as far as any sample needs to go to occlude nothing.
    let d = clamp(select(seen.depth, crossing, crossing > 0.0), seen.depth / (1.0 + DEPTH_EDGE),
                  2.0 * seen.depth);
    return vec4<f32>(near + d * along - p, 1.0);
}

// What a sample that lands off screen reads (AoSettings::offscreen_samples), compiled into
// each kernel like NEAREST_DEPTH: nothing, as if the scene were open beyond the edge
// (OFFSCREEN_UNOCCLUDED); the surface at the screen's edge continued (OFFSCREEN_EXTEND,
// edge_plane_sample); or the last texel on screen, as a clamping sampler reads it, placed as any
// nearest texel is (OFFSCREEN_CLAMP, slice_sample): on the sample's view ray, at that texel's
// height above the pixel's tangent plane, so that an open plane stays open and a rise at the
// edge goes on at its height, at the cost of a clamp. (Taking the edge's depth at the sample's
// position, as XeGTAO's clamping sampler does, raises a receding plane into a wall: an open
// plane seen orthographically read AO 0.63 at its far edge.)
// The codes are OffscreenSamples' declaration order (settings/enums.rs).
const OFFSCREEN_EXTEND: u32 = 0u;
const OFFSCREEN_UNOCCLUDED: u32 = 1u;
const OFFSCREEN_CLAMP: u32 = 2u;
override OFFSCREEN: u32 = OFFSCREEN_UNOCCLUDED;

// Distance in pixels from `center` along the screen direction `dir` to the last texel centre
// on screen: where a slice leaving the screen last sees the scene.
fn edge_distance(center: vec2<f32>, dir: vec2<f32>) -> f32 {
    let bound = select(vec2<f32>(0.5), view.size - 0.5, dir > vec2<f32>(0.0));
    let reach = select(vec2<f32>(MAX_DEPTH), (bound - center) / dir, abs(dir) > vec2<f32>(1e-6));
    return max(min(reach.x, reach.y), 0.0);
}

// The surface seen at `edge` (the last texel on screen towards an off-screen sample) as a plane:
// that texel's point and its normal. Walls, floors and ceilings mostly go on past the edge as
// they left it; taking the space beyond as open (the alternative) left the 12 px border band the
// largest error outside silhouettes (docs/quality.md#off-screen-samples-and-silhouettes).
struct EdgePlane {
    n: vec3<f32>,
    // dot(point, n): the plane is dot(x, n) = offset.
    offset: f32,
    depth: f32,
}

fn edge_plane(edge: vec2<f32>) -> EdgePlane {
    let texel = vec2<u32>(edge);
    let depth = textureLoad(linear_depth, texel, 0).r;
    let n = unpack_oct32(textureLoad(normals, texel, 0).r);
    return EdgePlane(n, dot(view_position(floor(edge) + 0.5, depth), n), depth);
}

// The off-screen sample on the view ray near + d * along (view_position at depths 0 and 1 of
// the sample's screen position) where it meets `plane`, as an offset from `p`. A plane seen
// nearly edge-on meets the ray arbitrarily far off, or behind the eye: the point stays within a
// factor of 4 of the edge's depth, a receding plane then lying out of reach and an approaching
// one still occluding. w = 0 where the edge shows no surface or the ray meets the plane behind
// the eye.
fn edge_plane_sample(plane: EdgePlane, near: vec3<f32>, along: vec3<f32>,
                     p: vec3<f32>) -> vec4<f32> {
    let d = (plane.offset - dot(near, plane.n)) / dot(along, plane.n);
    let valid = plane.depth != NO_SURFACE && d > 0.0;
    let offset = near + clamp(d, 0.25 * plane.depth, 4.0 * plane.depth) * along - p;
    return select(vec4<f32>(0.0), vec4<f32>(offset, 1.0), valid);
}

// Step jitter is stratified across a pixel's slices: slice i shifts it by i times the golden
// ratio's fraction (a low-discrepancy sequence), so together they cover the radius more evenly
// than one shared offset would. VBAO sets the two sides of a slice half a step apart as well;
// GTAO steps both to the same distances (gtao.wgsl, search_horizons), at no more error.
const GOLDEN_FRACTION: f32 = 0.618034;

// One slice of a pixel's hemisphere.
struct Slice {
    // Screen direction, pixel y down.
    omega: vec2<f32>,
    // Unit direction in the slice plane orthogonal to V, towards +omega.
    tangent: vec3<f32>,
    // Unit normal of the slice plane.
    axis: vec3<f32>,
    // Length of the normal projected onto the slice plane: the slice's weight.
    n_len: f32,
    // Signed angle of the projected normal from V, positive towards +omega.
    angle_n: f32,
}

fn make_slice(s: Surface, phi: f32) -> Slice {
    var slice: Slice;
    slice.omega = vec2<f32>(cos(phi), sin(phi));
    // The same direction in view space: where a step along omega on screen moves the view ray.
    // Pixels need not be square (an odd size halved, a stretched projection): taken this way,
    // the view ray through every sample lies in the slice plane, on its +omega or -omega half.
    let direction = vec3<f32>(pixel_to_ray() * slice.omega, 0.0);
    slice.tangent = normalize(direction - dot(direction, s.v) * s.v);
    slice.axis = normalize(cross(slice.tangent, s.v));
    let n_axis = dot(s.n, slice.axis);
    let n_proj = s.n - slice.axis * n_axis;
    slice.n_len = length(n_proj);
    let cos_n = saturate(dot(n_proj, s.v) / max(slice.n_len, 1e-6));
    slice.angle_n = select(-1.0, 1.0, dot(n_proj, slice.tangent) >= 0.0) * fast_acos(cos_n);
    return slice;
}

// The view ray's change per pixel of screen offset (its xy at depth 1 for perspective, its xy
// for orthographic), from view_position: y flips, pixel to uv to NDC.
fn pixel_to_ray() -> vec2<f32> {
    return vec2<f32>(2.0, -2.0) * view.uv_per_pixel * view.ndc_to_view;
}

// Distance in pixels of step `step` of `steps` from the pixel, jittered, from one pixel out
// (the pixel itself says nothing) to the radius: `step_power` above 1 crowds samples near the
// pixel, 1 spaces them evenly.
fn step_distance(step: u32, steps: u32, jitter: f32, radius_px: f32) -> f32 {
    let t = (f32(step) + jitter) / f32(steps);
    return 1.0 + step_fraction(t) * (radius_px - 1.0);
}

// t^step_power. With LEAN a power in quarters (every value `aokit tune` tries) is products of t
// and its square and fourth roots, which the compiler unrolls: pow is a log2 and an exp2, and
// on lavapipe it took a fifth of GTAO `high`'s lean kernel at a power of 1.25.
fn step_fraction(t: f32) -> f32 {
    let quarters = STEP_POWER * 4.0;
    if !LEAN || quarters != round(quarters) {
        return pow(t, select(ao.step_power, STEP_POWER, LEAN));
    }
    let whole = u32(quarters) / 4u;
    var power = 1.0;
    for (var i = 0u; i < whole; i++) {
        power *= t;
    }
    let root = sqrt(t);
    switch u32(quarters) % 4u {
        case 1u: {
            power *= sqrt(root);
        }
        case 2u: {
            power *= root;
        }
        case 3u: {
            power *= root * sqrt(root);
        }
        default: {}
    }
    return power;
}

// Where on screen, in pixels, the step `distance_px` from the pixel on one side of a slice lies.
fn side_position(s: Surface, slice: Slice, side: f32, distance_px: f32) -> vec2<f32> {
    return s.center + side * slice.omega * distance_px;
}

// The sample of a step on one side of a slice (side = +1 towards +omega, -1 away): the offset
// from the shaded point in xyz, w = 1, or w = 0 where there is nothing to learn (off screen
// with OFFSCREEN_UNOCCLUDED, or no surface). Every placement puts the sample on the view ray
// through its screen position, in front of the eye, so it lies on its side's half of the slice.
fn side_sample(s: Surface, slice: Slice, side: f32, distance_px: f32) -> vec4<f32> {
    let q = side_position(s, slice, side, distance_px);
    var sample: vec4<f32>;
    if any(q < vec2<f32>(0.0)) || any(q >= view.size) {
        if OFFSCREEN == OFFSCREEN_UNOCCLUDED {
            return vec4<f32>(0.0);
        }
        if OFFSCREEN == OFFSCREEN_EXTEND {
            let dir = side * slice.omega;
            let plane = edge_plane(s.center + dir * edge_distance(s.center, dir));
            let near = view_position(q, 0.0);
            sample = edge_plane_sample(plane, near, view_position(q, 1.0) - near, s.p);
        } else {
            let edge = clamp(q, vec2<f32>(0.0), view.size - 1.0);
            sample = place_sample(nearest_surface(edge, mip_level(distance_px)), q, s.p, s.n);
        }
    } else {
        sample = slice_sample(q, mip_level(distance_px), s.p, s.n);
    }
    return sample;
}

// The lean march (SliceMarch::Lean), compiled in with LEAN: a side of a slice set up once for
// all its steps, so that a sample costs one depth fetch and a few multiply-adds. On a slice side
// the view ray through the point `d` pixels from the pixel is affine in d (its xy at depth 1 for
// perspective, its xy for orthographic), and so is its dot product with the normal.
override LEAN: bool = false;
// With LEAN, the slices (or directions) and the steps per side as the settings give them
// (`ao.count`, `ao.steps`), so that the loops have literal trip counts the compiler can unroll.
override SLICES: u32 = 1u;
override STEPS: u32 = 1u;

fn slice_count() -> u32 {
    return select(ao.count, SLICES, LEAN);
}

fn step_count() -> u32 {
    return select(ao.steps, STEPS, LEAN);
}
// With LEAN, `ao.step_power` (step_fraction).
override STEP_POWER: f32 = 1.0;
// With LEAN, whether `ao.thickness` is above 0 (GTAO's thickness blend, gtao.wgsl).
override THICKNESS_BLEND: bool = true;

// With LEAN, whether the view is orthographic (`view.orthographic`): each kernel then holds
// the arithmetic of its projection only.
override ORTHOGRAPHIC: bool = false;

struct SideMarch {
    // Screen step per pixel of distance: side * omega.
    dir: vec2<f32>,
    side: f32,
    // The view ray at the pixel and its change per pixel of distance.
    ray: vec2<f32>,
    ray_step: vec2<f32>,
    // dot(ray, n.xy) - n.z (perspective) or -n.z (orthographic) at the pixel and per pixel of
    // distance: slice_sample's dot(along, n).
    along_n: f32,
    along_n_step: f32,
    // The ray's change per pixel of screen offset, times n.xy: moves the tangent plane's
    // crossing from the sample to the texel centre the depth was read at.
    pixel_n: vec2<f32>,
    // With LEAN and OFFSCREEN_EXTEND, where the side reaches past the screen's edge within the
    // radius: the surface at the edge (edge_plane), read once for all its steps. Depth
    // NO_SURFACE otherwise.
    edge: EdgePlane,
}

// The lean march's set-up of one side (the general march takes only `side` from it).
fn begin_side(s: Surface, slice: Slice, side: f32) -> SideMarch {
    var m: SideMarch;
    m.dir = side * slice.omega;
    m.side = side;
    m.ray = select(s.p.xy / s.depth, s.p.xy, ORTHOGRAPHIC);
    m.ray_step = pixel_to_ray() * m.dir;
    m.along_n = select(dot(m.ray, s.n.xy), 0.0, ORTHOGRAPHIC) - s.n.z;
    m.along_n_step = select(dot(m.ray_step, s.n.xy), 0.0, ORTHOGRAPHIC);
    m.pixel_n = pixel_to_ray() * s.n.xy;
    if OFFSCREEN == OFFSCREEN_EXTEND && LEAN {
        let edge = edge_distance(s.center, m.dir);
        if edge < s.radius_px {
            m.edge = edge_plane(s.center + m.dir * edge);
        }
    }
    return m;
}

// side_sample for the lean march, the same sample without branches: the offset from the shaded
// point in xyz, w = 1, or w = 0 where there is nothing to learn (off screen with
// OFFSCREEN_UNOCCLUDED, or no surface). The nearest texel's point is moved onto the view ray
// through the sample as slice_sample does; the fetch goes through the clamping sampler, so a
// sample off screen reads the last texel on screen, which OFFSCREEN_CLAMP places as side_sample
// does and OFFSCREEN_UNOCCLUDED weighs 0. With OFFSCREEN_EXTEND one off screen lies on the
// side's edge plane instead (read once in begin_side), selected without a branch: a few
// multiply-adds and a division.
fn march_sample(s: Surface, m: SideMarch, distance_px: f32) -> vec4<f32> {
    let q = s.center + m.dir * distance_px;
    let inside = all(q >= vec2<f32>(0.0)) && all(q < view.size);
    var texel: vec2<f32>;
    var depth: f32;
    if DEPTH_MIPS == DEPTH_MIPS_OFF {
        texel = floor(q) + 0.5;
        depth = textureSampleLevel(linear_depth, point_clamp, texel * view.inv_size, 0.0).r;
        if OFFSCREEN == OFFSCREEN_CLAMP {
            // The texel the sampler read, whose point the crossing below moves.
            texel = clamp(texel, vec2<f32>(0.5), view.size - 0.5);
        }
    } else {
        let on_screen = clamp(q, vec2<f32>(0.0), view.size - 1.0);
        let seen = nearest_surface(on_screen, mip_level(distance_px));
        texel = seen.at;
        depth = seen.depth;
    }
    let ray = m.ray + m.ray_step * distance_px;
    // slice_sample's crossing: where the view ray through q meets the plane through the
    // texel's point parallel to the tangent plane.
    let along_n = m.along_n + m.along_n_step * distance_px;
    let crossing = depth + dot(texel - q, m.pixel_n) * select(depth, 1.0, ORTHOGRAPHIC) / along_n;
    let d = clamp(select(depth, crossing, crossing > 0.0), depth * (1.0 / (1.0 + DEPTH_EDGE)),
                  2.0 * depth);
    var sample = vec4<f32>(vec3<f32>(select(ray * d, ray, ORTHOGRAPHIC), -d) - s.p,
                           select(0.0, 1.0, (inside || OFFSCREEN == OFFSCREEN_CLAMP)
                                            && depth != NO_SURFACE));
    if OFFSCREEN == OFFSCREEN_EXTEND {
        let near = select(vec3<f32>(0.0), vec3<f32>(ray, 0.0), ORTHOGRAPHIC);
        let along = select(vec3<f32>(ray, -1.0), vec3<f32>(0.0, 0.0, -1.0), ORTHOGRAPHIC);
        sample = select(edge_plane_sample(m.edge, near, along, s.p), sample, inside);
    }
    return sample;
}

// The sample of a step `distance_px` along a slice's side, as the settings' march places it:
// march_sample on the side `march` set up, or side_sample. Either way it is the same sample.
fn slice_method_sample(s: Surface, slice: Slice, march: SideMarch, distance_px: f32) -> vec4<f32> {
    if LEAN {
        return march_sample(s, march, distance_px);
    }
    return side_sample(s, slice, march.side, distance_px);
}

// The bent-normal vector of the slices' unoccluded hemispheres, replaced by its expectation.
//
// A few slices' full hemispheres do not sum to a vector along the normal (their weight
// |sin theta| is about V), so on open ground the raw sum tilts with the slice angles. The
// slice-based methods therefore add up only what each slice loses to occluders (its bent vector
// minus its unoccluded one, exact per slice) and add this: the cosine-weighted mean direction of
// a whole hemisphere is 2/3 of the normal, times the slices' unoccluded integral. Open ground
// then gets exactly the normal, and the estimate converges to the same value.
fn open_bent(n: vec3<f32>, unoccluded: f32) -> vec3<f32> {
    return (2.0 / 3.0) * unoccluded * n;
}
