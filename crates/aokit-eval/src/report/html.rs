//! `Report::html`: one offline page.

use super::chart::scatter_svg;
use super::text::{columns, fixed, has_sequence, html, row_cells, signed};
use super::{MethodResult, Report, ViewResult};
use crate::base64;

/// Layout only; images scale to their boxes with visible pixels so small renders stay readable.
const STYLE: &str = "
body { font: 15px/1.4 system-ui, sans-serif; color: #222; background: #fff; margin: 0 auto; max-width: 1200px; padding: 12px 16px; }
h1 { font-size: 1.5em; margin: 0.3em 0; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 1.4em; }
h3 { font-size: 1.05em; margin: 1em 0 0.3em; }
ul.notes { color: #444; padding-left: 1.2em; margin: 0.3em 0; }
figure { margin: 0; }
figcaption { font-size: 0.85em; color: #444; margin-top: 2px; }
img.px { image-rendering: pixelated; display: block; width: 100%; height: auto; background: #808080; }
.top { display: flex; flex-wrap: wrap; gap: 24px; align-items: flex-end; }
.reference { width: 400px; max-width: 100%; }
.legend { width: 320px; max-width: 100%; }
.legend img { display: block; width: 100%; height: 16px; image-rendering: pixelated; }
.ticks { display: flex; justify-content: space-between; font-size: 0.8em; }
.methods { display: flex; flex-wrap: wrap; gap: 16px; margin-top: 16px; }
.method { width: 560px; max-width: 100%; }
.pair { display: flex; gap: 6px; }
.pair > div { flex: 1; min-width: 0; font-size: 0.8em; color: #555; }
table { border-collapse: collapse; font-variant-numeric: tabular-nums; font-size: 0.9em; }
th, td { padding: 3px 8px; border-bottom: 1px solid #ddd; text-align: right; }
th:nth-child(-n+2), td:nth-child(-n+2) { text-align: left; }
svg.chart { max-width: 100%; height: auto; }
.red { color: #c8141e; font-weight: 600; }
.blue { color: #1946c8; font-weight: 600; }
";

fn img(class: &str, png: &[u8], alt: &str) -> String {
    format!(
        "<img class=\"{class}\" src=\"data:image/png;base64,{}\" alt=\"{}\">",
        base64::encode(png),
        html(alt)
    )
}

fn method_figure(m: &MethodResult) -> String {
    let name = format!("{} / {}", m.method, m.preset);
    format!(
        "<figure class=\"method\"><div class=\"pair\"><div>{}AO</div><div>{}Error</div></div>\
         <figcaption><b>{}</b>: RMSE {}, bias {}, SSIM {}</figcaption></figure>\n",
        img("px", &m.ao_png, &format!("AO of {name}")),
        img("px", &m.error_png, &format!("Signed error of {name}")),
        html(&name),
        fixed(m.all.rmse, 4),
        signed(m.all.bias, 4),
        fixed(m.all.ssim, 4),
    )
}

fn table(methods: &[MethodResult]) -> String {
    let cells = |tag: &str, texts: &[String]| -> String {
        texts
            .iter()
            .map(|t| format!("<{tag}>{}</{tag}>", html(t)))
            .collect()
    };
    let sequence = has_sequence(methods);
    let headings: Vec<String> = columns(sequence).iter().map(|c| c.to_string()).collect();
    let mut out = format!(
        "<table>\n<thead><tr>{}</tr></thead>\n<tbody>\n",
        cells("th", &headings)
    );
    for m in methods {
        out.push_str(&format!(
            "<tr>{}</tr>\n",
            cells("td", &row_cells(m, sequence))
        ));
    }
    out.push_str("</tbody>\n</table>\n");
    out
}

fn view_section(report: &Report, view: &ViewResult) -> String {
    let range = report.error_range;
    let mut out = format!(
        "<section>\n<h2>{}</h2>\n<div class=\"top\">\n",
        html(&view.name)
    );
    out.push_str(&format!(
        "<figure class=\"reference\">{}<figcaption>Reference</figcaption></figure>\n",
        img(
            "px",
            &view.reference_png,
            &format!("Reference AO of {}", view.name)
        )
    ));
    out.push_str(&format!(
        "<figure class=\"legend\">{}<div class=\"ticks\"><span>-{range}</span><span>0</span><span>+{range}</span></div>\
         <figcaption>Error = AO &minus; reference: <span class=\"blue\">blue</span> too dark (over-occludes), \
         <span class=\"red\">red</span> too bright (under-occludes), grey not scored.</figcaption></figure>\n</div>\n",
        img("bar", &report.legend_png, "Error colour scale")
    ));
    if view.methods.is_empty() {
        out.push_str("<p>No methods were scored.</p>\n</section>\n");
        return out;
    }
    out.push_str("<div class=\"methods\">\n");
    for m in &view.methods {
        out.push_str(&method_figure(m));
    }
    out.push_str("</div>\n<h3>Metrics</h3>\n");
    out.push_str(&table(&view.methods));
    out.push_str("<h3>Error versus cost</h3>\n");
    out.push_str(&scatter_svg(&view.methods));
    out.push_str("</section>\n");
    out
}

pub(super) fn render(report: &Report) -> String {
    let title = html(&report.title);
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n<h1>{title}</h1>\n"
    );
    let notes: Vec<&String> = report
        .notes
        .iter()
        .filter(|n| !n.trim().is_empty())
        .collect();
    if !notes.is_empty() {
        out.push_str("<ul class=\"notes\">\n");
        for note in notes {
            out.push_str(&format!("<li>{}</li>\n", html(note)));
        }
        out.push_str("</ul>\n");
    }
    out.push_str(
        "<p>Metrics compare each method's AO (1 = unoccluded) with the reference over surface pixels; \
         edge columns use only pixels near depth edges, grazing ones only surfaces seen nearly edge-on. \
         Bias &gt; 0 means too bright.</p>\n",
    );
    for view in &report.views {
        out.push_str(&view_section(report, view));
    }
    out.push_str("</body>\n</html>\n");
    out
}
