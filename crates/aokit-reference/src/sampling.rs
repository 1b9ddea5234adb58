//! Low-discrepancy hemisphere samples with per-pixel scrambling.
//!
//! Each pixel draws its rays from the first two dimensions of the Sobol sequence, a (0, 2)
//! sequence: every power-of-two prefix is stratified in both dimensions at once. Each pixel gets
//! its own Owen scrambling and its own shuffle of the sample order (Burley, "Practical Hash-based
//! Owen Scrambling", JCGT 9(4), 2020), so neighbouring pixels' errors are uncorrelated while each
//! pixel keeps the sequence's stratification, for any ray count.

use glam::Vec3;

/// A pixel's sample stream.
///
/// ```
/// use aokit_reference::{PixelSampler, cosine_hemisphere};
/// let (seed, width) = (7, 640);
/// let (x, y) = (100u64, 20u64);
/// let sampler = PixelSampler::new(seed, y * width + x);
/// // The pixel's first 64 ray directions, about +Z.
/// let directions: Vec<_> = (0..64).map(|i| cosine_hemisphere(sampler.square(i))).collect();
/// assert!(directions.iter().all(|d| d.z >= 0.0));
/// // The same seed and pixel give the same rays, whatever order pixels are traced in.
/// assert_eq!(PixelSampler::new(seed, y * width + x).square(5), sampler.square(5));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PixelSampler {
    shuffle_seed: u32,
    seeds: [u32; 2],
}

