//! `garmentcode`: build, check, render and sample GarmentCode sewing patterns.

/// `print!` that ends the program quietly when stdout is closed (`| head`)
/// instead of panicking.
macro_rules! out {
    ($($t:tt)*) => { $crate::write_stdout(&format!($($t)*)) };
}

/// `println!` with the same closed-pipe handling as [`out!`].
macro_rules! outln {
    ($($t:tt)*) => { $crate::write_stdout(&format!("{}\n", format_args!($($t)*))) };
}

/// mimalloc: building a garment makes and frees thousands of small vectors, and
/// the sampler does so on every thread at once; the system allocator spent a tenth
/// of the sampler's time on them.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

mod cli;
mod commands;
mod output;

use clap::Parser;
use cli::{Cli, Command};
use commands::CliError;

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
        Command::Print(a) => commands::print::run(a),
        Command::Serve(a) => commands::serve::run(a),
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

/// Write to stdout; a closed pipe ends the program with success (the reader has
/// what it wanted), any other failure with an error.
fn write_stdout(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        // stderr may be closed too: report if possible, never panic.
        let _ = writeln!(std::io::stderr(), "error: cannot write to stdout: {e}");
        std::process::exit(1);
    }
}
