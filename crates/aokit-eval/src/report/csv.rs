//! `Report::csv`.

use super::Report;
use super::text::csv_field;
use crate::metrics::{Metrics, SequenceMetrics};

const HEADER: &str = "view,method,preset,samples_per_pixel,gpu_ms,pixels,mae,rmse,bias,psnr,ssim,\
edge_pixels,edge_mae,edge_rmse,edge_bias,edge_psnr,edge_ssim,\
grazing_pixels,grazing_mae,grazing_rmse,grazing_bias,grazing_psnr,grazing_ssim,\
frames,mean_rmse,flicker,disoccluded_pixels,disoccluded_mae,disoccluded_rmse,disoccluded_bias,\
disoccluded_psnr,disoccluded_ssim";

fn metrics(m: &Metrics) -> String {
    format!(
        "{},{},{},{},{},{}",
        m.pixels, m.mae, m.rmse, m.bias, m.psnr, m.ssim
    )
}

/// Sequence columns, empty for a single frame.
fn sequence(s: Option<&SequenceMetrics>) -> String {
    s.map_or_else(
        || ",,,,,,,,".to_string(),
        |s| {
            format!(
                "{},{},{},{}",
                s.frames,
                s.mean_rmse,
                s.flicker,
                metrics(&s.disoccluded)
            )
        },
    )
}

pub(super) fn render(report: &Report) -> String {
    let mut out = format!("{HEADER}\n");
    for view in &report.views {
        for m in &view.methods {
            out.push_str(&format!(
                "{},{},{},{},{},{},{},{},{}\n",
                csv_field(&view.name),
                csv_field(&m.method),
                csv_field(&m.preset),
                m.samples_per_pixel,
                m.gpu_ms.map(|ms| ms.to_string()).unwrap_or_default(),
                metrics(&m.all),
                metrics(&m.edges),
                metrics(&m.grazing),
                sequence(m.sequence.as_ref()),
            ));
        }
    }
    out
}
