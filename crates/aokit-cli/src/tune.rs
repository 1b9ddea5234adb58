//! `aokit tune`: searches each method's parameters, at each preset's cost, for the lowest mean
//! squared error against the ray-traced reference over a set of views, and writes the table the
//! presets are taken from (docs/tuning.md).
//!
//! The cost of a preset is its depth samples per pixel; at that cost the search moves the
//! knobs that cost nothing (the final power, the falloff, the step spacing, a radius scale and
//! each method's own bias or thickness) and the split of the samples between directions and
//! steps. It is a coordinate descent: one parameter at a time over its candidate values, the
//! others held, best kept, round after round until one gains nothing, starting from the
//! current preset. `vbao` is held to GTAO's error on every view; where that search stalls
//! outside the bound it also moves two parameters at once.

use std::collections::HashMap;
use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use aokit::{AoInputs, AoPipeline, AoSettings, GpuContext, Method, NormalEncoding, Preset};
use aokit_eval::{rmse, surface_mask};
use aokit_reference::{AoOptions, Falloff, ReferenceImage};
use aokit_scene::Renderer;
use aokit_scene::gbuffer::GBuffer;
use clap::Args;
use serde::Serialize;

use crate::cache;
use crate::compare::{methods, open_view};
use crate::export::create_dir;
use crate::render::{open_gpu, parse_size};
use crate::view_sets;

#[derive(Args, Debug)]
pub struct TuneArgs {
    /// A view as SCENE or SCENE@CAMERA; repeat for several (default: the tuning views, the
    /// built-in room, stairs and thin, and Sponza's four cameras from scenes/sponza.obj). A
    /// view of a held-out scene is refused (docs/quality.md).
    #[arg(long, value_name = "SCENE[@CAMERA]")]
    pub view: Vec<String>,
    /// Image size of every view.
    #[arg(long, value_name = "WxH", default_value = "240x135", value_parser = parse_size, allow_hyphen_values = true)]
    pub size: [u32; 2],
    /// Methods to tune, comma-separated, or `all`. `ssao-crytek`, `sao`, `ue4-ssao` and `msvo`
    /// are left out unless named: their presets keep their published forms, Crytek's 2007
    /// formulation, whose grey look is what the method is chosen for (the search would trade
    /// it away: docs/tuning.md), the SAO paper's parameters, Unreal's as Unreal Engine 4's
    /// PostProcessAmbientOcclusion.usf (Epic Games) gives them and Unity's MSVO defaults (Unity
    /// Post-processing Stack v2). `vbao` is tuned twice: as it is, and measuring its occluders
    /// from the back faces (the presets of `AoSettings::preset_with_back_faces`).
    /// (`--methods` before.)
    #[arg(
        long = "method",
        alias = "methods",
        value_name = "METHOD,...",
        value_delimiter = ',',
        default_value = "ssao,hbao,hbao-plus,gtao,vbao"
    )]
    pub methods: Vec<String>,
    /// Presets (cost levels) to tune, comma-separated (`--presets` before).
    #[arg(
        long = "preset",
        alias = "presets",
        value_name = "PRESET,...",
        value_delimiter = ',',
        default_value = "low,medium,high,ultra"
    )]
    pub presets: Vec<Preset>,
    /// Reference rays per pixel.
    #[arg(long, default_value_t = 256, value_parser = crate::reference::parse_spp, allow_negative_numbers = true)]
    pub spp: u32,
    /// Most rounds of the coordinate descent over all parameters; a search stops at the first
    /// round that gains nothing. 3 rounds left the first tuning short of where the search
    /// ends (docs/tuning.md).
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=10), allow_negative_numbers = true)]
    pub rounds: u32,
    /// Tune `vbao` for the lowest mean error alone. By default its search is held to GTAO's
    /// error at the same preset on every view (GTAO's in this run when it is tuned too, its
    /// preset's otherwise): VBAO is GTAO's height field given a thickness, and a thickness
    /// that loses a view to GTAO is a trade the user did not ask for (docs/tuning.md).
    #[arg(long)]
    pub unbounded: bool,
    /// Where references are cached (default: $AOKIT_CACHE, $XDG_CACHE_HOME/aokit or ~/.cache/aokit).
    #[arg(long, value_name = "DIR")]
    pub cache: Option<PathBuf>,
    /// Output directory: tune.md, tune.json, evaluations.csv.
    #[arg(long, value_name = "DIR", default_value = "aokit-tune")]
    pub out: PathBuf,
    /// Also write what the search found as a settings file that --settings reads: every
    /// setting of the one method and preset tuned (vbao as it is, not from back faces), but
    /// the radius, which belongs to the scene.
    #[arg(long, value_name = "FILE")]
    pub write_settings: Option<PathBuf>,
}

