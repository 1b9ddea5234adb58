//! Typed AO settings with named presets and validation.
//!
//! Everything a user can tune lives in one [`AoSettings`] value. It serialises with serde, so the
//! CLI reaches every field by its dotted path (`gtao.slice_count`) and TOML files hold any subset.

use serde::{Deserialize, Serialize};

/// The AO method a pipeline runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Ground-truth based AO (Jimenez et al. 2016): cosine-weighted horizon integral per slice.
    #[default]
    Gtao,
}

impl Method {
    /// Every method, in the order the CLI lists them.
    pub const ALL: [Method; 1] = [Method::Gtao];

    /// The name used on the command line and in settings files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Gtao => "gtao",
        }
    }
}

impl std::str::FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        find_by_name(&Method::ALL, Method::name, "method", s)
    }
}

/// Quality levels, from cheapest to most accurate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Preset {
    /// Fewest samples: for low-end GPUs.
    Low,
    /// A balance for mid-range GPUs.
    Medium,
    /// The default.
    #[default]
    High,
    /// Many samples, for stills and comparisons.
    Ultra,
}

impl Preset {
    /// Every preset, cheapest first.
    pub const ALL: [Preset; 4] = [Preset::Low, Preset::Medium, Preset::High, Preset::Ultra];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Low => "low",
            Preset::Medium => "medium",
            Preset::High => "high",
            Preset::Ultra => "ultra",
        }
    }
}

impl std::str::FromStr for Preset {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        find_by_name(&Preset::ALL, Preset::name, "preset", s)
    }
}

/// The member of `all` called `wanted`, or an error listing the names on offer.
fn find_by_name<T: Copy>(
    all: &[T],
    name: fn(T) -> &'static str,
    what: &str,
    wanted: &str,
) -> Result<T, String> {
    all.iter()
        .copied()
        .find(|&t| name(t) == wanted)
        .ok_or_else(|| {
            let known: Vec<&str> = all.iter().map(|&t| name(t)).collect();
            format!("unknown {what} `{wanted}` (known: {})", known.join(", "))
        })
}

/// GTAO-specific sampling counts.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GtaoSettings {
    /// Slices (screen-space directions over a half circle) per pixel.
    pub slice_count: u32,
    /// Depth samples taken on each side of the pixel along a slice.
    pub steps_per_side: u32,
    /// Divide the visible arcs by the same slices' unoccluded arcs instead of by the slice count.
    /// A slice's unoccluded integral depends on its angle to the normal, so with few slices the
    /// plain average is noisy even on open ground; the ratio is exactly 1 there and converges to
    /// the same value as more slices are taken.
    pub normalize_slices: bool,
}

impl Default for GtaoSettings {
    fn default() -> Self {
        Self::preset(Preset::default())
    }
}

impl GtaoSettings {
    /// Sample counts of a preset. Slices cost more than steps but remove more noise (seed 000
    /// observes 4x4 beats 2x8 at equal cost), so presets grow slices first.
    pub fn preset(preset: Preset) -> Self {
        let (slice_count, steps_per_side) = match preset {
            Preset::Low => (1, 2),
            Preset::Medium => (2, 2),
            Preset::High => (3, 3),
            Preset::Ultra => (9, 3),
        };
        Self {
            slice_count,
            steps_per_side,
            normalize_slices: true,
        }
    }
}

/// Everything that shapes the AO a pipeline produces.
///
/// ```
/// use aokit::{AoSettings, Method, Preset};
/// let mut settings = AoSettings::preset(Method::Gtao, Preset::Medium);
/// settings.radius = 0.5;
/// settings.validate().unwrap();
/// settings.gtao.slice_count = 0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AoSettings {
    /// Which method runs.
    pub method: Method,
    /// World-space radius of the occlusion hemisphere.
    pub radius: f32,
    /// Fraction of the radius, at its outer end, over which a sample's influence fades to zero;
    /// 0 cuts off hard at the radius.
    pub falloff: f32,
    /// Scales occlusion: `ao = 1 - intensity * (1 - visibility)`, before `power`.
    pub intensity: f32,
    /// Exponent applied last: values above 1 darken and add contrast.
    pub power: f32,
    /// GTAO sampling.
    pub gtao: GtaoSettings,
}

