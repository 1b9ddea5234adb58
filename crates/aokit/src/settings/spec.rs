//! The declaration of every setting, once: its dotted key (as `--set` and settings files name
//! it), what values it takes, and its help. [`AoSettings::validate`], the keys `--set` accepts,
//! `aokit settings` and docs/settings.md are all derived from [`SETTINGS`].

use std::f32::consts::FRAC_PI_2;
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
            SettingKind::Choice(names) => format!("one of {}", names.join(", ")),
        }
    }
}

/// A setting's value, whatever its type.
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::SettingValue;
/// let mut settings = AoSettings::default();
/// settings.set("spatial.enabled", SettingValue::Bool(true))?;
/// settings.set("spatial.kind", SettingValue::Choice("guided"))?;
/// assert!(settings.spatial.enabled);
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
struct Rule {
    holds: fn(&AoSettings) -> bool,
    /// The value in the error: the setting's and the other one's.
    value: fn(&AoSettings) -> String,
    expected: &'static str,
}

/// One setting, declared once: its key, the values it takes and its help. Everything that
/// lists, checks or documents settings reads these ([`SETTINGS`]).
///
/// ```
/// use aokit::AoSettings;
/// use aokit::settings::{SETTINGS, SettingKind};
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
    get: fn(&AoSettings) -> SettingValue,
    set: fn(&mut AoSettings, SettingValue) -> Result<(), String>,
    rule: Option<Rule>,
}

