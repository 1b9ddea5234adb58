// The AO and the linear depth of a pixel in one 32-bit texel (`SpatialSettings::packed_input`):
// the per-pixel kernels write it beside the AO, and the spatial filter's edges kind then reads
// one texture in four gathers where it read two in eight (XeGTAO's main pass hands its denoiser
// AO and edges the same way). The depth keeps its sign, its exponent and the top 13 bits of its
// mantissa, truncated: within 1.3e-4 of itself, relative, under 1% of the filter's default
// `depth_sigma` (0.02). The AO takes the 10 low bits, rounded to steps of 1/1023. NO_SURFACE
// (depth 0) unpacks as NO_SURFACE.

const AO_BITS_MASK: u32 = 0x3ffu;

// `occlusion` is the AO as stored, 1 = unoccluded.
fn pack_ao_and_depth(occlusion: f32, depth: f32) -> u32 {
    let bits = u32(round(saturate(occlusion) * f32(AO_BITS_MASK)));
    return (bitcast<u32>(depth) & ~AO_BITS_MASK) | bits;
}

// The AO of four packed texels (a gather's).
fn unpacked_ao(texels: vec4<u32>) -> vec4<f32> {
    return vec4<f32>(texels & vec4<u32>(AO_BITS_MASK)) * (1.0 / f32(AO_BITS_MASK));
}

// The depth of four packed texels (a gather's).
fn unpacked_depth(texels: vec4<u32>) -> vec4<f32> {
    return bitcast<vec4<f32>>(texels & vec4<u32>(~AO_BITS_MASK));
}
