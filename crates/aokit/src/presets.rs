//! The presets' values: what `aokit tune` found best for each method at each preset's cost,
//! over the built-in scenes and Sponza's four cameras at 480x270 (docs/tuning.md has the table,
//! bench/data/tuning.json the numbers; `bash bench/tuning.sh` measures them again, and a test fails
//! until a new table is copied here).

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

const fn tuned(
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

/// The values `method` takes at `preset`.
pub(crate) fn preset_values(method: Method, preset: Preset) -> Tuned {
    match (method, preset) {
        // Not tuned: Crytek's SSAO keeps its 2007 form (a 2% bias, no falloff, power 1), whose
        // grey walls are what the method is chosen for; the search would trade them away.
        (Method::SsaoCrytek, _) => tuned([samples(preset), 1], 1.0, 0.0, 0.02, 1.0, 1.0),
        // Not tuned either: SAO keeps the paper's parameters (McGuire, Mara and Luebke 2012):
        // its bias of 0.01 m at its 1 m radius, its own falloff inside the estimator (so none
        // of ours), power and radius as given.
        (Method::Sao, _) => tuned([samples(preset), 1], 1.0, 0.0, 0.01, 1.0, 1.0),
        // Not tuned: Unreal's legacy SSAO as Unreal Engine 4's PostProcessAmbientOcclusion.usf
        // (Epic Games) gives it. Its weight fades linearly with how far a sample lies in front of
        // the pixel, to 0 at the radius (falloff 1); its flat-surface bias is 5 units, 2.5% of
        // Unreal's default 200-unit AO radius.
        (Method::Ue4Ssao, _) => tuned([samples(preset) / 2, 1], 1.0, 1.0, 0.025, 1.0, 1.0),
        // Not tuned: MSVO as Unity ships it (Post-processing Stack v2), every preset's samples at
        // each level, Unity's default thickness modifier of 1 (the knob), no falloff of ours (the
        // sphere's chords weight its samples), power and radius as given.
        (Method::Msvo, _) => tuned([samples(preset), 1], 1.0, 0.0, 1.0, 1.0, 1.0),
        (Method::Ssao, Preset::Low) => tuned([4, 1], 1.0, 1.0, 0.005, 1.0, 1.2),
        (Method::Ssao, Preset::Medium) => tuned([8, 1], 1.0, 0.5, 0.005, 1.1, 1.1),
        (Method::Ssao, Preset::High) => tuned([18, 1], 1.0, 0.75, 0.005, 1.6, 1.2),
        (Method::Ssao, Preset::Ultra) => tuned([54, 1], 1.0, 0.75, 0.005, 2.0, 1.1),
        (Method::Hbao, Preset::Low) => tuned([2, 2], 1.5, 0.0, 0.0, 0.9, 1.5),
        (Method::Hbao, Preset::Medium) => tuned([4, 2], 1.5, 0.0, 0.05, 1.4, 1.5),
        (Method::Hbao, Preset::High) => tuned([6, 3], 1.5, 0.0, 0.05, 1.25, 1.5),
        (Method::Hbao, Preset::Ultra) => tuned([6, 9], 1.5, 0.0, 0.1, 1.0, 1.35),
        (Method::HbaoPlus, Preset::Low) => tuned([2, 2], 1.75, 0.0, 0.0, 2.5, 1.5),
        (Method::HbaoPlus, Preset::Medium) => tuned([4, 2], 1.5, 0.0, 0.05, 3.5, 1.5),
        (Method::HbaoPlus, Preset::High) => tuned([6, 3], 1.5, 0.0, 0.05, 3.5, 1.5),
        (Method::HbaoPlus, Preset::Ultra) => tuned([6, 9], 1.5, 0.0, 0.05, 3.5, 1.5),
        (Method::Gtao, Preset::Low) => tuned([1, 2], 1.0, 0.0, 0.05, 1.6, 1.1),
        (Method::Gtao, Preset::Medium) => tuned([2, 2], 1.0, 0.0, 0.0, 1.0, 1.1),
        (Method::Gtao, Preset::High) => tuned([3, 3], 1.25, 0.0, 0.1, 1.25, 1.1),
        (Method::Gtao, Preset::Ultra) => tuned([3, 9], 1.0, 0.1, 0.0, 1.1, 0.8),
        (Method::Vbao, Preset::Low) => tuned([2, 1], 1.0, 0.0, 0.65, 1.1, 1.35),
        (Method::Vbao, Preset::Medium) => tuned([2, 2], 1.0, 0.0, 0.5, 1.0, 1.2),
        (Method::Vbao, Preset::High) => tuned([3, 3], 1.0, 0.0, 0.45, 1.1, 1.1),
        (Method::Vbao, Preset::Ultra) => tuned([3, 9], 1.75, 0.0, 0.2, 1.0, 1.1),
    }
}

/// `vbao`'s values at `preset` with [`VbaoSettings::back_faces`](crate::VbaoSettings::back_faces)
/// on, tuned as the others are: its knob is then the least thickness, for occluders whose back
/// faces lie closer than that or were not seen.
pub(crate) fn vbao_back_faces_values(preset: Preset) -> Tuned {
    match preset {
        Preset::Low => tuned([2, 1], 1.0, 0.0, 0.6, 1.1, 1.35),
        Preset::Medium => tuned([2, 2], 1.0, 0.0, 0.3, 1.1, 1.2),
        Preset::High => tuned([3, 3], 1.5, 0.0, 0.1, 1.25, 1.2),
        Preset::Ultra => tuned([3, 9], 1.75, 0.0, 0.05, 1.0, 1.1),
    }
}
