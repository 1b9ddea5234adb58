//! `aokit compare`: every method and preset against the ray-traced reference, on the same
//! pixels, with images, error maps, a metrics table and an error-versus-cost chart.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow, bail};
use aokit::projection::pixel_to_ndc;
use aokit::{AoSettings, GpuContext, Method, NormalEncoding, NormalSpace, Preset, Projection};
use aokit_eval::report::{MethodResult, Report, ViewResult};
use aokit_eval::{
    Metrics, compare as score, depth_edge_mask, encode_png_grey, encode_png_rgb, error_map_rgb,
    grazing_mask, legend_rgb, read_scalar_exr, surface_mask,
};
use aokit_reference::{AoOptions, Falloff, ReferenceImage};
use aokit_scene::external::ExternalAo;
use aokit_scene::{CameraPath, Renderer, Scene};
use clap::Args;
use glam::{Vec2, Vec3};
use serde_json::json;

use crate::cache;
use crate::camera_args::CameraArgs;
use crate::export::{check_out_dir, create_dir};
use crate::passes::{self, DepthKind, PassFiles};
use crate::peer::{self, PeerSettings, PeerSpec, XeGtao};
use crate::recorded;
use crate::reference::ReferenceInfo;
use crate::render::{open_gpu, open_gpu_with, parse_size};
use crate::sequence::{SequenceFrame, score_sequence};
use crate::settings_args::{OverrideArgs, SettingsArgs};
use crate::view_sets::ViewSet;

#[derive(Args, Debug)]
pub struct CompareArgs {
    /// Built-in scene or scene file (one view with --camera; see --view for several).
    #[arg(long, conflicts_with_all = ["view", "inputs"])]
    pub scene: Option<String>,
    #[command(flatten)]
    pub camera: CameraArgs,
    /// A view as SCENE or SCENE@CAMERA; repeat for several views in one report.
    #[arg(long, value_name = "SCENE[@CAMERA]", conflicts_with = "inputs")]
    pub view: Vec<String>,
    /// A named set of views instead of --view: `tuning` (the views `aokit tune` fits the
    /// presets on) or `held-out` (views of scenes it never reads, made by `bash
    /// scripts/fetch-scenes.sh`); paths are from the repository root (docs/quality.md).
    #[arg(long, value_name = "SET", conflicts_with_all = ["view", "scene", "inputs"])]
    pub views: Option<ViewSet>,
    /// Score `aokit ao` on the passes in DIR (depth.exr, optional normal.exr and back_depth.exr, camera.json)
    /// against DIR/reference.exr, with the radius from DIR/reference.json unless --radius is given,
    /// and the settings recorded in DIR/ao-settings.json (as `render --gbuffer` writes it), under
    /// --method, --preset, --settings and --set, when there is one.
    #[arg(long, value_name = "DIR")]
    pub inputs: Option<PathBuf>,
    /// Image size (scene views).
    #[arg(long, value_name = "WxH", default_value = "480x270", value_parser = parse_size, allow_hyphen_values = true)]
    pub size: [u32; 2],
    /// Methods to score, comma-separated, or `all` (`--methods` before) [default: all, or
    /// with --inputs the method recorded in DIR/ao-settings.json].
    #[arg(
        long = "method",
        alias = "methods",
        value_name = "METHOD,...",
        value_delimiter = ','
    )]
    pub methods: Vec<String>,
    /// Presets to score, comma-separated (`--presets` before) [default: low,medium,high,ultra,
    /// or with --inputs the preset recorded in DIR/ao-settings.json].
    #[arg(
        long = "preset",
        alias = "presets",
        value_name = "PRESET,...",
        value_delimiter = ','
    )]
    pub presets: Vec<Preset>,
    /// AO radius (default: the scene's suggested radius, else 1); the reference uses it too.
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f32>,
    /// Laid over every method's preset before scoring (keys of other methods are ignored by
    /// each method); `radius` must come from --radius, which the reference shares.
    #[command(flatten)]
    pub overrides: OverrideArgs,
    /// Reference rays per pixel.
    #[arg(long, default_value_t = 512, value_parser = crate::reference::parse_spp, allow_negative_numbers = true)]
    pub spp: u32,
    /// Where references are cached (default: $AOKIT_CACHE, $XDG_CACHE_HOME/aokit or ~/.cache/aokit).
    #[arg(long, value_name = "DIR")]
    pub cache: Option<PathBuf>,
    /// Frames timed per method and preset; the median is reported.
    #[arg(long, default_value_t = 5)]
    pub timing_frames: u32,
    /// Score a sequence of this many frames along --path, each against its own reference (the
    /// temporal filter, when on, accumulates over them): adds the mean RMSE over the frames,
    /// the flicker (mean change between frames; all noise with --path still) and the error in
    /// what each frame newly reveals. Images and the other columns are of the last frame.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=1000), allow_negative_numbers = true)]
    pub frames: u32,
    /// How the camera moves over --frames: still, orbit, dolly or strafe (as `aokit render`).
    #[arg(long, value_name = "PATH", default_value = "still")]
    pub path: CameraPath,
    /// Also score a peer, NAME=DIR, at each of --preset: `xegtao=` a checkout of XeGTAO, or a
    /// folder `aokit peer compile` wrote (docs/peers.md); its denoiser (one pass) is on
    /// as aokit's is, --set spatial.enabled=false turns it off, --set peer.denoise_passes=N
    /// sets its passes.
    #[arg(long, value_name = "NAME=DIR")]
    pub peer: Option<PeerSpec>,
    /// Pixels of overscan on each side (a guard band) for aokit's methods on scene views: the
    /// G-buffer is drawn this much larger, as `aokit render --guard-band`, and the AO of the
    /// camera's frame is scored against its reference (docs/quality.md#guard-band). The passes
    /// of --inputs carry their band in camera.json.
    #[arg(long, value_name = "PX", default_value_t = 0, conflicts_with_all = ["inputs", "peer"])]
    pub guard_band: u32,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "aokit-compare")]
    pub out: PathBuf,
}

