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
    build [--design FILE.yaml|NAME] [--body NAME|FILE.yaml] --out DIR [--strict] [--no-png]
          [--layout placed|flat]
        Build a garment: DIR/specification.json, pattern.svg, pattern.png,
        design_params.yaml, body_measurements.yaml and checks.json. Without
        --design the built-in t-shirt; without --body the neutral body mean_all.
        Built-in designs: t-shirt, fitted-dress, sundress, shirt-dress, jumpsuit.
        Built-in bodies: mean_all, mean_female, mean_male, f_smpl_average_A40,
        m_smpl_average_A40. The reference's checks are printed as warnings;
        --strict rejects a design that fails one (exit 1, nothing written).
    schema [--format reference-yaml|json-schema|table]
        The design space: every parameter with its type, range, default and
        sampling probability.
    check SPEC.json [--strict] [--format text|json]
        Validate a pattern: errors (open loops, bad indices, dangling stitches,
        edges stitched twice) and warnings (self-intersections, stitched edges of
        different lengths). Exit 1 on errors (with --strict also on warnings).
    render SPEC.json --out DIR [--no-png] [--layout placed|flat]
        Re-emit DIR/specification.json and draw DIR/pattern.svg and DIR/pattern.png.
        Drawings (build, render): --layout placed (default) draws panels where
        the reference does, as on the body; --layout flat lays them side by side
        without overlap, in rows at most 150 cm wide, to print and cut from.
    compare EXPECTED.json ACTUAL.json [--tol CM] [--strict] [--verbose]
    compare --cases EXPECTED_DIR ACTUAL_DIR [--tol CM] [--strict] [--verbose]
        Judge whether two patterns are the same garment by geometry (outlines,
        placement, perimeters and stitches within --tol, default 0.05 cm; vertex
        order and JSON layout do not matter; sleeve, cuff and hood panels, which
        the reference fits chaotically, are judged by how they sew). With --cases,
        every case folder (specification.json or error.txt) of EXPECTED_DIR
        against the same folder in ACTUAL_DIR. Exit 0 when all pass, else 1.
    sample --n N --seed S --out DIR [--design-space FILE.yaml] [--bodies NAME,NAME|DIR]
           [--jobs J] [--shard I/K] [--formats json,svg,png]
        A dataset of N random garments: DIR/rand_0000000 ... each with
        rand_NNNNNNN_specification.json (and _pattern.svg/.png as asked),
        design_params.yaml, body_measurements.yaml and sample_info.json, and
        DIR/dataset_properties.yaml (types, rejections by reason, time).
        Sample i depends on (S, i) alone: the same with any --jobs (default: all
        cores) and in any shard. Designs failing the reference's filters are
        drawn again (up to 100 times). A rerun into DIR skips finished samples.
        --design-space: a design file whose ranges and probabilities replace
        the built-in ones. --bodies: built-in names or body files, or a folder of
        body files (default mean_all). --shard I/K: only the samples i with
        i % K == I (0 <= I < K). --formats: default json.
    sample --seed S --replay INDEX[:ATTEMPT] --out DIR [--design-space ...] [--bodies ...]
        Rebuild one sample, or one attempt of it (also a rejected one), into DIR
        as `build` would, and print the filters' verdict.
    serve [--port P] [--host 127.0.0.1]
        The web configurator: a page with a control for every design parameter,
        the body measurements and the pattern drawn live, plus its JSON API
        (GET /api/schema, POST /api/pattern, ...; see README). Listens on
        loopback unless --host says otherwise; default port 8000, 0 picks a free
        one. Prints the page's address.
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
        "build" => commands::build::run(args),
        "schema" => commands::schema::run(args),
        "check" => commands::check::run(args),
        "render" => commands::render::run(args),
        "compare" => commands::compare::run(args),
        "sample" => commands::sample::run(args),
        "serve" => commands::serve::run(args),
        "help" | "--help" | "-h" => {
            out!("{HELP}");
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
        eprintln!("error: cannot write to stdout: {e}");
        std::process::exit(1);
    }
}
