// requires: common/view.wgsl, common/ao.wgsl, common/subsample_chain.wgsl, kernel/msvo/msvo.wgsl
// Multi-scale volumetric obscurance, one level (passes/kernel/msvo.rs): the approach of Microsoft
// MiniEngine's SSAO (DirectX-Graphics-Samples) and Unity PostProcessing's Multi-Scale Volumetric
// Obscurance (Post-processing Stack v2), written for this project's conventions. `linear_depth`
// holds the depth MIP chain; `ao_out` is the level's output, and the level is the chain level of
// its size. Each texel of the level estimates the fraction of a sphere around its surface point
// that lies in front of the depth buffer, from sample pairs mirrored about the texel on a fixed
// disc of whole texels; a sample far in front of the sphere is taken for a thin occluder and
// rejected (`msvo.thickness`).

// Radius of the sample disc in texels of the level (MiniEngine's and Unity's 5): level k's
// disc covers 5 * 2^k working texels, so the levels together cover radii from 5 texels up.
const DISC_RADIUS: f32 = 5.0;
// Half of the disc's whole-texel offsets (their mirrors are the other half), in the order the
// pairs are taken: each next pair lies farthest from the centre, the rim and the pairs before,
// so that any prefix (`ao.count / 2` pairs) covers the disc evenly. Private rather than const:
// a const array indexed by the loop is copied whole at each read (lavapipe's frame took 1.5x
// longer with it).
var<private> PAIRS: array<vec2<f32>, 32> = array<vec2<f32>, 32>(
    vec2(-2.0, 1.0), vec2(1.0, 2.0), vec2(3.0, 1.0), vec2(-1.0, 3.0),
    vec2(-3.0, 2.0), vec2(2.0, 3.0), vec2(3.0, 0.0), vec2(0.0, 3.0),
    vec2(-3.0, 1.0), vec2(1.0, 3.0), vec2(-2.0, 2.0), vec2(2.0, 2.0),
    vec2(3.0, 2.0), vec2(-2.0, 3.0), vec2(2.0, 1.0), vec2(-1.0, 2.0),
    vec2(2.0, 0.0), vec2(4.0, 0.0), vec2(0.0, 2.0), vec2(0.0, 4.0),
    vec2(-1.0, 1.0), vec2(1.0, 1.0), vec2(1.0, 0.0), vec2(0.0, 1.0),
    vec2(-4.0, 1.0), vec2(4.0, 1.0), vec2(-1.0, 4.0), vec2(1.0, 4.0),
    vec2(-3.0, 3.0), vec2(3.0, 3.0), vec2(-4.0, 2.0), vec2(4.0, 2.0),
);

// The fraction of the sphere's chord at a sample that lies in front of the depth buffer there:
// the chord spans `center +- half_chord`; below 0 the sample is in front of the whole chord,
// above 1 behind it. No surface is infinitely far: nothing there occludes.
fn disocclusion(sample_depth: f32, center: f32, half_chord: f32) -> f32 {
    if sample_depth == NO_SURFACE {
        return 1.0;
    }
    return 0.5 + (sample_depth - center) / (2.0 * half_chord);
}

// Volumetric obscurance of texel `t` of `level`: 1 unoccluded, 0 the sphere's whole front half
// filled. 1 where there is nothing to sample, and where a finer level's disc already covers the
// AO radius, so that each scale counts once.
fn level_visibility(t: vec2<u32>, level: u32) -> f32 {
    // Levels as i32: naga's GLSL output checks a load against textureSize(image, level), which
    // takes no u32 (wgpu's GL backend).
    let depth = textureLoad(linear_depth, t, i32(level)).r;
    if depth == NO_SURFACE || depth * ao.fade_mul + ao.fade_add <= 0.0 {
        return 1.0;
    }
    let texel_px = f32(1u << level);
    let unclamped = pixels_at_depth(ao.radius, depth);
    let radius_px = clamp(unclamped, ao.min_radius_px, ao.max_radius_px);
    if radius_px < 1.0 || (level > 0u && radius_px <= 0.5 * DISC_RADIUS * texel_px) {
        return 1.0;
    }
    // The level's sphere: the AO radius, or its disc where that is smaller. Its samples then
    // spread over `disc_px` working texels.
    let disc_px = min(radius_px, DISC_RADIUS * texel_px);
    let sphere = ao.radius * disc_px / unclamped;
    let spread = disc_px / (DISC_RADIUS * texel_px);
    let center = vec2<f32>(t) + 0.5;
    let dims = vec2<f32>(textureDimensions(linear_depth, level));
    var sum = 0.0;
    var total = 0.0;
    for (var i = 0u; i < ao.count / 2u; i++) {
        let o = PAIRS[i];
        let a = floor(center + o * spread);
        let b = floor(center - o * spread);
        if any(min(a, b) < vec2<f32>(0.0)) || any(max(a, b) >= dims) {
            continue;
        }
        // Where the two depths came from, in working pixels: the subsample shifts each level
        // texel's depth by up to a texel, so the pair is centred on the working depth at its
        // own midpoint (depth_at: exact on a plane), and a plane seen at any angle leaves the
        // pair's chords exactly as full as they are empty.
        let sa = vec2<f32>(subsample_source(vec2<u32>(a), level)) + 0.5;
        let sb = vec2<f32>(subsample_source(vec2<u32>(b), level)) + 0.5;
        let reach = 0.5 * length(sa - sb) / disc_px;
        let mid = depth_at(0.5 * (sa + sb), 0u);
        if reach >= 1.0 || mid == NO_SURFACE {
            continue;
        }
        // The sphere's thickness at the pair's offset, which also weights the pair: the
        // whole-texel offsets sample the disc's area evenly, each standing for a column.
        let thickness = sqrt(1.0 - reach * reach);
        let half_chord = sphere * thickness;
        let depth_a = textureLoad(linear_depth, vec2<u32>(a), i32(level)).r;
        let depth_b = textureLoad(linear_depth, vec2<u32>(b), i32(level)).r;
        let da = disocclusion(depth_a, mid, half_chord);
        let db = disocclusion(depth_b, mid, half_chord);
        // A sample more than `msvo.thickness` chords in front of the sphere is rejected: the
        // pair then counts its mirror as unoccluded too (MiniEngine's pair test), since an
        // occluder that far in front is thin, and may hide the open space behind it.
        let reject_a = saturate(-da / ao.thickness);
        let reject_b = saturate(-db / ao.thickness);
        let pair = saturate(clamp(da, reject_b, 1.0) + clamp(db, reject_a, 1.0) - reject_a * reject_b);
        sum += thickness * pair;
        total += thickness;
    }
    return select(1.0, sum / total, total > 0.0);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(ao_out)) {
        return;
    }
    let level = output_level();
    let visibility = level_visibility(id.xy, level);
    // `ao.steps` is the level count, which a short chain may cut: a single level is the
    // finished AO, shaped as every method's is; otherwise the merge shapes the product.
    var value = visibility;
    if min(ao.steps, textureNumLevels(linear_depth)) == 1u {
        value = shape_ao(visibility, textureLoad(linear_depth, id.xy, 0).r);
    }
    textureStore(ao_out, id.xy, vec4<f32>(value, 0.0, 0.0, 0.0));
}