/// The settings file `--write-settings` asks for: every setting of `tuned` but the radius, as
/// TOML that `--settings` reads.
fn settings_file(tuned: &Tuned) -> Result<String> {
    let method: Method = tuned.method.parse().map_err(anyhow::Error::msg)?;
    let preset: Preset = tuned.preset.parse().map_err(anyhow::Error::msg)?;
    let settings = tuned.tuned.apply(&AoSettings::preset(method, preset), 1.0);
    // Serialised from the typed value, so that f32 parameters read as they are (0.005, not
    // 0.004999999888241291); the top-level radius line goes, leaving the scene's.
    let text = toml::to_string(&settings)?;
    let mut top_level = true;
    let body: Vec<&str> = text
        .lines()
        .filter(|line| {
            top_level &= !line.starts_with('[');
            !(top_level && line.starts_with("radius ="))
        })
        .collect();
    Ok(format!(
        "# `aokit tune` found these for {} at `{}` (RMSE {:.4} over its views); the radius is\n\
         # the scene's. Read with --settings FILE.\n{}\n",
        tuned.method,
        tuned.preset,
        tuned.tuned_rmse,
        body.join("\n")
    ))
}

/// Step spacings searched for the marching methods.
const STEP_POWERS: &[f32] = &[1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0];

/// Final powers of the sweep that measures what the power alone does to the error.
const POWER_SWEEP: [f32; 9] = [0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.25, 1.4, 1.6];

/// How well a candidate does: its mean squared error over the views, and by how much it exceeds
/// a bound on each view's RMSE (the sum over the views of the excess; 0 without a bound).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Fit {
    mse: f64,
    excess: f64,
}

impl Fit {
    /// `rmse` (one per view) held to `bound` (the same views' largest allowed RMSE), if any.
    fn of(rmse: &[f64], bound: Option<&[f64]>) -> Self {
        let mse = rmse.iter().map(|r| r * r).sum::<f64>() / rmse.len() as f64;
        let excess = bound.map_or(0.0, |bound| {
            rmse.iter().zip(bound).map(|(r, b)| (r - b).max(0.0)).sum()
        });
        Self { mse, excess }
    }

    /// Whether the search should move from `self` to `other`: a candidate within the bound
    /// beats one outside it; outside, the smaller excess wins; inside, the lower error. A move
    /// must gain at least 0.5% of the mean squared error (0.25% of the RMSE, 0.0002 at a
    /// typical 0.08, the tables' last digit), so that ties and gains too small to tell from
    /// the fit to one set of references keep the current value: with 0.01% a search moved
    /// GTAO `high`'s step power on a gain that left its RMSE the same to four decimals and
    /// raised its held-out error (0.0596 to 0.0602).
    fn improved_by(&self, other: &Fit) -> bool {
        const GAIN: f64 = 1.0 - 5e-3;
        match (self.excess > 0.0, other.excess > 0.0) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => other.excess < self.excess * GAIN,
            (false, false) => other.mse < self.mse * GAIN,
        }
    }
}

/// One point of the search.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Candidate {
    /// `AoSettings::power`.
    pub power: f32,
    /// `AoSettings::falloff`.
    pub falloff: f32,
    /// `AoSettings::step_power`.
    pub step_power: f32,
    /// `AoSettings::radius_multiplier`: the kernel's radius over the reference's.
    pub radius_multiplier: f32,
    /// The method's own knob (see [`knob_name`]).
    pub knob: f32,
    /// Directions or slices, and steps per direction or side; `[samples, 1]` for the point
    /// methods.
    pub split: [u32; 2],
}

/// The setting each method's knob is: the one its preset rows set in the library (`Knob` in
/// crates/aokit/src/methods/; tests/cli/tune.rs compares the presets with the table this
/// writes). The search (these names, [`Candidate`]'s fields, the grids of `dimensions`) stays
/// with the tool rather than in each method's module: it is how `aokit tune` measures, not
/// what the library runs.
pub fn knob_name(method: Method) -> &'static str {
    match method {
        Method::SsaoCrytek | Method::Ssao | Method::Sao | Method::Ue4Ssao => "bias",
        Method::Hbao | Method::HbaoPlus => "angle_bias",
        Method::Gtao => "gtao.thickness",
        Method::Vbao => "vbao.thickness",
        Method::Msvo => "msvo.thickness",
    }
}

