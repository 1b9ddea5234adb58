// requires: common/view.wgsl
// requires: common/formats/pair_rg32float.wgsl | common/formats/pair_rgba32float.wgsl
// Temporal filter (after the SSAO temporal filter of ybniaobu's Unity YPipeline: variance clipping,
// Salvi 2016, "An Excursion in Temporal Supersampling", and depth rejection, Bavoil and Andersson
// 2012, "Stable SSAO in Battlefield 3 with Selective Temporal Filtering"): each pixel blends its AO
// with what the same surface showed last frame, found by reprojection, so the sampling noise, which
// moves every frame, averages out over about 1 / (1 - blend) frames.
//
// Per pixel: the mean and spread of the 3x3 neighbours on the same surface bound the history
// (variance clipping); the pixel's view position goes back through the previous
// camera (or the renderer's motion vectors) to where it was; the history there is read from the
// 2x2 texels whose depth agrees with the expected one, clipped to mean +- gamma * spread, and
// blended with the current value: the pixel's own, or with `filter_current` the 3x3 same-surface
// mean (YPipeline's filtered current value, which blurs contact shadows and measured worse, see
// docs/denoise.md). History is rejected, and the current value used alone, off screen, where no
// history texel lies on the same surface (a disocclusion), and after a camera cut.
// Mirrors `TemporalUniforms` in uniforms.rs.

struct TemporalUniforms {
    // Current view position to the previous frame's view position (identity for a still camera).
    prev_view_from_view: mat4x4<f32>,
    // The previous projection's NDC-to-view scale, NDC offset (its jitter) and orthographic
    // flag, for its pixel grid.
    prev_ndc_to_view: vec2<f32>,
    prev_ndc_offset: vec2<f32>,
    prev_orthographic: f32,
    // Weight of the history.
    blend: f32,
    // History is clipped to mean +- variance_gamma * standard deviation of the 3x3 neighbours.
    variance_gamma: f32,
    // Relative depth difference above which two depths are different surfaces.
    depth_threshold: f32,
    flags: u32,
    // Where this frame's pixel (0, 0) lies in the motion vectors: the guard band when they are
    // the renderer's overscan, 0 when cropped or downsampled to the frame.
    motion_offset: vec2<i32>,
}

const FLAG_HISTORY: u32 = 1u;
const FLAG_MOTION_VECTORS: u32 = 2u;
const FLAG_FILTER_CURRENT: u32 = 4u;

// The current AO and its depth come packed in one texture (ao_in's r and g), as the spatial
// filter's vertical pass writes them, or in two (ao_in's r, linear_depth). Packed, the 3x3
// neighbourhood takes 10 loads a pixel rather than 19, in a pass that runs at about its
// texture-fetch floor on an H100 (docs/notes/performance-investigations.md).
override PACKED_INPUT: bool;

@group(0) @binding(1) var<uniform> temporal: TemporalUniforms;
@group(0) @binding(2) var ao_in: texture_2d<f32>;
// Unread with PACKED_INPUT.
@group(0) @binding(3) var linear_depth: texture_2d<f32>;
// (AO, linear depth) of the previous frame.
@group(0) @binding(4) var history_in: texture_2d<f32>;
// Screen offset in pixels from a pixel to where its surface was last frame (1x1 when unused).
@group(0) @binding(5) var motion_vectors: texture_2d<f32>;
@group(0) @binding(6) var point_clamp: sampler;
@group(0) @binding(7) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(8) var history_out: pair_storage;
// 1 where the history was rejected, for debug views.
@group(0) @binding(9) var rejected_out: texture_storage_2d<r32float, write>;

// The current (AO, linear depth) at `pixel`.
fn current_at(pixel: vec2<i32>) -> vec2<f32> {
    if PACKED_INPUT {
        return textureLoad(ao_in, pixel, 0).rg;
    }
    return vec2<f32>(textureLoad(ao_in, pixel, 0).r, textureLoad(linear_depth, pixel, 0).r);
}

fn same_surface(a: f32, b: f32) -> bool {
    return a > 0.0 && b > 0.0 && abs(a - b) <= temporal.depth_threshold * min(a, b);
}

