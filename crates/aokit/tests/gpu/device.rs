//! A lost device answered with `AoError::DeviceLost` on whatever adapter exists (lavapipe in
//! CI). Running out of memory cannot be provoked reliably; its mapping is a unit test in
//! `src/device_errors.rs`.

use aokit::gpu::upload_texture_2d;
use aokit::{AoError, AoInputs, AoPipeline, AoSettings, GpuContext, Projection};

const SIZE: [u32; 2] = [16, 8];

#[test]
fn calls_after_the_device_is_destroyed_return_device_lost() {
    let gpu = GpuContext::headless()
        .expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)");
    let (device, queue) = (&gpu.device, &gpu.queue);
    let depth = upload_texture_2d(
        device,
        queue,
        "depth",
        SIZE,
        wgpu::TextureFormat::R32Float,
        bytemuck::cast_slice(&[2.0f32; 16 * 8]),
    )
    .unwrap();
    let settings = AoSettings::default();
    let mut pipeline = AoPipeline::new(device, queue, &settings).unwrap();
    let projection = Projection::perspective(1.0, 2.0, 0.1, None);
    let inputs = AoInputs::new(&depth, projection);
    let mut encoder = device.create_command_encoder(&Default::default());
    assert!(
        pipeline
            .encode(device, queue, &mut encoder, &inputs)
            .is_ok()
    );
    queue.submit([encoder.finish()]);

    device.destroy();
    // The lost callback runs while wgpu polls the device, once its queue is idle.
    device.poll(wgpu::PollType::wait_indefinitely()).ok();
    let mut encoder = device.create_command_encoder(&Default::default());
    let lost = |result: Result<(), AoError>| match result {
        Err(AoError::DeviceLost { reason }) => reason,
        other => panic!("{other:?}"),
    };
    let reason = lost(
        pipeline
            .encode(device, queue, &mut encoder, &inputs)
            .map(|_| ()),
    );
    assert_eq!(reason, "destroyed");
    lost(pipeline.set_settings(device, queue, &settings));
    let message = AoError::DeviceLost { reason }.to_string();
    assert!(
        message.contains("lost (destroyed)") && message.contains("new device"),
        "{message}"
    );
}
