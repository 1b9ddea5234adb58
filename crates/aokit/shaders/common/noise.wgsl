// Per-pixel noise for sample rotation and jitter: every `NoiseKind` (settings.rs) as two values
// in [0, 1) per pixel and frame. noise.rs mirrors each function and generates the tiles that
// `blue` and `white` read; docs/noise.md compares the kinds.

// `NoiseKind` codes (noise::kind_code).
const NOISE_IGN: u32 = 0u;
const NOISE_BLUE: u32 = 1u;
const NOISE_GTAO: u32 = 2u;
const NOISE_BAYER: u32 = 3u;
const NOISE_WHITE: u32 = 4u;
const NOISE_HILBERT_R2: u32 = 5u;
// `TemporalOffset` codes (noise::temporal_code).
const TEMPORAL_GOLDEN_RATIO: u32 = 0u;
const TEMPORAL_R2: u32 = 1u;

// 2^32 times the golden ratio's fraction, and R2's generators 1/g and 1/g^2 with g the plastic
// number (Roberts 2018), rounded: wrapping products with an integer are fract(n * alpha) to
// within n * 2^-33, where f32 products lose the fraction within a few thousand frames.
const GOLDEN_FIXED: u32 = 2654435769u;
const R2_FIXED: vec2<u32> = vec2<u32>(3242174889u, 2447445414u);

// Side of the Hilbert-R2 tile is 2^HILBERT_ORDER: 64 pixels, like the default blue-noise tile.
const HILBERT_ORDER: u32 = 6u;

// 32-bit binary fractions as floats in [0, 1): their top 24 bits, which f32 holds exactly.
fn unit_from_fixed(bits: vec2<u32>) -> vec2<f32> {
    return vec2<f32>(bits >> vec2<u32>(8u)) / 16777216.0;
}

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): cheap, and its low-discrepant 3x3 neighbourhoods average out quickly.
fn interleaved_gradient_noise(pixel: vec2<f32>) -> f32 {
    return fract(52.9829189 * fract(dot(pixel, vec2<f32>(0.06711056, 0.00583715))));
}

// Two decorrelated values: the second reads the pattern transposed. Reading it at an offset
// instead would only add a constant to the first value (the pattern is a fraction of a linear
// function of the pixel), locking each pixel's rotation to its jitter. The 5.588238 pixel shift
// per frame is Jimenez's choice for temporal variation of this noise.
fn ign_noise(pixel: vec2<u32>, frame: u32) -> vec2<f32> {
    let p = vec2<f32>(pixel) + 5.588238 * f32(frame % 64u);
    return vec2<f32>(interleaved_gradient_noise(p), interleaved_gradient_noise(p.yx));
}

// GTAO's noise (Jimenez et al. 2016, as their SIGGRAPH 2016 course slides give it): the 16
// sixteenths in a 4x4 pattern for the rotation, ((y - x) & 3) / 4 for the step offset, turned by 6
// rotations frame by frame and offset by 4 offsets every 6 frames, so a 24-frame cycle sees every
// combination once.
fn gtao_noise(pixel: vec2<u32>, frame: u32) -> vec2<f32> {
    var rotations = array<f32, 6>(60.0, 300.0, 180.0, 240.0, 120.0, 0.0);
    var offsets = array<f32, 4>(0.0, 0.5, 0.25, 0.75);
    let x = pixel.x;
    let y = pixel.y;
    let spatial = f32((((x + y) & 3u) << 2u) + (x & 3u)) / 16.0;
    let offset = f32((y - x) & 3u) / 4.0;
    return fract(vec2<f32>(
        spatial + rotations[frame % 6u] / 360.0,
        offset + offsets[(frame / 6u) % 4u],
    ));
}

// The Dither noise of the Unity Asset Store package "Horizon Based Ambient Occlusion": the 4x4
// Bayer index (Bayer 1973; the 2x2 matrix [[0, 2], [3, 1]] of the low coordinate bits times 4, plus
// that of the next bits) over 16, and its bit reversal over 16: the radical inverse, so the tile's
// 16 pairs are the 16-point Hammersley set.
fn bayer_noise(pixel: vec2<u32>) -> vec2<f32> {
    let low = (((pixel.x ^ pixel.y) & 1u) << 1u) | (pixel.y & 1u);
    let high = ((((pixel.x ^ pixel.y) >> 1u) & 1u) << 1u) | ((pixel.y >> 1u) & 1u);
    let index = 4u * low + high;
    return vec2<f32>(f32(index), f32(reverseBits(index) >> 28u)) / 16.0;
}

// Distance along the Hilbert curve (Hilbert 1891) filling the 2^HILBERT_ORDER tile to the
// pixel's cell: per level, the quadrant's place in the curve's U, then the coordinates turned
// into that quadrant's orientation.
fn hilbert_index(pixel: vec2<u32>) -> u32 {
    let n = 1u << HILBERT_ORDER;
    var x = pixel.x & (n - 1u);
    var y = pixel.y & (n - 1u);
    var index = 0u;
    for (var s = n >> 1u; s > 0u; s >>= 1u) {
        let rx = u32((x & s) != 0u);
        let ry = u32((y & s) != 0u);
        index += s * s * ((3u * rx) ^ ry);
        if ry == 0u {
            if rx == 1u {
                x = n - 1u - x;
                y = n - 1u - y;
            }
            let t = x;
            x = y;
            y = t;
        }
    }
    return index;
}

// Point `index` of the R2 sequence (Roberts 2018): fract(0.5 + index * (1/g, 1/g^2)).
fn r2(index: u32) -> vec2<f32> {
    return unit_from_fixed(index * R2_FIXED + vec2<u32>(0x80000000u));
}

// How far tiled noise moves at `frame`: by the golden ratio's fraction per frame on both values,
// or by R2's step per frame. Frame 0 is not moved.
fn temporal_offset(frame: u32, temporal: u32) -> vec2<f32> {
    if temporal == TEMPORAL_R2 {
        return unit_from_fixed(frame * R2_FIXED);
    }
    return unit_from_fixed(vec2<u32>(frame * GOLDEN_FIXED));
}

// The two noise values of `pixel` at `frame` for noise kind `kind`. `texel` is the pixel's
// texel of the noise tile, which only `blue` and `white` read. Interleaved gradient noise and
// GTAO's pattern move with the frame their own way; the tiled kinds move by temporal_offset.
fn pixel_noise(pixel: vec2<u32>, frame: u32, kind: u32, temporal: u32, texel: vec2<f32>)
    -> vec2<f32> {
    var tiled = texel;
    switch kind {
        case NOISE_IGN: {
            return ign_noise(pixel, frame);
        }
        case NOISE_GTAO: {
            return gtao_noise(pixel, frame);
        }
        case NOISE_BAYER: {
            tiled = bayer_noise(pixel);
        }
        case NOISE_HILBERT_R2: {
            tiled = r2(hilbert_index(pixel));
        }
        case NOISE_BLUE, NOISE_WHITE, default: {}
    }
    return fract(tiled + temporal_offset(frame, temporal));
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
    return unit_from_fixed(vec2<u32>(reverseBits(index), second));
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
