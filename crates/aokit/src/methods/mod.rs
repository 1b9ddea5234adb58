//! The AO methods, one module each: a method's own settings and their declarations
//! ([`SETTINGS`](crate::settings::SETTINGS) rows), its preset rows, how its settings reach the
//! kernel's uniforms, and its shader. [`REGISTRY`] lists them; everything that differs by method
//! reads it instead of matching on [`Method`]. docs/architecture.md says how to add one.

mod gtao;
mod hbao;
mod hbao_plus;
mod msvo;
mod sao;
mod ssao;
mod ssao_crytek;
mod ue4_ssao;
mod vbao;

pub use gtao::GtaoSettings;
pub use hbao::{HbaoSettings, SEPARABLE_HBAO_MAX_RADIUS_PX};
pub use msvo::{MSVO_MAX_LEVELS, MsvoSettings};
pub use ssao::SsaoSettings;
pub use ue4_ssao::Ue4SsaoSettings;
pub use vbao::VbaoSettings;
pub(crate) use vbao::with_back_faces;

use crate::passes::kernel::depth_mips::DepthReduction;
use crate::presets::Tuned;
use crate::settings::{AoSettings, Method, Preset, SettingSpec};
use crate::shader::ShaderSource;
use crate::uniforms::KernelCounts;

/// Most samples, slices, directions or steps a kernel accepts: beyond this the cost is far past
/// any real-time budget and the estimate has long converged.
pub const MAX_SAMPLE_COUNT: u32 = 64;

/// Every method, one line each, in the order docs/settings.md lists their settings.
pub(crate) const REGISTRY: &[MethodSpec] = &[
    ssao_crytek::SPEC,
    ssao::SPEC,
    sao::SPEC,
    msvo::SPEC,
    ue4_ssao::SPEC,
    hbao::SPEC,
    hbao_plus::SPEC,
    gtao::SPEC,
    vbao::SPEC,
];

/// Which of [`AoSettings`]' shared knobs a method's preset rows tune: the bias of the point
/// methods, the angle bias of the horizon methods, or a setting of the method's own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Knob {
    Bias,
    AngleBias,
    /// A key of the method's own settings, such as `gtao.thickness`.
    Own(&'static str),
}

/// What the library knows of one method.
pub(crate) struct MethodSpec {
    pub method: Method,
    /// The kernel program; for `msvo`, its per-level pass (passes/kernel/msvo.rs adds the
    /// merge).
    pub shader: ShaderSource,
    /// Its values at a preset (presets.rs has the table's provenance).
    pub tuned: fn(Preset) -> Tuned,
    /// Which setting [`Tuned::knob`] is.
    pub knob: Knob,
    /// Depth samples its kernel takes per pixel with these settings.
    pub samples_per_pixel: fn(&AoSettings) -> u32,
    /// The largest screen radius it reaches, in pixels of the input.
    pub max_radius_px: fn(&AoSettings) -> f32,
    /// Its counts and thickness in the kernel's uniforms; the radius is the kernel's.
    pub kernel_counts: fn(&AoSettings, f32) -> KernelCounts,
    /// `AoUniforms::flags` bits its own settings turn on.
    pub flags: fn(&AoSettings) -> u32,
    /// Whether it integrates over slices and so returns bent normals.
    pub bent_normals: bool,
    /// Whether its samples lie in slices through the view vector.
    pub marches_slices: bool,
    /// The depth MIP chain its kernel reads, if any.
    pub depth_mips: Option<DepthReduction>,
    /// The section of a settings file its own settings live in (`[gtao]`), the prefix of their
    /// keys: `hbao-plus` runs on `hbao`'s.
    pub section: &'static str,
    /// Its own settings' declarations.
    pub settings: &'static [SettingSpec],
}

/// The setting as asked for, for the methods whose radius nothing else stops.
fn max_radius_px(settings: &AoSettings) -> f32 {
    settings.max_radius_px
}

/// No flag bits, for the methods without a switch in the uniforms.
fn no_flags(_: &AoSettings) -> u32 {
    0
}

/// The registry's entry for `method`.
pub(crate) fn spec(method: Method) -> &'static MethodSpec {
    REGISTRY
        .iter()
        .find(|spec| spec.method == method)
        .expect("every method is in the registry (`every_method_is_registered_once`)")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_method_is_registered_once() {
        for method in Method::ALL {
            let entries = REGISTRY.iter().filter(|s| s.method == method).count();
            assert_eq!(entries, 1, "{method:?} in the registry");
        }
        assert_eq!(REGISTRY.len(), Method::ALL.len());
    }

    #[test]
    fn a_method_declares_settings_in_its_section_only() {
        for spec in REGISTRY {
            for setting in spec.settings {
                assert_eq!(
                    setting.section(),
                    Some(spec.section),
                    "{:?} declares {}",
                    spec.method,
                    setting.name
                );
            }
            assert!(
                spec.method.own_settings().next().is_some(),
                "{:?} reads no settings of its section {}",
                spec.method,
                spec.section
            );
        }
    }

    #[test]
    fn a_method_tunes_a_setting_it_declares_and_its_kernel_is_validated() {
        for spec in REGISTRY {
            if let Knob::Own(key) = spec.knob {
                assert!(
                    spec.settings.iter().any(|s| s.name == key),
                    "{:?} tunes {key}, which it does not declare",
                    spec.method
                );
            }
            assert!(
                crate::shader::ALL
                    .iter()
                    .any(|p| p.name == spec.shader.name),
                "{:?}'s kernel is not in shader::ALL, which naga validates",
                spec.method
            );
        }
    }
}
