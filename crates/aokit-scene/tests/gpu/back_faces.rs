//! VBAO measuring its occluders from the back faces' depth (`vbao.back_faces`), on lavapipe in
//! CI: the thickness it reads, its error against the reference, and the inputs it refuses.

use crate::common;

use aokit::gpu::{create_texture_2d, read_texture_f32};
use aokit::{
    AoError, AoInputs, AoPipeline, AoSettings, InputError, Method, Preset, Projection, Resolution,
};
use aokit_scene::{Builtin, Camera, Lens};
use common::{encode_frame, gpu, linear_depth_texture, reference_errors, render_frame};

const SIZE: [u32; 2] = [64, 48];

/// Linear depth of a wall 10 units away with a bar 1 unit in front of it across columns 24 to
/// 39, from top to bottom: a step whose occluder, the bar, is as thick as the back-face depth
/// says.
fn step_depth() -> Vec<f32> {
    (0..SIZE[0] * SIZE[1])
        .map(|i| {
            if (24..40).contains(&(i % SIZE[0])) {
                9.0
            } else {
                10.0
            }
        })
        .collect()
}

/// VBAO `high` with a 2-unit radius (about 9 pixels at the wall) and a constant thickness of
/// 0.2 radii, 0.4 units: the bar's back then lies 0.6 in front of the wall, light passing
/// between. Measuring back faces or not.
fn step_settings(back_faces: bool) -> AoSettings {
    let mut settings = AoSettings {
        radius: 2.0,
        ..AoSettings::preset(Method::Vbao, Preset::High)
    };
    settings.vbao.thickness = 0.2;
    settings.vbao.back_faces = back_faces;
    settings
}

/// The AO of the step with back faces at `back` (linear depth per pixel; 0 for none), or
/// without back faces.
fn step_ao(gpu: &aokit::GpuContext, back: Option<&[f32]>) -> Vec<f32> {
    let depth = linear_depth_texture(gpu, SIZE, &step_depth());
    let back = back.map(|b| linear_depth_texture(gpu, SIZE, b));
    let projection = Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None);
    let settings = step_settings(back.is_some());
    let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
    let inputs = AoInputs {
        back_depth: back.as_ref().map(Into::into),
        ..AoInputs::new(&depth, projection)
    };
    encode_frame(gpu, &mut pipeline, &inputs, |outputs| {
        read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap()
    })
}

/// Mean AO of the wall's columns 17 to 23, left of the bar and within the radius of it.
fn beside_the_bar(ao: &[f32]) -> f32 {
    let columns = 17..24;
    let values: Vec<f32> = (0..ao.len())
        .filter(|i| columns.contains(&(i % SIZE[0] as usize)))
        .map(|i| ao[i])
        .collect();
    values.iter().sum::<f32>() / values.len() as f32
}

#[test]
fn measured_thickness_darkens_behind_solids_and_never_thins_an_occluder() {
    let gpu = gpu();
    let front = step_depth();
    let assumed = step_ao(&gpu, None);
    // Back faces right behind the front ones measure less than the constant thickness, which
    // then holds: the AO is exactly what it is without back faces.
    let flush = step_ao(&gpu, Some(&front));
    assert_eq!(flush, assumed);
    // A bar 8 units deep hides more of the wall's hemisphere beside it than one 0.9 deep.
    let deep: Vec<f32> = front.iter().map(|d| d + 8.0).collect();
    let deep = beside_the_bar(&step_ao(&gpu, Some(&deep)));
    let constant = beside_the_bar(&assumed);
    assert!(
        deep < constant - 0.02,
        "beside the bar: AO {deep} with a deep bar, {constant} with the constant thickness"
    );
    // No back face behind a surface (0, as for a closed room's walls) makes it solid: as dark
    // as the deepest occluder and no darker.
    let solid = beside_the_bar(&step_ao(&gpu, Some(&vec![0.0; front.len()])));
    let far: Vec<f32> = front.iter().map(|d| d + 1000.0).collect();
    let far = beside_the_bar(&step_ao(&gpu, Some(&far)));
    assert!(solid <= deep, "solid {solid} vs 8 units deep {deep}");
    assert!(
        (solid - far).abs() < 0.01,
        "solid {solid} vs 1000 deep {far}"
    );
}

