//! The G-buffer export shared by `render --gbuffer` and `reference`: depth.exr, normal.exr and
//! camera.json, the format docs/camera-json.md describes, and back_depth.exr where the back
//! faces were drawn.

use std::path::Path;

use anyhow::{Context, Result, bail};
use aokit_eval::write_exr;
use aokit_scene::CameraFile;
use glam::Vec3;

/// Writes the three files into `out` and returns their names: depth.exr, normal.exr and
/// camera.json, each name with `suffix` before its extension (`-007` for a sequence's frame).
/// The images are `size`: `camera`'s, or with its [`CameraFile::guard_band`] the overscan.
pub fn write_gbuffer(
    out: &Path,
    suffix: &str,
    size: [u32; 2],
    linear_depth: &[f32],
    normals: &[Vec3],
    camera: &CameraFile,
) -> Result<[String; 3]> {
    let names = [
        format!("depth{suffix}.exr"),
        format!("normal{suffix}.exr"),
        format!("camera{suffix}.json"),
    ];
    write_exr(&out.join(&names[0]), size, &[("Z", linear_depth.to_vec())])?;
    let channel = |i: usize| normals.iter().map(|n| n[i]).collect::<Vec<f32>>();
    write_exr(
        &out.join(&names[1]),
        size,
        &[("R", channel(0)), ("G", channel(1)), ("B", channel(2))],
    )?;
    write_json(&out.join(&names[2]), camera)?;
    Ok(names)
}

/// Writes the back faces' linear depth into `out` as back_depth.exr (one channel `Z`, as
/// depth.exr; `suffix` as for [`write_gbuffer`]), which `aokit ao --back-depth` reads; returns
/// its name.
pub fn write_back_depth(
    out: &Path,
    suffix: &str,
    size: [u32; 2],
    back_depth: &[f32],
) -> Result<String> {
    let name = format!("back_depth{suffix}.exr");
    write_exr(&out.join(&name), size, &[("Z", back_depth.to_vec())])?;
    Ok(name)
}

/// Pretty JSON with a trailing newline.
pub fn write_json(path: &Path, value: &impl serde::Serialize) -> Result<()> {
    std::fs::write(path, serde_json::to_string_pretty(value)? + "\n")
        .with_context(|| format!("cannot write {}", path.display()))
}

/// Checks that `dir` (`--out`) is, or can become, a directory: run before any work, so that a
/// file in its place fails at once rather than after a trace or a search of minutes.
pub fn check_out_dir(dir: &Path) -> Result<()> {
    // The nearest part of the path that exists must be a directory.
    let existing = dir.ancestors().find(|p| p.exists());
    if let Some(existing) = existing
        && !existing.is_dir()
    {
        if existing == dir {
            bail!(
                "--out {}: a file of that name exists; the output must be a directory",
                dir.display()
            );
        }
        bail!(
            "--out {}: {} is a file, so the output directory cannot be made under it",
            dir.display(),
            existing.display()
        );
    }
    Ok(())
}

/// Creates `dir` and its parents, naming it on failure.
pub fn create_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))
}
