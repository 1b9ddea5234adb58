//! `aokit view`: an interactive viewer. A winit window shows the scene rendered every frame by
//! the scene renderer and the AO pipeline; an egui side panel, generated from the settings'
//! declarations, changes the settings live. docs/viewer.md describes it.
//!
//! - [`camera`]: fly and orbit camera, the pose as flags.
//! - [`panel`]: the settings panel from [`aokit::settings::SETTINGS`], flags and TOML out.
//! - [`frame`]: display modes, internal render size, timings.
//! - [`gpu`]: the window's device and surface, reading back a screenshot.
//! - [`app`]: the event loop: input, one frame, the screenshot mode.
//! - [`motion`]: the moving parts and the camera path over a loop, pause and step.
//! - [`truth`]: the CPU reference of the view, traced in the background.
//! - [`ui`]: the layout of the panel and the central view.

mod app;
pub mod camera;
pub mod frame;
mod gpu;
pub mod motion;
pub mod panel;
mod truth;
mod ui;

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use aokit_scene::Scene;
use aokit_scene::composite::Lighting;
use clap::Args;

use crate::camera_args::CameraArgs;
use crate::lighting_args::LightingArgs;
use crate::render::parse_size;
use crate::settings_args::{OverrideArgs, SettingsArgs};

use frame::DisplayMode;
use ui::{Config, Split};

/// The flags of `aokit view`.
#[derive(Args, Debug)]
pub struct ViewArgs {
    /// Built-in scene (room, stairs, thin, open) or a .gltf/.glb/.obj file.
    #[arg(long, default_value = "room")]
    pub scene: String,
    #[command(flatten)]
    pub camera: CameraArgs,
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// What to show: lit, ao, reference, error (the last two once the reference is traced), or
    /// a debug view (depth, working-depth, normals, edges, bent-normals, raw-ao, rejected).
    #[arg(long, default_value = "lit", value_parser = parse_mode)]
    pub mode: DisplayMode,
    /// Window size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1280x720", value_parser = parse_size)]
    pub window_size: [u32; 2],
    /// Render at this fraction of the view's pixels, upscaled to it (default: 1 on a GPU, 0.5
    /// on a software adapter).
    #[arg(long, value_name = "S", value_parser = parse_scale)]
    pub scale: Option<f32>,
    /// Pixels of overscan the AO reads on each side, as `aokit render --guard-band`: the
    /// G-buffer is drawn that much larger, and the AO near the view's edges sees what lies just
    /// beyond them (docs/integration.md#a-guard-band). The panel changes it.
    #[arg(long, value_name = "PX", default_value_t = 0)]
    pub guard_band: u32,
    /// Start with the side panel hidden (Tab shows it).
    #[arg(long)]
    pub no_panel: bool,
    /// Render this many frames, then exit (with --screenshot: 5 unless given).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub frames: Option<u32>,
    /// After the last frame, write the window's content to this PNG file and exit.
    #[arg(long, value_name = "FILE.png")]
    pub screenshot: Option<PathBuf>,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub motion: MotionArgs,
    #[command(flatten)]
    pub lighting: LightingArgs,
    /// Trace the CPU reference of the starting view as soon as the window shows; with
    /// --screenshot, the frames are counted once it is traced, and the RMSE is printed.
    #[arg(long)]
    pub reference: bool,
    /// Rays per pixel of the reference (default: 128, or 32 on a software adapter).
    #[arg(long, value_name = "N", value_parser = crate::reference::parse_spp)]
    pub reference_spp: Option<u32>,
    /// Print the settings panel's widgets (group, key, widget and bounds, one setting a line)
    /// for the settings the flags give, and exit without opening a window.
    #[arg(long)]
    pub panel_layout: bool,
}

/// The motion's flags, as `aokit render`'s sequences take them.
#[derive(Args, Debug)]
pub struct MotionArgs {
    /// Move the scene's moving parts over the loop (room: the sphere rolls; stairs: a block
    /// slides; thin: a panel swings).
    #[arg(long)]
    pub animate: bool,
    /// Move the camera over the loop, about the camera you steer: still, orbit, dolly or
    /// strafe (as `aokit render --path`).
    #[arg(long, value_name = "PATH", default_value = "still")]
    pub path: aokit_scene::CameraPath,
    /// Frames in one loop of the motion, time 0 at the first and 1 at the last; one step per
    /// rendered frame.
    #[arg(long, value_name = "N", default_value_t = 120, value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub loop_frames: u32,
    /// Start with the motion paused (Space plays).
    #[arg(long)]
    pub paused: bool,
}

/// The A/B split's flags: B's settings start from A's method and preset unless these say.
#[derive(Args, Debug)]
pub struct SplitArgs {
    /// Open in the A/B split: the flags' settings on the left (A), B's on the right, on the
    /// same G-buffer.
    #[arg(long)]
    pub split: bool,
    /// B's AO method (default: A's).
    #[arg(long, requires = "split", value_parser = clap::builder::PossibleValuesParser::new(aokit::Method::ALL.map(aokit::Method::name)))]
    pub b_method: Option<String>,
    /// B's quality preset (default: A's).
    #[arg(long, requires = "split", value_parser = clap::builder::PossibleValuesParser::new(aokit::Preset::ALL.map(aokit::Preset::name)))]
    pub b_preset: Option<String>,
    /// Set one of B's settings by its dotted path, as `--set` does for A; applied last.
    #[arg(long = "b-set", value_name = "KEY=VALUE", requires = "split")]
    pub b_set: Vec<String>,
    /// Where the halves meet, as a fraction of the view's width from the left.
    #[arg(long, value_name = "F", default_value = "0.5", requires = "split", value_parser = parse_divider)]
    pub divider: f32,
}