impl SettingSpec {
    /// The setting's value in `settings`.
    ///
    /// ```
    /// use aokit::settings::{SettingValue, find_setting};
    /// use aokit::{AoSettings, Method, Preset};
    /// let settings = AoSettings::preset(Method::Gtao, Preset::Low);
    /// let steps = find_setting("gtao.steps_per_side").unwrap();
    /// assert_eq!(steps.get(&settings), SettingValue::Integer(1));
    /// ```
    pub fn get(&self, settings: &AoSettings) -> SettingValue {
        (self.get)(settings)
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
    /// assert!(matches!(radius.set(&mut settings, SettingValue::Bool(true)), Err(SetError::Invalid { .. })));
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
        let invalid = |what: &str| SetError::Invalid {
            key: self.name,
            reason: format!("expected {what}, not `{text}`"),
        };
        match self.kind {
            SettingKind::Bool => text
                .parse()
                .map(SettingValue::Bool)
                .map_err(|_| invalid("true or false")),
            SettingKind::Integer(_) => text
                .parse()
                .map(SettingValue::Integer)
                .map_err(|_| invalid("an integer")),
            SettingKind::Float(_) => text
                .parse()
                .map(SettingValue::Float)
                .map_err(|_| invalid("a number")),
            SettingKind::Choice(names) => names
                .iter()
                .find(|&&name| name == text)
                .map(|&name| SettingValue::Choice(name))
                .ok_or_else(|| invalid(&format!("one of {}", names.join(", ")))),
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
    /// assert_eq!(settings.get("spatial.enabled")?, SettingValue::Bool(false));
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
    /// // What a Python binding does with `{"spatial.enabled": True, "spatial.radius": 4}`.
    /// let mut settings = AoSettings::default();
    /// for (key, value) in [
    ///     ("spatial.enabled", SettingValue::Bool(true)),
    ///     ("spatial.radius", SettingValue::Integer(4)),
    /// ] {
    ///     settings.set(key, value)?;
    /// }
    /// settings.validate()?;
    /// assert_eq!((settings.spatial.enabled, settings.spatial.radius), (true, 4));
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

const fn integers(min: u32, max: u32, step: u32) -> SettingKind {
    SettingKind::Integer(IntegerRange { min, max, step })
}

/// Samples, slices, directions or steps.
const fn count() -> SettingKind {
    integers(1, MAX_SAMPLE_COUNT, 1)
}

const fn float(
    min: f32,
    min_inclusive: bool,
    max: Limit,
    max_inclusive: bool,
    unit: Option<&'static str>,
) -> SettingKind {
    SettingKind::Float(FloatRange {
        min,
        min_inclusive,
        max: Some(max),
        max_inclusive,
        unit,
    })
}

const fn above(min: f32, min_inclusive: bool) -> SettingKind {
    SettingKind::Float(FloatRange {
        min,
        min_inclusive,
        max: None,
        max_inclusive: false,
        unit: None,
    })
}

const fn positive() -> SettingKind {
    above(0.0, false)
}

const fn at_least(min: f32) -> SettingKind {
    above(min, true)
}

const fn within(min: f32, max: f32) -> SettingKind {
    float(min, true, Limit::Value(max), true, None)
}

const fn unit() -> SettingKind {
    within(0.0, 1.0)
}

/// From 0 up to another setting's value.
const fn up_to(key: &'static str, unless_zero: bool) -> SettingKind {
    float(0.0, true, Limit::Setting { key, unless_zero }, true, None)
}

const fn names_of<T: Field>(_field: fn(&AoSettings) -> T) -> &'static [&'static str] {
    T::NAMES
}

/// One [`SettingSpec`]: the field's path is its key. `choice` takes the names of the field's
/// enum, `bool` is a bool; other kinds are given.
macro_rules! setting {
    ($head:ident $(. $tail:ident)*, choice, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*,
            SettingKind::Choice(names_of(|s: &AoSettings| s.$head $(. $tail)*)), $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, bool, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*, SettingKind::Bool, $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, $kind:expr, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*, $kind, $($rest)*)
    };
    (@spec $head:ident $(. $tail:ident)*, $kind:expr, $help:expr
        $(, note = $note:expr)? $(, rule = $rule:expr)? $(,)?) => {
        SettingSpec {
            name: concat!(stringify!($head) $(, ".", stringify!($tail))*),
            kind: $kind,
            help: $help,
            default_note: setting!(@option $($note)?),
            get: |s| Field::to_value(s.$head $(. $tail)*),
            set: |s, value| {
                s.$head $(. $tail)* = Field::from_value(value)?;
                Ok(())
            },
            rule: setting!(@option $($rule)?),
        }
    };
    (@option $value:expr) => { Some($value) };
    (@option) => { None };
}

/// Every setting of [`AoSettings`], in the order docs/settings.md lists them and
/// [`AoSettings::validate`] checks them.
///
/// ```
/// use aokit::settings::{SETTINGS, SettingKind};
/// // The keys a `--set` completion offers, with their ranges.
/// for spec in SETTINGS {
///     println!("{} {}", spec.name, spec.kind.range_text());
/// }
/// let counts = SETTINGS.iter().filter(|s| matches!(s.kind, SettingKind::Integer(_))).count();
/// assert!(counts > 10);
/// ```
pub static SETTINGS: &[SettingSpec] = &[
    setting!(method, choice, "the AO method ([methods.md](methods.md))"),
    setting!(
        radius,
        positive(),
        "world-space radius of the occlusion hemisphere",
        note = "`aokit`: the scene's suggested radius, where it has one"
    ),
    setting!(
        radius_multiplier,
        float(0.0, false, Limit::Value(4.0), true, None),
        "the kernel's radius over `radius`: screen-space methods under-occlude at the true radius, and sampling a little farther brings them closer to the reference traced at `radius`; 1 samples at `radius`"
    ),
    setting!(
        falloff,
        unit(),
        "fraction of the radius, at its outer end, over which a sample's influence fades to zero; 0 cuts off hard, as the reference does (used by `gtao`, by the range checks of `ssao` and `ssao-crytek`, and by `ue4-ssao`'s weight, which fades with how far a sample rises towards the eye: its preset's 1 is Unreal Engine 4's linear fade over the whole radius; `sao` has its own in its estimator)"
    ),
    setting!(
        intensity,
        at_least(0.0),
        "`ao = 1 - intensity * (1 - visibility)`, before `power`"
    ),
    setting!(
        power,
        positive(),
        "exponent applied last; above 1 darkens and adds contrast"
    ),
    setting!(
        max_radius_px,
        at_least(1.0),
        "largest screen radius in pixels of the input, at any `resolution` (Max Radius Pixels of the Unity Asset Store package \"Horizon Based Ambient Occlusion\"): nearer surfaces get a world radius that covers this many pixels; `msvo` stops sooner, at its coarsest level's disc"
    ),
    setting!(
        min_radius_px,
        up_to("max_radius_px", false),
        "smallest screen radius in pixels of the input: farther surfaces get a world radius widened to cover this many pixels, so distant geometry keeps a contact shadow (a look control: it departs from the world radius and the reference); 0 keeps the world radius, and AO stops where it covers under one pixel"
    ),
    setting!(
        bias,
        unit(),
        "self-occlusion bias of `ssao`, `ssao-crytek` and `sao` (the paper's beta, subtracted from `v . n`), and `ue4-ssao`'s flat-surface bias in its depth-only version (a pair occludes only where its two samples together rise this far towards the eye above the pixel), as a fraction of the radius; `sao`'s preset is the paper's, `ue4-ssao`'s Unreal's 5 units at its 200-unit radius"
    ),
    setting!(
        angle_bias,
        float(
            0.0,
            true,
            Limit::Named(FRAC_PI_2, "pi/2"),
            false,
            Some("radians")
        ),
        "angle bias of `hbao` (added to the tangent angle) and `hbao-plus` (its sine is the N.V bias), radians"
    ),
    setting!(
        step_power,
        within(0.25, 4.0),
        "step spacing of the marching methods, `1 + t^step_power * (R_px - 1)` pixels: 1 even, 2 crowded near the pixel"
    ),
    setting!(
        max_distance,
        at_least(0.0),
        "view depth beyond which there is no AO; 0: no limit (Max Distance of the Unity Asset Store package \"Horizon Based Ambient Occlusion\")"
    ),
    setting!(
        distance_falloff,
        up_to("max_distance", true),
        "distance before `max_distance` over which AO fades out"
    ),
    setting!(
        bent_normals,
        bool,
        "also output bent normals (`gtao` and `vbao` only)",
        rule = Rule {
            holds: |s| !s.bent_normals || s.method.has_bent_normals(),
            value: |s| format!("true with method {}", s.method.name()),
            expected: "false, or a method with slices (gtao, vbao)",
        }
    ),
    setting!(
        ssao_crytek.sample_count,
        count(),
        "points in the sphere per pixel"
    ),
    setting!(
        ssao.sample_count,
        count(),
        "points in the hemisphere per pixel"
    ),
    setting!(
        sao.sample_count,
        count(),
        "taps on SAO's spiral per pixel (its turns follow from the count: [methods/sao.md](methods/sao.md))"
    ),
    setting!(
        msvo.sample_count,
        integers(2, MAX_SAMPLE_COUNT, 2),
        "depth samples per texel at each level, in mirrored pairs on a disc of 5 texels of the level; the working level costs this many per pixel, the coarser four together at most a third more ([methods/msvo.md](methods/msvo.md))"
    ),
    setting!(
        msvo.levels,
        integers(1, MSVO_MAX_LEVELS, 1),
        "levels of the depth MIP chain the obscurance is computed at and merged from; the screen radius stops at `5 * 2^(levels - 1)` working texels (80 with all five)"
    ),
    setting!(
        msvo.thickness,
        positive(),
        "Unity's thickness modifier: a sample more than this many sphere chords in front of the sphere is taken for a thin occluder and rejected; larger darkens creases and adds halos around objects",
        note = "Unity's default"
    ),
    setting!(
        ue4_ssao.sample_count,
        count(),
        "sample pairs per pixel, each two depth samples mirrored about the pixel: a pixel reads twice this many depths, so presets give 2, 4, 9 and 27 pairs ([methods/ue4-ssao.md](methods/ue4-ssao.md))"
    ),
    setting!(
        ue4_ssao.use_normals,
        bool,
        "`ue4-ssao`'s normal version, each sample's angle measured from the tangent plane; false: the depth-only version, the angle between the two samples of a pair with the flat-surface `bias`"
    ),
    setting!(
        hbao.direction_count,
        count(),
        "screen directions over the full circle, rotated per pixel (`hbao`, `hbao-plus`; not read by `hbao.variant = separable`, which has four)"
    ),
    setting!(
        hbao.step_count,
        count(),
        "samples per direction (`hbao`, `hbao-plus`)"
    ),
    setting!(
        hbao.variant,
        choice,
        "how `hbao` runs: one kernel per pixel, or two passes over rows and then columns of depth in workgroup memory, after NVIDIA's compute-shader HBAO: four fixed directions (+-x, +-y), `4 * step_count` samples, the screen radius stopped at 128 texels of the working resolution ([methods/hbao.md](methods/hbao.md#separable-hbao-hbaovariant--separable)); `hbao-plus` accepts only `per-pixel`",
        rule = Rule {
            holds: |s| !(s.method == Method::HbaoPlus && s.hbao.variant == HbaoVariant::Separable),
            value: |s| format!("{} with method {}", s.hbao.variant.name(), s.method.name()),
            expected: "per-pixel: the separable passes integrate hbao's horizons, which \
                       hbao-plus does not have",
        }
    ),
    setting!(
        gtao.slice_count,
        count(),
        "slices (screen directions over a half circle) per pixel"
    ),
    setting!(
        gtao.steps_per_side,
        count(),
        "depth samples on each side of the pixel per slice"
    ),
    setting!(
        gtao.normalize_slices,
        bool,
        "divide by the slices' unoccluded integrals (see [gtao.md](methods/gtao.md#slices-normalised-by-their-unoccluded-integrals))"
    ),
    setting!(
        gtao.thickness,
        unit(),
        "the GTAO paper's thickness heuristic: how far the horizon falls back towards a sample below it"
    ),
    setting!(vbao.slice_count, count(), "slices per pixel"),
    setting!(
        vbao.steps_per_side,
        count(),
        "depth samples on each side per slice"
    ),
    setting!(
        vbao.thickness,
        positive(),
        "thickness of every occluder, as a fraction of the radius"
    ),
    setting!(
        vbao.thickness_growth,
        at_least(0.0),
        "extra thickness per unit of the occluder's view depth"
    ),
    setting!(
        vbao.back_faces,
        bool,
        "measure each occluder's thickness from `AoInputs::back_depth` (the depth of the back faces; `aokit ao --back-depth`), `vbao.thickness` then being the least thickness; turning it on in `--set` or a settings file starts from VBAO's presets tuned with back faces (`AoSettings::preset_with_back_faces`, [methods/vbao.md](methods/vbao.md#measured-thickness-vbaoback_faces))"
    ),
    setting!(
        normals.encoding,
        choice,
        "how the normal texture is encoded: what the pipeline decodes from the input normals (their texture format must match), what the scene renderer's G-buffer and `aokit ao` upload store ([normals.md](normals.md))"
    ),
    setting!(
        normals.space,
        choice,
        "the space of the input normals; world-space ones are turned into view space with `AoInputs::view_from_world` by the decode pass, which then runs for oct32 too (0.026 ms at 1080p on an H100, the decode pass's cost in [performance.md](performance.md))"
    ),
    setting!(
        normals.source,
        choice,
        "where the AO's normals come from: the normal texture (without one, `depth-5tap`, the best reconstruction), or reconstructed from depth by the named method ([normals.md](normals.md#normals-from-depth))"
    ),
    setting!(
        noise.kind,
        choice,
        "per-pixel noise that rotates and jitters every method's samples ([noise.md](noise.md))"
    ),
    setting!(
        noise.blue_size,
        integers(64, 128, 64),
        "side of the blue-noise tile, in texels"
    ),
    setting!(
        noise.temporal,
        choice,
        "how the tiled kinds (`blue`, `bayer`, `white`, `hilbert-r2`) move each frame: both values by the golden ratio's fraction, or by R2's step"
    ),
    setting!(
        spatial.enabled,
        bool,
        "run the spatial filter, an edge-aware blur of the AO ([denoise.md](denoise.md)); off so that the published tables keep scoring raw AO"
    ),
    setting!(
        spatial.kind,
        choice,
        "which filter: the separable bilateral blur (the keys `radius` to `normal_power` below), He, Sun and Tang's guided filter with log depth as the guide (`guided_radius`, `guided_epsilon`; [denoise.md](denoise.md#guided-filter)), or one pass over each pixel's 3x3 neighbourhood with the bilateral weights (`sigma` to `normal_power`; [denoise.md](denoise.md#edges-kind))"
    ),
    setting!(
        spatial.radius,
        integers(1, MAX_SPATIAL_RADIUS, 1),
        "bilateral kernel radius in pixels: each of the two passes averages `2 * radius + 1` pixels"
    ),
    setting!(
        spatial.sigma,
        positive(),
        "standard deviation of the Gaussian spatial weight, in pixels"
    ),
    setting!(
        spatial.depth_weight,
        choice,
        "how a neighbour's depth difference weighs it: a Gaussian, or all or nothing"
    ),
    setting!(
        spatial.depth_sigma,
        positive(),
        "relative depth difference `|d - d0| / d0` that scales the depth weight: the Gaussian's standard deviation, or the threshold above which a neighbour is rejected"
    ),
    setting!(
        spatial.normal_power,
        at_least(0.0),
        "exponent of the normal weight `max(0, n . n0)^normal_power`; 0 turns it off"
    ),
    setting!(
        spatial.guided_radius,
        integers(1, MAX_SPATIAL_RADIUS, 1),
        "guided filter window radius in pixels: AO is fitted against depth in windows of `(2 * guided_radius + 1)^2` pixels, and each pixel averages the fits of the windows that hold it"
    ),
    setting!(
        spatial.guided_epsilon,
        positive(),
        "the guided filter's regularisation: the variance of log depth in a window below which its AO is smoothed flat rather than fitted against depth; `sqrt` of it is a relative depth spread (1e-6: 0.1%)"
    ),
    setting!(
        temporal.enabled,
        bool,
        "blend each frame's AO with its reprojected history ([denoise.md](denoise.md))"
    ),
    setting!(
        temporal.blend,
        float(0.0, true, Limit::Value(1.0), false, None),
        "weight of the history; the noise averages over about `1 / (1 - blend)` frames"
    ),
    setting!(
        temporal.variance_gamma,
        positive(),
        "history clipped to the 3x3 same-surface mean +- this many standard deviations"
    ),
    setting!(
        temporal.depth_threshold,
        positive(),
        "relative depth difference above which reprojected history shows another surface and is rejected"
    ),
    setting!(
        temporal.filter_current,
        bool,
        "blend the 3x3 same-surface mean of the current frame instead of the pixel's own value (the filtered current value of [ybniaobu's Unity YPipeline](https://github.com/ybniaobu/Unity_YPipeline); blurs contact shadows)"
    ),
    setting!(
        resolution,
        choice,
        "resolution the AO kernel runs at: every pixel, or one texel per 2x2 or 4x4 pixels upsampled back ([denoise.md](denoise.md#resolution)); full so that the published tables stand"
    ),
    setting!(
        downsample,
        choice,
        "which pixel of each block gives a working texel its depth, normal and motion: a fixed one, the nearest, the farthest, or nearest and farthest alternating in a checkerboard"
    ),
    setting!(
        upsample,
        choice,
        "how each pixel combines the 2x2 working texels around it: those on its surface equally or bilinearly weighted, or bilinearly where all four are on its surface and else the one of nearest depth"
    ),
    setting!(
        upsample_threshold,
        positive(),
        "relative depth difference `|d - d0| / d0` below which a working texel shows the pixel's surface in the upsample"
    ),
    setting!(
        filter_resolution,
        choice,
        "below full resolution, where the spatial and temporal filters run: before the upsample, on the working texels, or after it, on every pixel"
    ),
    setting!(
        depth_mips,
        choice,
        "whether `gtao`, `vbao`, `hbao`, `hbao-plus`, `ssao` and `ssao-crytek` read far samples from a depth MIP chain, and its precision ([depth-mips.md](depth-mips.md)); `fp16` needs R16Float storage on the device"
    ),
    setting!(
        depth_mip_offset,
        float(0.0, true, Limit::Value(16.0), true, Some("log2 pixels")),
        "with `depth_mips` on, a sample `d` pixels out reads level `floor(log2(d) - depth_mip_offset)`, clamped to the chain's levels"
    ),
    setting!(
        sample_depth,
        choice,
        "how `gtao`, `vbao`, `hbao` and `hbao-plus` read the depth where a sample lands: the texel it lands in, moved onto the view ray through the sample at the same height above the tangent plane (one load), or 1 / depth interpolated over its 2x2 texels (exact on planes; slightly lower error for 1.06 to 1.32 times the frame's time on an H100: [methods.md](methods.md#sample-depth))"
    ),
    setting!(
        slice_march,
        choice,
        "how `gtao`, `vbao`, `hbao` and `hbao-plus` march their slices with the `nearest` read: each side set up once, with the counts and the step power compiled into the kernel, or every sample placed from scratch; the same AO to rounding, at different cost ([gtao.md](methods/gtao.md#the-lean-march))"
    ),
];
