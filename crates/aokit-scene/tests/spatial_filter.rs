//! The spatial filter on rendered frames, on whatever adapter exists (lavapipe in CI), against a
//! CPU implementation of the same separable bilateral blur (docs/denoise.md).

mod common;

use aokit::{AoSettings, DepthWeight, SpatialSettings};
use aokit_scene::{Builtin, Frame, Renderer};
use common::gpu;
use glam::Vec3;

const SIZE: [u32; 2] = [160, 96];

/// The weight of a neighbour `offset` pixels from the centre, as `spatial_filter.wgsl` computes
/// it: 0 without a surface, else the spatial Gaussian times the depth weight of the relative
/// depth difference, times the normal weight when `normal_power` is above 0.
fn weight(s: &SpatialSettings, offset: i32, depth: f32, centre: f32, n: Vec3, n0: Vec3) -> f32 {
    if depth == 0.0 {
        return 0.0;
    }
    let x = offset as f32 / s.sigma;
    let r = (depth - centre).abs() / centre / s.depth_sigma;
    let mut w = match s.depth_weight {
        DepthWeight::Gaussian => (-0.5 * (x * x + r * r)).exp(),
        DepthWeight::Threshold if r < 1.0 => (-0.5 * x * x).exp(),
        DepthWeight::Threshold => 0.0,
    };
    if s.normal_power > 0.0 {
        w *= n.dot(n0).max(0.0).powf(s.normal_power);
    }
    w
}

/// One pass along `axis` (0: rows, 1: columns) over `ao`: pixels outside the image and sky
/// pixels never contribute, and sky pixels read 1.
fn filter_axis(s: &SpatialSettings, frame: &Frame, ao: &[f32], axis: usize) -> Vec<f32> {
    let [width, height] = frame.size.map(|v| v as i32);
    let index = |x: i32, y: i32| (y * width + x) as usize;
    let mut out = Vec::with_capacity(ao.len());
    for y in 0..height {
        for x in 0..width {
            let centre = index(x, y);
            let depth = frame.linear_depth[centre];
            if depth == 0.0 {
                out.push(1.0);
                continue;
            }
            let (mut sum, mut weight_sum) = (0.0, 0.0);
            let radius = s.radius as i32;
            for offset in -radius..=radius {
                let (nx, ny) = if axis == 0 {
                    (x + offset, y)
                } else {
                    (x, y + offset)
                };
                if nx < 0 || ny < 0 || nx >= width || ny >= height {
                    continue;
                }
                let i = index(nx, ny);
                let w = weight(
                    s,
                    offset,
                    frame.linear_depth[i],
                    depth,
                    frame.normals[i],
                    frame.normals[centre],
                );
                sum += w * ao[i];
                weight_sum += w;
            }
            out.push(sum / weight_sum);
        }
    }
    out
}

#[test]
fn the_gpu_filter_matches_the_cpu_one_on_rendered_frames() {
    let gpu = gpu();
    let base = SpatialSettings {
        enabled: true,
        ..SpatialSettings::default()
    };
    let filters = [
        SpatialSettings { radius: 1, ..base },
        SpatialSettings {
            radius: 8,
            sigma: 4.0,
            depth_weight: DepthWeight::Threshold,
            normal_power: 8.0,
            ..base
        },
        SpatialSettings {
            radius: 5,
            sigma: 3.0,
            depth_sigma: 0.02,
            normal_power: 2.0,
            ..base
        },
    ];
    for builtin in [Builtin::Room, Builtin::Stairs, Builtin::Thin] {
        let scene = builtin.build();
        let camera = &scene.cameras[0];
        let raw_settings = AoSettings {
            radius: scene.suggested_radius.unwrap_or(1.0),
            ..AoSettings::default()
        };
        let mut renderer = Renderer::new(&gpu, &scene, &raw_settings).unwrap();
        let raw = renderer.render(&gpu, camera, SIZE, 3).unwrap();
        for spatial in filters {
            let settings = AoSettings {
                spatial,
                ..raw_settings
            };
            renderer.set_settings(&gpu, &settings).unwrap();
            let filtered = renderer.render(&gpu, camera, SIZE, 3).unwrap();
            assert_eq!(filtered.linear_depth, raw.linear_depth);
            let horizontal = filter_axis(&spatial, &raw, &raw.ao, 0);
            let expected = filter_axis(&spatial, &raw, &horizontal, 1);
            let mut changed = 0;
            for (i, (&gpu_ao, &cpu_ao)) in filtered.ao.iter().zip(&expected).enumerate() {
                let view = format!("{} / {spatial:?} / pixel {i}", scene.name);
                assert!(
                    (gpu_ao - cpu_ao).abs() < 1e-4,
                    "{view}: GPU {gpu_ao}, CPU {cpu_ao}"
                );
                if raw.linear_depth[i] == 0.0 {
                    assert_eq!(gpu_ao, 1.0, "{view}: sky");
                }
                changed += usize::from((gpu_ao - raw.ao[i]).abs() > 1e-3);
            }
            // The comparison means something only if the filter changed the image.
            assert!(
                changed > filtered.ao.len() / 10,
                "{}: {changed}",
                scene.name
            );
        }
    }
}
