//! The harness on the GPU with the stand-in XeGTAO (tests/data/peer-stand-in), whose passes
//! compute what these tests can check: view depth, a normal's facing, a box filter. With
//! `AOKIT_XEGTAO_DIR` naming a checkout of XeGTAO, the depth test also runs on the real one.

use std::path::{Path, PathBuf};

use aokit::{GpuContext, NormalEncoding, Preset, Projection};
use aokit_scene::gbuffer::GBuffer;
use aokit_scene::{Renderer, Scene};

use super::compile::compiler;
use super::{PeerSettings, PeerSpec, ShaderPath, Shaders, XeGtao};

const SIZE: [u32; 2] = [72, 40];

/// Whether glslangValidator runs; without it the test is skipped, or fails where
/// `AOKIT_REQUIRE_GLSLANG=1` (CI) says it must be there.
pub fn have_compiler() -> bool {
    match compiler() {
        Ok(_) => true,
        Err(e) if std::env::var("AOKIT_REQUIRE_GLSLANG").as_deref() == Ok("1") => {
            panic!("AOKIT_REQUIRE_GLSLANG=1 but: {e:#}")
        }
        Err(e) => {
            eprintln!("skipping: {e:#}");
            false
        }
    }
}

fn stand_in() -> PeerSpec {
    PeerSpec {
        name: "xegtao".into(),
        dir: Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/peer-stand-in"),
    }
}

/// The room's G-buffer (oct32 normals) and projection.
fn room(gpu: &GpuContext) -> (GBuffer, Projection) {
    let scene = Scene::open("room").unwrap();
    let camera = scene.camera(None).unwrap();
    let mut renderer = Renderer::new(gpu, &scene, &Default::default()).unwrap();
    renderer
        .render_gbuffer(gpu, &camera, SIZE, NormalEncoding::Oct32)
        .unwrap()
}

/// Runs one frame of `spec` with `denoise_passes` through naga; the harness, for reading back.
fn run(
    gpu: &GpuContext,
    spec: &PeerSpec,
    gbuffer: &GBuffer,
    projection: &Projection,
    denoise_passes: u32,
) -> XeGtao {
    run_by(
        gpu,
        spec,
        gbuffer,
        projection,
        denoise_passes,
        ShaderPath::Naga,
    )
}

fn run_by(
    gpu: &GpuContext,
    spec: &PeerSpec,
    gbuffer: &GBuffer,
    projection: &Projection,
    denoise_passes: u32,
    path: ShaderPath,
) -> XeGtao {
    let mut settings = PeerSettings::from_flags(Preset::High, 0.5, &[], true).unwrap();
    settings.denoise_passes = denoise_passes;
    let shaders = Shaders::load(spec, settings.quality).unwrap();
    let mut passes = XeGtao::new(&gpu.device, &shaders, path, &settings, SIZE).unwrap();
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    passes
        .encode(
            &gpu.device,
            &gpu.queue,
            &mut encoder,
            &gbuffer.depth,
            &gbuffer.normals,
            projection,
        )
        .unwrap();
    gpu.queue.submit([encoder.finish()]);
    passes
}

fn gpu() -> GpuContext {
    GpuContext::headless_with_features(super::FEATURES).unwrap()
}

/// XeGTAO's working depth against aokit's linear depth, on every surface pixel: equal to
/// half-float precision.
fn check_working_depth(spec: &PeerSpec) {
    let gpu = gpu();
    let (gbuffer, projection) = room(&gpu);
    let passes = run(&gpu, spec, &gbuffer, &projection, 0);
    let theirs = passes.read_working_depth(&gpu.device, &gpu.queue).unwrap();
    let depth = aokit::gpu::read_texture_f32(&gpu.device, &gpu.queue, &gbuffer.depth).unwrap();
    let mut surfaces = 0;
    for (i, (&d, &t)) in depth.iter().zip(&theirs).enumerate() {
        let ours = projection.surface_depth(d);
        if ours > 0.0 {
            surfaces += 1;
            assert!(
                (t - ours).abs() <= ours * 1e-3,
                "pixel {i}: {t} against {ours}"
            );
        }
    }
    assert!(
        surfaces > SIZE[0] * SIZE[1] / 2,
        "{surfaces} surface pixels"
    );
}

