//! `aokit.Camera`: the camera.json that `aokit ao` reads, checked once.

use std::path::PathBuf;

use aokit::Projection;
use aokit_scene::CameraFile;
use glam::Mat4;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// A camera: image size, projection and placement, as camera.json describes them
/// (docs/camera-json.md). Build one with `Camera.perspective`, `Camera.orthographic` or
/// `Camera.from_json`.
#[pyclass(module = "aokit._aokit", frozen)]
#[derive(Clone, Debug)]
pub struct Camera {
    /// What camera.json holds.
    pub file: CameraFile,
    /// The projection, checked.
    pub projection: Projection,
    /// World to view, checked finite.
    pub view_from_world: Mat4,
}

impl Camera {
    /// Checks `file` as `aokit ao` does; `what` names it in the error.
    fn checked(file: CameraFile, what: &str) -> PyResult<Self> {
        let (projection, view_from_world) = file
            .checked()
            .map_err(|e| PyValueError::new_err(format!("{what}: {e}")))?;
        Ok(Self {
            file,
            projection,
            view_from_world,
        })
    }

    /// Width and height in pixels: the frame's, which the AO covers.
    pub fn size(&self) -> [u32; 2] {
        [self.file.width, self.file.height]
    }

    /// Pixels of overscan on each side of the depth and normals (camera.json's `guard_band`).
    pub fn guard_band(&self) -> u32 {
        self.file.guard_band
    }

    /// The size of the depth and normals: the frame's and the guard band on each side.
    pub fn input_size(&self) -> [u32; 2] {
        let band = self.file.guard_band.saturating_mul(2);
        self.size().map(|side| side.saturating_add(band))
    }

    /// The projection the depth and normals were drawn with: the camera's, widened by the
    /// guard band.
    pub fn input_projection(&self) -> Projection {
        self.projection
            .with_guard_band(self.size(), self.file.guard_band)
    }
}

/// A 4x4 matrix from nested sequences or a numpy array, row-major; the identity for `None`.
fn matrix_rows(value: Option<&Bound<'_, PyAny>>) -> PyResult<[[f32; 4]; 4]> {
    let Some(value) = value else {
        return Ok(Mat4::IDENTITY.transpose().to_cols_array_2d());
    };
    let value = if value.hasattr("tolist")? {
        value.call_method0("tolist")?
    } else {
        value.clone()
    };
    let bad = || PyValueError::new_err("view_from_world: expected 4 rows of 4 numbers (row-major)");
    let rows: Vec<Vec<f32>> = value.extract().map_err(|_| bad())?;
    let mut matrix = [[0.0f32; 4]; 4];
    if rows.len() != 4 || rows.iter().any(|row| row.len() != 4) {
        return Err(bad());
    }
    for (out, row) in matrix.iter_mut().zip(&rows) {
        out.copy_from_slice(row);
    }
    Ok(matrix)
}

