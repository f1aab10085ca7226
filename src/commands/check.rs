//! `garmentcode check SPEC.json [--strict] [--format text|json]`

use crate::args::{Args, UsageError};
use crate::commands::{CliError, read_pattern};
use garmentcode::{Problem, Severity, validate};
use serde_json::json;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let strict = args.switch("strict");
    let format = args.value("format")?.unwrap_or_else(|| "text".into());
    if format != "text" && format != "json" {
        return Err(UsageError(format!("check --format: expected text or json, got '{format}'")).into());
    }
    let files = args.finish()?;
    let [file] = files.as_slice() else {
        return Err(UsageError("check: expects exactly one SPEC.json file".into()).into());
    };
    let pattern = read_pattern(file)?;
    let problems = validate(&pattern);
    let errors = problems.iter().filter(|p| p.severity == Severity::Error).count();
    let warnings = problems.len() - errors;
    if format == "json" {
        let list: Vec<serde_json::Value> = problems.iter().map(problem_json).collect();
        let report = json!({ "file": file, "errors": errors, "warnings": warnings, "problems": list });
        outln!("{}", serde_json::to_string_pretty(&report).expect("report serialises"));
    } else {
        for p in &problems {
            outln!("{p}");
        }
        outln!("{file}: {} panels, {} stitches: {errors} error(s), {warnings} warning(s)", pattern.panels.len(), pattern.stitches.len());
    }
    Ok(if errors > 0 || (strict && warnings > 0) { 1 } else { 0 })
}

fn problem_json(p: &Problem) -> serde_json::Value {
    json!({
        "kind": p.kind.as_str(),
        "severity": match p.severity { Severity::Error => "error", Severity::Warning => "warning" },
        "panel": p.panel,
        "edge": p.edge,
        "stitch": p.stitch,
        "ratio": p.ratio,
        "message": p.message,
    })
}
