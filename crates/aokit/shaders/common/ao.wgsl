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
    // With DEPTH_MIPS, the offset of the depth MIP level selection in log2 pixels (mip_level).
    mip_offset: f32,
}

const FLAG_NORMALIZE_SLICES: u32 = 1u;
const FLAG_BENT_NORMALS: u32 = 2u;

@group(0) @binding(1) var<uniform> ao: AoUniforms;
@group(0) @binding(2) var linear_depth: texture_2d<f32>;
@group(0) @binding(3) var normals: texture_2d<u32>;
@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;
@group(0) @binding(5) var point_clamp: sampler;
// View-space bent normal in xyz and AO in w, when FLAG_BENT_NORMALS is set (a 1x1 stand-in
// otherwise, never written).
@group(0) @binding(6) var bent_out: texture_storage_2d<rgba16float, write>;
// The noise tile of `blue` and `white` noise, two values per texel, repeated over the image (a
// 1x1 stand-in for the kinds computed here).
@group(0) @binding(7) var noise_tile: texture_2d<f32>;
// With DEPTH_MIPS, levels 1 to 4 of the working depth's MIP chain, stacked in one texture
// (passes/depth_mips.rs, `DepthMipsPass::create_atlas`): level L's texel t, covering pixels
// t * 2^L to (t + 1) * 2^L, at (t.x, atlas_row(L) + t.y). A 1x1 stand-in otherwise, never read.
@group(0) @binding(8) var depth_mips: texture_2d<f32>;
// Whether far samples read the chain (AoSettings::depth_mips); when off, the pipeline
// compiles the kernels without any of its code.
override DEPTH_MIPS: bool = false;

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
// gather's 2x2 footprint fits in it (`coarser_levels` in passes/depth_mips.rs).
fn mip_levels() -> u32 {
    let shorter = u32(min(view.size.x, view.size.y));
    return min(4u, max(firstLeadingBit(shorter), 1u) - 1u);
}

// The depth MIP level a sample `distance_px` pixels from the shaded pixel reads: the farther,
// the coarser, so that far samples stay in the cache (XeGTAO's depthMIPSamplingOffset, floored
// here). Always 0 without DEPTH_MIPS.
fn mip_level(distance_px: f32) -> u32 {
    if !DEPTH_MIPS {
        return 0u;
    }
    let level = floor(log2(max(distance_px, 1.0)) - ao.mip_offset);
    return u32(clamp(level, 0.0, f32(mip_levels())));
}

// First row of level `level` (1 to 4) in the depth_mips atlas: the levels above it stacked.
fn atlas_row(level: u32) -> f32 {
    var row = 0.0;
    for (var k = 1u; k < level; k++) {
        row += max(floor(view.size.y / f32(1u << k)), 1.0);
    }
    return row;
}

// The surface seen at continuous pixel position `q`, read at depth MIP level `level` (0: the
// working depth; see mip_level). Inside one surface, 1 / depth (perspective) or depth
// (orthographic) is affine in screen space across a plane, so interpolating it bilinearly
// gives the depth exactly at `q`, on a plane seen at any angle; reading the nearest texel
// instead makes planes seen at grazing angles occlude themselves. Across a depth edge
// interpolation would invent a surface between foreground and background, so there the nearest
// texel is returned with its centre. A coarser level does the same on its own grid, whose
// texels are 2^level pixels wide.
fn surface_at(q: vec2<f32>, level: u32) -> SeenSurface {
    // The 2x2 texels around `q`, gathered at their shared corner: a coordinate there cannot
    // round into a neighbouring footprint the way `q` itself can near texel centres, so `f`
    // weights exactly the texels read. In the outermost half texel the footprint stays inside
    // the image and `f` extrapolates, which is exact on a plane where clamping is not. Gather
    // order: x = (left, bottom), y = (right, bottom), z = (right, top), w = (left, top), with
    // "top" the smaller row index.
    var scale = 1.0;
    var corner: vec2<f32>;
    var depths: vec4<f32>;
    var f: vec2<f32>;
    if DEPTH_MIPS && level > 0u {
        // The same footprint on the level's grid, inside its rectangle of the atlas.
        scale = f32(1u << level);
        let ql = q / scale;
        let size = max(floor(view.size / scale), vec2<f32>(1.0));
        corner = clamp(floor(ql - 0.5) + 1.0, vec2<f32>(1.0), size - 1.0);
        let at = vec2<f32>(corner.x, corner.y + atlas_row(level));
        depths = textureGather(0, depth_mips, point_clamp, at / vec2<f32>(textureDimensions(depth_mips)));
        f = ql - 0.5 - (corner - 1.0);
    } else {
        corner = clamp(floor(q - 0.5) + 1.0, vec2<f32>(1.0), view.size - 1.0);
        depths = textureGather(0, linear_depth, point_clamp, corner * view.inv_size);
        f = q - 0.5 - (corner - 1.0);
    }
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
    return SeenSurface(depth, texel * scale, false);
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
    return saturate(distance / s.scale * ao.falloff_mul + ao.falloff_add);
}

// Shapes visibility into the stored AO: intensity, power, then the distance fade.
fn shape_ao(visibility: f32, depth: f32) -> f32 {
    let shaped = pow(saturate(1.0 - ao.intensity * (1.0 - saturate(visibility))), ao.power);
    return mix(1.0, shaped, saturate(depth * ao.fade_mul + ao.fade_add));
}

fn store_ao(s: Surface, visibility: f32, bent: vec3<f32>) {
    let value = shape_ao(visibility, s.depth);
    textureStore(ao_out, s.pixel, vec4<f32>(value, 0.0, 0.0, 0.0));
    if (ao.flags & FLAG_BENT_NORMALS) != 0u {
        let b = select(s.n, normalize(bent), dot(bent, bent) > 1e-12);
        textureStore(bent_out, s.pixel, vec4<f32>(b, value));
    }
}

// AO 1 and the normal as bent normal, for pixels with nothing to sample.
fn store_unoccluded(s: Surface) {
    textureStore(ao_out, s.pixel, vec4<f32>(1.0, 0.0, 0.0, 0.0));
    if (ao.flags & FLAG_BENT_NORMALS) != 0u {
        let n = select(vec3<f32>(0.0), s.n, s.depth != NO_SURFACE);
        textureStore(bent_out, s.pixel, vec4<f32>(n, 1.0));
    }
}
