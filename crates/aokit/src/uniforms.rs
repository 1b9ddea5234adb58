//! GPU uniform structs. Each is mirrored once in WGSL; the tests prove the two layouts agree.

use bytemuck::{Pod, Zeroable};
use glam::{Vec2, Vec4};

use crate::methods;
use crate::noise;
use crate::projection::Projection;
use crate::settings::{AoSettings, SpatialSettings};

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
    pub uv_per_pixel: [f32; 2],
    pub ndc_offset: [f32; 2],
    /// The per-pixel kernel's first texel: the guard band, in texels of the grid. The kernel
    /// dispatches over the grid less this on each side and adds it to its thread's position.
    pub kernel_offset: [u32; 2],
}

impl ViewUniforms {
    /// The view of an image of `size` pixels, at full resolution.
    pub fn new(projection: &Projection, size: [u32; 2], frame_index: u32) -> Self {
        Self::scaled(projection, size, 1, frame_index)
    }

    /// The view of an image of `full_size` pixels on a grid `scale` times coarser:
    /// `ceil(full_size / scale)` texels, texel `c` covering pixels `c * scale ..
    /// (c + 1) * scale`. The grid's size is the texture's, for bounds and texel addressing;
    /// positions map through the image's exact extent, `full_size / scale` texels, so that the
    /// projection stays the input's when a side is not a multiple of `scale` (the last texel
    /// then reaches past the image).
    pub fn scaled(
        projection: &Projection,
        full_size: [u32; 2],
        scale: u32,
        frame_index: u32,
    ) -> Self {
        let grid = Vec2::from(full_size.map(|side| side.div_ceil(scale) as f32));
        let extent = Vec2::from(full_size.map(|side| side as f32)) / scale as f32;
        let linearize: Vec4 = projection.linearize_coefficients();
        Self {
            size: grid.to_array(),
            inv_size: grid.recip().to_array(),
            linearize: linearize.to_array(),
            ndc_to_view: projection.ndc_to_view_scale().to_array(),
            pixels_per_unit: projection.pixels_per_unit(extent.y),
            orthographic: if projection.is_orthographic() {
                1.0
            } else {
                0.0
            },
            far_ndc_depth: projection.far_ndc_depth(),
            frame_index,
            uv_per_pixel: extent.recip().to_array(),
            ndc_offset: projection.ndc_offset.to_array(),
            kernel_offset: [0; 2],
        }
    }
}

/// Mirrors `AoUniforms` in `shaders/common/ao.wgsl`: the settings of whichever method runs.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct AoUniforms {
    pub radius: f32,
    pub falloff_mul: f32,
    pub falloff_add: f32,
    pub intensity: f32,
    pub power: f32,
    pub max_radius_px: f32,
    pub min_radius_px: f32,
    pub bias: f32,
    pub angle_bias: f32,
    pub fade_mul: f32,
    pub fade_add: f32,
    pub thickness: f32,
    pub thickness_growth: f32,
    pub count: u32,
    pub steps: u32,
    pub flags: u32,
    pub step_power: f32,
    pub noise_kind: u32,
    pub noise_temporal: u32,
    pub mip_scale: f32,
}

/// `AoUniforms::flags` bits, mirrored as constants in `common/ao.wgsl`. Bent normals are the
/// kernels' `BENT_NORMALS` override instead (passes/kernel/method.rs).
pub(crate) mod flags {
    /// Divide slice integrals by their unoccluded integrals (GTAO).
    pub const NORMALIZE_SLICES: u32 = 1;
    /// `ue4-ssao`: the normal version rather than the depth-only one.
    pub const UE4_SSAO_NORMALS: u32 = 4;
    /// `vbao`: occluder thickness from the back faces' depth.
    pub const BACK_FACES: u32 = 8;
}

/// A method's part of [`AoUniforms`]: what its `count` and `steps` count, and its occluder
/// thickness (methods/).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct KernelCounts {
    pub count: u32,
    pub steps: u32,
    pub thickness: f32,
    pub thickness_growth: f32,
}

impl KernelCounts {
    /// Counts with no thickness.
    pub const fn new(count: u32, steps: u32) -> Self {
        Self {
            count,
            steps,
            thickness: 0.0,
            thickness_growth: 0.0,
        }
    }
}

