//! Flags that build an [`AoSettings`]: method, preset, radius, a TOML file and `--set` paths.

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow, bail};
use aokit::settings::SettingValue;
use aokit::{AoSettings, Method, Preset, settings};
use clap::Args;
use serde::Deserialize;

use crate::recorded::Recorded;

#[derive(Args, Debug, Clone)]
pub struct SettingsArgs {
    /// AO method.
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(Method::ALL.map(Method::name)))]
    pub method: Option<String>,
    /// Quality preset.
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(Preset::ALL.map(Preset::name)))]
    pub preset: Option<String>,
    /// AO radius in world units (default: the scene's suggested radius, else 1).
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f32>,
    #[command(flatten)]
    pub overrides: OverrideArgs,
}

/// A settings file and `--set` paths, laid over settings built elsewhere.
#[derive(Args, Debug, Clone, Default)]
pub struct OverrideArgs {
    /// TOML file with any subset of the settings; applied after the preset.
    #[arg(long, value_name = "FILE.toml")]
    pub settings: Option<PathBuf>,
    /// Set any setting by its dotted path, e.g. `--set gtao.slice_count=4`; applied last
    /// (`aokit settings` lists the keys with their ranges).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
}

impl SettingsArgs {
    /// Preset, then the scene's radius, then the file, then `--radius`, then each `--set`.
    pub fn resolve(&self, suggested_radius: Option<f32>) -> Result<AoSettings> {
        let method: Method = parse_or_default(self.method.as_deref())?;
        let preset: Preset = parse_or_default(self.preset.as_deref())?;
        self.overrides
            .apply_to_preset(method, preset, suggested_radius, self.radius)
    }

    /// The preset `--preset` names, else the default one.
    pub fn preset(&self) -> Result<Preset> {
        parse_or_default(self.preset.as_deref())
    }

    /// [`SettingsArgs::resolve`] over settings recorded with the passes (`aokit ao`): without
    /// `--method` and `--preset` the recorded settings are the base, as they ran; with either,
    /// that method at that preset (the other one as recorded), the recorded radius standing in
    /// for the scene's. Then the file, `--radius` and each `--set`, as always.
    pub fn resolve_recorded(&self, recorded: &Recorded) -> Result<AoSettings> {
        let in_file = || format!("in {}", recorded.path.display());
        // Laid over the defaults to learn the method, then over the method's recorded preset,
        // which fills any setting the file lacks (one written by another version).
        let over = |base: &AoSettings| -> Result<AoSettings> {
            let mut table = to_table(base)?;
            merge(&mut table, recorded.settings.clone(), "")?;
            let settings =
                AoSettings::deserialize(toml::Value::Table(table)).map_err(invalid_setting)?;
            settings.validate()?;
            Ok(settings)
        };
        let method = over(&AoSettings::default()).with_context(in_file)?.method;
        let base = over(&AoSettings::preset(method, recorded.preset)).with_context(in_file)?;
        if self.method.is_none() && self.preset.is_none() {
            return self.overrides.apply(&base, self.radius);
        }
        let method = match &self.method {
            Some(name) => name.parse().map_err(|e: String| anyhow!(e))?,
            None => base.method,
        };
        let preset = match &self.preset {
            Some(name) => name.parse().map_err(|e: String| anyhow!(e))?,
            None => recorded.preset,
        };
        self.overrides
            .apply_to_preset(method, preset, Some(base.radius), self.radius)
    }

    /// [`SettingsArgs::resolve`] for frames that follow each other (`render --frames N`, the
    /// viewer): the temporal filter is on under the file and `--set`, which can still turn it
    /// off.
    pub fn resolve_for_sequence(&self, suggested_radius: Option<f32>) -> Result<AoSettings> {
        let method: Method = parse_or_default(self.method.as_deref())?;
        let preset: Preset = parse_or_default(self.preset.as_deref())?;
        self.overrides
            .apply_to_sequence_preset(method, preset, suggested_radius, self.radius)
    }
}

impl OverrideArgs {
    /// `method` at `preset` with `base_radius` when given, then [`OverrideArgs::apply`] with
    /// `radius`. Where the overrides turn `vbao.back_faces` on, they are laid over VBAO's
    /// presets tuned with back faces instead (`AoSettings::preset_with_back_faces`), so that
    /// the preset still names tuned values.
    pub fn apply_to_preset(
        &self,
        method: Method,
        preset: Preset,
        base_radius: Option<f32>,
        radius: Option<f32>,
    ) -> Result<AoSettings> {
        self.apply_to_base(method, preset, base_radius, radius, |settings| settings)
    }

