//! What a reference is traced with, and the checks on it.

use std::fmt;
use std::str::FromStr;

use crate::ReferenceError;

/// Most rays per pixel [`AoOptions::validate`] accepts: past this the estimate's noise is far
/// below 8-bit precision and a 4K image would take days on a CPU.
pub const MAX_SPP: u32 = 1 << 20;

/// How a ray that hits geometry at distance `t < radius` counts.
///
/// With [`Falloff::None`] the reference is ambient occlusion proper: the cosine-weighted fraction
/// of the hemisphere that reaches `radius` unblocked. The other two are the *obscurance* variants
/// screen-space methods approximate, where a far occluder darkens less than a near one.
///
/// ```
/// use aokit_reference::{AoOptions, Falloff};
/// // Names as a command line or settings file gives them.
/// let falloff: Falloff = "quadratic".parse()?;
/// assert_eq!(falloff.name(), "quadratic");
/// // A hit halfway to the radius.
/// assert_eq!(Falloff::None.occlusion(0.5), 1.0);
/// assert_eq!(falloff.occlusion(0.5), 0.75);
/// AoOptions { falloff, ..Default::default() }.validate()?;
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Falloff {
    /// A hit occludes fully.
    #[default]
    None,
    /// A hit occludes `1 - t / radius`.
    Linear,
    /// A hit occludes `1 - (t / radius)^2`.
    Quadratic,
}

impl Falloff {
    /// Every variant, in the order of their names in help texts.
    ///
    /// ```
    /// use aokit_reference::Falloff;
    /// let names: Vec<&str> = Falloff::ALL.iter().map(|f| f.name()).collect();
    /// assert_eq!(names.join("|"), "none|linear|quadratic");
    /// ```
    pub const ALL: [Falloff; 3] = [Falloff::None, Falloff::Linear, Falloff::Quadratic];

    /// The name used on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            Falloff::None => "none",
            Falloff::Linear => "linear",
            Falloff::Quadratic => "quadratic",
        }
    }

    /// How much a hit at `t / radius = x` (in `[0, 1)`) occludes.
    pub fn occlusion(self, x: f32) -> f32 {
        match self {
            Falloff::None => 1.0,
            Falloff::Linear => 1.0 - x,
            Falloff::Quadratic => 1.0 - x * x,
        }
    }
}

impl fmt::Display for Falloff {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Falloff {
    type Err = ReferenceError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Falloff::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| ReferenceError::Falloff(s.to_string()))
    }
}

/// The parameters of one reference image.
///
/// ```
/// use aokit_reference::{AoOptions, Falloff};
/// let options = AoOptions { radius: 0.5, spp: 256, seed: 7, falloff: Falloff::None };
/// options.validate()?;
/// assert!(AoOptions { spp: 0, ..options }.validate().is_err());
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AoOptions {
    /// Occlusion radius in world units: geometry farther than this does not occlude.
    pub radius: f32,
    /// Rays per pixel.
    pub spp: u32,
    /// Seed of the per-pixel scrambling; the same seed gives the same image.
    pub seed: u64,
    /// How a hit's distance weighs its occlusion.
    pub falloff: Falloff,
}

impl Default for AoOptions {
    fn default() -> Self {
        Self {
            radius: 1.0,
            spp: 256,
            seed: 0,
            falloff: Falloff::None,
        }
    }
}

impl AoOptions {
    /// Checks every field, naming the first one out of range.
    ///
    /// ```
    /// use aokit_reference::{AoOptions, MAX_SPP, ReferenceError};
    /// let too_many = AoOptions { spp: MAX_SPP + 1, ..Default::default() };
    /// assert_eq!(too_many.validate(), Err(ReferenceError::Spp(MAX_SPP + 1)));
    /// ```
    pub fn validate(&self) -> Result<(), ReferenceError> {
        if !(self.radius.is_finite() && self.radius > 0.0) {
            return Err(ReferenceError::Radius(self.radius));
        }
        if !(1..=MAX_SPP).contains(&self.spp) {
            return Err(ReferenceError::Spp(self.spp));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn falloff_names_round_trip() {
        for f in Falloff::ALL {
            assert_eq!(f.name().parse::<Falloff>().unwrap(), f);
        }
        assert_eq!("Linear".parse::<Falloff>().unwrap(), Falloff::Linear);
        let err = "cubic".parse::<Falloff>().unwrap_err().to_string();
        assert!(err.contains("cubic") && err.contains("quadratic"), "{err}");
    }

    #[test]
    fn out_of_range_options_are_named() {
        let ok = AoOptions::default();
        ok.validate().unwrap();
        for radius in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            let err = AoOptions { radius, ..ok }.validate().unwrap_err();
            assert!(err.to_string().contains("radius"), "{err}");
        }
        for spp in [0, MAX_SPP + 1] {
            let err = AoOptions { spp, ..ok }.validate().unwrap_err();
            assert!(err.to_string().contains("rays per pixel"), "{err}");
        }
    }
}
