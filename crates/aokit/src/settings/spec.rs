//! What a setting's declaration says ([`SettingSpec`]: key, kind, range, help) and what can be
//! done with it: check it, read and set it by key, suggest a key for a mistyped one. The
//! declarations themselves are in table.rs ([`SETTINGS`]).

use std::fmt;
use std::sync::OnceLock;

use super::*;

/// What values a setting takes: a GUI's widget for it (check box, slider, menu).
///
/// ```
/// use aokit::settings::{SettingKind, find_setting};
/// let slices = find_setting("gtao.slice_count").unwrap();
/// let SettingKind::Integer(range) = slices.kind else { panic!("gtao.slice_count counts") };
/// assert_eq!((range.min, range.max, range.step), (1, 64, 1));
/// assert!(matches!(find_setting("spatial.enabled").unwrap().kind, SettingKind::Bool));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SettingKind {
    /// `true` or `false`.
    Bool,
    /// Whole numbers in a range.
    Integer(IntegerRange),
    /// Real numbers in a range.
    Float(FloatRange),
    /// One of these names.
    Choice(&'static [&'static str]),
}

/// The whole numbers `min`, `min + step`, ... up to `max`.
///
/// ```
/// use aokit::settings::{SettingKind, find_setting};
/// // `msvo` samples come in mirrored pairs: even counts only.
/// let SettingKind::Integer(pairs) = find_setting("msvo.sample_count").unwrap().kind else {
///     unreachable!()
/// };
/// assert!(pairs.contains(18) && !pairs.contains(7) && !pairs.contains(66));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IntegerRange {
    /// The smallest value.
    pub min: u32,
    /// The largest value.
    pub max: u32,
    /// The spacing of the values from `min`: 1 for every integer, 2 for even ones.
    pub step: u32,
}

impl IntegerRange {
    /// Whether `value` is one of the range's values.
    ///
    /// ```
    /// use aokit::settings::IntegerRange;
    /// let tiles = IntegerRange { min: 64, max: 128, step: 64 };
    /// assert!(tiles.contains(128) && !tiles.contains(96));
    /// ```
    pub fn contains(&self, value: u32) -> bool {
        (self.min..=self.max).contains(&value) && (value - self.min).is_multiple_of(self.step)
    }

    /// The values as docs/settings.md shows them: `1..=64`, `even, 2..=64`, `64, 128`.
    fn text(&self) -> String {
        let Self { min, max, step } = *self;
        match step {
            1 => format!("{min}..={max}"),
            _ if max - min <= step => format!("{min}, {max}"),
            2 if min % 2 == 0 => format!("even, {min}..={max}"),
            _ => format!("multiples of {step} from {min}, {min}..={max}"),
        }
    }

    /// What an error says would be accepted.
    fn expected(&self) -> String {
        let Self { min, max, step } = *self;
        match step {
            1 => format!("an integer in {min}..={max}"),
            _ if max - min <= step => format!("{min} or {max}"),
            2 if min % 2 == 0 => format!("an even integer in {min}..={max}"),
            _ => format!("an integer in {min}..={max}, {min} plus a multiple of {step}"),
        }
    }
}

/// Real numbers from `min` up to `max`, each end included or not. Every value must be finite.
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::{Limit, SettingKind, find_setting};
/// let SettingKind::Float(range) = find_setting("temporal.blend").unwrap().kind else {
///     unreachable!()
/// };
/// // A weight in [0, 1): a slider from 0 that stops short of 1.
/// assert_eq!((range.min, range.min_inclusive), (0.0, true));
/// assert_eq!((range.max, range.max_inclusive), (Some(Limit::Value(1.0)), false));
/// let settings = AoSettings::default();
/// assert!(range.contains(0.8, &settings) && !range.contains(1.0, &settings));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatRange {
    /// The lower end.
    pub min: f32,
    /// Whether `min` itself is allowed.
    pub min_inclusive: bool,
    /// The upper end; none: any finite number.
    pub max: Option<Limit>,
    /// Whether the upper end itself is allowed.
    pub max_inclusive: bool,
    /// What the number counts, where its name does not say (`radians`).
    pub unit: Option<&'static str>,
}

