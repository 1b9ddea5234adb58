//! G-buffer passes read from files: depth, optional normals and camera.json.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use aokit::{NormalSpace, Projection};
use aokit_eval::{read_depth, read_normals};
use aokit_scene::CameraFile;
use clap::ValueEnum;
use glam::Vec3;

/// What the depth file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DepthKind {
    /// Positive distance along the view axis.
    Linear,
    /// Depth-buffer values in [0, 1], in the convention camera.json names.
    Ndc,
}

/// Passes ready for the AO pipeline.
pub struct LoadedPasses {
    pub size: [u32; 2],
    pub projection: Projection,
    /// Linear view depth; non-positive or non-finite where there is no surface.
    pub linear_depth: Vec<f32>,
    /// View-space normals, when a normal file was given.
    pub normals: Option<Vec<Vec3>>,
}

impl LoadedPasses {
    pub fn passes(&self) -> aokit_scene::external::Passes<'_> {
        aokit_scene::external::Passes {
            size: self.size,
            linear_depth: &self.linear_depth,
            normals: self.normals.as_deref(),
            projection: self.projection,
        }
    }
}

pub fn read_camera(path: &Path) -> Result<CameraFile> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| anyhow!("{} is not a camera.json: {e}", path.display()))
}

pub fn load(
    depth_path: &Path,
    normals_path: Option<&Path>,
    camera_path: &Path,
    depth_kind: DepthKind,
    normal_space: NormalSpace,
) -> Result<LoadedPasses> {
    let camera = read_camera(camera_path)?;
    let projection = camera
        .projection()
        .map_err(|e| anyhow!("{}: {e}", camera_path.display()))?;
    let view_from_world = camera.view_from_world();
    if !view_from_world.is_finite() {
        bail!(
            "{}: view_from_world has non-finite entries",
            camera_path.display()
        );
    }
    let size = [camera.width, camera.height];
    let depth = read_depth(depth_path)?;
    if [depth.width, depth.height] != size {
        bail!(
            "{} is {}x{} but {} describes {}x{}",
            depth_path.display(),
            depth.width,
            depth.height,
            camera_path.display(),
            size[0],
            size[1]
        );
    }
    let linear_depth = match depth_kind {
        DepthKind::Linear => depth.data,
        DepthKind::Ndc => depth
            .data
            .iter()
            .map(|&d| {
                if d == projection.far_ndc_depth() {
                    0.0
                } else {
                    projection.linear_depth(d)
                }
            })
            .collect(),
    };
    let normals = normals_path
        .map(|path| -> Result<Vec<Vec3>> {
            let image = read_normals(path)?;
            if [image.width, image.height] != size {
                bail!(
                    "{} is {}x{} but the depth is {}x{}",
                    path.display(),
                    image.width,
                    image.height,
                    size[0],
                    size[1]
                );
            }
            Ok(image
                .data
                .chunks_exact(3)
                .map(|n| {
                    let n = Vec3::new(n[0], n[1], n[2]);
                    match normal_space {
                        NormalSpace::View => n,
                        NormalSpace::World => view_from_world.transform_vector3(n),
                    }
                })
                .collect())
        })
        .transpose()?;
    Ok(LoadedPasses {
        size,
        projection,
        linear_depth,
        normals,
    })
}
