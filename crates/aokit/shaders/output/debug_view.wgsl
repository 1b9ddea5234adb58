// requires: common/encoding.wgsl
// Debug views (AoDebug in debug.rs): one of a frame's intermediates as colour, one texel per
// pixel of the input's size, so that it lines up with the image. Textures at the working size
// are shown blocky, each texel over the pixels it covers. Mirrors `DebugUniforms` in uniforms.rs.

struct DebugUniforms {
    // A VIEW_* code: what to show.
    view: u32,
    // Relative depth step shown fully as an edge.
    edge_threshold: f32,
    // log2 of the depth shown white, and 1 / log2(far / near) with `far` shown black.
    log_near: f32,
    inv_log_range: f32,
    // Input pixels per texel of `depth` and of `scalar` (1, 2 or 4).
    depth_step: u32,
    scalar_step: u32,
    // 1 for an orthographic projection, where depth (not 1 / depth) is affine on a plane.
    orthographic: u32,
}

@group(0) @binding(0) var<uniform> debug: DebugUniforms;
// Linear depth, 0 where there is no surface.
@group(0) @binding(1) var depth: texture_2d<f32>;
// oct32 view-space normals, at the input's size.
@group(0) @binding(2) var normals: texture_2d<u32>;
// AO, raw AO or the rejected-history mask (a 1x1 stand-in when not shown).
@group(0) @binding(3) var scalar: texture_2d<f32>;
// Bent normals in xyz, at the input's size (a 1x1 stand-in when not shown).
@group(0) @binding(4) var bent: texture_2d<f32>;
@group(0) @binding(5) var shown: texture_storage_2d<rgba8unorm, write>;

// `DebugView::shader_code` in Rust (a test compares them).
const VIEW_DEPTH: u32 = 0u;
const VIEW_NORMALS: u32 = 1u;
const VIEW_EDGES: u32 = 2u;
const VIEW_BENT_NORMALS: u32 = 3u;
const VIEW_SCALAR: u32 = 4u;

fn depth_texel(pixel: vec2<i32>) -> f32 {
    let texels = vec2<i32>(textureDimensions(depth));
    return textureLoad(depth, clamp(pixel / i32(debug.depth_step), vec2<i32>(0), texels - 1), 0).r;
}

// Near white to far black, on a log scale so that near and far detail both show.
fn depth_grey(d: f32) -> f32 {
    return 1.0 - saturate((log2(d) - debug.log_near) * debug.inv_log_range);
}

// A quantity affine in screen space across any plane: 1 / depth in perspective, depth in
// orthographic projection.
fn planar(d: f32) -> f32 {
    return select(1.0 / d, d, debug.orthographic != 0u);
}

// How far the depth at `pixel` departs from the plane through its two neighbours along either
// axis, relative to itself, over the edge threshold: 1 from the threshold on. Planes give 0 at
// any angle, so only discontinuities and creases show; a neighbour without a surface is a full
// step.
fn edge_strength(pixel: vec2<i32>, d: f32) -> f32 {
    var departure = 0.0;
    let axes = array<vec2<i32>, 2>(vec2<i32>(1, 0), vec2<i32>(0, 1));
    for (var i = 0; i < 2; i++) {
        let offset = axes[i] * i32(debug.depth_step);
        let a = depth_texel(pixel - offset);
        let b = depth_texel(pixel + offset);
        let predicted = 0.5 * (planar(a) + planar(b));
        let here = planar(d);
        departure = max(departure, select(1.0, abs(predicted - here) / here, a > 0.0 && b > 0.0));
    }
    return saturate(departure / debug.edge_threshold);
}

fn direction_colour(v: vec3<f32>) -> vec3<f32> {
    return v * 0.5 + 0.5;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(shown);
    if any(id.xy >= size) {
        return;
    }
    let pixel = vec2<i32>(id.xy);
    let d = depth_texel(pixel);
    var colour = vec3<f32>(0.0);
    switch debug.view {
        case VIEW_DEPTH: {
            colour = vec3<f32>(select(0.0, depth_grey(d), d > 0.0));
        }
        case VIEW_NORMALS: {
            let n = unpack_oct32(textureLoad(normals, pixel, 0).r);
            colour = select(vec3<f32>(0.0), direction_colour(n), d > 0.0);
        }
        case VIEW_EDGES: {
            // Edges in red over the depth, dimmed.
            if d > 0.0 {
                colour = mix(vec3<f32>(0.5 * depth_grey(d)), vec3<f32>(1.0, 0.0, 0.0), edge_strength(pixel, d));
            }
        }
        case VIEW_BENT_NORMALS: {
            let b = textureLoad(bent, pixel, 0).xyz;
            colour = select(vec3<f32>(0.0), direction_colour(b), d > 0.0 && dot(b, b) > 0.0);
        }
        default: {
            let texels = vec2<i32>(textureDimensions(scalar));
            let texel = clamp(pixel / i32(debug.scalar_step), vec2<i32>(0), texels - 1);
            colour = vec3<f32>(saturate(textureLoad(scalar, texel, 0).r));
        }
    }
    textureStore(shown, id.xy, vec4<f32>(colour, 1.0));
}