/// The presets scored when `--preset` is not given (and no recorded settings stand in).
const DEFAULT_PRESETS: [Preset; 4] = [Preset::Low, Preset::Medium, Preset::High, Preset::Ultra];

impl CompareArgs {
    /// `--method`, else every method.
    fn method_names(&self) -> Vec<String> {
        match self.methods.is_empty() {
            true => vec!["all".to_string()],
            false => self.methods.clone(),
        }
    }

    /// `--preset`, else [`DEFAULT_PRESETS`].
    fn presets(&self) -> &[Preset] {
        match self.presets.is_empty() {
            true => &DEFAULT_PRESETS,
            false => &self.presets,
        }
    }

    /// `--settings` and `--set` without the `peer.*` keys, which are the peer's alone.
    fn aokit_overrides(&self) -> OverrideArgs {
        OverrideArgs {
            settings: self.overrides.settings.clone(),
            set: (self.overrides.set.iter())
                .filter(|s| !PeerSettings::is_peer_key(s))
                .cloned()
                .collect(),
        }
    }
}

/// The error maps' colour scale: errors beyond a quarter of the AO range read as saturated.
pub const ERROR_RANGE: f32 = 0.25;
/// Depth edges: a neighbour 5% nearer or farther, or a surface next to the sky...
const EDGE_RELATIVE_DEPTH: f32 = 0.05;
/// ...and pixels within 2 of one, where halos and missing contact shadows show.
const EDGE_RADIUS: u32 = 2;
/// Grazing surfaces: |n . v| below this, within about 17 degrees of edge-on.
const GRAZING_COS: f32 = 0.3;

/// What every view brings to scoring: the reference and a way to run a method on the same pixels.
struct Scored {
    name: String,
    reference: ReferenceImage,
    results: Vec<MethodResult>,
}

