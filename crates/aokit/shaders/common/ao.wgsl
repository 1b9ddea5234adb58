// requires: common/view.wgsl, common/encoding.wgsl
// The interface every AO method kernel shares (mirrors `AoUniforms` in uniforms.rs): its settings,
// its inputs and outputs, the surface at the pixel, and the final shaping of the result. The
// per-pixel kernels add common/ao_entry.wgsl's entry point, and a method's file its `estimate`.

struct AoUniforms {
    // World-space radius.
    radius: f32,
    // Sample weight = saturate(distance * falloff_mul + falloff_add): 1 inside, 0 at the radius.
    falloff_mul: f32,
    falloff_add: f32,
    intensity: f32,
    power: f32,
    // Upper and lower clamps of the screen radius, pixels.
    max_radius_px: f32,
    min_radius_px: f32,
    // Point methods' self-occlusion bias, world units.
    bias: f32,
    // Horizon methods' angle bias, radians.
    angle_bias: f32,
    // AO weight over view depth: saturate(depth * fade_mul + fade_add).
    fade_mul: f32,
    fade_add: f32,
    // GTAO: horizon fall-back blend; VBAO: occluder thickness in world units.
    thickness: f32,
    // VBAO: thickness added per unit of occluder depth.
    thickness_growth: f32,
    // Samples, directions or slices.
    count: u32,
    // Steps per direction or per side; SAO: turns of its spiral.
    steps: u32,
    flags: u32,
    // Exponent of the step distribution: 1 even, 2 quadratic.
    step_power: f32,
    // NOISE_* and TEMPORAL_* codes of common/noise.wgsl.
    noise_kind: u32,
    noise_temporal: u32,
    // With DEPTH_MIPS, 2^-depth_mip_offset: the level selection's scale (mip_level).
    mip_scale: f32,
}

const FLAG_NORMALIZE_SLICES: u32 = 1u;

// AoSettings::bent_normals, compiled in rather than a flag: a kernel without bent normals holds
// none of their code. The per-pixel kernels get it from the settings (passes/kernel/method.rs); the
// others have no bent normals.
override BENT_NORMALS: bool = false;

@group(0) @binding(1) var<uniform> ao: AoUniforms;
@group(0) @binding(2) var linear_depth: texture_2d<f32>;
@group(0) @binding(3) var normals: texture_2d<u32>;
@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(5) var point_clamp: sampler;
// View-space bent normal in xyz and AO in w, with BENT_NORMALS (a 1x1 stand-in
// otherwise, never written).
@group(0) @binding(6) var bent_out: texture_storage_2d<rgba16float, write>;
// The noise tile of `blue` and `white` noise, two values per texel, repeated over the image (a
// 1x1 stand-in for the kinds computed here).
@group(0) @binding(7) var noise_tile: texture_2d<f32>;
// With DEPTH_MIPS on, the working depth's MIP chain in one texture (passes/kernel/depth_mips.rs,
// `DepthMipsPass::create_atlas`): level L's texel t, covering pixels t * 2^L to (t + 1) * 2^L,
// at atlas_origin(L) + t. A 1x1 stand-in otherwise, never read.
@group(0) @binding(8) var depth_mips: texture_2d<f32>;
// How far samples read the chain (AoSettings::depth_mips), one of the DEPTH_MIPS_* codes
// (`DepthMipsRead` in passes/kernel/method.rs). The pipeline compiles each kernel for one of them,
// so that the code of the others, and of the chain when it is off, is not in it.
override DEPTH_MIPS: u32 = 0u;
// Every sample reads the working depth.
const DEPTH_MIPS_OFF: u32 = 0u;
// fp32: every level, 0 included, in the atlas; samples read it without a branch.
const DEPTH_MIPS_ATLAS: u32 = 1u;
// fp16: levels 1 to 4 in the atlas, level 0 from the working depth (fp16 would round the
// nearest samples' depths by more than their distance from the shaded point can take).
const DEPTH_MIPS_COARSE: u32 = 2u;