impl Candidate {
    /// What `settings` (a method at a preset) has.
    fn of(settings: &AoSettings) -> Self {
        let (knob, split) = match settings.method {
            Method::SsaoCrytek => (settings.bias, [settings.ssao_crytek.sample_count, 1]),
            Method::Ssao => (settings.bias, [settings.ssao.sample_count, 1]),
            Method::Sao => (settings.bias, [settings.sao.sample_count, 1]),
            Method::Ue4Ssao => (settings.bias, [settings.ue4_ssao.sample_count, 1]),
            Method::Msvo => (settings.msvo.thickness, [settings.msvo.sample_count, 1]),
            Method::Hbao | Method::HbaoPlus => (
                settings.angle_bias,
                [settings.hbao.direction_count, settings.hbao.step_count],
            ),
            Method::Gtao => (
                settings.gtao.thickness,
                [settings.gtao.slice_count, settings.gtao.steps_per_side],
            ),
            Method::Vbao => (
                settings.vbao.thickness,
                [settings.vbao.slice_count, settings.vbao.steps_per_side],
            ),
        };
        Self {
            power: settings.power,
            falloff: settings.falloff,
            step_power: settings.step_power,
            radius_multiplier: settings.radius_multiplier,
            knob,
            split,
        }
    }

    /// `settings` with this candidate's values, for a view whose reference radius is `radius`.
    fn apply(&self, settings: &AoSettings, radius: f32) -> AoSettings {
        let mut s = AoSettings {
            radius,
            radius_multiplier: self.radius_multiplier,
            power: self.power,
            falloff: self.falloff,
            step_power: self.step_power,
            ..*settings
        };
        let [a, b] = self.split;
        match s.method {
            Method::SsaoCrytek => (s.bias, s.ssao_crytek.sample_count) = (self.knob, a),
            Method::Ssao => (s.bias, s.ssao.sample_count) = (self.knob, a),
            Method::Sao => (s.bias, s.sao.sample_count) = (self.knob, a),
            Method::Ue4Ssao => (s.bias, s.ue4_ssao.sample_count) = (self.knob, a),
            Method::Msvo => (s.msvo.thickness, s.msvo.sample_count) = (self.knob, a),
            Method::Hbao | Method::HbaoPlus => {
                s.angle_bias = self.knob;
                (s.hbao.direction_count, s.hbao.step_count) = (a, b);
            }
            Method::Gtao => {
                s.gtao.thickness = self.knob;
                (s.gtao.slice_count, s.gtao.steps_per_side) = (a, b);
            }
            Method::Vbao => {
                s.vbao.thickness = self.knob;
                (s.vbao.slice_count, s.vbao.steps_per_side) = (a, b);
            }
        }
        s
    }

    fn key(&self) -> String {
        format!("{self:?}")
    }
}

/// One parameter of the search: its name, and the candidates that vary it alone.
struct Dimension {
    name: &'static str,
    values: Vec<Candidate>,
}

