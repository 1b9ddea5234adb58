//! The WGSL noise functions against their CPU mirrors in `aokit::noise`, on whatever adapter
//! exists (lavapipe in CI): every noise kind with both temporal offsets over several frames, and
//! the Sobol and Halton sequences of the SSAO kernels.

use aokit::noise::{self, Tile};
use aokit::passes::{ComputeKernel, bind};
use aokit::shader::{NOISE, ShaderSource};
use aokit::{GpuContext, NoiseKind, NoiseSettings, TemporalOffset};
use bytemuck::{Pod, Zeroable};

/// Pixels per side of the image evaluated: a multiple of every tile.
const SIDE: u32 = 128;

/// Mirrors `Params` in [`KERNEL`].
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Params {
    kind: u32,
    temporal: u32,
    frame: u32,
    side: u32,
}

/// Per pixel: its two noise values and the Sobol point of its index in one texel, the Halton
/// value in the next.
const KERNEL: &str = r#"
struct Params {
    kind: u32,
    temporal: u32,
    frame: u32,
    side: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var tile: texture_2d<f32>;
@group(0) @binding(2) var results: texture_storage_2d<rgba32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(params.side)) {
        return;
    }
    let index = id.y * params.side + id.x;
    let texel = textureLoad(tile, id.xy % textureDimensions(tile), 0).xy;
    let noise = pixel_noise(id.xy, params.frame, params.kind, params.temporal, texel);
    textureStore(results, vec2<u32>(2u * id.x, id.y), vec4<f32>(noise, sobol_2d(index)));
    textureStore(results, vec2<u32>(2u * id.x + 1u, id.y), vec4<f32>(halton_3(index)));
}
"#;

struct Evaluator {
    gpu: GpuContext,
    kernel: ComputeKernel,
    params: wgpu::Buffer,
}

impl Evaluator {
    fn new() -> Self {
        let gpu = GpuContext::headless()
            .expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)");
        let program = ShaderSource {
            name: "noise test",
            parts: &[NOISE, KERNEL],
        };
        program.validate().unwrap();
        let kernel = ComputeKernel::new(
            &gpu.device,
            &program,
            &[
                bind::uniform(0),
                bind::texture(1, wgpu::TextureSampleType::Float { filterable: false }),
                bind::storage_texture(2, wgpu::TextureFormat::Rgba32Float),
            ],
        );
        let params = aokit::gpu::create_uniform_buffer::<Params>(&gpu.device, "noise params");
        Self {
            gpu,
            kernel,
            params,
        }
    }

    /// `(pixel_noise, sobol_2d, halton_3)` of every pixel, row major.
    fn run(&self, settings: &NoiseSettings, frame: u32) -> Vec<([f32; 2], [f32; 2], f32)> {
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        // The kinds without a tile read a 1x1 stand-in, as in the method pass.
        let tile = noise::tile(settings).unwrap_or(Tile {
            size: 1,
            texels: &[[0.0, 0.0]],
        });
        let tile = tile.upload(device, queue).create_view(&Default::default());
        let results = aokit::gpu::create_texture_2d(
            device,
            "noise results",
            [2 * SIDE, SIDE],
            wgpu::TextureFormat::Rgba32Float,
            wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        );
        let params = Params {
            kind: noise::kind_code(settings.kind),
            temporal: noise::temporal_code(settings.temporal),
            frame,
            side: SIDE,
        };
        queue.write_buffer(&self.params, 0, bytemuck::bytes_of(&params));
        let mut encoder = device.create_command_encoder(&Default::default());
        self.kernel.dispatch(
            device,
            &mut encoder,
            &[
                self.params.as_entire_binding(),
                wgpu::BindingResource::TextureView(&tile),
                wgpu::BindingResource::TextureView(&results.create_view(&Default::default())),
            ],
            [SIDE, SIDE],
            None,
        );
        queue.submit([encoder.finish()]);
        let bytes = aokit::gpu::read_texture(device, queue, &results).unwrap();
        let texels: Vec<[f32; 4]> = bytemuck::pod_collect_to_vec(&bytes);
        texels
            .chunks_exact(2)
            .map(|t| ([t[0][0], t[0][1]], [t[0][2], t[0][3]], t[1][0]))
            .collect()
    }
}

/// Distance on the unit circle: values near 0 and near 1 are neighbours as rotations.
fn circular(a: f32, b: f32) -> f32 {
    let d = (a - b).abs();
    d.min(1.0 - d)
}

#[test]
fn every_noise_kind_matches_its_cpu_mirror_and_is_neither_nan_nor_constant() {
    let evaluator = Evaluator::new();
    for kind in NoiseKind::ALL {
        for temporal in TemporalOffset::ALL {
            let settings = NoiseSettings {
                kind,
                temporal,
                ..NoiseSettings::default()
            };
            // Interleaved gradient noise multiplies a fraction by 53, so the GPU's last bits of
            // the inner fraction show in the third decimal; the other kinds are exact up to
            // rounding.
            let tolerance = if kind == NoiseKind::Ign { 2e-3 } else { 1e-5 };
            let mut previous: Option<Vec<[f32; 2]>> = None;
            for frame in [0, 1, 7, 1000] {
                let what = format!("{} / {} / frame {frame}", kind.name(), temporal.name());
                let gpu: Vec<[f32; 2]> = evaluator
                    .run(&settings, frame)
                    .into_iter()
                    .map(|(n, _, _)| n)
                    .collect();
                for (i, v) in gpu.iter().enumerate() {
                    let pixel = [i as u32 % SIDE, i as u32 / SIDE];
                    let cpu = noise::pixel_noise(&settings, pixel, frame);
                    for c in 0..2 {
                        assert!((0.0..1.0).contains(&v[c]), "{what}: {pixel:?} {v:?}");
                        let error = circular(v[c], cpu[c]);
                        assert!(
                            error <= tolerance,
                            "{what}: {pixel:?} GPU {v:?} CPU {cpu:?}"
                        );
                    }
                }
                // Uniform values have variance 1/12; the 16 values of the white tile can
                // spread less, but a constant pattern has none.
                for c in 0..2 {
                    let n = gpu.len() as f32;
                    let mean = gpu.iter().map(|v| v[c]).sum::<f32>() / n;
                    let variance = gpu.iter().map(|v| (v[c] - mean).powi(2)).sum::<f32>() / n;
                    assert!(variance > 0.03, "{what}: value {c} has variance {variance}");
                }
                if let Some(previous) = previous {
                    assert!(previous != gpu, "{what}: same as the frame before");
                }
                previous = Some(gpu);
            }
        }
    }
}

#[test]
fn sobol_and_halton_match_their_cpu_mirrors() {
    let evaluator = Evaluator::new();
    for (i, (_, sobol, halton)) in evaluator
        .run(&NoiseSettings::default(), 0)
        .into_iter()
        .enumerate()
    {
        assert_eq!(sobol, noise::sobol_2d(i as u32), "sobol {i}");
        assert!(
            (halton - noise::halton_3(i as u32)).abs() < 1e-6,
            "halton {i}"
        );
    }
}
