//! Escaping and number formatting shared by the report formats.

/// `v` with `decimals` places; "inf" for infinity and "n/a" when undefined.
pub(super) fn fixed(v: f64, decimals: usize) -> String {
    if v.is_nan() {
        "n/a".to_string()
    } else if v.is_infinite() {
        if v > 0.0 { "inf" } else { "-inf" }.to_string()
    } else {
        format!("{v:.decimals$}")
    }
}

/// A signed value with an explicit `+`, so the bias reads as a direction.
pub(super) fn signed(v: f64, decimals: usize) -> String {
    if v.is_finite() {
        format!("{v:+.decimals$}")
    } else {
        fixed(v, decimals)
    }
}

/// GPU time in milliseconds, or "n/a" without timestamps.
pub(super) fn gpu_ms(ms: Option<f64>) -> String {
    ms.map_or_else(|| "n/a".to_string(), |ms| fixed(ms, 3))
}

/// Headings of the metrics table, which the Markdown and HTML tables share.
const COLUMNS: [&str; 13] = [
    "Method",
    "Preset",
    "Samples/px",
    "GPU ms",
    "MAE",
    "RMSE",
    "Bias",
    "PSNR dB",
    "SSIM",
    "Edge MAE",
    "Edge RMSE",
    "Edge SSIM",
    "Grazing bias",
];

/// Headings of the sequence columns, shown when a view has a result over a sequence.
const SEQUENCE_COLUMNS: [&str; 3] = ["Mean RMSE over frames", "Flicker", "Disoccluded RMSE"];

/// The table's headings: with the sequence columns when `sequence` is true.
pub(super) fn columns(sequence: bool) -> Vec<&'static str> {
    let mut all = COLUMNS.to_vec();
    if sequence {
        all.extend(SEQUENCE_COLUMNS);
    }
    all
}

/// Whether any of `methods` was scored over a sequence.
pub(super) fn has_sequence(methods: &[super::MethodResult]) -> bool {
    methods.iter().any(|m| m.sequence.is_some())
}

/// One result as the cells of [`columns`], formatted but not escaped.
pub(super) fn row_cells(m: &super::MethodResult, sequence: bool) -> Vec<String> {
    let mut cells = vec![
        m.method.clone(),
        m.preset.clone(),
        m.samples_per_pixel.to_string(),
        gpu_ms(m.gpu_ms),
        fixed(m.all.mae, 4),
        fixed(m.all.rmse, 4),
        signed(m.all.bias, 4),
        fixed(m.all.psnr, 2),
        fixed(m.all.ssim, 4),
        fixed(m.edges.mae, 4),
        fixed(m.edges.rmse, 4),
        fixed(m.edges.ssim, 4),
        signed(m.grazing.bias, 4),
    ];
    if sequence {
        cells.extend(match &m.sequence {
            Some(s) => [
                fixed(s.mean_rmse, 4),
                fixed(s.flicker, 4),
                fixed(s.disoccluded.rmse, 4),
            ],
            None => ["n/a".to_string(), "n/a".to_string(), "n/a".to_string()],
        });
    }
    cells
}

/// Text safe inside HTML elements and quoted attributes.
pub(super) fn html(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A CSV field, quoted when it holds a separator, quote or line break.
pub(super) fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// Text safe inside a Markdown table cell.
pub(super) fn markdown_cell(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('|', "\\|")
        .replace(['\n', '\r'], " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes() {
        assert_eq!(
            html("<a href=\"x\">&'"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;"
        );
        assert_eq!(csv_field("plain"), "plain");
        assert_eq!(csv_field("a,\"b\""), "\"a,\"\"b\"\"\"");
        assert_eq!(markdown_cell("a|b\nc"), "a\\|b c");
    }

    #[test]
    fn numbers() {
        assert_eq!(fixed(0.123456, 4), "0.1235");
        assert_eq!(fixed(f64::INFINITY, 2), "inf");
        assert_eq!(fixed(f64::NAN, 2), "n/a");
        assert_eq!(signed(0.01, 3), "+0.010");
        assert_eq!(signed(-0.01, 3), "-0.010");
        assert_eq!(gpu_ms(None), "n/a");
        assert_eq!(gpu_ms(Some(1.23456)), "1.235");
    }
}
