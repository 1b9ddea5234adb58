//! `aokit bench`: times the AO pipeline alone on one rasterised G-buffer, per pass on the GPU
//! (timestamp queries), and its CPU encode; `--compare` times several configurations
//! interleaved frame by frame.

use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::ffi::OsString;
use std::time::Instant;

use anyhow::{Result, anyhow, bail};
use aokit::{AdapterKind, AoInputs, AoPipeline, AoSettings, GpuContext, PassTime, Projection};
use aokit_scene::gbuffer::GBuffer;
use aokit_scene::{Renderer, Scene};
use clap::{Args, Parser};
use glam::Mat4;
use serde_json::{Value, json};

use crate::camera_args::CameraArgs;
use crate::peer::{self, PeerSettings, PeerSpec, ShaderPath, XeGtao};
use crate::render::{open_gpu, open_gpu_with, parse_size};
use crate::settings_args::SettingsArgs;

#[derive(Args, Debug, Clone)]
pub struct BenchArgs {
    /// Built-in scene (room, stairs, thin, open) or a .gltf/.glb/.obj file.
    #[arg(long, default_value = "room")]
    pub scene: String,
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Image size.
    #[arg(long, value_name = "WxH", default_value = "1920x1080", value_parser = parse_size, allow_hyphen_values = true)]
    pub size: [u32; 2],
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Pixels of overscan on each side (a guard band): the G-buffer is drawn this much larger
    /// and the AO computed for the inner --size, as `aokit render --guard-band`; with
    /// --compare, for timing a band against none.
    #[arg(long, value_name = "PX", default_value_t = 0)]
    pub guard_band: u32,
    /// Run a peer instead of an aokit method, NAME=DIR: `xegtao=` a checkout of XeGTAO, or a
    /// folder `aokit peer compile` wrote (docs/peers.md). --preset picks its quality level,
    /// --set spatial.enabled=false turns its denoiser off.
    #[arg(long, value_name = "NAME=DIR", conflicts_with = "method")]
    pub peer: Option<PeerSpec>,
    /// Timed frames; the statistics are over these (`--frames` before; `compare` names its
    /// own the same).
    #[arg(long = "timing-frames", alias = "frames", value_name = "N", default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=MAX_FRAMES), allow_negative_numbers = true)]
    pub frames: u32,
    /// Untimed frames before the timed ones (shader compilation, caches, temporal history).
    #[arg(long, value_name = "N", default_value_t = 10, value_parser = clap::value_parser!(u32).range(0..=MAX_FRAMES), allow_negative_numbers = true)]
    pub warmup: u32,
    /// Print one JSON object (with --compare, an array of them) on stdout instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Time several configurations against each other, interleaved: each ARGS is a set of
    /// bench options (e.g. "--method hbao --set resolution=half") laid over the options given
    /// before --compare. Takes every argument after it, so it comes last.
    #[arg(long, value_name = "ARGS", num_args = 1.., allow_hyphen_values = true)]
    pub compare: Vec<String>,
}

/// Most frames `--frames` and `--warmup` take: a limit against typing mistakes, minutes of
/// work even for a fast GPU at 4K.
const MAX_FRAMES: i64 = 100_000;

/// One `--compare` configuration, parsed by the same flags as `aokit bench`; an option given
/// again replaces the shared one, `--set` adds to the shared ones.
#[derive(Parser, Debug)]
#[command(name = "aokit bench --compare", args_override_self = true)]
struct Configuration {
    #[command(flatten)]
    args: BenchArgs,
}

/// Splits `text` into words as a shell would: at whitespace, with "double" and 'single' quotes
/// grouping and a backslash escaping the next character (not inside single quotes).
pub fn split_words(text: &str) -> Result<Vec<String>, String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut in_word = false;
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' | '\'' => {
                in_word = true;
                loop {
                    match chars.next() {
                        Some(q) if q == c => break,
                        Some('\\') if c == '"' => match chars.next() {
                            Some(escaped) => word.push(escaped),
                            None => return Err(format!("`{text}` ends inside a {c} quote")),
                        },
                        Some(other) => word.push(other),
                        None => return Err(format!("`{text}` ends inside a {c} quote")),
                    }
                }
            }
            '\\' => {
                in_word = true;
                word.push(
                    chars
                        .next()
                        .ok_or_else(|| format!("`{text}` ends with a backslash"))?,
                );
            }
            c if c.is_whitespace() => {
                if in_word {
                    words.push(std::mem::take(&mut word));
                    in_word = false;
                }
            }
            c => {
                in_word = true;
                word.push(c);
            }
        }
    }
    if in_word {
        words.push(word);
    }
    Ok(words)
}

