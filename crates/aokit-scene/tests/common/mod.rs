//! Helpers the GPU tests share: each test file is its own crate and uses some of them.
#![allow(dead_code)]

use aokit::gpu::upload_texture_2d;
use aokit::{AoInputs, AoOutputs, AoPipeline, GpuContext};

pub fn gpu() -> GpuContext {
    GpuContext::headless().expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
}

/// Linear view depth as the `R32Float` texture `AoInputs::depth` accepts.
pub fn linear_depth_texture(gpu: &GpuContext, size: [u32; 2], depth: &[f32]) -> wgpu::Texture {
    upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "linear depth",
        size,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(depth),
    )
    .unwrap()
}

/// Records one frame of `pipeline` on `inputs`, submits it and returns what `read` takes from
/// the outputs (read back after the submit).
pub fn encode_frame<T>(
    gpu: &GpuContext,
    pipeline: &mut AoPipeline,
    inputs: &AoInputs<'_>,
    read: impl FnOnce(&AoOutputs<'_>) -> T,
) -> T {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let outputs = pipeline
        .encode(&gpu.device, &gpu.queue, &mut encoder, inputs)
        .unwrap();
    gpu.queue.submit([encoder.finish()]);
    read(&outputs)
}

/// RMSE of `a` against `b` over the pixels `keep` selects.
pub fn rmse(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool) -> f64 {
    let errors: Vec<f64> = (0..a.len())
        .filter(|&i| keep(i))
        .map(|i| f64::from(a[i] - b[i]).powi(2))
        .collect();
    (errors.iter().sum::<f64>() / errors.len() as f64).sqrt()
}
