//! Power spectra of square tiles, for judging noise patterns (blue noise keeps its power at high
//! frequencies): [`power_spectrum`] and its rings, [`radial_average`]. `aokit`'s noise tests and
//! its `noise_spectra` example use them.

/// The power spectrum of a square tile of `size * size` values, row major: `|DFT|^2 / size^2`
/// of the values less their mean, with frequency `(u, v)` at index `v * size + u`. So scaled,
/// white noise of variance s^2 has expected power s^2 at every frequency. A plain separable DFT:
/// meant for tiles of up to a few hundred texels.
///
/// ```
/// use aokit_eval::spectrum::power_spectrum;
/// let size = 16;
/// // Uniform values in [0, 1) from a 32-bit LCG's top bits.
/// let mut state = 3u32;
/// let white: Vec<f32> = (0..size * size)
///     .map(|_| {
///         state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
///         (state >> 8) as f32 / (1u32 << 24) as f32
///     })
///     .collect();
/// let power = power_spectrum(&white, size);
/// // The mean is taken out, so frequency (0, 0) holds nothing.
/// assert!(power[0] < 1e-9);
/// // Parseval: the powers add up to the tile's variance times its texel count (1/12 each).
/// let total: f64 = power.iter().sum();
/// assert!((total / (size * size) as f64 - 1.0 / 12.0).abs() < 0.02);
/// ```
pub fn power_spectrum(values: &[f32], size: usize) -> Vec<f64> {
    assert_eq!(values.len(), size * size, "a {size}x{size} tile");
    let mean = values.iter().map(|&v| f64::from(v)).sum::<f64>() / values.len() as f64;
    let turn = -std::f64::consts::TAU / size as f64;
    let twiddle: Vec<(f64, f64)> = (0..size)
        .map(|k| ((turn * k as f64).cos(), (turn * k as f64).sin()))
        .collect();
    // One-dimensional DFT of `n` complex values spaced `stride` apart from `start`.
    let dft = |data: &[(f64, f64)], start: usize, stride: usize| -> Vec<(f64, f64)> {
        (0..size)
            .map(|k| {
                (0..size).fold((0.0, 0.0), |(re, im), x| {
                    let (c, s) = twiddle[(k * x) % size];
                    let (a, b) = data[start + x * stride];
                    (re + a * c - b * s, im + a * s + b * c)
                })
            })
            .collect()
    };
    let centred: Vec<(f64, f64)> = values.iter().map(|&v| (f64::from(v) - mean, 0.0)).collect();
    let mut rows = vec![(0.0, 0.0); size * size];
    for y in 0..size {
        rows[y * size..(y + 1) * size].copy_from_slice(&dft(&centred, y * size, 1));
    }
    let mut power = vec![0.0; size * size];
    for u in 0..size {
        for (v, (re, im)) in dft(&rows, u, size).into_iter().enumerate() {
            power[v * size + u] = (re * re + im * im) / (size * size) as f64;
        }
    }
    power
}

/// The mean of a [`power_spectrum`] over rings of frequency radius `0, 1, ..., size / 2`
/// (cycles per tile, the radius rounded, frequencies above `size / 2` taken as negative).
/// Index `r` is the ring of radius `r`; ring 0 holds the (zero) mean.
///
/// ```
/// use aokit_eval::spectrum::{power_spectrum, radial_average};
/// let size = 16;
/// // Stripes two texels on, two off: 4 cycles a tile along x, so all the power is on ring 4.
/// let stripes: Vec<f32> = (0..size * size).map(|i| (i % size / 2 % 2) as f32).collect();
/// let rings = radial_average(&power_spectrum(&stripes, size), size);
/// assert_eq!(rings.len(), size / 2 + 1);
/// for (r, &p) in rings.iter().enumerate() {
///     assert_eq!(p > 1e-9, r == 4, "ring {r}: {p}");
/// }
/// ```
pub fn radial_average(power: &[f64], size: usize) -> Vec<f64> {
    let rings = size / 2 + 1;
    let mut sum = vec![0.0; rings];
    let mut count = vec![0usize; rings];
    let signed = |f: usize| {
        if f > size / 2 {
            f as f64 - size as f64
        } else {
            f as f64
        }
    };
    for v in 0..size {
        for u in 0..size {
            let r = signed(u).hypot(signed(v)).round() as usize;
            if r < rings {
                sum[r] += power[v * size + u];
                count[r] += 1;
            }
        }
    }
    sum.iter().zip(&count).map(|(s, &c)| s / c as f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spectrum_of_a_sinusoid_is_one_ring() {
        let size = 32;
        let values: Vec<f32> = (0..size * size)
            .map(|i| (std::f64::consts::TAU * 3.0 * (i % size) as f64 / size as f64).cos() as f32)
            .collect();
        let rings = radial_average(&power_spectrum(&values, size), size);
        for (r, &p) in rings.iter().enumerate() {
            if r == 3 {
                assert!(p > 1.0, "{p}");
            } else {
                assert!(p < 1e-9, "ring {r}: {p}");
            }
        }
    }
}