/// The upper end of a [`FloatRange`].
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::{Limit, SettingKind, find_setting};
/// // The smallest screen radius may not pass the largest.
/// let SettingKind::Float(range) = find_setting("min_radius_px").unwrap().kind else {
///     unreachable!()
/// };
/// assert_eq!(range.max, Some(Limit::Setting { key: "max_radius_px", unless_zero: false }));
/// let settings = AoSettings { max_radius_px: 40.0, ..AoSettings::default() };
/// assert_eq!(range.max_value(&settings), Some(40.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Limit {
    /// A number.
    Value(f32),
    /// A number shown by a name (`pi/2`).
    Named(f32, &'static str),
    /// The value of another setting; where `unless_zero`, that setting's 0 means no limit.
    Setting {
        /// The other setting's key.
        key: &'static str,
        /// Whether a 0 there lifts the limit.
        unless_zero: bool,
    },
}

impl FloatRange {
    /// The upper end for `settings`: none where there is no limit.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// use aokit::settings::{SettingKind, find_setting};
    /// let SettingKind::Float(fade) = find_setting("distance_falloff").unwrap().kind else {
    ///     unreachable!()
    /// };
    /// // The fade ends at `max_distance`, whose 0 means no limit.
    /// let settings = AoSettings::default();
    /// assert_eq!(fade.max_value(&settings), None);
    /// assert_eq!(fade.max_value(&AoSettings { max_distance: 50.0, ..settings }), Some(50.0));
    /// ```
    pub fn max_value(&self, settings: &AoSettings) -> Option<f32> {
        match self.max? {
            Limit::Value(value) | Limit::Named(value, _) => Some(value),
            Limit::Setting { key, unless_zero } => {
                let spec = find_setting(key).expect("a limit names a declared setting");
                let SettingValue::Float(value) = spec.get(settings) else {
                    unreachable!("a limit names a float setting")
                };
                (!(unless_zero && value == 0.0)).then_some(value)
            }
        }
    }

    /// Whether `value` lies in the range, with `settings` giving a limit that is another
    /// setting.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// use aokit::settings::{SettingKind, find_setting};
    /// let SettingKind::Float(radius) = find_setting("radius").unwrap().kind else {
    ///     unreachable!()
    /// };
    /// let settings = AoSettings::default();
    /// assert!(radius.contains(0.5, &settings));
    /// assert!(!radius.contains(0.0, &settings) && !radius.contains(f32::INFINITY, &settings));
    /// ```
    pub fn contains(&self, value: f32, settings: &AoSettings) -> bool {
        let above = if self.min_inclusive {
            value >= self.min
        } else {
            value > self.min
        };
        let below = match self.max_value(settings) {
            None => true,
            Some(max) if self.max_inclusive => value <= max,
            Some(max) => value < max,
        };
        value.is_finite() && above && below
    }

    fn max_text(&self) -> Option<String> {
        Some(match self.max? {
            Limit::Value(value) => value.to_string(),
            Limit::Named(_, name) | Limit::Setting { key: name, .. } => name.to_string(),
        })
    }

    /// The range as docs/settings.md shows it: `> 0`, `(0, 4]`.
    fn text(&self) -> String {
        match self.max_text() {
            None => format!(
                "{} {}",
                if self.min_inclusive { ">=" } else { ">" },
                self.min
            ),
            Some(max) => format!(
                "{}{}, {max}{}",
                if self.min_inclusive { "[" } else { "(" },
                self.min,
                if self.max_inclusive { "]" } else { ")" },
            ),
        }
    }

    /// What an error says would be accepted.
    fn expected(&self) -> String {
        let range = match self.max {
            None => format!("a finite number {}", self.text()),
            Some(_) => format!("a number in {}", self.text()),
        };
        match self.unit {
            Some(unit) => format!("{range} ({unit})"),
            None => range,
        }
    }
}