/// Shortest fade the kernels use, as a fraction of the radius: `falloff = 0` (a hard cut) becomes
/// this so the weight stays a finite linear ramp; the difference is below any sample spacing.
const MIN_FALLOFF: f32 = 1e-4;

impl AoUniforms {
    pub fn new(settings: &AoSettings) -> Self {
        let radius = settings.radius * settings.radius_multiplier;
        let range = settings.falloff.max(MIN_FALLOFF) * radius;
        // AO weight over view depth: saturate(depth * fade_mul + fade_add), 1 everywhere
        // without a maximum distance; a zero-length fade becomes a step one thousandth as long.
        let max = settings.max_distance;
        let (fade_mul, fade_add) = if max > 0.0 {
            let fade = settings.distance_falloff.max(1e-3 * max);
            (-1.0 / fade, max / fade)
        } else {
            (0.0, 1.0)
        };
        let method = methods::spec(settings.method);
        let kernel = (method.kernel_counts)(settings, radius);
        let max_radius_px = settings.effective_max_radius_px();
        // Every method's bits, whichever runs: each kernel reads only its own.
        let bits = methods::REGISTRY
            .iter()
            .fold(0, |bits, method| bits | (method.flags)(settings));
        Self {
            radius,
            falloff_mul: -1.0 / range,
            falloff_add: radius / range,
            intensity: settings.intensity,
            power: settings.power,
            // The kernel measures in working texels; the limit is in the input's pixels, so
            // that a lower resolution covers the same screen area. The separable HBAO passes'
            // apron may lower it, and the widening stops there too.
            max_radius_px: max_radius_px / settings.resolution.scale() as f32,
            min_radius_px: settings.min_radius_px.min(max_radius_px)
                / settings.resolution.scale() as f32,
            bias: settings.bias * radius,
            angle_bias: settings.angle_bias,
            fade_mul,
            fade_add,
            thickness: kernel.thickness,
            thickness_growth: kernel.thickness_growth,
            count: kernel.count,
            steps: kernel.steps,
            flags: bits,
            step_power: settings.step_power,
            noise_kind: noise::kind_code(settings.noise.kind),
            noise_temporal: noise::temporal_code(settings.noise.temporal),
            mip_scale: (-settings.depth_mip_offset).exp2(),
        }
    }
}

/// Mirrors `DecodeUniforms` in `shaders/input/decode_normals.wgsl`: a `mat3x3<f32>`, each column
/// padded to 16 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct DecodeUniforms {
    pub to_view: [[f32; 4]; 3],
}

impl DecodeUniforms {
    pub fn new(to_view: glam::Mat3) -> Self {
        Self {
            to_view: [to_view.x_axis, to_view.y_axis, to_view.z_axis]
                .map(|c| c.extend(0.0).to_array()),
        }
    }
}

/// Mirrors `DebugUniforms` in `shaders/output/debug_view.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct DebugUniforms {
    pub view: u32,
    pub edge_threshold: f32,
    pub log_near: f32,
    pub inv_log_range: f32,
    pub depth_step: u32,
    pub scalar_step: u32,
    pub orthographic: u32,
}

/// Mirrors `SpatialUniforms` in `shaders/filter/spatial_filter.wgsl`: the spatial filter's weights,
/// the sigmas as reciprocals so that the shader multiplies. The radius, the depth weight's kind
/// and whether normals weigh in are the shader's `override`s.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct SpatialUniforms {
    pub spatial_scale: f32,
    pub depth_scale: f32,
    pub normal_power: f32,
}

impl SpatialUniforms {
    pub fn new(settings: &SpatialSettings) -> Self {
        Self {
            spatial_scale: settings.sigma.recip(),
            depth_scale: settings.depth_sigma.recip(),
            normal_power: settings.normal_power,
        }
    }
}

/// Mirrors `GuidedUniforms` in `shaders/filter/guided_filter.wgsl`: the guided filter's
/// regularisation. The window radius is the shader's `override`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct GuidedUniforms {
    pub epsilon: f32,
}

impl GuidedUniforms {
    pub fn new(settings: &SpatialSettings) -> Self {
        Self {
            epsilon: settings.guided_epsilon,
        }
    }
}

