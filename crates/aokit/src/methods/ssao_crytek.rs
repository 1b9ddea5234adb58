//! `ssao-crytek`: Crytek's 2007 SSAO, points in a sphere around the pixel tested against the
//! depth buffer. Its sampling is an [`SsaoSettings`](super::SsaoSettings).

use super::{Knob, MethodSpec, max_radius_px, no_flags};
use crate::presets::{samples, tuned};
use crate::settings::{Method, count, setting};
use crate::shader;

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::SsaoCrytek,
    shader: shader::SSAO_CRYTEK,
    // Not tuned: Crytek's SSAO keeps its 2007 form (a 2% bias, no falloff, power 1), whose
    // grey walls are what the method is chosen for; the search would trade them away.
    tuned: |preset| tuned([samples(preset), 1], 1.0, 0.0, 0.02, 1.0, 1.0),
    knob: Knob::Bias,
    samples_per_pixel: |s| s.ssao_crytek.sample_count,
    max_radius_px,
    kernel_counts: |s, _| s.ssao_crytek.kernel_counts(),
    flags: no_flags,
    bent_normals: false,
    marches_slices: false,
    depth_mips: None,
    section: "ssao_crytek",
    settings: &[setting!(
        ssao_crytek.sample_count,
        count(),
        "points in the sphere per pixel"
    )],
};
