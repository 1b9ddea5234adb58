//! Typed AO settings with named presets and validation.
//!
//! Everything a user can tune lives in one [`AoSettings`] value. It serialises with serde, so the
//! CLI reaches every field by its dotted path (`gtao.slice_count`) and TOML files hold any subset.

mod ao;
mod enums;
mod methods;
mod named;
mod stages;
#[cfg(test)]
mod tests;
mod validate;

pub use ao::*;
pub use enums::*;
pub use methods::*;
pub(crate) use named::{find_by_name, named_enum};
pub use stages::*;
pub use validate::*;
