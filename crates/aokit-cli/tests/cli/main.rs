//! The `aokit` binary, run in fresh temporary directories: aokit-cli's integration tests,
//! gathered in one test binary (one link instead of one per file). Each file is a module, so a
//! test is named `module::test`, as in `cargo test -p aokit-cli --test cli ground_truth::`.

mod common;

mod animate;
mod bench;
mod cli;
mod composite;
mod ground_truth;
mod peer;
mod provenance;
mod robustness;
mod roundtrip;
mod sequences;
mod settings;
mod suspicious;
mod tune;
mod view;
