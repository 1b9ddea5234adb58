//! The error-versus-cost scatter chart as inline SVG.

use super::MethodResult;
use super::text::html;

const WIDTH: f64 = 640.0;
const HEIGHT: f64 = 360.0;
/// Room for tick labels on the left and the axis title below.
const LEFT: f64 = 72.0;
const RIGHT: f64 = 24.0;
const TOP: f64 = 16.0;
const BOTTOM: f64 = 52.0;
/// One colour per method, in order of first appearance; distinct from the error map's red/blue.
const PALETTE: [&str; 6] = [
    "#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#a6761d",
];

/// An axis from 0 to a round number at or above `max`, with its tick step: steps of 1, 2 or 5
/// times a power of ten, about five ticks.
fn axis(max: f64) -> (f64, f64) {
    if !(max.is_finite() && max > 0.0) {
        return (1.0, 0.2);
    }
    let raw = max / 5.0;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = match raw / magnitude {
        r if r <= 1.0 => 1.0,
        r if r <= 2.0 => 2.0,
        r if r <= 5.0 => 5.0,
        _ => 10.0,
    } * magnitude;
    ((max / step).ceil() * step, step)
}

/// A tick label with as many decimals as the step needs.
fn tick_label(value: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).clamp(0.0, 6.0) as usize;
    format!("{value:.decimals$}")
}

/// Where a point's label goes: right of the point unless that leaves the chart, and moved down
/// past labels already placed so that close points (presets of similar cost) stay readable.
/// `placed` holds the horizontal extent and baseline of earlier labels.
fn place_label(
    placed: &mut Vec<(f64, f64, f64)>,
    sx: f64,
    sy: f64,
    chars: usize,
) -> (f64, f64, &'static str) {
    // About the advance of an 11px sans-serif character.
    let width = chars as f64 * 6.2;
    let (x, anchor, x0, x1) = if sx + 6.0 + width > WIDTH {
        (sx - 6.0, "end", sx - 6.0 - width, sx - 6.0)
    } else {
        (sx + 6.0, "start", sx + 6.0, sx + 6.0 + width)
    };
    let mut y = sy - 6.0;
    while placed
        .iter()
        .any(|&(a0, a1, b)| a0 < x1 && x0 < a1 && (b - y).abs() < 12.0)
    {
        y += 12.0;
    }
    placed.push((x0, x1, y));
    (x, y, anchor)
}

/// RMSE over all pixels (y) against GPU milliseconds when every result was timed, otherwise
/// against samples per pixel (x); each point labelled `method/preset`.
pub(super) fn scatter_svg(methods: &[MethodResult]) -> String {
    let timed = !methods.is_empty() && methods.iter().all(|m| m.gpu_ms.is_some());
    let (x_title, cost): (&str, fn(&MethodResult) -> f64) = if timed {
        ("GPU time per frame (ms)", |m| m.gpu_ms.unwrap_or(f64::NAN))
    } else {
        ("Samples per pixel", |m| f64::from(m.samples_per_pixel))
    };
    let mut names: Vec<&str> = Vec::new();
    let points: Vec<(f64, f64, &MethodResult)> = methods
        .iter()
        .map(|m| (cost(m), m.all.rmse, m))
        .filter(|(x, y, _)| x.is_finite() && y.is_finite() && *x >= 0.0 && *y >= 0.0)
        .collect();
    let (x_max, x_step) = axis(points.iter().map(|p| p.0).fold(0.0, f64::max));
    let (y_max, y_step) = axis(points.iter().map(|p| p.1).fold(0.0, f64::max));
    let (plot_w, plot_h) = (WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM);
    let px = |x: f64| LEFT + x / x_max * plot_w;
    let py = |y: f64| TOP + plot_h - y / y_max * plot_h;

    let mut svg = format!(
        "<svg class=\"chart\" viewBox=\"0 0 {WIDTH} {HEIGHT}\" width=\"{WIDTH}\" height=\"{HEIGHT}\" role=\"img\" \
         aria-label=\"RMSE versus {}\" font-family=\"system-ui, sans-serif\" font-size=\"11\">\n",
        html(&x_title.to_lowercase())
    );
    svg.push_str(&format!(
        "<rect x=\"{LEFT}\" y=\"{TOP}\" width=\"{plot_w}\" height=\"{plot_h}\" fill=\"#fafafa\" stroke=\"#999\"/>\n"
    ));
    let ticks =
        |max: f64, step: f64| (0..=(max / step).round() as usize).map(move |i| i as f64 * step);
    for x in ticks(x_max, x_step) {
        let sx = px(x);
        svg.push_str(&format!(
            "<line x1=\"{sx:.1}\" y1=\"{TOP}\" x2=\"{sx:.1}\" y2=\"{:.1}\" stroke=\"#e2e2e2\"/>\
             <text x=\"{sx:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\n",
            TOP + plot_h,
            TOP + plot_h + 16.0,
            tick_label(x, x_step)
        ));
    }
    for y in ticks(y_max, y_step) {
        let sy = py(y);
        svg.push_str(&format!(
            "<line x1=\"{LEFT}\" y1=\"{sy:.1}\" x2=\"{:.1}\" y2=\"{sy:.1}\" stroke=\"#e2e2e2\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>\n",
            LEFT + plot_w,
            LEFT - 6.0,
            sy + 4.0,
            tick_label(y, y_step)
        ));
    }
    svg.push_str(&format!(
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"12\">{}</text>\n\
         <text transform=\"translate(16 {:.1}) rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">RMSE (all surface pixels)</text>\n",
        LEFT + plot_w / 2.0,
        HEIGHT - 12.0,
        html(x_title),
        TOP + plot_h / 2.0
    ));
    let mut placed = Vec::new();
    for (x, y, m) in &points {
        let index = names
            .iter()
            .position(|n| *n == m.method)
            .unwrap_or_else(|| {
                names.push(&m.method);
                names.len() - 1
            });
        let text = format!("{}/{}", m.method, m.preset);
        let label = html(&text);
        let (sx, sy) = (px(*x), py(*y));
        let (lx, ly, anchor) = place_label(&mut placed, sx, sy, text.chars().count());
        svg.push_str(&format!(
            "<circle cx=\"{sx:.1}\" cy=\"{sy:.1}\" r=\"4\" fill=\"{}\"><title>{label}: RMSE {:.4}</title></circle>\
             <text x=\"{lx:.1}\" y=\"{ly:.1}\" text-anchor=\"{anchor}\">{label}</text>\n",
            PALETTE[index % PALETTE.len()],
            y,
        ));
    }
    if points.is_empty() {
        svg.push_str(&format!(
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">no finite results to plot</text>\n",
            LEFT + plot_w / 2.0,
            TOP + plot_h / 2.0
        ));
    }
    svg.push_str("</svg>\n");
    svg
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_are_round() {
        assert_eq!(axis(0.0), (1.0, 0.2));
        assert_eq!(axis(f64::NAN), (1.0, 0.2));
        let (max, step) = axis(0.037);
        assert!(
            (step - 0.01).abs() < 1e-12 && (max - 0.04).abs() < 1e-12,
            "{max} {step}"
        );
        let (max, step) = axis(64.0);
        assert!(
            (step - 20.0).abs() < 1e-9 && (max - 80.0).abs() < 1e-9,
            "{max} {step}"
        );
        assert_eq!(tick_label(0.04, 0.01), "0.04");
        assert_eq!(tick_label(80.0, 20.0), "80");
    }
}