/// The methods named on the command line, `all` standing for every one.
pub fn methods(names: &[String]) -> Result<Vec<Method>> {
    let mut methods = Vec::new();
    for name in names {
        let named: Vec<Method> = if name == "all" {
            Method::ALL.to_vec()
        } else {
            vec![name.parse().map_err(|e: String| anyhow!(e))?]
        };
        for method in named {
            if !methods.contains(&method) {
                methods.push(method);
            }
        }
    }
    Ok(methods)
}

fn settings_for(
    args: &CompareArgs,
    method: Method,
    preset: Preset,
    radius: f32,
) -> Result<AoSettings> {
    let settings = args
        .aokit_overrides()
        .apply_to_preset(method, preset, Some(radius), None)?;
    if settings.radius != radius {
        bail!("set the radius with --radius, so that the reference is traced with it too");
    }
    Ok(settings)
}

fn median(mut values: Vec<f64>) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    values.sort_by(f64::total_cmp);
    Some(values[values.len() / 2])
}

/// Scores one method's AO against the reference and renders its images.
/// Surfaces seen within about 17 degrees of edge-on (|n . v| < 0.3), where methods that march in
/// screen space miss most of the hemisphere. Needs the reference's normals; without them
/// (passes without normal.exr) nothing is selected.
fn grazing(reference: &ReferenceImage, projection: &Projection) -> Vec<bool> {
    let size = Vec2::new(reference.size[0] as f32, reference.size[1] as f32);
    let to_eye: Vec<[f32; 3]> = reference
        .linear_depth
        .iter()
        .enumerate()
        .map(|(i, &depth)| {
            let pixel = Vec2::new(
                (i % reference.size[0] as usize) as f32,
                (i / reference.size[0] as usize) as f32,
            );
            let p = projection.view_position_from_linear(pixel_to_ndc(pixel, size), depth);
            let v = if projection.is_orthographic() {
                Vec3::Z
            } else {
                -p
            };
            v.normalize_or_zero().to_array()
        })
        .collect();
    let normals: Vec<[f32; 3]> = reference.normals.iter().map(|n| n.to_array()).collect();
    grazing_mask(&normals, &to_eye, GRAZING_COS)
}

/// Which method is scored: its name, and its cost in samples per pixel.
struct Scoring<'a> {
    method: &'a str,
    samples_per_pixel: u32,
}

impl<'a> Scoring<'a> {
    fn of(settings: &'a AoSettings) -> Self {
        Self {
            method: settings.method.name(),
            samples_per_pixel: settings.samples_per_pixel(),
        }
    }
}

fn score_method(
    reference: &ReferenceImage,
    grazing: &[bool],
    ao: &[f32],
    scoring: Scoring<'_>,
    preset: Preset,
    gpu_ms: Option<f64>,
) -> Result<MethodResult> {
    let edges = depth_edge_mask(
        reference.size,
        &reference.linear_depth,
        EDGE_RELATIVE_DEPTH,
        EDGE_RADIUS,
    );
    if ao.iter().any(|v| !v.is_finite()) {
        bail!("{} wrote non-finite AO values", scoring.method);
    }
    Ok(MethodResult {
        method: scoring.method.to_string(),
        preset: preset.name().to_string(),
        all: surface_error(reference, ao),
        edges: score(reference.size, ao, &reference.ao, &edges),
        grazing: score(reference.size, ao, &reference.ao, grazing),
        sequence: None,
        gpu_ms,
        samples_per_pixel: scoring.samples_per_pixel,
        ao_png: encode_png_grey(reference.size, ao)?,
        error_png: encode_png_rgb(reference.size, &error_map(reference, ao))?,
    })
}

/// `ao`'s error against `reference` over every surface pixel: the report's `all` column (and
/// the RMSE `aokit view` shows).
pub fn surface_error(reference: &ReferenceImage, ao: &[f32]) -> Metrics {
    let surface = surface_mask(&reference.linear_depth);
    score(reference.size, ao, &reference.ao, &surface)
}

