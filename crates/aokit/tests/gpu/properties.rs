//! Property tests (issue 29): for random valid settings, random sizes from 1x1 to 37x23 and
//! random depth and normal content (NaN, infinities, 0, negative numbers and denormals among
//! ordinary values), every method and filter gives finite AO in [0, 1], pixels without a
//! surface (depth 0, negative or not finite) stay 1, and changing the settings between two
//! frames on one pipeline never fails.
//!
//! The cases are few, for lavapipe: `AOKIT_PROPTEST_CASES` sets how many (32 by default).

use aokit::gpu::{read_texture_f32, upload_texture_2d};
use aokit::normals::encode_texels;
use aokit::settings::{SETTINGS, SettingKind, SettingValue};
use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, Preset, Projection};
use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

/// One `AoSettings::set` to try: which setting (an index into `SETTINGS`, wrapped), where in
/// its range (0 to 1) and which choice (wrapped).
#[derive(Clone, Debug)]
struct Assign {
    setting: usize,
    at: f64,
    choice: usize,
}

/// A setting's value at `at` (0 to 1) of its range, or its `choice`-th name.
fn value_in_range(
    kind: SettingKind,
    settings: &AoSettings,
    at: f64,
    choice: usize,
) -> SettingValue {
    match kind {
        SettingKind::Bool => SettingValue::Bool(at < 0.5),
        SettingKind::Integer(range) => {
            let steps = (range.max - range.min) / range.step;
            SettingValue::Integer(range.min + range.step * (at * f64::from(steps)).round() as u32)
        }
        SettingKind::Float(range) => {
            // No upper limit: up to 8 past the lower end, enough for radii, scales and powers.
            let hi = range.max_value(settings).unwrap_or(range.min + 8.0);
            let mut value = range.min + (at as f32) * (hi - range.min);
            if !range.min_inclusive && value <= range.min {
                value = range.min + (hi - range.min) * 1e-3;
            }
            if !range.max_inclusive && value >= hi {
                value = hi - (hi - range.min) * 1e-3;
            }
            SettingValue::Float(value)
        }
        SettingKind::Choice(names) => SettingValue::Choice(names[choice % names.len()]),
    }
}

/// The settings of one frame: a method at a preset, the spatial and temporal filters on or
/// off, then random assignments.
type Choice = (Method, Preset, (bool, bool), Vec<Assign>);

/// `method` at `preset` with the filters as `filters` says, then each of `assigns` that `set`
/// accepts; `None` where the result fails `validate()` (a combination the settings refuse,
/// skipped).
fn settings_from((method, preset, filters, assigns): &Choice) -> Option<AoSettings> {
    let mut settings = AoSettings::preset(*method, *preset);
    settings.spatial.enabled = filters.0;
    settings.temporal.enabled = filters.1;
    for assign in assigns {
        let spec = &SETTINGS[assign.setting % SETTINGS.len()];
        let value = value_in_range(spec.kind, &settings, assign.at, assign.choice);
        // Out of range for this combination (a limit that is another setting): keep the old.
        let _ = settings.set(spec.name, value);
    }
    settings.validate().ok().map(|_| settings)
}

fn assigns() -> impl Strategy<Value = Vec<Assign>> {
    prop::collection::vec(
        (any::<usize>(), 0.0..=1.0f64, any::<usize>()).prop_map(|(setting, at, choice)| Assign {
            setting,
            at,
            choice,
        }),
        0..12,
    )
}

/// A depth: mostly surfaces 0.5 to 20 units away, with the values a renderer's bugs or a
/// file's background give.
fn depth_value() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => 0.5f32..20.0,
        1 => Just(0.0f32),
        1 => prop::sample::select(vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -1.0,
            -0.0,
            1e-30,
            f32::MIN_POSITIVE,
            f32::MAX,
            1e30,
        ]),
        1 => (1u32..0x0080_0000).prop_map(f32::from_bits), // denormals
    ]
}

/// A normal component: mostly a direction's, with zeros, NaN, infinities and denormals.
fn normal_component() -> impl Strategy<Value = f32> {
    prop_oneof![
        8 => -1.0f32..=1.0,
        1 => prop::sample::select(vec![
            0.0f32,
            -0.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1e-40,
            1e30,
        ]),
    ]
}

#[derive(Clone, Debug)]
struct Case {
    size: [u32; 2],
    depth: Vec<f32>,
    normals: Option<Vec<Vec3>>,
    /// The back faces' depth: the front depth plus this.
    thickness: f32,
    orthographic: bool,
    fov: f32,
    first: Choice,
    second: Choice,
}

fn case() -> impl Strategy<Value = Case> {
    let settings = || {
        (
            prop::sample::select(Method::ALL.to_vec()),
            prop::sample::select(Preset::ALL.to_vec()),
            (any::<bool>(), any::<bool>()),
            assigns(),
        )
    };
    ((1u32..=37, 1u32..=23), settings(), settings()).prop_flat_map(|((w, h), first, second)| {
        let n = (w * h) as usize;
        (
            prop::collection::vec(depth_value(), n),
            prop::option::of(prop::collection::vec(
                prop::array::uniform3(normal_component()).prop_map(Vec3::from),
                n,
            )),
            0.0f32..2.0,
            any::<bool>(),
            0.3f32..2.5,
            Just(first),
            Just(second),
        )
            .prop_map(
                move |(depth, normals, thickness, orthographic, fov, first, second)| Case {
                    size: [w, h],
                    depth,
                    normals,
                    thickness,
                    orthographic,
                    fov,
                    first,
                    second,
                },
            )
    })
}

