//! `Report::markdown`.

use super::Report;
use super::text::{columns, fixed, has_sequence, markdown_cell, row_cells, signed};

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
         Edge columns score only pixels near depth edges, grazing ones only surfaces seen nearly \
         edge-on.\n",
    );
    for view in &report.views {
        out.push_str(&format!("\n## {}\n\n", markdown_cell(&view.name)));
        let sequence = has_sequence(&view.methods);
        let headings = columns(sequence);
        out.push_str(&format!("| {} |\n|:--|:--|", headings.join(" | ")));
        out.push_str(&"--:|".repeat(headings.len() - 2));
        out.push('\n');
        for m in &view.methods {
            let row: Vec<String> = row_cells(m, sequence)
                .iter()
                .map(|c| markdown_cell(c))
                .collect();
            out.push_str(&format!("| {} |\n", row.join(" | ")));
        }
    }
    out
}

pub(super) fn render_by_method(report: &Report) -> String {
    let mut methods: Vec<&str> = Vec::new();
    for m in report.views.iter().flat_map(|v| &v.methods) {
        if !methods.contains(&m.method.as_str()) {
            methods.push(&m.method);
        }
    }
    let mut out = String::new();
    for method in methods {
        out.push_str(&format!(
            "## {}\n\n| Preset | Samples/px |",
            markdown_cell(method)
        ));
        for view in &report.views {
            out.push_str(&format!(" {} |", markdown_cell(&view.name)));
        }
        out.push_str("\n|:--|--:|");
        out.push_str(&"--:|".repeat(report.views.len()));
        out.push('\n');
        let mut rows: Vec<&super::MethodResult> = Vec::new();
        for m in report.views.iter().flat_map(|v| &v.methods) {
            if m.method == method && !rows.iter().any(|r| r.preset == m.preset) {
                rows.push(m);
            }
        }
        for row in rows {
            out.push_str(&format!(
                "| {} | {} |",
                markdown_cell(&row.preset),
                row.samples_per_pixel
            ));
            for view in &report.views {
                let cell = view
                    .methods
                    .iter()
                    .find(|m| m.method == method && m.preset == row.preset)
                    .map_or_else(
                        || "n/a".to_string(),
                        |m| format!("{} ({})", fixed(m.all.rmse, 4), signed(m.all.bias, 3)),
                    );
                out.push_str(&format!(" {cell} |"));
            }
            out.push('\n');
        }
        out.push('\n');
    }
    out
}