/// The dimensions searched for `method` (measuring its occluders from the back faces when
/// `back_faces`) around `at`, with the samples per pixel of its preset.
fn dimensions(method: Method, back_faces: bool, at: &Candidate, samples: u32) -> Vec<Dimension> {
    let along = |name, values: &[f32], set: fn(&mut Candidate, f32)| Dimension {
        name,
        values: values
            .iter()
            .map(|&v| {
                let mut c = *at;
                set(&mut c, v);
                c
            })
            .collect(),
    };
    let mut dims = vec![
        along(
            "power",
            &[
                0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.25, 1.4, 1.6, 1.8, 2.0, 2.5, 3.0, 3.5,
            ],
            |c, v| c.power = v,
        ),
        along(
            "radius_multiplier",
            &[0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.35, 1.5, 1.7, 2.0, 2.5],
            |c, v| c.radius_multiplier = v,
        ),
    ];
    // The falloff shapes gtao's horizons and the point methods' range check; hbao, vbao and
    // sao weigh samples their own way.
    if matches!(method, Method::Gtao | Method::Ssao | Method::SsaoCrytek) {
        dims.push(along(
            "falloff",
            &[0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0],
            |c, v| c.falloff = v,
        ));
    }
    let knob: &[f32] = match method {
        // Not 0: the views hold 32-bit float depth, and with 16- or 24-bit depth a plane
        // needs some bias not to occlude itself.
        Method::SsaoCrytek | Method::Ssao | Method::Sao | Method::Ue4Ssao => {
            &[0.005, 0.01, 0.02, 0.04, 0.08, 0.12, 0.2, 0.3]
        }
        Method::Hbao | Method::HbaoPlus => &[0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5],
        Method::Gtao => &[0.0, 0.05, 0.1, 0.2, 0.3, 0.5],
        // Measured from the back faces, solids are as thick as they are, and the knob is the
        // least thickness, for poles and fences whose back faces lie closer or were not seen.
        // Finer between 0.45 and 0.6: at `low` GTAO's error bounds `thin` from one side and the
        // atrium from the other, and only 0.5 lay between (2026-11-28).
        Method::Vbao if back_faces => &[0.05, 0.1, 0.15, 0.2, 0.3, 0.45, 0.5, 0.55, 0.6],
        // Finer between 0.4 and 0.8, where the views trade: boxes and steps want it thick, the
        // pillars and fences of `thin` thin, and the bound on each view (TuneArgs::unbounded)
        // leaves a narrow band.
        Method::Vbao => &[
            0.2, 0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 1.0, 1.3,
        ],
        // Unity's slider runs from 1 to 10; below 1 rejects occluders of a plain crease.
        Method::Msvo => &[0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0],
    };
    dims.push(along(knob_name(method), knob, |c, v| c.knob = v));
    if matches!(
        method,
        Method::SsaoCrytek | Method::Ssao | Method::Sao | Method::Ue4Ssao | Method::Msvo
    ) {
        return dims;
    }
    dims.push(along("step_power", STEP_POWERS, |c, v| c.step_power = v));
    // hbao-plus runs on hbao's directions and steps (one `hbao` settings block): it takes
    // hbao's split rather than one of its own.
    if method == Method::HbaoPlus {
        return dims;
    }
    // Splits of the samples at the same cost: the slice methods take 2 samples per slice
    // and step (one per side).
    let pairs = if matches!(method, Method::Gtao | Method::Vbao) {
        samples / 2
    } else {
        samples
    };
    dims.push(Dimension {
        name: "split",
        values: (1..=pairs)
            .filter(|&d| {
                let max = aokit::settings::MAX_SAMPLE_COUNT;
                pairs.is_multiple_of(d) && d <= max && pairs / d <= max
            })
            .map(|d| Candidate {
                split: [d, pairs / d],
                ..*at
            })
            .collect(),
    });
    dims
}

/// Every candidate that differs from `at` in two of the search's parameters at once.
fn pair_moves(method: Method, back_faces: bool, at: &Candidate, samples: u32) -> Vec<Candidate> {
    let dims = dimensions(method, back_faces, at, samples);
    let mut moves = Vec::new();
    for (i, first) in dims.iter().enumerate() {
        for moved in first.values.iter().filter(|c| *c != at) {
            // The dimensions are the same list around any candidate of the same method.
            for second in &dimensions(method, back_faces, moved, samples)[i + 1..] {
                moves.extend(second.values.iter().filter(|c| *c != moved));
            }
        }
    }
    moves
}

/// A view ready for scoring: its G-buffer, the reference and the pixels with a surface.
struct View {
    name: String,
    radius: f32,
    gbuffer: GBuffer,
    projection: aokit::Projection,
    reference: ReferenceImage,
    surface: Vec<bool>,
}

/// Runs candidates on every view and remembers what each scored.
struct Evaluator<'a> {
    gpu: &'a GpuContext,
    views: Vec<View>,
    pipeline: AoPipeline,
    /// Each view's RMSE, by method, back faces and candidate.
    scores: HashMap<(Method, bool, String), Vec<f64>>,
    /// Every evaluation in order, for evaluations.csv: the subject (method, and whether it
    /// measures back faces), the preset, the candidate and its mean squared error.
    log: Vec<(Method, bool, Preset, Candidate, f64)>,
}

