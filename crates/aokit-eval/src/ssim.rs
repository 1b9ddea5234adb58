//! Masked structural similarity.
//!
//! SSIM after Z. Wang, A. C. Bovik, H. R. Sheikh and E. P. Simoncelli, "Image quality
//! assessment: from error visibility to structural similarity", IEEE Transactions on Image
//! Processing 13(4), 600-612, 2004: K1 = 0.01, K2 = 0.03, dynamic range L = 1, an 11x11 Gaussian
//! window with sigma 1.5. Background pixels would otherwise drag in a flat, perfectly matching
//! region, so every window statistic is weighted by the mask: only masked pixels contribute to
//! the local means, variances and covariance, and the map is averaged over masked pixels.

/// Window radius: the paper's 11x11 window.
const RADIUS: usize = 5;
/// The paper's Gaussian window width.
const SIGMA: f64 = 1.5;
/// Stabilisers (K1 L)^2 and (K2 L)^2 with L = 1, the AO range.
const C1: f64 = 0.01 * 0.01;
const C2: f64 = 0.03 * 0.03;

/// Per-pixel sums the window needs: weight, x, y, x^2, y^2, xy (each times the mask).
const MOMENTS: usize = 6;

fn kernel() -> [f64; 2 * RADIUS + 1] {
    std::array::from_fn(|i| {
        let d = i as f64 - RADIUS as f64;
        (-d * d / (2.0 * SIGMA * SIGMA)).exp()
    })
}

/// Horizontally filtered moments of one row: `MOMENTS` planes of `w` values.
fn filter_row(w: usize, x: &[f32], y: &[f32], mask: &[bool], g: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for (i, ((&xi, &yi), &m)) in x.iter().zip(y).zip(mask).enumerate() {
        if !m {
            continue;
        }
        let (a, b) = (f64::from(xi), f64::from(yi));
        let moments = [1.0, a, b, a * a, b * b, a * b];
        // Scatter this pixel into the columns whose windows contain it.
        let lo = i.saturating_sub(RADIUS);
        let hi = (i + RADIUS).min(w - 1);
        for c in lo..=hi {
            let weight = g[c + RADIUS - i];
            for (k, &value) in moments.iter().enumerate() {
                out[k * w + c] += weight * value;
            }
        }
    }
}

/// Mean SSIM over the pixels where `mask` is set; NaN when none is. Slices must hold
/// `size[0] * size[1]` values (the caller checks).
pub(crate) fn masked_ssim(size: [u32; 2], x: &[f32], y: &[f32], mask: &[bool]) -> f64 {
    let (w, h) = (size[0] as usize, size[1] as usize);
    let g = kernel();
    // A ring of horizontally filtered rows keeps memory at 11 rows instead of 6 full images.
    let ring_len = 2 * RADIUS + 1;
    let mut ring = vec![0.0; ring_len * MOMENTS * w];
    let row_len = MOMENTS * w;
    let mut filtered = 0; // rows filtered so far
    let (mut sum, mut count) = (0.0, 0usize);
    let mut acc = vec![0.0; MOMENTS];
    for row in 0..h {
        let last = (row + RADIUS).min(h - 1);
        while filtered <= last {
            let slot = filtered % ring_len;
            let span = filtered * w..(filtered + 1) * w;
            filter_row(
                w,
                &x[span.clone()],
                &y[span.clone()],
                &mask[span],
                &g,
                &mut ring[slot * row_len..(slot + 1) * row_len],
            );
            filtered += 1;
        }
        let first = row.saturating_sub(RADIUS);
        for col in 0..w {
            if !mask[row * w + col] {
                continue;
            }
            acc.fill(0.0);
            for r in first..=last {
                let weight = g[r + RADIUS - row];
                let base = (r % ring_len) * row_len + col;
                for (k, a) in acc.iter_mut().enumerate() {
                    *a += weight * ring[base + k * w];
                }
            }
            sum += ssim_of(&acc);
            count += 1;
        }
    }
    if count == 0 {
        f64::NAN
    } else {
        sum / count as f64
    }
}

/// SSIM of one window from its weighted sums. The pixel itself is masked, so the weight is
/// positive.
fn ssim_of(s: &[f64]) -> f64 {
    let n = s[0];
    let (mx, my) = (s[1] / n, s[2] / n);
    let vx = s[3] / n - mx * mx;
    let vy = s[4] / n - my * my;
    let cxy = s[5] / n - mx * my;
    ((2.0 * mx * my + C1) * (2.0 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same statistics straight from the definition, for comparison.
    fn brute(size: [u32; 2], x: &[f32], y: &[f32], mask: &[bool]) -> f64 {
        let (w, h) = (size[0] as isize, size[1] as isize);
        let g = kernel();
        let (mut sum, mut count) = (0.0, 0);
        for py in 0..h {
            for px in 0..w {
                if !mask[(py * w + px) as usize] {
                    continue;
                }
                let mut s = [0.0; MOMENTS];
                for dy in -5..=5isize {
                    for dx in -5..=5isize {
                        let (qx, qy) = (px + dx, py + dy);
                        if qx < 0 || qy < 0 || qx >= w || qy >= h || !mask[(qy * w + qx) as usize] {
                            continue;
                        }
                        let i = (qy * w + qx) as usize;
                        let wt = g[(dx + 5) as usize] * g[(dy + 5) as usize];
                        let (a, b) = (f64::from(x[i]), f64::from(y[i]));
                        for (k, v) in [1.0, a, b, a * a, b * b, a * b].into_iter().enumerate() {
                            s[k] += wt * v;
                        }
                    }
                }
                sum += ssim_of(&s);
                count += 1;
            }
        }
        sum / count as f64
    }

    #[test]
    fn matches_direct_evaluation() {
        let size = [17, 14];
        let n = 17 * 14;
        let x: Vec<f32> = (0..n).map(|i| ((i * 37 % 101) as f32) / 100.0).collect();
        let y: Vec<f32> = (0..n).map(|i| ((i * 53 % 89) as f32) / 88.0).collect();
        let mask: Vec<bool> = (0..n).map(|i| i % 7 != 3).collect();
        let fast = masked_ssim(size, &x, &y, &mask);
        let slow = brute(size, &x, &y, &mask);
        assert!((fast - slow).abs() < 1e-9, "{fast} vs {slow}");
    }

    #[test]
    fn identical_images_score_one() {
        let x: Vec<f32> = (0..100)
            .map(|i| (i as f32 * 0.37).sin() * 0.5 + 0.5)
            .collect();
        let mask = vec![true; 100];
        assert!((masked_ssim([10, 10], &x, &x, &mask) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn empty_mask_is_nan() {
        assert!(masked_ssim([2, 2], &[0.0; 4], &[0.0; 4], &[false; 4]).is_nan());
    }
}
