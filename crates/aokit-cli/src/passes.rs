//! G-buffer passes read from files: depth, optional normals and back-face depth, and
//! camera.json.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use aokit::{NormalSpace, Projection};
use aokit_eval::{read_depth, read_normals};
use aokit_scene::CameraFile;
pub use aokit_scene::external::DepthKind;
use aokit_scene::external::{linear_depth, view_normals};
use glam::{Mat4, Vec3};

use crate::suspicious;

/// `--depth-kind`: the names [`DepthKind`] takes, listed in `--help`.
pub fn depth_kind_parser() -> impl clap::builder::TypedValueParser<Value = DepthKind> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(DepthKind::ALL.map(DepthKind::name))
        .map(|name| name.parse().expect("one of DepthKind::ALL's names"))
}

/// Passes ready for the AO pipeline.
#[derive(Clone)]
pub struct LoadedPasses {
    /// The images' size: the output's and the guard band on each side.
    pub size: [u32; 2],
    /// The camera's projection, the inner frame's.
    pub projection: Projection,
    /// Pixels of overscan on each side of the images.
    pub guard_band: u32,
    /// The camera's world-to-view transform.
    pub view_from_world: Mat4,
    /// Linear view depth; non-positive or non-finite where there is no surface.
    pub linear_depth: Vec<f32>,
    /// View-space normals, when a normal file was given.
    pub normals: Option<Vec<Vec3>>,
    /// Linear view depth of the back faces, when a back-face depth file was given.
    pub back_depth: Option<Vec<f32>>,
}

impl LoadedPasses {
    /// The AO's size: the images' less the guard band on each side.
    pub fn output_size(&self) -> [u32; 2] {
        self.size.map(|side| side - 2 * self.guard_band)
    }

    /// The linear depth of the output's pixels, the band cut off.
    pub fn output_depth(&self) -> Vec<f32> {
        self.crop_to_output(&self.linear_depth)
    }

    /// The output's pixels of an image the size of the passes: the band cut off.
    pub fn crop_to_output<T: Copy>(&self, image: &[T]) -> Vec<T> {
        let [width, _] = self.size;
        let [inner_width, inner_height] = self.output_size();
        let band = self.guard_band as usize;
        (0..inner_height as usize)
            .flat_map(|y| {
                let row = (y + band) * width as usize + band;
                image[row..row + inner_width as usize].iter().copied()
            })
            .collect()
    }

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

/// Prints a warning about the inputs, when there is one.
fn warn(warning: Option<String>) {
    if let Some(warning) = warning {
        eprintln!("warning: {warning}");
    }
}

/// Reads the passes of `files`; `guard_band`, when given, overrides the band camera.json
/// records (0 when it records none).
pub fn load(
    files: &PassFiles<'_>,
    depth_kind: DepthKind,
    normal_space: NormalSpace,
    guard_band: Option<u32>,
) -> Result<LoadedPasses> {
    let PassFiles {
        depth: depth_path,
        normals: normals_path,
        back_depth: back_depth_path,
        camera: camera_path,
    } = *files;
    let camera = read_camera(camera_path)?;
    let (projection, view_from_world) = camera
        .checked()
        .map_err(|e| anyhow!("{}: {e}", camera_path.display()))?;
    // World-space normals are turned by the rotation part: a degenerate one (a camera.json
    // written by hand) is refused before any image is read.
    if normals_path.is_some() {
        view_normals(Vec::new(), normal_space, view_from_world)
            .map_err(|e| anyhow!("{}: {e} (--normal-space world)", camera_path.display()))?;
    }
    let band = guard_band.unwrap_or(camera.guard_band);
    let size =
        [camera.width, camera.height].map(|side| side.saturating_add(band.saturating_mul(2)));
    // The images were drawn through the frustum widened by the band.
    let camera_projection = projection;
    let projection = projection.with_guard_band([camera.width, camera.height], band);
    let read_linear = |path: &Path| -> Result<Vec<f32>> {
        let depth = read_depth(path)?;
        if [depth.width, depth.height] != size {
            let with_band = match band {
                0 => String::new(),
                _ => format!(" with a guard band of {band} px on each side"),
            };
            bail!(
                "{} is {}x{} but {} describes {}x{}{with_band}",
                path.display(),
                depth.width,
                depth.height,
                camera_path.display(),
                size[0],
                size[1]
            );
        }
        // A colour image's values look like anything: say the likelier mistake only.
        let colour = suspicious::depth_is_a_colour_image(path, &depth.data);
        let ndc = (colour.is_none() && depth_kind == DepthKind::Linear)
            .then(|| suspicious::linear_depth_looks_like_ndc(path, &depth.data, &projection))
            .flatten();
        warn(colour.or(ndc));
        linear_depth(depth.data, depth_kind, &projection, size[0])
            .map_err(|e| anyhow!("{}: {e}", path.display()))
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
            let normals = image
                .data
                .chunks_exact(3)
                .map(|n| Vec3::new(n[0], n[1], n[2]))
                .collect();
            let normals = view_normals(normals, normal_space, view_from_world)
                .map_err(|e| anyhow!("{}: {e}", camera_path.display()))?;
            warn(suspicious::normals_face_away(
                path,
                &normals,
                &linear_depth,
                &projection,
                size,
                normal_space,
            ));
            Ok(normals)
        })
        .transpose()?;
    Ok(LoadedPasses {
        size,
        projection: camera_projection,
        guard_band: band,
        view_from_world,
        linear_depth,
        normals,
        back_depth,
    })
}
