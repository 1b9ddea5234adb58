//! `sao`: Scalable Ambient Obscurance (McGuire, Mara and Luebke 2012), taps on a spiral read
//! from a depth MIP level chosen by their distance. Its taps are an
//! [`SsaoSettings`](super::SsaoSettings).

use super::{Knob, MethodSpec, max_radius_px, no_flags};
use crate::passes::kernel::depth_mips::DepthReduction;
use crate::presets::{samples, tuned};
use crate::settings::{Method, count, setting};
use crate::shader;
use crate::spiral;
use crate::uniforms::KernelCounts;

pub(super) const SPEC: MethodSpec = MethodSpec {
    method: Method::Sao,
    shader: shader::SAO,
    // Not tuned: SAO keeps the paper's parameters (McGuire, Mara and Luebke 2012): its bias of
    // 0.01 m at its 1 m radius, its own falloff inside the estimator (so none of ours), power
    // and radius as given.
    tuned: |preset| tuned([samples(preset), 1], 1.0, 0.0, 0.01, 1.0, 1.0),
    knob: Knob::Bias,
    samples_per_pixel: |s| s.sao.sample_count,
    max_radius_px,
    // SAO's taps and the turns of their spiral.
    kernel_counts: |s, _| KernelCounts::new(s.sao.sample_count, spiral::turns(s.sao.sample_count)),
    flags: no_flags,
    bent_normals: false,
    marches_slices: false,
    depth_mips: Some(DepthReduction::Subsample),
    section: "sao",
    settings: &[setting!(
        sao.sample_count,
        count(),
        "taps on SAO's spiral per pixel (its turns follow from the count: \
         [methods/sao.md](methods/sao.md))"
    )],
};
