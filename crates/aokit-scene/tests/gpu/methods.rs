//! Every AO method on the built-in scenes, on whatever adapter exists (lavapipe in CI).

use crate::common;

use aokit::{
    AoSettings, DepthMips, GpuContext, Method, NoiseKind, NoiseSettings, OffscreenSamples, Preset,
    SampleDepth, SliceMarch, TemporalOffset,
};
use aokit_scene::{Builtin, Camera, Frame, Lens, Renderer, Scene};
use common::{
    assert_in_range_with_sky_at_one, covered, gpu, mean_abs_difference, pixel_of, render_frame,
    scene_settings, trace,
};
use glam::Vec3;

const SIZE: [u32; 2] = [160, 96];

fn render(gpu: &GpuContext, scene: &Scene, camera: &Camera, settings: &AoSettings) -> Frame {
    render_frame(gpu, scene, camera, settings, SIZE)
}

#[test]
fn every_method_writes_finite_ao_in_range_with_sky_left_at_one() {
    let gpu = gpu();
    for builtin in Builtin::ALL {
        let scene = builtin.build();
        for camera in &scene.cameras {
            for method in Method::ALL {
                let frame = render(
                    &gpu,
                    &scene,
                    camera,
                    &scene_settings(&scene, method, Preset::Medium),
                );
                let view = format!("{} / {} / {}", method.name(), scene.name, camera.name);
                assert_in_range_with_sky_at_one(&frame, &view);
            }
        }
    }
}

