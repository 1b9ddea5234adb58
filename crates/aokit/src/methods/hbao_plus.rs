//! `hbao-plus`: HBAO+'s normal-based estimator, each sample occluding by its elevation above
//! the tangent plane. It runs on `hbao`'s [`HbaoSettings`](super::HbaoSettings).

use super::{Knob, MethodSpec, max_radius_px, no_flags};
use crate::presets::tuned;
use crate::settings::{Method, Preset};
use crate::shader;

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::HbaoPlus,
    shader: shader::HBAO_PLUS,
    tuned: |preset| match preset {
        Preset::Low => tuned([2, 2], 1.5, 0.0, 0.05, 3.5, 1.7),
        Preset::Medium => tuned([4, 2], 1.5, 0.0, 0.05, 3.5, 1.7),
        Preset::High => tuned([6, 3], 1.5, 0.0, 0.05, 3.5, 1.5),
        Preset::Ultra => tuned([6, 9], 1.5, 0.0, 0.05, 3.5, 1.5),
    },
    knob: Knob::AngleBias,
    samples_per_pixel: |s| s.hbao.direction_count * s.hbao.step_count,
    max_radius_px,
    kernel_counts: |s, _| s.hbao.kernel_counts(),
    flags: no_flags,
    bent_normals: false,
    marches_slices: true,
    depth_mips: None,
    section: "hbao",
    // `hbao`'s settings, declared there.
    settings: &[],
};
