//! XeGTAO's constant buffer, from aokit's [`Projection`] and radius, with XeGTAO's default
//! heuristics.

use anyhow::{Result, bail};
use aokit::Projection;
use bytemuck::{Pod, Zeroable};

/// XeGTAO's defaults for what aokit does not map (XeGTAO.h, `XE_GTAO_DEFAULT_*`); the wrapper
/// compiles with `XE_GTAO_USE_DEFAULT_CONSTANTS`, as its integration does when they hold, so
/// the shader reads most of them as literals and these fill the buffer alike.
const RADIUS_MULTIPLIER: f32 = 1.457;
const FALLOFF_RANGE: f32 = 0.615;
const SAMPLE_DISTRIBUTION_POWER: f32 = 2.0;
const THIN_OCCLUDER_COMPENSATION: f32 = 0.0;
const FINAL_VALUE_POWER: f32 = 2.2;
const DEPTH_MIP_SAMPLING_OFFSET: f32 = 3.3;
/// Blur strength of the denoiser's centre pixel: XeGTAO's, and one so large that it leaves the
/// term alone where its denoiser is off.
const DENOISE_BLUR_BETA: f32 = 1.2;
const NO_DENOISE_BLUR_BETA: f32 = 1e4;
/// Added to the depth a reverse-Z infinite projection leaves for the sky (0), which XeGTAO's
/// `mul / (add - depth)` would turn into a division by zero: the sky lands beyond XeGTAO's
/// depth clamp, far away as in a renderer with a far plane, and no surface's depth (at least
/// `near / depth`, far above 1e-30) changes.
const SKY_OFFSET: f32 = 1e-30;

/// `GTAOConstants` of XeGTAO.h, field by field, each named as its field there in snake case
/// (96 bytes, no padding in std140).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GtaoConstants {
    pub viewport_size: [i32; 2],
    pub viewport_pixel_size: [f32; 2],
    /// Linear depth = `x / (y - depth)`.
    pub depth_unpack: [f32; 2],
    pub camera_tan_half_fov: [f32; 2],
    /// View xy at depth 1 = `mul * uv + add`, uv from the top-left corner.
    pub ndc_to_view_mul: [f32; 2],
    pub ndc_to_view_add: [f32; 2],
    pub ndc_to_view_mul_x_pixel_size: [f32; 2],
    pub effect_radius: f32,
    pub effect_falloff_range: f32,
    pub radius_multiplier: f32,
    pub padding: f32,
    pub final_value_power: f32,
    pub denoise_blur_beta: f32,
    pub sample_distribution_power: f32,
    pub thin_occluder_compensation: f32,
    pub depth_mip_sampling_offset: f32,
    pub noise_index: i32,
}

impl GtaoConstants {
    /// The constants for `projection` on images of `size`, `radius` world units, and
    /// XeGTAO's `denoise_passes` (0: its denoiser off). Noise index 0: no temporal
    /// accumulation.
    pub fn new(
        projection: &Projection,
        size: [u32; 2],
        radius: f32,
        denoise_passes: u32,
    ) -> Result<Self> {
        let pixel_size = [1.0 / size[0] as f32, 1.0 / size[1] as f32];
        let tan_half = projection.ndc_to_view_scale();
        let offset = projection.ndc_offset;
        // aokit's view position is (ndc - offset) * tan_half * depth, with ndc = 2u - 1 across
        // and 1 - 2v down: XeGTAO's mul and add, which take y up and z forward as aokit's
        // -z.
        let mul = [2.0 * tan_half.x, -2.0 * tan_half.y];
        Ok(Self {
            viewport_size: [size[0] as i32, size[1] as i32],
            viewport_pixel_size: pixel_size,
            depth_unpack: depth_unpack(projection)?,
            camera_tan_half_fov: tan_half.to_array(),
            ndc_to_view_mul: mul,
            ndc_to_view_add: [
                -tan_half.x * (1.0 + offset.x),
                tan_half.y * (1.0 - offset.y),
            ],
            ndc_to_view_mul_x_pixel_size: [mul[0] * pixel_size[0], mul[1] * pixel_size[1]],
            effect_radius: radius,
            effect_falloff_range: FALLOFF_RANGE,
            radius_multiplier: RADIUS_MULTIPLIER,
            padding: 0.0,
            final_value_power: FINAL_VALUE_POWER,
            denoise_blur_beta: if denoise_passes == 0 {
                NO_DENOISE_BLUR_BETA
            } else {
                DENOISE_BLUR_BETA
            },
            sample_distribution_power: SAMPLE_DISTRIBUTION_POWER,
            thin_occluder_compensation: THIN_OCCLUDER_COMPENSATION,
            depth_mip_sampling_offset: DEPTH_MIP_SAMPLING_OFFSET,
            noise_index: 0,
        })
    }
}

