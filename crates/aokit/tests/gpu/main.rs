//! aokit's integration tests, gathered in one test binary: each file is a module, so a test is
//! named `module::test`, as in `cargo test -p aokit --test gpu noise::`.

mod device;
mod noise;
mod normals;
mod properties;
mod views;