impl Default for AoSettings {
    fn default() -> Self {
        Self::preset(Method::default(), Preset::default())
    }
}

/// A setting outside the range it can take.
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

/// Most slices or steps a kernel accepts: beyond this the cost is far past any real-time budget
/// and the estimate has long converged.
pub const MAX_SAMPLE_COUNT: u32 = 64;

impl AoSettings {
    /// A method at a preset quality, with a radius of 1 world unit.
    pub fn preset(method: Method, preset: Preset) -> Self {
        Self {
            method,
            radius: 1.0,
            // A short fade hides the disc edge of the radius without weakening contact shadows.
            falloff: 0.2,
            intensity: 1.0,
            power: 1.0,
            gtao: GtaoSettings::preset(preset),
        }
    }

    /// Depth samples the AO kernel takes per pixel: the cost that does not depend on the GPU.
    pub fn samples_per_pixel(&self) -> u32 {
        match self.method {
            Method::Gtao => 2 * self.gtao.slice_count * self.gtao.steps_per_side,
        }
    }

    /// Checks every field, naming the first one out of range.
    pub fn validate(&self) -> Result<(), SettingsError> {
        positive("radius", self.radius)?;
        in_unit_range("falloff", self.falloff)?;
        if !(self.intensity.is_finite() && self.intensity >= 0.0) {
            return Err(SettingsError {
                field: "intensity",
                value: self.intensity.to_string(),
                expected: "a finite number >= 0",
            });
        }
        positive("power", self.power)?;
        count("gtao.slice_count", self.gtao.slice_count)?;
        count("gtao.steps_per_side", self.gtao.steps_per_side)?;
        Ok(())
    }
}

fn positive(field: &'static str, value: f32) -> Result<(), SettingsError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "a finite number > 0",
        })
    }
}

fn in_unit_range(field: &'static str, value: f32) -> Result<(), SettingsError> {
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "a number in [0, 1]",
        })
    }
}

fn count(field: &'static str, value: u32) -> Result<(), SettingsError> {
    if (1..=MAX_SAMPLE_COUNT).contains(&value) {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: "an integer in 1..=64",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_and_grow_in_cost() {
        let mut last = 0;
        for preset in Preset::ALL {
            let s = AoSettings::preset(Method::Gtao, preset);
            s.validate().unwrap();
            let cost = s.samples_per_pixel();
            assert!(cost > last, "{preset:?}");
            last = cost;
        }
    }

    #[test]
    fn out_of_range_values_name_their_field() {
        let field = |s: AoSettings| s.validate().unwrap_err().field;
        let base = AoSettings::default();
        assert_eq!(
            field(AoSettings {
                radius: f32::NAN,
                ..base
            }),
            "radius"
        );
        let mut s = AoSettings::default();
        s.gtao.steps_per_side = 65;
        assert_eq!(s.validate().unwrap_err().field, "gtao.steps_per_side");
        assert_eq!(
            field(AoSettings {
                falloff: 1.5,
                ..base
            }),
            "falloff"
        );
        assert_eq!(
            field(AoSettings {
                intensity: -1.0,
                ..base
            }),
            "intensity"
        );
    }

    #[test]
    fn names_parse_back() {
        for m in Method::ALL {
            assert_eq!(m.name().parse::<Method>().unwrap(), m);
        }
        for p in Preset::ALL {
            assert_eq!(p.name().parse::<Preset>().unwrap(), p);
        }
        assert!("hbao9".parse::<Method>().unwrap_err().contains("gtao"));
    }
}
