//! `aokit render`.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use aokit::debug::DebugView;
use aokit::{AdapterKind, GpuContext};
use aokit_scene::{Camera, CameraFile, CameraPath, Frame, Renderer, Scene};
use clap::Args;
use glam::Vec3;

use aokit_eval::{grey_to_rgba, write_exr, write_gif, write_grey_png, write_rgba_png};

use crate::camera_args::CameraArgs;
use crate::export::{check_out_dir, create_dir, write_back_depth, write_gbuffer};
use crate::lighting_args::LightingArgs;
use crate::settings_args::SettingsArgs;

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Built-in scene (room, stairs, thin, open) or a .gltf/.glb/.obj file.
    #[arg(long, default_value = "room")]
    pub scene: String,
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Image size.
    #[arg(long, value_name = "WxH", default_value = "1280x720", value_parser = parse_size, allow_hyphen_values = true)]
    pub size: [u32; 2],
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "aokit-out")]
    pub out: PathBuf,
    /// Also write depth.exr, normal.exr, camera.json and ao-settings.json (the settings this
    /// ran, which `aokit ao` reads back), and back_depth.exr when the settings measure back
    /// faces (`--set vbao.back_faces=true`); with --frames N, each frame's as
    /// frames/depth-NNN.exr and so on, for `aokit ao --sequence`.
    #[arg(long)]
    pub gbuffer: bool,
    /// Pixels of overscan on each side that the AO reads (a guard band): the G-buffer for the
    /// AO is drawn this much larger through a widened frustum, and the AO computed for the
    /// image of --size alone, so that occluders just off screen count at its edges. A
    /// multiple of the resolution's scale below full resolution. docs/integration.md gives
    /// the size to choose. With --gbuffer the overscan G-buffer is written, its camera.json
    /// recording the band, for `aokit ao`.
    #[arg(long, value_name = "PX", default_value_t = 0)]
    pub guard_band: u32,
    #[command(flatten)]
    pub lighting: LightingArgs,
    /// Render a sequence of this many frames along --path, each reprojecting the last (the
    /// temporal filter accumulates over them: on for N > 1 unless --set temporal.enabled=false
    /// turns it off): writes frames/ao-NNN.png and
    /// lit-NNN.png, animated ao.gif and lit.gif, and the last frame as ao.png, ao.exr, lit.png;
    /// with the temporal filter on, rejected.png (and frames/rejected-NNN.png): white where the
    /// frame rejected its history.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub frames: u32,
    /// How the camera moves over the frames: still, orbit (40 degrees about the target), dolly
    /// (30% of the way in) or strafe (sideways by 40% of the distance).
    #[arg(long, value_name = "PATH", default_value = "still")]
    pub path: CameraPath,
    /// Move the scene's moving parts over the frames, from rest at the first frame to the end
    /// of their motion at the last (room: the sphere rolls; stairs: a block slides; thin: a
    /// panel swings).
    #[arg(long)]
    pub animate: bool,
    /// Also write debug views of the last frame, as debug-VIEW.png: depth, working-depth (the
    /// depth the kernel read below full resolution), normals, edges (depth steps the filters
    /// and the upsample stop at), bent-normals, raw-ao (before filtering), ao, rejected.
    #[arg(long, value_name = "VIEW,...", value_delimiter = ',', value_parser = parse_debug_view)]
    pub debug: Vec<DebugView>,
}

fn parse_debug_view(s: &str) -> Result<DebugView, String> {
    s.parse()
}

/// Largest side `--size` accepts: twice the 8192 every wgpu device supports, far past any
/// screen; the total is held to the library's budget (`aokit::inputs::MAX_PIXELS`).
const MAX_SIDE: u32 = 16384;

pub fn parse_size(s: &str) -> Result<[u32; 2], String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("`{s}` is not WIDTHxHEIGHT"))?;
    let parse = |v: &str| {
        let v = v.trim();
        // `-64x48` reaches here (the flag allows a leading minus so that clap does not take
        // it for a flag): say what is wrong with it rather than "invalid digit".
        if v.starts_with('-') {
            return Err(format!("`{s}`: width and height must be at least 1"));
        }
        v.parse::<u32>()
            .map_err(|e| format!("`{s}` is not WIDTHxHEIGHT: {e}"))
    };
    let size = [parse(w)?, parse(h)?];
    if size.contains(&0) {
        return Err(format!("`{s}`: width and height must be at least 1"));
    }
    if size.iter().any(|&side| side > MAX_SIDE) {
        return Err(format!(
            "`{s}`: width and height must be at most {MAX_SIDE}"
        ));
    }
    // The library's total budget, checked here before anything is allocated.
    aokit::inputs::check_size(size).map_err(|e| format!("`{s}`: {e}"))?;
    Ok(size)
}