#[pymethods]
impl Camera {
    /// A pinhole camera with a vertical field of view in degrees.
    #[staticmethod]
    #[pyo3(signature = (fov_y_deg, width, height, near = 0.1, far = None, reverse_z = true,
                        view_from_world = None, ndc_offset = (0.0, 0.0), guard_band = 0))]
    #[allow(clippy::too_many_arguments)]
    fn perspective(
        fov_y_deg: f32,
        width: u32,
        height: u32,
        near: f32,
        far: Option<f32>,
        reverse_z: bool,
        view_from_world: Option<&Bound<'_, PyAny>>,
        ndc_offset: (f32, f32),
        guard_band: u32,
    ) -> PyResult<Self> {
        let file = CameraFile {
            width,
            height,
            projection: "perspective".into(),
            fov_y_deg: Some(fov_y_deg),
            ortho_height: None,
            near,
            far,
            reverse_z,
            ndc_offset: [ndc_offset.0, ndc_offset.1],
            view_from_world: matrix_rows(view_from_world)?,
            guard_band,
        };
        Self::checked(file, "camera")
    }

    /// A parallel projection `view_height` world units tall.
    #[staticmethod]
    #[pyo3(signature = (view_height, width, height, near = 0.1, far = 1000.0, reverse_z = true,
                        view_from_world = None, ndc_offset = (0.0, 0.0), guard_band = 0))]
    #[allow(clippy::too_many_arguments)]
    fn orthographic(
        view_height: f32,
        width: u32,
        height: u32,
        near: f32,
        far: f32,
        reverse_z: bool,
        view_from_world: Option<&Bound<'_, PyAny>>,
        ndc_offset: (f32, f32),
        guard_band: u32,
    ) -> PyResult<Self> {
        let file = CameraFile {
            width,
            height,
            projection: "orthographic".into(),
            fov_y_deg: None,
            ortho_height: Some(view_height),
            near,
            far: Some(far),
            reverse_z,
            ndc_offset: [ndc_offset.0, ndc_offset.1],
            view_from_world: matrix_rows(view_from_world)?,
            guard_band,
        };
        Self::checked(file, "camera")
    }

    /// The camera of a camera.json file (a path) or of its contents (a dict).
    #[staticmethod]
    fn from_json(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (text, what) = if source.is_instance_of::<PyDict>() {
            let json = py.import("json")?;
            let text: String = json.call_method1("dumps", (source,))?.extract()?;
            (text, "camera dict".to_string())
        } else {
            let path: PathBuf = source.extract().map_err(|_| {
                PyValueError::new_err("camera: expected a path to camera.json or a dict")
            })?;
            let text = std::fs::read_to_string(&path)
                .map_err(|e| PyOSError::new_err(format!("cannot read {}: {e}", path.display())))?;
            (text, path.display().to_string())
        };
        let file: CameraFile = serde_json::from_str(&text)
            .map_err(|e| PyValueError::new_err(format!("{what} is not a camera.json: {e}")))?;
        Self::checked(file, &what)
    }

    /// The camera.json contents, for `json.dump`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = serde_json::to_string(&self.file).expect("a CameraFile serialises");
        py.import("json")?
            .call_method1("loads", (PyString::new(py, &text),))
    }

    /// Image width in pixels.
    #[getter]
    fn width(&self) -> u32 {
        self.file.width
    }

    /// Image height in pixels.
    #[getter]
    fn height(&self) -> u32 {
        self.file.height
    }

    /// Pixels of overscan on each side of the depth and normals; the AO is `width` x `height`.
    #[getter(guard_band)]
    fn guard_band_px(&self) -> u32 {
        self.file.guard_band
    }

    /// `"perspective"` or `"orthographic"`.
    #[getter]
    fn projection(&self) -> &str {
        &self.file.projection
    }

    /// Vertical field of view in degrees (perspective), else None.
    #[getter]
    fn fov_y_deg(&self) -> Option<f32> {
        self.file.fov_y_deg
    }

    /// Height of the view volume in world units (orthographic), else None.
    #[getter]
    fn ortho_height(&self) -> Option<f32> {
        self.file.ortho_height
    }

    /// Near plane distance.
    #[getter]
    fn near(&self) -> f32 {
        self.file.near
    }

    /// Far plane distance, None for an infinite far plane.
    #[getter]
    fn far(&self) -> Option<f32> {
        self.file.far
    }

    /// Whether the depth buffer holds 1 at the near plane and 0 at the far plane.
    #[getter]
    fn reverse_z(&self) -> bool {
        self.file.reverse_z
    }

    /// Where the view axis meets the image, in NDC.
    #[getter]
    fn ndc_offset(&self) -> (f32, f32) {
        (self.file.ndc_offset[0], self.file.ndc_offset[1])
    }

    /// The world-to-view matrix, row-major: 4 lists of 4 floats, translation in the last
    /// column. It turns world-space normals (`normal_space="world"`) into view space.
    #[getter]
    fn view_from_world(&self) -> Vec<Vec<f32>> {
        self.file
            .view_from_world
            .iter()
            .map(|r| r.to_vec())
            .collect()
    }

    fn __repr__(&self) -> String {
        let lens = match (self.file.fov_y_deg, self.file.ortho_height) {
            (Some(fov), _) => format!("perspective fov_y_deg={fov}"),
            (_, Some(h)) => format!("orthographic ortho_height={h}"),
            _ => self.file.projection.clone(),
        };
        let band = match self.file.guard_band {
            0 => String::new(),
            band => format!(", guard_band={band}"),
        };
        format!(
            "Camera({}x{}, {lens}, near={}, far={:?}, reverse_z={}{band})",
            self.file.width, self.file.height, self.file.near, self.file.far, self.file.reverse_z
        )
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.file == other.file
    }
}