    /// [`OverrideArgs::apply_to_preset`] for frames that follow each other (`render --frames
    /// N`, the viewer's A and B): the temporal filter on under the overrides, which can still
    /// turn it off.
    pub fn apply_to_sequence_preset(
        &self,
        method: Method,
        preset: Preset,
        base_radius: Option<f32>,
        radius: Option<f32>,
    ) -> Result<AoSettings> {
        self.apply_to_base(method, preset, base_radius, radius, |mut settings| {
            settings.temporal.enabled = true;
            settings
        })
    }

    /// [`OverrideArgs::apply_to_preset`] with `adjust` applied to the preset before the
    /// overrides, so that they still win over what it changes.
    fn apply_to_base(
        &self,
        method: Method,
        preset: Preset,
        base_radius: Option<f32>,
        radius: Option<f32>,
        adjust: impl Fn(AoSettings) -> AoSettings,
    ) -> Result<AoSettings> {
        let with_radius = |settings: AoSettings| {
            adjust(AoSettings {
                radius: base_radius.unwrap_or(settings.radius),
                ..settings
            })
        };
        let settings = self.apply(&with_radius(AoSettings::preset(method, preset)), radius)?;
        if settings.method == Method::Vbao && settings.vbao.back_faces {
            let measured = AoSettings::preset_with_back_faces(Method::Vbao, preset);
            return self.apply(&with_radius(measured), radius);
        }
        Ok(settings)
    }

    /// `base` with the file, then `radius` when given, then each `--set`, checked.
    pub fn apply(&self, base: &AoSettings, radius: Option<f32>) -> Result<AoSettings> {
        let mut table = to_table(base)?;
        if let Some(path) = &self.settings {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read settings file {}", path.display()))?;
            let patch: toml::Table = toml::from_str(&text)
                .with_context(|| format!("settings file {} is not valid TOML", path.display()))?;
            merge(&mut table, patch, "")
                .with_context(|| format!("in settings file {}", path.display()))?;
            // A bad value shows only when the table deserialises and validates: check the file's
            // values here, where the message can name the file.
            AoSettings::deserialize(toml::Value::Table(table.clone()))
                .map_err(invalid_setting)
                .and_then(|settings| Ok(settings.validate()?))
                .with_context(|| format!("in settings file {}", path.display()))?;
        }
        if let Some(radius) = radius {
            table.insert("radius".into(), toml::Value::Float(radius.into()));
        }
        for assignment in &self.set {
            set_path(&mut table, assignment)?;
        }
        let settings =
            AoSettings::deserialize(toml::Value::Table(table)).map_err(invalid_setting)?;
        settings.validate()?;
        Ok(settings)
    }
}

/// A settings table that does not deserialise, named by the setting's path: toml's error tells
/// the path only in its text, on a line `in `path``.
fn invalid_setting(error: toml::de::Error) -> anyhow::Error {
    let text = error.to_string();
    let path = text
        .lines()
        .find_map(|line| line.strip_prefix("in `")?.strip_suffix('`'));
    match path {
        Some(path) => {
            // The declaration's type and range, as `aokit settings` shows them.
            let takes = settings::find_setting(path)
                .map(|spec| {
                    let range = spec.kind.range_text();
                    let sep = if range.is_empty() { "" } else { " " };
                    format!(" (takes {}{sep}{range})", spec.kind.type_name())
                })
                .unwrap_or_default();
            anyhow!("invalid setting `{path}`: {}{takes}", error.message())
        }
        None => anyhow!("invalid settings: {}", error.message()),
    }
}

fn parse_or_default<T: std::str::FromStr<Err = String> + Default>(name: Option<&str>) -> Result<T> {
    name.map_or_else(
        || Ok(T::default()),
        |n| n.parse().map_err(|e: String| anyhow!(e)),
    )
}

fn to_table(settings: &AoSettings) -> Result<toml::Table> {
    match toml::Value::try_from(settings)? {
        toml::Value::Table(t) => Ok(t),
        _ => bail!("settings did not serialise to a table"),
    }
}

/// An unknown key, answered with the declared key nearest to it, or else with all of them.
fn unknown_setting(path: &str) -> anyhow::Error {
    match settings::suggest_setting(path) {
        Some(near) => anyhow!(
            "unknown setting `{path}`: did you mean `{near}`? (`aokit settings` lists every key)"
        ),
        None => anyhow!("unknown setting `{path}` (known: {})", known_settings()),
    }
}

/// Every key `--set` and settings files accept: the declarations' (`aokit::settings::SETTINGS`).
fn known_settings() -> String {
    let names: Vec<&str> = settings::SETTINGS.iter().map(|spec| spec.name).collect();
    names.join(", ")
}

/// Whether `path` names a group of settings (`gtao`) rather than one.
fn is_group(path: &str) -> bool {
    let prefix = format!("{path}.");
    settings::SETTINGS
        .iter()
        .any(|spec| spec.name.starts_with(&prefix))
}