/// The options of an `aokit bench` command line (`argv` as the process got it) before
/// `--compare`: the ones every configuration shares.
fn shared_words(argv: &[OsString]) -> Vec<OsString> {
    argv.iter()
        .skip(1)
        .skip_while(|word| *word != "bench")
        .skip(1)
        .take_while(|word| {
            let word = word.to_string_lossy();
            word != "--compare" && !word.starts_with("--compare=")
        })
        .cloned()
        .collect()
}

/// The configurations to time, each with its label: this command line's, or each `--compare`
/// entry laid over the options before `--compare`.
fn configurations(args: &BenchArgs) -> Result<Vec<(String, BenchArgs)>> {
    if args.compare.is_empty() {
        return Ok(vec![(String::new(), args.clone())]);
    }
    let shared = shared_words(&std::env::args_os().collect::<Vec<_>>());
    let mut configurations = Vec::new();
    for (i, entry) in args.compare.iter().enumerate() {
        let name = format!("--compare configuration {} (`{entry}`)", i + 1);
        let words = split_words(entry).map_err(|e| anyhow!("{name}: {e}"))?;
        let argv = std::iter::once(OsString::from("bench"))
            .chain(shared.iter().cloned())
            .chain(words.into_iter().map(OsString::from));
        let parsed = Configuration::try_parse_from(argv).map_err(|e| {
            // clap's first paragraph names the problem; its usage lines are of no help here.
            let message = e.to_string();
            let message = message.split("\n\n").next().unwrap_or_default();
            anyhow!(
                "{name}: {}",
                message.trim_start_matches("error: ").trim_end()
            )
        })?;
        let config = parsed.args;
        if !config.compare.is_empty() {
            bail!("{name}: a configuration cannot hold --compare");
        }
        if config.json != args.json || config.frames != args.frames || config.warmup != args.warmup
        {
            bail!(
                "{name}: --json, --frames and --warmup apply to the whole run (its frames \
                 interleave); give them before --compare"
            );
        }
        configurations.push((entry.trim().to_string(), config));
    }
    Ok(configurations)
}

/// Median and the 10th and 90th percentiles of a set of times, in milliseconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    pub median: f64,
    pub p10: f64,
    pub p90: f64,
}

impl Stats {
    /// The statistics of `values`, interpolating linearly between the nearest ranks (as
    /// numpy's default); `None` when empty.
    pub fn of(values: &[f64]) -> Option<Stats> {
        if values.is_empty() {
            return None;
        }
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        let at = |p: f64| {
            let rank = p * (sorted.len() - 1) as f64;
            let (lo, hi) = (rank.floor() as usize, rank.ceil() as usize);
            sorted[lo] + (sorted[hi] - sorted[lo]) * (rank - lo as f64)
        };
        Some(Stats {
            median: at(0.5),
            p10: at(0.1),
            p90: at(0.9),
        })
    }

    fn json(&self) -> Value {
        json!({ "median": self.median, "p10": self.p10, "p90": self.p90 })
    }
}

/// What `--compare`'s ratios compare.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Basis {
    /// The GPU time of whole frames, from timestamps: on hardware adapters.
    GpuTotal,
    /// The wall time from submit until idle: without timestamps, and on software adapters,
    /// whose timestamps need not bracket the compute work.
    Wall,
}

impl Basis {
    /// The JSON field it is the median of.
    fn field(self) -> &'static str {
        match self {
            Basis::GpuTotal => "total_gpu_ms",
            Basis::Wall => "wall_ms",
        }
    }
}

