// Per-pixel noise for sample rotation and jitter.

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): cheap, and its low-discrepant 3x3 neighbourhoods average out quickly.
fn interleaved_gradient_noise(pixel: vec2<f32>) -> f32 {
    return fract(52.9829189 * fract(dot(pixel, vec2<f32>(0.06711056, 0.00583715))));
}

// Two decorrelated values in [0, 1) per pixel, moving each frame. The 5.588238 pixel shift per
// frame is Jimenez's choice for temporal variation of this noise.
fn pixel_noise(pixel: vec2<u32>, frame: u32) -> vec2<f32> {
    let p = vec2<f32>(pixel) + 5.588238 * f32(frame % 64u);
    return vec2<f32>(
        interleaved_gradient_noise(p),
        interleaved_gradient_noise(p + vec2<f32>(47.0, 17.0)),
    );
}