/// The signed error map of `ao` against `reference` as RGB (blue too dark, red too bright,
/// saturated at [`ERROR_RANGE`]; the sky grey), as the report draws it.
pub fn error_map(reference: &ReferenceImage, ao: &[f32]) -> Vec<u8> {
    let surface = surface_mask(&reference.linear_depth);
    error_map_rgb(ao, &reference.ao, &surface, ERROR_RANGE)
}

/// Sums each frame's pass times; `None` without timestamps.
fn frame_ms(times: Option<Result<Vec<aokit::PassTime>, aokit::GpuError>>) -> Result<Option<f64>> {
    times
        .transpose()
        .map(|t| t.map(|passes| passes.iter().map(|p| p.ms).sum()))
        .map_err(|e| anyhow!(e))
}

fn score_scene_view(
    gpu: &GpuContext,
    args: &CompareArgs,
    methods: &[Method],
    cache_dir: &Path,
    scene: &Scene,
    camera: &aokit_scene::Camera,
) -> Result<Scored> {
    let radius = args.radius.or(scene.suggested_radius).unwrap_or(1.0);
    let options = AoOptions {
        radius,
        spp: args.spp,
        seed: 0,
        falloff: Falloff::None,
    };
    let aspect = args.size[0] as f32 / args.size[1] as f32;
    // The cameras of the frames, and each one's reference (a still path traces one).
    let cameras: Vec<aokit_scene::Camera> = (0..args.frames)
        .map(|i| {
            let t = if args.frames > 1 {
                i as f32 / (args.frames - 1) as f32
            } else {
                0.0
            };
            args.path.at(camera, t)
        })
        .collect();
    let mut references: Vec<ReferenceImage> = Vec::new();
    for (i, c) in cameras.iter().enumerate() {
        let same = i > 0 && cameras[i - 1] == *c;
        let reference = if same {
            references[i - 1].clone()
        } else {
            cache::reference(cache_dir, scene, c, args.size, &options)?
        };
        references.push(reference);
    }
    let last = cameras.len() - 1;
    let sequence_frames: Vec<SequenceFrame<'_>> = cameras
        .iter()
        .zip(&references)
        .map(|(c, reference)| SequenceFrame {
            view_from_world: c.view_from_world(),
            projection: c.projection(aspect, &scene.bounds),
            reference,
        })
        .collect();
    let grazing = grazing(&references[last], &sequence_frames[last].projection);
    let first = settings_for(args, methods[0], args.presets()[0], radius)?;
    let mut renderer = Renderer::new(gpu, scene, &first)?;
    renderer.guard_band = args.guard_band;
    let timed = renderer.enable_timing(gpu);
    let mut results = Vec::new();
    // Scoring every method at every preset takes as long as the trace on lavapipe: a bar, as
    // the trace has, so that the run does not fall silent.
    let bar = crate::reference::progress_bar(
        (methods.len() * args.presets().len()) as u64,
        "scoring",
        "",
    );
    for &method in methods {
        for &preset in args.presets() {
            bar.set_message(format!("{} {}", method.name(), preset.name()));
            let settings = settings_for(args, method, preset, radius)?;
            renderer.set_settings(gpu, &settings)?;
            // Each method and preset starts its own sequence: no history from the last one.
            renderer.reset_history();
            let mut frames = Vec::new();
            for (i, c) in cameras.iter().enumerate() {
                frames.push(renderer.render(gpu, c, args.size, i as u32)?.ao);
            }
            let mut times = Vec::new();
            for _ in 0..if timed { args.timing_frames } else { 0 } {
                renderer.render(gpu, &cameras[last], args.size, args.frames)?;
                times.extend(frame_ms(renderer.last_ao_times(gpu))?);
            }
            let mut result = score_method(
                &references[last],
                &grazing,
                &frames[last],
                Scoring::of(&settings),
                preset,
                median(times),
            )?;
            if args.frames > 1 {
                result.sequence = Some(score_sequence(&sequence_frames, &frames));
            }
            results.push(result);
            bar.inc(1);
        }
    }
    bar.finish_and_clear();
    if let Some(spec) = &args.peer {
        let view = PeerView {
            camera: &cameras[last],
            reference: &references[last],
            grazing: &grazing,
            radius,
        };
        results.extend(score_peer(gpu, args, spec, &mut renderer, &view)?);
    }
    let name = format!("{} / {}", scene.name, camera.name);
    Ok(Scored {
        name: if args.frames > 1 {
            format!("{name} ({} frames, {})", args.frames, args.path.name())
        } else {
            name
        },
        reference: references.swap_remove(last),
        results,
    })
}