/// What runs a configuration's frames: aokit's pipeline or a peer's passes. Where the ratios
/// come from the wall time and the frames are timed, `untimed` is the same configuration
/// without timestamps, whose frames give the encode and wall times: writing timestamps costs
/// lavapipe about 0.1 ms a pass (it waits for the pass to finish), which would count against
/// configurations with more passes.
enum Engine {
    // Pipelines and passes boxed: they dwarf the rest and differ in size.
    Aokit {
        settings: AoSettings,
        pipeline: Box<AoPipeline>,
        untimed: Option<Box<AoPipeline>>,
    },
    Peer {
        spec: PeerSpec,
        settings: PeerSettings,
        shader: ShaderPath,
        passes: Box<XeGtao>,
        untimed: Option<Box<XeGtao>>,
    },
}

impl Engine {
    /// The method, or the peer and its way to the GPU.
    fn method_name(&self) -> String {
        match self {
            Engine::Aokit { settings, .. } => settings.method.name().to_string(),
            Engine::Peer { spec, shader, .. } => peer::method_name(spec, *shader),
        }
    }

    fn settings_json(&self) -> Result<Value> {
        Ok(match self {
            // Through text, so that the f32 settings read as written (0.1, not 0.100000001).
            Engine::Aokit { settings, .. } => {
                serde_json::from_str::<Value>(&serde_json::to_string(settings)?)?
            }
            Engine::Peer {
                spec,
                settings,
                shader,
                ..
            } => settings.json(spec, *shader),
        })
    }
}

/// One configuration's engine and what its timed frames measured.
struct Run {
    label: String,
    args: BenchArgs,
    engine: Engine,
    /// Per timed frame: each pass's GPU time (with timestamps).
    pass_times: Vec<Vec<PassTime>>,
    /// Per timed frame: milliseconds in [`AoPipeline::encode`].
    encode_ms: Vec<f64>,
    /// Per timed frame: milliseconds from submit until the device was idle.
    wall_ms: Vec<f64>,
}

/// What a configuration asks for: an aokit method's settings, or a peer's.
enum Wanted {
    Aokit(AoSettings),
    Peer(PeerSpec, PeerSettings),
}

impl Wanted {
    /// `config`'s settings, `suggested_radius` the scene's.
    fn of(config: &BenchArgs, suggested_radius: Option<f32>) -> Result<Self> {
        let s = &config.settings;
        let Some(spec) = &config.peer else {
            return Ok(Wanted::Aokit(s.resolve(suggested_radius)?));
        };
        if s.overrides.settings.is_some() {
            bail!("--settings has no counterpart in a peer: give its settings with --set");
        }
        let preset = match s.preset.as_deref() {
            Some(name) => name.parse().map_err(|e: String| anyhow!(e))?,
            None => aokit::Preset::default(),
        };
        let radius = s
            .radius
            .or(suggested_radius)
            .unwrap_or(AoSettings::default().radius);
        let settings = PeerSettings::from_flags(preset, radius, &s.overrides.set, true)?;
        Ok(Wanted::Peer(spec.clone(), settings))
    }
}

/// The G-buffer the configurations share (one per normal encoding they ask for).
struct View {
    /// By normal encoding and guard band.
    gbuffers: HashMap<(aokit::NormalEncoding, u32), GBuffer>,
    projection: Projection,
    view_from_world: Mat4,
}

impl Run {
    /// Encodes, submits and waits for one frame (one on each pipeline); records its times
    /// when `record`.
    fn frame(
        &mut self,
        gpu: &GpuContext,
        view: &View,
        frame_index: u32,
        record: bool,
    ) -> Result<()> {
        let ((encode_ms, wall_ms), times) = match &mut self.engine {
            Engine::Aokit {
                settings,
                pipeline,
                untimed,
            } => {
                let band = self.args.guard_band;
                let gbuffer = &view.gbuffers[&(settings.normals.encoding, band)];
                let frame = Frame {
                    view,
                    gbuffer,
                    band,
                    index: frame_index,
                };
                let mut measured = submit_frame(pipeline, gpu, &frame)?;
                if let Some(untimed) = untimed {
                    measured = submit_frame(untimed, gpu, &frame)?;
                }
                (measured, pipeline.last_pass_times(&gpu.device))
            }
            Engine::Peer {
                passes, untimed, ..
            } => {
                // XeGTAO reads aokit's default normals, oct32 (the wrapper decodes them).
                let gbuffer = &view.gbuffers[&(aokit::NormalEncoding::Oct32, 0)];
                let mut measured = submit_peer_frame(passes, gpu, view, gbuffer)?;
                if let Some(untimed) = untimed {
                    measured = submit_peer_frame(untimed, gpu, view, gbuffer)?;
                }
                (measured, passes.last_pass_times(&gpu.device))
            }
        };
        if record {
            self.encode_ms.push(encode_ms);
            self.wall_ms.push(wall_ms);
            if let Some(times) = times {
                self.pass_times.push(times?);
            }
        }
        Ok(())
    }

