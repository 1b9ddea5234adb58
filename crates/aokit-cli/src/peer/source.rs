//! Where a peer's shaders come from: the user's XeGTAO sources, compiled at run time, or the
//! SPIR-V and manifest `aokit peer compile` wrote, for machines without glslangValidator.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::{Deserialize, Serialize};

use super::compile::{Entry, Prepared, SOURCE_FILES, wrapper_digest};
use super::{PeerSpec, Quality};

/// The manifest of a compiled folder.
pub const MANIFEST: &str = "aokit-peer.json";
/// Where a checkout of XeGTAO keeps its shaders.
const CHECKOUT_SHADERS: &str = "Source/Rendering/Shaders";

/// What `aokit peer compile` records beside the modules.
#[derive(Serialize, Deserialize)]
pub struct Manifest {
    /// The peer's name, as `--peer` gives it.
    pub peer: String,
    /// [`wrapper_digest`] of the wrapper compiled: the modules fit its bindings only.
    pub wrapper: String,
    /// The compiler's version line.
    pub compiler: String,
    /// The folder of XeGTAO.h and XeGTAO.hlsli compiled.
    pub sources: String,
    /// The module files, as [`Entry::file_name`] names them.
    pub modules: Vec<String>,
}

/// A `--peer` folder's contents.
pub enum Origin {
    /// The folder holding XeGTAO.h and XeGTAO.hlsli.
    Sources(PathBuf),
    /// A folder `aokit peer compile` wrote.
    Compiled(PathBuf),
}

/// What `spec.dir` holds: a compiled folder, a checkout, or its shader folder; else an error
/// naming what is missing.
pub fn locate(spec: &PeerSpec) -> Result<Origin> {
    let dir = &spec.dir;
    if !dir.is_dir() {
        bail!(
            "--peer {}={}: no such folder (give a checkout of XeGTAO, the folder of its \
             XeGTAO.h and XeGTAO.hlsli, or a folder `aokit peer compile` wrote)",
            spec.name,
            dir.display()
        );
    }
    if dir.join(MANIFEST).is_file() {
        return Ok(Origin::Compiled(dir.clone()));
    }
    let candidates = [dir.clone(), dir.join(CHECKOUT_SHADERS)];
    if let Some(found) = candidates
        .iter()
        .find(|c| SOURCE_FILES.iter().all(|f| c.join(f).is_file()))
    {
        return Ok(Origin::Sources(found.clone()));
    }
    // The folder that holds some of the files, or the checkout's shader folder, names what
    // it lacks.
    let closest = candidates
        .iter()
        .find(|c| SOURCE_FILES.iter().any(|f| c.join(f).is_file()))
        .unwrap_or(&candidates[1]);
    let missing: Vec<String> = SOURCE_FILES
        .iter()
        .map(|f| closest.join(f))
        .filter(|p| !p.is_file())
        .map(|p| p.display().to_string())
        .collect();
    bail!(
        "--peer {}={}: missing {} (nor is there a {MANIFEST} of `aokit peer compile`)",
        spec.name,
        dir.display(),
        missing.join(" and ")
    )
}

/// The four modules one configuration runs.
pub struct Shaders {
    /// The depth prefilter.
    pub prefilter: Vec<u32>,
    /// The main pass at the quality level.
    pub main: Vec<u32>,
    /// A denoiser pass before the last.
    pub denoise: Vec<u32>,
    /// The last denoiser pass, which writes the final term.
    pub denoise_last: Vec<u32>,
}

impl Shaders {
    /// The modules for `quality`: read from a compiled folder, or compiled now.
    pub fn load(spec: &PeerSpec, quality: Quality) -> Result<Self> {
        let entries = [
            Entry::Prefilter,
            Entry::Main(quality),
            Entry::Denoise,
            Entry::DenoiseLast,
        ];
        let context = || format!("--peer {}={}", spec.name, spec.dir.display());
        let mut modules = match locate(spec)? {
            Origin::Sources(dir) => {
                let prepared = Prepared::new(&dir).with_context(context)?;
                entries
                    .iter()
                    .map(|&e| prepared.compile(e))
                    .collect::<Result<Vec<_>>>()
                    .with_context(context)?
            }
            Origin::Compiled(dir) => {
                check_manifest(&dir, &spec.name).with_context(context)?;
                entries
                    .iter()
                    .map(|e| read_module(&dir.join(e.file_name())))
                    .collect::<Result<Vec<_>>>()
                    .with_context(context)?
            }
        }
        .into_iter();
        let mut next = || modules.next().expect("one module per entry");
        Ok(Self {
            prefilter: next(),
            main: next(),
            denoise: next(),
            denoise_last: next(),
        })
    }
}

fn check_manifest(dir: &Path, peer: &str) -> Result<()> {
    let path = dir.join(MANIFEST);
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let manifest: Manifest = serde_json::from_str(&text).with_context(|| {
        format!(
            "{} is not a manifest of `aokit peer compile`",
            path.display()
        )
    })?;
    if manifest.peer != peer {
        bail!("{} holds the peer `{}`", path.display(), manifest.peer);
    }
    if manifest.wrapper != wrapper_digest() {
        bail!(
            "{} was compiled from another version of aokit's XeGTAO wrapper, whose bindings \
             need not match this aokit's: compile it again with this aokit's `aokit peer \
             compile`",
            dir.display()
        );
    }
    Ok(())
}

fn read_module(path: &Path) -> Result<Vec<u32>> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    super::spirv::words(&bytes).with_context(|| path.display().to_string())
}
