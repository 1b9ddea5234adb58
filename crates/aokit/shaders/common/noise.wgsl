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

// Point `index` of the first two dimensions of the Sobol sequence, a (0, 2)-sequence: every
// power-of-two prefix is stratified in both dimensions. The second dimension's generator matrix
// is Pascal's triangle mod 2, whose columns follow from `column ^= column >> 1`.
fn sobol_2d(index: u32) -> vec2<f32> {
    var i = index;
    var column = 0x80000000u;
    var second = 0u;
    while i != 0u {
        if (i & 1u) != 0u {
            second ^= column;
        }
        i >>= 1u;
        column ^= column >> 1u;
    }
    return vec2<f32>(vec2<u32>(reverseBits(index), second) >> vec2<u32>(8u)) / 16777216.0;
}

// Radical inverse of `index` in base 3: the Halton sequence's second dimension, a third
// dimension independent of sobol_2d's two.
fn halton_3(index: u32) -> f32 {
    var i = index;
    var scale = 1.0 / 3.0;
    var result = 0.0;
    while i != 0u {
        result += f32(i % 3u) * scale;
        i /= 3u;
        scale /= 3.0;
    }
    return result;
}

// Cosine-weighted direction about +Z from a point of the unit square (Malley's method: a uniform
// disk point lifted onto the hemisphere).
fn cosine_hemisphere(u: vec2<f32>) -> vec3<f32> {
    let r = sqrt(u.x);
    let phi = 6.28318531 * u.y;
    return vec3<f32>(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}

// Two unit tangents completing the unit vector `n` to a right-handed orthonormal frame (Duff et
// al. 2017, "Building an Orthonormal Basis, Revisited").
fn tangent_frame(n: vec3<f32>) -> mat2x3<f32> {
    let sign = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    return mat2x3<f32>(
        vec3<f32>(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        vec3<f32>(b, sign + n.y * n.y * a, -n.y),
    );
}