/// What the peer is scored on: one camera's G-buffer and reference.
struct PeerView<'a> {
    camera: &'a aokit_scene::Camera,
    reference: &'a ReferenceImage,
    grazing: &'a [bool],
    radius: f32,
}

/// Scores the peer at each preset, on the G-buffer aokit's methods read, as they are scored.
fn score_peer(
    gpu: &GpuContext,
    args: &CompareArgs,
    spec: &PeerSpec,
    renderer: &mut Renderer,
    view: &PeerView<'_>,
) -> Result<Vec<MethodResult>> {
    if args.frames > 1 {
        bail!(
            "--peer scores one frame: XeGTAO runs without temporal accumulation here; drop \
             --frames"
        );
    }
    let (gbuffer, projection) =
        renderer.render_gbuffer(gpu, view.camera, args.size, NormalEncoding::Oct32)?;
    let settings_at = |preset| {
        let settings = PeerSettings::from_flags(preset, view.radius, &args.overrides.set, false)?;
        if settings.radius != view.radius {
            bail!("set the radius with --radius, so that the reference is traced with it too");
        }
        Ok(settings)
    };
    let paths = peer::shader_paths(&gpu.device, settings_at(args.presets()[0])?.shader);
    let mut results = Vec::new();
    for &preset in args.presets() {
        let settings = settings_at(preset)?;
        let shaders = peer::Shaders::load(spec, settings.quality)?;
        for &shader in &paths {
            let mut passes = XeGtao::new(&gpu.device, &shaders, shader, &settings, args.size)?;
            let timed = passes.enable_timing(&gpu.device, &gpu.queue);
            let frame = |passes: &mut XeGtao| -> Result<()> {
                let mut encoder = gpu.device.create_command_encoder(&Default::default());
                let (depth, normals) = (&gbuffer.depth, &gbuffer.normals);
                passes.encode(
                    &gpu.device,
                    &gpu.queue,
                    &mut encoder,
                    depth,
                    normals,
                    &projection,
                )?;
                gpu.queue.submit([encoder.finish()]);
                Ok(())
            };
            frame(&mut passes)?;
            let ao = passes.read_visibility(&gpu.device, &gpu.queue)?;
            let mut times = Vec::new();
            for _ in 0..if timed { args.timing_frames } else { 0 } {
                frame(&mut passes)?;
                times.extend(frame_ms(passes.last_pass_times(&gpu.device))?);
            }
            let name = peer::method_name(spec, shader);
            let scoring = Scoring {
                method: &name,
                samples_per_pixel: settings.samples_per_pixel(),
            };
            results.push(score_method(
                view.reference,
                view.grazing,
                &ao,
                scoring,
                preset,
                median(times),
            )?);
        }
    }
    Ok(results)
}

