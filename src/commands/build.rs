//! `garmentcode build [--design FILE|NAME] [--body NAME|FILE] --out DIR [--strict] [--no-png] [--layout placed|flat]`

use crate::args::{Args, UsageError};
use crate::commands::{CliError, load_body, load_design};
use crate::output::OutputSet;
use garmentcode::Params;
use garmentcode::io::write_design;
use garments::Design;
use garments::build::build;
use std::path::PathBuf;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let out = args.value("out")?.ok_or_else(|| UsageError("build: --out DIR is required".into()))?;
    let design_arg = args.value("design")?;
    let body_arg = args.value("body")?;
    let name = args.value("name")?;
    let strict = args.switch("strict");
    let no_png = args.switch("no-png");
    let layout = crate::commands::layout_arg(&mut args, "build")?;
    let rest = args.finish()?;
    if !rest.is_empty() {
        return Err(UsageError(format!("build: unexpected argument '{}'", rest[0])).into());
    }
    let (design, design_label) = load_design(design_arg.as_deref())?;
    let (body, body_label) = load_body(body_arg.as_deref())?;
    let name = name.unwrap_or_else(|| design_label.clone());
    let built = build(&design, &body, &name).map_err(|e| CliError::Input(format!("{design_label} on {body_label}: {e}")))?;
    let warnings = built.checks.warnings();
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    if strict && !warnings.is_empty() {
        return Err(CliError::Rejected(format!(
            "{design_label} on {body_label}: rejected by --strict ({} failed check(s)); nothing written",
            warnings.len()
        )));
    }
    let mut set = OutputSet::default();
    set.add("specification.json", built.pattern.to_json().map_err(|e| CliError::Input(e.to_string()))?);
    crate::commands::add_drawings(&mut set, &built.pattern, !no_png, layout).map_err(|e| CliError::Input(e.to_string()))?;
    set.add("design_params.yaml", write_design(&design, &Design::design_space()));
    set.add("body_measurements.yaml", body.to_yaml());
    set.add("checks.json", built.checks.to_json());
    let dir = PathBuf::from(&out);
    set.write(&dir).map_err(|e| CliError::Input(format!("cannot write {}: {e}", dir.display())))?;
    eprintln!(
        "wrote {}: {} panels, {} stitches ({design_label} on {body_label})",
        dir.display(),
        built.pattern.panels.len(),
        built.pattern.stitches.len()
    );
    Ok(0)
}