/// Mirrors `TemporalUniforms` in `shaders/filter/temporal_filter.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct TemporalUniforms {
    pub prev_view_from_view: [[f32; 4]; 4],
    pub prev_ndc_to_view: [f32; 2],
    pub prev_ndc_offset: [f32; 2],
    pub prev_orthographic: f32,
    pub blend: f32,
    pub variance_gamma: f32,
    pub depth_threshold: f32,
    pub flags: u32,
    pub _pad: u32,
    /// Where the frame's pixel (0, 0) lies in the motion vectors: the guard band when they are
    /// the input's overscan, 0 when cropped or downsampled to the frame.
    pub motion_offset: [i32; 2],
}

/// `TemporalUniforms::flags` bits, mirrored as constants in `temporal_filter.wgsl`.
pub(crate) mod temporal_flags {
    /// A previous frame of the same view exists and may be reprojected.
    pub const HISTORY: u32 = 1;
    /// Motion vectors replace the camera reprojection.
    pub const MOTION_VECTORS: u32 = 2;
    /// Blend the 3x3 same-surface mean instead of the pixel's own value.
    pub const FILTER_CURRENT: u32 = 4;
}

impl TemporalUniforms {
    /// `previous`: the transform from this frame's view space to the previous frame's, and the
    /// previous projection; `None` starts the history over. `motion_offset`: the frame's origin
    /// in the motion vectors, when there are some.
    pub fn new(
        settings: &crate::settings::TemporalSettings,
        previous: Option<(glam::Mat4, Projection)>,
        motion_offset: Option<u32>,
    ) -> Self {
        let (transform, projection) = previous.unzip();
        let mut flags = 0;
        if previous.is_some() {
            flags |= temporal_flags::HISTORY;
        }
        if motion_offset.is_some() {
            flags |= temporal_flags::MOTION_VECTORS;
        }
        if settings.filter_current {
            flags |= temporal_flags::FILTER_CURRENT;
        }
        Self {
            prev_view_from_view: transform.unwrap_or(glam::Mat4::IDENTITY).to_cols_array_2d(),
            prev_ndc_to_view: projection.map_or([1.0; 2], |p| p.ndc_to_view_scale().to_array()),
            prev_ndc_offset: projection.map_or([0.0; 2], |p| p.ndc_offset.to_array()),
            prev_orthographic: projection.map_or(0.0, |p| f32::from(u8::from(p.is_orthographic()))),
            blend: settings.blend,
            variance_gamma: settings.variance_gamma,
            depth_threshold: settings.depth_threshold,
            flags,
            _pad: 0,
            // A band is at most the input's size, which wgpu caps far below i32::MAX.
            motion_offset: [motion_offset.unwrap_or(0) as i32; 2],
        }
    }
}

/// Mirrors `UpsampleUniforms` in `shaders/resample/upsample.wgsl`: the one resampling setting that
/// is a value rather than a choice of code path (those are the shaders' `override`s).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct UpsampleUniforms {
    pub threshold: f32,
}

