//! `garmentcode`: build, check, render and sample GarmentCode sewing patterns.

mod args;
mod commands;
mod output;

use args::Args;
use commands::CliError;

const HELP: &str = "\
garmentcode — parametric sewing patterns (a Rust implementation of GarmentCode)

USAGE:
    garmentcode <COMMAND> [OPTIONS]

COMMANDS:
    check SPEC.json [--strict] [--format text|json]
        Validate a pattern: errors (open loops, bad indices, dangling stitches,
        edges stitched twice) and warnings (self-intersections, stitched edges of
        different lengths). Exit 1 on errors (with --strict also on warnings).
    render SPEC.json --out DIR [--no-png]
        Re-emit DIR/specification.json and draw DIR/pattern.svg and DIR/pattern.png.
    help
        Show this text.
";

fn main() {
    let mut argv: Vec<String> = std::env::args().skip(1).collect();
    if argv.is_empty() {
        eprint!("{HELP}");
        std::process::exit(2);
    }
    let command = argv.remove(0);
    let args = Args::new(&command, argv);
    let result = match command.as_str() {
        "check" => commands::check::run(args),
        "render" => commands::render::run(args),
        "help" | "--help" | "-h" => {
            print!("{HELP}");
            Ok(0)
        }
        other => Err(CliError::Usage(format!("unknown command '{other}' (see `garmentcode help`)"))),
    };
    match result {
        Ok(code) => std::process::exit(code),
        Err(CliError::Usage(m)) => {
            eprintln!("error: {m}");
            std::process::exit(2);
        }
        Err(CliError::Input(m)) => {
            eprintln!("error: {m}");
            std::process::exit(2);
        }
    }
}
