//! The presets' values: what `aokit tune` found best for each method at each preset's cost,
//! over the built-in scenes and Sponza's four cameras at 480x270 (docs/tuning.md has the table,
//! bench/data/tuning.json the numbers; `bash bench/tuning.sh` measures them again, and a test fails
//! until a new table is copied into the methods' modules, each method's rows in its own).

use crate::methods;
use crate::settings::{Method, Preset};

/// One method's values at one preset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tuned {
    /// Directions or slices, and steps per direction or side; samples and 1 for the point
    /// methods; sample pairs and 1 for ue4-ssao.
    pub split: [u32; 2],
    pub step_power: f32,
    pub falloff: f32,
    /// The method's own knob: `bias` (ssao, ssao-crytek, sao, ue4-ssao), `angle_bias` (hbao,
    /// hbao-plus), `gtao.thickness`, `vbao.thickness` or `msvo.thickness`.
    pub knob: f32,
    pub power: f32,
    pub radius_multiplier: f32,
}

pub(crate) const fn tuned(
    split: [u32; 2],
    step_power: f32,
    falloff: f32,
    knob: f32,
    power: f32,
    radius_multiplier: f32,
) -> Tuned {
    Tuned {
        split,
        step_power,
        falloff,
        knob,
        power,
        radius_multiplier,
    }
}

/// Depth samples per pixel of each preset: the cost levels the table is searched at.
pub(crate) fn samples(preset: Preset) -> u32 {
    match preset {
        Preset::Low => 4,
        Preset::Medium => 8,
        Preset::High => 18,
        Preset::Ultra => 54,
    }
}

/// The values `method` takes at `preset`: its module's rows (methods/).
pub(crate) fn preset_values(method: Method, preset: Preset) -> Tuned {
    (methods::spec(method).tuned)(preset)
}
