//! `aokit settings`: every setting's range, default and effective value, and docs/settings.md
//! as the declarations (crates/aokit/src/settings/table.rs, and each method's in
//! crates/aokit/src/methods/) generate it.

use crate::common::{aokit, failure, ok};

#[test]
fn docs_settings_md_is_what_the_declarations_generate() {
    let dir = tempfile::tempdir().unwrap();
    let generated = ok(&aokit(dir.path(), &["settings", "--markdown"]));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/settings.md");
    let docs = std::fs::read_to_string(path).unwrap();
    if docs != generated {
        let (line, (old, new)) = docs
            .lines()
            .chain(std::iter::repeat("<end of file>"))
            .zip(generated.lines().chain(std::iter::repeat("<end of file>")))
            .enumerate()
            .find(|(_, (old, new))| old != new)
            .unwrap_or((0, ("", "")));
        panic!(
            "docs/settings.md is not what the settings' declarations generate; regenerate it \
             with\n\n    cargo run -p aokit-cli -- settings --markdown > docs/settings.md\n\n\
             first difference, line {}:\n  file:      {old}\n  generated: {new}",
            line + 1
        );
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
