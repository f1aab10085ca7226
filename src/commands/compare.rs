//! `garmentcode compare EXPECTED ACTUAL [--cases] [--tol CM] [--strict] [-v]`:
//! judge whether two patterns are the same garment by their geometry.

use crate::cli::CompareArgs;
use crate::commands::CliError;
use garmentcode_compare::{self as compare, CompareOptions};

/// Printed once when a report mentions chaotic panels.
const CHAOTIC_NOTE: &str = "note: \"chaotic panels\" are sleeve, cuff and hood panels, whose curves the reference fits with a numerically \
chaotic optimiser; they are judged by how they sew (shared seam lengths, placement) within wider bounds, not point by point \
(--no-chaotic-rule compares them point by point)";

pub fn run(args: CompareArgs) -> Result<i32, CliError> {
    let opts = CompareOptions { tol: args.tol, strict: args.strict, chaotic_rule: !args.no_chaotic_rule, ..CompareOptions::default() };
    let (expected, actual) = (args.expected.as_path(), args.actual.as_path());
    for p in [expected, actual] {
        if !p.exists() {
            return Err(CliError::Input(format!("{}: no such file or folder", p.display())));
        }
    }
    let results = if args.cases {
        compare::compare_case_dirs(expected, actual, &opts).map_err(CliError::Input)?
    } else {
        let name = actual.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        vec![(name, compare::compare_spec_files(expected, actual, &opts))]
    };
    let mut chaotic = false;
    for (name, v) in &results {
        let line = v.report_line(name, if args.verbose { i64::MAX } else { 3 });
        chaotic |= line.contains("chaotic");
        outln!("{line}");
        if args.verbose {
            for n in &v.notes {
                chaotic |= n.contains("chaotic");
                outln!("  note: {n}");
            }
        }
    }
    for line in compare::summary(&results, &opts) {
        chaotic |= line.contains("chaotic");
        outln!("{line}");
    }
    if chaotic {
        outln!("{CHAOTIC_NOTE}");
    }
    let passed = results.iter().filter(|(_, v)| v.pass).count();
    Ok(if passed == results.len() && passed > 0 { 0 } else { 1 })
}
