//! Renders report.html in headless Chromium and checks the screenshot shows the page: images,
//! error colours and the reference gradient, not a blank or broken page.
//!
//! Skipped (with a notice) when no Chromium is installed, unless `AOKIT_REQUIRE_CHROMIUM` is set.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use aokit_eval::report::{MethodResult, Report, ViewResult};
use aokit_eval::{
    Metrics, compare, depth_edge_mask, encode_png_grey, encode_png_rgb, error_map_rgb, legend_rgb,
    surface_mask,
};

const W: u32 = 96;
const H: u32 = 64;
const RANGE: f32 = 0.25;
/// A cold Chromium start on a small CI machine takes seconds; a hang should still fail the test.
const TIMEOUT: Duration = Duration::from_secs(60);

fn find_chromium() -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .flat_map(|name| std::env::split_paths(&path).map(move |dir| dir.join(name)))
        .find(|candidate| candidate.is_file())
}

/// Deterministic noise in [-1, 1].
fn noise(i: usize, seed: u32) -> f32 {
    let h = (i as u32 ^ seed)
        .wrapping_mul(0x9e37_79b9)
        .rotate_left(15)
        .wrapping_mul(0x85eb_ca6b);
    (h >> 8) as f32 / (1u32 << 23) as f32 - 1.0
}

/// A left-to-right gradient reference with a background corner, and two methods (one too
/// bright, one too dark) at two noise levels.
fn synthetic_report() -> Report {
    let n = (W * H) as usize;
    let size = [W, H];
    let depth: Vec<f32> = (0..n)
        .map(|i| {
            let (x, y) = (i as u32 % W, i as u32 / W);
            if x >= 80 && y < 16 {
                0.0
            } else if x < 40 {
                2.0
            } else {
                3.0
            }
        })
        .collect();
    let reference: Vec<f32> = (0..n)
        .map(|i| 0.1 + 0.85 * (i as u32 % W) as f32 / (W - 1) as f32)
        .collect();
    let surface = surface_mask(&depth);
    let edges = depth_edge_mask(size, &depth, 0.05, 2);
    let mut methods = Vec::new();
    for (m, (method, bias)) in [("gtao", 0.12f32), ("hbao", -0.12)].into_iter().enumerate() {
        for (p, (preset, amplitude, spp)) in [("low", 0.08f32, 8u32), ("high", 0.03, 32)]
            .into_iter()
            .enumerate()
        {
            let ao: Vec<f32> = (0..n)
                .map(|i| {
                    (reference[i] + bias + amplitude * noise(i, (m * 2 + p) as u32)).clamp(0.0, 1.0)
                })
                .collect();
            methods.push(MethodResult {
                method: method.to_string(),
                preset: preset.to_string(),
                all: compare(size, &ao, &reference, &surface),
                edges: compare(size, &ao, &reference, &edges),
                grazing: Metrics::EMPTY,
                sequence: None,
                gpu_ms: None,
                samples_per_pixel: spp,
                ao_png: encode_png_grey(size, &ao).unwrap(),
                error_png: encode_png_rgb(size, &error_map_rgb(&ao, &reference, &surface, RANGE))
                    .unwrap(),
            });
        }
    }
    Report {
        title: "Screenshot test report".to_string(),
        notes: vec!["Synthetic images: gradient reference, biased noisy methods.".to_string()],
        error_range: RANGE,
        legend_png: encode_png_rgb([256, 12], &legend_rgb(256, 12)).unwrap(),
        views: vec![ViewResult {
            name: "synthetic / gradient".to_string(),
            reference_png: encode_png_grey(size, &reference).unwrap(),
            methods,
        }],
    }
}