const PI: f32 = 3.14159265;
const HALF_PI: f32 = 1.57079633;
const TWO_PI: f32 = 6.28318531;

// The shaded point of one pixel.
struct Surface {
    pixel: vec2<u32>,
    // Pixel centre, in pixels.
    center: vec2<f32>,
    depth: f32,
    // View-space position, unit vector towards the eye, unit normal.
    p: vec3<f32>,
    v: vec3<f32>,
    n: vec3<f32>,
    // The AO radius on screen, clamped to [min_radius_px, max_radius_px].
    radius_px: f32,
    // The world radius that covers radius_px here, and its ratio to ao.radius: lengths the
    // settings give relative to the radius (falloff, bias, thickness) scale with it.
    radius: f32,
    scale: f32,
    // falloff_weight's slope here: ao.falloff_mul over scale, divided once per pixel.
    falloff_mul: f32,
}

fn load_surface(pixel: vec2<u32>) -> Surface {
    var s: Surface;
    s.pixel = pixel;
    s.center = vec2<f32>(pixel) + 0.5;
    s.depth = textureLoad(linear_depth, pixel, 0).r;
    s.p = view_position(s.center, s.depth);
    s.v = view_direction(s.p);
    // A visible surface faces the eye, but normals interpolated across a silhouette, or
    // reconstructed from depth there, can face away, and a hemisphere about such a normal lies
    // mostly behind the surface: it would read as fully occluded. Those normals are turned
    // towards V until they are at most grazing.
    let n = unpack_oct32(textureLoad(normals, pixel, 0).r);
    s.n = normalize(n + max(0.0, 0.01 - dot(n, s.v)) * s.v);
    let unclamped = pixels_at_depth(ao.radius, s.depth);
    s.radius_px = clamp(unclamped, ao.min_radius_px, ao.max_radius_px);
    s.scale = select(1.0, s.radius_px / unclamped, unclamped > 0.0);
    s.radius = ao.radius * s.scale;
    s.falloff_mul = ao.falloff_mul / s.scale;
    return s;
}

// No surface, a radius under one pixel, or past max_distance, where the fade leaves AO 1:
// nothing in the depth buffer can occlude, or nothing of it would show.
fn nothing_to_sample(s: Surface) -> bool {
    return s.depth == NO_SURFACE || s.radius_px < 1.0 || s.depth * ao.fade_mul + ao.fade_add <= 0.0;
}

// Relative depth spread above which a 2x2 footprint is taken to straddle a depth edge. A plane
// seen 2 degrees from grazing spreads about 10% per pixel at 60 degrees field of view.
const DEPTH_EDGE: f32 = 0.1;

// The surface seen near a continuous pixel position.
struct SeenSurface {
    // Linear depth, NO_SURFACE for none.
    depth: f32,
    // Where it was seen, in pixels: the position asked for when `exact`, else a texel centre.
    at: vec2<f32>,
    exact: bool,
}

// Coarser levels the depth MIP chain has: up to 4, each at least 2 texels on a side so that a
// gather's 2x2 footprint fits in it (`atlas_levels` in passes/kernel/depth_mips.rs).
fn mip_levels() -> u32 {
    let shorter = u32(min(view.size.x, view.size.y));
    return min(4u, max(firstLeadingBit(shorter), 1u) - 1u);
}

// The depth MIP level a sample `distance_px` pixels from the shaded pixel reads: the farther,
// the coarser, so that far samples stay in the cache (XeGTAO's depthMIPSamplingOffset, floored
// here). Always 0 without DEPTH_MIPS. floor(log2(d) - offset) is the index of the highest set
// bit of d * 2^-offset: an integer bit scan where log2 would cost a polynomial on some
// adapters (on lavapipe GTAO's time with the chain went from 1.22-1.25 to 1.11-1.13 of off).
fn mip_level(distance_px: f32) -> u32 {
    if DEPTH_MIPS == DEPTH_MIPS_OFF {
        return 0u;
    }
    let level = firstLeadingBit(max(u32(distance_px * ao.mip_scale), 1u));
    return min(level, mip_levels());
}

