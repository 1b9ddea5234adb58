//! Normal encodings on whatever adapter exists (lavapipe in CI): the WGSL encoders against their
//! CPU mirrors, the pipeline's decode of every texture format, and the checks on the inputs.

use aokit::gpu::{read_texture, upload_texture_2d};
use aokit::normals::{
    angle_degrees, decode_texel, encode_texel, fibonacci_directions, pack_rgba16f, unpack_oct32,
};
use aokit::passes::{ComputeKernel, bind};
use aokit::shader::{ENCODING, ShaderSource};
use aokit::{
    AoError, AoInputs, AoPipeline, AoSettings, GpuContext, InputError, NormalEncoding, Projection,
};
use glam::Vec3;

/// Directions as a texture of this size: the lattice, then the axes and diagonals.
const SIZE: [u32; 2] = [128, 64];

fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

/// A Fibonacci lattice over the sphere followed by the 26 axis, edge and corner directions of
/// the cube, where the encodings fold, wrap or divide by zero.
fn directions() -> Vec<Vec3> {
    let mut special = Vec::new();
    for x in [-1.0f32, 0.0, 1.0] {
        for y in [-1.0f32, 0.0, 1.0] {
            for z in [-1.0f32, 0.0, 1.0] {
                if (x, y, z) != (0.0, 0.0, 0.0) {
                    special.push(Vec3::new(x, y, z).normalize());
                }
            }
        }
    }
    let lattice = (SIZE[0] * SIZE[1]) as usize - special.len();
    fibonacci_directions(lattice as u32)
        .chain(special)
        .collect()
}

/// Encodes each direction with the WGSL encoder and writes the texel as little-endian words:
/// for unorm formats the bytes the fixed-function conversion stores (exact for values on the
/// grid); for `rgba16f` the f32 values written, which the texture rounds to halves.
const ENCODE_KERNEL: &str = r#"
@group(0) @binding(0) var directions: texture_2d<f32>;
@group(0) @binding(1) var stored: texture_storage_2d<rgba32uint, write>;
override ENCODING: u32;

fn stored_words(n: vec3<f32>) -> vec4<u32> {
    let v = encode_normal_float(n, ENCODING);
    switch ENCODING {
        case ENCODING_OCT24: { return vec4<u32>(pack4x8unorm(v), 0u, 0u, 0u); }
        case ENCODING_OCT16: { return vec4<u32>(pack4x8unorm(v) & 0xffffu, 0u, 0u, 0u); }
        case ENCODING_OCT20, ENCODING_RGB10A2: {
            let q = vec4<u32>(round(v * vec4<f32>(1023.0, 1023.0, 1023.0, 3.0)));
            return vec4<u32>(q.x | (q.y << 10u) | (q.z << 20u) | (q.w << 30u), 0u, 0u, 0u);
        }
        case ENCODING_RGBA16F: { return bitcast<vec4<u32>>(v); }
        default: { return vec4<u32>(encode_normal_uint(n, ENCODING), 0u, 0u, 0u); }
    }
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    textureStore(stored, id.xy, stored_words(textureLoad(directions, id.xy, 0).xyz));
}
"#;