impl Evaluator<'_> {
    /// Each view's RMSE with `candidate`.
    fn score(
        &mut self,
        base: &AoSettings,
        preset: Preset,
        candidate: &Candidate,
    ) -> Result<Vec<f64>> {
        let back_faces = base.method == Method::Vbao && base.vbao.back_faces;
        let key = (base.method, back_faces, candidate.key());
        if let Some(scored) = self.scores.get(&key) {
            return Ok(scored.clone());
        }
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let mut scores = Vec::with_capacity(self.views.len());
        for view in &self.views {
            let settings = candidate.apply(base, view.radius);
            self.pipeline.set_settings(device, queue, &settings)?;
            let mut encoder = device.create_command_encoder(&Default::default());
            let outputs = self.pipeline.encode(
                device,
                queue,
                &mut encoder,
                &AoInputs {
                    normals: Some((&view.gbuffer.normals).into()),
                    back_depth: view.gbuffer.back_depth.as_ref().map(Into::into),
                    ..AoInputs::new(&view.gbuffer.depth, view.projection)
                },
            )?;
            queue.submit([encoder.finish()]);
            let ao = aokit::gpu::read_texture_f32(device, queue, outputs.ao)?;
            if ao.iter().any(|v| !v.is_finite()) {
                bail!(
                    "{} wrote non-finite AO on {}",
                    base.method.name(),
                    view.name
                );
            }
            scores.push(rmse(
                view.reference.size,
                &ao,
                &view.reference.ao,
                &view.surface,
            ));
        }
        let mse = Fit::of(&scores, None).mse;
        self.log
            .push((base.method, back_faces, preset, *candidate, mse));
        self.scores.insert(key, scores.clone());
        Ok(scores)
    }
}

/// What the search found for one method at one preset.
#[derive(Serialize)]
struct Tuned {
    method: &'static str,
    /// Whether `vbao` measured its occluders from the back faces
    /// (`AoSettings::preset_with_back_faces`).
    back_faces: bool,
    preset: &'static str,
    samples_per_pixel: u32,
    knob: &'static str,
    start: Candidate,
    start_rmse: f64,
    tuned: Candidate,
    tuned_rmse: f64,
    /// Each view's RMSE with the tuned candidate.
    views_rmse: Vec<f64>,
    /// Each view's largest RMSE the search allowed, when it was held to one (`vbao`, by
    /// GTAO's), and by how much the start and the tuned candidate exceed it, summed over the
    /// views (0 when within it everywhere).
    bound: Option<Vec<f64>>,
    start_excess: f64,
    tuned_excess: f64,
}

/// What tune.json holds.
#[derive(Serialize)]
struct TuneFile<'a> {
    adapter: String,
    command: String,
    size: [u32; 2],
    spp: u32,
    views: Vec<String>,
    results: &'a [Tuned],
    power_sweep: Vec<PowerSweep>,
}

/// The error of one method at its `high` preset over a range of final powers.
#[derive(Serialize)]
struct PowerSweep {
    method: &'static str,
    power: [f32; POWER_SWEEP.len()],
    rmse: Vec<f64>,
}

/// Coordinate descent from the preset's own values (those of
/// `AoSettings::preset_with_back_faces` when `back_faces`); `split`, when given, replaces the
/// preset's split of the samples and is kept (hbao-plus takes hbao's). With a `bound` (each
/// view's largest allowed RMSE) the search first brings every view within it, then lowers the
/// mean error without leaving it (see [`Fit::improved_by`]).
fn tune_one(
    evaluator: &mut Evaluator<'_>,
    (method, back_faces): (Method, bool),
    preset: Preset,
    rounds: u32,
    split: Option<[u32; 2]>,
    bound: Option<&[f64]>,
) -> Result<Tuned> {
    let base = if back_faces {
        AoSettings::preset_with_back_faces(method, preset)
    } else {
        AoSettings::preset(method, preset)
    };
    let samples = base.samples_per_pixel();
    let mut start = Candidate::of(&base);
    if let Some(split) = split {
        start.split = split;
    }
    let start_fit = Fit::of(&evaluator.score(&base, preset, &start)?, bound);
    let mut best = (start, start_fit);
    let progress = |step: &str, best: &(Candidate, Fit)| {
        eprintln!(
            "tune: {} {} after {step}: RMSE {:.4}{}",
            subject(method, back_faces),
            preset.name(),
            best.1.mse.sqrt(),
            if best.1.excess > 0.0 {
                format!(", {:.4} over the bound", best.1.excess)
            } else {
                String::new()
            }
        );
    };
    // Scores each of `candidates` and moves `best` to every one that improves on it.
    let mut search = |candidates: &[Candidate], best: &mut (Candidate, Fit)| -> Result<()> {
        for candidate in candidates {
            let fit = Fit::of(&evaluator.score(&base, preset, candidate)?, bound);
            if best.1.improved_by(&fit) {
                *best = (*candidate, fit);
            }
        }
        Ok(())
    };
    for _ in 0..rounds {
        let before = best.0;
        for dimension in dimensions(method, back_faces, &best.0, samples) {
            search(&dimension.values, &mut best)?;
            progress(dimension.name, &best);
        }
        // One parameter at a time the search can stall outside the bound where points within
        // it exist (vbao `low`, docs/tuning.md): there it moves two parameters at once.
        if best.0 == before && best.1.excess > 0.0 {
            search(&pair_moves(method, back_faces, &best.0, samples), &mut best)?;
            progress("pairs of parameters", &best);
        }
        if best.0 == before {
            break;
        }
    }
    let views_rmse = evaluator.score(&base, preset, &best.0)?;
    Ok(Tuned {
        method: method.name(),
        back_faces,
        preset: preset.name(),
        samples_per_pixel: samples,
        knob: knob_name(method),
        start,
        start_rmse: start_fit.mse.sqrt(),
        tuned: best.0,
        tuned_rmse: best.1.mse.sqrt(),
        views_rmse,
        bound: bound.map(<[f64]>::to_vec),
        start_excess: start_fit.excess,
        tuned_excess: best.1.excess,
    })
}