/// A well-mixed 32-bit hash of two words (a 64-bit finaliser in the style of splitmix64).
fn hash(a: u64, b: u64) -> u64 {
    let mut x = a ^ b.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

/// An Owen scrambling of the bits of `x` read from the most significant end: flipping bit `k`
/// depends only on the bits above it. Built from the hash Burley (2020) gives for
/// Laine and Karras's bit-reversed formulation, whose multipliers are his.
fn owen_scramble(x: u32, seed: u32) -> u32 {
    let mut v = x.reverse_bits().wrapping_add(seed);
    v ^= v.wrapping_mul(0x6c50_b47c);
    v ^= v.wrapping_mul(0xb82f_1e52);
    v ^= v.wrapping_mul(0xc7af_e638);
    v ^= v.wrapping_mul(0x8d22_f6e6);
    v.reverse_bits()
}

/// Second Sobol dimension: the generator matrix is Pascal's triangle mod 2, whose columns are
/// produced by `v ^= v >> 1` from the top bit.
fn sobol_second(mut index: u32) -> u32 {
    let mut column = 1u32 << 31;
    let mut result = 0;
    while index != 0 {
        if index & 1 != 0 {
            result ^= column;
        }
        index >>= 1;
        column ^= column >> 1;
    }
    result
}

/// A 32-bit fraction as a float in `[0, 1)`, keeping the 24 bits an `f32` can hold.
fn unit(bits: u32) -> f32 {
    (bits >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
}

impl PixelSampler {
    /// The stream of pixel `pixel` for image seed `seed`.
    ///
    /// ```
    /// use aokit_reference::PixelSampler;
    /// // Neighbouring pixels get unrelated streams, so their errors do not line up.
    /// assert_ne!(PixelSampler::new(0, 41).square(0), PixelSampler::new(0, 42).square(0));
    /// ```
    pub fn new(seed: u64, pixel: u64) -> Self {
        let h = hash(seed, pixel);
        let g = hash(h, 0x5eed);
        Self {
            shuffle_seed: h as u32,
            seeds: [(h >> 32) as u32, g as u32],
        }
    }

    /// Sample `index` as a point of the unit square.
    ///
    /// ```
    /// use aokit_reference::PixelSampler;
    /// let sampler = PixelSampler::new(3, 12);
    /// // Stratified: the first 4 samples split evenly between the halves of each axis.
    /// let first: Vec<[f32; 2]> = (0..4).map(|i| sampler.square(i)).collect();
    /// assert_eq!(first.iter().filter(|p| p[0] < 0.5).count(), 2);
    /// assert_eq!(first.iter().filter(|p| p[1] < 0.5).count(), 2);
    /// ```
    pub fn square(&self, index: u32) -> [f32; 2] {
        let i = owen_scramble(index, self.shuffle_seed);
        [
            unit(owen_scramble(i.reverse_bits(), self.seeds[0])),
            unit(owen_scramble(sobol_second(i), self.seeds[1])),
        ]
    }
}

/// Cosine-weighted direction about +Z from a point of the unit square (Malley's method: a
/// uniform disk point lifted onto the hemisphere). `u` is `sin^2` of the angle to +Z.
///
/// ```
/// use aokit_reference::cosine_hemisphere;
/// let d = cosine_hemisphere([0.36, 0.25]);
/// assert!((d.length() - 1.0).abs() < 1e-6);
/// // sin^2 = 0.36, so cos = 0.8; a quarter turn about +Z points the rest along +Y.
/// assert!((d.z - 0.8).abs() < 1e-6 && (d.y - 0.6).abs() < 1e-6);
/// ```
pub fn cosine_hemisphere([u, v]: [f32; 2]) -> Vec3 {
    let r = u.sqrt();
    let (sin, cos) = (std::f32::consts::TAU * v).sin_cos();
    Vec3::new(r * cos, r * sin, (1.0 - u).max(0.0).sqrt())
}

/// Two unit tangents completing `n` to a right-handed orthonormal frame, without a branch on a
/// special axis (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017).
///
/// ```
/// use aokit_reference::{cosine_hemisphere, tangent_frame};
/// use glam::Vec3;
/// let normal = Vec3::new(0.0, 0.6, -0.8);
/// let (t, b) = tangent_frame(normal);
/// assert!((t.cross(b) - normal).length() < 1e-6);
/// // Turns a direction about +Z into one about `normal`.
/// let local = cosine_hemisphere([0.5, 0.1]);
/// let world = t * local.x + b * local.y + normal * local.z;
/// assert!((world.dot(normal) - local.z).abs() < 1e-6);
/// ```
pub fn tangent_frame(n: Vec3) -> (Vec3, Vec3) {
    let sign = 1.0f32.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owen_scrambling_permutes_every_prefix_of_bits() {
        // A bijection on 32-bit words that keeps each top-k prefix a function of the input's
        // top-k prefix: check the second property on all 8-bit prefixes.
        for seed in [0u32, 1, 0xdead_beef] {
            let mut seen = [false; 256];
            for top in 0u32..256 {
                let a = owen_scramble(top << 24, seed) >> 24;
                let b = owen_scramble((top << 24) | 0x00ff_ffff, seed) >> 24;
                assert_eq!(a, b, "prefix depends on lower bits");
                assert!(!seen[a as usize], "prefix map is not a permutation");
                seen[a as usize] = true;
            }
        }
    }

    #[test]
    fn each_power_of_two_prefix_is_stratified_in_both_dimensions() {
        let sampler = PixelSampler::new(3, 12345);
        for log_n in [2u32, 4, 6, 8] {
            let n = 1u32 << log_n;
            // A (0, 2)-sequence puts one point in each of the n elementary intervals of every
            // shape; check the two extreme shapes, n columns and n rows.
            let mut columns = vec![0; n as usize];
            let mut rows = vec![0; n as usize];
            for i in 0..n {
                let [u, v] = sampler.square(i);
                columns[(u * n as f32) as usize] += 1;
                rows[(v * n as f32) as usize] += 1;
            }
            assert!(columns.iter().all(|&c| c == 1), "n = {n}: {columns:?}");
            assert!(rows.iter().all(|&c| c == 1), "n = {n}: {rows:?}");
        }
    }

    #[test]
    fn pixels_get_different_streams() {
        let a = PixelSampler::new(0, 1).square(0);
        let b = PixelSampler::new(0, 2).square(0);
        let c = PixelSampler::new(1, 1).square(0);
        assert_ne!(a, b);
        assert_ne!(a, c);
        assert_eq!(a, PixelSampler::new(0, 1).square(0));
    }

    #[test]
    fn cosine_hemisphere_has_the_cosine_mean() {
        // E[cos] under the cosine density is 2/3.
        let sampler = PixelSampler::new(0, 0);
        let n = 4096;
        let mean: f32 = (0..n)
            .map(|i| cosine_hemisphere(sampler.square(i)).z)
            .sum::<f32>()
            / n as f32;
        assert!((mean - 2.0 / 3.0).abs() < 1e-3, "{mean}");
    }

    #[test]
    fn tangent_frames_are_orthonormal() {
        for n in [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            Vec3::new(0.3, -0.9, 0.1).normalize(),
        ] {
            let (t, b) = tangent_frame(n);
            for (x, y) in [(t, b), (t, n), (b, n)] {
                assert!(x.dot(y).abs() < 1e-5);
            }
            assert!((t.cross(b) - n).length() < 1e-5, "{n}");
        }
    }
}