impl SettingKind {
    /// The type as docs/settings.md names it: `bool`, `integer`, `float` or `string`.
    ///
    /// ```
    /// use aokit::settings::find_setting;
    /// assert_eq!(find_setting("method").unwrap().kind.type_name(), "string");
    /// assert_eq!(find_setting("radius").unwrap().kind.type_name(), "float");
    /// ```
    pub fn type_name(&self) -> &'static str {
        match self {
            SettingKind::Bool => "bool",
            SettingKind::Integer(_) => "integer",
            SettingKind::Float(_) => "float",
            SettingKind::Choice(_) => "string",
        }
    }

    /// The values it takes, as docs/settings.md and `aokit settings` show them: `1..=64`,
    /// `[0, 1]`, `` `full`, `half`, `quarter` ``; empty for a bool.
    ///
    /// ```
    /// use aokit::settings::find_setting;
    /// assert_eq!(find_setting("radius_multiplier").unwrap().kind.range_text(), "(0, 4]");
    /// assert_eq!(find_setting("noise.blue_size").unwrap().kind.range_text(), "64, 128");
    /// assert_eq!(
    ///     find_setting("normals.space").unwrap().kind.range_text(),
    ///     "`view`, `world`"
    /// );
    /// ```
    pub fn range_text(&self) -> String {
        match self {
            SettingKind::Bool => String::new(),
            SettingKind::Integer(range) => range.text(),
            SettingKind::Float(range) => range.text(),
            SettingKind::Choice(names) => names
                .iter()
                .map(|name| format!("`{name}`"))
                .collect::<Vec<_>>()
                .join(", "),
        }
    }

    fn expected(&self) -> String {
        match self {
            SettingKind::Bool => "true or false".into(),
            SettingKind::Integer(range) => range.expected(),
            SettingKind::Float(range) => range.expected(),
            SettingKind::Choice(_) => format!("one of {}", self.range_text()),
        }
    }
}

/// A setting's value, whatever its type.
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::SettingValue;
/// let mut settings = AoSettings::default();
/// settings.set("spatial.enabled", SettingValue::Bool(false))?;
/// settings.set("spatial.kind", SettingValue::Choice("guided"))?;
/// assert!(!settings.spatial.enabled);
/// assert_eq!(settings.get("gtao.slice_count")?, SettingValue::Integer(3));
/// assert_eq!(settings.get("method")?.to_string(), "gtao");
/// # Ok::<(), aokit::settings::SetError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SettingValue {
    /// Of a [`SettingKind::Bool`].
    Bool(bool),
    /// Of a [`SettingKind::Integer`].
    Integer(u32),
    /// Of a [`SettingKind::Float`]; an integer is taken for one too.
    Float(f32),
    /// Of a [`SettingKind::Choice`]: one of its names.
    Choice(&'static str),
}

impl fmt::Display for SettingValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingValue::Bool(value) => value.fmt(f),
            SettingValue::Integer(value) => value.fmt(f),
            SettingValue::Float(value) => value.fmt(f),
            SettingValue::Choice(name) => f.write_str(name),
        }
    }
}

/// A Rust type a setting is stored as, and how it converts to and from [`SettingValue`].
pub(crate) trait Field: Sized {
    /// The names of an enum's values; empty for the others.
    const NAMES: &'static [&'static str] = &[];
    fn to_value(self) -> SettingValue;
    fn from_value(value: SettingValue) -> Result<Self, String>;
}

impl Field for bool {
    fn to_value(self) -> SettingValue {
        SettingValue::Bool(self)
    }
    fn from_value(value: SettingValue) -> Result<Self, String> {
        match value {
            SettingValue::Bool(value) => Ok(value),
            other => Err(format!("expected true or false, not {other}")),
        }
    }
}

impl Field for u32 {
    fn to_value(self) -> SettingValue {
        SettingValue::Integer(self)
    }
    fn from_value(value: SettingValue) -> Result<Self, String> {
        match value {
            SettingValue::Integer(value) => Ok(value),
            other => Err(format!("expected an integer, not {other}")),
        }
    }
}

impl Field for f32 {
    fn to_value(self) -> SettingValue {
        SettingValue::Float(self)
    }
    fn from_value(value: SettingValue) -> Result<Self, String> {
        match value {
            SettingValue::Float(value) => Ok(value),
            SettingValue::Integer(value) => Ok(value as f32),
            other => Err(format!("expected a number, not {other}")),
        }
    }
}

/// A check between settings that no range states (a method that cannot run a variant).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rule {
    pub(crate) holds: fn(&AoSettings) -> bool,
    /// The value in the error: the setting's and the other one's.
    pub(crate) value: fn(&AoSettings) -> String,
    pub(crate) expected: &'static str,
}

