//! `aokit settings`: every setting with its type, range, default and the value a method, preset,
//! settings file and `--set` give it; with `--markdown`, docs/settings.md, or with `--method` too
//! the table of that method's own keys in docs/methods/METHOD.md, generated from the declarations
//! (`aokit::settings::SETTINGS`).

use anyhow::Result;
use aokit::settings::{SETTINGS, SettingSpec, SettingValue};
use aokit::{AoSettings, Method, Preset};
use clap::Args;

use crate::settings_args::SettingsArgs;

#[derive(Args, Debug, Clone)]
pub struct SettingsListArgs {
    /// Print docs/settings.md instead (`aokit settings --markdown > docs/settings.md`); with
    /// `--method M`, the table of M's own keys in docs/methods/M.md (`bash
    /// scripts/settings-docs.sh` writes both).
    #[arg(long)]
    pub markdown: bool,
    #[command(flatten)]
    pub settings: SettingsArgs,
}

pub fn run(args: &SettingsListArgs) -> Result<()> {
    if args.markdown {
        match &args.settings.method {
            Some(name) => print!(
                "{}",
                method_markdown(name.parse().map_err(anyhow::Error::msg)?)
            ),
            None => print!("{}", markdown()),
        }
        return Ok(());
    }
    let settings = args.settings.resolve(None)?;
    print!("{}", listing(&settings));
    Ok(())
}

/// A value as docs/settings.md and the listing show it: floats below 0.001 in exponent form
/// (`1e-6`), names in backticks where `markdown`.
fn show(value: SettingValue, markdown: bool) -> String {
    match value {
        SettingValue::Float(v) if v != 0.0 && v.abs() < 1e-3 => format!("{v:e}"),
        SettingValue::Choice(name) if markdown => format!("`{name}`"),
        value => value.to_string(),
    }
}

