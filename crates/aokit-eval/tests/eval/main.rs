//! aokit-eval's integration tests, gathered in one test binary: each file is a module, so a test
//! is named `module::test`, as in `cargo test -p aokit-eval --test eval report::`.

mod exr_io;
mod metrics;
mod pfm_npy;
mod report;
mod report_screenshot;