impl UpsampleUniforms {
    pub fn new(settings: &AoSettings) -> Self {
        Self {
            threshold: settings.upsample_threshold,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Method;
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
            uv_per_pixel,
            ndc_offset,
            kernel_offset,
        });
        shader::check_layout(
            &shader::LINEAR_DEPTH[0],
            "ViewUniforms",
            fields,
            size_of::<ViewUniforms>(),
        )
        .unwrap();
    }

    #[test]
    fn ao_uniforms_match_wgsl_in_every_method() {
        let fields = crate::field_offsets!(AoUniforms {
            radius,
            falloff_mul,
            falloff_add,
            intensity,
            power,
            max_radius_px,
            min_radius_px,
            bias,
            angle_bias,
            fade_mul,
            fade_add,
            thickness,
            thickness_growth,
            count,
            steps,
            flags,
            step_power,
            noise_kind,
            noise_temporal,
            mip_scale,
        });
        let separable_hbao = [shader::HBAO_ROWS, shader::HBAO_COLUMNS];
        for program in crate::Method::ALL
            .map(shader::method)
            .iter()
            .chain(&separable_hbao)
        {
            shader::check_layout(program, "AoUniforms", fields, size_of::<AoUniforms>()).unwrap();
        }
    }

    #[test]
    fn ao_flags_match_wgsl_and_ue4_ssao_and_vbao_set_theirs() {
        let module = shader::UE4_SSAO.validate().unwrap();
        for (name, bit) in [
            ("FLAG_NORMALIZE_SLICES", flags::NORMALIZE_SLICES),
            ("FLAG_UE4_SSAO_NORMALS", flags::UE4_SSAO_NORMALS),
        ] {
            assert_eq!(shader::u32_constant(&module, name), Some(bit), "{name}");
        }
        let mut settings = AoSettings::preset(Method::Ue4Ssao, crate::Preset::High);
        let uniforms = AoUniforms::new(&settings);
        assert_eq!((uniforms.count, uniforms.steps), (9, 1));
        assert_ne!(uniforms.flags & flags::UE4_SSAO_NORMALS, 0);
        settings.ue4_ssao.use_normals = false;
        assert_eq!(
            AoUniforms::new(&settings).flags & flags::UE4_SSAO_NORMALS,
            0
        );
        let vbao = shader::VBAO.validate().unwrap();
        assert_eq!(
            shader::u32_constant(&vbao, "FLAG_BACK_FACES"),
            Some(flags::BACK_FACES)
        );
        let measured = AoSettings::preset_with_back_faces(Method::Vbao, crate::Preset::High);
        assert_ne!(AoUniforms::new(&measured).flags & flags::BACK_FACES, 0);
    }

    #[test]
    fn decode_uniforms_match_wgsl_for_both_texel_types() {
        let fields = crate::field_offsets!(DecodeUniforms { to_view });
        for program in [shader::DECODE_NORMALS_UINT, shader::DECODE_NORMALS_FLOAT] {
            shader::check_layout(
                &program,
                "DecodeUniforms",
                fields,
                size_of::<DecodeUniforms>(),
            )
            .unwrap();
        }
    }

    #[test]
    fn debug_uniforms_and_codes_match_wgsl() {
        let fields = crate::field_offsets!(DebugUniforms {
            view,
            edge_threshold,
            log_near,
            inv_log_range,
            depth_step,
            scalar_step,
            orthographic,
        });
        shader::check_layout(
            &shader::DEBUG_VIEW,
            "DebugUniforms",
            fields,
            size_of::<DebugUniforms>(),
        )
        .unwrap();
    }

    #[test]
    fn spatial_uniforms_match_wgsl_in_both_passes() {
        let fields = crate::field_offsets!(SpatialUniforms {
            spatial_scale,
            depth_scale,
            normal_power,
        });
        for pass in [
            shader::SPATIAL_FILTER_HORIZONTAL[0],
            shader::SPATIAL_FILTER_VERTICAL[0],
        ] {
            shader::check_layout(
                &pass,
                "SpatialUniforms",
                fields,
                size_of::<SpatialUniforms>(),
            )
            .unwrap();
        }
    }

    #[test]
    fn guided_uniforms_match_wgsl_in_both_passes() {
        let fields = crate::field_offsets!(GuidedUniforms { epsilon });
        for pass in [
            shader::GUIDED_FILTER_COEFFICIENTS[0],
            shader::GUIDED_FILTER_OUTPUT,
        ] {
            shader::check_layout(&pass, "GuidedUniforms", fields, size_of::<GuidedUniforms>())
                .unwrap();
        }
    }

    #[test]
    fn temporal_uniforms_match_wgsl() {
        let fields = crate::field_offsets!(TemporalUniforms {
            prev_view_from_view,
            prev_ndc_to_view,
            prev_ndc_offset,
            prev_orthographic,
            blend,
            variance_gamma,
            depth_threshold,
            flags,
            motion_offset,
        });
        shader::check_layout(
            &shader::TEMPORAL_FILTER[0],
            "TemporalUniforms",
            fields,
            size_of::<TemporalUniforms>(),
        )
        .unwrap();
        let module = shader::TEMPORAL_FILTER[0].validate().unwrap();
        for (name, bit) in [
            ("FLAG_HISTORY", temporal_flags::HISTORY),
            ("FLAG_MOTION_VECTORS", temporal_flags::MOTION_VECTORS),
            ("FLAG_FILTER_CURRENT", temporal_flags::FILTER_CURRENT),
        ] {
            assert_eq!(shader::u32_constant(&module, name), Some(bit), "{name}");
        }
        // A jittered previous frame is reprojected through its own offset, as the current one
        // through its (ViewUniforms::ndc_offset).
        let projection = Projection::perspective(1.0, 1.5, 0.1, None);
        let previous = projection.with_jitter(Vec2::new(0.5, -0.5), [300, 200]);
        let settings = crate::settings::TemporalSettings::default();
        let uniforms =
            TemporalUniforms::new(&settings, Some((glam::Mat4::IDENTITY, previous)), None);
        assert_eq!(uniforms.prev_ndc_offset, previous.ndc_offset.to_array());
        let current = projection.with_jitter(Vec2::new(-0.5, 0.5), [300, 200]);
        assert_eq!(
            ViewUniforms::new(&current, [300, 200], 1).ndc_offset,
            current.ndc_offset.to_array()
        );
    }

    #[test]
    fn resample_uniforms_and_codes_match_wgsl_in_both_passes() {
        let fields = crate::field_offsets!(UpsampleUniforms { threshold });
        for pass in shader::UPSAMPLE {
            shader::check_layout(
                &pass,
                "UpsampleUniforms",
                fields,
                size_of::<UpsampleUniforms>(),
            )
            .unwrap();
        }
        for pass in [shader::DOWNSAMPLE[0][0], shader::UPSAMPLE[0]] {
            let module = pass.validate().unwrap();
            let constant = |name: &str| shader::u32_constant(&module, name);
            for mode in crate::Downsample::ALL {
                let name = format!("DOWNSAMPLE_{}", mode.name().to_uppercase());
                assert_eq!(constant(&name), Some(mode as u32), "{name}");
            }
            for mode in crate::Upsample::ALL {
                let name = format!("UPSAMPLE_{}", mode.name().replace('-', "_").to_uppercase());
                assert_eq!(constant(&name), Some(mode as u32), "{name}");
            }
        }
    }

    #[test]
    fn a_coarser_grid_keeps_the_image_extent_and_the_projection() {
        let projection = Projection::perspective(1.0, 481.0 / 270.0, 0.1, None);
        let full = ViewUniforms::new(&projection, [481, 270], 3);
        let half = ViewUniforms::scaled(&projection, [481, 270], 2, 3);
        assert_eq!(half.size, [241.0, 135.0]);
        assert_eq!(half.inv_size, [1.0 / 241.0, 1.0 / 135.0]);
        // The image ends half a texel before the grid's last texel does.
        assert_eq!(half.uv_per_pixel, [1.0 / 240.5, 1.0 / 135.0]);
        assert_eq!(half.pixels_per_unit, full.pixels_per_unit / 2.0);
        assert_eq!(full.uv_per_pixel, full.inv_size);
        assert_eq!(
            (half.linearize, half.ndc_to_view, half.frame_index),
            (full.linearize, full.ndc_to_view, 3)
        );
    }

    #[test]
    fn distance_fade_is_one_before_the_falloff_and_zero_past_the_maximum() {
        let settings = AoSettings {
            max_distance: 20.0,
            distance_falloff: 5.0,
            ..AoSettings::default()
        };
        let u = AoUniforms::new(&settings);
        let fade = |d: f32| (d * u.fade_mul + u.fade_add).clamp(0.0, 1.0);
        assert_eq!(fade(10.0), 1.0);
        assert!((fade(17.5) - 0.5).abs() < 1e-6);
        assert_eq!(fade(20.0), 0.0);
        let none = AoUniforms::new(&AoSettings::default());
        assert_eq!((none.fade_mul, none.fade_add), (0.0, 1.0));
    }

    #[test]
    fn falloff_weight_is_one_inside_and_zero_at_the_radius() {
        let mut settings = AoSettings {
            radius: 2.0,
            radius_multiplier: 1.0,
            falloff: 0.25,
            ..AoSettings::default()
        };
        let u = AoUniforms::new(&settings);
        let weight = |d: f32| (d * u.falloff_mul + u.falloff_add).clamp(0.0, 1.0);
        assert_eq!(weight(1.0), 1.0);
        assert_eq!(weight(1.5), 1.0);
        assert!((weight(1.75) - 0.5).abs() < 1e-6);
        assert_eq!(weight(2.0), 0.0);
        settings.falloff = 0.0;
        let u = AoUniforms::new(&settings);
        let weight = |d: f32| (d * u.falloff_mul + u.falloff_add).clamp(0.0, 1.0);
        assert_eq!(weight(1.999), 1.0);
        assert_eq!(weight(2.0), 0.0);
    }
}
