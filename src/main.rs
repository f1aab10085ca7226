//! `garmentcode`: build, check, render and sample GarmentCode sewing patterns.

/// mimalloc: building a garment makes and frees thousands of small vectors, and
/// the sampler does so on every thread at once; the system allocator spent a tenth
/// of the sampler's time on them.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use clap::Parser;
use garmentcode_cli::cli::{Cli, Command};
use garmentcode_cli::commands::{self, CliError};

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Build(a) => commands::build::run(a),
        Command::Schema(a) => commands::schema::run(a),
        Command::Check(a) => commands::check::run(a),
        Command::Render(a) => commands::render::run(a),
        Command::Compare(a) => commands::compare::run(a),
        Command::Sample(a) => commands::sample::run(a),
        Command::Mesh(a) => commands::mesh::run(a),
        Command::Drape(a) => commands::drape::run(a),
        Command::Print(a) => commands::print::run(a),
        Command::Serve(a) => commands::serve::run(a),
        Command::Guide(a) => commands::guide::run(a),
        Command::Completions(a) => commands::completions(a),
    };
    match result {
        Ok(code) => std::process::exit(code),
        Err(CliError::Usage(m)) | Err(CliError::Input(m)) => {
            eprintln!("error: {m}");
            std::process::exit(2);
        }
        Err(CliError::Rejected(m)) | Err(CliError::Failed(m)) => {
            eprintln!("error: {m}");
            std::process::exit(1);
        }
    }
}