/// Opens a headless device and says so when it is a software rasteriser.
pub fn open_gpu() -> Result<GpuContext> {
    open_gpu_with(wgpu::Features::empty())
}

/// [`open_gpu`], also asking for those of `features` the adapter has.
pub fn open_gpu_with(features: wgpu::Features) -> Result<GpuContext> {
    let gpu = GpuContext::headless_with_features(features)?;
    if gpu.adapter_kind() == AdapterKind::Software {
        eprintln!(
            "note: no GPU found, rendering on the software adapter {} (slow)",
            gpu.describe()
        );
    }
    Ok(gpu)
}

pub fn run(args: &RenderArgs) -> Result<()> {
    check_out_dir(&args.out)?;
    if args.guard_band > 0 && args.gbuffer && args.frames > 1 {
        bail!(
            "--guard-band with --gbuffer writes the overscan G-buffer of a single frame; drop \
             --frames, or --gbuffer"
        );
    }
    let scene = Scene::open(&args.scene)?;
    for note in &scene.notes {
        eprintln!("note: {}: {note}", scene.name);
    }
    let camera = args.camera.resolve(&scene)?;
    // Frames that follow each other get the temporal filter (`--set temporal.enabled=false`
    // still turns it off).
    let settings = if args.frames > 1 {
        args.settings.resolve_for_sequence(scene.suggested_radius)?
    } else {
        args.settings.resolve(scene.suggested_radius)?
    };
    let gpu = open_gpu()?;
    let mut renderer = Renderer::new(&gpu, &scene, &settings)?;
    renderer.guard_band = args.guard_band;
    args.lighting
        .apply(&mut renderer.lighting, settings.method)?;
    for note in
        crate::sequence::single_frame_notes(args.frames, args.path, settings.temporal.enabled)
    {
        eprintln!("note: {note}");
    }
    if args.animate && scene.moving_parts.is_empty() {
        eprintln!(
            "note: `{}` has no moving parts: --animate changes nothing",
            scene.name
        );
    }
    let out = &args.out;
    create_dir(out)?;
    let mut previews = (Vec::new(), Vec::new());
    let mut last = None;
    for i in 0..args.frames {
        let t = if args.frames > 1 {
            i as f32 / (args.frames - 1) as f32
        } else {
            0.0
        };
        let time = if args.animate { t } else { 0.0 };
        if i + 1 == args.frames {
            renderer.debug_views.clone_from(&args.debug);
        }
        let frame = renderer.render_at(&gpu, &args.path.at(&camera, t), args.size, i, time)?;
        if frame.ao.iter().any(|v| !v.is_finite()) {
            bail!(
                "the AO pass produced non-finite values: please report this with the command line"
            );
        }
        if args.frames > 1 {
            let frames = out.join("frames");
            create_dir(&frames)?;
            write_grey_png(
                &frames.join(format!("ao-{i:03}.png")),
                frame.size,
                &frame.ao,
            )?;
            write_rgba_png(
                &frames.join(format!("lit-{i:03}.png")),
                frame.size,
                &frame.lit,
            )?;
            if let Some((rejected, size)) = &frame.history_rejected {
                write_grey_png(
                    &frames.join(format!("rejected-{i:03}.png")),
                    *size,
                    rejected,
                )?;
            }
            if args.gbuffer {
                write_frame_gbuffer(&frames, &format!("-{i:03}"), &frame)?;
            }
            previews.0.push(grey_to_rgba(&frame.ao));
            previews.1.push(frame.lit.clone());
        }
        last = Some(frame);
    }
    let frame = last.expect("at least one frame was rendered");
    write_grey_png(&out.join("ao.png"), frame.size, &frame.ao)?;
    write_exr(&out.join("ao.exr"), frame.size, &[("Y", frame.ao.clone())])?;
    write_rgba_png(&out.join("lit.png"), frame.size, &frame.lit)?;
    let mut written: Vec<String> = ["ao.png", "ao.exr", "lit.png"].map(String::from).into();
    if let Some((rejected, size)) = &frame.history_rejected {
        write_grey_png(&out.join("rejected.png"), *size, rejected)?;
        written.push("rejected.png".into());
    }
    for (view, image) in &frame.debug {
        let name = format!("debug-{}.png", view.name());
        write_rgba_png(&out.join(&name), frame.size, image)?;
        written.push(name);
    }
    if args.frames > 1 {
        // 30 frames per second, the pace the sequence would play at.
        write_gif(&out.join("ao.gif"), frame.size, &previews.0, 33)?;
        write_gif(&out.join("lit.gif"), frame.size, &previews.1, 33)?;
        written.extend(["frames/", "ao.gif", "lit.gif"].map(String::from));
    }
    if args.gbuffer && args.guard_band > 0 {
        let camera = args.path.at(&camera, 0.0);
        let overscan = Overscan {
            renderer: &mut renderer,
            gpu: &gpu,
            camera: &camera,
            band: args.guard_band,
        };
        written.extend(overscan.write(out, &frame)?);
    } else if args.gbuffer {
        written.extend(write_frame_gbuffer(out, "", &frame)?);
    }
    if args.gbuffer {
        let preset = args.settings.preset()?;
        written.push(crate::recorded::write(out, preset, &settings)?.into());
        if args.frames > 1 {
            crate::recorded::write(&out.join("frames"), preset, &settings)?;
            written.push("frames/ depth, normals and cameras".into());
        }
    }
    outln!(
        "rendered `{}` from camera `{}` at {}x{} with {} (radius {}): wrote {} to {}",
        scene.name,
        camera.name,
        frame.size[0],
        frame.size[1],
        settings.method.name(),
        settings.radius,
        written.join(", "),
        out.display()
    );
    outln!("{}", ao_summary(&frame.ao, &frame.linear_depth));
    Ok(())
}

