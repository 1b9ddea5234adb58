//! `Report::markdown`.

use super::Report;
use super::text::{fixed, gpu_ms, markdown_cell, signed};

pub(super) fn render(report: &Report) -> String {
    let mut out = format!("# {}\n\n", markdown_cell(&report.title));
    let notes: Vec<&String> = report
        .notes
        .iter()
        .filter(|n| !n.trim().is_empty())
        .collect();
    for note in &notes {
        out.push_str(&format!("- {}\n", markdown_cell(note)));
    }
    if !notes.is_empty() {
        out.push('\n');
    }
    out.push_str(
        "Errors are AO minus reference over surface pixels; bias > 0 means too bright (under-occludes). \
         Edge columns score only pixels near depth edges.\n",
    );
    for view in &report.views {
        out.push_str(&format!("\n## {}\n\n", markdown_cell(&view.name)));
        out.push_str(
            "| Method | Preset | Samples/px | GPU ms | MAE | RMSE | Bias | PSNR dB | SSIM | Edge MAE | Edge RMSE |\n\
             |:--|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
        );
        for m in &view.methods {
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                markdown_cell(&m.method),
                markdown_cell(&m.preset),
                m.samples_per_pixel,
                gpu_ms(m.gpu_ms),
                fixed(m.all.mae, 4),
                fixed(m.all.rmse, 4),
                signed(m.all.bias, 4),
                fixed(m.all.psnr, 2),
                fixed(m.all.ssim, 4),
                fixed(m.edges.mae, 4),
                fixed(m.edges.rmse, 4),
            ));
        }
    }
    out
}
