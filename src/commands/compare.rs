//! `garmentcode compare EXPECTED ACTUAL [--cases] [--tol CM] [--strict] [-v]`:
//! judge whether two patterns are the same garment by their geometry.

use crate::args::{Args, UsageError};
use crate::commands::CliError;
use garmentcode_compare::{self as compare, CompareOptions};
use std::path::Path;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let mut opts = CompareOptions::default();
    if let Some(t) = args.value("tol")? {
        opts.tol = match t.trim().parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 => x,
            _ => return Err(UsageError(format!("compare --tol: expects a positive number of cm, got '{t}'")).into()),
        };
    }
    let cases = args.switch("cases");
    opts.strict = args.switch("strict");
    opts.chaotic_rule = !args.switch("no-chaotic-rule");
    let verbose = args.switch("verbose");
    let files = args.finish()?;
    let (expected, actual) = match files.as_slice() {
        [e, a] => (Path::new(e), Path::new(a)),
        _ => return Err(UsageError("compare: expects EXPECTED and ACTUAL (two files, or two case folders with --cases)".into()).into()),
    };
    for p in [expected, actual] {
        if !p.exists() {
            return Err(CliError::Input(format!("{}: no such file or folder", p.display())));
        }
    }
    let results = if cases {
        compare::compare_case_dirs(expected, actual, &opts).map_err(CliError::Input)?
    } else {
        let name = actual.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        vec![(name, compare::compare_spec_files(expected, actual, &opts))]
    };
    for (name, v) in &results {
        outln!("{}", v.report_line(name, if verbose { i64::MAX } else { 3 }));
        if verbose {
            for n in &v.notes {
                outln!("  note: {n}");
            }
        }
    }
    for line in compare::summary(&results, &opts) {
        outln!("{line}");
    }
    let passed = results.iter().filter(|(_, v)| v.pass).count();
    Ok(if passed == results.len() && passed > 0 { 0 } else { 1 })
}