// Where texel (0, 0) of level `level` (1 to 4) lies in the depth_mips atlas: right of level 0
// where the atlas holds it, at row H - (H >> (level - 1)) (`atlas_origin` in
// depth_mips.wgsl), below the levels before it.
fn atlas_origin(level: u32) -> vec2<f32> {
    let row = view.size.y - floor(view.size.y * inverse_pow2(level - 1u));
    return vec2<f32>(select(0.0, view.size.x, DEPTH_MIPS == DEPTH_MIPS_ATLAS), row);
}

// The 2x2 texels of `level` around continuous pixel position `q`, gathered at their shared
// corner (see surface_at), from the atlas, or at level 0 from the working depth where the
// atlas lacks it: the depths, the corner in the level's texels and the level's texel width
// in pixels.
struct Footprint {
    depths: vec4<f32>,
    corner: vec2<f32>,
    scale: f32,
}

fn footprint(q: vec2<f32>, level: u32) -> Footprint {
    if reads_atlas(level) {
        let grid = atlas_level(level);
        let corner = clamp(floor(q * grid.inverse_scale - 0.5) + 1.0, vec2<f32>(1.0),
                           grid.size - 1.0);
        let uv = (grid.origin + corner) / vec2<f32>(textureDimensions(depth_mips));
        return Footprint(textureGather(0, depth_mips, point_clamp, uv), corner, grid.scale);
    }
    // The same corner at a scale of 1, written out: the scaled form for both cost the kernels
    // 1 to 5% on lavapipe with the chain off.
    let corner = clamp(floor(q - 0.5) + 1.0, vec2<f32>(1.0), view.size - 1.0);
    return Footprint(textureGather(0, linear_depth, point_clamp, corner * view.inv_size), corner, 1.0);
}

// Whether samples at `level` read the depth_mips atlas rather than the working depth.
fn reads_atlas(level: u32) -> bool {
    return DEPTH_MIPS == DEPTH_MIPS_ATLAS || (DEPTH_MIPS == DEPTH_MIPS_COARSE && level > 0u);
}

// 2^-level, exactly, from the exponent's bits. The levels' texel widths are powers of two, so a
// product with this equals the quotient by 2^level to the bit, without the division's
// reciprocal, which GPUs run on their slower special-function units (a read of the atlas took
// five).
fn inverse_pow2(level: u32) -> f32 {
    return bitcast<f32>((127u - level) << 23u);
}

// Level `level`'s grid in the atlas: its texel width in pixels and the inverse, its size in
// texels (at least one a side) and where its texel (0, 0) lies.
struct AtlasLevel {
    scale: f32,
    inverse_scale: f32,
    size: vec2<f32>,
    origin: vec2<f32>,
}

fn atlas_level(level: u32) -> AtlasLevel {
    let inverse_scale = inverse_pow2(level);
    let size = max(floor(view.size * inverse_scale), vec2<f32>(1.0));
    return AtlasLevel(f32(1u << level), inverse_scale, size,
                      select(vec2<f32>(0.0), atlas_origin(level), level > 0u));
}