/// The preset and settings of each run on `--inputs` passes: every method at every preset, or
/// with settings recorded beside `camera` those (`aokit ao`'s rules: `--method` and `--preset`
/// pick others, the flags go over them), all at the reference's `radius`.
fn inputs_settings(
    args: &CompareArgs,
    methods: &[Method],
    camera: &Path,
    radius: f32,
) -> Result<Vec<(Preset, AoSettings)>> {
    let Some(recorded) = recorded::read_beside(camera)? else {
        let mut runs = Vec::new();
        for &method in methods {
            for &preset in args.presets() {
                runs.push((preset, settings_for(args, method, preset, radius)?));
            }
        }
        return Ok(runs);
    };
    // Each flag given picks its own list; one not given keeps the recorded value.
    let method_names: Vec<Option<String>> = match args.methods.is_empty() {
        true => vec![None],
        false => methods.iter().map(|m| Some(m.name().to_string())).collect(),
    };
    let presets: Vec<Option<Preset>> = match args.presets.is_empty() {
        true => vec![None],
        false => args.presets.iter().copied().map(Some).collect(),
    };
    let mut runs = Vec::new();
    for method in &method_names {
        for preset in &presets {
            let flags = SettingsArgs {
                method: method.clone(),
                preset: preset.map(|p| p.name().to_string()),
                radius: args.radius,
                overrides: args.aokit_overrides(),
            };
            let settings = flags.resolve_recorded(&recorded)?;
            if settings.radius != radius {
                bail!(
                    "{} records radius {} but the reference was traced with radius {radius} \
                     (reference.json): trace it again with `aokit reference --radius {}`, or \
                     give --radius to score both at one",
                    recorded.path.display(),
                    settings.radius,
                    settings.radius
                );
            }
            runs.push((preset.unwrap_or(recorded.preset), settings));
        }
    }
    let (preset, settings) = &runs[0];
    eprintln!(
        "note: settings recorded in {} ({} at {}, radius {}); --method, --preset, --settings, \
         --set and --radius go over them",
        recorded.path.display(),
        settings.method.name(),
        preset.name(),
        settings.radius
    );
    Ok(runs)
}

fn score_inputs(
    gpu: &GpuContext,
    args: &CompareArgs,
    methods: &[Method],
    dir: &Path,
) -> Result<Scored> {
    let (normals, back_depth) = (dir.join("normal.exr"), dir.join("back_depth.exr"));
    let camera = dir.join("camera.json");
    let loaded = passes::load(
        &PassFiles {
            depth: &dir.join("depth.exr"),
            normals: normals.is_file().then_some(normals.as_path()),
            back_depth: back_depth.is_file().then_some(back_depth.as_path()),
            camera: &camera,
        },
        DepthKind::Linear,
        NormalSpace::View,
        None,
    )?;
    let reference_path = dir.join("reference.exr");
    let reference_ao = read_scalar_exr(&reference_path)?;
    // One NaN makes every metric NaN, which the report prints as "n/a": refuse it here.
    let non_finite = reference_ao.data.iter().filter(|v| !v.is_finite()).count();
    if non_finite > 0 {
        bail!(
            "{}: {non_finite} of {} pixels are not finite (NaN or infinity); the reference AO \
             must be a number in [0, 1] at every pixel",
            reference_path.display(),
            reference_ao.data.len()
        );
    }
    // With a guard band the passes are larger than the frame the reference was traced for.
    let size = loaded.output_size();
    if [reference_ao.width, reference_ao.height] != size {
        bail!(
            "{}: reference.exr is {}x{}, but the frame of depth.exr is {}x{}{}",
            dir.display(),
            reference_ao.width,
            reference_ao.height,
            size[0],
            size[1],
            if loaded.guard_band > 0 {
                format!(" (its {} px guard band cut off)", loaded.guard_band)
            } else {
                String::new()
            }
        );
    }
    let info = ReferenceInfo::read(dir);
    if let Ok(ReferenceInfo {
        size: Some(traced), ..
    }) = &info
        && *traced != size
    {
        bail!(
            "{}: reference.json says the reference was traced at {}x{}, but the passes' frame is \
             {}x{}",
            dir.display(),
            traced[0],
            traced[1],
            size[0],
            size[1]
        );
    }
    let radius = match args.radius {
        Some(r) => r,
        None => {
            info.context("give --radius, or keep the reference.json `aokit reference` writes")?
                .radius
        }
    };
    let reference = ReferenceImage {
        size,
        ao: reference_ao.data,
        linear_depth: loaded
            .output_depth()
            .iter()
            .map(|&d| if d.is_finite() && d > 0.0 { d } else { 0.0 })
            .collect(),
        normals: loaded
            .normals
            .as_deref()
            .map(|n| loaded.crop_to_output(n))
            .unwrap_or_default(),
    };
    let grazing = grazing(&reference, &loaded.projection);
    if args.peer.is_some() {
        bail!(
            "--peer needs a scene view: XeGTAO reads the hardware depth buffer, which --inputs \
             does not hold"
        );
    }
    if args.frames > 1 {
        bail!("--frames needs a scene to move through; --inputs holds one frame");
    }
    let runs = inputs_settings(args, methods, &camera, radius)?;
    let mut external = ExternalAo::new(gpu, &runs[0].1, &loaded.passes())?;
    external.set_guard_band(loaded.guard_band);
    let timed = external.enable_timing(gpu);
    let mut results = Vec::new();
    for (preset, settings) in runs {
        external.set_settings(gpu, &settings)?;
        let ao = external.run(gpu, 0)?;
        let mut times = Vec::new();
        for _ in 0..if timed { args.timing_frames } else { 0 } {
            external.run(gpu, 0)?;
            times.extend(frame_ms(external.last_times(gpu))?);
        }
        results.push(score_method(
            &reference,
            &grazing,
            &ao,
            Scoring::of(&settings),
            preset,
            median(times),
        )?);
    }
    Ok(Scored {
        name: dir.display().to_string(),
        reference,
        results,
    })
}