    /// Each pass's statistics, in the order the pipeline runs them; a pass that runs twice in
    /// a frame (under one shader name) is two rows. `None` without timestamps.
    fn pass_stats(&self) -> Option<Vec<(&'static str, Stats)>> {
        if self.pass_times.is_empty() {
            return None;
        }
        let mut rows: Vec<((&'static str, usize), Vec<f64>)> = Vec::new();
        for frame in &self.pass_times {
            let mut seen: HashMap<&'static str, usize> = HashMap::new();
            for pass in frame {
                let occurrence = seen.entry(pass.name).or_default();
                let key = (pass.name, *occurrence);
                *occurrence += 1;
                match rows.iter_mut().find(|(k, _)| *k == key) {
                    Some((_, values)) => values.push(pass.ms),
                    None => rows.push((key, vec![pass.ms])),
                }
            }
        }
        Some(
            rows.into_iter()
                .filter_map(|((name, _), values)| Stats::of(&values).map(|s| (name, s)))
                .collect(),
        )
    }

    /// The GPU time of whole frames: the sum of their passes.
    fn total_gpu(&self) -> Option<Stats> {
        let totals: Vec<f64> = self
            .pass_times
            .iter()
            .map(|frame| frame.iter().map(|p| p.ms).sum())
            .collect();
        Stats::of(&totals)
    }

    /// The median `--compare`'s ratios compare.
    fn median(&self, basis: Basis) -> f64 {
        match basis {
            Basis::GpuTotal => self.total_gpu(),
            Basis::Wall => Stats::of(&self.wall_ms),
        }
        .map_or(f64::NAN, |s| s.median)
    }

    /// The preset's name, with the overrides laid over it.
    fn preset_label(&self) -> String {
        let s = &self.args.settings;
        let mut label = s.preset.clone().unwrap_or_else(|| "high".into());
        let mut extra: Vec<String> = Vec::new();
        if let Some(radius) = s.radius {
            extra.push(format!("--radius {radius}"));
        }
        if let Some(file) = &s.overrides.settings {
            extra.push(format!("--settings {}", file.display()));
        }
        extra.extend(s.overrides.set.iter().map(|kv| format!("--set {kv}")));
        if !extra.is_empty() {
            label = format!("{label} + {}", extra.join(" "));
        }
        label
    }

    fn json(&self, gpu: &GpuContext, scene: &Scene, camera: &str) -> Result<Value> {
        let stats = |s: Option<Stats>| s.map_or(Value::Null, |s| s.json());
        Ok(json!({
            "adapter": gpu.describe(),
            "backend": format!("{:?}", gpu.adapter_info.backend),
            "scene": scene.name,
            "camera": camera,
            "size": self.args.size,
            "frames": self.args.frames,
            "warmup": self.args.warmup,
            "settings": self.engine.settings_json()?,
            "total_gpu_ms": stats(self.total_gpu()),
            "passes": self.pass_stats().map_or(Value::Null, |passes| {
                passes
                    .iter()
                    .map(|(name, s)| json!({ "name": name, "gpu_ms": s.json() }))
                    .collect()
            }),
            "cpu_encode_ms": stats(Stats::of(&self.encode_ms)),
            "wall_ms": stats(Stats::of(&self.wall_ms)),
        }))
    }
}

fn ms(v: f64) -> String {
    format!("{v:.4}")
}

pub fn run(args: &BenchArgs) -> Result<()> {
    let configurations = configurations(args)?;
    let first = &configurations[0].1;
    let scene = Scene::open(&first.scene)?;
    for note in &scene.notes {
        eprintln!("note: {}: {note}", scene.name);
    }
    let camera = first.camera.resolve(&scene)?;
    let size = first.size;
    let same_view = |a: &BenchArgs, b: &BenchArgs| -> Result<bool> {
        Ok(a.scene == b.scene
            && a.size == b.size
            && a.camera.resolve(&scene)? == b.camera.resolve(&scene)?)
    };
    let mut mixed = false;
    for (_, config) in configurations.iter().skip(1) {
        mixed |= !same_view(config, first)?;
    }
    if mixed {
        // Blame a configuration that sets a view of its own: the shared flags (`args`) hold
        // the view of those that set none, so comparing with the first would blame the
        // second when the first set `--size`.
        let mut blamed = 1;
        for (i, (_, config)) in configurations.iter().enumerate() {
            if !same_view(config, args)? {
                blamed = i;
                break;
            }
        }
        let (label, config) = &configurations[blamed];
        bail!(
            "--compare configuration {} (`{label}`) sets another scene, camera or size \
             ({} at {}x{}) than the others: the configurations run on one G-buffer; give \
             --scene, camera options and --size before --compare",
            blamed + 1,
            config.scene,
            config.size[0],
            config.size[1]
        );
    }
    // Errors of a --compare configuration say which.
    let in_configuration = |i: usize, label: &str, error: anyhow::Error| {
        if args.compare.is_empty() {
            error
        } else {
            error.context(format!("--compare configuration {} (`{label}`)", i + 1))
        }
    };
    let mut all_wanted = Vec::new();
    for (i, (label, config)) in configurations.iter().enumerate() {
        all_wanted.push(
            Wanted::of(config, scene.suggested_radius)
                .map_err(|e| in_configuration(i, label, e))?,
        );
    }

    let has_peer = all_wanted.iter().any(|w| matches!(w, Wanted::Peer(..)));
    let gpu = if has_peer {
        open_gpu_with(peer::FEATURES)?
    } else {
        open_gpu()?
    };
    let renderer_settings = all_wanted
        .iter()
        .find_map(|w| match w {
            Wanted::Aokit(settings) => Some(*settings),
            Wanted::Peer(..) => None,
        })
        .unwrap_or_default();
    let mut renderer = Renderer::new(&gpu, &scene, &renderer_settings)?;
    let mut gbuffers = HashMap::new();
    let mut projection = None;
    for (wanted, (_, config)) in all_wanted.iter().zip(&configurations) {
        let band = config.guard_band;
        let encoding = match wanted {
            Wanted::Aokit(settings) => settings.normals.encoding,
            Wanted::Peer(..) if band > 0 => bail!("--guard-band is for aokit's methods, not peers"),
            Wanted::Peer(..) => aokit::NormalEncoding::Oct32,
        };
        if let Entry::Vacant(slot) = gbuffers.entry((encoding, band)) {
            let (gbuffer, p) = renderer
                .render_gbuffer_with_guard_band(&gpu, &camera, first.size, encoding, band)?;
            slot.insert(gbuffer);
            projection = Some(p);
        }
    }
    let view = View {
        gbuffers,
        projection: projection.expect("at least one configuration"),
        view_from_world: camera.view_from_world(),
    };
    drop(renderer);
    // The raster done before any frame is timed, --warmup 0 included.
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| anyhow!("waiting for the GPU failed: {e}"))?;

    let software = gpu.adapter_kind() == AdapterKind::Software;
    let mut runs = Vec::new();
    let mut timed = true;
    let run = |label: String, args: BenchArgs, engine: Engine| Run {
        label,
        args,
        engine,
        pass_times: Vec::new(),
        encode_ms: Vec::new(),
        wall_ms: Vec::new(),
    };
    for (i, ((label, config), wanted)) in configurations.into_iter().zip(all_wanted).enumerate() {
        match wanted {
            Wanted::Aokit(settings) => {
                let mut pipeline = Box::new(AoPipeline::new(&gpu.device, &gpu.queue, &settings)?);
                let has_timestamps = pipeline.enable_timing(&gpu.device, &gpu.queue);
                timed &= has_timestamps;
                let untimed = if software && has_timestamps {
                    Some(Box::new(AoPipeline::new(
                        &gpu.device,
                        &gpu.queue,
                        &settings,
                    )?))
                } else {
                    None
                };
                let engine = Engine::Aokit {
                    settings,
                    pipeline,
                    untimed,
                };
                runs.push(run(label, config, engine));
            }
            Wanted::Peer(spec, settings) => {
                let shaders = peer::Shaders::load(&spec, settings.quality)
                    .map_err(|e| in_configuration(i, &label, e))?;
                let paths = peer::shader_paths(&gpu.device, settings.shader);
                for &shader in &paths {
                    let new = || {
                        XeGtao::new(&gpu.device, &shaders, shader, &settings, size)
                            .map(Box::new)
                            .map_err(|e| in_configuration(i, &label, e))
                    };
                    let mut passes = new()?;
                    let has_timestamps = passes.enable_timing(&gpu.device, &gpu.queue);
                    timed &= has_timestamps;
                    let untimed = if software && has_timestamps {
                        Some(new()?)
                    } else {
                        None
                    };
                    // One configuration, two runs where both ways to the GPU are timed.
                    let label = if paths.len() > 1 {
                        format!("{label} [{}]", shader.name()).trim().to_string()
                    } else {
                        label.clone()
                    };
                    let engine = Engine::Peer {
                        spec: spec.clone(),
                        settings: settings.clone(),
                        shader,
                        passes,
                        untimed,
                    };
                    runs.push(run(label, config.clone(), engine));
                }
            }
        }
    }
    if !timed {
        eprintln!(
            "note: the adapter {} has no TIMESTAMP_QUERY: no GPU times; reporting the CPU \
             encode time and the wall time from submit until the GPU is idle",
            gpu.describe()
        );
    }
    if software {
        eprintln!(
            "note: software adapter: absolute times say nothing about a GPU, and its \
             timestamps need not bracket the compute work (llvmpipe's do not: its GPU times \
             gather in the last pass and fall far below the wall time); compare wall times, \
             as --compare's ratios do here, taken from a second run of each frame without \
             timestamps"
        );
    }
    let basis = if timed && !software {
        Basis::GpuTotal
    } else {
        Basis::Wall
    };
    let (frames, warmup) = (args.frames, args.warmup);
    // Round-robin: one frame of each configuration per round, so that drift in clocks and
    // temperature falls on all alike.
    for round in 0..warmup + frames {
        for run in &mut runs {
            run.frame(&gpu, &view, round, round >= warmup)?;
        }
    }

    let camera_name = camera.name.as_str();
    if args.compare.is_empty() && runs.len() == 1 {
        let run = &runs[0];
        if args.json {
            outln!(
                "{}",
                serde_json::to_string_pretty(&run.json(&gpu, &scene, camera_name)?)?
            );
        } else {
            print_one(&gpu, &scene, camera_name, run);
        }
    } else {
        if args.json {
            let mut array = Vec::new();
            for run in &runs {
                let mut object = run.json(&gpu, &scene, camera_name)?;
                object["configuration"] = json!(run.label);
                object["ratio_to_first"] = json!(run.median(basis) / runs[0].median(basis));
                object["ratio_of"] = json!(basis.field());
                array.push(object);
            }
            outln!("{}", serde_json::to_string_pretty(&Value::Array(array))?);
        } else {
            print_compare(&gpu, &scene, camera_name, &runs, basis);
        }
    }
    Ok(())
}

/// Encodes, submits and waits for one frame of a peer's `passes` on `gbuffer`, as
/// [`submit_frame`] does aokit's.
fn submit_peer_frame(
    passes: &mut XeGtao,
    gpu: &GpuContext,
    view: &View,
    gbuffer: &GBuffer,
) -> Result<(f64, f64)> {
    timed_frame(gpu, |encoder| {
        passes.encode(
            &gpu.device,
            &gpu.queue,
            encoder,
            &gbuffer.depth,
            &gbuffer.normals,
            &view.projection,
        )
    })
}

/// One frame's inputs: the G-buffer of `band` pixels of overscan.
struct Frame<'a> {
    view: &'a View,
    gbuffer: &'a GBuffer,
    band: u32,
    index: u32,
}

