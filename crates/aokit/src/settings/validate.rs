//! [`AoSettings::validate`] and its error: each setting checked as [`SETTINGS`] declares it.

use super::*;

/// A setting outside the range it can take.
///
/// ```
/// use aokit::{AoSettings, SettingsError};
/// let mut settings = AoSettings::default();
/// settings.gtao.slice_count = 0;
/// // A settings panel highlights the field by its dotted path, as `--set` takes it.
/// let SettingsError { field, value, expected } = settings.validate().unwrap_err();
/// assert_eq!(field, "gtao.slice_count");
/// assert_eq!((value.as_str(), expected), ("0", "an integer in 1..=64"));
/// assert_eq!(
///     settings.validate().unwrap_err().to_string(),
///     "setting `gtao.slice_count` = 0 is out of range: an integer in 1..=64"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("setting `{field}` = {value} is out of range: {expected}")]
pub struct SettingsError {
    /// Dotted path of the setting, as `--set` takes it.
    pub field: &'static str,
    /// The value given.
    pub value: String,
    /// What would be accepted.
    pub expected: &'static str,
}

impl AoSettings {
    /// Checks every field against its declaration in [`SETTINGS`] (its range, and any rule
    /// tying it to another setting), naming the first one out of range.
    ///
    /// ```
    /// use aokit::AoSettings;
    /// let mut settings = AoSettings::default();
    /// settings.max_distance = 50.0;
    /// // A fade longer than the distance it ends at.
    /// settings.distance_falloff = 80.0;
    /// assert_eq!(settings.validate().unwrap_err().field, "distance_falloff");
    /// settings.distance_falloff = 10.0;
    /// settings.validate()?;
    /// # Ok::<(), aokit::SettingsError>(())
    /// ```
    pub fn validate(&self) -> Result<(), SettingsError> {
        SETTINGS.iter().try_for_each(|spec| spec.check(self))
    }
}