fn metrics_json(m: &Metrics) -> serde_json::Value {
    // JSON has no infinity: a perfect match's PSNR is written as null.
    let finite = |v: f64| {
        if v.is_finite() {
            json!(v)
        } else {
            serde_json::Value::Null
        }
    };
    json!({
        "pixels": m.pixels,
        "mae": finite(m.mae),
        "rmse": finite(m.rmse),
        "bias": finite(m.bias),
        "psnr": finite(m.psnr),
        "ssim": finite(m.ssim),
    })
}

/// A view name as a file name: `sponza / atrium` -> `sponza-atrium`.
fn slug(name: &str) -> String {
    name.split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|part| !part.is_empty())
        .collect::<Vec<_>>()
        .join("-")
        .to_ascii_lowercase()
}

/// The report's images as files, for docs and other tools: `VIEW-reference.png`,
/// `VIEW-METHOD-PRESET.png` and `VIEW-METHOD-PRESET-error.png`.
fn write_images(dir: &Path, views: &[ViewResult]) -> Result<()> {
    create_dir(dir)?;
    let write = |name: String, png: &[u8]| -> Result<()> {
        let path = dir.join(name);
        std::fs::write(&path, png).with_context(|| format!("cannot write {}", path.display()))
    };
    for view in views {
        let view_name = slug(&view.name);
        write(format!("{view_name}-reference.png"), &view.reference_png)?;
        for m in &view.methods {
            let stem = format!("{view_name}-{}-{}", m.method, m.preset);
            write(format!("{stem}.png"), &m.ao_png)?;
            write(format!("{stem}-error.png"), &m.error_png)?;
        }
    }
    Ok(())
}

/// The scene and camera of a view named SCENE or SCENE@CAMERA.
pub fn open_view(view: &str) -> Result<(Scene, aokit_scene::Camera)> {
    let (spec, camera_name) = match view.rsplit_once('@') {
        Some((spec, camera)) => (spec, Some(camera)),
        None => (view, None),
    };
    let scene = Scene::open(spec)?;
    let camera = scene.camera(camera_name)?;
    Ok((scene, camera))
}

