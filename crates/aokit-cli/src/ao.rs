//! `aokit ao`: AO for passes exported by another renderer.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use aokit::{AoSettings, NormalSource, NormalSpace};
use aokit_eval::{write_exr, write_grey_png};
use aokit_scene::external::ExternalAo;
use clap::Args;

use crate::export::{check_out_dir, create_dir};
use crate::passes::{self, DepthKind, LoadedPasses, PassFiles};
use crate::recorded::{self, Recorded};
use crate::render::{ao_summary, open_gpu};
use crate::settings_args::SettingsArgs;

#[derive(Args, Debug)]
#[command(mut_arg("radius", |arg| arg.help(
    "AO radius in world units (default: the one recorded in ao-settings.json, else 1)"
)))]
pub struct AoArgs {
    /// Depth image: EXR, PFM or NPY (float32; H x W; background 0, +inf or NaN).
    #[arg(long, value_name = "FILE", required_unless_present = "sequence")]
    pub depth: Option<PathBuf>,
    /// Normal image: EXR, PFM or NPY (H x W x 3). Without it normals are reconstructed from depth.
    #[arg(long, value_name = "FILE", conflicts_with = "sequence")]
    pub normals: Option<PathBuf>,
    /// Depth of the nearest back faces (the scene drawn with front faces culled), in the
    /// format and kind of --depth, for `--set vbao.back_faces=true`.
    #[arg(long, value_name = "FILE", conflicts_with = "sequence")]
    pub back_depth: Option<PathBuf>,
    /// The camera, in the camera.json format `render --gbuffer` writes. An ao-settings.json
    /// beside it (as `render --gbuffer` writes) gives the settings, under the flags below.
    #[arg(
        long,
        value_name = "camera.json",
        alias = "camera",
        required_unless_present = "sequence"
    )]
    pub camera_json: Option<PathBuf>,
    /// A sequence of frames instead of --depth, --normals, --back-depth and --camera-json: a
    /// directory of depth-NNN.exr and camera-NNN.json, with normal-NNN.exr and
    /// back_depth-NNN.exr where there are (what `render --frames N --gbuffer` writes into
    /// frames/), or a pattern of the depth files with one `*` for the frame number
    /// (`'shot/depth.*.exr'`), whose other files are named with `depth` replaced by `camera`
    /// (and the extension by .json), `normal` and `back_depth`. The temporal filter, when on,
    /// accumulates over them.
    #[arg(long, value_name = "DIR|PATTERN", conflicts_with_all = ["depth", "camera_json"])]
    pub sequence: Option<PathBuf>,
    /// Whether the depth is linear view depth or depth-buffer values.
    #[arg(long, value_parser = passes::depth_kind_parser(), default_value = "linear")]
    pub depth_kind: DepthKind,
    /// Whether the normals are in view or world space (camera.json's `view_from_world` turns
    /// world-space ones); the same as `--set normals.space=SPACE`, which wins when both are
    /// given (default: view).
    #[arg(long, value_parser = parse_normal_space)]
    pub normal_space: Option<NormalSpace>,
    /// Pixels of overscan on each side of the depth, normals and back-face depth (a guard
    /// band): the images are this much larger each way than the camera's width and height, and
    /// the AO is written for the inner frame alone (default: the `guard_band` camera.json
    /// records, which `render --gbuffer --guard-band` writes, else 0).
    #[arg(long, value_name = "PX")]
    pub guard_band: Option<u32>,
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "aokit-out")]
    pub out: PathBuf,
}

fn parse_normal_space(s: &str) -> Result<NormalSpace, String> {
    s.parse()
}

/// The files of one frame.
struct FrameFiles {
    depth: PathBuf,
    normals: Option<PathBuf>,
    back_depth: Option<PathBuf>,
    camera: PathBuf,
}

impl FrameFiles {
    fn pass_files(&self) -> PassFiles<'_> {
        PassFiles {
            depth: &self.depth,
            normals: self.normals.as_deref(),
            back_depth: self.back_depth.as_deref(),
            camera: &self.camera,
        }
    }
}

