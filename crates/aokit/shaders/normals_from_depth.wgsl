// View-space normals reconstructed from linear depth, for renderers that provide none.
//
// Per axis, the tangent comes from the side whose two depths continue the centre best: the side
// whose linear extrapolation to the centre misses least ("accurate" reconstruction, atyuwen 2021,
// "Accurate Normal Reconstruction from Depth Buffer"). The extrapolation runs on a value that is
// affine in screen space across a plane (1 / depth for perspective, depth for orthographic), so
// on a plane the true side extrapolates exactly and a neighbouring object across an edge does
// not. Output is oct32, like a G-buffer's.

@group(0) @binding(1) var linear_depth: texture_2d<f32>;
@group(0) @binding(2) var normals_out: texture_storage_2d<r32uint, write>;

// Stands for "no usable extrapolation" in the side comparison.
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

// How badly the samples one and two steps away predict the centre; a side with only its near
// sample ranks behind any side with both, and a side with none is unusable.
fn extrapolation_error(near: f32, far: f32, center: f32) -> f32 {
    if near == NO_SURFACE {
        return UNUSABLE;
    }
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
    let back_error = extrapolation_error(back, depth_at(pixel - 2 * axis), depth);
    let ahead_error = extrapolation_error(ahead, depth_at(pixel + 2 * axis), depth);
    if min(back_error, ahead_error) == UNUSABLE {
        return vec3<f32>(0.0);
    }
    if back_error < ahead_error {
        return p - view_position(vec2<f32>(pixel - axis) + 0.5, back);
    }
    return view_position(vec2<f32>(pixel + axis) + 0.5, ahead) - p;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let pixel = vec2<i32>(id.xy);
    let depth = depth_at(pixel);
    if depth == NO_SURFACE {
        textureStore(normals_out, id.xy, vec4<u32>(pack_oct32(vec3<f32>(0.0, 0.0, 1.0)), 0u, 0u, 0u));
        return;
    }
    let p = view_position(vec2<f32>(id.xy) + 0.5, depth);
    let v = view_direction(p);
    let across = cross(tangent(pixel, vec2<i32>(1, 0), p, depth), tangent(pixel, vec2<i32>(0, 1), p, depth));
    // An isolated pixel has no tangents: facing the eye is the least wrong guess.
    var n = select(v, normalize(across), length(across) > 0.0);
    if dot(n, v) < 0.0 {
        n = -n;
    }
    textureStore(normals_out, id.xy, vec4<u32>(pack_oct32(n), 0u, 0u, 0u));
}
