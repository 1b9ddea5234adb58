//! `aokit._aokit.Context`: one GPU device and one AO pipeline, reused by every call.

use aokit::settings::SettingValue;
use aokit::{AdapterKind, AoSettings, GpuContext, NormalSpace};
use aokit_scene::RenderError;
use aokit_scene::external::{
    DepthKind, ExternalAo, Passes, SubmittedRun, linear_depth, view_normals,
};
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

/// One frame's inputs as the Python layer hands them in, read without the GIL: the float32
/// bytes of its depth and normals (immutable `bytes`, kept alive by the caller), the camera,
/// and the arguments' names for errors.
struct Frame<'a> {
    depth: &'a [u8],
    normals: Option<&'a [u8]>,
    camera: Camera,
    names: &'a (String, String),
}

/// How a batch's frames are converted: the depth kind and the space of the normals.
#[derive(Clone, Copy)]
struct Conversion {
    depth_kind: DepthKind,
    normal_space: NormalSpace,
}

/// A frame's linear depth and view-space normals.
type Converted = (Vec<f32>, Option<Vec<Vec3>>);

impl Frame<'_> {
    /// The frame's passes as the pipeline takes them, as `aokit ao` reads them.
    fn convert(&self, conversion: Conversion) -> PyResult<Converted> {
        let (depth_name, normals_name) = self.names;
        let size = self.camera.input_size();
        let pixels = size[0] as usize * size[1] as usize;
        let depth = f32_values(self.depth, pixels, depth_name)?;
        let linear = linear_depth(
            depth,
            conversion.depth_kind,
            &self.camera.input_projection(),
            size[0],
        )
        .map_err(|e| PyValueError::new_err(format!("{depth_name}: {e}")))?;
        let normals = self
            .normals
            .map(|bytes| -> PyResult<Vec<Vec3>> {
                let values = f32_values(bytes, 3 * pixels, normals_name)?;
                let normals = values
                    .chunks_exact(3)
                    .map(|n| Vec3::new(n[0], n[1], n[2]))
                    .collect();
                view_normals(
                    normals,
                    conversion.normal_space,
                    self.camera.view_from_world,
                )
                .map_err(|e| PyValueError::new_err(format!("camera: {e}")))
            })
            .transpose()?;
        Ok((linear, normals))
    }
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

/// [`render_error`] for a frame's passes, naming the frame's normals where they are refused
/// (`normals[2]: ...` in a batch).
fn passes_error(error: RenderError, frame: &Frame<'_>) -> PyErr {
    match error {
        RenderError::Normals(message) => {
            PyValueError::new_err(format!("{}: {message}", frame.names.1))
        }
        other => render_error(other),
    }
}

impl Context {
    /// Runs `frames` as one sequence numbered from `first_frame` (the temporal history starts
    /// over at the first). Each frame is converted and uploaded while the GPU still runs the
    /// frame before, and read back while it runs the frame after.
    fn run_frames(
        &mut self,
        settings: &AoSettings,
        conversion: Conversion,
        frames: &[Frame<'_>],
        first_frame: u32,
        bent_normals: bool,
    ) -> PyResult<Vec<Output>> {
        let mut outputs = Vec::with_capacity(frames.len());
        let mut submitted: Option<SubmittedRun> = None;
        for (index, frame) in frames.iter().enumerate() {
            let (linear_depth, normals) = frame.convert(conversion)?;
            let passes = Passes {
                size: frame.camera.input_size(),
                linear_depth: &linear_depth,
                normals: normals.as_deref(),
                back_depth: None,
                projection: frame.camera.projection,
            };
            let external = match self.external.as_mut() {
                Some(external) => {
                    if index == 0 {
                        if external.settings() != settings {
                            external
                                .set_settings(&self.gpu, settings)
                                .map_err(render_error)?;
                        }
                        external.reset_history();
                    }
                    external
                        .set_passes(&self.gpu, &passes)
                        .map_err(|e| passes_error(e, frame))?;
                    external
                }
                None => self.external.insert(
                    ExternalAo::new(&self.gpu, settings, &passes)
                        .map_err(|e| passes_error(e, frame))?,
                ),
            };
            // Where the camera moved since the last frame: the temporal filter reprojects by it.
            external.set_view_from_world(frame.camera.view_from_world);
            external.set_guard_band(frame.camera.guard_band());
            let frame_index = first_frame.wrapping_add(index as u32);
            let run = external
                .submit(&self.gpu, frame_index, bent_normals)
                .map_err(render_error)?;
            if let Some(previous) = submitted.replace(run) {
                outputs.push(previous.wait(&self.gpu).map_err(render_error)?);
            }
        }
        if let Some(last) = submitted {
            outputs.push(last.wait(&self.gpu).map_err(render_error)?);
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
        let conversion = Conversion {
            depth_kind,
            normal_space: resolved.normal_space,
        };
        let prepared: Vec<Frame<'_>> = frames
            .iter()
            .zip(&names)
            .map(|((depth, normals, camera), names)| Frame {
                depth: depth.as_bytes(),
                normals: normals.as_ref().map(|bytes| bytes.as_bytes()),
                camera: (**camera).clone(),
                names,
            })
            .collect();
        let outputs = py.detach(|| {
            self.run_frames(&settings, conversion, &prepared, first_frame, bent_normals)
        })?;
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
