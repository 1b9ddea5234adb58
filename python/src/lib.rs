//! `aokit._aokit`: the native part of the `aokit` Python package.
//!
//! The package's Python layer (`python/aokit/`) turns numpy arrays into float32 bytes, checks
//! their shapes and calls in here; this crate reads settings and cameras, runs
//! [`aokit_scene::external::ExternalAo`] with the GIL released, and hands the results back as
//! `bytearray`s that numpy wraps without a copy.

mod arrays;
mod camera;
mod context;
mod eval;
mod settings;

use pyo3::prelude::*;

/// The native module: `Camera`, `Context` and the functions the Python layer wraps.
#[pymodule]
fn _aokit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<camera::Camera>()?;
    m.add_class::<context::Context>()?;
    m.add_function(wrap_pyfunction!(settings::setting_names, m)?)?;
    m.add_function(wrap_pyfunction!(settings::resolve_settings, m)?)?;
    m.add_function(wrap_pyfunction!(eval::reference, m)?)?;
    m.add_function(wrap_pyfunction!(eval::metrics, m)?)?;
    m.add_function(wrap_pyfunction!(eval::read_image, m)?)?;
    m.add_function(wrap_pyfunction!(eval::write_exr, m)?)?;
    Ok(())
}
