//! aokit-scene's integration tests, gathered in one test binary (one link of wgpu, naga and the
//! crates, instead of one per file): each file is a module, so a test is named
//! `module::test`, as in `cargo test -p aokit-scene --test gpu methods::`.

mod common;

mod accuracy;
mod back_faces;
mod backends;
mod conventions;
mod debug_views;
mod depth_mips;
mod guard_band;
mod load;
mod mask;
mod methods;
mod motion;
mod msaa;
mod msvo;
mod normals;
mod occlusion;
mod reference;
mod render;
mod resolution;
mod robustness;
mod sao;
mod separable_hbao;
mod soak;
mod spatial_filter;
mod temporal;
mod ue4_ssao;
