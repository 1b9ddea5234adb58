//! The three report formats.

use aokit_eval::report::{MethodResult, Report, ViewResult};
use aokit_eval::{Metrics, encode_png_grey, encode_png_rgb, legend_rgb};

fn metrics(rmse: f64) -> Metrics {
    Metrics {
        pixels: 100,
        mae: rmse * 0.8,
        rmse,
        bias: -rmse / 2.0,
        psnr: 10.0 * (1.0 / (rmse * rmse)).log10(),
        ssim: 0.9,
    }
}

fn method(name: &str, preset: &str, rmse: f64, gpu_ms: Option<f64>, spp: u32) -> MethodResult {
    MethodResult {
        method: name.to_string(),
        preset: preset.to_string(),
        all: metrics(rmse),
        edges: metrics(rmse * 2.0),
        grazing: metrics(rmse * 3.0),
        sequence: None,
        gpu_ms,
        samples_per_pixel: spp,
        ao_png: encode_png_grey([2, 2], &[0.0, 0.5, 1.0, 0.25]).unwrap(),
        error_png: encode_png_rgb([1, 1], &[255, 0, 0]).unwrap(),
    }
}

fn report() -> Report {
    Report {
        title: "AO <compare> & friends".to_string(),
        notes: vec![
            "Adapter: <script>alert(1)</script>".to_string(),
            String::new(),
        ],
        error_range: 0.25,
        legend_png: encode_png_rgb([4, 1], &legend_rgb(4, 1)).unwrap(),
        views: vec![
            ViewResult {
                name: "room / default".to_string(),
                reference_png: encode_png_grey([2, 2], &[1.0; 4]).unwrap(),
                methods: vec![
                    method("gtao", "low", 0.05, Some(0.5), 8),
                    method("gtao", "high", 0.02, Some(1.25), 32),
                ],
            },
            ViewResult {
                name: "stairs, \"top\"".to_string(),
                reference_png: encode_png_grey([2, 2], &[0.5; 4]).unwrap(),
                methods: vec![
                    method("hbao", "medium", 0.03, None, 16),
                    MethodResult {
                        all: Metrics {
                            psnr: f64::INFINITY,
                            ..metrics(0.0)
                        },
                        edges: Metrics::EMPTY,
                        grazing: Metrics::EMPTY,
                        sequence: None,
                        ..method("ssao", "ultra", 0.0, None, 64)
                    },
                ],
            },
        ],
    }
}

#[test]
fn csv_has_header_and_one_row_per_result() {
    let csv = report().csv();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "view,method,preset,samples_per_pixel,gpu_ms,pixels,mae,rmse,bias,psnr,ssim,edge_pixels,edge_mae,edge_rmse,edge_bias,edge_psnr,edge_ssim,grazing_pixels,grazing_mae,grazing_rmse,grazing_bias,grazing_psnr,grazing_ssim,frames,mean_rmse,flicker,disoccluded_pixels,disoccluded_mae,disoccluded_rmse,disoccluded_bias,disoccluded_psnr,disoccluded_ssim"
    );
    assert_eq!(lines.len(), 5);
    assert!(
        lines[1].starts_with("room / default,gtao,low,8,0.5,100,0.04"),
        "{}",
        lines[1]
    );
    assert!(
        lines[3].starts_with("\"stairs, \"\"top\"\"\",hbao,medium,16,,100,"),
        "{}",
        lines[3]
    );
    assert!(
        lines[4].contains(",inf,")
            && lines[4].ends_with(",0,NaN,NaN,NaN,NaN,NaN,0,NaN,NaN,NaN,NaN,NaN,,,,,,,,,"),
        "{}",
        lines[4]
    );
    for line in &lines[1..] {
        // 32 fields once the quoted comma is accounted for.
        let fields = line
            .replace("\"stairs, \"\"top\"\"\"", "view")
            .split(',')
            .count();
        assert_eq!(fields, 32, "{line}");
    }
}

#[test]
fn markdown_has_a_table_per_view() {
    let md = report().markdown();
    assert!(md.starts_with("# AO <compare> & friends\n"));
    assert!(md.contains("## room / default") && md.contains("## stairs, \"top\""));
    assert_eq!(md.matches("| Method | Preset |").count(), 2);
    assert!(md.contains("| gtao | low | 8 | 0.500 | 0.0400 | 0.0500 | -0.0250 | 26.02 | 0.9000 | 0.0800 | 0.1000 | 0.9000 | -0.0750 |"), "{md}");
    assert!(md.contains("| hbao | medium | 16 | n/a |"), "{md}");
    assert!(
        md.contains("| inf |") && md.contains("| n/a | n/a |"),
        "{md}"
    );
}

