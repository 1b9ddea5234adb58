//! `Report::html`: one offline page.

use super::chart::scatter_svg;
use super::text::{columns, fixed, has_sequence, html, row_cells, signed};
use super::{MethodResult, Report, ViewResult};
use crate::base64;

/// Layout only. Every AO, error and reference image shows at one width, `--img`, which the
/// zoom buttons set; images keep visible pixels so small renders stay readable. The page has no
/// script: clicking a method's AO ticks a hidden checkbox whose state shows the reference in
/// its place, and the zoom buttons are radio inputs whose state sets `--img`.
const STYLE: &str = "
body { font: 15px/1.4 system-ui, sans-serif; color: #222; background: #fff; margin: 0 auto; max-width: 1400px; padding: 12px 16px; }
h1 { font-size: 1.5em; margin: 0.3em 0; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 1.4em; }
h3 { font-size: 1.05em; margin: 1em 0 0.3em; }
ul.notes { color: #444; padding-left: 1.2em; margin: 0.3em 0; }
figure { margin: 0; }
figcaption { font-size: 0.85em; color: #444; margin-top: 2px; }
main { --img: 320px; }
#zoom-2:checked ~ main { --img: 640px; }
#zoom-4:checked ~ main { --img: 1280px; }
.zoom { position: sticky; top: 0; background: #fff; padding: 4px 0; z-index: 1; font-size: 0.9em; }
input.zoom-choice { display: none; }
.zoom label { border: 1px solid #999; border-radius: 3px; padding: 1px 8px; margin-left: 4px; cursor: pointer; }
#zoom-1:checked ~ .zoom label[for=zoom-1], #zoom-2:checked ~ .zoom label[for=zoom-2], #zoom-4:checked ~ .zoom label[for=zoom-4] { background: #222; color: #fff; }
img.px { image-rendering: pixelated; display: block; width: var(--img); max-width: none; height: auto; background: #808080; }
.top { display: flex; flex-wrap: wrap; gap: 24px; align-items: flex-end; }
.legend { width: 320px; max-width: 100%; }
.legend img { display: block; width: 100%; height: 16px; image-rendering: pixelated; }
.ticks { display: flex; justify-content: space-between; font-size: 0.8em; }
.methods { display: flex; flex-wrap: wrap; gap: 16px; margin-top: 16px; overflow-x: auto; }
.pair { display: flex; gap: 6px; }
.pair > div { font-size: 0.8em; color: #555; }
label.flip { display: block; cursor: pointer; }
label.flip input { display: none; }
label.flip img.reference-flip, label.flip input:checked ~ img.ao { display: none; }
label.flip input:checked ~ img.reference-flip { display: block; }
table { border-collapse: collapse; font-variant-numeric: tabular-nums; font-size: 0.9em; }
th, td { padding: 3px 8px; border-bottom: 1px solid #ddd; text-align: right; }
th:nth-child(-n+2), td:nth-child(-n+2) { text-align: left; }
table.summary th:nth-child(2), table.summary td:nth-child(2) { text-align: right; }
td.best { font-weight: 700; }
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

/// A method's AO, which shows the view's reference in its place while clicked on, and its
/// error map beside it.
fn method_figure(m: &MethodResult, reference_png: &[u8]) -> String {
    let name = format!("{} / {}", m.method, m.preset);
    format!(
        "<figure class=\"method\"><div class=\"pair\"><div>\
         <label class=\"flip\" title=\"Click to flip between this AO and the reference\">\
         <input type=\"checkbox\">{}{}</label>AO (click: reference)</div><div>{}Error</div></div>\
         <figcaption><b>{}</b>: RMSE {}, bias {}, SSIM {}</figcaption></figure>\n",
        img("px ao", &m.ao_png, &format!("AO of {name}")),
        img("px reference-flip", reference_png, "Reference AO"),
        img("px", &m.error_png, &format!("Signed error of {name}")),
        html(&name),
        fixed(m.all.rmse, 4),
        signed(m.all.bias, 4),
        fixed(m.all.ssim, 4),
    )
}

/// The RMSE of every method in every view, one row per view, the lowest of each row in bold:
/// what the page says, before its images.
fn summary(report: &Report) -> String {
    let mut columns: Vec<String> = Vec::new();
    for m in report.views.iter().flat_map(|v| &v.methods) {
        let name = format!("{} / {}", m.method, m.preset);
        if !columns.contains(&name) {
            columns.push(name);
        }
    }
    if columns.is_empty() {
        return String::new();
    }
    let mut out = String::from(
        "<h2>Summary</h2>\n<p>RMSE against the reference over surface pixels; the lowest of each \
         view in bold.</p>\n<table class=\"summary\">\n<thead><tr><th>View</th>",
    );
    for c in &columns {
        out.push_str(&format!("<th>{}</th>", html(c)));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    for (i, view) in report.views.iter().enumerate() {
        let rmse = |c: &String| {
            view.methods
                .iter()
                .find(|m| &format!("{} / {}", m.method, m.preset) == c)
                .map(|m| m.all.rmse)
        };
        let best = columns
            .iter()
            .filter_map(rmse)
            .filter(|v| v.is_finite())
            .fold(f64::INFINITY, f64::min);
        out.push_str(&format!(
            "<tr><td><a href=\"#view-{i}\">{}</a></td>",
            html(&view.name)
        ));
        for c in &columns {
            match rmse(c) {
                Some(v) if v == best => {
                    out.push_str(&format!("<td class=\"best\">{}</td>", fixed(v, 4)))
                }
                Some(v) => out.push_str(&format!("<td>{}</td>", fixed(v, 4))),
                None => out.push_str("<td></td>"),
            }
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody>\n</table>\n");
    out
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

fn view_section(report: &Report, index: usize, view: &ViewResult) -> String {
    let range = report.error_range;
    let mut out = format!(
        "<section id=\"view-{index}\">\n<h2>{}</h2>\n<div class=\"top\">\n",
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
        out.push_str(&method_figure(m, &view.reference_png));
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
    out.push_str(&summary(report));
    out.push_str(
        "<input class=\"zoom-choice\" type=\"radio\" name=\"zoom\" id=\"zoom-1\" checked>\
         <input class=\"zoom-choice\" type=\"radio\" name=\"zoom\" id=\"zoom-2\">\
         <input class=\"zoom-choice\" type=\"radio\" name=\"zoom\" id=\"zoom-4\">\n\
         <div class=\"zoom\">Images: <label for=\"zoom-1\">1x</label><label for=\"zoom-2\">2x</label>\
         <label for=\"zoom-4\">4x</label> &middot; click a method's AO to flip to the reference</div>\n<main>\n",
    );
    for (i, view) in report.views.iter().enumerate() {
        out.push_str(&view_section(report, i, view));
    }
    out.push_str("</main>\n</body>\n</html>\n");
    out
}
