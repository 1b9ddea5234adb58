//! `aokit reference`: ray-traced ground-truth AO for a scene and camera.

use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow};
use aokit_eval::{write_exr, write_grey_png};
use aokit_reference::{AoOptions, Falloff, ReferenceImage, Tracer};
use aokit_scene::{Camera, CameraFile, Scene};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use serde::{Deserialize, Serialize};

use crate::camera_args::CameraArgs;
use crate::export::{check_out_dir, create_dir, write_back_depth, write_gbuffer, write_json};
use crate::render::parse_size;

#[derive(Args, Debug)]
pub struct ReferenceArgs {
    /// Built-in scene (room, stairs, thin, open) or a .gltf/.glb/.obj file.
    #[arg(long, default_value = "room")]
    pub scene: String,
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Image size.
    #[arg(long, value_name = "WxH", default_value = "640x360", value_parser = parse_size, allow_hyphen_values = true)]
    pub size: [u32; 2],
    /// AO radius in world units (default: the scene's suggested radius, else 1).
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f32>,
    /// Rays per pixel.
    #[arg(long, default_value_t = 256, value_parser = crate::reference::parse_spp, allow_negative_numbers = true)]
    pub spp: u32,
    /// Seed of the per-pixel sample scrambling; the same seed gives the same image.
    #[arg(long, default_value_t = 0, allow_negative_numbers = true)]
    pub seed: u64,
    /// How a hit at distance t counts: none (1), linear (1 - t/R), quadratic (1 - (t/R)^2).
    /// (Formerly `--falloff`, which the methods' numeric `falloff` setting is also called.)
    #[arg(long, value_name = "CURVE", default_value = "none", alias = "falloff")]
    pub falloff_curve: Falloff,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "aokit-out")]
    pub out: PathBuf,
}

/// `--spp`: rays per pixel, at least 1. Negative values reach here (the flag allows a leading
/// minus so that clap does not take `-1` for a flag) and are named as such.
pub fn parse_spp(s: &str) -> Result<u32, String> {
    let n: i64 = s
        .trim()
        .parse()
        .map_err(|e| format!("`{s}` is not a whole number of rays per pixel: {e}"))?;
    if n < 1 {
        return Err(format!("rays per pixel must be at least 1, got {n}"));
    }
    u32::try_from(n).map_err(|_| format!("rays per pixel must be at most {}, got {n}", u32::MAX))
}

/// What a reference was traced with, saved beside it as `reference.json` so that `aokit
/// compare --inputs` scores methods with the same radius and says what it scored against.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReferenceInfo {
    /// The scene's name (a built-in one's, or the file's), and the camera's; absent in files
    /// from before they were recorded.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub camera: Option<String>,
    /// Width and height traced.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<[u32; 2]>,
    /// AO radius in world units.
    pub radius: f32,
    /// Rays per pixel.
    pub spp: u32,
    /// Scrambling seed.
    pub seed: u64,
    /// `none`, `linear` or `quadratic`.
    pub falloff: String,
}

impl ReferenceInfo {
    pub fn new(scene: &Scene, camera: &Camera, size: [u32; 2], options: &AoOptions) -> Self {
        Self {
            scene: Some(scene.name.clone()),
            camera: Some(camera.name.clone()),
            size: Some(size),
            radius: options.radius,
            spp: options.spp,
            seed: options.seed,
            falloff: options.falloff.name().to_string(),
        }
    }

    pub fn read(dir: &Path) -> Result<Self> {
        let path = dir.join("reference.json");
        let text = std::fs::read_to_string(&path)
            .map_err(|e| anyhow!("cannot read {}: {e}", path.display()))?;
        serde_json::from_str(&text)
            .map_err(|e| anyhow!("{} is not a reference.json: {e}", path.display()))
    }

    /// What the reference is, for a report: "`room` from camera `front`, 512 rays per pixel,
    /// radius 1, falloff none".
    pub fn describe(&self) -> String {
        let view = match (&self.scene, &self.camera) {
            (Some(scene), Some(camera)) => format!("`{scene}` from camera `{camera}`, "),
            _ => String::new(),
        };
        format!(
            "{view}{} rays per pixel, radius {}, falloff {}",
            self.spp, self.radius, self.falloff
        )
    }
}

/// A bar on stderr (drawn only where stderr is a terminal) over `len` steps of `unit`:
/// "VERB MESSAGE [====>    ] 3/8UNIT, 12s left".
pub fn progress_bar(len: u64, verb: &str, unit: &str) -> ProgressBar {
    ProgressBar::new(len).with_style(
        ProgressStyle::with_template(&format!(
            "{verb} {{msg}} [{{bar:30}}] {{pos}}/{{len}}{unit}, {{eta}} left"
        ))
        .expect("progress template is valid")
        .progress_chars("=> "),
    )
}