/// Runs Chromium to completion or kills it at the timeout; returns its stderr on failure.
fn screenshot(
    chromium: &Path,
    html: &Path,
    shot: &Path,
    profile: &Path,
    log: &Path,
) -> Result<(), String> {
    let log_file = std::fs::File::create(log).map_err(|e| e.to_string())?;
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--disable-dev-shm-usage",
            "--hide-scrollbars",
            "--window-size=1200,1600",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", html.display()))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(log_file)
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", chromium.display()))?;
    let start = Instant::now();
    let status = loop {
        match child.try_wait().map_err(|e| e.to_string())? {
            Some(status) => break status,
            None if start.elapsed() > TIMEOUT => {
                // Kill only the process this test started.
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "{} did not finish within {TIMEOUT:?}",
                    chromium.display()
                ));
            }
            None => std::thread::sleep(Duration::from_millis(100)),
        }
    };
    let stderr = std::fs::read_to_string(log).unwrap_or_default();
    if !status.success() || !shot.is_file() {
        return Err(format!(
            "{} exited with {status}, screenshot written: {}\n{stderr}",
            chromium.display(),
            shot.is_file()
        ));
    }
    Ok(())
}

/// Whether some row holds a long, smooth, left-to-right brightening run of grey: the reference
/// gradient scaled up, and nothing else on the page (text is short, AO images are noisy).
fn has_grey_gradient(image: &image::RgbImage) -> bool {
    let grey = |p: &image::Rgb<u8>| {
        let [r, g, b] = p.0;
        (r.max(g).max(b) - r.min(g).min(b) <= 2).then_some(i32::from(g))
    };
    (0..image.height()).any(|y| {
        let (mut run, mut first, mut previous) = (0u32, 0, -1);
        for x in 0..image.width() {
            match grey(image.get_pixel(x, y)) {
                Some(v)
                    if v >= previous
                        && (v - previous <= 8 || run == 0)
                        && (20..250).contains(&v) =>
                {
                    if run == 0 {
                        first = v;
                    }
                    run += 1;
                    previous = v;
                    if run >= 200 && previous - first >= 120 {
                        return true;
                    }
                }
                _ => {
                    run = 0;
                    previous = -1;
                }
            }
        }
        false
    })
}

#[test]
fn report_renders_in_chromium() {
    let Some(chromium) = find_chromium() else {
        if std::env::var_os("AOKIT_REQUIRE_CHROMIUM").is_some() {
            panic!(
                "AOKIT_REQUIRE_CHROMIUM is set but no chromium, chromium-browser or google-chrome is on PATH; apt-get install chromium"
            );
        }
        eprintln!(
            "notice: skipping the report screenshot test: no chromium on PATH (apt-get install chromium)"
        );
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let html = dir.path().join("report.html");
    std::fs::write(&html, synthetic_report().html()).unwrap();
    let shot = dir.path().join("shot.png");
    let profile = dir.path().join("profile");
    std::fs::create_dir(&profile).unwrap();
    if let Err(e) = screenshot(
        &chromium,
        &html,
        &shot,
        &profile,
        &dir.path().join("chromium.log"),
    ) {
        panic!("{e}");
    }

    let image = image::open(&shot).unwrap().to_rgb8();
    assert!(
        image.width() >= 1000 && image.height() >= 1000,
        "{}x{}",
        image.width(),
        image.height()
    );
    let pixels: Vec<[u8; 3]> = image.pixels().map(|p| p.0).collect();
    let distinct: HashSet<[u8; 3]> = pixels.iter().copied().collect();
    assert!(
        distinct.len() > 200,
        "only {} colours: a blank page?",
        distinct.len()
    );
    let red = pixels
        .iter()
        .filter(|[r, g, b]| *r > 150 && *g < 100 && *b < 100)
        .count();
    let blue = pixels
        .iter()
        .filter(|[r, g, b]| *b > 150 && *r < 100 && *g < 130)
        .count();
    assert!(red > 2000, "{red} red error-map pixels");
    assert!(blue > 2000, "{blue} blue error-map pixels");
    let mid_grey = pixels
        .iter()
        .filter(|p| p.iter().all(|&c| (126..=130).contains(&c)))
        .count();
    assert!(
        mid_grey > 200,
        "{mid_grey} grey (unscored) error-map pixels"
    );
    assert!(
        has_grey_gradient(&image),
        "the grey reference gradient is not on the page"
    );
}