#[test]
fn working_depth_is_aokits_linear_depth() {
    if have_compiler() {
        check_working_depth(&stand_in());
    }
}

#[test]
fn working_depth_of_the_real_xegtao_is_aokits_linear_depth() {
    let Some(dir) = std::env::var_os("AOKIT_XEGTAO_DIR") else {
        eprintln!("skipping: AOKIT_XEGTAO_DIR names no checkout of XeGTAO");
        return;
    };
    if have_compiler() {
        check_working_depth(&PeerSpec {
            name: "xegtao".into(),
            dir: PathBuf::from(dir),
        });
    }
}

#[test]
fn normals_reach_the_main_pass_and_the_denoiser_output_is_read_back() {
    if !have_compiler() {
        return;
    }
    let gpu = gpu();
    let (gbuffer, projection) = room(&gpu);
    let bytes = aokit::gpu::read_texture(&gpu.device, &gpu.queue, &gbuffer.normals).unwrap();
    let normals = aokit::normals::decode_texels(NormalEncoding::Oct32, &bytes);
    // The stand-in's term: how squarely each normal faces the camera (+z in aokit's view
    // space), over XE_GTAO_OCCLUSION_TERM_SCALE in 8 bits.
    let term: Vec<f32> = normals
        .iter()
        .map(|n| (n.z.clamp(0.0, 1.0) / 1.5 * 255.0 + 0.5).floor())
        .collect();
    let [w, h] = SIZE.map(|v| v as usize);
    let final_value = |v: f32| (v * 1.5 + 0.5).floor().min(255.0) / 255.0;
    let close = |got: &[f32], want: &dyn Fn(usize) -> f32| {
        for (i, &g) in got.iter().enumerate() {
            assert!(
                (g - want(i)).abs() <= 1.01 / 255.0,
                "pixel {i}: {g} against {}",
                want(i)
            );
        }
    };

    let off = run(&gpu, &stand_in(), &gbuffer, &projection, 0)
        .read_visibility(&gpu.device, &gpu.queue)
        .unwrap();
    close(&off, &|i| final_value(term[i]));
    // The back wall and the objects face the camera: a sign error would zero them.
    let facing = off.iter().filter(|&&v| v > 0.5).count();
    assert!(facing > w * h / 20, "{facing} pixels face the camera");

    let box3 = |i: usize| {
        let (x, y) = ((i % w) as i64, (i / w) as i64);
        let mut sum = 0.0;
        for (dx, dy) in (-1..=1).flat_map(|dy| (-1..=1).map(move |dx| (dx, dy))) {
            let (sx, sy) = (
                (x + dx).clamp(0, w as i64 - 1),
                (y + dy).clamp(0, h as i64 - 1),
            );
            sum += term[sy as usize * w + sx as usize];
        }
        sum / 9.0
    };
    let one = run(&gpu, &stand_in(), &gbuffer, &projection, 1)
        .read_visibility(&gpu.device, &gpu.queue)
        .unwrap();
    close(&one, &|i| final_value(box3(i)));
}

#[test]
fn passed_through_the_modules_give_what_naga_gives() {
    if !have_compiler() {
        return;
    }
    let gpu = gpu();
    if !gpu
        .device
        .features()
        .contains(wgpu::Features::PASSTHROUGH_SHADERS)
    {
        eprintln!("skipping: the adapter cannot pass SPIR-V through");
        return;
    }
    let (gbuffer, projection) = room(&gpu);
    let read = |path| {
        run_by(&gpu, &stand_in(), &gbuffer, &projection, 2, path)
            .read_visibility(&gpu.device, &gpu.queue)
            .unwrap()
    };
    assert_eq!(read(ShaderPath::Passthrough), read(ShaderPath::Naga));
}
