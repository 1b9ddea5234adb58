//! Ground truth and scores: the CPU reference tracer, `aokit compare`'s metrics, and the
//! image files `aokit ao` reads and writes.

use std::path::PathBuf;

use aokit_eval::{compare, read_depth, read_normals, write_exr as write_exr_file};
use aokit_reference::{AoOptions, Falloff, Tracer};
use aokit_scene::reference::pixel_camera_for;
use glam::Vec3;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyDict};

use crate::arrays::{f32_values, to_bytearray};
use crate::camera::Camera;

/// Traces `camera`'s view of the triangles (`vertices`: float32 bytes, 3 per vertex;
/// `indices`: uint32 bytes, 3 per triangle) on every core with the GIL released. Returns the
/// AO, linear depth and view-space normals as float32 bytearrays.
#[pyfunction]
#[pyo3(signature = (vertices, indices, camera, radius, spp, seed = 0, falloff = "none"))]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
pub fn reference<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyBytes>,
    indices: &Bound<'py, PyBytes>,
    camera: PyRef<'py, Camera>,
    radius: f32,
    spp: u32,
    seed: u64,
    falloff: &str,
) -> PyResult<(
    Bound<'py, PyByteArray>,
    Bound<'py, PyByteArray>,
    Bound<'py, PyByteArray>,
)> {
    let falloff: Falloff = falloff
        .parse()
        .map_err(|e: aokit_reference::ReferenceError| {
            PyValueError::new_err(format!("falloff: {e}"))
        })?;
    let vertex_bytes = vertices.as_bytes();
    if vertex_bytes.len() % 12 != 0 {
        return Err(PyValueError::new_err(
            "vertices: expected N x 3 float32 values",
        ));
    }
    let positions: Vec<Vec3> = f32_values(vertex_bytes, vertex_bytes.len() / 4, "vertices")?
        .chunks_exact(3)
        .map(Vec3::from_slice)
        .collect();
    let index_bytes = indices.as_bytes();
    if index_bytes.len() % 12 != 0 {
        return Err(PyValueError::new_err(
            "indices: expected M x 3 uint32 values",
        ));
    }
    let indices: Vec<u32> = bytemuck::pod_collect_to_vec(index_bytes);
    let options = AoOptions {
        radius,
        spp,
        seed,
        falloff,
    };
    let pixel_camera = pixel_camera_for(&camera.projection, camera.view_from_world, camera.size());
    let image = py
        .detach(|| Tracer::new(&positions, &indices)?.render(&pixel_camera, &options, &|_| {}))
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let normals: Vec<f32> = image.normals.iter().flat_map(|n| n.to_array()).collect();
    Ok((
        to_bytearray(py, &image.ao),
        to_bytearray(py, &image.linear_depth),
        to_bytearray(py, &normals),
    ))
}

/// Scores `ao` against `reference` (float32 bytes of `width * height` values) over `mask`
/// (one byte per pixel, nonzero = scored; all pixels when None), as `aokit compare` does.
#[pyfunction]
#[pyo3(signature = (width, height, ao, reference, mask = None))]
pub fn metrics<'py>(
    py: Python<'py>,
    width: u32,
    height: u32,
    ao: &Bound<'py, PyBytes>,
    reference: &Bound<'py, PyBytes>,
    mask: Option<&Bound<'py, PyBytes>>,
) -> PyResult<Bound<'py, PyDict>> {
    let pixels = width as usize * height as usize;
    let ao = f32_values(ao.as_bytes(), pixels, "ao")?;
    let reference = f32_values(reference.as_bytes(), pixels, "reference")?;
    let mask: Vec<bool> = match mask {
        Some(mask) => mask.as_bytes().iter().map(|&m| m != 0).collect(),
        None => vec![true; pixels],
    };
    if mask.len() != pixels {
        return Err(PyValueError::new_err("mask: not one value per pixel"));
    }
    let m = py.detach(|| compare([width, height], &ao, &reference, &mask));
    let out = PyDict::new(py);
    out.set_item("pixels", m.pixels)?;
    out.set_item("rmse", m.rmse)?;
    out.set_item("mae", m.mae)?;
    out.set_item("bias", m.bias)?;
    out.set_item("psnr", m.psnr)?;
    out.set_item("ssim", m.ssim)?;
    Ok(out)
}

/// Reads a depth (`channels=1`) or normal (`channels=3`) pass from EXR, PFM or NPY as `aokit
/// ao` reads it. Returns `(float32 bytearray, width, height)`.
#[pyfunction]
pub fn read_image(
    py: Python<'_>,
    path: PathBuf,
    channels: u32,
) -> PyResult<(Bound<'_, PyByteArray>, u32, u32)> {
    let image = py
        .detach(|| match channels {
            1 => read_depth(&path),
            _ => read_normals(&path),
        })
        .map_err(|e| PyOSError::new_err(e.to_string()))?;
    Ok((to_bytearray(py, &image.data), image.width, image.height))
}

/// Writes one float32 channel (`Y` for AO, as `aokit ao` writes ao.exr) to an EXR file.
#[pyfunction]
#[pyo3(signature = (path, width, height, values, channel = "Y"))]
pub fn write_exr(
    py: Python<'_>,
    path: PathBuf,
    width: u32,
    height: u32,
    values: &Bound<'_, PyBytes>,
    channel: &str,
) -> PyResult<()> {
    let values = f32_values(values.as_bytes(), width as usize * height as usize, "image")?;
    py.detach(|| write_exr_file(&path, [width, height], &[(channel, values)]))
        .map_err(|e| PyOSError::new_err(e.to_string()))
}
