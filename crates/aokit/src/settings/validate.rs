//! [`AoSettings::validate`] and its error.

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
    /// Checks every field, naming the first one out of range.
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
        positive("radius", self.radius)?;
        if !(self.radius_multiplier > 0.0 && self.radius_multiplier <= 4.0) {
            return Err(SettingsError {
                field: "radius_multiplier",
                value: self.radius_multiplier.to_string(),
                expected: "a number in (0, 4]",
            });
        }
        in_unit_range("falloff", self.falloff)?;
        at_least("intensity", self.intensity, 0.0)?;
        positive("power", self.power)?;
        at_least("max_radius_px", self.max_radius_px, 1.0)?;
        at_least("min_radius_px", self.min_radius_px, 0.0)?;
        if self.min_radius_px > self.max_radius_px {
            return Err(SettingsError {
                field: "min_radius_px",
                value: self.min_radius_px.to_string(),
                expected: "pixels in [0, max_radius_px]",
            });
        }
        in_unit_range("bias", self.bias)?;
        if !(0.0..std::f32::consts::FRAC_PI_2).contains(&self.angle_bias) {
            return Err(SettingsError {
                field: "angle_bias",
                value: self.angle_bias.to_string(),
                expected: "an angle in [0, pi/2) radians",
            });
        }
        if !(0.25..=4.0).contains(&self.step_power) {
            return Err(SettingsError {
                field: "step_power",
                value: self.step_power.to_string(),
                expected: "a number in [0.25, 4]",
            });
        }
        at_least("max_distance", self.max_distance, 0.0)?;
        at_least("distance_falloff", self.distance_falloff, 0.0)?;
        if self.max_distance > 0.0 && self.distance_falloff > self.max_distance {
            return Err(SettingsError {
                field: "distance_falloff",
                value: self.distance_falloff.to_string(),
                expected: "a distance in [0, max_distance]",
            });
        }
        if self.bent_normals && !self.method.has_bent_normals() {
            return Err(SettingsError {
                field: "bent_normals",
                value: format!("true with method {}", self.method.name()),
                expected: "false, or a method with slices (gtao, vbao)",
            });
        }
        count("ssao_crytek.sample_count", self.ssao_crytek.sample_count)?;
        count("ssao.sample_count", self.ssao.sample_count)?;
        count("hbao.direction_count", self.hbao.direction_count)?;
        count("hbao.step_count", self.hbao.step_count)?;
        if self.method == Method::HbaoPlus && self.hbao.variant == HbaoVariant::Separable {
            return Err(SettingsError {
                field: "hbao.variant",
                value: "separable with method hbao-plus".into(),
                expected: "per-pixel: the separable passes integrate hbao's horizons, which \
                           hbao-plus does not have",
            });
        }
        count("gtao.slice_count", self.gtao.slice_count)?;
        count("gtao.steps_per_side", self.gtao.steps_per_side)?;
        in_unit_range("gtao.thickness", self.gtao.thickness)?;
        count("vbao.slice_count", self.vbao.slice_count)?;
        count("vbao.steps_per_side", self.vbao.steps_per_side)?;
        count("sao.sample_count", self.sao.sample_count)?;
        count("ue4_ssao.sample_count", self.ue4_ssao.sample_count)?;
        count("msvo.sample_count", self.msvo.sample_count)?;
        if !self.msvo.sample_count.is_multiple_of(2) {
            return Err(SettingsError {
                field: "msvo.sample_count",
                value: self.msvo.sample_count.to_string(),
                expected: "an even integer in 2..=64: samples come in mirrored pairs",
            });
        }
        if !(1..=MSVO_MAX_LEVELS).contains(&self.msvo.levels) {
            return Err(SettingsError {
                field: "msvo.levels",
                value: self.msvo.levels.to_string(),
                expected: "an integer in 1..=5",
            });
        }
        positive("msvo.thickness", self.msvo.thickness)?;
        positive("vbao.thickness", self.vbao.thickness)?;
        at_least("vbao.thickness_growth", self.vbao.thickness_growth, 0.0)?;
        if ![64, 128].contains(&self.noise.blue_size) {
            return Err(SettingsError {
                field: "noise.blue_size",
                value: self.noise.blue_size.to_string(),
                expected: "64 or 128",
            });
        }
        if !(1..=MAX_SPATIAL_RADIUS).contains(&self.spatial.radius) {
            return Err(SettingsError {
                field: "spatial.radius",
                value: self.spatial.radius.to_string(),
                expected: "an integer in 1..=8",
            });
        }
        positive("spatial.sigma", self.spatial.sigma)?;
        if !(0.0..1.0).contains(&self.temporal.blend) {
            return Err(SettingsError {
                field: "temporal.blend",
                value: self.temporal.blend.to_string(),
                expected: "a weight in [0, 1)",
            });
        }
        positive("temporal.variance_gamma", self.temporal.variance_gamma)?;
        positive("temporal.depth_threshold", self.temporal.depth_threshold)?;
        positive("spatial.depth_sigma", self.spatial.depth_sigma)?;
        at_least("spatial.normal_power", self.spatial.normal_power, 0.0)?;
        if !(1..=MAX_SPATIAL_RADIUS).contains(&self.spatial.guided_radius) {
            return Err(SettingsError {
                field: "spatial.guided_radius",
                value: self.spatial.guided_radius.to_string(),
                expected: "an integer in 1..=8",
            });
        }
        positive("spatial.guided_epsilon", self.spatial.guided_epsilon)?;
        positive("upsample_threshold", self.upsample_threshold)?;
        // Below 0 a sample one pixel away would read a coarser texel than its distance; from
        // 16 on, no sample within any radius a texture can hold reads a coarser level.
        if !(0.0..=16.0).contains(&self.depth_mip_offset) {
            return Err(SettingsError {
                field: "depth_mip_offset",
                value: self.depth_mip_offset.to_string(),
                expected: "a number in [0, 16] (log2 pixels)",
            });
        }
        Ok(())
    }
}

fn at_least(field: &'static str, value: f32, min: f32) -> Result<(), SettingsError> {
    if value.is_finite() && value >= min {
        Ok(())
    } else {
        Err(SettingsError {
            field,
            value: value.to_string(),
            expected: if min == 0.0 {
                "a finite number >= 0"
            } else {
                "a finite number >= 1"
            },
        })
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