/// One setting, declared once: its key, the values it takes and its help. Everything that
/// lists, checks or documents settings reads these ([`SETTINGS`]).
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::{SETTINGS, SettingKind, SettingValue};
/// // A settings panel: one widget per setting, labelled by key, with its help as a tooltip.
/// let settings = AoSettings::default();
/// for spec in SETTINGS {
///     let widget = match spec.kind {
///         SettingKind::Bool => "check box",
///         SettingKind::Integer(_) | SettingKind::Float(_) => "slider",
///         SettingKind::Choice(_) => "menu",
///     };
///     println!("{} ({widget}) = {}: {}", spec.name, spec.get(&settings), spec.help);
/// }
/// // Every setting has help for its tooltip; the radius is a slider showing its default.
/// assert!(SETTINGS.iter().all(|spec| !spec.help.is_empty()));
/// let radius = SETTINGS.iter().find(|spec| spec.name == "radius").unwrap();
/// assert!(matches!(radius.kind, SettingKind::Float(_)));
/// assert_eq!(radius.get(&settings), SettingValue::Float(settings.radius));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct SettingSpec {
    /// The dotted key, as `--set` and settings files name it: `radius`, `gtao.slice_count`.
    pub name: &'static str,
    /// What values it takes.
    pub kind: SettingKind,
    /// What it does, in Markdown (docs/settings.md's "meaning").
    pub help: &'static str,
    /// Where the default needs a word more than its value: shown after it in docs/settings.md.
    pub default_note: Option<&'static str>,
    pub(crate) get: fn(&AoSettings) -> SettingValue,
    pub(crate) set: fn(&mut AoSettings, SettingValue) -> Result<(), String>,
    pub(crate) rule: Option<Rule>,
}

impl SettingSpec {
    /// The setting's value in `settings`.
    ///
    /// ```
    /// use aokit::settings::{SettingValue, find_setting};
    /// use aokit::{AoSettings, Method, Preset};
    /// let settings = AoSettings::preset(Method::Gtao, Preset::Low);
    /// let steps = find_setting("gtao.steps_per_side").unwrap();
    /// assert_eq!(steps.get(&settings), SettingValue::Integer(settings.gtao.steps_per_side));
    /// ```
    pub fn get(&self, settings: &AoSettings) -> SettingValue {
        (self.get)(settings)
    }