#[test]
fn measured_occluders_only_ever_add_occlusion_in_every_depth_convention() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let front = scene.cameras[0].clone();
    let conventions = [
        ("reverse-Z", front.clone()),
        (
            "standard Z",
            Camera {
                reverse_z: false,
                near: Some(0.1),
                far: Some(50.0),
                ..front.clone()
            },
        ),
        (
            "orthographic",
            Camera {
                lens: Lens::Orthographic { height: 8.0 },
                ..front
            },
        ),
    ];
    let mut means = Vec::new();
    for (name, camera) in &conventions {
        // The same settings but for the switch: each occluder is at least as thick measured as
        // assumed, so every pixel is at most as bright, and the sphere and boxes, far thicker
        // than assumed, darken the floor under and around them.
        let mut settings = AoSettings {
            radius: scene.suggested_radius.unwrap(),
            ..AoSettings::preset(Method::Vbao, Preset::High)
        };
        let assumed = render_frame(&gpu, &scene, camera, &settings, [96, 64]);
        settings.vbao.back_faces = true;
        let measured = render_frame(&gpu, &scene, camera, &settings, [96, 64]);
        for (i, (m, a)) in measured.ao.iter().zip(&assumed.ao).enumerate() {
            assert!(
                m.is_finite() && *m <= a + 1e-5,
                "{name}, pixel {i}: AO {m} measured, {a} assumed"
            );
        }
        let darkest = measured
            .ao
            .iter()
            .zip(&assumed.ao)
            .map(|(m, a)| a - m)
            .fold(0.0f32, f32::max);
        assert!(darkest > 0.1, "{name}: darkened by at most {darkest}");
        means.push(measured.ao.iter().sum::<f32>() / measured.ao.len() as f32);
    }
    assert!(
        (means[0] - means[1]).abs() < 0.01,
        "reverse-Z {} against standard Z {}",
        means[0],
        means[1]
    );
}

#[test]
fn measuring_back_faces_brings_vbao_closer_to_the_reference_on_solids() {
    let gpu = gpu();
    let size = [160, 96];
    for builtin in [Builtin::Room, Builtin::Stairs] {
        let scene = builtin.build();
        let radius = scene.suggested_radius.unwrap();
        for resolution in [Resolution::Full, Resolution::Half] {
            let settings = |preset: AoSettings| AoSettings {
                radius,
                resolution,
                ..preset
            };
            // The same values both ways, so that only where the thickness comes from differs:
            // the assumed one is then the least thickness, and measuring can only close
            // what lies behind solids. (The presets differ: the assumed thickness's is held
            // to GTAO's error on solids too, docs/tuning.md.)
            let assumed = settings(AoSettings::preset(Method::Vbao, Preset::High));
            let mut measured = assumed;
            measured.vbao.back_faces = true;
            let (errors, _) = reference_errors(&gpu, &scene, &[assumed, measured], size);
            assert!(
                errors[1] < errors[0],
                "{} at {} resolution: RMSE {} measuring back faces, {} assuming thickness",
                scene.name,
                resolution.name(),
                errors[1],
                errors[0]
            );
        }
    }
    // Poles and fences stay open: measuring keeps VBAO's lead over GTAO behind them.
    let thin = Builtin::Thin.build();
    let radius = thin.suggested_radius.unwrap();
    let (errors, _) = reference_errors(
        &gpu,
        &thin,
        &[
            AoSettings {
                radius,
                ..AoSettings::preset_with_back_faces(Method::Vbao, Preset::High)
            },
            AoSettings {
                radius,
                ..AoSettings::preset(Method::Gtao, Preset::High)
            },
        ],
        size,
    );
    assert!(
        errors[0] < errors[1],
        "thin: VBAO measuring back faces {}, GTAO {}",
        errors[0],
        errors[1]
    );
}

#[test]
fn missing_or_unusable_back_faces_are_refused_naming_the_problem() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let texture = |format, size| {
        create_texture_2d(
            device,
            "back faces",
            size,
            format,
            wgpu::TextureUsages::TEXTURE_BINDING,
        )
    };
    let depth = texture(wgpu::TextureFormat::Depth32Float, SIZE);
    let projection = Projection::perspective(1.0, 1.5, 0.1, None);
    let mut pipeline = AoPipeline::new(device, queue, &step_settings(true)).unwrap();
    let mut encode = |back_depth| {
        let mut encoder = device.create_command_encoder(&Default::default());
        let inputs = AoInputs {
            back_depth,
            ..AoInputs::new(&depth, projection)
        };
        pipeline
            .encode(device, queue, &mut encoder, &inputs)
            .err()
            .map(|e| (e.to_string(), e))
    };
    let (message, error) = encode(None).unwrap();
    assert_eq!(error, AoError::MissingBackDepth);
    assert!(message.contains("vbao.back_faces"), "{message}");
    let rgba = texture(wgpu::TextureFormat::Rgba8Unorm, SIZE);
    let (message, error) = encode(Some((&rgba).into())).unwrap();
    assert_eq!(
        error,
        AoError::Input(InputError::DepthFormat(
            "back-face depth",
            wgpu::TextureFormat::Rgba8Unorm
        ))
    );
    assert!(message.contains("back-face depth"), "{message}");
    let small = texture(wgpu::TextureFormat::Depth32Float, [SIZE[0] / 2, SIZE[1]]);
    let (_, error) = encode(Some((&small).into())).unwrap();
    assert_eq!(
        error,
        AoError::Input(InputError::SizeMismatch {
            what: "back-face depth",
            depth: SIZE,
            other: [SIZE[0] / 2, SIZE[1]],
        })
    );
    // Other methods do not read them: with the setting on, a frame without them is fine.
    let mut other = AoSettings::default();
    other.vbao.back_faces = true;
    assert_ne!(other.method, Method::Vbao);
    let mut gtao = AoPipeline::new(device, queue, &other).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    assert!(
        gtao.encode(
            device,
            queue,
            &mut encoder,
            &AoInputs::new(&depth, projection)
        )
        .is_ok()
    );
}
