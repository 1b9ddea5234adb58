//! Images between Python and Rust: float32 bytes in (the Python layer makes them C-ordered
//! float32), `bytearray`s out (writable, wrapped by numpy without a copy).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyByteArray;

/// `bytes` of native-endian float32 values as a vector; `name` is the argument's, for the
/// error when the length is not `len` values.
pub fn f32_values(bytes: &[u8], len: usize, name: &str) -> PyResult<Vec<f32>> {
    if bytes.len() != 4 * len {
        return Err(PyValueError::new_err(format!(
            "{name}: {} bytes are not {len} float32 values",
            bytes.len()
        )));
    }
    // The buffer need not be 4-byte aligned: copy rather than cast.
    Ok(bytemuck::pod_collect_to_vec(bytes))
}

/// Float32 values as a `bytearray`.
pub fn to_bytearray<'py>(py: Python<'py>, values: &[f32]) -> Bound<'py, PyByteArray> {
    PyByteArray::new(py, bytemuck::cast_slice(values))
}
