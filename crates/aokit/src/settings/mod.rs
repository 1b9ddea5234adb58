//! Typed AO settings with named presets and validation.
//!
//! Everything a user can tune lives in one [`AoSettings`] value. It serialises with serde, so the
//! CLI reaches every field by its dotted path (`gtao.slice_count`) and TOML files hold any subset.
//! Each setting is declared once in [`SETTINGS`] (its key, type, range and help), and
//! [`AoSettings::validate`], [`AoSettings::get`] and [`AoSettings::set`], the CLI's `--set` and
//! `aokit settings`, and docs/settings.md all derive from those declarations.

mod ao;
mod enums;
mod named;
mod spec;
mod stages;
mod table;
#[cfg(test)]
mod tests;
mod validate;

pub use crate::methods::{
    GtaoSettings, HbaoSettings, MAX_SAMPLE_COUNT, MSVO_MAX_LEVELS, MsvoSettings,
    SEPARABLE_HBAO_MAX_RADIUS_PX, SsaoSettings, Ue4SsaoSettings, VbaoSettings,
};
pub use ao::*;
pub use enums::*;
pub(crate) use named::{find_by_name, named_enum};
pub(crate) use spec::{Field, Rule};
pub use spec::{
    FloatRange, IntegerRange, Limit, SetError, SettingKind, SettingSpec, SettingValue,
    find_setting, suggest_setting,
};
pub use stages::*;
pub use table::SETTINGS;
pub(crate) use table::{at_least, count, integers, names_of, positive, setting, unit};
pub use validate::*;
