//! G-buffer passes read from files: depth, optional normals and back-face depth, and
//! camera.json.

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
    /// Linear view depth of the back faces, when a back-face depth file was given.
    pub back_depth: Option<Vec<f32>>,
}

impl LoadedPasses {
    pub fn passes(&self) -> aokit_scene::external::Passes<'_> {
        aokit_scene::external::Passes {
            size: self.size,
            linear_depth: &self.linear_depth,
            normals: self.normals.as_deref(),
            back_depth: self.back_depth.as_deref(),
            projection: self.projection,
        }
    }
}

pub fn read_camera(path: &Path) -> Result<CameraFile> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| anyhow!("{} is not a camera.json: {e}", path.display()))
}

/// The files `aokit ao` reads: depth, optional normals and back-face depth, and camera.json.
pub struct PassFiles<'a> {
    pub depth: &'a Path,
    pub normals: Option<&'a Path>,
    pub back_depth: Option<&'a Path>,
    pub camera: &'a Path,
}

pub fn load(
    files: &PassFiles<'_>,
    depth_kind: DepthKind,
    normal_space: NormalSpace,
) -> Result<LoadedPasses> {
    let PassFiles {
        depth: depth_path,
        normals: normals_path,
        back_depth: back_depth_path,
        camera: camera_path,
    } = *files;
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
    // World-space normals are turned by the rotation part: a zero or degenerate one (a
    // camera.json written by hand) would turn every normal into zero, which decodes to a normal
    // facing the camera and darkens the AO without a word.
    if normal_space == NormalSpace::World && normals_path.is_some() {
        let rotation = glam::Mat3::from_mat4(view_from_world);
        let determinant = rotation.determinant();
        if !(determinant.is_finite() && determinant.abs() > 1e-6) {
            bail!(
                "{}: view_from_world's 3x3 part has determinant {determinant}, not a rotation; \
                 world-space normals (--normal-space world) cannot be turned into view space \
                 with it",
                camera_path.display()
            );
        }
    }
    let size = [camera.width, camera.height];
    let read_linear = |path: &Path| -> Result<Vec<f32>> {
        let depth = read_depth(path)?;
        if [depth.width, depth.height] != size {
            bail!(
                "{} is {}x{} but {} describes {}x{}",
                path.display(),
                depth.width,
                depth.height,
                camera_path.display(),
                size[0],
                size[1]
            );
        }
        Ok(match depth_kind {
            DepthKind::Linear => depth.data,
            DepthKind::Ndc => {
                // Depth-buffer values lie in [0, 1]; others (linear depth given by mistake)
                // would map to plausible but wrong distances. Non-finite values stay background.
                let outside = |d: &f32| d.is_finite() && !(0.0..=1.0).contains(d);
                let bad = depth.data.iter().filter(|d| outside(d)).count();
                if bad > 0 {
                    let (i, example) = depth
                        .data
                        .iter()
                        .enumerate()
                        .find(|(_, d)| outside(d))
                        .expect("counted above");
                    bail!(
                        "{}: {bad} of {} pixels hold depth outside [0, 1] (e.g. {example} at \
                         x {}, y {}), which --depth-kind ndc needs; is it linear depth \
                         (--depth-kind linear)?",
                        path.display(),
                        depth.data.len(),
                        i % size[0] as usize,
                        i / size[0] as usize
                    );
                }
                depth
                    .data
                    .iter()
                    .map(|&d| projection.surface_depth(d))
                    .collect()
            }
        })
    };
    let linear_depth = read_linear(depth_path)?;
    let back_depth = back_depth_path.map(read_linear).transpose()?;
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
        back_depth,
    })
}