pub fn run(args: &AoArgs) -> Result<()> {
    check_out_dir(&args.out)?;
    let frames = match &args.sequence {
        Some(dir) => sequence_files(dir)?,
        None => vec![FrameFiles {
            depth: args.depth.clone().expect("clap requires --depth"),
            normals: args.normals.clone(),
            back_depth: args.back_depth.clone(),
            camera: args
                .camera_json
                .clone()
                .expect("clap requires --camera-json"),
        }],
    };
    let recorded = recorded::read_beside(&frames[0].camera)?;
    let mut settings = resolve_settings(args, recorded.as_ref())?;
    if args.sequence.is_none() && settings.temporal.enabled {
        eprintln!(
            "note: {}",
            crate::sequence::temporal_single_frame_note("--sequence DIR")
        );
    }
    let normal_space = settings.normals.space;
    let load = |files: &FrameFiles| {
        passes::load(
            &files.pass_files(),
            args.depth_kind,
            normal_space,
            args.guard_band,
        )
    };
    let first = load(&frames[0])?;
    // The normals were turned into view space as they were read.
    settings.normals.space = NormalSpace::View;
    let gpu = open_gpu()?;
    let mut external = ExternalAo::new(&gpu, &settings, &first.passes())?;
    create_dir(&args.out)?;
    let mut last = None;
    for (index, files) in frames.iter().enumerate() {
        let loaded = match index {
            0 => first.clone(),
            _ => load(files)?,
        };
        if loaded.size != first.size {
            bail!(
                "{} is {}x{} but the sequence's first frame is {}x{}",
                files.depth.display(),
                loaded.size[0],
                loaded.size[1],
                first.size[0],
                first.size[1]
            );
        }
        if index > 0 {
            external.set_passes(&gpu, &loaded.passes())?;
        }
        external.set_view_from_world(loaded.view_from_world);
        external.set_guard_band(loaded.guard_band);
        let ao = external.run(&gpu, index as u32)?;
        let size = loaded.output_size();
        if args.sequence.is_some() {
            let dir = args.out.join("frames");
            create_dir(&dir)?;
            write_exr(
                &dir.join(format!("ao-{index:03}.exr")),
                size,
                &[("Y", ao.clone())],
            )?;
            write_grey_png(&dir.join(format!("ao-{index:03}.png")), size, &ao)?;
        }
        last = Some((loaded, ao));
    }
    let (loaded, ao) = last.expect("at least one frame");
    let size = loaded.output_size();
    write_exr(&args.out.join("ao.exr"), size, &[("Y", ao.clone())])?;
    write_grey_png(&args.out.join("ao.png"), size, &ao)?;
    let what = match &args.sequence {
        Some(dir) => format!(
            "{} frames of {} ({}x{}",
            frames.len(),
            dir.display(),
            size[0],
            size[1]
        ),
        None => format!("{} ({}x{}", frames[0].depth.display(), size[0], size[1]),
    };
    outln!(
        "AO of {what}, normals {}) with {} (radius {}{}): wrote {}ao.exr, ao.png to {}",
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
        match &recorded {
            Some(recorded) => format!(", settings recorded in {}", recorded.path.display()),
            None => String::new(),
        },
        if args.sequence.is_some() {
            "frames/ao-NNN.exr and .png, the last frame as "
        } else {
            ""
        },
        args.out.display()
    );
    outln!("{}", summary(&loaded, &ao));
    Ok(())
}

/// The settings flags over the recorded settings when there are some.
fn resolve_settings(args: &AoArgs, recorded: Option<&Recorded>) -> Result<AoSettings> {
    // `--normal-space` is a setting like `--radius`: applied before `--set`, so that a
    // `--set normals.space=...` (documented as applied last) wins over it, and a settings file's
    // value stands when neither is given. A default on the flag would override both.
    let mut settings_args = args.settings.clone();
    if let Some(space) = args.normal_space {
        let set = &mut settings_args.overrides.set;
        set.insert(0, format!("normals.space={}", space.name()));
    }
    match recorded {
        Some(recorded) => settings_args.resolve_recorded(recorded),
        None => settings_args.resolve(None),
    }
}

/// [`ao_summary`] over the pixels the depth shows a surface at.
fn summary(loaded: &LoadedPasses, ao: &[f32]) -> String {
    let depth: Vec<f32> = loaded
        .output_depth()
        .iter()
        .map(|&d| if d > 0.0 && d.is_finite() { d } else { 0.0 })
        .collect();
    ao_summary(ao, &depth)
}