/// The texel bytes the WGSL encoder produces for each of `directions`.
fn encode_on_gpu(gpu: &GpuContext, encoding: NormalEncoding, directions: &[Vec3]) -> Vec<Vec<u8>> {
    let (device, queue) = (&gpu.device, &gpu.queue);
    let program = ShaderSource {
        name: "encoding test",
        parts: &[ENCODING, ENCODE_KERNEL],
    };
    program.validate().unwrap();
    let kernel = ComputeKernel::with_constants(
        device,
        &program,
        &[
            bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
            bind::storage_texture(1, wgpu::TextureFormat::Rgba32Uint),
        ],
        &[("ENCODING", f64::from(encoding.shader_code()))],
    );
    let texels: Vec<[f32; 4]> = directions
        .iter()
        .map(|n| n.extend(0.0).to_array())
        .collect();
    let input = upload_texture_2d(
        device,
        queue,
        "directions",
        SIZE,
        wgpu::TextureFormat::Rgba32Float,
        bytemuck::cast_slice(&texels),
    )
    .unwrap();
    let output = aokit::gpu::create_texture_2d(
        device,
        "stored texels",
        SIZE,
        wgpu::TextureFormat::Rgba32Uint,
        wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
    );
    let mut encoder = device.create_command_encoder(&Default::default());
    kernel.dispatch(
        device,
        &mut encoder,
        &[
            wgpu::BindingResource::TextureView(&input.create_view(&Default::default())),
            wgpu::BindingResource::TextureView(&output.create_view(&Default::default())),
        ],
        SIZE,
        None,
    );
    queue.submit([encoder.finish()]);
    let words: Vec<[u32; 4]> =
        bytemuck::pod_collect_to_vec(&read_texture(device, queue, &output).unwrap());
    words
        .iter()
        .map(|w| match encoding {
            // Rounded to halves as the CPU mirror rounds, which is what the format does.
            NormalEncoding::Rgba16f => {
                let v = Vec3::new(
                    f32::from_bits(w[0]),
                    f32::from_bits(w[1]),
                    f32::from_bits(w[2]),
                );
                pack_rgba16f(v)
                    .iter()
                    .flat_map(|h| h.to_le_bytes())
                    .collect()
            }
            _ => w[0].to_le_bytes()[..encoding.texel_size()].to_vec(),
        })
        .collect()
}

#[test]
fn wgsl_encoders_write_the_texels_of_the_cpu_mirrors() {
    let gpu = gpu();
    let directions = directions();
    for encoding in NormalEncoding::ALL {
        let on_gpu = encode_on_gpu(&gpu, encoding, &directions);
        let on_cpu: Vec<Vec<u8>> = directions
            .iter()
            .map(|&n| {
                let mut texel = Vec::new();
                encode_texel(encoding, n, &mut texel);
                texel
            })
            .collect();
        let exact = on_gpu.iter().zip(&on_cpu).filter(|(a, b)| a == b).count() as f64
            / directions.len() as f64;
        // Directions an encoding holds (xy and stereographic hold only z >= 0): the CPU's worst
        // rounding error, and how far the GPU's texel lands from the CPU's.
        let held = || {
            directions
                .iter()
                .zip(on_gpu.iter().zip(&on_cpu))
                .filter(|(n, _)| n.z >= 0.0)
        };
        let worst_rounding = held()
            .map(|(&n, (_, cpu))| angle_degrees(n, decode_texel(encoding, cpu)))
            .fold(0.0, f64::max);
        let worst_apart = held()
            .map(|(_, (gpu, cpu))| {
                angle_degrees(decode_texel(encoding, gpu), decode_texel(encoding, cpu))
            })
            .fold(0.0, f64::max);
        // Texels differ only where a value sits on a rounding boundary and the GPU's division,
        // sqrt or atan2 (looser than the CPU's) tips it over: then the GPU stores a neighbouring
        // step, at most twice the worst rounding error from the CPU's (a diagonal step).
        assert!(
            exact >= 0.95 && worst_apart <= 2.0 * worst_rounding + 1e-6,
            "{encoding:?}: {:.3}% of texels match the CPU's; the others decode up to \
             {worst_apart} degrees apart, against a worst rounding error of {worst_rounding}",
            100.0 * exact
        );
    }
}

/// A linear depth texture with a surface one unit away at every pixel.
fn flat_depth(gpu: &GpuContext) -> wgpu::Texture {
    let depth = vec![1.0f32; (SIZE[0] * SIZE[1]) as usize];
    upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "depth",
        SIZE,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(&depth),
    )
    .unwrap()
}

fn settings(encoding: NormalEncoding) -> AoSettings {
    let mut settings = AoSettings::default();
    settings.normals.encoding = encoding;
    settings
}

fn projection() -> Projection {
    Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None)
}

