//! Writes the pictures of docs/noise.md: per noise kind, a tile of its first value, that tile's
//! power spectrum, the radially averaged spectra of both values and the scatter of the pairs.
//!
//! ```sh
//! cargo run --release --example noise_spectra -p aokit [-- OUT_DIR]   # default docs/images/noise
//! ```

use std::path::{Path, PathBuf};

use aokit::noise::{self, pixel_noise};
use aokit::{NoiseKind, NoiseSettings};
use aokit_eval::spectrum::{power_spectrum, radial_average};

/// Side of the tiles analysed: the default blue-noise tile, and a multiple of every other
/// kind's period.
const SIZE: usize = 64;
/// Pictures are this many times the tile, so single texels stay visible.
const ZOOM: usize = 2;
/// Radial plot size in pixels.
const PLOT: [usize; 2] = [256, 128];
/// The plot's vertical range, in multiples of white noise's power (1/12 for uniform values):
/// enough to show blue noise's peak; the periodic kinds' spikes are clipped.
const PLOT_RANGE: f64 = 3.0;
/// Variance of values uniform in [0, 1): white noise's flat power.
const WHITE_POWER: f64 = 1.0 / 12.0;
/// Side of the pair scatter plot in pixels.
const SCATTER: usize = 128;
/// Cells per side of the grid over the unit square that counts where the pairs fall: 64 cells
/// for the 4096 pairs of a tile, which independent uniform pairs all reach.
const PAIR_GRID: usize = 8;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("docs/images/noise"), PathBuf::from);
    std::fs::create_dir_all(&out)?;
    let started = std::time::Instant::now();
    noise::blue_noise(128);
    println!(
        "128x128 blue noise: {:.2} s",
        started.elapsed().as_secs_f64()
    );

    for kind in NoiseKind::ALL {
        let settings = NoiseSettings {
            kind,
            ..NoiseSettings::default()
        };
        let values: Vec<[f32; 2]> = (0..SIZE * SIZE)
            .map(|i| pixel_noise(&settings, [(i % SIZE) as u32, (i / SIZE) as u32], 0))
            .collect();
        let channels: [Vec<f32>; 2] = [0, 1].map(|c| values.iter().map(|v| v[c]).collect());
        let spectra = channels.each_ref().map(|c| power_spectrum(c, SIZE));
        let rings = spectra.each_ref().map(|p| radial_average(p, SIZE));

        let name = kind.name();
        write_grey(&out.join(format!("{name}-tile.png")), &channels[0])?;
        write_grey(
            &out.join(format!("{name}-spectrum.png")),
            &centred_log(&spectra[0]),
        )?;
        write_plot(&out.join(format!("{name}-radial.png")), &rings)?;
        write_scatter(&out.join(format!("{name}-pairs.png")), &values)?;
        let low = |r: &[f64]| r[1..=4].iter().sum::<f64>() / 4.0 / WHITE_POWER;
        let mut cells = [false; PAIR_GRID * PAIR_GRID];
        for [a, b] in &values {
            let cell = |v: f32| (v * PAIR_GRID as f32) as usize;
            cells[cell(*a) * PAIR_GRID + cell(*b)] = true;
        }
        println!(
            "{name:>10}: power in rings 1-4 (of {}) relative to white noise {:.4} {:.4}; \
             pairs reach {} of {} cells",
            SIZE / 2,
            low(&rings[0]),
            low(&rings[1]),
            cells.iter().filter(|&&c| c).count(),
            cells.len()
        );
    }
    println!("wrote {}", out.display());
    Ok(())
}

/// Writes a `SIZE`x`SIZE` tile of values in [0, 1], magnified `ZOOM` times.
fn write_grey(path: &Path, values: &[f32]) -> Result<(), Box<dyn std::error::Error>> {
    let side = SIZE * ZOOM;
    let zoomed: Vec<f32> = (0..side * side)
        .map(|i| values[(i / side / ZOOM) * SIZE + (i % side) / ZOOM])
        .collect();
    aokit_eval::write_grey_png(path, [side as u32; 2], &zoomed)?;
    Ok(())
}