    /// The section of a settings file the setting lives in, its key's prefix (`gtao` for
    /// `gtao.slice_count`); `None` for a key at the top level.
    ///
    /// ```
    /// use aokit::settings::find_setting;
    /// assert_eq!(find_setting("gtao.slice_count").unwrap().section(), Some("gtao"));
    /// assert_eq!(find_setting("radius").unwrap().section(), None);
    /// ```
    pub fn section(&self) -> Option<&'static str> {
        self.name.split_once('.').map(|(section, _)| section)
    }

    /// The setting's value in [`AoSettings::default`].
    ///
    /// ```
    /// use aokit::settings::{SettingValue, find_setting};
    /// let blend = find_setting("temporal.blend").unwrap();
    /// assert_eq!(blend.default_value(), SettingValue::Float(0.8));
    /// ```
    pub fn default_value(&self) -> SettingValue {
        self.get(&AoSettings::default())
    }

    /// Sets the setting in `settings` to `value`, which must be of its kind and pass its
    /// checks (the range, and any rule tying it to another setting) as
    /// [`AoSettings::validate`] makes them, with the same error. On an error `settings` is left
    /// as it was. Other settings are not checked: call [`AoSettings::validate`] after a batch.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// use aokit::settings::{SetError, SettingValue, find_setting};
    /// let mut settings = AoSettings::default();
    /// let radius = find_setting("spatial.radius").unwrap();
    /// radius.set(&mut settings, SettingValue::Integer(5))?;
    /// assert_eq!(settings.spatial.radius, 5);
    /// let err = radius.set(&mut settings, SettingValue::Integer(9)).unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "setting `spatial.radius` = 9 is out of range: an integer in 1..=8"
    /// );
    /// let wrong_type = radius.set(&mut settings, SettingValue::Bool(true));
    /// assert!(matches!(wrong_type, Err(SetError::Invalid { .. })));
    /// assert_eq!(settings.spatial.radius, 5);
    /// # Ok::<(), SetError>(())
    /// ```
    pub fn set(&self, settings: &mut AoSettings, value: SettingValue) -> Result<(), SetError> {
        let mut next = *settings;
        (self.set)(&mut next, value).map_err(|reason| SetError::Invalid {
            key: self.name,
            reason,
        })?;
        self.check(&next)?;
        *settings = next;
        Ok(())
    }

    /// Reads `text` as a value of this setting (`true`, `4`, `0.25`, `gtao`), as a text field
    /// or a command line gives it.
    ///
    /// ```
    /// use aokit::settings::{SettingValue, find_setting};
    /// let kind = find_setting("noise.kind").unwrap();
    /// assert_eq!(kind.parse("blue")?, SettingValue::Choice("blue"));
    /// let power = find_setting("power").unwrap();
    /// assert_eq!(power.parse("2")?, SettingValue::Float(2.0));
    /// assert!(find_setting("bent_normals").unwrap().parse("yes").is_err());
    /// # Ok::<(), aokit::settings::SetError>(())
    /// ```
    pub fn parse(&self, text: &str) -> Result<SettingValue, SetError> {
        let text = text.trim();
        let invalid = || SetError::Invalid {
            key: self.name,
            reason: format!("expected {}, not `{text}`", self.kind.expected()),
        };
        match self.kind {
            SettingKind::Bool => text.parse().map(SettingValue::Bool).map_err(|_| invalid()),
            SettingKind::Integer(_) => text
                .parse()
                .map(SettingValue::Integer)
                .map_err(|_| invalid()),
            SettingKind::Float(_) => text.parse().map(SettingValue::Float).map_err(|_| invalid()),
            SettingKind::Choice(names) => names
                .iter()
                .find(|&&name| name == text)
                .map(|&name| SettingValue::Choice(name))
                .ok_or_else(invalid),
        }
    }

    /// Checks the setting in `settings` as [`AoSettings::validate`] does: its range, and any
    /// rule tying it to another setting.
    ///
    /// ```
    /// use aokit::settings::find_setting;
    /// use aokit::{AoSettings, Method, Preset};
    /// let mut settings = AoSettings::preset(Method::Ssao, Preset::High);
    /// settings.bent_normals = true;
    /// // Only the slice methods compute bent normals.
    /// let err = find_setting("bent_normals").unwrap().check(&settings).unwrap_err();
    /// assert_eq!(err.value, "true with method ssao");
    /// ```
    pub fn check(&self, settings: &AoSettings) -> Result<(), SettingsError> {
        let value = self.get(settings);
        let out_of_range = |value: String| SettingsError {
            field: self.name,
            value,
            expected: self.expected(),
        };
        match (self.kind, value) {
            (SettingKind::Integer(range), SettingValue::Integer(v)) if !range.contains(v) => {
                return Err(out_of_range(v.to_string()));
            }
            (SettingKind::Float(range), SettingValue::Float(v)) if !range.contains(v, settings) => {
                // Name the other setting's value where it is the limit that failed.
                let limit = match (range.max, range.max_value(settings)) {
                    (Some(Limit::Setting { key, .. }), Some(max)) if v.is_finite() && v > max => {
                        format!(" with {key} = {max}")
                    }
                    _ => String::new(),
                };
                return Err(out_of_range(format!("{v}{limit}")));
            }
            _ => {}
        }
        match self.rule {
            Some(rule) if !(rule.holds)(settings) => Err(SettingsError {
                field: self.name,
                value: (rule.value)(settings),
                expected: rule.expected,
            }),
            _ => Ok(()),
        }
    }

    /// What an error about this setting says would be accepted, made from its kind once.
    fn expected(&self) -> &'static str {
        static EXPECTED: OnceLock<Vec<String>> = OnceLock::new();
        let all = EXPECTED.get_or_init(|| SETTINGS.iter().map(|s| s.kind.expected()).collect());
        let index = SETTINGS
            .iter()
            .position(|s| s.name == self.name)
            .expect("every SettingSpec is one of SETTINGS");
        &all[index]
    }
}

/// The setting called `key` (`gtao.slice_count`), if there is one.
///
/// ```
/// use aokit::settings::find_setting;
/// assert_eq!(find_setting("spatial.sigma").unwrap().name, "spatial.sigma");
/// assert!(find_setting("spatial").is_none());
/// ```
pub fn find_setting(key: &str) -> Option<&'static SettingSpec> {
    SETTINGS.iter().find(|spec| spec.name == key)
}

