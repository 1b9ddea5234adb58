// requires: common/view.wgsl, common/noise.wgsl, common/ao.wgsl, common/slice.wgsl
// requires: common/horizon.wgsl
// Separable HBAO (docs/methods/hbao.md, "separable HBAO"): hbao.wgsl's horizons along four fixed
// screen directions, +x and -x in a pass over rows, then +y and -y in a pass over columns, each
// reading its line of linear depth from workgroup memory instead of the depth texture. The
// approach is NVIDIA's compute-shader HBAO in their DirectX 11 SDK sample (SSAO11; Bavoil 2011,
// "Horizon-Based Ambient Occlusion using Compute Shaders"): like a separable blur, a workgroup
// loads its row (column) segment once and every pixel's samples along that line read it from there.
// A program is this file plus one pass file (hbao_rows.wgsl or hbao_columns.wgsl) that sets `AXIS`
// and defines `store_line` and `store_unsampled` over its own textures.
//
// Workgroups are LINE threads along x in both passes: workgroup (s, l) takes segment s of line l,
// a row in the rows pass and a column in the columns pass, which is dispatched over the
// transposed grid. A GPU assigns lanes by invocation index, so a 1 x LINE workgroup would run
// the same; llvmpipe packs only the x extent of a workgroup into its SIMD lanes and would run a
// 1 x LINE one at one lane in eight.
//
// Direction i (0: +x, 1: +y, 2: -x, 3: -y, pixel y down) is hbao.wgsl's slice at screen angle
// i pi/2 with no rotation: hbao with four directions and the rotation noise at 0. A sample on the
// pixel's own row (column) lies exactly in that slice, since the slice is the plane through the
// eye, the point and the screen axis, so nothing needs sliding into it as slice_sample does, and
// depth is interpolated along the line alone. The price of reading lines from workgroup memory:
// the directions never rotate, per pixel or over frames (only the step jitter moves), and the
// screen radius cannot pass the apron.

// Texels of a workgroup's line segment, one thread each: with 128, a 1080p row takes 15
// segments, and the aprons add about two loads per pixel of the segment (386 for 128).
const LINE: u32 = 128u;

// The apron on each side of the segment, in working texels: the largest screen radius the passes
// reach (`SEPARABLE_HBAO_MAX_RADIUS_PX` in Rust, which lowers the kernel's max_radius_px to it; a
// test compares the two). At half resolution it is the default max_radius_px, 256 pixels of the
// input; the tile costs 1.5 KiB of workgroup memory.
const MAX_RADIUS: u32 = 128u;

// The segment, both aprons, and one texel more on each side: a step that rounds onto the apron's
// outer edge interpolates with the texel beyond it.
const TILE: u32 = LINE + 2u * MAX_RADIUS + 2u;

// The axis across the lines.
const ACROSS = vec2<i32>(1, 1) - AXIS;

var<workgroup> tile_depth: array<f32, TILE>;

// Loads the linear depth of the segment that starts at pixel `start` and of its aprons into
// `tile_depth` (no surface outside the image) and waits for the whole workgroup. Returns the
// coordinate along the line of `tile_depth[0]`.
fn load_tile(start: vec2<i32>, local: u32) -> i32 {
    let first = dot(start, AXIS) - i32(MAX_RADIUS + 1u);
    for (var i = local; i < TILE; i += LINE) {
        let pixel = start * ACROSS + AXIS * (first + i32(i));
        var depth = NO_SURFACE;
        if all(pixel >= vec2<i32>(0)) && all(pixel < vec2<i32>(view.size)) {
            depth = textureLoad(linear_depth, pixel, 0).r;
        }
        tile_depth[i] = depth;
    }
    workgroupBarrier();
    return first;
}

// The surface seen at continuous coordinate `q` along the line of `s` (in pixels; across the
// line, at the pixel's centre): common/ao.wgsl's surface_at in one dimension, from the two texels
// of the tile around `q` rather than a gather of the texture. Inside one surface 1 / depth (depth,
// orthographic) is affine along the line, so interpolating it gives the depth exactly at `q`;
// across a depth edge the nearer texel is returned with its centre.
fn line_surface_at(s: Surface, q: f32, first: i32) -> SeenSurface {
    let left = floor(q - 0.5);
    let f = q - 0.5 - left;
    let i = u32(i32(left) - first);
    let depths = vec2<f32>(tile_depth[i], tile_depth[i + 1u]);
    let across = s.center * vec2<f32>(ACROSS);
    let lowest = min(depths.x, depths.y);
    if lowest > 0.0 && max(depths.x, depths.y) <= lowest * (1.0 + DEPTH_EDGE) {
        let ortho = view.orthographic > 0.5;
        let w = select(1.0 / depths, depths, ortho);
        let b = mix(w.x, w.y, f);
        return SeenSurface(select(1.0 / b, b, ortho), across + q * vec2<f32>(AXIS), true);
    }
    let right = f >= 0.5;
    let texel = left + select(0.5, 1.5, right);
    return SeenSurface(select(depths.x, depths.y, right), across + texel * vec2<f32>(AXIS), false);
}

// The occlusion of direction `direction` (0 to 3, see above): hbao.wgsl's march along its slice,
// the samples read from the tile. The four directions' step jitters lie a quarter step apart, so
// that together they cover the radius more evenly than one shared jitter would.
fn march(s: Surface, direction: u32, jitter: f32, first: i32) -> f32 {
    let slice = make_slice(s, f32(direction) * HALF_PI);
    // +1 when the direction runs towards +AXIS, -1 against it.
    let side = sign(dot(slice.omega, vec2<f32>(AXIS)));
    let centre = dot(s.center, vec2<f32>(AXIS));
    let end = dot(view.size, vec2<f32>(AXIS));
    let shifted = fract(jitter + 0.25 * f32(direction));
    let steps = horizon_steps(s);
    var horizon = start_horizon(slice);
    for (var k = 0u; k < steps; k++) {
        let q = centre + side * step_distance(k, steps, shifted, s.radius_px);
        // Steps only move outwards: once one leaves the image, the rest do.
        if q < 0.0 || q >= end {
            break;
        }
        let seen = line_surface_at(s, q, first);
        if seen.depth != NO_SURFACE {
            horizon = raise_horizon(horizon, s, view_position(seen.at, seen.depth) - s.p);
        }
    }
    return horizon.occlusion;
}

@compute @workgroup_size(LINE)
fn main(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let start = ACROSS * i32(group.y) + AXIS * i32(group.x * LINE);
    let first = load_tile(start, local);
    let pixel = start + AXIS * i32(local);
    if any(pixel >= vec2<i32>(view.size)) {
        return;
    }
    let surface = load_surface(vec2<u32>(pixel));
    if nothing_to_sample(surface) {
        store_unsampled(surface);
        return;
    }
    // hbao.wgsl's step jitter; its rotation, the first value, has nothing to turn here.
    let texel = textureLoad(noise_tile, surface.pixel % textureDimensions(noise_tile), 0).xy;
    let noise = pixel_noise(surface.pixel, view.frame_index, ao.noise_kind, ao.noise_temporal, texel);
    // The line's two directions: 0 and 2 along rows, 1 and 3 along columns.
    let direction = u32(AXIS.y);
    let occlusion = march(surface, direction, noise.y, first)
        + march(surface, direction + 2u, noise.y, first);
    store_line(surface, occlusion);
}