/// Writes `frame`'s G-buffer into `dir` (see [`write_gbuffer`]); returns the files' names.
fn write_frame_gbuffer(dir: &Path, suffix: &str, frame: &Frame) -> Result<Vec<String>> {
    let mut written: Vec<String> = write_gbuffer(
        dir,
        suffix,
        frame.size,
        &frame.linear_depth,
        &frame.normals,
        &CameraFile::new(&frame.projection, frame.view_from_world, frame.size),
    )?
    .into();
    if let Some(back_depth) = &frame.back_depth {
        written.push(write_back_depth(dir, suffix, frame.size, back_depth)?);
    }
    Ok(written)
}

/// The overscan G-buffer of a frame rendered with a guard band.
struct Overscan<'a> {
    renderer: &'a mut Renderer,
    gpu: &'a GpuContext,
    camera: &'a Camera,
    band: u32,
}

impl Overscan<'_> {
    /// Draws the G-buffer the AO of `frame` read (the scene at rest) and writes it into `dir`
    /// with the camera's inner frame and the band in camera.json, as `aokit ao` reads it back;
    /// returns the files' names.
    fn write(self, dir: &Path, frame: &Frame) -> Result<Vec<String>> {
        let (gbuffer, projection) = self.renderer.render_gbuffer_with_guard_band(
            self.gpu,
            self.camera,
            frame.size,
            aokit::NormalEncoding::Oct32,
            self.band,
        )?;
        let widened = projection.with_guard_band(frame.size, self.band);
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let linear = |texture| -> Result<Vec<f32>> {
            let ndc = aokit::gpu::read_texture_f32(device, queue, texture)?;
            Ok(ndc.iter().map(|&d| widened.surface_depth(d)).collect())
        };
        let depth = linear(&gbuffer.depth)?;
        let packed: Vec<u32> = bytemuck::pod_collect_to_vec(&aokit::gpu::read_texture(
            device,
            queue,
            &gbuffer.normals,
        )?);
        let normals: Vec<Vec3> = packed
            .iter()
            .zip(&depth)
            .map(|(&bits, &d)| match d > 0.0 {
                true => aokit::normals::unpack_oct32(bits),
                false => Vec3::ZERO,
            })
            .collect();
        let mut written: Vec<String> = write_gbuffer(
            dir,
            "",
            gbuffer.size,
            &depth,
            &normals,
            // The camera's inner frame, and the band the images add to it.
            &CameraFile {
                guard_band: self.band,
                ..CameraFile::new(&projection, frame.view_from_world, frame.size)
            },
        )?
        .into();
        if let (Some(_), Some(back)) = (&frame.back_depth, &gbuffer.back_depth) {
            written.push(write_back_depth(dir, "", gbuffer.size, &linear(back)?)?);
        }
        Ok(written)
    }
}

/// Mean and minimum AO over the pixels that show a surface.
pub fn ao_summary(ao: &[f32], linear_depth: &[f32]) -> String {
    let covered: Vec<f32> = ao
        .iter()
        .zip(linear_depth)
        .filter(|&(_, &d)| d > 0.0)
        .map(|(&a, _)| a)
        .collect();
    if covered.is_empty() {
        return "no surface in view".to_string();
    }
    let mean = covered.iter().sum::<f32>() / covered.len() as f32;
    let min = covered.iter().copied().fold(1.0f32, f32::min);
    format!(
        "AO over the {:.1}% of pixels showing a surface: mean {mean:.4}, min {min:.4}",
        100.0 * covered.len() as f32 / ao.len() as f32
    )
}