// The surface seen at continuous pixel position `q`, read at depth MIP level `level` (0: the
// working depth; see mip_level). Inside one surface, 1 / depth (perspective) or depth
// (orthographic) is affine in screen space across a plane, so interpolating it bilinearly
// gives the depth exactly at `q`, on a plane seen at any angle; a point method comparing a
// sample with the nearest texel instead sees planes at grazing angles occlude themselves.
// Across a depth edge interpolation would invent a surface between foreground and background,
// so there the nearest texel is returned with its centre. A coarser level does the same on its
// own grid, whose texels are 2^level pixels wide.
fn surface_at(q: vec2<f32>, level: u32) -> SeenSurface {
    // The 2x2 texels around `q`, gathered at their shared corner: a coordinate there cannot
    // round into a neighbouring footprint the way `q` itself can near texel centres, so `f`
    // weights exactly the texels read. In the outermost half texel the footprint stays inside
    // the image and `f` extrapolates, which is exact on a plane where clamping is not. Gather
    // order: x = (left, bottom), y = (right, bottom), z = (right, top), w = (left, top), with
    // "top" the smaller row index.
    let read = footprint(q, level);
    let depths = read.depths;
    let corner = read.corner;
    let f = q / read.scale - 0.5 - (corner - 1.0);
    let lowest = min(min(depths.x, depths.y), min(depths.z, depths.w));
    let highest = max(max(depths.x, depths.y), max(depths.z, depths.w));
    if lowest > 0.0 && highest <= lowest * (1.0 + DEPTH_EDGE) {
        let ortho = view.orthographic > 0.5;
        let w = select(1.0 / depths, depths, ortho);
        let b = mix(mix(w.w, w.z, f.x), mix(w.x, w.y, f.x), f.y);
        return SeenSurface(select(1.0 / b, b, ortho), q, true);
    }
    let right = f.x >= 0.5;
    let bottom = f.y >= 0.5;
    let depth = select(select(depths.w, depths.z, right), select(depths.x, depths.y, right), bottom);
    let texel = corner + select(vec2<f32>(-0.5), vec2<f32>(0.5), vec2<bool>(right, bottom));
    return SeenSurface(depth, texel * read.scale, false);
}

// The texel of `level` that continuous pixel position `q` lies in, seen at its centre: one load
// where surface_at takes a gather and its interpolation. Never `exact`.
fn nearest_surface(q: vec2<f32>, level: u32) -> SeenSurface {
    if reads_atlas(level) {
        let grid = atlas_level(level);
        let texel = min(floor(q * grid.inverse_scale), grid.size - 1.0);
        let depth = textureLoad(depth_mips, vec2<u32>(grid.origin + texel), 0).r;
        return SeenSurface(depth, (texel + 0.5) * grid.scale, false);
    }
    let texel = floor(q);
    return SeenSurface(textureLoad(linear_depth, vec2<u32>(texel), 0).r, texel + 0.5, false);
}

// Linear depth of the surface seen at continuous pixel position `q`, read at MIP level `level`
// (see surface_at); NO_SURFACE off screen.
fn depth_at(q: vec2<f32>, level: u32) -> f32 {
    if any(q < vec2<f32>(0.0)) || any(q >= view.size) {
        return NO_SURFACE;
    }
    return surface_at(q, level).depth;
}

// A sample's weight by its distance from the shaded point: 1 inside, fading to 0 at the
// surface's radius.
fn falloff_weight(s: Surface, distance: f32) -> f32 {
    return saturate(distance * s.falloff_mul + ao.falloff_add);
}

// Shapes visibility into the stored AO: intensity, power, then the distance fade.
fn shape_ao(visibility: f32, depth: f32) -> f32 {
    let shaped = pow(saturate(1.0 - ao.intensity * (1.0 - saturate(visibility))), ao.power);
    return mix(1.0, shaped, saturate(depth * ao.fade_mul + ao.fade_add));
}

// Stores the shaped AO (and the bent normal) and returns the AO stored.
fn store_ao(s: Surface, visibility: f32, bent: vec3<f32>) -> f32 {
    let value = shape_ao(visibility, s.depth);
    textureStore(ao_out, s.pixel, vec4<f32>(value, 0.0, 0.0, 0.0));
    if BENT_NORMALS {
        let b = select(s.n, normalize(bent), dot(bent, bent) > 1e-12);
        textureStore(bent_out, s.pixel, vec4<f32>(b, value));
    }
    return value;
}

// AO 1 and the normal as bent normal, for pixels with nothing to sample.
fn store_unoccluded(s: Surface) {
    textureStore(ao_out, s.pixel, vec4<f32>(1.0, 0.0, 0.0, 0.0));
    if BENT_NORMALS {
        let n = select(vec3<f32>(0.0), s.n, s.depth != NO_SURFACE);
        textureStore(bent_out, s.pixel, vec4<f32>(n, 1.0));
    }
}
