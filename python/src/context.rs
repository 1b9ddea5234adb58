//! `aokit._aokit.Context`: one GPU device and one AO pipeline, reused by every call.

use aokit::settings::SettingValue;
use aokit::{AdapterKind, AoSettings, GpuContext, NormalSpace};
use aokit_scene::RenderError;
use aokit_scene::external::{DepthKind, ExternalAo, Passes, linear_depth, view_normals};
use glam::Vec3;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyDict};

use crate::arrays::{f32_values, to_bytearray};
use crate::camera::Camera;
use crate::settings::resolve;

/// A GPU device with the AO pipeline compiled on it. Opening one takes a moment and compiling
/// the pipeline more: keep one and call it for every image.
#[pyclass(module = "aokit._aokit")]
pub struct Context {
    gpu: GpuContext,
    /// The pipeline with the passes of the last call; `None` until the first.
    external: Option<ExternalAo>,
}

/// One frame's inputs on the CPU, converted and checked.
struct Frame {
    size: [u32; 2],
    camera: Camera,
    linear_depth: Vec<f32>,
    normals: Option<Vec<Vec3>>,
}

/// AO of one frame, and its bent normals when asked for.
type Output = (Vec<f32>, Option<Vec<[f32; 4]>>);

/// One frame as the Python layer hands it in: depth and normal bytes, and the camera.
type FrameIn<'py> = (
    Bound<'py, PyBytes>,
    Option<Bound<'py, PyBytes>>,
    PyRef<'py, Camera>,
);

/// One frame's AO and bent normals as bytearrays.
type FrameOut<'py> = (Bound<'py, PyByteArray>, Option<Bound<'py, PyByteArray>>);

fn render_error(error: RenderError) -> PyErr {
    use aokit::AoError;
    match error {
        RenderError::Normals(_) => PyValueError::new_err(error.to_string()),
        RenderError::Size { .. }
        | RenderError::Camera(_)
        | RenderError::Ao(AoError::Settings(_) | AoError::Projection(_) | AoError::Input(_)) => {
            PyValueError::new_err(error.to_string())
        }
        _ => PyRuntimeError::new_err(error.to_string()),
    }
}

impl Context {
    /// Runs `frames` as one sequence numbered from `first_frame` (the temporal history starts
    /// over at the first).
    fn run_frames(
        &mut self,
        settings: &AoSettings,
        frames: &[Frame],
        first_frame: u32,
        bent_normals: bool,
    ) -> Result<Vec<Output>, RenderError> {
        let mut outputs = Vec::with_capacity(frames.len());
        for (index, frame) in frames.iter().enumerate() {
            let passes = Passes {
                size: frame.size,
                linear_depth: &frame.linear_depth,
                normals: frame.normals.as_deref(),
                back_depth: None,
                projection: frame.camera.projection,
            };
            let external = match self.external.as_mut() {
                Some(external) => {
                    if index == 0 {
                        if external.settings() != settings {
                            external.set_settings(&self.gpu, settings)?;
                        }
                        external.reset_history();
                    }
                    external.set_passes(&self.gpu, &passes)?;
                    external
                }
                None => self
                    .external
                    .insert(ExternalAo::new(&self.gpu, settings, &passes)?),
            };
            // Where the camera moved since the last frame: the temporal filter reprojects by it.
            external.set_view_from_world(frame.camera.view_from_world);
            let frame_index = first_frame.wrapping_add(index as u32);
            outputs.push(if bent_normals {
                external.run_with_bent_normals(&self.gpu, frame_index)?
            } else {
                (external.run(&self.gpu, frame_index)?, None)
            });
        }
        Ok(outputs)
    }
}