/// Traces `camera`'s view of `scene` with a progress bar on stderr.
pub fn trace(
    scene: &Scene,
    camera: &Camera,
    size: [u32; 2],
    options: &AoOptions,
) -> Result<ReferenceImage> {
    trace_on(&scene_tracer(scene)?, scene, camera, size, options)
}

pub fn scene_tracer(scene: &Scene) -> Result<Tracer> {
    scene_tracer_at(scene, 0.0)
}

/// The tracer of `scene` with its moving parts where they are at `time` of a sequence.
pub fn scene_tracer_at(scene: &Scene, time: f32) -> Result<Tracer> {
    aokit_scene::reference::tracer_at(scene, time).map_err(|e| anyhow!("{}: {e}", scene.name))
}

/// [`trace`] with the scene's tracer built.
fn trace_on(
    tracer: &Tracer,
    scene: &Scene,
    camera: &Camera,
    size: [u32; 2],
    options: &AoOptions,
) -> Result<ReferenceImage> {
    let bar = progress_bar(u64::from(size[1]), "tracing", " rows");
    bar.set_message(format!("{} ({} rays per pixel)", scene.name, options.spp));
    let image = trace_reporting(tracer, scene, camera, size, options, &|rows| {
        bar.set_position(rows as u64)
    });
    bar.finish_and_clear();
    image
}

/// Traces `camera`'s view of `scene` with its tracer, calling `rows_done` with the number of
/// rows finished as they finish (`aokit view` shows it in its panel); the options, camera and
/// projection are checked first.
pub fn trace_reporting(
    tracer: &Tracer,
    scene: &Scene,
    camera: &Camera,
    size: [u32; 2],
    options: &AoOptions,
    rows_done: &(dyn Fn(usize) + Sync),
) -> Result<ReferenceImage> {
    options.validate()?;
    camera.validate().map_err(|e| anyhow!(e))?;
    // The projection written to camera.json afterwards, checked before the trace (planes
    // fitted to the scene included), so that nothing is written that `aokit ao` refuses.
    camera
        .projection(size[0] as f32 / size[1] as f32, &scene.bounds)
        .validate()
        .map_err(|e| anyhow!("camera `{}`: {e}", camera.name))?;
    let pixel_camera = aokit_scene::reference::pixel_camera(scene, camera, size);
    Ok(tracer.render(&pixel_camera, options, rows_done)?)
}

pub fn run(args: &ReferenceArgs) -> Result<()> {
    check_out_dir(&args.out)?;
    let scene = Scene::open(&args.scene)?;
    let camera = args.camera.resolve(&scene)?;
    let options = AoOptions {
        radius: args.radius.or(scene.suggested_radius).unwrap_or(1.0),
        spp: args.spp,
        seed: args.seed,
        falloff: args.falloff_curve,
    };
    let started = std::time::Instant::now();
    let tracer = scene_tracer(&scene)?;
    let image = trace_on(&tracer, &scene, &camera, args.size, &options)?;
    let elapsed = started.elapsed();
    // For `vbao.back_faces` when the directory is scored with `aokit compare --inputs`, as
    // `aokit render` writes it from the rasteriser.
    let pixel_camera = aokit_scene::reference::pixel_camera(&scene, &camera, args.size);
    let back_depth = tracer.back_depth(&pixel_camera)?;

    let out = &args.out;
    create_dir(out)?;
    write_exr(
        &out.join("reference.exr"),
        image.size,
        &[("Y", image.ao.clone())],
    )?;
    write_grey_png(&out.join("reference.png"), image.size, &image.ao)?;
    let projection = camera.projection(image.size[0] as f32 / image.size[1] as f32, &scene.bounds);
    let gbuffer = write_gbuffer(
        out,
        "",
        image.size,
        &image.linear_depth,
        &image.normals,
        &CameraFile::new(&projection, camera.view_from_world(), image.size),
    )?;
    let back = write_back_depth(out, "", image.size, &back_depth)?;
    let info = ReferenceInfo::new(&scene, &camera, image.size, &options);
    write_json(&out.join("reference.json"), &info)?;
    let rays = f64::from(image.size[0]) * f64::from(image.size[1]) * f64::from(options.spp);
    outln!(
        "traced `{}` from camera `{}` at {}x{}, {} rays per pixel, radius {}, falloff {} in {:.1} s \
         ({:.2} M rays/s): wrote reference.exr, reference.png, {}, {back}, reference.json to {}",
        scene.name,
        camera.name,
        image.size[0],
        image.size[1],
        options.spp,
        options.radius,
        options.falloff.name(),
        elapsed.as_secs_f64(),
        rays / elapsed.as_secs_f64() / 1e6,
        gbuffer.join(", "),
        out.display()
    );
    outln!(
        "{}",
        crate::render::ao_summary(&image.ao, &image.linear_depth)
    );
    Ok(())
}
