// Between the input's resolution and the working resolution (docs/denoise.md, "Resolution"): the
// settings both directions share. A program is this file plus downsample.wgsl or upsample.wgsl.
// Mirrors `ResampleUniforms` in uniforms.rs.

struct ResampleUniforms {
    // Input pixels per working texel along each axis: 2 or 4.
    scale: u32,
    // A DOWNSAMPLE_* code: which texel of each block the working texel takes.
    downsample: u32,
    // An UPSAMPLE_* code: how a pixel combines the working texels around it.
    upsample: u32,
    // Relative depth difference below which a working texel shows the pixel's surface.
    threshold: f32,
    flags: u32,
}

@group(0) @binding(1) var<uniform> resample: ResampleUniforms;

// `Downsample as u32` and `Upsample as u32` in Rust (a test compares them).
const DOWNSAMPLE_POINT: u32 = 0u;
const DOWNSAMPLE_MIN: u32 = 1u;
const DOWNSAMPLE_MAX: u32 = 2u;
const DOWNSAMPLE_CHECKERBOARD: u32 = 3u;
const UPSAMPLE_BILATERAL: u32 = 0u;
const UPSAMPLE_BILATERAL_BILINEAR: u32 = 1u;
const UPSAMPLE_NEAREST_DEPTH: u32 = 2u;

// Downsample the motion vectors too (the temporal filter runs at working resolution).
const FLAG_MOTION_VECTORS: u32 = 1u;
// Upsample the bent normals too.
const FLAG_BENT_NORMALS: u32 = 2u;