/// What this run tuned for `method` at `preset` (the variant without back faces).
fn tuned_at(tuned: &[Tuned], method: Method, preset: Preset) -> Option<&Tuned> {
    tuned
        .iter()
        .find(|t| t.method == method.name() && t.preset == preset.name() && !t.back_faces)
}

/// GTAO's RMSE on each view at `preset`: as this run tuned it, or its preset's when GTAO is not
/// tuned here.
fn gtao_rmse(evaluator: &mut Evaluator<'_>, tuned: &[Tuned], preset: Preset) -> Result<Vec<f64>> {
    if let Some(t) = tuned_at(tuned, Method::Gtao, preset) {
        return Ok(t.views_rmse.clone());
    }
    let gtao = AoSettings::preset(Method::Gtao, preset);
    evaluator.score(&gtao, preset, &Candidate::of(&gtao))
}

/// How the progress lines and evaluations.csv name what is tuned.
fn subject(method: Method, back_faces: bool) -> String {
    if back_faces {
        format!("{} + back faces", method.name())
    } else {
        method.name().to_string()
    }
}

/// The views a search reads: those named, or the tuning views; never a held-out one.
fn view_specs(named: &[String]) -> Result<Vec<String>> {
    let specs: Vec<String> = if named.is_empty() {
        view_sets::TUNING.iter().map(|s| s.to_string()).collect()
    } else {
        named.to_vec()
    };
    for spec in &specs {
        view_sets::check_not_held_out(spec)?;
    }
    Ok(specs)
}

fn load_views(gpu: &GpuContext, args: &TuneArgs) -> Result<Vec<View>> {
    let cache_dir = args.cache.clone().unwrap_or_else(cache::default_dir);
    let mut views = Vec::new();
    for spec in &view_specs(&args.view)? {
        let (scene, camera) = open_view(spec)?;
        let radius = scene.suggested_radius.unwrap_or(1.0);
        let options = AoOptions {
            radius,
            spp: args.spp,
            seed: 0,
            falloff: Falloff::None,
        };
        let reference = cache::reference(&cache_dir, &scene, &camera, args.size, &options)?;
        let mut renderer = Renderer::new(gpu, &scene, &AoSettings::default())?;
        let (gbuffer, projection) =
            renderer.render_gbuffer(gpu, &camera, args.size, NormalEncoding::Oct32)?;
        views.push(View {
            name: format!("{} / {}", scene.name, camera.name),
            radius,
            gbuffer,
            projection,
            surface: surface_mask(&reference.linear_depth),
            reference,
        });
    }
    Ok(views)
}