/// Encodes, submits and waits for one frame of `pipeline`.
fn submit_frame(
    pipeline: &mut AoPipeline,
    gpu: &GpuContext,
    frame: &Frame<'_>,
) -> Result<(f64, f64)> {
    let gbuffer = frame.gbuffer;
    timed_frame(gpu, |encoder| {
        pipeline.encode(
            &gpu.device,
            &gpu.queue,
            encoder,
            &AoInputs {
                normals: Some((&gbuffer.normals).into()),
                view_from_world: frame.view.view_from_world,
                frame_index: frame.index,
                // Refused with a band; only the temporal filter reads them.
                motion_vectors: (frame.band == 0).then_some((&gbuffer.motion).into()),
                back_depth: gbuffer.back_depth.as_ref().map(Into::into),
                guard_band: frame.band,
                ..AoInputs::new(&gbuffer.depth, frame.view.projection)
            },
        )?;
        Ok(())
    })
}

/// Records one frame with `encode` into a fresh encoder, submits it and waits until the
/// device is idle: the milliseconds in `encode` and from submit until idle.
fn timed_frame(
    gpu: &GpuContext,
    encode: impl FnOnce(&mut wgpu::CommandEncoder) -> Result<()>,
) -> Result<(f64, f64)> {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let start = Instant::now();
    encode(&mut encoder)?;
    let encode_ms = start.elapsed().as_secs_f64() * 1e3;
    let commands = encoder.finish();
    let start = Instant::now();
    gpu.queue.submit([commands]);
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| anyhow!("waiting for the GPU failed: {e}"))?;
    Ok((encode_ms, start.elapsed().as_secs_f64() * 1e3))
}