/// One line per setting: key, type, default, the value in `settings` (marked `*` where it
/// differs from the default) and the range.
fn listing(settings: &AoSettings) -> String {
    let defaults = AoSettings::default();
    let rows: Vec<[String; 5]> = SETTINGS
        .iter()
        .map(|spec| {
            let default = spec.get(&defaults);
            let value = spec.get(settings);
            let mark = if value == default { "" } else { " *" };
            [
                spec.name.to_string(),
                spec.kind.type_name().to_string(),
                show(default, false),
                format!("{}{mark}", show(value, false)),
                spec.kind.range_text().replace('`', ""),
            ]
        })
        .collect();
    let header = ["key", "type", "default", "value", "range"].map(String::from);
    let mut widths = [0; 5];
    for row in std::iter::once(&header).chain(&rows) {
        for (width, cell) in widths.iter_mut().zip(row) {
            *width = (*width).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    for row in std::iter::once(&header).chain(&rows) {
        let line: Vec<String> = row
            .iter()
            .zip(widths)
            .map(|(cell, width)| format!("{cell:width$}"))
            .collect();
        out += line.join("  ").trim_end();
        out += "\n";
    }
    out +=
        "\n* differs from the default (`gtao` at `high`). docs/settings.md has what each does.\n";
    out
}

/// How a setting's preset values vary, for the default column: "per method and preset" and
/// the like, with the other methods' values at the default preset where only a few differ.
fn variation(spec: &SettingSpec) -> Option<String> {
    if spec.name == "method" {
        // The one setting that is the method itself.
        return None;
    }
    let value = |method, preset| spec.get(&AoSettings::preset(method, preset));
    let by_method = Preset::ALL.into_iter().any(|preset| {
        Method::ALL
            .into_iter()
            .any(|method| value(method, preset) != value(Method::default(), preset))
    });
    let by_preset = Method::ALL.into_iter().any(|method| {
        Preset::ALL
            .into_iter()
            .any(|preset| value(method, preset) != value(method, Preset::default()))
    });
    let per = match (by_method, by_preset) {
        (false, false) => return None,
        (true, true) => "per method and preset",
        (true, false) => "per method",
        (false, true) => "per preset",
    };
    let default = spec.default_value();
    let others: Vec<String> = Method::ALL
        .into_iter()
        .filter_map(|method| {
            let v = value(method, Preset::default());
            (v != default).then(|| format!("`{}`: {}", method.name(), show(v, true)))
        })
        .collect();
    let mut text = format!("{per}, [tuning.md](tuning.md)");
    if !others.is_empty() && others.len() <= 3 {
        text += &format!("; {}", others.join(", "));
    }
    Some(text)
}

const INTRO: &str = "\
# Settings

<!-- Generated from the declarations in crates/aokit/src/settings/table.rs by
`bash scripts/settings-docs.sh` (`aokit settings --markdown`): edit those, not this file. -->

Everything that shapes the AO lives in one struct, `aokit::AoSettings`. The CLI builds it in
this order, each step overriding the last:

1. the preset of the method: `--method gtao --preset low|medium|high|ultra` (default `gtao`,
   `high`);
2. the scene's suggested radius;
3. a TOML file: `--settings FILE.toml`, holding any subset of the keys below;
4. `--radius R`;
5. each `--set KEY=VALUE`, in order. `KEY` is the dotted path below; `VALUE` is read as TOML
   (`4`, `0.25`, `true`, `\"gtao\"`), or as a bare string.

An unknown key, a value of the wrong type or a value out of range stops the command with exit
code 2 and names the key (a mistyped key, with the nearest one); nothing is clamped silently.
`aokit settings [--method M] [--preset P] [--settings FILE.toml] [--set KEY=VALUE]` lists every
key with its range, its default and the value those flags give it. Programs reach the same
declarations through `aokit::settings::SETTINGS`, and set a setting by its key with
`AoSettings::set`.

";

const AFTER_TABLE: &str = "
Keys of methods other than the one running are kept but unused, so one file can tune several
methods.

## Presets

Every method takes the same number of depth samples per pixel at a preset, so presets compare
methods at equal cost:

";

const AFTER_PRESETS: &str = "
Each split, and each method's `step_power`, is the one with the lowest mean RMSE against the
reference over the built-in scenes and the Sponza cameras among those tried
([methods.md](methods.md#how-the-presets-were-chosen)); GPU cost, which the split also moves, is
the performance work's to weigh. `msvo`'s count is per level: its coarser levels add at most a
third to the working level's samples, and each level's merge reads four texels.

## Example

```toml
# gtao-soft.toml
radius = 1.5
power = 1.3

[gtao]
slice_count = 4
```

```sh
aokit render --scene stairs --settings gtao-soft.toml --set gtao.steps_per_side=6
```
";

/// A table row of `spec` with the default `value` and the note on how it varies, if any.
fn row(spec: &SettingSpec, value: SettingValue, variation: Option<String>) -> String {
    let mut default = show(value, true);
    let notes: Vec<String> = spec
        .default_note
        .map(String::from)
        .into_iter()
        .chain(variation)
        .collect();
    if !notes.is_empty() {
        default += &format!(" ({})", notes.join("; "));
    }
    let cells = [
        format!("`{}`", spec.name),
        spec.kind.type_name().to_string(),
        spec.kind.range_text(),
        default,
        spec.help.to_string(),
    ];
    let mut out = String::new();
    for cell in cells {
        // An empty cell as `| |`, as a Markdown table writes it.
        out += "| ";
        if !cell.is_empty() {
            out += &cell.replace('|', "\\|");
            out += " ";
        }
    }
    out + "|\n"
}

/// The table of `method`'s own keys on its page, docs/methods/METHOD.md: each default is the
/// method's at the default preset, noted where its other presets differ, and the links are
/// made relative to docs/methods/.
pub fn method_markdown(method: Method) -> String {
    let base = AoSettings::preset(method, Preset::default());
    let mut out = format!(
        "| key | type | range | default (`{}`) | meaning |\n\
         |-----|------|-------|------------------|---------|\n",
        Preset::default().name()
    );
    for spec in method.own_settings() {
        let by_preset = Preset::ALL
            .into_iter()
            .any(|preset| spec.get(&AoSettings::preset(method, preset)) != spec.get(&base));
        let variation = by_preset.then(|| "per preset, [tuning.md](tuning.md)".to_string());
        out += &relink(&row(spec, spec.get(&base), variation));
    }
    out
}

/// `text`'s Markdown links, relative to docs/, made relative to docs/methods/ (and their texts
/// that name a path under it).
fn relink(text: &str) -> String {
    let text = text.replace("[methods/", "[");
    let mut out = String::new();
    let mut rest = text.as_str();
    while let Some(at) = rest.find("](") {
        out += &rest[..at + 2];
        rest = &rest[at + 2..];
        let target = rest.split(')').next().unwrap_or("");
        if target.starts_with("http") || target.starts_with('#') {
            continue;
        }
        match target.strip_prefix("methods/") {
            Some(local) => out += local,
            None => out += &format!("../{target}"),
        }
        rest = &rest[target.len()..];
    }
    out + rest
}

/// docs/settings.md: the prose around a table of the declarations and one of the presets.
pub fn markdown() -> String {
    let mut out = String::from(INTRO);
    out += "| key | type | range | default (`gtao`, `high`) | meaning |\n";
    out += "|-----|------|-------|--------------------------|---------|\n";
    for spec in SETTINGS {
        out += &row(spec, spec.default_value(), variation(spec));
    }
    out += AFTER_TABLE;
    out += "| preset | samples per pixel | `ssao*`/`sao`/`msvo.sample_count` \
             (`ue4_ssao.sample_count`: half, in pairs) | `hbao.direction_count` x `step_count` \
             | `gtao`/`vbao` slices x steps per side |\n";
    out += "|--------|----|----|-------|-------|\n";
    for preset in Preset::ALL {
        let s = AoSettings::preset(Method::Gtao, preset);
        out += &format!(
            "| {} | {} | {} | {} x {} | {} x {} |\n",
            preset.name(),
            s.samples_per_pixel(),
            s.ssao.sample_count,
            s.hbao.direction_count,
            s.hbao.step_count,
            s.gtao.slice_count,
            s.gtao.steps_per_side,
        );
    }
    out += AFTER_PRESETS;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listing_marks_what_the_flags_change() {
        let settings = AoSettings {
            radius: 2.0,
            ..AoSettings::default()
        };
        let listing = listing(&settings);
        let line = |key: &str| {
            listing
                .lines()
                .find(|l| l.split_whitespace().next() == Some(key))
                .unwrap_or_else(|| panic!("no {key} in\n{listing}"))
                .to_string()
        };
        assert!(line("radius").contains("2 *"), "{}", line("radius"));
        assert!(line("gtao.slice_count").contains("1..=64"));
        assert!(!line("gtao.slice_count").contains('*'));
        assert!(line("spatial.guided_epsilon").contains("1e-6"));
        assert_eq!(listing.lines().count(), SETTINGS.len() + 3);
    }

    #[test]
    fn a_method_page_links_from_docs_methods() {
        assert_eq!(
            relink(
                "[a](tuning.md), [methods/sao.md](methods/sao.md#t), [c](https://x.org/a.md), [d](#e)"
            ),
            "[a](../tuning.md), [sao.md](sao.md#t), [c](https://x.org/a.md), [d](#e)"
        );
        let hbao = method_markdown(Method::Hbao);
        assert!(hbao.contains("| `hbao.direction_count` | integer | 1..=64 | 6 (per preset"));
        assert!(!hbao.contains("](tuning.md)"), "{hbao}");
    }

    #[test]
    fn the_markdown_has_a_row_per_setting_and_the_presets_table() {
        let md = markdown();
        for spec in SETTINGS {
            assert!(
                md.contains(&format!("| `{}` |", spec.name)),
                "{}",
                spec.name
            );
        }
        assert!(md.contains("| high | 18 | 18 | 6 x 3 | 3 x 3 |"), "{md}");
        assert!(md.contains(
            "| `bias` | float | [0, 1] | 0.005 (per method, [tuning.md](tuning.md); \
             `ssao-crytek`: 0.02, `sao`: 0.01, `ue4-ssao`: 0.025) |"
        ));
    }
}
