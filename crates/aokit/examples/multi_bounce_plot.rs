//! Writes docs/composite.md's plot of the two multi-bounce curves, GTAO's fit and the closed
//! form, as the effective visibility `k'` against the AO `k` for a few albedos, and prints the
//! largest difference between them.
//!
//! ```sh
//! cargo run -p aokit --example multi_bounce_plot [-- OUT.svg]   # default docs/images/multi-bounce.svg
//! ```

use std::fmt::Write as _;
use std::path::PathBuf;

use aokit::occlusion::{multi_bounce_closed_form, multi_bounce_gtao};
use glam::Vec3;

/// Albedos plotted, with their stroke colours: dark, middling and bright materials.
const CURVES: [(f32, &str); 3] = [(0.2, "#1f77b4"), (0.5, "#2ca02c"), (0.8, "#d62728")];
/// Plot area in SVG units, and the margin around it that holds the labels.
const SIDE: f32 = 400.0;
const MARGIN: f32 = 50.0;
/// Points per curve: 0.005 apart in `k`, smooth at this size.
const STEPS: usize = 200;

/// SVG coordinates of the point (k, k') of the unit square.
fn to_svg(k: f32, value: f32) -> (f32, f32) {
    (MARGIN + k * SIDE, MARGIN + (1.0 - value) * SIDE)
}

/// An SVG polyline through `f(k)` for k from 0 to 1.
fn polyline(f: impl Fn(f32) -> f32, color: &str, dashed: bool) -> String {
    let points: Vec<String> = (0..=STEPS)
        .map(|i| {
            let k = i as f32 / STEPS as f32;
            let (x, y) = to_svg(k, f(k));
            format!("{x:.1},{y:.1}")
        })
        .collect();
    let dash = if dashed {
        r#" stroke-dasharray="6 4""#
    } else {
        ""
    };
    format!(
        r#"<polyline fill="none" stroke="{color}" stroke-width="2"{dash} points="{}"/>"#,
        points.join(" ")
    )
}

/// Largest `closed form - fit` over a 0.01 grid of `k` and of albedos up to `max_albedo`:
/// (difference, k, albedo).
fn largest_difference(max_albedo: f32) -> (f32, f32, f32) {
    let mut worst = (0.0f32, 0.0, 0.0);
    for i in 0..=100 {
        for j in 0..=(max_albedo * 100.0).round() as u32 {
            let (k, albedo) = (i as f32 / 100.0, j as f32 / 100.0);
            let a = Vec3::splat(albedo);
            let d = multi_bounce_closed_form(k, a).x - multi_bounce_gtao(k, a).x;
            if d.abs() > worst.0.abs() {
                worst = (d, k, albedo);
            }
        }
    }
    worst
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).map_or_else(
        || PathBuf::from("docs/images/multi-bounce.svg"),
        PathBuf::from,
    );
    let size = SIDE + 2.0 * MARGIN;
    let mut svg = String::new();
    writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}" font-family="sans-serif" font-size="12">"#
    )?;
    writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#)?;
    // Grid every 0.1, labelled every 0.2.
    for i in 0..=10 {
        let t = i as f32 / 10.0;
        let (x, _) = to_svg(t, 0.0);
        let (_, y) = to_svg(0.0, t);
        let (x0, y0) = to_svg(0.0, 0.0);
        let (x1, y1) = to_svg(1.0, 1.0);
        writeln!(
            svg,
            r##"<line x1="{x}" y1="{y1}" x2="{x}" y2="{y0}" stroke="#ddd"/><line x1="{x0}" y1="{y}" x2="{x1}" y2="{y}" stroke="#ddd"/>"##
        )?;
        if i % 2 == 0 {
            writeln!(
                svg,
                r#"<text x="{x}" y="{}" text-anchor="middle">{t:.1}</text><text x="{}" y="{}" text-anchor="end">{t:.1}</text>"#,
                y0 + 16.0,
                x0 - 6.0,
                y + 4.0
            )?;
        }
    }
    let (x0, y0) = to_svg(0.0, 0.0);
    writeln!(
        svg,
        r##"<rect x="{x0}" y="{MARGIN}" width="{SIDE}" height="{SIDE}" fill="none" stroke="#444"/>"##
    )?;
    writeln!(
        svg,
        r#"<text x="{}" y="{}" text-anchor="middle">AO k</text>"#,
        x0 + SIDE / 2.0,
        y0 + 36.0
    )?;
    writeln!(
        svg,
        r#"<text transform="translate({} {}) rotate(-90)" text-anchor="middle">effective visibility k'</text>"#,
        x0 - 34.0,
        MARGIN + SIDE / 2.0
    )?;
    writeln!(
        svg,
        r#"<text x="{}" y="{}" text-anchor="middle">Multi-bounce AO: GTAO fit (solid) and closed form (dashed)</text>"#,
        x0 + SIDE / 2.0,
        MARGIN - 20.0
    )?;
    // k' = k, the raw AO, which both give for black surroundings.
    writeln!(
        svg,
        "{}",
        polyline(|k| k, "#888", true).replace(r#"stroke-width="2""#, r#"stroke-width="1""#)
    )?;
    for (i, (albedo, color)) in CURVES.into_iter().enumerate() {
        let a = Vec3::splat(albedo);
        writeln!(
            svg,
            "{}",
            polyline(|k| multi_bounce_gtao(k, a).x, color, false)
        )?;
        writeln!(
            svg,
            "{}",
            polyline(|k| multi_bounce_closed_form(k, a).x, color, true)
        )?;
        // Legend in the lower right, where every curve is far above.
        let (lx, ly) = (x0 + SIDE - 150.0, y0 - 90.0 + 20.0 * i as f32);
        writeln!(
            svg,
            r#"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="{color}" stroke-width="2"/><text x="{}" y="{}">albedo {albedo}</text>"#,
            lx + 30.0,
            lx + 38.0,
            ly + 4.0
        )?;
    }
    let (lx, ly) = (x0 + SIDE - 150.0, y0 - 30.0);
    writeln!(
        svg,
        r##"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="#888" stroke-dasharray="6 4"/><text x="{}" y="{}">k' = k (no bounce)</text>"##,
        lx + 30.0,
        lx + 38.0,
        ly + 4.0
    )?;
    writeln!(svg, "</svg>")?;
    std::fs::write(&out, svg)?;
    println!("wrote {}", out.display());
    for max_albedo in [0.5, 0.8, 1.0] {
        let (d, k, albedo) = largest_difference(max_albedo);
        println!(
            "albedo <= {max_albedo}: largest closed form - fit {d:+.4} at k {k:.2}, albedo {albedo:.2}"
        );
    }
    Ok(())
}