#[pymethods]
impl Context {
    /// Opens a device: `"auto"` picks a GPU where there is one, else a software rasteriser;
    /// `"software"` takes the software one (lavapipe) even beside a GPU.
    #[new]
    #[pyo3(signature = (adapter = "auto"))]
    fn new(py: Python<'_>, adapter: &str) -> PyResult<Self> {
        let kind = match adapter {
            "auto" => None,
            "software" => Some(AdapterKind::Software),
            "hardware" => Some(AdapterKind::Hardware),
            other => {
                return Err(PyValueError::new_err(format!(
                    "adapter: `{other}` is not one of auto, software, hardware"
                )));
            }
        };
        let gpu = py
            .detach(|| match kind {
                None => GpuContext::headless(),
                Some(kind) => GpuContext::headless_of_kind(kind),
            })
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(Self {
            gpu,
            external: None,
        })
    }

    /// The adapter: `name (backend, driver)`.
    #[getter]
    fn adapter(&self) -> String {
        self.gpu.describe()
    }

    /// Whether the adapter is a software rasteriser.
    #[getter]
    fn software(&self) -> bool {
        self.gpu.adapter_kind() == AdapterKind::Software
    }

    /// Runs the pipeline on `frames`, a list of `(depth, normals, camera)` with depth and
    /// normals as float32 bytes (C order, H x W and H x W x 3); `names` name each frame's
    /// arrays in errors; the frames are numbered from `first_frame` (the noise pattern of
    /// each). Returns per frame `(ao, bent)` as bytearrays of float32.
    #[pyo3(signature = (frames, names, depth_kind, normal_space, method, preset, radius,
                        settings, bent_normals, first_frame))]
    #[allow(clippy::too_many_arguments)]
    fn run<'py>(
        &mut self,
        py: Python<'py>,
        frames: Vec<FrameIn<'py>>,
        names: Vec<(String, String)>,
        depth_kind: &str,
        normal_space: Option<&str>,
        method: &str,
        preset: &str,
        radius: Option<f32>,
        settings: Option<&Bound<'py, PyDict>>,
        bent_normals: bool,
        first_frame: u32,
    ) -> PyResult<Vec<FrameOut<'py>>> {
        let depth_kind: DepthKind = depth_kind
            .parse()
            .map_err(|e: String| PyValueError::new_err(format!("depth_kind: {e}")))?;
        let resolved = resolve(method, preset, radius, settings, normal_space)?;
        let mut settings = resolved.settings;
        if bent_normals {
            settings
                .set("bent_normals", SettingValue::Bool(true))
                .map_err(|e| PyValueError::new_err(format!("bent_normals: {e}")))?;
        }
        // The normals are turned into view space as they are read, as `aokit ao` does.
        settings.normals.space = NormalSpace::View;
        let mut prepared = Vec::with_capacity(frames.len());
        for ((depth, normals, camera), (depth_name, normals_name)) in frames.iter().zip(&names) {
            let size = camera.size();
            let pixels = size[0] as usize * size[1] as usize;
            let depth = f32_values(depth.as_bytes(), pixels, depth_name)?;
            let linear = linear_depth(depth, depth_kind, &camera.projection, size[0])
                .map_err(|e| PyValueError::new_err(format!("{depth_name}: {e}")))?;
            let normals = normals
                .as_ref()
                .map(|bytes| -> PyResult<Vec<Vec3>> {
                    let values = f32_values(bytes.as_bytes(), 3 * pixels, normals_name)?;
                    let normals = values
                        .chunks_exact(3)
                        .map(|n| Vec3::new(n[0], n[1], n[2]))
                        .collect();
                    view_normals(normals, resolved.normal_space, camera.view_from_world)
                        .map_err(|e| PyValueError::new_err(format!("camera: {e}")))
                })
                .transpose()?;
            prepared.push(Frame {
                size,
                camera: (**camera).clone(),
                linear_depth: linear,
                normals,
            });
        }
        let outputs = py
            .detach(|| self.run_frames(&settings, &prepared, first_frame, bent_normals))
            .map_err(render_error)?;
        Ok(outputs
            .iter()
            .map(|(ao, bent)| {
                let bent = bent.as_ref().map(|texels| {
                    let xyz: Vec<f32> = texels.iter().flat_map(|t| [t[0], t[1], t[2]]).collect();
                    to_bytearray(py, &xyz)
                });
                (to_bytearray(py, ao), bent)
            })
            .collect())
    }
}
