//! `aokit view`: an interactive viewer. A winit window shows the scene rendered every frame by
//! the scene renderer and the AO pipeline; an egui side panel, generated from the settings'
//! declarations, changes the settings live. docs/viewer.md describes it.
//!
//! - [`camera`]: fly and orbit camera, the pose as flags.
//! - [`panel`]: the settings panel from [`aokit::settings::SETTINGS`], flags and TOML out.
//! - [`frame`]: display modes, internal render size, timings.
//! - [`gpu`]: the window's device and surface, reading back a screenshot.
//! - [`app`]: the event loop: input, one frame, the screenshot mode.
//! - [`ui`]: the layout of the panel and the central view.

mod app;
pub mod camera;
pub mod frame;
mod gpu;
pub mod panel;
mod ui;

use std::path::PathBuf;

use anyhow::{Result, bail};
use aokit_scene::Scene;
use clap::Args;

use crate::camera_args::CameraArgs;
use crate::render::parse_size;
use crate::settings_args::SettingsArgs;

use frame::DisplayMode;

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
    /// What to show: lit, ao, or a debug view (depth, working-depth, normals, edges,
    /// bent-normals, raw-ao, rejected).
    #[arg(long, default_value = "lit", value_parser = parse_mode)]
    pub mode: DisplayMode,
    /// Window size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1280x720", value_parser = parse_size)]
    pub window_size: [u32; 2],
    /// Render at this fraction of the view's pixels, upscaled to it (default: 1 on a GPU, 0.5
    /// on a software adapter).
    #[arg(long, value_name = "S", value_parser = parse_scale)]
    pub scale: Option<f32>,
    /// Start with the side panel hidden (Tab shows it).
    #[arg(long)]
    pub no_panel: bool,
    /// Render this many frames, then exit (with --screenshot: 5 unless given).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub frames: Option<u32>,
    /// After the last frame, write the window's content to this PNG file and exit.
    #[arg(long, value_name = "FILE.png")]
    pub screenshot: Option<PathBuf>,
    /// Print the settings panel's widgets (group, key, widget and bounds, one setting a line)
    /// for the settings the flags give, and exit without opening a window.
    #[arg(long)]
    pub panel_layout: bool,
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
    let scene = Scene::open(&args.scene)?;
    for note in &scene.notes {
        eprintln!("note: {}: {note}", scene.name);
    }
    let camera = args.camera.resolve(&scene)?;
    let settings = args.settings.resolve_for_sequence(scene.suggested_radius)?;
    if args.panel_layout {
        out!("{}", panel::layout(&settings));
        return Ok(());
    }
    let frames = args
        .frames
        .or(args.screenshot.as_ref().map(|_| SCREENSHOT_FRAMES));
    app::run(app::Start {
        scene,
        camera,
        settings,
        preset: args
            .settings
            .preset
            .as_deref()
            .map_or(Ok(aokit::Preset::default()), str::parse)
            .map_err(anyhow::Error::msg)?,
        mode: args.mode,
        window_size: args.window_size,
        scale: args.scale,
        panel: !args.no_panel,
        frames,
        screenshot: args.screenshot.clone(),
    })
}
