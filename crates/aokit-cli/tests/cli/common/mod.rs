//! Helpers the CLI tests share: run the `aokit` binary in a directory and read what it printed.

use std::path::Path;
use std::process::{Command, Output};

/// The `aokit` binary with `args`, to run in `dir`; add arguments or environment, then run it
/// with [`output`].
pub fn command(dir: &Path, args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_aokit"));
    command.args(args).current_dir(dir);
    command
}

/// Runs `command` to the end: its exit status, stdout and stderr.
pub fn output(command: &mut Command) -> Output {
    command.output().expect("run aokit")
}

/// Runs `aokit args` in `dir`.
pub fn aokit(dir: &Path, args: &[&str]) -> Output {
    output(&mut command(dir, args))
}

/// Printed bytes as text (lossy).
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The stdout of a run that must succeed.
pub fn ok(out: &Output) -> String {
    assert!(out.status.success(), "{}", text(&out.stderr));
    text(&out.stdout)
}

/// The error text of a run that must fail.
pub fn failure(out: &Output) -> String {
    assert!(!out.status.success(), "succeeded: {}", text(&out.stdout));
    text(&out.stderr)
}