/// The declared key closest to a mistyped `key`, by edit distance, where one is close enough
/// to be what was meant.
///
/// ```
/// use aokit::settings::suggest_setting;
/// assert_eq!(suggest_setting("gtao.slices"), Some("gtao.slice_count"));
/// assert_eq!(suggest_setting("spatial.sigam"), Some("spatial.sigma"));
/// assert_eq!(suggest_setting("gtao.steps"), Some("gtao.steps_per_side"));
/// assert_eq!(suggest_setting("frobnicate"), None);
/// ```
pub fn suggest_setting(key: &str) -> Option<&'static str> {
    let key = key.to_ascii_lowercase();
    // A key cut short (`gtao.steps`) is completed; otherwise the nearest within half
    // the length.
    let completion = SETTINGS
        .iter()
        .map(|spec| spec.name)
        .filter(|name| key.len() > 2 && name.starts_with(key.as_str()))
        .min_by_key(|name| name.len());
    completion.or_else(|| {
        SETTINGS
            .iter()
            .map(|spec| (edit_distance(&key, spec.name), spec.name))
            .filter(|&(distance, name)| 2 * distance <= key.len().max(name.len()))
            // Typos come late more often than early: a longer common start counts for it.
            .min_by_key(|&(distance, name)| {
                let start = key
                    .bytes()
                    .zip(name.bytes())
                    .take_while(|(a, b)| a == b)
                    .count();
                2 * distance as isize - start as isize
            })
            .map(|(_, name)| name)
    })
}

/// Levenshtein distance: the fewest insertions, deletions and substitutions of characters
/// that turn `a` into `b`.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// An error setting a setting by key ([`AoSettings::set`], [`SettingSpec::set`]).
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::{SetError, SettingValue};
/// let mut settings = AoSettings::default();
/// let err = settings.set("gtao.slices", SettingValue::Integer(4)).unwrap_err();
/// assert_eq!(
///     err,
///     SetError::UnknownKey { key: "gtao.slices".into(), suggestion: Some("gtao.slice_count") }
/// );
/// assert_eq!(
///     err.to_string(),
///     "unknown setting `gtao.slices`: did you mean `gtao.slice_count`?"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SetError {
    /// No setting has this key.
    #[error(
        "unknown setting `{key}`{}",
        .suggestion.map(|s| format!(": did you mean `{s}`?")).unwrap_or_default()
    )]
    UnknownKey {
        /// The key given.
        key: String,
        /// The declared key closest to it, where one is close ([`suggest_setting`]).
        suggestion: Option<&'static str>,
    },
    /// A value of another type, or a name the setting does not offer.
    #[error("invalid setting `{key}`: {reason}")]
    Invalid {
        /// The setting's key.
        key: &'static str,
        /// What was wrong with the value.
        reason: String,
    },
    /// A value out of the setting's range, or one another setting rules out.
    #[error(transparent)]
    OutOfRange(#[from] SettingsError),
}

impl AoSettings {
    /// The value of the setting called `key` (`gtao.slice_count`).
    ///
    /// ```
    /// use aokit::AoSettings;
    /// use aokit::settings::SettingValue;
    /// let settings = AoSettings::default();
    /// assert_eq!(settings.get("spatial.enabled")?, SettingValue::Bool(true));
    /// assert!(settings.get("spatial.enable").is_err());
    /// # Ok::<(), aokit::settings::SetError>(())
    /// ```
    pub fn get(&self, key: &str) -> Result<SettingValue, SetError> {
        Ok(setting_by_key(key)?.get(self))
    }

    /// Sets the setting called `key` (`spatial.enabled`) to `value`, checked as
    /// [`SettingSpec::set`] checks it; an unknown key is answered with the closest declared
    /// one.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// use aokit::settings::SettingValue;
    /// // What a Python binding does with `{"spatial.kind": "bilateral", "spatial.radius": 4}`.
    /// let mut settings = AoSettings::default();
    /// for (key, value) in [
    ///     ("spatial.kind", SettingValue::Choice("bilateral")),
    ///     ("spatial.radius", SettingValue::Integer(4)),
    /// ] {
    ///     settings.set(key, value)?;
    /// }
    /// settings.validate()?;
    /// assert_eq!((settings.spatial.kind.name(), settings.spatial.radius), ("bilateral", 4));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn set(&mut self, key: &str, value: SettingValue) -> Result<(), SetError> {
        setting_by_key(key)?.set(self, value)
    }
}

fn setting_by_key(key: &str) -> Result<&'static SettingSpec, SetError> {
    find_setting(key).ok_or_else(|| SetError::UnknownKey {
        key: key.to_string(),
        suggestion: suggest_setting(key),
    })
}
