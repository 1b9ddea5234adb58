//! `aokit`: render scenes with screen-space AO, headless.

mod camera_args;
mod output;
mod render;
mod settings_args;

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
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render::run(&args),
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