fn parse_divider(s: &str) -> Result<f32, String> {
    let divider: f32 = s
        .trim()
        .parse()
        .map_err(|e| format!("`{s}` is not a number: {e}"))?;
    if !(0.0..=1.0).contains(&divider) {
        return Err(format!("`{s}` is outside [0, 1]"));
    }
    Ok(divider)
}

fn parse_mode(s: &str) -> Result<DisplayMode, String> {
    s.parse()
}

/// Smallest and largest internal scale.
const SCALE_RANGE: std::ops::RangeInclusive<f32> = 0.1..=2.0;

fn parse_scale(s: &str) -> Result<f32, String> {
    let scale: f32 = s
        .trim()
        .parse()
        .map_err(|e| format!("`{s}` is not a number: {e}"))?;
    if !SCALE_RANGE.contains(&scale) {
        return Err(format!(
            "`{s}` is outside [{}, {}]",
            SCALE_RANGE.start(),
            SCALE_RANGE.end()
        ));
    }
    Ok(scale)
}

/// Frames `--screenshot` renders when `--frames` is not given.
const SCREENSHOT_FRAMES: u32 = 5;

/// Runs the viewer until the window closes (or `--frames` are done).
pub fn run(args: &ViewArgs) -> Result<()> {
    if let Some(path) = &args.screenshot
        && path.extension().and_then(|e| e.to_str()) != Some("png")
    {
        bail!("--screenshot {} must name a .png file", path.display());
    }
    let moving = args.motion.animate || args.motion.path != aokit_scene::CameraPath::Still;
    if args.reference && moving && !args.motion.paused {
        bail!(
            "--reference traces one view, which the motion would leave at once: with --animate \
             or --path, add --paused"
        );
    }
    let scene = Scene::open(&args.scene)?;
    for note in &scene.notes {
        eprintln!("note: {}: {note}", scene.name);
    }
    let camera = args.camera.resolve(&scene)?;
    if args.motion.animate && scene.moving_parts.is_empty() {
        eprintln!(
            "note: `{}` has no moving parts: --animate changes nothing",
            scene.name
        );
    }
    let settings = args.settings.resolve_for_sequence(scene.suggested_radius)?;
    let preset = parse_preset(args.settings.preset.as_deref())?;
    let config = Config {
        method: settings.method,
        preset,
        settings,
    };
    let split = args
        .split
        .split
        .then(|| split_start(&args.split, &args.settings, &config, scene.suggested_radius))
        .transpose()
        .context("B's settings (--b-method, --b-preset, --b-set)")?;
    if args.panel_layout {
        out!("{}", panel::layout(&settings));
        return Ok(());
    }
    let frames = args
        .frames
        .or(args.screenshot.as_ref().map(|_| SCREENSHOT_FRAMES));
    let mut lighting = Lighting::default();
    args.lighting.apply(&mut lighting, config.settings.method)?;
    app::run(app::Start {
        scene,
        camera,
        config,
        split,
        lighting,
        motion: motion::Motion {
            animate: args.motion.animate,
            path: args.motion.path,
            loop_frames: args.motion.loop_frames,
            frame: 0,
            playing: !args.motion.paused,
        },
        reference: args.reference,
        reference_spp: args.reference_spp,
        mode: args.mode,
        window_size: args.window_size,
        scale: args.scale,
        guard_band: args.guard_band,
        panel: !args.no_panel,
        frames,
        screenshot: args.screenshot.clone(),
    })
}

fn parse_preset(name: Option<&str>) -> Result<aokit::Preset> {
    name.map_or(Ok(aokit::Preset::default()), str::parse)
        .map_err(anyhow::Error::msg)
}

/// B's configuration from the split's flags: its method and preset (A's unless given) with the
/// scene's radius, then `--radius` as A has it, then each `--b-set`.
fn split_start(
    split: &SplitArgs,
    settings: &SettingsArgs,
    a: &Config,
    suggested_radius: Option<f32>,
) -> Result<Split> {
    let method = match &split.b_method {
        Some(name) => name.parse().map_err(anyhow::Error::msg)?,
        None => a.method,
    };
    let preset = match &split.b_preset {
        Some(name) => parse_preset(Some(name))?,
        None => a.preset,
    };
    let overrides = OverrideArgs {
        settings: None,
        set: split.b_set.clone(),
    };
    let b =
        overrides.apply_to_sequence_preset(method, preset, suggested_radius, settings.radius)?;
    if b.normals.encoding != a.settings.normals.encoding {
        bail!(
            "normals.encoding `{}` differs from A's `{}`: both halves run on one G-buffer, whose \
             normals are in A's encoding",
            b.normals.encoding.name(),
            a.settings.normals.encoding.name()
        );
    }
    Ok(Split {
        b: Config {
            method: b.method,
            preset,
            settings: b,
        },
        divider: split.divider,
    })
}
