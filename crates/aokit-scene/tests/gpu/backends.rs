//! wgpu's GL backend (llvmpipe's GL with Mesa's EGL in CI): the frames Vulkan renders, with
//! every two-channel target in `Rgba32Float`, since GL has no `Rg32Float` storage textures, and
//! every method.
//!
//! Skipped (with a notice) where no GL adapter exists, unless `AOKIT_REQUIRE_GL` is set, as CI
//! sets it.

use crate::common;

use aokit::gpu::PairFormat;
use aokit::{AoSettings, GpuContext, Method, Preset, Resolution, SpatialKind};
use aokit_scene::{Builtin, CameraPath, Frame, Scene};
use common::{gpu, mean_abs_difference, render_frame, scene_settings};

const SIZE: [u32; 2] = [96, 64];

/// A device on this machine's first GL adapter, when it has one.
fn gl_gpu() -> Option<GpuContext> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::GL,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let Some(adapter) = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::GL))
        .into_iter()
        .next()
    else {
        assert!(
            std::env::var_os("AOKIT_REQUIRE_GL").is_none(),
            "AOKIT_REQUIRE_GL is set but wgpu finds no GL adapter; apt-get install libegl-mesa0 \
             libgl1-mesa-dri"
        );
        eprintln!("skipped: no GL adapter on this machine");
        return None;
    };
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_limits: adapter.limits(),
        ..Default::default()
    }))
    .expect("a device on the GL adapter");
    Some(GpuContext {
        device,
        queue,
        adapter_info: adapter.get_info(),
    })
}

/// Two frames of the scene's first camera orbiting, the second reprojecting the first.
fn orbit(gpu: &GpuContext, scene: &Scene, settings: &AoSettings) -> Vec<Frame> {
    let mut renderer = aokit_scene::Renderer::new(gpu, scene, settings).unwrap();
    (0..2)
        .map(|i| {
            let camera = CameraPath::Orbit.at(&scene.cameras[0], i as f32);
            renderer.render(gpu, &camera, SIZE, i).unwrap()
        })
        .collect()
}

#[test]
fn gl_renders_the_frames_vulkan_renders() {
    let Some(gl) = gl_gpu() else { return };
    let vulkan = gpu();
    assert_eq!(PairFormat::of(&gl.device), PairFormat::Rgba32Float);
    assert_eq!(PairFormat::of(&vulkan.device), PairFormat::Rg32Float);
    let scene = Builtin::Room.build();
    let base = scene_settings(&scene, Method::Gtao, Preset::High);
    // Every pass that writes a two-channel target: the downsample's motion vectors, both kinds
    // of spatial filter and the temporal history.
    let mut half = AoSettings {
        resolution: Resolution::Half,
        ..base
    };
    half.spatial.enabled = true;
    half.temporal.enabled = true;
    let mut guided = base;
    guided.spatial.enabled = true;
    guided.spatial.kind = SpatialKind::Guided;
    for (name, settings) in [("half resolution, both filters", half), ("guided", guided)] {
        let on_gl = orbit(&gl, &scene, &settings);
        let on_vulkan = orbit(&vulkan, &scene, &settings);
        for (i, (a, b)) in on_gl.iter().zip(&on_vulkan).enumerate() {
            assert!(a.ao.iter().all(|v| (0.0..=1.0).contains(v)), "{name}");
            let mean = mean_abs_difference(&a.ao, &b.ao);
            // The two compilers round differently, and where that flips a depth test a pixel
            // differs by more.
            let near =
                a.ao.iter()
                    .zip(&b.ao)
                    .filter(|(x, y)| (*x - *y).abs() < 1e-2);
            let near = near.count() as f32 / a.ao.len() as f32;
            eprintln!("{name}, frame {i}: mean |GL - Vulkan| {mean:.2e}, within 0.01: {near:.4}");
            assert!(
                mean < 1e-3 && near > 0.98,
                "{name}, frame {i}: {mean}, {near}"
            );
        }
    }
}

/// Every method at `high` on `stairs`: SAO, UE4's SSAO and MSVO read levels of the depth chain
/// (naga's GLSL output needed their levels as i32, and MSVO a texture per level).
#[test]
fn every_method_renders_on_gl_as_on_vulkan() {
    let Some(gl) = gl_gpu() else { return };
    let vulkan = gpu();
    let scene = Builtin::Stairs.build();
    for method in Method::ALL {
        let settings = scene_settings(&scene, method, Preset::High);
        let [a, b] =
            [&gl, &vulkan].map(|gpu| render_frame(gpu, &scene, &scene.cameras[0], &settings, SIZE));
        let mean = mean_abs_difference(&a.ao, &b.ao);
        eprintln!("{}: mean |GL - Vulkan| {mean:.2e}", method.name());
        assert!(mean < 1e-3, "{}: {mean}", method.name());
    }
}

/// VBAO measuring its occluders from the back faces: the renderer reads their depth back, which
/// on GL takes a compute copy (GL copies no depth texture to a buffer).
#[test]
fn back_faces_render_and_read_back_on_gl() {
    let Some(gl) = gl_gpu() else { return };
    let vulkan = gpu();
    let scene = Builtin::Stairs.build();
    let mut settings = scene_settings(&scene, Method::Vbao, Preset::High);
    settings.vbao.back_faces = true;
    let [a, b] =
        [&gl, &vulkan].map(|gpu| render_frame(gpu, &scene, &scene.cameras[0], &settings, SIZE));
    let mean = mean_abs_difference(&a.ao, &b.ao);
    let (back_a, back_b) = (a.back_depth.unwrap(), b.back_depth.unwrap());
    let scale = back_b.iter().sum::<f32>() / back_b.len() as f32;
    let back = mean_abs_difference(&back_a, &back_b) / scale;
    eprintln!("mean |GL - Vulkan|: AO {mean:.2e}, back depth {back:.2e} of its mean");
    assert!(mean < 1e-3 && back < 1e-4, "{mean}, {back}");
}
