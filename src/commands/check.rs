//! `garmentcode check SPEC.json [--strict] [--format text|json]`

use crate::cli::{CheckArgs, CheckFormat};
use crate::commands::{CliError, read_pattern};
use garmentcode::{Problem, ProblemKind, Severity, validate};
use serde_json::json;

/// Whether `build --strict` rejects a pattern with this warning. Stitched edges of
/// different lengths are gathers wherever a design asks for them, so they are
/// reported but never fail `--strict`; self-intersections fail both.
pub fn fails_strict(p: &Problem) -> bool {
    p.severity == Severity::Warning && p.kind == ProblemKind::SelfIntersection
}

pub fn run(args: CheckArgs) -> Result<i32, CliError> {
    let file = &args.file;
    let pattern = read_pattern(file)?;
    let problems = validate(&pattern);
    let errors = problems.iter().filter(|p| p.severity == Severity::Error).count();
    let warnings = problems.len() - errors;
    let strict_failures = problems.iter().filter(|p| fails_strict(p)).count();
    if args.format == CheckFormat::Json {
        let list: Vec<serde_json::Value> = problems.iter().map(problem_json).collect();
        let report = json!({ "file": file, "errors": errors, "warnings": warnings, "problems": list });
        outln!("{}", serde_json::to_string_pretty(&report).expect("report serialises"));
    } else {
        for p in &problems {
            outln!("{p}");
        }
        let inner = match pattern.inner_stitches.len() {
            0 => String::new(),
            n => format!(" and {n} inner stitches"),
        };
        outln!(
            "{file}: {} panels, {} stitches{inner}: {errors} error(s), {warnings} warning(s)",
            pattern.panels.len(),
            pattern.stitches.len()
        );
    }
    Ok(if errors > 0 || (args.strict && strict_failures > 0) { 1 } else { 0 })
}

/// A structural problem as `check --format json` lists it.
pub fn problem_json(p: &Problem) -> serde_json::Value {
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
