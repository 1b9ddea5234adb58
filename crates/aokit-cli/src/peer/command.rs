//! `aokit peer compile`: a peer's SPIR-V and manifest in a folder, for `--peer NAME=FOLDER` on
//! machines without glslangValidator.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::{Args, Subcommand};

use super::PeerSpec;
use super::compile::{Entry, Prepared, wrapper_digest};
use super::source::{MANIFEST, Manifest, Origin, locate};

#[derive(Args, Debug)]
pub struct PeerArgs {
    #[command(subcommand)]
    command: PeerCommand,
}

#[derive(Subcommand, Debug)]
enum PeerCommand {
    /// Compile a peer's shaders (every quality level) to SPIR-V in --out, with a manifest;
    /// `--peer NAME=OUT` then runs them without the compiler.
    Compile {
        /// NAME=DIR: the peer and its checkout (or the folder of its shader files).
        #[arg(value_name = "NAME=DIR")]
        spec: PeerSpec,
        /// Folder to write the modules and aokit-peer.json to.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
}

/// Runs `aokit peer` (its one subcommand, `compile`).
pub fn run(args: &PeerArgs) -> Result<()> {
    let PeerCommand::Compile { spec, out } = &args.command;
    let Origin::Sources(sources) = locate(spec)? else {
        bail!(
            "{} already holds compiled shaders; give the checkout",
            spec.dir.display()
        );
    };
    let prepared = Prepared::new(&sources)?;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let mut modules = Vec::new();
    for entry in Entry::all() {
        let words = prepared.compile(entry)?;
        let path = out.join(entry.file_name());
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        std::fs::write(&path, bytes).with_context(|| format!("cannot write {}", path.display()))?;
        modules.push(entry.file_name());
    }
    let manifest = Manifest {
        peer: spec.name.clone(),
        wrapper: wrapper_digest(),
        compiler: prepared.compiler_version.clone(),
        sources: sources.display().to_string(),
        modules,
    };
    let path = out.join(MANIFEST);
    std::fs::write(&path, serde_json::to_string_pretty(&manifest)? + "\n")
        .with_context(|| format!("cannot write {}", path.display()))?;
    outln!(
        "compiled {} modules of {} from {} with {} into {}",
        manifest.modules.len(),
        spec.name,
        sources.display(),
        manifest.compiler,
        out.display()
    );
    Ok(())
}