pub fn run(args: &CompareArgs) -> Result<()> {
    check_out_dir(&args.out)?;
    let methods = methods(&args.method_names())?;
    if args.timing_frames > 1000 {
        bail!("--timing-frames {} is more than 1000", args.timing_frames);
    }
    // As every method will run it (`peer.*` keys left to the peer).
    let temporal = settings_for(args, methods[0], args.presets()[0], 1.0)?
        .temporal
        .enabled;
    for note in crate::sequence::single_frame_notes(args.frames, args.path, temporal) {
        eprintln!("note: {note}");
    }
    let cache_dir = args.cache.clone().unwrap_or_else(cache::default_dir);
    let gpu = if args.peer.is_some() {
        open_gpu_with(peer::FEATURES)?
    } else {
        open_gpu()?
    };
    let mut scored = Vec::new();
    if let Some(dir) = &args.inputs {
        scored.push(score_inputs(&gpu, args, &methods, dir)?);
    } else if args.view.is_empty() && args.views.is_none() {
        let scene = Scene::open(args.scene.as_deref().unwrap_or("room"))?;
        let camera = args.camera.resolve(&scene)?;
        scored.push(score_scene_view(
            &gpu, args, &methods, &cache_dir, &scene, &camera,
        )?);
    } else {
        let views = match args.views {
            Some(set) => set.present_views()?,
            None => args.view.clone(),
        };
        for view in &views {
            let (scene, camera) = open_view(view)?;
            scored.push(score_scene_view(
                &gpu, args, &methods, &cache_dir, &scene, &camera,
            )?);
        }
    }

    let out = &args.out;
    create_dir(out)?;
    let mut views = Vec::new();
    let mut rows = Vec::new();
    for view in scored {
        for m in &view.results {
            rows.push(json!({
                "view": view.name,
                "method": m.method,
                "preset": m.preset,
                "samples_per_pixel": m.samples_per_pixel,
                "gpu_ms": m.gpu_ms,
                "all": metrics_json(&m.all),
                "edges": metrics_json(&m.edges),
                "grazing": metrics_json(&m.grazing),
                "sequence": m.sequence.as_ref().map(|s| json!({
                    "frames": s.frames,
                    "mean_rmse": s.mean_rmse,
                    "flicker": s.flicker,
                    "disoccluded": metrics_json(&s.disoccluded),
                })),
            }));
        }
        views.push(ViewResult {
            reference_png: encode_png_grey(view.reference.size, &view.reference.ao)?,
            name: view.name,
            methods: view.results,
        });
    }
    write_images(&out.join("images"), &views)?;
    let size = views.first().map(|_| args.size);
    let report = Report {
        title: "aokit: AO methods against the ray-traced reference".to_string(),
        notes: vec![
            format!("Adapter: {}.", gpu.describe()),
            match (&args.inputs, size) {
                (Some(dir), _) => match ReferenceInfo::read(dir) {
                    Ok(info) => format!(
                        "Passes from {}; reference: {}.",
                        dir.display(),
                        info.describe()
                    ),
                    Err(_) => format!("Passes from {}.", dir.display()),
                },
                (None, Some(size)) => format!(
                    "{}x{} pixels; reference with {} cosine-weighted rays per pixel, no falloff.",
                    size[0], size[1], args.spp
                ),
                (None, None) => String::new(),
            },
            format!(
                "Command: aokit {}",
                std::env::args().skip(1).collect::<Vec<_>>().join(" ")
            ),
        ],
        error_range: ERROR_RANGE,
        legend_png: encode_png_rgb([256, 12], &legend_rgb(256, 12))?,
        views,
    };
    let write = |name: &str, text: String| -> Result<()> {
        let path = out.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))
    };
    write("metrics.csv", report.csv())?;
    write("metrics.md", report.markdown())?;
    write("metrics-by-method.md", report.markdown_by_method())?;
    write(
        "metrics.json",
        serde_json::to_string_pretty(&json!({ "adapter": gpu.describe(), "results": rows }))?
            + "\n",
    )?;
    write("report.html", report.html())?;
    out!("{}", report.markdown());
    outln!(
        "wrote metrics.csv, metrics.md, metrics-by-method.md, metrics.json, report.html and images/ to {}",
        out.display()
    );
    Ok(())
}
