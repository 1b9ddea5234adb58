// requires: common/view.wgsl
// View-space normals reconstructed from linear depth: the `normals_from_depth` pass, and the
// decode pass's fallback where a texel holds no usable normal. The program declares the linear
// depth it reads as `linear_depth` (texture_2d<f32>, 0 where there is no surface).
//
// Each normal is the cross product of two tangents, one per screen axis, each the offset from the
// centre's view-space position to one neighbour's. The variants (the `SOURCE` override, the
// `NormalSource` codes) differ only in which side each axis takes:
// - naive: the right and lower neighbours (the left and upper ones where those show no surface).
//   Across a depth edge the tangent spans the gap and the normal tilts towards it.
// - 3-tap: the neighbour whose depth differs less from the centre's (the "improved" reconstruction
//   of Turanszki 2019, "Improved normal reconstruction from depth", Wicked Engine). Right at an
//   edge the far side loses, but on a slanted plane either side may win and the pick is decided by
//   noise.
// - 5-tap: the side whose two depths continue the centre best, i.e. whose linear extrapolation to
//   the centre misses least ("accurate" reconstruction, atyuwen 2021, "Accurate Normal
//   Reconstruction from Depth Buffer"). The extrapolation runs on a value that is affine in screen
//   space across a plane (1 / depth for perspective, depth for orthographic), so on a plane the
//   true side extrapolates exactly and a neighbouring object across an edge does not.

// `NormalSource as u32` in Rust (a test compares them).
const SOURCE_DEPTH_NAIVE: u32 = 1u;
const SOURCE_DEPTH_3TAP: u32 = 2u;
const SOURCE_DEPTH_5TAP: u32 = 3u;
override SOURCE: u32;

// Stands for "no usable neighbour" in the side comparison.
const UNUSABLE: f32 = 3.0e38;

fn depth_at(pixel: vec2<i32>) -> f32 {
    if any(pixel < vec2<i32>(0)) || any(pixel >= vec2<i32>(view.size)) {
        return NO_SURFACE;
    }
    return textureLoad(linear_depth, pixel, 0).r;
}

fn screen_affine(depth: f32) -> f32 {
    return select(1.0 / depth, depth, view.orthographic > 0.5);
}

// How badly the side one `step` from `pixel`, whose neighbour has depth `near`, suits the tangent;
// the lower of the two sides is taken.
fn side_error(pixel: vec2<i32>, step: vec2<i32>, near: f32, center: f32) -> f32 {
    if near == NO_SURFACE {
        return UNUSABLE;
    }
    if SOURCE == SOURCE_DEPTH_NAIVE {
        return select(1.0, 0.0, step.x + step.y > 0);
    }
    if SOURCE == SOURCE_DEPTH_3TAP {
        return abs(near - center);
    }
    // A side with only its near sample ranks behind any side with both.
    let far = depth_at(pixel + 2 * step);
    if far == NO_SURFACE {
        return 0.5 * UNUSABLE;
    }
    return abs(2.0 * screen_affine(near) - screen_affine(far) - screen_affine(center));
}

// Tangent along `axis` (a unit pixel step), pointing along +axis in screen space; zero when
// neither side has a surface.
fn tangent(pixel: vec2<i32>, axis: vec2<i32>, p: vec3<f32>, depth: f32) -> vec3<f32> {
    let back = depth_at(pixel - axis);
    let ahead = depth_at(pixel + axis);
    let back_error = side_error(pixel, -axis, back, depth);
    let ahead_error = side_error(pixel, axis, ahead, depth);
    if min(back_error, ahead_error) == UNUSABLE {
        return vec3<f32>(0.0);
    }
    if back_error < ahead_error {
        return p - view_position(vec2<f32>(pixel - axis) + 0.5, back);
    }
    return view_position(vec2<f32>(pixel + axis) + 0.5, ahead) - p;
}

// The view-space normal at `pixel` from the depth around it, facing the eye; +z where the pixel
// shows no surface.
fn normal_from_depth(pixel: vec2<i32>) -> vec3<f32> {
    let depth = depth_at(pixel);
    if depth == NO_SURFACE {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let p = view_position(vec2<f32>(pixel) + 0.5, depth);
    let v = view_direction(p);
    let across = cross(tangent(pixel, vec2<i32>(1, 0), p, depth), tangent(pixel, vec2<i32>(0, 1), p, depth));
    // An isolated pixel has no tangents: facing the eye is the least wrong guess.
    var n = select(v, normalize(across), length(across) > 0.0);
    if dot(n, v) < 0.0 {
        n = -n;
    }
    return n;
}