fn markdown(
    args: &TuneArgs,
    views: &[View],
    tuned: &[Tuned],
    sweep: &[(Method, Vec<f64>)],
) -> String {
    let mut md = String::new();
    md.push_str(&format!(
        "Views: {}; {}x{} pixels; references with {} rays per pixel; {} round(s).\n\n",
        views
            .iter()
            .map(|v| v.name.as_str())
            .collect::<Vec<_>>()
            .join(", "),
        args.size[0],
        args.size[1],
        args.spp,
        args.rounds
    ));
    md.push_str(
        "| method | preset | samples | split | step_power | falloff | knob | power | radius_multiplier | RMSE before | after | over GTAO's |\n\
         |---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
    );
    for t in tuned {
        let c = &t.tuned;
        // Where the search was held to GTAO's error on every view, by how much it ended
        // above it (summed over the views).
        let over = match &t.bound {
            None => String::new(),
            Some(_) if t.tuned_excess == 0.0 => "0".to_string(),
            Some(_) => format!("{:.4}", t.tuned_excess),
        };
        md.push_str(&format!(
            "| `{}`{} | {} | {} | {}x{} | {} | {} | `{}` = {} | {} | {} | {:.4} | {:.4} | {} |\n",
            t.method,
            if t.back_faces { " + back faces" } else { "" },
            t.preset,
            t.samples_per_pixel,
            c.split[0],
            c.split[1],
            c.step_power,
            c.falloff,
            t.knob,
            c.knob,
            c.power,
            c.radius_multiplier,
            t.start_rmse,
            t.tuned_rmse,
            over
        ));
    }
    if !sweep.is_empty() {
        md.push_str("\nThe final power alone, every other parameter at the method's `high` preset (RMSE over the views):\n\n| method |");
        for p in POWER_SWEEP {
            md.push_str(&format!(" {p} |"));
        }
        md.push_str("\n|---|");
        md.push_str(&"--:|".repeat(POWER_SWEEP.len()));
        md.push('\n');
        for (method, mse) in sweep {
            md.push_str(&format!("| `{}` |", method.name()));
            for m in mse {
                md.push_str(&format!(" {:.4} |", m.sqrt()));
            }
            md.push('\n');
        }
    }
    md
}

