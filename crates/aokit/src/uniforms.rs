//! GPU uniform structs. Each is mirrored once in WGSL; the tests prove the two layouts agree.

use bytemuck::{Pod, Zeroable};
use glam::{Vec2, Vec4};

use crate::projection::Projection;
use crate::settings::AoSettings;

/// Mirrors `ViewUniforms` in `shaders/common/view.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct ViewUniforms {
    pub size: [f32; 2],
    pub inv_size: [f32; 2],
    pub linearize: [f32; 4],
    pub ndc_to_view: [f32; 2],
    pub pixels_per_unit: f32,
    pub orthographic: f32,
    pub far_ndc_depth: f32,
    pub frame_index: u32,
    pub _pad: [u32; 2],
}

impl ViewUniforms {
    pub fn new(projection: &Projection, size: [u32; 2], frame_index: u32) -> Self {
        let size = Vec2::new(size[0] as f32, size[1] as f32);
        let linearize: Vec4 = projection.linearize_coefficients();
        Self {
            size: size.to_array(),
            inv_size: size.recip().to_array(),
            linearize: linearize.to_array(),
            ndc_to_view: projection.ndc_to_view_scale().to_array(),
            pixels_per_unit: projection.pixels_per_unit(size.y),
            orthographic: if projection.is_orthographic() {
                1.0
            } else {
                0.0
            },
            far_ndc_depth: projection.far_ndc_depth(),
            frame_index,
            _pad: [0; 2],
        }
    }
}

/// Mirrors `GtaoUniforms` in `shaders/gtao.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct GtaoUniforms {
    pub radius: f32,
    pub falloff_mul: f32,
    pub falloff_add: f32,
    pub intensity: f32,
    pub power: f32,
    pub slice_count: u32,
    pub steps_per_side: u32,
    pub normalize_slices: u32,
}

/// Shortest fade the kernel uses, as a fraction of the radius: `falloff = 0` (a hard cut) becomes
/// this so the weight stays a finite linear ramp; the difference is below any sample spacing.
const MIN_FALLOFF: f32 = 1e-4;

impl GtaoUniforms {
    pub fn new(settings: &AoSettings) -> Self {
        let radius = settings.radius;
        let range = settings.falloff.max(MIN_FALLOFF) * radius;
        Self {
            radius,
            falloff_mul: -1.0 / range,
            falloff_add: radius / range,
            intensity: settings.intensity,
            power: settings.power,
            slice_count: settings.gtao.slice_count,
            steps_per_side: settings.gtao.steps_per_side,
            normalize_slices: u32::from(settings.gtao.normalize_slices),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shader;
    use std::mem::size_of;

    #[test]
    fn view_uniforms_match_wgsl() {
        let fields = crate::field_offsets!(ViewUniforms {
            size,
            inv_size,
            linearize,
            ndc_to_view,
            pixels_per_unit,
            orthographic,
            far_ndc_depth,
            frame_index,
        });
        shader::check_layout(
            &shader::LINEAR_DEPTH,
            "ViewUniforms",
            fields,
            size_of::<ViewUniforms>(),
        )
        .unwrap();
    }

    #[test]
    fn gtao_uniforms_match_wgsl() {
        let fields = crate::field_offsets!(GtaoUniforms {
            radius,
            falloff_mul,
            falloff_add,
            intensity,
            power,
            slice_count,
            steps_per_side,
            normalize_slices,
        });
        shader::check_layout(
            &shader::GTAO,
            "GtaoUniforms",
            fields,
            size_of::<GtaoUniforms>(),
        )
        .unwrap();
    }
    #[test]
    fn falloff_weight_is_one_inside_and_zero_at_the_radius() {
        let mut settings = AoSettings {
            radius: 2.0,
            falloff: 0.25,
            ..AoSettings::default()
        };
        let u = GtaoUniforms::new(&settings);
        let weight = |d: f32| (d * u.falloff_mul + u.falloff_add).clamp(0.0, 1.0);
        assert_eq!(weight(1.0), 1.0);
        assert_eq!(weight(1.5), 1.0);
        assert!((weight(1.75) - 0.5).abs() < 1e-6);
        assert_eq!(weight(2.0), 0.0);
        settings.falloff = 0.0;
        let u = GtaoUniforms::new(&settings);
        let weight = |d: f32| (d * u.falloff_mul + u.falloff_add).clamp(0.0, 1.0);
        assert_eq!(weight(1.999), 1.0);
        assert_eq!(weight(2.0), 0.0);
    }
}
