//! `aokit`: render scenes with screen-space AO, headless, or look at them live (`aokit view`).

/// `print!` for the command's report on stdout, which does not panic when the reader has gone
/// (`aokit render | head -c1`): see [`stdout_text`].
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::stdout_text(format_args!($($arg)*))
    };
}

/// `println!` as [`out!`] is `print!`.
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::stdout_text(format_args!("{}\n", format_args!($($arg)*)))
    };
}

mod ao;
mod bench;
mod cache;
mod camera_args;
mod compare;
mod export;
mod lighting_args;
mod passes;
mod peer;
mod recorded;
mod reference;
mod render;
mod sequence;
mod settings_args;
mod settings_list;
mod suspicious;
mod tune;
mod view;
mod view_sets;

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "aokit", version, about = "Screen-space ambient occlusion toolkit", long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene's G-buffer, its AO and a lit image.
    Render(render::RenderArgs),
    /// Ray-trace the reference AO of a scene and camera on the CPU.
    Reference(reference::ReferenceArgs),
    /// Compute AO for depth (and normal) passes exported by another renderer.
    Ao(ao::AoArgs),
    /// Score methods and presets against the reference: metrics, error maps, report.html.
    Compare(compare::CompareArgs),
    /// Time the AO passes alone on one G-buffer: GPU time per pass, CPU encode time; with
    /// --compare, several configurations interleaved.
    Bench(bench::BenchArgs),
    /// Search each method's parameters at each preset's cost for the lowest error against the
    /// reference: the table the presets come from.
    Tune(tune::TuneArgs),
    /// Prepare a peer (another AO implementation run beside aokit's by bench and compare
    /// --peer): compile its shaders once for machines without its compiler.
    Peer(peer::PeerArgs),
    /// List every setting with its type, range, default and the value the flags give it;
    /// --markdown prints docs/settings.md.
    Settings(settings_list::SettingsListArgs),
    /// Look at a scene live in a window: fly or orbit, change every setting from a panel,
    /// switch display modes, read per-pass GPU times; --frames N --screenshot FILE renders N
    /// frames, writes a PNG of the window and exits.
    View(view::ViewArgs),
}

/// Flags renamed so that one name means one thing in every subcommand: (subcommand, old
/// spelling, new one, why). The old spellings still parse (clap aliases) and draw a warning.
const RENAMED_FLAGS: &[(&str, &str, &str, &str)] = &[
    (
        "compare",
        "--methods",
        "--method",
        "as in the other subcommands",
    ),
    (
        "compare",
        "--presets",
        "--preset",
        "as in the other subcommands",
    ),
    (
        "tune",
        "--methods",
        "--method",
        "as in the other subcommands",
    ),
    (
        "tune",
        "--presets",
        "--preset",
        "as in the other subcommands",
    ),
    (
        "bench",
        "--frames",
        "--timing-frames",
        "as in the other subcommands",
    ),
    (
        "ao",
        "--camera",
        "--camera-json",
        "since --camera names one of a scene's cameras in the other subcommands",
    ),
    (
        "reference",
        "--falloff",
        "--falloff-curve",
        "since `falloff` is also the methods' numeric setting",
    ),
];

/// Warns about each renamed flag `args` (the command line, program name first) spells the old
/// way.
fn warn_renamed_flags(args: &[String]) {
    let Some(subcommand) = args.get(1) else {
        return;
    };
    for (command, old, new, why) in RENAMED_FLAGS {
        let used = args[2..].iter().any(|a| {
            a == old
                || a.strip_prefix(old)
                    .is_some_and(|rest| rest.starts_with('='))
        });
        if subcommand == command && used {
            eprintln!(
                "warning: `aokit {command} {old}` is now `{new}`, {why}; the old name still \
                 works for now"
            );
        }
    }
}

fn main() -> ExitCode {
    quiet_wayland_probe();
    warn_renamed_flags(&std::env::args().collect::<Vec<_>>());
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render::run(&args),
        Command::Reference(args) => reference::run(&args),
        Command::Ao(args) => ao::run(&args),
        Command::Compare(args) => compare::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Tune(args) => tune::run(&args),
        Command::Peer(args) => peer::run(&args),
        Command::Settings(args) => settings_list::run(&args),
        Command::View(args) => view::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            // Everything reported here is about the user's input or machine: the same code as
            // clap's usage errors, so scripts test one value.
            ExitCode::from(2)
        }
    }
}

/// Points `XDG_RUNTIME_DIR` at the temporary directory where it is unset, as on a headless
/// machine or in a container: wgpu's GL backend probes for a Wayland display while it looks for
/// adapters, and libwayland then prints "XDG_RUNTIME_DIR is invalid or not set" to stderr, once
/// per probe. With a directory there it finds no display and says nothing.
fn quiet_wayland_probe() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // SAFETY: called first thing in `main`, before any thread exists that could read the
        // environment concurrently.
        unsafe { std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir()) };
    }
}

/// Writes to stdout. `println!` panics when stdout is a closed pipe (Rust ignores
/// SIGPIPE, so the write fails with EPIPE); the report on stdout only summarises what the
/// command wrote to files, so a reader that stopped early loses nothing else: the line is
/// dropped and the command goes on to write its files and exit 0. Any other write error is
/// said on stderr, not fatal, for the same reason.
pub fn stdout_text(args: std::fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args).and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        eprintln!("warning: cannot write to stdout: {e}");
    }
}