pub fn run(args: &TuneArgs) -> Result<()> {
    crate::export::check_out_dir(&args.out)?;
    let mut methods = methods(&args.methods)?;
    // hbao-plus takes hbao's split and vbao is held to GTAO's error, each as this run tuned
    // them: those two go after the others, whatever order --method names them in.
    methods.sort_by_key(|m| matches!(m, Method::HbaoPlus | Method::Vbao));
    if methods.is_empty() || args.presets.is_empty() {
        bail!("--method and --preset need at least one entry each");
    }
    if args.write_settings.is_some() && (methods.len() != 1 || args.presets.len() != 1) {
        bail!(
            "--write-settings writes the settings of one method at one preset: name one each \
             with --method and --preset"
        );
    }
    let gpu = open_gpu()?;
    let views = load_views(&gpu, args)?;
    let mut evaluator = Evaluator {
        gpu: &gpu,
        pipeline: AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default())?,
        views,
        scores: HashMap::new(),
        log: Vec::new(),
    };
    let mut tuned = Vec::new();
    let mut sweep = Vec::new();
    for &method in &methods {
        let high = AoSettings::preset(method, Preset::High);
        let mut mse = Vec::new();
        for power in POWER_SWEEP {
            let candidate = Candidate {
                power,
                ..Candidate::of(&high)
            };
            mse.push(Fit::of(&evaluator.score(&high, Preset::High, &candidate)?, None).mse);
        }
        sweep.push((method, mse));
        // vbao is tuned twice: as it is, and measuring its occluders from the back faces.
        let variants: &[bool] = if method == Method::Vbao {
            &[false, true]
        } else {
            &[false]
        };
        for &back_faces in variants {
            for &preset in &args.presets {
                let split = (method == Method::HbaoPlus)
                    .then(|| tuned_at(&tuned, Method::Hbao, preset).map(|t| t.tuned.split))
                    .flatten();
                let bound = if method == Method::Vbao && !args.unbounded {
                    Some(gtao_rmse(&mut evaluator, &tuned, preset)?)
                } else {
                    None
                };
                let result = tune_one(
                    &mut evaluator,
                    (method, back_faces),
                    preset,
                    args.rounds,
                    split,
                    bound.as_deref(),
                )?;
                tuned.push(result);
            }
        }
    }

    let out = &args.out;
    create_dir(out)?;
    let write = |name: &str, text: String| -> Result<()> {
        let path = out.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))
    };
    let md = markdown(args, &evaluator.views, &tuned, &sweep);
    write("tune.md", md.clone())?;
    // A typed value, not `json!`: serde then writes the f32 parameters as they are (0.35),
    // where a JSON value would widen them to f64 first (0.3499999940395355).
    let file = TuneFile {
        adapter: gpu.describe(),
        command: format!(
            "aokit {}",
            std::env::args().skip(1).collect::<Vec<_>>().join(" ")
        ),
        size: args.size,
        spp: args.spp,
        views: evaluator.views.iter().map(|v| v.name.clone()).collect(),
        results: &tuned,
        power_sweep: sweep
            .iter()
            .map(|(m, mse)| PowerSweep {
                method: m.name(),
                power: POWER_SWEEP,
                rmse: mse.iter().map(|m| m.sqrt()).collect(),
            })
            .collect(),
    };
    write("tune.json", serde_json::to_string_pretty(&file)? + "\n")?;
    let mut csv = String::from(
        "method,preset,directions,steps,step_power,falloff,knob,power,radius_multiplier,rmse\n",
    );
    for (method, back_faces, preset, c, mse) in &evaluator.log {
        csv.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{:.6}\n",
            subject(*method, *back_faces),
            preset.name(),
            c.split[0],
            c.split[1],
            c.step_power,
            c.falloff,
            c.knob,
            c.power,
            c.radius_multiplier,
            mse.sqrt()
        ));
    }
    write("evaluations.csv", csv)?;
    if let Some(path) = &args.write_settings {
        let found = tuned_at(&tuned, methods[0], args.presets[0])
            .context("the search found nothing to write")?;
        std::fs::write(path, settings_file(found)?)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    out!("{md}");
    outln!(
        "wrote tune.md, tune.json and evaluations.csv ({} evaluations) to {}",
        evaluator.log.len(),
        out.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{Candidate, Fit, pair_moves, view_specs};
    use crate::view_sets::{HELD_OUT, TUNING};
    use aokit::{AoSettings, Method, Preset};

    /// Which of a candidate's parameters differ from `at`'s, by name.
    fn changed(at: &Candidate, c: &Candidate) -> Vec<&'static str> {
        [
            ("power", at.power != c.power),
            ("falloff", at.falloff != c.falloff),
            ("step_power", at.step_power != c.step_power),
            (
                "radius_multiplier",
                at.radius_multiplier != c.radius_multiplier,
            ),
            ("knob", at.knob != c.knob),
            ("split", at.split != c.split),
        ]
        .into_iter()
        .filter_map(|(name, differs)| differs.then_some(name))
        .collect()
    }

    #[test]
    fn pair_moves_change_exactly_two_parameters_and_every_pair_of_them() {
        let settings = AoSettings::preset(Method::Gtao, Preset::High);
        let at = Candidate::of(&settings);
        let moves = pair_moves(Method::Gtao, false, &at, settings.samples_per_pixel());
        let mut pairs = std::collections::BTreeSet::new();
        for c in &moves {
            let names = changed(&at, c);
            assert_eq!(names.len(), 2, "{c:?} changes {names:?}");
            pairs.insert(names);
        }
        // gtao searches all six parameters: 15 pairs.
        assert_eq!(pairs.len(), 15, "{pairs:?}");
    }

    #[test]
    fn a_bounded_search_gets_within_its_bound_first_then_lowers_the_error() {
        let bound = [0.05, 0.10];
        let fit = |rmse: [f64; 2]| Fit::of(&rmse, Some(&bound));
        // Over on the first view by 0.01, under on the second: only the excess counts.
        let over = fit([0.06, 0.02]);
        assert!((over.excess - 0.01).abs() < 1e-12);
        assert!((over.mse - (0.06f64.powi(2) + 0.02f64.powi(2)) / 2.0).abs() < 1e-12);
        let within = fit([0.05, 0.09]);
        assert_eq!(within.excess, 0.0);
        // Within the bound wins over a lower error outside it, and is never given up for one.
        assert!(over.improved_by(&within));
        assert!(!within.improved_by(&over));
        // Outside, the smaller excess wins whatever the error; inside, the lower error.
        assert!(over.improved_by(&fit([0.055, 0.09])));
        assert!(!over.improved_by(&fit([0.07, 0.0])));
        assert!(within.improved_by(&fit([0.04, 0.09])));
        assert!(!within.improved_by(&fit([0.05, 0.09])));
        // Without a bound nothing is in excess, and only the error decides.
        let free = Fit::of(&[0.2, 0.2], None);
        assert_eq!(free.excess, 0.0);
        assert!(free.improved_by(&Fit::of(&[0.1, 0.2], None)));
    }

    #[test]
    fn a_move_must_show_in_the_error_to_be_taken() {
        let at = |rmse: f64| Fit::of(&[rmse], None);
        // 0.0003 off an RMSE of 0.08 takes 0.75% off its square: taken; 0.0001 (0.25%) is not.
        assert!(at(0.08).improved_by(&at(0.0797)));
        assert!(!at(0.08).improved_by(&at(0.0799)));
    }

    #[test]
    fn a_search_reads_the_tuning_views_and_never_a_held_out_one() {
        assert_eq!(view_specs(&[]).unwrap(), TUNING);
        for view in HELD_OUT {
            let named = [TUNING[0].to_string(), view.to_string()];
            let error = view_specs(&named).unwrap_err().to_string();
            assert!(error.contains("held-out scene"), "{error}");
        }
    }
}
