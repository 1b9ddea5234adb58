// Between the input's resolution and the working resolution (docs/denoise.md, "Resolution"): the
// codes both directions share. A program is this file plus downsample.wgsl or upsample.wgsl.
//
// Every choice of code path (mode, scale, optional outputs) is an `override`, fixed per
// pipeline, and only values stay in a buffer. Besides leaving the unused paths out of the
// code, that spares lavapipe (Mesa 22.3) its per-dispatch folding of uniforms that steer
// control flow: where the folded shader comes out much smaller it compiles it afresh at every
// dispatch, which the downsample at a scale of 4 did (one compile per frame, 5 of quarter
// resolution's 8 ms a frame at 320x180).

// `Downsample as u32` and `Upsample as u32` in Rust (a test compares them).
const DOWNSAMPLE_POINT: u32 = 0u;
const DOWNSAMPLE_MIN: u32 = 1u;
const DOWNSAMPLE_MAX: u32 = 2u;
const DOWNSAMPLE_CHECKERBOARD: u32 = 3u;
const UPSAMPLE_BILATERAL: u32 = 0u;
const UPSAMPLE_BILATERAL_BILINEAR: u32 = 1u;
const UPSAMPLE_NEAREST_DEPTH: u32 = 2u;

// Input pixels per working texel along each axis: 2 or 4 (the back-face pass also runs at 1).
override SCALE: u32;

// The pixel the point downsample takes for working texel `texel`: the top-left one of its
// block's central 2x2 (the choice of ybniaobu's Unity YPipeline; the texel itself at a scale of 1),
// clamped to `last`, the input's last pixel. The back-face pass measures thickness at the same
// pixel.
fn point_pixel(texel: vec2<u32>, last: vec2<u32>) -> vec2<u32> {
    return min(texel * SCALE + max(SCALE / 2u, 1u) - 1u, last);
}