#[test]
fn the_pipeline_decodes_every_format_to_the_cpu_mirrors_normals() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let directions = directions();
    let depth = flat_depth(&gpu);
    let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default()).unwrap();
    for encoding in NormalEncoding::ALL {
        let bytes = aokit::normals::encode_texels(encoding, &directions);
        let normals = upload_texture_2d(
            device,
            queue,
            "normals",
            SIZE,
            encoding.texture_format(),
            &bytes,
        )
        .unwrap();
        pipeline
            .set_settings(device, queue, &settings(encoding))
            .unwrap();
        let mut encoder = device.create_command_encoder(&Default::default());
        let outputs = pipeline
            .encode(
                device,
                queue,
                &mut encoder,
                &AoInputs {
                    normals: Some((&normals).into()),
                    ..AoInputs::new(&depth, projection())
                },
            )
            .unwrap();
        queue.submit([encoder.finish()]);
        // oct32 is read as it is: no decode, the input itself is what the kernels used.
        if encoding == NormalEncoding::Oct32 {
            assert!(*outputs.normals == normals);
            continue;
        }
        let decoded: Vec<u32> =
            bytemuck::pod_collect_to_vec(&read_texture(device, queue, outputs.normals).unwrap());
        let worst = bytes
            .chunks_exact(encoding.texel_size())
            .zip(&decoded)
            .map(|(texel, &bits)| angle_degrees(decode_texel(encoding, texel), unpack_oct32(bits)))
            .fold(0.0, f64::max);
        // The GPU decodes as the CPU does, then rounds to oct32, whose worst error is 0.0037
        // degrees (docs/normals.md).
        assert!(
            worst < 0.004,
            "{encoding:?}: decoded normals differ from the CPU's by up to {worst} degrees"
        );
    }
}

#[test]
fn a_normal_texture_in_another_format_than_the_encoding_is_refused_naming_both() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let depth = flat_depth(&gpu);
    let normals = upload_texture_2d(
        device,
        queue,
        "normals",
        SIZE,
        wgpu::TextureFormat::R32Uint,
        &aokit::normals::encode_texels(NormalEncoding::Oct32, &directions()),
    )
    .unwrap();
    let inputs = AoInputs {
        normals: Some((&normals).into()),
        ..AoInputs::new(&depth, projection())
    };
    for encoding in NormalEncoding::ALL {
        let result = inputs.validate(encoding);
        if encoding.is_uint() {
            assert_eq!(result, Ok(SIZE), "{encoding:?}");
            continue;
        }
        let error = result.unwrap_err();
        assert_eq!(
            error,
            InputError::NormalsFormat {
                format: wgpu::TextureFormat::R32Uint,
                encoding
            }
        );
        let message = error.to_string();
        assert!(
            message.contains("R32Uint")
                && message.contains(encoding.name())
                && message.contains(&format!("{:?}", encoding.texture_format())),
            "{message}"
        );
    }
    let mut pipeline = AoPipeline::new(device, queue, &settings(NormalEncoding::Oct24)).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    assert!(matches!(
        pipeline.encode(device, queue, &mut encoder, &inputs),
        Err(AoError::Input(InputError::NormalsFormat { .. }))
    ));
}

/// A slanted floor with a block standing on it, as linear depth: enough relief for the AO to
/// vary with the normal.
fn block_scene() -> Vec<f32> {
    let [w, h] = SIZE;
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let floor = 3.0 - 1.5 * y as f32 / h as f32;
            let block = (40..88).contains(&x) && (16..48).contains(&y);
            if block { floor - 0.4 } else { floor }
        })
        .collect()
}

/// Pixels given an unusable normal: a sparse scatter over the image, on the floor, the block and
/// their edges.
fn spoiled(i: usize) -> bool {
    i % 23 == 5
}