/// XeGTAO's `(mul, add)` with linear depth = `mul / (add - depth)`: aokit linearises a
/// perspective depth as `b / (depth + a)` (`Projection::linearize_coefficients`), the same
/// form. Orthographic depth is linear in distance, which this form cannot express.
fn depth_unpack(projection: &Projection) -> Result<[f32; 2]> {
    if projection.is_orthographic() {
        bail!(
            "XeGTAO reads perspective depth only (linear depth = mul / (add - depth)); this \
             camera is orthographic"
        );
    }
    let c = projection.linearize_coefficients();
    let add = -c.w;
    let sky = if projection.reverse_z && projection.far.is_none() {
        SKY_OFFSET
    } else {
        0.0
    };
    Ok([-c.y, add - sky])
}

#[cfg(test)]
mod tests {
    use super::*;
    use aokit::projection::pixel_to_ndc;
    use glam::{Vec2, Vec3};

    /// XeGTAO.hlsli's view depth and view position, as the shader computes them.
    fn xegtao_depth(c: &GtaoConstants, depth: f32) -> f32 {
        c.depth_unpack[0] / (c.depth_unpack[1] - depth)
    }

    fn xegtao_position(c: &GtaoConstants, uv: Vec2, depth: f32) -> Vec3 {
        let mul = Vec2::from(c.ndc_to_view_mul);
        let add = Vec2::from(c.ndc_to_view_add);
        ((mul * uv + add) * depth).extend(depth)
    }

    #[test]
    fn depth_and_positions_match_aokit_in_every_perspective_convention() {
        let size = [64, 40];
        for reverse_z in [false, true] {
            for far in [Some(80.0), None] {
                for offset in [Vec2::ZERO, Vec2::new(0.2, -0.1)] {
                    let p = Projection::perspective(1.1, 1.6, 0.05, far)
                        .with_reverse_z(reverse_z)
                        .with_ndc_offset(offset);
                    let c = GtaoConstants::new(&p, size, 0.5, 0).unwrap();
                    for z in [0.06, 1.0, 7.5, 60.0] {
                        let d = xegtao_depth(&c, p.ndc_depth(z));
                        assert!((d - z).abs() < 1e-4 * z, "{p:?}: {z} -> {d}");
                        let pixel = Vec2::new(13.0, 31.0);
                        let uv = (pixel + 0.5) / Vec2::new(64.0, 40.0);
                        let aokit = p.view_position_from_linear(
                            pixel_to_ndc(pixel, Vec2::new(64.0, 40.0)),
                            z,
                        );
                        let theirs = xegtao_position(&c, uv, z);
                        let flipped = Vec3::new(aokit.x, aokit.y, -aokit.z);
                        assert!((theirs - flipped).length() < 1e-4 * z, "{theirs} {flipped}");
                    }
                    // The sky: far away (a finite far plane, or beyond XeGTAO's clamp).
                    let sky = xegtao_depth(&c, p.far_ndc_depth());
                    assert!(sky >= far.unwrap_or(65504.0) * 0.999, "{p:?}: sky at {sky}");
                }
            }
        }
    }

    #[test]
    fn orthographic_depth_is_an_error_and_the_denoiser_sets_the_blur() {
        let ortho = Projection::orthographic(10.0, 1.0, 0.1, 100.0);
        let err = GtaoConstants::new(&ortho, [8, 8], 1.0, 0)
            .unwrap_err()
            .to_string();
        assert!(err.contains("orthographic"), "{err}");
        let p = Projection::perspective(1.0, 1.0, 0.1, None);
        assert_eq!(
            GtaoConstants::new(&p, [8, 8], 1.0, 0)
                .unwrap()
                .denoise_blur_beta,
            1e4
        );
        assert_eq!(
            GtaoConstants::new(&p, [8, 8], 1.0, 2)
                .unwrap()
                .denoise_blur_beta,
            1.2
        );
        assert_eq!(std::mem::size_of::<GtaoConstants>(), 96);
    }
}
