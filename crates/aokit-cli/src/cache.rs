//! Reference images cached on disk, keyed by everything that changes them.
//!
//! An entry is a directory laid out exactly like `aokit reference --out` writes it, so a cached
//! reference can also be handed to `aokit compare --inputs`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use aokit_eval::{
    FloatImage, read_depth, read_normals, read_scalar_exr, write_exr, write_grey_png,
};
use aokit_reference::{AoOptions, ReferenceImage};
use aokit_scene::{Camera, CameraFile, Lens, Scene};
use glam::Vec3;

use crate::export::{create_dir, write_gbuffer, write_json};
use crate::reference::{ReferenceInfo, trace};

/// Bump when the tracer's output changes for the same inputs, so old entries are not reused.
const TRACER_VERSION: u32 = 2;

/// The cache directory: `--cache`, else `$AOKIT_CACHE`, else `$XDG_CACHE_HOME/aokit`, else
/// `~/.cache/aokit`.
pub fn default_dir() -> PathBuf {
    let env = |name| {
        std::env::var_os(name)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    env("AOKIT_CACHE")
        .or_else(|| env("XDG_CACHE_HOME").map(|d| d.join("aokit")))
        .or_else(|| env("HOME").map(|d| d.join(".cache").join("aokit")))
        .unwrap_or_else(|| PathBuf::from("aokit-cache"))
}

/// FNV-1a, 64 bits: stable across Rust versions and platforms, unlike `DefaultHasher`.
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    fn floats(&mut self, values: &[f32]) {
        for v in values {
            self.bytes(&v.to_le_bytes());
        }
    }
}

fn key(scene: &Scene, camera: &Camera, size: [u32; 2], options: &AoOptions) -> String {
    let mut hash = Fnv::new();
    hash.bytes(&TRACER_VERSION.to_le_bytes());
    for p in &scene.mesh.positions {
        hash.floats(&p.to_array());
    }
    for i in &scene.mesh.indices {
        hash.bytes(&i.to_le_bytes());
    }
    for v in [camera.eye, camera.target, camera.up] {
        hash.floats(&v.to_array());
    }
    match camera.lens {
        Lens::Perspective { fov_y_deg } => hash.floats(&[0.0, fov_y_deg]),
        Lens::Orthographic { height } => hash.floats(&[1.0, height]),
    }
    let name = |s: &str| -> String {
        s.chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect()
    };
    format!(
        "{}-{}-{}x{}-r{}-spp{}-seed{}-{}-{:016x}",
        name(&scene.name),
        name(&camera.name),
        size[0],
        size[1],
        options.radius,
        options.spp,
        options.seed,
        options.falloff.name(),
        hash.0
    )
}

/// A reference read back from a directory in `aokit reference` layout.
pub fn read_reference_dir(dir: &Path) -> Result<ReferenceImage> {
    let ao: FloatImage = read_scalar_exr(&dir.join("reference.exr"))?;
    let depth = read_depth(&dir.join("depth.exr"))?;
    let normals = read_normals(&dir.join("normal.exr"))?;
    Ok(ReferenceImage {
        size: [ao.width, ao.height],
        ao: ao.data,
        linear_depth: depth.data,
        normals: normals
            .data
            .chunks_exact(3)
            .map(|n| Vec3::new(n[0], n[1], n[2]))
            .collect(),
    })
}

/// The reference for this view, from the cache or traced now and stored.
pub fn reference(
    cache: &Path,
    scene: &Scene,
    camera: &Camera,
    size: [u32; 2],
    options: &AoOptions,
) -> Result<ReferenceImage> {
    let dir = cache
        .join("references")
        .join(key(scene, camera, size, options));
    if dir.join("reference.json").is_file() {
        eprintln!("reference: {} (cached)", dir.display());
        return read_reference_dir(&dir)
            .with_context(|| format!("cached reference {}", dir.display()));
    }
    let image = trace(scene, camera, size, options)?;
    create_dir(&dir)?;
    write_exr(&dir.join("reference.exr"), size, &[("Y", image.ao.clone())])?;
    write_grey_png(&dir.join("reference.png"), size, &image.ao)?;
    let projection = camera.projection(size[0] as f32 / size[1] as f32, &scene.bounds);
    write_gbuffer(
        &dir,
        "",
        size,
        &image.linear_depth,
        &image.normals,
        &CameraFile::new(&projection, camera.view_from_world(), size),
    )?;
    // Written last: its presence marks a complete entry.
    write_json(
        &dir.join("reference.json"),
        &ReferenceInfo::new(scene, camera, size, options),
    )?;
    eprintln!("reference: {} (traced, cached)", dir.display());
    Ok(image)
}