/// `name  median  p10  p90` rows.
fn stats_row(name: &str, width: usize, s: &Stats) -> String {
    format!(
        "{name:<width$}  {:>10}  {:>10}  {:>10}",
        ms(s.median),
        ms(s.p10),
        ms(s.p90)
    )
}

fn print_one(gpu: &GpuContext, scene: &Scene, camera: &str, run: &Run) {
    let [w, h] = run.args.size;
    outln!(
        "adapter: {} | size: {w}x{h} | method: {} | preset: {}",
        gpu.describe(),
        run.engine.method_name(),
        run.preset_label()
    );
    outln!(
        "scene `{}`, camera `{camera}`: {} timed frames after {} warm-up",
        scene.name,
        run.args.frames,
        run.args.warmup
    );
    match (run.pass_stats(), run.total_gpu()) {
        (Some(passes), Some(total)) => {
            let width = passes
                .iter()
                .map(|(n, _)| n.len())
                .max()
                .unwrap_or(0)
                .max(5);
            outln!(
                "{:<width$}  {:>10}  {:>10}  {:>10}",
                "GPU ms",
                "median",
                "p10",
                "p90"
            );
            for (name, s) in &passes {
                outln!("{}", stats_row(name, width, s));
            }
            outln!("{}", stats_row("total", width, &total));
        }
        _ => outln!("GPU time: not measured (the adapter has no TIMESTAMP_QUERY)"),
    }
    let line = |what: &str, s: Option<Stats>| {
        if let Some(s) = s {
            outln!(
                "{what}: median {} ms, p10 {} ms, p90 {} ms",
                ms(s.median),
                ms(s.p10),
                ms(s.p90)
            );
        }
    };
    let encode = match run.engine {
        Engine::Aokit { .. } => "CPU encode (AoPipeline::encode)",
        Engine::Peer { .. } => "CPU encode (the peer's passes)",
    };
    line(encode, Stats::of(&run.encode_ms));
    line("wall time (submit until idle)", Stats::of(&run.wall_ms));
}