/// The first full path under `path` in `value`: a table's first leaf, so that an unknown group
/// in a file (`[gtoa]`) is named by a key the suggestion can match (`gtoa.slice_count`).
fn first_leaf(path: String, value: &toml::Value) -> String {
    match value {
        toml::Value::Table(table) => match table.iter().next() {
            Some((key, inner)) => first_leaf(format!("{path}.{key}"), inner),
            None => path,
        },
        _ => path,
    }
}

/// Overlays `patch` on `base`, refusing keys that are not declared settings.
fn merge(base: &mut toml::Table, patch: toml::Table, prefix: &str) -> Result<()> {
    for (key, value) in patch {
        let path = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        let declared = settings::find_setting(&path).is_some() || is_group(&path);
        match (base.get_mut(&key), value) {
            (Some(toml::Value::Table(inner)), toml::Value::Table(patch)) if declared => {
                merge(inner, patch, &path)?
            }
            (Some(slot), value) if declared => *slot = value,
            (_, value) => return Err(unknown_setting(&first_leaf(path, &value))),
        }
    }
    Ok(())
}

/// Applies one `KEY=VALUE`. VALUE is read by the setting's declaration
/// ([`SettingSpec::parse`](settings::SettingSpec::parse), as the viewer's fields and Python's
/// `settings` read it, with the same errors); a TOML string's quotes are dropped first, so
/// `--set noise.kind=blue` and `--set 'noise.kind="blue"'` are one.
fn set_path(table: &mut toml::Table, assignment: &str) -> Result<()> {
    let (path, raw) = assignment
        .split_once('=')
        .ok_or_else(|| anyhow!("--set `{assignment}` is not KEY=VALUE"))?;
    let path = path.trim();
    let raw = raw.trim();
    let Some(spec) = settings::find_setting(path) else {
        if is_group(path) {
            let fields: Vec<&str> = settings::SETTINGS
                .iter()
                .map(|spec| spec.name)
                .filter(|name| name.starts_with(&format!("{path}.")))
                .collect();
            bail!(
                "`{path}` is a group of settings; set one of its fields ({})",
                fields.join(", ")
            );
        }
        return Err(unknown_setting(path));
    };
    let text = match toml::from_str::<toml::Table>(&format!("v = {raw}")) {
        Ok(mut table) => match table.remove("v") {
            Some(toml::Value::String(text)) => text,
            _ => raw.to_string(),
        },
        Err(_) => raw.to_string(),
    };
    let value = match spec.parse(&text)? {
        SettingValue::Bool(flag) => toml::Value::Boolean(flag),
        SettingValue::Integer(integer) => toml::Value::Integer(integer.into()),
        SettingValue::Float(number) => toml::Value::Float(number.into()),
        SettingValue::Choice(name) => toml::Value::String(name.to_string()),
    };
    let mut keys = path.split('.').peekable();
    let mut current = table;
    while let Some(key) = keys.next() {
        let slot = current
            .get_mut(key)
            .ok_or_else(|| anyhow!("setting `{path}` is declared but not serialised"))?;
        if keys.peek().is_none() {
            *slot = value;
            return Ok(());
        }
        current = slot
            .as_table_mut()
            .ok_or_else(|| anyhow!("setting `{path}` is declared but not serialised"))?;
    }
    Err(unknown_setting(path))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(set: &[&str]) -> SettingsArgs {
        SettingsArgs {
            method: None,
            preset: None,
            radius: None,
            overrides: OverrideArgs {
                settings: None,
                set: set.iter().map(|s| s.to_string()).collect(),
            },
        }
    }

    #[test]
    fn set_reaches_nested_fields_and_coerces_numbers() {
        let s = args(&[
            "gtao.slice_count=5",
            "radius=2",
            "gtao.normalize_slices=false",
            "method=gtao",
        ])
        .resolve(None)
        .unwrap();
        assert_eq!(s.gtao.slice_count, 5);
        assert_eq!(s.radius, 2.0);
        assert!(!s.gtao.normalize_slices);
    }

    #[test]
    fn unknown_paths_and_bad_values_name_the_problem() {
        let err = args(&["gtao.slices=2"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("gtao.slices") && err.contains("gtao.slice_count"),
            "{err}"
        );
        let err = args(&["gtao.slice_count=2.5"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(err.contains("invalid setting `gtao.slice_count`"), "{err}");
        let err = args(&["noise.kind=foo"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("`noise.kind`") && err.contains("`ign`"),
            "{err}"
        );
        let err = args(&["radius=-1"]).resolve(None).unwrap_err().to_string();
        assert!(err.contains("radius"), "{err}");
        let err = args(&["gtao=1"]).resolve(None).unwrap_err().to_string();
        assert!(err.contains("group"), "{err}");
    }

    /// Every leaf of the serialised settings, by its dotted path.
    fn leaf_paths(table: &toml::Table, prefix: &str, out: &mut Vec<String>) {
        for (key, value) in table {
            let path = if prefix.is_empty() {
                key.clone()
            } else {
                format!("{prefix}.{key}")
            };
            match value {
                toml::Value::Table(inner) => leaf_paths(inner, &path, out),
                _ => out.push(path),
            }
        }
    }

    #[test]
    fn every_serialised_setting_is_declared_and_every_declaration_is_serialised() {
        let mut paths = Vec::new();
        leaf_paths(&to_table(&AoSettings::default()).unwrap(), "", &mut paths);
        let mut declared: Vec<String> = settings::SETTINGS
            .iter()
            .map(|spec| spec.name.to_string())
            .collect();
        paths.sort();
        declared.sort();
        assert_eq!(paths, declared);
    }

    #[test]
    fn mistyped_keys_get_a_suggestion_and_groups_list_their_fields() {
        let err = args(&["spatial.sigam=2"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(err.contains("did you mean `spatial.sigma`?"), "{err}");
        let err = args(&["frobnicate=2"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("known:") && err.contains("gtao.slice_count"),
            "{err}"
        );
        let err = args(&["msvo=2"]).resolve(None).unwrap_err().to_string();
        assert!(err.contains("msvo.levels"), "{err}");
        let err = args(&["gtao.slice_count=2.5"])
            .resolve(None)
            .unwrap_err()
            .to_string();
        assert!(err.contains("an integer in 1..=64"), "{err}");
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("s.toml");
        std::fs::write(&file, "[gtoa]\nslice_count = 7\n").unwrap();
        let mut a = args(&[]);
        a.overrides.settings = Some(file);
        let err = format!("{:#}", a.resolve(None).unwrap_err());
        assert!(err.contains("did you mean `gtao.slice_count`?"), "{err}");
    }

    #[test]
    fn turning_back_faces_on_takes_their_tuned_preset_under_the_overrides() {
        let mut a = args(&["vbao.back_faces=true"]);
        a.method = Some("vbao".into());
        a.preset = Some("medium".into());
        let measured = AoSettings::preset_with_back_faces(Method::Vbao, Preset::Medium);
        assert_eq!(a.resolve(None).unwrap(), measured);
        // Overrides still win over the preset, and the scene's radius still applies.
        a.overrides.set.push("vbao.thickness=0.7".into());
        let s = a.resolve(Some(0.5)).unwrap();
        assert_eq!((s.vbao.thickness, s.radius), (0.7, 0.5));
        assert_eq!(s.power, measured.power);
        // Without back faces the plain preset stands.
        a.overrides.set = vec![];
        assert_eq!(
            a.resolve(None).unwrap(),
            AoSettings::preset(Method::Vbao, Preset::Medium)
        );
    }

    #[test]
    fn sequences_start_with_the_temporal_filter_on_unless_the_overrides_turn_it_off() {
        let single = args(&[]).resolve(None).unwrap();
        assert!(single.spatial.enabled && !single.temporal.enabled);
        let sequence = args(&[]).resolve_for_sequence(None).unwrap();
        assert_eq!(
            sequence,
            AoSettings {
                temporal: aokit::TemporalSettings {
                    enabled: true,
                    ..single.temporal
                },
                ..single
            }
        );
        let raw = args(&["temporal.enabled=false", "spatial.enabled=false"])
            .resolve_for_sequence(None)
            .unwrap();
        assert!(!raw.temporal.enabled && !raw.spatial.enabled);
        // Back faces take their own presets, still with the filter on.
        let mut a = args(&["vbao.back_faces=true"]);
        a.method = Some("vbao".into());
        assert!(a.resolve_for_sequence(None).unwrap().temporal.enabled);
    }

    #[test]
    fn precedence_is_preset_scene_file_flag_set() {
        let dir = std::env::temp_dir().join(format!("aokit-settings-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("s.toml");
        std::fs::write(&file, "radius = 3.0\n[gtao]\nsteps_per_side = 7\n").unwrap();
        let mut a = args(&[]);
        a.preset = Some("low".into());
        a.overrides.settings = Some(file.clone());
        let s = a.resolve(Some(0.5)).unwrap();
        assert_eq!(
            (s.radius, s.gtao.steps_per_side, s.gtao.slice_count),
            (3.0, 7, aokit::GtaoSettings::preset(Preset::Low).slice_count)
        );
        a.radius = Some(4.0);
        assert_eq!(a.resolve(Some(0.5)).unwrap().radius, 4.0);
        a.overrides.set = vec!["radius=5".into()];
        assert_eq!(a.resolve(Some(0.5)).unwrap().radius, 5.0);
        std::fs::write(&file, "[gtao]\nslicecount = 7\n").unwrap();
        let err = format!("{:#}", a.resolve(None).unwrap_err());
        assert!(err.contains("gtao.slicecount"), "{err}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