/// One frame of `settings` on `depth` (and `normals`), its AO and normals read back.
fn ao_and_normals(
    gpu: &GpuContext,
    settings: &AoSettings,
    depth: &wgpu::Texture,
    normals: Option<&wgpu::Texture>,
) -> (Vec<f32>, Vec<u32>) {
    let (device, queue) = (&gpu.device, &gpu.queue);
    let mut pipeline = AoPipeline::new(device, queue, settings).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(
            device,
            queue,
            &mut encoder,
            &AoInputs {
                normals: normals.map(Into::into),
                ..AoInputs::new(depth, projection())
            },
        )
        .unwrap();
    queue.submit([encoder.finish()]);
    let ao = aokit::gpu::read_texture_f32(device, queue, outputs.ao).unwrap();
    let normals =
        bytemuck::pod_collect_to_vec(&read_texture(device, queue, outputs.normals).unwrap());
    (ao, normals)
}

#[test]
fn unusable_normals_in_a_texture_fall_back_to_normals_from_depth_per_pixel() {
    let gpu = gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let depth = upload_texture_2d(
        device,
        queue,
        "depth",
        SIZE,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(&block_scene()),
    )
    .unwrap();
    let mut settings = AoSettings::default();
    settings.spatial.enabled = false;
    settings.temporal.enabled = false;
    let (from_depth, depth_normals) = ao_and_normals(&gpu, &settings, &depth, None);
    // The renderer's normals: those from depth tilted 30 degrees about x, as a normal map
    // would, so that its AO differs from the AO with normals from depth.
    let tilt = glam::Quat::from_rotation_x(30f32.to_radians());
    let good: Vec<Vec3> = depth_normals
        .iter()
        .map(|&bits| tilt * unpack_oct32(bits))
        .collect();
    for (encoding, unusable) in [
        (
            NormalEncoding::Rgba16f,
            &[
                Vec3::ZERO,
                Vec3::new(f32::NAN, 0.0, 1.0),
                Vec3::new(0.0, f32::INFINITY, 0.0),
                Vec3::new(0.0, 0.0, -3.0),
                Vec3::splat(0.1),
            ][..],
        ),
        // Mid-grey, the nearest a 10-bit texel comes to the zero vector.
        (NormalEncoding::Rgb10a2, &[Vec3::ZERO][..]),
    ] {
        settings.normals.encoding = encoding;
        let upload = |normals: &[Vec3]| {
            let bytes = aokit::normals::encode_texels(encoding, normals);
            upload_texture_2d(
                device,
                queue,
                "normals",
                SIZE,
                encoding.texture_format(),
                &bytes,
            )
            .unwrap()
        };
        let mut bad = good.clone();
        for (i, n) in bad.iter_mut().enumerate().filter(|(i, _)| spoiled(*i)) {
            *n = unusable[i % unusable.len()];
        }
        let (with_good, _) = ao_and_normals(&gpu, &settings, &depth, Some(&upload(&good)));
        let (with_bad, decoded) = ao_and_normals(&gpu, &settings, &depth, Some(&upload(&bad)));
        let mut changed_by_the_tilt = 0;
        for i in 0..good.len() {
            let at = format!(
                "{encoding:?}, x {}, y {}",
                i as u32 % SIZE[0],
                i as u32 / SIZE[0]
            );
            assert!(with_bad[i].is_finite(), "AO {} at {at}", with_bad[i]);
            if spoiled(i) {
                // The same normal as the reconstruction's, so the same AO.
                assert_eq!(decoded[i], depth_normals[i], "normal at {at}");
                assert!(
                    (with_bad[i] - from_depth[i]).abs() < 1e-4,
                    "AO {} at {at}, {} with normals from depth",
                    with_bad[i],
                    from_depth[i]
                );
                changed_by_the_tilt += usize::from((with_good[i] - from_depth[i]).abs() > 0.02);
            } else {
                assert_eq!(with_bad[i], with_good[i], "AO at {at}");
            }
        }
        // Else the fallback could not be told from the renderer's normals.
        let spoiled_count = (0..good.len()).filter(|&i| spoiled(i)).count();
        assert!(
            changed_by_the_tilt > spoiled_count / 2,
            "{encoding:?}: the tilt changed the AO at only {changed_by_the_tilt} of the \
             {spoiled_count} spoiled pixels"
        );
    }
}
