//! Scores, masks and error-map colours on synthetic images.

use aokit_eval::{Metrics, compare, depth_edge_mask, error_map_rgb, legend_rgb, surface_mask};

const SIZE: [u32; 2] = [24, 16];
const N: usize = 24 * 16;

fn gradient() -> Vec<f32> {
    (0..N).map(|i| 0.2 + 0.6 * (i % 24) as f32 / 23.0).collect()
}

/// Deterministic noise in [-1, 1].
fn noise(seed: u32) -> Vec<f32> {
    (0..N as u32)
        .map(|i| {
            let h = (i ^ seed)
                .wrapping_mul(0x9e37_79b9)
                .rotate_left(13)
                .wrapping_mul(0x85eb_ca6b);
            (h >> 8) as f32 / (1u32 << 23) as f32 - 1.0
        })
        .collect()
}

#[test]
fn identical_images_are_perfect() {
    let image = gradient();
    let m = compare(SIZE, &image, &image, &vec![true; N]);
    assert_eq!(m.pixels, N);
    assert_eq!((m.mae, m.rmse, m.bias), (0.0, 0.0, 0.0));
    assert_eq!(m.psnr, f64::INFINITY);
    assert!((m.ssim - 1.0).abs() < 1e-9, "{}", m.ssim);
}

#[test]
fn constant_offset_gives_that_error() {
    let reference = gradient();
    let c = 0.125f32;
    let brighter: Vec<f32> = reference.iter().map(|v| v + c).collect();
    let m = compare(SIZE, &brighter, &reference, &vec![true; N]);
    for (name, value) in [("mae", m.mae), ("rmse", m.rmse), ("bias", m.bias)] {
        // Within f32 rounding of the sums `reference + c`.
        assert!((value - 0.125).abs() < 1e-6, "{name} = {value}");
    }
    assert!((m.psnr - 10.0 * (1.0 / 0.125f64.powi(2)).log10()).abs() < 1e-4);
    let darker: Vec<f32> = reference.iter().map(|v| v - c).collect();
    let m = compare(SIZE, &darker, &reference, &vec![true; N]);
    assert!((m.bias + 0.125).abs() < 1e-6 && (m.mae - 0.125).abs() < 1e-6);
}

#[test]
fn masked_out_pixels_do_not_matter() {
    let reference = gradient();
    let mask: Vec<bool> = (0..N).map(|i| (i % 24) < 12).collect();
    let mut ao = reference.clone();
    for (v, &m) in ao.iter_mut().zip(&mask) {
        if !m {
            *v = 0.0; // wildly wrong, but never scored
        }
    }
    let m = compare(SIZE, &ao, &reference, &mask);
    assert_eq!(m.pixels, N / 2);
    assert_eq!(m.mae, 0.0);
    assert!((m.ssim - 1.0).abs() < 1e-9);
}

#[test]
fn noise_lowers_ssim() {
    let reference = gradient();
    let noisy: Vec<f32> = reference
        .iter()
        .zip(noise(7))
        .map(|(r, n)| r + 0.1 * n)
        .collect();
    let m = compare(SIZE, &noisy, &reference, &vec![true; N]);
    assert!(m.ssim < 0.9 && m.ssim > -1.0, "{}", m.ssim);
    assert!(m.mae > 0.0 && m.rmse >= m.mae);
    let noisier: Vec<f32> = reference
        .iter()
        .zip(noise(7))
        .map(|(r, n)| r + 0.3 * n)
        .collect();
    assert!(compare(SIZE, &noisier, &reference, &vec![true; N]).ssim < m.ssim);
}

#[test]
fn empty_selection_is_nan() {
    let image = gradient();
    let m = compare(SIZE, &image, &image, &vec![false; N]);
    assert_eq!(m.pixels, 0);
    assert!(
        m.mae.is_nan() && m.rmse.is_nan() && m.bias.is_nan() && m.psnr.is_nan() && m.ssim.is_nan()
    );
    // Mismatched lengths score nothing instead of panicking.
    assert_eq!(
        compare(SIZE, &image[1..], &image, &vec![true; N]).pixels,
        Metrics::EMPTY.pixels
    );
}

#[test]
fn edge_mask_follows_a_depth_step() {
    // Columns 0..8 at depth 1, 8..16 at depth 2, 16..24 background.
    let depth: Vec<f32> = (0..N)
        .map(|i| match i % 24 {
            0..8 => 1.0,
            8..16 => 2.0,
            _ => 0.0,
        })
        .collect();
    let column_set = |mask: &[bool]| -> Vec<usize> {
        (0..24)
            .filter(|&x| (0..16).all(|y| mask[y * 24 + x]))
            .collect()
    };
    let edges = depth_edge_mask(SIZE, &depth, 0.05, 0);
    assert_eq!(column_set(&edges), [7, 8, 15]);
    assert_eq!(edges.iter().filter(|&&e| e).count(), 3 * 16);
    let dilated = depth_edge_mask(SIZE, &depth, 0.05, 2);
    assert_eq!(column_set(&dilated), [5, 6, 7, 8, 9, 10, 13, 14, 15]);
    // Never outside surfaces.
    let surface = surface_mask(&depth);
    assert!(dilated.iter().zip(&surface).all(|(&e, &s)| !e || s));
    // A step below the threshold is no edge.
    let gentle: Vec<f32> = (0..N)
        .map(|i| if i % 24 < 12 { 1.0 } else { 1.04 })
        .collect();
    assert!(depth_edge_mask(SIZE, &gentle, 0.05, 1).iter().all(|&e| !e));
}

#[test]
fn error_map_colours() {
    let reference = [0.5; 5];
    let ao = [0.5, 0.75, 0.25, 0.9, 0.5];
    let mask = [true, true, true, true, false];
    let rgb = error_map_rgb(&ao, &reference, &mask, 0.25);
    let px = |i: usize| [rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]];
    assert_eq!(rgb.len(), 15);
    assert_eq!(px(0), [255, 255, 255], "zero error is white");
    let red = px(1);
    assert!(
        red[0] > 150 && red[1] < 60 && red[2] < 60,
        "too bright is red: {red:?}"
    );
    let blue = px(2);
    assert!(
        blue[2] > 150 && blue[0] < 60 && blue[1] < 120,
        "too dark is blue: {blue:?}"
    );
    assert_eq!(px(3), red, "saturates beyond the range");
    assert_eq!(px(4), [128, 128, 128], "masked is grey");
    // Half the range is halfway to red.
    let half = error_map_rgb(&[0.625], &[0.5], &[true], 0.25);
    assert!(
        half[0] > red[0] && half[1] > 100 && half[1] < 200,
        "{half:?}"
    );

    let legend = legend_rgb(64, 4);
    assert_eq!(legend.len(), 64 * 4 * 3);
    assert_eq!(&legend[0..3], &blue[..], "left end is -range");
    assert_eq!(&legend[63 * 3..64 * 3], &red[..], "right end is +range");
    assert!(legend_rgb(0, 5).is_empty());
}
