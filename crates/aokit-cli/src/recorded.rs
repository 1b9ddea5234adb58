//! `ao-settings.json`: the AO settings `render --gbuffer` ran, written beside camera.json so
//! that `aokit ao` on the exported passes runs the same ones (docs/camera-json.md). A file of
//! its own rather than keys in camera.json, which readers refuse unknown keys in.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow};
use aokit::{AoSettings, Preset};
use serde::{Deserialize, Serialize};

use crate::export::write_json;

/// The file's name, beside the camera.json it goes with.
pub const FILE_NAME: &str = "ao-settings.json";

/// The file's contents: the preset the settings started from and every setting as it ran
/// (`method` and `radius` among them). `S` is [`AoSettings`] when written, a table of settings
/// when read, so that a file from another version (a setting added or dropped) gets the same
/// checks and messages as a `--settings` file.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Record<S> {
    preset: String,
    settings: S,
}

/// Settings read back from an `ao-settings.json`.
#[derive(Debug, Clone)]
pub struct Recorded {
    /// Where they were read from.
    pub path: PathBuf,
    pub preset: Preset,
    /// The settings as recorded: any subset of the settings table, by their names.
    pub settings: toml::Table,
}

/// Writes `settings`, started from `preset`, into `dir`; returns the file's name.
pub fn write(dir: &Path, preset: Preset, settings: &AoSettings) -> Result<&'static str> {
    write_json(
        &dir.join(FILE_NAME),
        &Record {
            preset: preset.name().to_string(),
            settings,
        },
    )?;
    Ok(FILE_NAME)
}

/// The settings recorded beside `camera` (a camera.json), or `None` when there is no
/// `ao-settings.json` there.
pub fn read_beside(camera: &Path) -> Result<Option<Recorded>> {
    let path = camera.with_file_name(FILE_NAME);
    if !path.exists() {
        return Ok(None);
    }
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let record: Record<toml::Table> = serde_json::from_str(&text)
        .map_err(|e| anyhow!("{} is not an {FILE_NAME}: {e}", path.display()))?;
    let preset = record
        .preset
        .parse()
        .map_err(|e: String| anyhow!("{}: {e}", path.display()))?;
    Ok(Some(Recorded {
        path,
        preset,
        settings: record.settings,
    }))
}