fn print_compare(gpu: &GpuContext, scene: &Scene, camera: &str, runs: &[Run], basis: Basis) {
    let [w, h] = runs[0].args.size;
    outln!("adapter: {} | size: {w}x{h}", gpu.describe());
    outln!(
        "scene `{}`, camera `{camera}`: {} configurations, {} timed frames each after {} \
         warm-up, interleaved; ratio: of the median {} time",
        scene.name,
        runs.len(),
        runs[0].args.frames,
        runs[0].args.warmup,
        match basis {
            Basis::GpuTotal => "total GPU",
            Basis::Wall => "wall",
        }
    );
    outln!(
        "{:<3}  {:>10}  {:>10}  {:>10}  {:>10}  {:>7}  {:>10}  configuration (method, preset)",
        "#",
        "GPU ms",
        "p10",
        "p90",
        "wall ms",
        "ratio",
        "encode ms"
    );
    let median = |values: &[f64]| Stats::of(values).map_or(f64::NAN, |s| s.median);
    for (i, run) in runs.iter().enumerate() {
        let gpu = run
            .total_gpu()
            .map_or(["-".to_string(), "-".into(), "-".into()], |s| {
                [ms(s.median), ms(s.p10), ms(s.p90)]
            });
        outln!(
            "{:<3}  {:>10}  {:>10}  {:>10}  {:>10}  {:>7.3}  {:>10}  {} ({}, {})",
            i + 1,
            gpu[0],
            gpu[1],
            gpu[2],
            ms(median(&run.wall_ms)),
            run.median(basis) / runs[0].median(basis),
            ms(median(&run.encode_ms)),
            if run.label.is_empty() {
                "(shared options)"
            } else {
                &run.label
            },
            run.engine.method_name(),
            run.preset_label()
        );
    }
    if runs[0].pass_times.is_empty() {
        return;
    }
    // Per-pass medians, one column per configuration; passes in order of first appearance.
    let stats: Vec<Vec<(&'static str, Stats)>> = runs
        .iter()
        .map(|run| run.pass_stats().unwrap_or_default())
        .collect();
    let mut names: Vec<&'static str> = Vec::new();
    for passes in &stats {
        for (name, _) in passes {
            if !names.contains(name) {
                names.push(name);
            }
        }
    }
    let width = names.iter().map(|n| n.len()).max().unwrap_or(0).max(6);
    outln!("per-pass GPU median ms:");
    let header: Vec<String> = (1..=runs.len())
        .map(|i| format!("{:>10}", format!("#{i}")))
        .collect();
    outln!("{:<width$}  {}", "pass", header.join("  "));
    for name in names {
        let cells: Vec<String> = stats
            .iter()
            .map(|passes| {
                // A pass that runs twice in a frame: its runs added.
                let matching: Vec<f64> = passes
                    .iter()
                    .filter(|(n, _)| *n == name)
                    .map(|(_, s)| s.median)
                    .collect();
                if matching.is_empty() {
                    format!("{:>10}", "-")
                } else {
                    format!("{:>10}", ms(matching.iter().sum()))
                }
            })
            .collect();
        outln!("{name:<width$}  {}", cells.join("  "));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_split_like_a_shell() {
        assert_eq!(
            split_words(r#"  --method gtao --set "a=b c"  --x 'y z' a\ b "q\"" "#).unwrap(),
            [
                "--method", "gtao", "--set", "a=b c", "--x", "y z", "a b", "q\""
            ]
        );
        assert!(split_words("").unwrap().is_empty());
        assert_eq!(split_words(r#""""#).unwrap(), [""]);
        assert!(split_words(r#"--set "a"#).is_err());
        assert!(split_words(r"a\").is_err());
    }

    #[test]
    fn shared_words_stop_at_compare() {
        let argv: Vec<OsString> = [
            "aokit",
            "bench",
            "--size",
            "8x8",
            "--compare",
            "--method hbao",
            "x",
        ]
        .map(OsString::from)
        .to_vec();
        assert_eq!(shared_words(&argv), ["--size", "8x8"].map(OsString::from));
        let argv: Vec<OsString> = ["aokit", "bench", "--json", "--compare=--method hbao"]
            .map(OsString::from)
            .to_vec();
        assert_eq!(shared_words(&argv), ["--json"].map(OsString::from));
    }

    #[test]
    fn percentiles_interpolate_between_ranks() {
        let s = Stats::of(&[4.0, 1.0, 3.0, 2.0, 5.0]).unwrap();
        assert_eq!(s.median, 3.0);
        assert!(
            (s.p10 - 1.4).abs() < 1e-12 && (s.p90 - 4.6).abs() < 1e-12,
            "{s:?}"
        );
        let s = Stats::of(&[7.0]).unwrap();
        assert_eq!((s.median, s.p10, s.p90), (7.0, 7.0, 7.0));
        assert!(Stats::of(&[]).is_none());
    }
}
