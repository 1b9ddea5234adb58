//! Issue 29's bad inputs that reach the library: tiny depths, unusable normals and sizes past
//! the pixel budget are answered with the right AO or a clear error, never a silently wrong
//! answer. docs/reliability.md lists them all.

use aokit::{AoSettings, Method, Preset, Projection, SliceMarch};
use aokit_scene::external::{self, Passes};
use aokit_scene::{Builtin, RenderError, Renderer};
use glam::Vec3;

use crate::common::gpu;

fn flat_passes<'a>(size: [u32; 2], depth: &'a [f32], normals: Option<&'a [Vec3]>) -> Passes<'a> {
    Passes {
        size,
        linear_depth: depth,
        normals,
        back_depth: None,
        projection: Projection::perspective(1.0, 1.0, 0.1, None),
    }
}

/// A wall facing the camera at depth 1e-30 hides nothing: every method gives AO 1 there. GTAO
/// gave 0, its squared sample distances underflowing to 0 (an infinite inverse square root).
#[test]
fn a_wall_at_a_tiny_depth_is_unoccluded_for_every_method() {
    let gpu = gpu();
    let size = [16, 16];
    let depth = vec![1e-30f32; 16 * 16];
    let normals = vec![Vec3::Z; 16 * 16];
    for method in Method::ALL {
        for march in [SliceMarch::General, SliceMarch::Lean] {
            let mut settings = AoSettings::preset(method, Preset::Low);
            settings.slice_march = march;
            let passes = flat_passes(size, &depth, Some(&normals));
            let ao = external::ambient_occlusion(&gpu, &settings, &passes, 0).unwrap();
            let centre = ao[8 * 16 + 8];
            assert!(
                centre > 0.99,
                "{} ({march:?}): AO {centre} at depth 1e-30",
                method.name()
            );
        }
    }
}

/// Zero, NaN, infinite and far-from-unit normals where there is a surface are refused, naming
/// the count; before, they were normalised to a normal facing the camera (the room's mean AO
/// 0.95 fell to 0.28 with sao) without a word. Pixels without a surface may hold anything.
#[test]
fn unusable_normals_at_surfaces_are_refused_with_their_count() {
    let gpu = gpu();
    let size = [8, 8];
    let mut depth = vec![2.0f32; 64];
    depth[0] = 0.0; // no surface: its normal is not looked at
    let settings = AoSettings::preset(Method::Sao, Preset::Low);
    for bad in [Vec3::ZERO, Vec3::NAN, Vec3::INFINITY, Vec3::splat(0.1)] {
        let mut normals = vec![Vec3::Z; 64];
        normals[0] = Vec3::ZERO;
        normals[9] = bad;
        normals[10] = bad;
        let passes = flat_passes(size, &depth, Some(&normals));
        let err = external::ambient_occlusion(&gpu, &settings, &passes, 0)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("normals: 2 pixels showing a surface") && err.contains("x 1, y 1"),
            "{bad}: {err}"
        );
    }
    // Within the tolerance, normals are normalised and used.
    let normals = vec![Vec3::new(0.0, 0.0, 0.9); 64];
    let passes = flat_passes(size, &depth, Some(&normals));
    let ao = external::ambient_occlusion(&gpu, &settings, &passes, 0).unwrap();
    assert!(ao[27] > 0.99, "{}", ao[27]);
}

/// World-space normals with a zero (or non-finite) view_from_world would all turn into zero:
/// the pipeline refuses the inputs.
#[test]
fn world_normals_with_a_degenerate_view_from_world_are_refused() {
    let gpu = gpu();
    let size = [8, 8];
    let depth = crate::common::linear_depth_texture(&gpu, size, &[2.0; 64]);
    let normals = aokit::gpu::upload_texture_2d(
        &gpu.device,
        &gpu.queue,
        "normals",
        size,
        wgpu::TextureFormat::R32Uint,
        &aokit::normals::encode_texels(aokit::NormalEncoding::Oct32, &[Vec3::Z; 64]),
    )
    .unwrap();
    let mut settings = AoSettings::preset(Method::Gtao, Preset::Low);
    settings.normals.space = aokit::NormalSpace::World;
    let mut pipeline = aokit::AoPipeline::new(&gpu.device, &gpu.queue, &settings).unwrap();
    for matrix in [glam::Mat4::ZERO, glam::Mat4::NAN] {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        let inputs = aokit::AoInputs {
            normals: Some((&normals).into()),
            view_from_world: matrix,
            ..aokit::AoInputs::new(&depth, Projection::perspective(1.0, 1.0, 0.1, None))
        };
        let err = match pipeline.encode(&gpu.device, &gpu.queue, &mut encoder, &inputs) {
            Ok(_) => panic!("view_from_world {matrix} was not refused"),
            Err(e) => e.to_string(),
        };
        assert!(err.contains("view_from_world"), "{err}");
    }
}

/// The budget is on pixels, not only on sides: a renderer refuses 16384x16384 before it makes
/// its G-buffer (a device may allow 16384 a side).
#[test]
fn sizes_past_the_pixel_budget_are_refused_before_allocation() {
    let gpu = gpu();
    let scene = Builtin::Room.build();
    let mut renderer = Renderer::new(&gpu, &scene, &AoSettings::default()).unwrap();
    let max = gpu.device.limits().max_texture_dimension_2d;
    let side = max.min(16384);
    // At 8192 or less a side, every size is within the budget: nothing to refuse here.
    if u64::from(side) * u64::from(side) <= aokit::inputs::MAX_PIXELS {
        return;
    }
    match renderer.render(&gpu, &scene.cameras[0], [side, side], 0) {
        Err(RenderError::Size { reason, .. }) => {
            assert!(reason.contains("pixels"), "{reason}")
        }
        other => panic!("{side}x{side} was not refused: {:?}", other.err()),
    }
    let err = aokit::inputs::check_size([16384, 16384])
        .unwrap_err()
        .to_string();
    assert!(err.contains("268435456 pixels"), "{err}");
}

/// The CPU reference refuses the same budget before it allocates.
#[test]
fn the_reference_tracer_refuses_sizes_past_the_pixel_budget() {
    let scene = Builtin::Room.build();
    let tracer = aokit_scene::reference::tracer(&scene).unwrap();
    let camera = aokit_scene::reference::pixel_camera(&scene, &scene.cameras[0], [16384, 16384]);
    let options = aokit_reference::AoOptions {
        radius: 1.0,
        spp: 1,
        seed: 0,
        falloff: aokit_reference::Falloff::None,
    };
    let err = tracer
        .render(&camera, &options, &|_| {})
        .unwrap_err()
        .to_string();
    assert!(err.contains("268435456 pixels"), "{err}");
    let err = tracer.back_depth(&camera).unwrap_err().to_string();
    assert!(err.contains("268435456 pixels"), "{err}");
}