/// The power spectrum with the zero frequency in the middle, on a log scale from 1/100 to 10
/// times white noise's power.
fn centred_log(power: &[f64]) -> Vec<f32> {
    let half = SIZE / 2;
    (0..SIZE * SIZE)
        .map(|i| {
            let (u, v) = ((i % SIZE + half) % SIZE, (i / SIZE + half) % SIZE);
            let relative = power[v * SIZE + u] / WHITE_POWER;
            ((relative.max(1e-2).log10() + 2.0) / 3.0) as f32
        })
        .collect()
}

/// Plots each pixel's (first, second) pair as a dark dot, first value to the right, second up;
/// dots are 3 pixels wide when the pairs are few (the 4x4 tiles' 16), so that they show.
fn write_scatter(path: &Path, pairs: &[[f32; 2]]) -> Result<(), Box<dyn std::error::Error>> {
    let mut distinct: Vec<[u32; 2]> = pairs.iter().map(|p| p.map(f32::to_bits)).collect();
    distinct.sort_unstable();
    distinct.dedup();
    let reach = if distinct.len() < 256 { 1 } else { 0 };
    let mut grey = vec![1.0f32; SCATTER * SCATTER];
    for [a, b] in pairs {
        let x = (a * SCATTER as f32) as isize;
        let y = (SCATTER - 1) as isize - (b * SCATTER as f32) as isize;
        for dy in -reach..=reach {
            for dx in -reach..=reach {
                let (px, py) = (x + dx, y + dy);
                if (0..SCATTER as isize).contains(&px) && (0..SCATTER as isize).contains(&py) {
                    grey[py as usize * SCATTER + px as usize] = 0.0;
                }
            }
        }
    }
    aokit_eval::write_grey_png(path, [SCATTER as u32; 2], &grey)?;
    Ok(())
}

/// Plots the radially averaged spectra of both values against frequency (0 to 0.5 cycles per
/// pixel, left to right): the first value dark blue, the second orange, on a vertical axis from 0
/// to `PLOT_RANGE` times white noise's level, with grey lines at each multiple of that level.
fn write_plot(path: &Path, rings: &[Vec<f64>; 2]) -> Result<(), Box<dyn std::error::Error>> {
    let [w, h] = PLOT;
    let mut rgba = vec![255u8; w * h * 4];
    let mut dot = |x: f64, y: f64, colour: [u8; 3]| {
        let (x, y) = (x.round() as isize, y.round() as isize);
        for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (px, py) = (x + dx, y + dy);
            if (0..w as isize).contains(&px) && (0..h as isize).contains(&py) {
                let i = (py as usize * w + px as usize) * 4;
                rgba[i..i + 3].copy_from_slice(&colour);
            }
        }
    };
    let to_y = |power: f64| (h - 2) as f64 * (1.0 - (power / WHITE_POWER / PLOT_RANGE).min(1.0));
    for level in 1..PLOT_RANGE as usize {
        for x in (0..w).step_by(4) {
            dot(x as f64, to_y(level as f64 * WHITE_POWER), [200, 200, 200]);
        }
    }
    let last = (rings[0].len() - 1) as f64;
    for (ring, colour) in rings.iter().zip([[20, 40, 140], [230, 120, 20]]) {
        // Ring 0 is the mean, removed: the curves start at ring 1.
        for r in 1..ring.len() - 1 {
            let (x0, y0) = ((r as f64) / last * (w - 2) as f64, to_y(ring[r]));
            let (x1, y1) = ((r + 1) as f64 / last * (w - 2) as f64, to_y(ring[r + 1]));
            let steps = (x1 - x0).abs().max((y1 - y0).abs()).ceil().max(1.0) as usize;
            for s in 0..=steps {
                let t = s as f64 / steps as f64;
                dot(x0 + t * (x1 - x0), y0 + t * (y1 - y0), colour);
            }
        }
    }
    aokit_eval::write_rgba_png(path, [w as u32, h as u32], &rgba)?;
    Ok(())
}