/// The frames `--sequence` names: a directory, or a pattern of depth files.
fn sequence_files(sequence: &Path) -> Result<Vec<FrameFiles>> {
    let shown = sequence.display();
    if sequence.is_dir() {
        // `render --frames N --gbuffer`'s frames/: the cameras number the frames.
        let names = SequenceNames {
            dir: sequence.to_path_buf(),
            template: "depth-*.exr".to_string(),
        };
        return names.frames(&shown.to_string(), "camera");
    }
    let name = sequence
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    if name.matches('*').count() != 1 || name.matches("depth").count() != 1 {
        bail!(
            "--sequence {shown}: neither a directory nor a pattern of depth files such as \
             `frames/depth-*.exr` (one `*` for the frame number and `depth` once in the file \
             name, which names the other passes)"
        );
    }
    let dir = match sequence.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if dir.to_string_lossy().contains('*') {
        bail!("--sequence {shown}: only the file name may hold a `*`");
    }
    let names = SequenceNames {
        dir,
        template: name,
    };
    names.frames(&shown.to_string(), "depth")
}

/// How one sequence names its files: `template` is the depth files' name in `dir`, with `*`
/// for the frame number; the other passes' names put their own in place of `depth`.
struct SequenceNames {
    dir: PathBuf,
    template: String,
}

impl SequenceNames {
    /// The name of `pass`'s file pattern: `depth` replaced, and a camera's extension .json.
    fn pattern(&self, pass: &str) -> String {
        let name = self.template.replacen("depth", pass, 1);
        if pass != "camera" {
            return name;
        }
        let stem = Path::new(&name).with_extension("json");
        stem.to_string_lossy().into_owned()
    }

    fn path(&self, pass: &str, number: &str) -> PathBuf {
        self.dir.join(self.pattern(pass).replacen('*', number, 1))
    }

    /// The frames, in the order of their numbers: each file of the `lead` pass (camera or
    /// depth) with the other one beside it, and normals and back-face depth where every frame
    /// has them. `shown` names the sequence in errors.
    fn frames(&self, shown: &str, lead: &str) -> Result<Vec<FrameFiles>> {
        let pattern = self.pattern(lead);
        let (before, after) = pattern.split_once('*').expect("one `*` in the template");
        let entries =
            std::fs::read_dir(&self.dir).map_err(|e| anyhow::anyhow!("--sequence {shown}: {e}"))?;
        let mut numbers = Vec::new();
        for entry in entries {
            let name = entry?.file_name();
            let name = name.to_string_lossy();
            if let Some(number) = name
                .strip_prefix(before)
                .and_then(|rest| rest.strip_suffix(after))
            {
                numbers.push(number.to_string());
            }
        }
        if numbers.is_empty() {
            bail!(
                "--sequence {shown}: no file matches {} in {} (`render --frames N --gbuffer` \
                 writes a sequence into its frames/)",
                pattern,
                self.dir.display()
            );
        }
        numbers.sort_by_key(|n| (n.len(), n.clone()));
        // A pass every frame has, else none; some frames with one is a broken sequence.
        let optional = |pass: &str| -> Result<Option<Vec<PathBuf>>> {
            let paths: Vec<PathBuf> = numbers.iter().map(|n| self.path(pass, n)).collect();
            match paths.iter().filter(|p| p.is_file()).count() {
                0 => Ok(None),
                count if count == paths.len() => Ok(Some(paths)),
                count => bail!(
                    "--sequence {shown}: {count} of the {} frames have a {}; give one for \
                     every frame or none",
                    paths.len(),
                    self.pattern(pass)
                ),
            }
        };
        let normals = optional("normal")?;
        let back_depth = optional("back_depth")?;
        let other = if lead == "camera" { "depth" } else { "camera" };
        let mut frames = Vec::with_capacity(numbers.len());
        for (i, n) in numbers.iter().enumerate() {
            let name = |pass| self.pattern(pass).replacen('*', n, 1);
            if !self.path(other, n).is_file() {
                bail!(
                    "--sequence {shown}: {} has no {} beside it",
                    name(lead),
                    name(other)
                );
            }
            frames.push(FrameFiles {
                depth: self.path("depth", n),
                normals: normals.as_ref().map(|paths| paths[i].clone()),
                back_depth: back_depth.as_ref().map(|paths| paths[i].clone()),
                camera: self.path("camera", n),
            });
        }
        Ok(frames)
    }
}
