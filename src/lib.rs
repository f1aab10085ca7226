//! Library part of the `garmentcode` tool: its commands (parsed by [`cli`], run by
//! [`commands`]), the output folders they write ([`output`]) and the web
//! configurator, shared by the binary, its integration tests, its benchmarks and
//! the Python package (which runs the same commands' code, so that its files are the
//! CLI's byte for byte).

/// `print!` that ends the program quietly when stdout is closed (`| head`)
/// instead of panicking.
macro_rules! out {
    ($($t:tt)*) => { $crate::write_stdout(&format!($($t)*)) };
}

/// `println!` with the same closed-pipe handling as [`out!`].
macro_rules! outln {
    ($($t:tt)*) => { $crate::write_stdout(&format!("{}\n", format_args!($($t)*))) };
}

pub mod cli;
pub mod commands;
pub mod output;
pub mod web;

/// Write to stdout; a closed pipe ends the program with success (the reader has
/// what it wanted), any other failure with an error.
pub fn write_stdout(text: &str) {
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

/// A build warning as users read it: the reference's internal error strings
/// (`ERROR::IncorrectParams::...`, kept verbatim in `checks.json`) explained.
pub fn explain_warning(w: &str) -> String {
    match w.split_once("ERROR::IncorrectParams::") {
        Some((before, what)) => {
            format!("{before}the reference refuses this combination of parameters ({what}); change one of them to get a valid garment")
        }
        None => w.to_string(),
    }
}

/// The README's code blocks, compiled and run by `cargo test` as doc tests (blocks
/// tagged `sh`, `text` and the like are not Rust and are skipped).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