fn store(pixel: vec2<u32>, ao: f32, depth: f32, rejected: bool) {
    textureStore(ao_out, pixel, vec4<f32>(ao, 0.0, 0.0, 0.0));
    textureStore(history_out, pixel, vec4<f32>(ao, depth, 0.0, 0.0));
    textureStore(rejected_out, pixel, vec4<f32>(select(0.0, 1.0, rejected), 0.0, 0.0, 0.0));
}

// The history's AO at continuous pixel position `q` from the 2x2 texels around it that show a
// surface at `expected` depth, bilinearly weighted; w = 0 when none does.
fn history_at(q: vec2<f32>, expected: f32) -> vec2<f32> {
    let corner = clamp(floor(q - 0.5) + 1.0, vec2<f32>(1.0), view.size - 1.0);
    let uv = corner * view.inv_size;
    let aos = textureGather(0, history_in, point_clamp, uv);
    let depths = textureGather(1, history_in, point_clamp, uv);
    let f = clamp(q - 0.5 - (corner - 1.0), vec2<f32>(0.0), vec2<f32>(1.0));
    // Gather order: x = (left, bottom), y = (right, bottom), z = (right, top), w = (left, top).
    let bilinear = vec4<f32>((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    var sum = 0.0;
    var weight = 0.0;
    for (var i = 0; i < 4; i++) {
        let w = select(0.0, bilinear[i], same_surface(depths[i], expected));
        sum += w * aos[i];
        weight += w;
    }
    return vec2<f32>(sum / max(weight, 1e-6), weight);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let pixel = vec2<i32>(id.xy);
    let own = current_at(pixel);
    let depth = own.y;
    if depth == NO_SURFACE {
        store(id.xy, 1.0, NO_SURFACE, false);
        return;
    }

    // The spread of the 3x3 neighbours on the same surface, for the clip box. Loaded one texel
    // at a time: the same neighbourhood from four gathers per texture (when AO and depth came
    // in two textures always) took the pass from 0.21 to 0.15 of a GTAO `high` frame on
    // lavapipe, but from 0.061 to 0.107 ms at 1920x1080 on an H100, where the loads ran at 1.1
    // to 1.2 times their texel-rate floor (docs/notes/performance-investigations.md).
    let last = vec2<i32>(view.size) - 1;
    var sum = 0.0;
    var sum_squares = 0.0;
    var count = 0.0;
    for (var dy = -1; dy <= 1; dy++) {
        for (var dx = -1; dx <= 1; dx++) {
            let neighbour = current_at(clamp(pixel + vec2<i32>(dx, dy), vec2<i32>(0), last));
            if same_surface(neighbour.y, depth) {
                let a = neighbour.x;
                sum += a;
                sum_squares += a * a;
                count += 1.0;
            }
        }
    }
    let mean = sum / count;
    let spread = sqrt(max(sum_squares / count - mean * mean, 0.0));
    let current = select(own.x, mean,
                         (temporal.flags & FLAG_FILTER_CURRENT) != 0u);

    if (temporal.flags & FLAG_HISTORY) == 0u {
        store(id.xy, current, depth, true);
        return;
    }
    // Where the surface was last frame, and at what depth.
    let center = vec2<f32>(id.xy) + 0.5;
    let previous = (temporal.prev_view_from_view * vec4<f32>(view_position(center, depth), 1.0)).xyz;
    let expected = -previous.z;
    var q: vec2<f32>;
    if (temporal.flags & FLAG_MOTION_VECTORS) != 0u {
        q = center + textureLoad(motion_vectors, pixel + temporal.motion_offset, 0).xy;
    } else {
        let scale = mix(expected, 1.0, temporal.prev_orthographic);
        let ndc = previous.xy / (temporal.prev_ndc_to_view * scale) + temporal.prev_ndc_offset;
        q = uv_to_pixel(vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5));
    }
    let on_screen = all(q >= vec2<f32>(0.0)) && all(q < view.size) && expected > 0.0;
    let history = select(vec2<f32>(0.0), history_at(q, expected), on_screen);
    if history.y < 1e-3 {
        store(id.xy, current, depth, true);
        return;
    }
    let clipped = clamp(history.x, mean - temporal.variance_gamma * spread,
                        mean + temporal.variance_gamma * spread);
    store(id.xy, mix(current, clipped, temporal.blend), depth, false);
}
