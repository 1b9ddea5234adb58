//! `aokit ao`: AO for passes exported by another renderer.

use std::path::PathBuf;

use anyhow::Result;
use aokit::{NormalSource, NormalSpace};
use aokit_eval::{write_exr, write_grey_png};
use aokit_scene::external;
use clap::Args;

use crate::export::{check_out_dir, create_dir};
use crate::passes::{self, DepthKind, PassFiles};
use crate::render::{ao_summary, open_gpu};
use crate::settings_args::SettingsArgs;

#[derive(Args, Debug)]
pub struct AoArgs {
    /// Depth image: EXR, PFM or NPY (float32; H x W; background 0, +inf or NaN).
    #[arg(long, value_name = "FILE")]
    pub depth: PathBuf,
    /// Normal image: EXR, PFM or NPY (H x W x 3). Without it normals are reconstructed from depth.
    #[arg(long, value_name = "FILE")]
    pub normals: Option<PathBuf>,
    /// Depth of the nearest back faces (the scene drawn with front faces culled), in the
    /// format and kind of --depth, for `--set vbao.back_faces=true`.
    #[arg(long, value_name = "FILE")]
    pub back_depth: Option<PathBuf>,
    /// The camera, in the camera.json format `render --gbuffer` writes.
    #[arg(long, value_name = "camera.json")]
    pub camera: PathBuf,
    /// Whether the depth is linear view depth or depth-buffer values.
    #[arg(long, value_parser = passes::depth_kind_parser(), default_value = "linear")]
    pub depth_kind: DepthKind,
    /// Whether the normals are in view or world space (camera.json's `view_from_world` turns
    /// world-space ones); the same as `--set normals.space=SPACE`, which wins when both are
    /// given (default: view).
    #[arg(long, value_parser = parse_normal_space)]
    pub normal_space: Option<NormalSpace>,
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "aokit-out")]
    pub out: PathBuf,
}

fn parse_normal_space(s: &str) -> Result<NormalSpace, String> {
    s.parse()
}

pub fn run(args: &AoArgs) -> Result<()> {
    check_out_dir(&args.out)?;
    // `--normal-space` is a setting like `--radius`: applied before `--set`, so that a
    // `--set normals.space=...` (documented as applied last) wins over it, and a settings file's
    // value stands when neither is given. A default on the flag would override both.
    let mut settings_args = args.settings.clone();
    if let Some(space) = args.normal_space {
        let set = &mut settings_args.overrides.set;
        set.insert(0, format!("normals.space={}", space.name()));
    }
    let mut settings = settings_args.resolve(None)?;
    let normal_space = settings.normals.space;
    let loaded = passes::load(
        &PassFiles {
            depth: &args.depth,
            normals: args.normals.as_deref(),
            back_depth: args.back_depth.as_deref(),
            camera: &args.camera,
        },
        args.depth_kind,
        normal_space,
    )?;
    // The normals were turned into view space as they were read.
    settings.normals.space = NormalSpace::View;
    let gpu = open_gpu()?;
    let ao = external::ambient_occlusion(&gpu, &settings, &loaded.passes(), 0)?;
    create_dir(&args.out)?;
    write_exr(&args.out.join("ao.exr"), loaded.size, &[("Y", ao.clone())])?;
    write_grey_png(&args.out.join("ao.png"), loaded.size, &ao)?;
    outln!(
        "AO of {} ({}x{}, normals {}) with {} (radius {}): wrote ao.exr, ao.png to {}",
        args.depth.display(),
        loaded.size[0],
        loaded.size[1],
        match (settings.normals.source, loaded.normals.is_some()) {
            (NormalSource::Buffer, true) => format!(
                "from file, uploaded as {}",
                settings.normals.encoding.name()
            ),
            (NormalSource::Buffer, false) => "reconstructed from depth".to_string(),
            (source, _) => format!("reconstructed from depth, {}", source.name()),
        },
        settings.method.name(),
        settings.radius,
        args.out.display()
    );
    let depth_for_summary: Vec<f32> = loaded
        .linear_depth
        .iter()
        .map(|&d| if d > 0.0 && d.is_finite() { d } else { 0.0 })
        .collect();
    outln!("{}", ao_summary(&ao, &depth_for_summary));
    Ok(())
}