fn texture(gpu: &GpuContext, case: &Case, label: &str, values: &[f32]) -> wgpu::Texture {
    upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        label,
        case.size,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(values),
    )
    .unwrap()
}

/// One frame of `pipeline` (set to `settings`) on the case's passes, read back and checked.
fn frame(
    gpu: &GpuContext,
    pipeline: &mut AoPipeline,
    settings: &AoSettings,
    case: &Case,
    frame_index: u32,
) -> Result<(), TestCaseError> {
    let depth = texture(gpu, case, "depth", &case.depth);
    let back: Vec<f32> = case.depth.iter().map(|d| d + case.thickness).collect();
    let back = texture(gpu, case, "back depth", &back);
    let encoding = settings.normals.encoding;
    let normals = case.normals.as_ref().map(|normals| {
        upload_texture_2d(
            &gpu.device,
            &gpu.queue,
            "normals",
            case.size,
            encoding.texture_format(),
            &encode_texels(encoding, normals),
        )
        .unwrap()
    });
    let aspect = case.size[0] as f32 / case.size[1] as f32;
    let projection = if case.orthographic {
        Projection::orthographic(8.0, aspect, 0.1, 50.0)
    } else {
        Projection::perspective(case.fov, aspect, 0.1, None)
    };
    let inputs = AoInputs {
        normals: normals.as_ref().map(Into::into),
        back_depth: settings.vbao.back_faces.then_some((&back).into()),
        frame_index,
        ..AoInputs::new(&depth, projection)
    };
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(&gpu.device, &gpu.queue, &mut encoder, &inputs)
        .map_err(|e| TestCaseError::fail(format!("encode failed: {e}")))?;
    gpu.queue.submit([encoder.finish()]);
    let ao = read_texture_f32(&gpu.device, &gpu.queue, outputs.ao).unwrap();
    let [w, h] = case.size;
    prop_assert_eq!(ao.len(), (w * h) as usize);
    for (i, (&a, &d)) in ao.iter().zip(&case.depth).enumerate() {
        let at = format!("x {}, y {} (depth {d})", i as u32 % w, i as u32 / w);
        prop_assert!(
            a.is_finite() && (0.0..=1.0).contains(&a),
            "AO {} at {}",
            a,
            at
        );
        if !(d.is_finite() && d > 0.0) {
            prop_assert!(a == 1.0, "AO {} without a surface at {}", a, at);
        }
    }
    Ok(())
}

#[test]
fn random_settings_sizes_and_content_give_finite_ao_in_0_1() {
    let gpu = gpu();
    let cases = std::env::var("AOKIT_PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(32);
    let config = Config {
        cases,
        max_shrink_iters: 64,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner = TestRunner::new(config);
    let result = runner.run(&case(), |case| {
        let Some(first) = settings_from(&case.first) else {
            return Err(TestCaseError::reject("first settings refused"));
        };
        let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &first)
            .map_err(|e| TestCaseError::fail(format!("{first:?}: {e}")))?;
        frame(&gpu, &mut pipeline, &first, &case, 0)?;
        // The second frame on the same pipeline, with other settings where they validate.
        if let Some(second) = settings_from(&case.second) {
            pipeline
                .set_settings(&gpu.device, &gpu.queue, &second)
                .map_err(|e| TestCaseError::fail(format!("set_settings {second:?}: {e}")))?;
            frame(&gpu, &mut pipeline, &second, &case, 1)?;
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// Found by the property test above: a pixel at a denormal depth (6.7e-39) turned NaN in
/// the spatial filter, whose `depth_sigma / depth` overflowed to infinity and met a depth
/// difference of 0 at the centre (0 * infinity), for every method. Every spatial kind and
/// depth weight, after GTAO.
#[test]
fn a_denormal_depth_gives_finite_ao_through_every_spatial_filter() {
    let gpu = gpu();
    let depth = vec![0.5, 0.5, 18.2, 12.0, 13.3, 12.0, 6.69934e-39, 19.8];
    let case = Case {
        size: [1, 8],
        depth,
        normals: None,
        thickness: 0.5,
        orthographic: false,
        fov: 0.5,
        first: (Method::Gtao, Preset::Low, (true, false), vec![]),
        second: (Method::Gtao, Preset::Low, (true, false), vec![]),
    };
    for kind in aokit::SpatialKind::ALL {
        for weight in aokit::DepthWeight::ALL {
            let mut settings = AoSettings::preset(Method::Gtao, Preset::Low);
            settings.spatial.enabled = true;
            settings.spatial.kind = kind;
            settings.spatial.depth_weight = weight;
            let mut pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
            if let Err(e) = frame(&gpu, &mut pipeline, &settings, &case, 0) {
                panic!("{kind:?} ({weight:?}): {e}");
            }
        }
    }
}