#[test]
fn every_noise_kind_renders_every_method_in_range_and_unbiased() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    let mut renderer = Renderer::new(&gpu, &scene, &AoSettings::default()).unwrap();
    // Blue noise first: its two values are independent and uniform, the others are compared
    // with it.
    let mut kinds: Vec<NoiseSettings> = [NoiseKind::Blue]
        .into_iter()
        .chain(NoiseKind::ALL.into_iter().filter(|&k| k != NoiseKind::Blue))
        .map(|kind| NoiseSettings {
            kind,
            ..NoiseSettings::default()
        })
        .collect();
    kinds.push(NoiseSettings {
        kind: NoiseKind::Blue,
        blue_size: 128,
        temporal: TemporalOffset::R2,
    });
    for method in Method::ALL {
        let mut blue: Option<Vec<f32>> = None;
        for noise in &kinds {
            let ao_settings = AoSettings {
                noise: *noise,
                ..scene_settings(&scene, method, Preset::Medium)
            };
            renderer.set_settings(&gpu, &ao_settings).unwrap();
            for frame_index in [0, 5] {
                let frame = renderer.render(&gpu, camera, SIZE, frame_index).unwrap();
                let view = format!(
                    "{} / {} {} {} / frame {frame_index}",
                    method.name(),
                    noise.kind.name(),
                    noise.blue_size,
                    noise.temporal.name()
                );
                assert_in_range_with_sky_at_one(&frame, &view);
                // Noise only rotates and shifts the samples: the pattern changes, the mean
                // hardly does. The point methods' means move most, by up to 0.02: interleaved
                // gradient noise's second value is its first shifted (docs/noise.md), and the
                // GTAO and Bayer patterns hold 16 rotations a frame.
                let values: Vec<f32> = covered(&frame).collect();
                let mean = values.iter().sum::<f32>() / values.len() as f32;
                match &blue {
                    None => blue = Some(values),
                    // MSVO samples a fixed pattern of whole texels at each level, as MiniEngine
                    // and Unity do: no noise reaches it.
                    Some(reference) if method == Method::Msvo => {
                        assert!(values == *reference, "{view}: AO differs from blue noise's");
                    }
                    Some(reference) => {
                        assert!(values != *reference, "{view}: same AO as blue noise");
                        let reference_mean = reference.iter().sum::<f32>() / reference.len() as f32;
                        assert!(
                            (mean - reference_mean).abs() < 0.025,
                            "{view}: mean AO {mean}, {reference_mean} with blue noise at frame 0"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn an_open_plane_is_unoccluded_except_for_crytek_grey() {
    let gpu = gpu();
    let scene = Builtin::Open.build();
    for camera in &scene.cameras {
        for method in Method::ALL {
            let frame = render(
                &gpu,
                &scene,
                camera,
                &scene_settings(&scene, method, Preset::High),
            );
            let values: Vec<f32> = covered(&frame).collect();
            let mean = values.iter().sum::<f32>() / values.len() as f32;
            let lowest = values.iter().copied().fold(1.0f32, f32::min);
            let view = format!("{} / {}", method.name(), camera.name);
            if method == Method::SsaoCrytek {
                // Half of a sphere centred on a plane lies behind it: the 2007 look. Seen at a
                // grazing angle, the depth gap behind the plane outgrows the range check for
                // part of that half, and the plane lightens.
                assert!((0.45..0.75).contains(&mean), "{view}: mean {mean}");
            } else {
                assert!(mean > 0.99, "{view}: mean {mean}");
                // SSAO compares single points with the depth buffer: on the plane's farthest
                // rows before the sky, seen almost edge-on (20% depth per row), the nearest
                // texel rises above points just over the plane; the `high` preset's tuned power
                // (1.4) and falloff deepen it: 0.73 from above, 0.64 from the low camera. The
                // slice methods place their samples on the surface itself.
                let floor = if method == Method::Ssao { 0.6 } else { 0.99 };
                assert!(lowest > floor, "{view}: lowest {lowest}");
            }
        }
    }
}

#[test]
fn every_method_darkens_room_corners_more_than_open_floor() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    for method in Method::ALL {
        let frame = render(
            &gpu,
            &scene,
            camera,
            &scene_settings(&scene, method, Preset::Ultra),
        );
        let open_floor = frame.ao[pixel_of(&frame, Vec3::new(-0.3, 0.0, 2.5))];
        let corner = frame.ao[pixel_of(&frame, Vec3::new(3.93, 0.06, -3.93))];
        let wall_foot = frame.ao[pixel_of(&frame, Vec3::new(0.0, 0.05, -3.95))];
        // HBAO+ darkens least: its weakness on surfaces seen at grazing angles
        // (docs/methods/hbao-plus.md).
        // Unreal's SSAO darkens the wall's foot least (0.97 here): the floor in front rises
        // towards the eye by half the radius per pixel at this size, and Unreal's weight
        // drops all but its nearest samples (docs/methods/ue4-ssao.md).
        let wall_margin = if method == Method::Ue4Ssao {
            0.02
        } else {
            0.05
        };
        assert!(
            corner < open_floor - 0.05 && wall_foot < open_floor - wall_margin,
            "{}: corner {corner}, wall foot {wall_foot}, open floor {open_floor}",
            method.name()
        );
    }
}

fn angle_deg(a: Vec3, b: Vec3) -> f32 {
    a.normalize()
        .dot(b.normalize())
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

#[test]
fn bent_normals_follow_the_normal_on_open_ground_and_lean_out_of_corners() {
    let gpu = gpu();
    for method in [Method::Gtao, Method::Vbao] {
        let open = Builtin::Open.build();
        let frame = render(
            &gpu,
            &open,
            &open.cameras[0],
            &AoSettings {
                bent_normals: true,
                ..scene_settings(&open, method, Preset::High)
            },
        );
        let bent = frame
            .bent_normals
            .as_ref()
            .expect("bent normals were asked for");
        for (i, (b, n)) in bent.iter().zip(&frame.normals).enumerate() {
            if frame.linear_depth[i] > 0.0 {
                assert!(
                    angle_deg(*b, *n) < 3.0,
                    "{}: open ground pixel {i}: bent {b}, normal {n}",
                    method.name()
                );
            }
        }

        // On the floor at the foot of the right wall the unoccluded directions lean away from it.
        let room = Builtin::Room.build();
        let frame = render(
            &gpu,
            &room,
            &room.cameras[0],
            &AoSettings {
                bent_normals: true,
                ..scene_settings(&room, method, Preset::Ultra)
            },
        );
        let i = pixel_of(&frame, Vec3::new(3.8, 0.0, 1.0));
        let bent = frame.bent_normals.as_ref().unwrap()[i];
        let away_from_wall = frame.view_from_world.transform_vector3(Vec3::NEG_X);
        assert!(
            bent.dot(away_from_wall) > 0.1,
            "{}: bent normal {bent} at the wall's foot does not lean away from it",
            method.name()
        );
    }
}

/// RMSE of each method's AO against a small ray-traced reference of the same view.
fn rmse_against_reference(gpu: &GpuContext, scene: &Scene, methods: &[Method]) -> Vec<f64> {
    let camera = &scene.cameras[0];
    let traced = trace(scene, camera, SIZE, 128);
    methods
        .iter()
        .map(|&method| {
            let frame = render(
                gpu,
                scene,
                camera,
                &scene_settings(scene, method, Preset::High),
            );
            let (sum, count) = frame
                .ao
                .iter()
                .zip(&traced.ao)
                .zip(&traced.linear_depth)
                .filter(|(_, d)| **d > 0.0)
                .fold((0.0, 0usize), |(s, c), ((a, r), _)| {
                    (s + f64::from(a - r).powi(2), c + 1)
                });
            (sum / count as f64).sqrt()
        })
        .collect()
}

#[test]
fn vbao_beats_gtao_behind_thin_objects_and_gtao_beats_both_ssaos_in_the_room() {
    let gpu = gpu();
    let thin = rmse_against_reference(&gpu, &Builtin::Thin.build(), &[Method::Gtao, Method::Vbao]);
    assert!(
        thin[1] < thin[0],
        "thin: VBAO RMSE {} vs GTAO {}",
        thin[1],
        thin[0]
    );
    // Not HBAO: with the presets of the converged tuning the two lie within 2% of each other
    // here (GTAO 0.0557, HBAO 0.0545 at this size; 0.0545 and 0.0547 at 480x270), and HBAO is
    // lower on Sponza (docs/methods.md, "Against the targets").
    let room = rmse_against_reference(
        &gpu,
        &Builtin::Room.build(),
        &[Method::Gtao, Method::Ssao, Method::SsaoCrytek],
    );
    for (name, rmse) in ["ssao", "ssao-crytek"].iter().zip(&room[1..]) {
        assert!(
            room[0] < *rmse,
            "room: GTAO RMSE {} vs {name} {rmse}",
            room[0]
        );
    }
}

#[test]
fn vbao_leaves_an_open_plane_unoccluded_with_and_without_back_faces() {
    let gpu = gpu();
    let scene = Builtin::Open.build();
    let radius = scene.suggested_radius.unwrap_or(1.0);
    for settings in [
        AoSettings::preset(Method::Vbao, Preset::High),
        AoSettings::preset_with_back_faces(Method::Vbao, Preset::High),
    ] {
        let settings = AoSettings { radius, ..settings };
        for camera in &scene.cameras {
            // Two sizes: the samples, and how far inside the hemisphere rounding puts them,
            // differ between them.
            for size in [SIZE, [320, 180]] {
                let frame = render_frame(&gpu, &scene, camera, &settings, size);
                let worst = covered(&frame).fold(1.0f32, f32::min);
                assert!(
                    worst >= 0.999,
                    "back faces {}, camera {} at {size:?}: lowest AO {worst} on an open plane",
                    settings.vbao.back_faces,
                    camera.name
                );
            }
        }
    }
}

#[test]
fn slice_methods_leave_an_open_plane_unoccluded_with_either_depth_read() {
    let gpu = gpu();
    let scene = Builtin::Open.build();
    // Seen orthographically the plane recedes at the same slope up to the frame's edge: samples
    // past it that kept the edge's depth (an earlier `clamp`) rose into a wall there (AO 0.63).
    let orthographic = Camera {
        name: "orthographic".into(),
        lens: Lens::Orthographic { height: 12.0 },
        ..scene.cameras[0].clone()
    };
    let cameras: Vec<&Camera> = scene.cameras.iter().chain([&orthographic]).collect();
    for method in Method::ALL.into_iter().filter(|m| m.marches_slices()) {
        for (sample_depth, depth_mips, offscreen_samples) in [
            (
                SampleDepth::Nearest,
                DepthMips::Off,
                OffscreenSamples::Unoccluded,
            ),
            (
                SampleDepth::Nearest,
                DepthMips::Off,
                OffscreenSamples::Clamp,
            ),
            (
                SampleDepth::Nearest,
                DepthMips::Off,
                OffscreenSamples::Extend,
            ),
            (
                SampleDepth::Nearest,
                DepthMips::Fp32,
                OffscreenSamples::Unoccluded,
            ),
            (
                SampleDepth::Nearest,
                DepthMips::Fp32,
                OffscreenSamples::Clamp,
            ),
            (
                SampleDepth::Interpolated,
                DepthMips::Off,
                OffscreenSamples::Unoccluded,
            ),
            (
                SampleDepth::Interpolated,
                DepthMips::Off,
                OffscreenSamples::Clamp,
            ),
        ] {
            let settings = AoSettings {
                sample_depth,
                depth_mips,
                offscreen_samples,
                ..scene_settings(&scene, method, Preset::High)
            };
            for &camera in &cameras {
                let frame = render(&gpu, &scene, camera, &settings);
                let worst = covered(&frame).fold(1.0f32, f32::min);
                assert!(
                    worst >= 0.999,
                    "{} with {} depth, mips {}, off screen {}, camera {}: lowest AO {worst} on \
                     an open plane",
                    method.name(),
                    sample_depth.name(),
                    depth_mips.name(),
                    offscreen_samples.name(),
                    camera.name
                );
            }
        }
    }
}

/// A plane seen through a perspective and an orthographic projection whose pixels are not
/// square: a step along a slice on screen moves the view ray in a direction other than the
/// screen direction's, and a slice whose plane ignored that (as it did before) tilted against
/// the samples' rays, which rose off the plane (lowest AO 0.64 to 0.95 for HBAO, GTAO and
/// VBAO).
#[test]
fn slice_methods_leave_an_open_plane_unoccluded_with_pixels_that_are_not_square() {
    let gpu = gpu();
    let size = [160u32, 96];
    // Each pixel 2.5 times as wide as it is tall.
    let aspect = 2.5 * size[0] as f32 / size[1] as f32;
    // A floor 1.5 below the eye, tilted a little sideways so that no slice runs along a
    // symmetry of it: seen to its horizon in perspective; tilted towards the eye as well for the
    // orthographic view, which would see it edge-on, and cut where it comes within 1 of the eye
    // (closer, a texel's depth spreads by more than DEPTH_EDGE across it).
    let offset = -1.5;
    let mut failures = Vec::new();
    for (projection, normal, depths) in [
        (
            aokit::Projection::perspective(1.0, aspect, 0.1, None),
            Vec3::new(0.25, 1.0, 0.0).normalize(),
            0.0..200.0,
        ),
        (
            aokit::Projection::orthographic(6.0, aspect, 0.1, 100.0),
            Vec3::new(0.25, 1.0, 0.3).normalize(),
            1.0..90.0,
        ),
    ] {
        let depth: Vec<f32> = (0..size[1])
            .flat_map(|y| (0..size[0]).map(move |x| (x, y)))
            .map(|(x, y)| {
                let ndc = aokit::projection::pixel_to_ndc(
                    glam::Vec2::new(x as f32, y as f32),
                    glam::Vec2::new(size[0] as f32, size[1] as f32),
                );
                // The pixel's view ray is near + t * along for linear depth t; it meets the
                // plane at depth t.
                let near = projection.view_position_from_linear(ndc, 0.0);
                let along = projection.view_position_from_linear(ndc, 1.0) - near;
                let t = (offset - normal.dot(near)) / normal.dot(along);
                if t > depths.start && t < depths.end {
                    t
                } else {
                    0.0
                }
            })
            .collect();
        let covered_count = depth.iter().filter(|&&d| d > 0.0).count();
        assert!(
            covered_count > depth.len() / 3,
            "the plane should fill much of the view"
        );
        let texture = common::linear_depth_texture(&gpu, size, &depth);
        // The plane's own normal, so that no normal reconstructed from depth at the plane's
        // ends (where its depth meets the sky) tilts.
        let encoding = AoSettings::default().normals.encoding;
        let normal_texels = aokit::normals::encode_texels(encoding, &vec![normal; depth.len()]);
        let normals = aokit::gpu::upload_texture_2d(
            &gpu.device,
            &gpu.queue,
            "plane normals",
            size,
            encoding.texture_format(),
            &normal_texels,
        )
        .unwrap();
        let inputs = aokit::AoInputs {
            normals: Some((&normals).into()),
            ..aokit::AoInputs::new(&texture, projection)
        };
        for method in Method::ALL.into_iter().filter(|m| m.marches_slices()) {
            for slice_march in [SliceMarch::Lean, SliceMarch::General] {
                let settings = AoSettings {
                    radius: 1.0,
                    slice_march,
                    ..AoSettings::preset(method, Preset::High)
                };
                let mut pipeline =
                    aokit::AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
                let ao = common::encode_frame(&gpu, &mut pipeline, &inputs, |outputs| {
                    aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, outputs.raw_ao).unwrap()
                });
                let worst = ao
                    .iter()
                    .zip(&depth)
                    .filter(|&(_, &d)| d > 0.0)
                    .fold(1.0f32, |worst, (&a, _)| worst.min(a));
                if worst < 0.999 {
                    failures.push(format!(
                        "{} with the {} march, {:?}: lowest AO {worst}",
                        method.name(),
                        slice_march.name(),
                        projection.kind
                    ));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "an open plane seen through pixels 2.5 times as wide as tall:\n{}",
        failures.join("\n")
    );
}

#[test]
fn the_nearest_depth_read_moves_the_slice_methods_ao_a_little_and_switches_at_runtime() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    for method in Method::ALL.into_iter().filter(|m| m.marches_slices()) {
        let at = |sample_depth| AoSettings {
            sample_depth,
            ..scene_settings(&scene, method, Preset::High)
        };
        let nearest = render(&gpu, &scene, camera, &at(SampleDepth::Nearest)).ao;
        let interpolated = render(&gpu, &scene, camera, &at(SampleDepth::Interpolated)).ao;
        assert_ne!(
            nearest,
            interpolated,
            "{}: the read changed nothing",
            method.name()
        );
        let mean_change = mean_abs_difference(&nearest, &interpolated);
        assert!(
            mean_change < 0.01,
            "{}: mean change {mean_change}",
            method.name()
        );
        let mut renderer = Renderer::new(&gpu, &scene, &at(SampleDepth::Nearest)).unwrap();
        renderer
            .set_settings(&gpu, &at(SampleDepth::Interpolated))
            .unwrap();
        let switched = renderer.render(&gpu, camera, SIZE, 0).unwrap().ao;
        assert_eq!(switched, interpolated, "{}", method.name());
    }
}

#[test]
fn the_lean_slice_march_gives_the_general_marchs_ao_for_every_slice_method() {
    let gpu = gpu();
    let room = Builtin::Room.build();
    let orthographic = Camera {
        eye: Vec3::new(4.0, 4.0, 7.0),
        target: Vec3::new(0.0, 0.8, 0.0),
        lens: Lens::Orthographic { height: 8.0 },
        ..room.cameras[0].clone()
    };
    let mut views: Vec<(Scene, Camera)> = Builtin::ALL
        .into_iter()
        .map(|builtin| {
            let scene = builtin.build();
            let camera = scene.cameras[0].clone();
            (scene, camera)
        })
        .collect();
    views.push((room, orthographic));
    let slice_methods = Method::ALL.into_iter().filter(|m| m.marches_slices());
    for ((scene, camera), method) in views
        .iter()
        .flat_map(|v| slice_methods.clone().map(move |m| (v, m)))
    {
        let unoccluded = OffscreenSamples::Unoccluded;
        for (preset, depth_mips, bent_normals, offscreen_samples) in [
            (Preset::Low, DepthMips::Off, false, unoccluded),
            (
                Preset::High,
                DepthMips::Off,
                method.has_bent_normals(),
                unoccluded,
            ),
            (Preset::High, DepthMips::Off, false, OffscreenSamples::Clamp),
            (
                Preset::High,
                DepthMips::Off,
                false,
                OffscreenSamples::Extend,
            ),
            (Preset::High, DepthMips::Fp32, false, unoccluded),
            (
                Preset::High,
                DepthMips::Fp32,
                false,
                OffscreenSamples::Clamp,
            ),
            (Preset::Ultra, DepthMips::Off, false, unoccluded),
        ] {
            let at = |slice_march| AoSettings {
                slice_march,
                depth_mips,
                bent_normals,
                offscreen_samples,
                ..scene_settings(scene, method, preset)
            };
            let view = format!(
                "{} / {} / {} / {} / mips {} / off screen {}",
                method.name(),
                scene.name,
                camera.name,
                preset.name(),
                depth_mips.name(),
                offscreen_samples.name()
            );
            let lean = render(&gpu, scene, camera, &at(SliceMarch::Lean));
            let general = render(&gpu, scene, camera, &at(SliceMarch::General));
            assert_in_range_with_sky_at_one(&lean, &view);
            // The same samples and horizons: only rounding differs, where a sample's crossing
            // or a horizon lands within an ulp of a select's threshold.
            let largest = lean
                .ao
                .iter()
                .zip(&general.ao)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0f32, f32::max);
            let mean = mean_abs_difference(&lean.ao, &general.ao);
            assert!(
                mean < 1e-5 && largest < 0.02,
                "{view}: mean {mean}, largest {largest}"
            );
        }
    }
}

/// RMSE of `ao` against `reference` over the surface pixels within `band` pixels of the image's
/// edge.
fn border_rmse(ao: &[f32], reference: &aokit_reference::ReferenceImage, band: u32) -> f64 {
    let [w, h] = SIZE;
    let (sum, count) = (0..w * h)
        .filter(|i| {
            let (x, y) = (i % w, i / w);
            let inside = x >= band && y >= band && x + band < w && y + band < h;
            !inside && reference.linear_depth[*i as usize] > 0.0
        })
        .fold((0.0, 0usize), |(s, c), i| {
            let i = i as usize;
            (s + f64::from(ao[i] - reference.ao[i]).powi(2), c + 1)
        });
    (sum / count as f64).sqrt()
}

#[test]
fn continuing_the_edges_surface_off_screen_lowers_the_border_bands_error() {
    // The room's walls and floor, and the stairs' steps, go on past the frame: taking the space
    // beyond as open leaves the band along the edge too bright (docs/quality.md, "Off-screen
    // samples and silhouettes").
    let gpu = gpu();
    for builtin in [Builtin::Room, Builtin::Stairs] {
        let scene = builtin.build();
        let camera = &scene.cameras[0];
        let traced = trace(&scene, camera, SIZE, 128);
        for method in Method::ALL.into_iter().filter(|m| m.marches_slices()) {
            let at = |offscreen_samples| AoSettings {
                offscreen_samples,
                ..scene_settings(&scene, method, Preset::High)
            };
            let open = render(&gpu, &scene, camera, &at(OffscreenSamples::Unoccluded));
            let without = border_rmse(&open.ao, &traced, 12);
            for offscreen in [OffscreenSamples::Extend, OffscreenSamples::Clamp] {
                let continued = render(&gpu, &scene, camera, &at(offscreen));
                let view = format!("{} / {} / {}", method.name(), scene.name, offscreen.name());
                assert_in_range_with_sky_at_one(&continued, &view);
                let with = border_rmse(&continued.ao, &traced, 12);
                assert!(
                    with < 0.95 * without,
                    "{view}: border RMSE {with}, {without} unoccluded"
                );
            }
        }
    }
}

#[test]
fn distance_fade_intensity_and_method_switches_apply_at_runtime() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let camera = &scene.cameras[0];
    let base = scene_settings(&scene, Method::Gtao, Preset::Medium);
    let mut renderer = Renderer::new(&gpu, &scene, &base).unwrap();
    // Every method through one renderer gives what a fresh one gives.
    for method in Method::ALL {
        let s = scene_settings(&scene, method, Preset::Medium);
        renderer.set_settings(&gpu, &s).unwrap();
        let switched = renderer.render(&gpu, camera, SIZE, 0).unwrap();
        assert_eq!(
            switched.ao,
            render(&gpu, &scene, camera, &s).ao,
            "{}",
            method.name()
        );
    }
    // Past max_distance nothing is occluded; intensity 0 removes all occlusion. The kernel's
    // AO: the spatial filter would blend nearer neighbours' into the first texels past it.
    let mut faded = AoSettings {
        max_distance: 6.0,
        distance_falloff: 1.0,
        ..base
    };
    faded.spatial.enabled = false;
    renderer.set_settings(&gpu, &faded).unwrap();
    let faded = renderer.render(&gpu, camera, SIZE, 0).unwrap();
    for (ao, depth) in faded.ao.iter().zip(&faded.linear_depth) {
        if *depth >= 6.0 {
            assert_eq!(*ao, 1.0, "AO {ao} at depth {depth}");
        }
    }
    assert!(
        faded.ao.iter().any(|&ao| ao < 0.8),
        "nearer pixels keep their AO"
    );
    renderer
        .set_settings(
            &gpu,
            &AoSettings {
                intensity: 0.0,
                ..base
            },
        )
        .unwrap();
    let off = renderer.render(&gpu, camera, SIZE, 0).unwrap();
    assert!(off.ao.iter().all(|&ao| ao == 1.0));
}

#[test]
fn the_pixel_radius_clamps_apply_to_every_method() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let perspective = &scene.cameras[0];
    // Through an orthographic lens a world radius covers the same pixels at every depth, so a
    // clamp to `p` pixels must give exactly the AO of the world radius that covers `p`.
    let orthographic = Camera {
        eye: Vec3::new(4.0, 4.0, 7.0),
        target: Vec3::new(0.0, 0.8, 0.0),
        lens: Lens::Orthographic { height: 8.0 },
        ..perspective.clone()
    };
    let pixels = 6.0;
    let covering = pixels * 8.0 / SIZE[1] as f32;
    for method in Method::ALL {
        let name = method.name();
        // The kernel's radius is the world radius here, which the clamps are compared with.
        let base = AoSettings {
            radius_multiplier: 1.0,
            ..scene_settings(&scene, method, Preset::Medium)
        };
        // A radius far under a pixel everywhere: no AO at all, unless min_radius_px widens it.
        let tiny = AoSettings {
            radius: base.radius * 1e-3,
            ..base
        };
        let none = render(&gpu, &scene, perspective, &tiny);
        assert!(covered(&none).all(|a| a == 1.0), "{name}");
        let widened = AoSettings {
            min_radius_px: 8.0,
            ..tiny
        };
        let widened = render(&gpu, &scene, perspective, &widened);
        let occluded = covered(&widened).filter(|&a| a < 0.9).count();
        assert!(occluded > 100, "{name}: {occluded} pixels under 0.9");

        let exact = render(
            &gpu,
            &scene,
            &orthographic,
            &AoSettings {
                radius: covering,
                ..base
            },
        );
        for (clamp, settings) in [
            (
                "max_radius_px",
                AoSettings {
                    radius: covering * 4.0,
                    max_radius_px: pixels,
                    ..base
                },
            ),
            (
                "min_radius_px",
                AoSettings {
                    radius: covering / 4.0,
                    min_radius_px: pixels,
                    ..base
                },
            ),
        ] {
            let clamped = render(&gpu, &scene, &orthographic, &settings);
            let worst = clamped
                .ao
                .iter()
                .zip(&exact.ao)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f32::max);
            assert!(
                worst < 1e-3,
                "{name} / {clamp}: {worst} from the world radius"
            );
        }
    }
}
