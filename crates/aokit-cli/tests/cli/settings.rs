//! `aokit settings`: every setting's range, default and effective value, and docs/settings.md
//! and the method pages' tables of their own keys as the declarations
//! (crates/aokit/src/settings/table.rs, and each method's in crates/aokit/src/methods/) generate them.

use crate::common::{aokit, failure, ok};

/// Fails with the first line where `docs` (the text of `what`) is not `generated`.
fn assert_generated(what: &str, docs: &str, generated: &str) {
    if docs != generated {
        let (line, (old, new)) = docs
            .lines()
            .chain(std::iter::repeat("<end>"))
            .zip(generated.lines().chain(std::iter::repeat("<end>")))
            .enumerate()
            .find(|(_, (old, new))| old != new)
            .unwrap_or((0, ("", "")));
        panic!(
            "{what} is not what the settings' declarations generate; regenerate it with\n\n    \
             bash scripts/settings-docs.sh\n\nfirst difference, line {}:\n  file:      {old}\n  \
             generated: {new}",
            line + 1
        );
    }
}

#[test]
fn docs_settings_md_is_what_the_declarations_generate() {
    let dir = tempfile::tempdir().unwrap();
    let generated = ok(&aokit(dir.path(), &["settings", "--markdown"]));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/settings.md");
    let docs = std::fs::read_to_string(path).unwrap();
    assert_generated("docs/settings.md", &docs, &generated);
}

#[test]
fn each_method_page_holds_the_table_of_its_keys_the_declarations_generate() {
    let dir = tempfile::tempdir().unwrap();
    for method in aokit::Method::ALL {
        let name = method.name();
        let generated = ok(&aokit(
            dir.path(),
            &["settings", "--markdown", "--method", name],
        ));
        assert!(
            generated.lines().count() > 2,
            "{name}: no keys in\n{generated}"
        );
        let path = format!(
            "{}/../../docs/methods/{name}.md",
            env!("CARGO_MANIFEST_DIR")
        );
        let page = std::fs::read_to_string(&path).unwrap();
        let (start, end) = (
            format!("<!-- settings:{name} -->"),
            format!("<!-- /settings:{name} -->"),
        );
        let block = page
            .split_once(&start)
            .and_then(|(_, rest)| rest.split_once(&end))
            .unwrap_or_else(|| panic!("docs/methods/{name}.md has no {start} ... {end}"))
            .0;
        let what = format!("the table of docs/methods/{name}.md");
        assert_generated(&what, block.trim(), generated.trim());
    }
}

#[test]
fn settings_lists_every_key_with_the_value_the_flags_give_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = ok(&aokit(
        dir.path(),
        &[
            "settings",
            "--method",
            "vbao",
            "--preset",
            "low",
            "--set",
            "spatial.radius=5",
        ],
    ));
    let line = |key: &str| {
        out.lines()
            .find(|l| l.split_whitespace().next() == Some(key))
            .unwrap_or_else(|| panic!("no {key} in\n{out}"))
            .split_whitespace()
            .collect::<Vec<_>>()
    };
    assert_eq!(
        line("spatial.radius"),
        ["spatial.radius", "integer", "3", "5", "*", "1..=8"]
    );
    assert_eq!(
        line("method")[..5],
        ["method", "string", "gtao", "vbao", "*"]
    );
    let low = aokit::AoSettings::preset(aokit::Method::Vbao, aokit::Preset::Low);
    assert_eq!(
        line("vbao.steps_per_side")[3],
        low.vbao.steps_per_side.to_string()
    );
    let err = failure(&aokit(dir.path(), &["settings", "--set", "gtao.slices=2"]));
    assert!(err.contains("did you mean `gtao.slice_count`?"), "{err}");
}
