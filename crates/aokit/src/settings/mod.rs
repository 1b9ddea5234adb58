//! Typed AO settings with named presets and validation.
//!
//! Everything a user can tune lives in one [`AoSettings`] value. It serialises with serde, so the
//! CLI reaches every field by its dotted path (`gtao.slice_count`) and TOML files hold any subset.
//! Each setting is declared once in [`SETTINGS`] (its key, type, range and help), and
//! [`AoSettings::validate`], [`AoSettings::get`] and [`AoSettings::set`], the CLI's `--set` and
//! `aokit settings`, and docs/settings.md all derive from those declarations.

mod ao;
mod enums;
mod methods;
mod named;
mod spec;
mod stages;
mod table;
#[cfg(test)]
mod tests;
mod validate;

pub use ao::*;
pub use enums::*;
pub use methods::*;
pub(crate) use named::{find_by_name, named_enum};
pub(crate) use spec::Field;
pub use spec::{
    FloatRange, IntegerRange, Limit, SetError, SettingKind, SettingSpec, SettingValue,
    find_setting, suggest_setting,
};
pub use stages::*;
pub use table::SETTINGS;
pub use validate::*;
