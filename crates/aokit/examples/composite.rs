//! Shading with aokit's occlusion functions: multi-bounce AO on the diffuse ambient light and
//! specular occlusion (GTSO, from the bent normals) on the ambient reflection.
//!
//! ```sh
//! cargo run -p aokit --example composite -- out.png [WIDTHxHEIGHT]   # default composite.png
//! ```
//!
//! The same renderer as the `forward` example (`common/mod.rs`); what aokit adds lies between
//! the `aokit: begin` and `aokit: end` comments. docs/composite.md derives the functions;
//! docs/integration.md has the conventions.

mod common;

use std::path::Path;

use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, Preset};
use common::{Renderer, Result, Stats};

/// The lighting pass's fragment shader, after common/scene.wgsl and aokit's
/// `shader::OCCLUSION` (`multi_bounce_gtao`, `specular_occlusion_gtso`).
const LIGHTING: &str = r#"
// --- aokit: begin ---
// The AO (R32Float, 1 = unoccluded) and the bent normals (Rgba16Float, view space in xyz): one
// texel per pixel.
@group(1) @binding(0) var ao_texture: texture_2d<f32>;
@group(1) @binding(1) var bent_normal_texture: texture_2d<f32>;
// --- aokit: end ---

// Reflectance of a dielectric (index 1.5) at normal incidence.
const F0: f32 = 0.04;

@fragment
fn fs_lighting(in: VertexOut) -> @location(0) vec4<f32> {
    let v = normalize(-in.view_position);
    // Interpolated normals can face away from the eye at silhouettes (the sphere's facets): tilt
    // them towards it, or their reflection points into the surface and GTSO takes it all away.
    let interpolated = normalize(in.view_normal);
    let n = normalize(interpolated + v * max(0.1 - dot(interpolated, v), 0.0));
    let n_dot_v = saturate(dot(n, v));
    // Schlick's Fresnel for the ambient reflection, its grazing value lowered for rough surfaces.
    let fresnel = F0 + (max(1.0 - in.roughness, F0) - F0) * pow(1.0 - n_dot_v, 5.0);
    let sun = frame.sun_color.rgb * max(dot(n, frame.sun_direction.xyz), 0.0);
    // --- aokit: begin ---
    let pixel = vec2<u32>(in.clip.xy);
    let ao = textureLoad(ao_texture, pixel, 0).r;
    let bent_normal = textureLoad(bent_normal_texture, pixel, 0).xyz;
    // Diffuse: occluded directions still show lit surfaces, the more so the brighter they are.
    let diffuse_occlusion = multi_bounce_gtao(ao, in.albedo);
    // Specular: the part of the reflection lobe inside the cone of open directions. Both vectors
    // are in view space, like the bent normals.
    let specular_occlusion =
        specular_occlusion_gtso(bent_normal, reflect(-v, n), ao, in.roughness);
    // --- aokit: end ---
    let ambient = frame.sky_color.rgb;
    let diffuse = in.albedo * (sun + ambient * (1.0 - fresnel) * diffuse_occlusion);
    let specular = ambient * fresnel * specular_occlusion;
    return vec4<f32>(diffuse + specular, 1.0);
}
"#;

fn main() -> Result<()> {
    common::main("composite", run)
}

/// Renders one frame of `size` pixels with AO and writes it to `out` as PNG. (`cargo test`
/// runs it too: see `common::tests`.)
fn run(gpu: &GpuContext, out: &Path, size: [u32; 2]) -> Result<Stats> {
    let (device, queue) = (&gpu.device, &gpu.queue);

    // --- aokit: begin (once) ---
    // GTAO at High with the spatial filter, as in `forward`, and the bent normals GTSO needs.
    let mut settings = AoSettings::preset(Method::Gtao, Preset::High);
    settings.radius = 0.75;
    settings.spatial.enabled = true;
    settings.bent_normals = true;
    let mut ao = AoPipeline::new(device, queue, &settings)?;
    // Group 1 of the lighting pass: the AO and the bent normals.
    let ao_layout = common::load_textures_layout(device, 2);
    // The occlusion functions go before the lighting shader that calls them.
    let lighting = [aokit::shader::OCCLUSION, LIGHTING];
    // --- aokit: end ---

    let renderer = Renderer::new(device, size, &lighting, &ao_layout);
    let mut encoder = device.create_command_encoder(&Default::default());
    renderer.prepass(&mut encoder);

    // --- aokit: begin (each frame, between the prepass and the lighting pass) ---
    let inputs = AoInputs {
        normals: Some((&renderer.normals).into()),
        view_from_world: renderer.camera.view_from_world,
        ..AoInputs::new(&renderer.depth, renderer.camera.projection)
    };
    let outputs = ao.encode(device, queue, &mut encoder, &inputs)?;
    let bent_normals = outputs
        .bent_normals_view
        .ok_or("bent normals are on in the settings")?;
    let views = [outputs.ao_view, bent_normals];
    let ao_group = common::load_textures_group(device, &ao_layout, &views);
    // --- aokit: end ---

    renderer.lighting(&mut encoder, &ao_group);
    renderer.finish(gpu, encoder, &outputs, out)
}
