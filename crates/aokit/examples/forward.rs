//! Adding aokit to a wgpu forward renderer: depth prepass, then AO, then the lighting pass.
//!
//! ```sh
//! cargo run -p aokit --example forward -- out.png [WIDTHxHEIGHT]   # default forward.png, 960x540
//! ```
//!
//! The renderer itself (scene, prepass, lighting pass, PNG) is in `common/mod.rs` and stands in
//! for yours. What aokit adds to it lies between the `aokit: begin` and `aokit: end` comments:
//! the Rust below and the lines of the lighting shader that read the AO. The prepass's side
//! (reverse-Z `Depth32Float` depth and oct32 normals) is in `common/`; docs/integration.md has
//! the conventions.

mod common;

use std::path::Path;

use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, Preset, SpatialSettings};
use common::{Renderer, Result, Stats};

/// The lighting pass's fragment shader, after common/scene.wgsl: sunlight plus the sky's
/// ambient light, which the AO darkens.
const LIGHTING: &str = r#"
// --- aokit: begin ---
// The AO (R32Float, 1 = unoccluded) at the lighting pass's resolution: one texel per pixel.
@group(1) @binding(0) var ao_texture: texture_2d<f32>;
// --- aokit: end ---

@fragment
fn fs_lighting(in: VertexOut) -> @location(0) vec4<f32> {
    let n = normalize(in.view_normal);
    let sun = frame.sun_color.rgb * max(dot(n, frame.sun_direction.xyz), 0.0);
    // --- aokit: begin ---
    let ao = textureLoad(ao_texture, vec2<u32>(in.clip.xy), 0).r;
    // AO darkens the ambient light only: direct light has its own visibility (shadows).
    let ambient = frame.sky_color.rgb * ao;
    // --- aokit: end ---
    return vec4<f32>(in.albedo * (sun + ambient), 1.0);
}
"#;

fn main() -> Result<()> {
    common::main("forward", run)
}

/// Renders one frame of `size` pixels with AO and writes it to `out` as PNG. (`cargo test`
/// runs it too: see `common::tests`.)
fn run(gpu: &GpuContext, out: &Path, size: [u32; 2]) -> Result<Stats> {
    let (device, queue) = (&gpu.device, &gpu.queue);

    // --- aokit: begin (once) ---
    // GTAO at its High preset, with the spatial filter on. The radius is in world units: how
    // far away an occluder still counts (the boxes here are 1 m).
    let settings = AoSettings {
        radius: 0.75,
        spatial: SpatialSettings {
            enabled: true,
            ..SpatialSettings::default()
        },
        ..AoSettings::preset(Method::Gtao, Preset::High)
    };
    let mut ao = AoPipeline::new(device, queue, &settings)?;
    // The lighting pass binds the AO as group 1: one unfilterable float texture.
    let ao_layout = common::load_textures_layout(device, 1);
    // --- aokit: end ---

    let renderer = Renderer::new(device, size, &[LIGHTING], &ao_layout);
    let mut encoder = device.create_command_encoder(&Default::default());
    renderer.prepass(&mut encoder);

    // --- aokit: begin (each frame, between the prepass and the lighting pass) ---
    let outputs = ao.encode(
        device,
        queue,
        &mut encoder,
        &AoInputs {
            normals: Some((&renderer.normals).into()),
            // The temporal filter (off here) reprojects with the camera; the frame counter
            // moves the sampling noise each frame.
            view_from_world: renderer.camera.view_from_world,
            frame_index: 0,
            ..AoInputs::new(&renderer.depth, renderer.camera.projection)
        },
    )?;
    // The AO texture is the pipeline's: it lives until the size or resolution changes, so a
    // renderer may keep this bind group while its `outputs.ao` is the same texture.
    let ao_group = common::load_textures_group(device, &ao_layout, &[outputs.ao_view]);
    // --- aokit: end ---

    renderer.lighting(&mut encoder, &ao_group);
    renderer.finish(gpu, encoder, &outputs, out)
}