#[test]
fn html_leads_with_a_summary_and_flips_and_zooms_without_scripts() {
    let html = report().html();
    let summary = html
        .find("<table class=\"summary\">")
        .expect("a summary table");
    let first_view = html
        .find("<section id=\"view-0\">")
        .expect("the first view");
    assert!(summary < first_view, "the summary comes before the views");
    // One row per view, linked to its section, with the lower RMSE of each in bold.
    let table = &html[summary..html[summary..].find("</table>").unwrap() + summary];
    assert!(
        table.contains("<a href=\"#view-0\">room / default</a>"),
        "{table}"
    );
    assert!(
        table.contains("<a href=\"#view-1\">stairs, &quot;top&quot;</a>"),
        "{table}"
    );
    assert_eq!(table.matches("<td class=\"best\">").count(), 2, "{table}");
    assert!(table.contains("<td class=\"best\">0.0200</td>"), "{table}");
    assert!(table.contains("<td class=\"best\">0.0000</td>"), "{table}");
    // Every method's AO flips to its view's reference: the reference's image follows it.
    assert_eq!(html.matches("<label class=\"flip\"").count(), 4);
    assert_eq!(html.matches("class=\"px reference-flip\"").count(), 4);
    // Three zoom levels set one image width for every image.
    for level in ["zoom-1", "zoom-2", "zoom-4"] {
        assert!(html.contains(&format!("id=\"{level}\"")), "{level}");
        assert!(
            html.contains(&format!("<label for=\"{level}\">")),
            "{level}"
        );
    }
    assert!(html.contains("width: var(--img)"));
    assert!(!html.contains("<script"));
}

#[test]
fn html_is_self_contained_and_escaped() {
    let html = report().html();
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(html.trim_end().ends_with("</html>"));
    assert!(!html.contains("http"), "no external references");
    assert!(
        !html.contains("<script"),
        "no scripts, and notes are escaped"
    );
    assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
    assert!(html.contains("<title>AO &lt;compare&gt; &amp; friends</title>"));
    assert!(html.contains("stairs, &quot;top&quot;"));
    assert!(html.contains("image-rendering: pixelated"));
    // 2 references + 4 methods x 3 images (AO, its reference to flip to, error) + 2 legends.
    assert_eq!(
        html.matches("src=\"data:image/png;base64,").count(),
        2 + 12 + 2
    );
    assert!(html.contains("<span>-0.25</span><span>0</span><span>+0.25</span>"));
    for label in ["gtao / low", "gtao / high", "hbao / medium", "ssao / ultra"] {
        assert!(html.contains(label), "{label}");
    }
    // The first view is timed, the second is not.
    assert_eq!(html.matches("<svg").count(), 2);
    assert!(
        html.contains(">GPU time per frame (ms)</text>")
            && html.contains(">Samples per pixel</text>")
    );
    assert!(html.contains(">gtao/high</text>") && html.contains(">ssao/ultra</text>"));
    // Balanced structure.
    for tag in ["section", "table", "svg", "figure", "ul", "body", "html"] {
        assert_eq!(
            html.matches(&format!("<{tag}")).count(),
            html.matches(&format!("</{tag}>")).count(),
            "{tag}"
        );
    }
}

#[test]
fn empty_report_still_renders() {
    let report = Report {
        title: String::new(),
        notes: Vec::new(),
        error_range: 0.25,
        legend_png: Vec::new(),
        views: vec![ViewResult {
            name: "nothing".to_string(),
            reference_png: Vec::new(),
            methods: Vec::new(),
        }],
    };
    assert_eq!(report.csv().lines().count(), 1);
    assert!(report.markdown().contains("## nothing"));
    assert!(report.html().contains("No methods were scored."));
}

#[test]
fn markdown_by_method_has_a_row_per_preset_and_a_column_per_view() {
    let md = report().markdown_by_method();
    assert!(md.contains("## gtao") && md.contains("## hbao") && md.contains("## ssao"));
    assert!(
        md.contains("| Preset | Samples/px | room / default | stairs, \"top\" |"),
        "{md}"
    );
    assert!(md.contains("| low | 8 | 0.0500 (-0.025) | n/a |"), "{md}");
    assert!(
        md.contains("| medium | 16 | n/a | 0.0300 (-0.015) |"),
        "{md}"
    );
}

#[test]
fn sequence_scores_add_columns_only_where_there_are_sequences() {
    let mut report = report();
    assert!(!report.markdown().contains("Flicker"));
    report.views[0].methods[0].sequence = Some(aokit_eval::SequenceMetrics {
        frames: 8,
        mean_rmse: 0.0612,
        flicker: 0.0021,
        disoccluded: metrics(0.2),
    });
    let md = report.markdown();
    assert!(md.contains("| Flicker |"), "{md}");
    assert!(md.contains("| 0.0612 | 0.0021 | 0.2000 |"), "{md}");
    assert!(md.contains("| n/a | n/a | n/a |"), "{md}");
    assert!(report.html().contains("<th>Flicker</th>"));
    assert!(
        report
            .csv()
            .lines()
            .nth(1)
            .unwrap()
            .contains(",8,0.0612,0.0021,100,")
    );
}
