//! `garmentcode print SPEC.json --out DIR [--paper ...] [--seam CM] [--hem CM]
//! [--seam-edge PANEL[:EDGE]=CM]... [--fabric-width CM]`: the pattern as pieces to
//! print, cut and sew (see `garmentcode::fabricate`). With `--sizes BODY,...` or
//! `--size-chart FILE.yaml` the argument is a design, built on every size and
//! printed nested (`garmentcode::fabricate::size_run_files`).

use crate::cli::PrintArgs;
use crate::commands::{CliError, load_body, load_design, read_pattern, write_folder};
use crate::output::OutputSet;
use garmentcode::fabricate::{PrintOptions, files, size_run_files};
use std::path::Path;

pub fn run(args: PrintArgs) -> Result<i32, CliError> {
    if !args.sizes.is_empty() || args.size_chart.is_some() {
        return size_run(args);
    }
    let file = &args.file;
    let pattern = read_pattern(file)?;
    check_seam_edges(&args, &pattern, file)?;
    let opts = print_options(&args, crate::commands::mesh::prefix(file), args.size.clone());
    for problem in garmentcode::validate(&pattern).iter().filter(|x| x.kind == garmentcode::ProblemKind::SelfIntersection) {
        eprintln!("warning: {file}: {problem}; its cut line follows the crossing outline and needs checking by hand");
    }
    let mut set = OutputSet::default();
    for (name, bytes) in files(&pattern, &opts).map_err(|e| CliError::Input(format!("{file}: {e}")))? {
        set.add(&name, bytes);
    }
    set.add_input(file);
    write_folder(&set, &args.out, args.force)?;
    eprintln!("wrote {} ({} panels)", args.out.display(), pattern.panels.len());
    Ok(0)
}

/// `print DESIGN --sizes ...|--size-chart ...`: the design on every size, nested. A
/// size whose design fails (cannot be built, or fails a validity check) is named
/// with the reason and left out; the others are written, with `size-run.txt`
/// saying which is which.
fn size_run(args: PrintArgs) -> Result<i32, CliError> {
    let file = &args.file;
    if file.ends_with(".json") {
        return Err(CliError::Usage(format!(
            "{file}: a size run builds the design on every size: give a design file (.yaml) or a built-in design, not a specification (a specification is built for one body)"
        )));
    }
    let (design, design_label) = load_design(file)?;
    let mut sizes: Vec<(String, garmentcode::Body)> = Vec::new();
    let mut from = String::new();
    if let Some(chart) = &args.size_chart {
        let text = crate::commands::read_text(chart).map_err(|e| CliError::Input(format!("{chart}: cannot read: {e}")))?;
        let c = garmentcode::SizeChart::from_yaml(&text, chart, garments::builtin::BODIES).map_err(|e| CliError::Input(e.to_string()))?;
        from = format!("size chart {} ({chart})", c.name);
        sizes = c.sizes;
    }
    for body in &args.sizes {
        let (b, _) = load_body(body)?;
        let name = Path::new(body).file_stem().map_or_else(|| body.clone(), |s| s.to_string_lossy().into_owned());
        if sizes.iter().any(|(n, _)| *n == name) {
            return Err(CliError::Usage(format!("--sizes: size {name} is listed twice")));
        }
        sizes.push((name, b));
    }
    if sizes.len() > garmentcode::MAX_SIZES {
        return Err(CliError::Usage(format!("--sizes: {} sizes; a size run has at most {}", sizes.len(), garmentcode::MAX_SIZES)));
    }
    let opts = print_options(&args, design_label.clone(), String::new());
    let garment = opts.garment.clone();
    let mut built = Vec::new();
    let mut report = format!("Size run of {design_label}{}\n", if from.is_empty() { String::new() } else { format!(" from the {from}") });
    for (name, body) in &sizes {
        let figures = format!("height {}, bust {}, waist {}, hips {}", cm(body.height), cm(body.bust), cm(body.waist), cm(body.hips));
        let failure = match garments::build::build(&design, body, &garment) {
            Err(e) => Some(e.to_string()),
            Ok(b) => {
                let warnings = b.checks.warnings();
                if warnings.is_empty() {
                    built.push((name.clone(), b.pattern));
                    None
                } else {
                    Some(warnings.iter().map(|w| crate::explain_warning(w)).collect::<Vec<_>>().join("; "))
                }
            }
        };
        match failure {
            None => report.push_str(&format!("  {name}: printed ({figures})\n")),
            Some(reason) => {
                eprintln!("warning: size {name}: left out: {reason}");
                report.push_str(&format!("  {name}: left out: {reason} ({figures})\n"));
            }
        }
    }
    if built.is_empty() {
        return Err(CliError::Rejected(format!("{design_label}: no size could be built (see the warnings above); nothing written")));
    }
    for (name, pattern) in &built {
        check_seam_edges(&args, pattern, &format!("{design_label} (size {name})"))?;
    }
    let mut set = OutputSet::default();
    for (name, bytes) in size_run_files(&built, &opts).map_err(|e| CliError::Input(format!("{design_label}: {e}")))? {
        set.add(&name, bytes);
    }
    set.add("size-run.txt", report.into_bytes());
    set.add_input(file);
    write_folder(&set, &args.out, args.force)?;
    eprintln!("wrote {}: {} of {} sizes nested ({design_label})", args.out.display(), built.len(), sizes.len());
    Ok(0)
}

/// The print options of the command line; the garment's name defaults to `default_garment`.
fn print_options(args: &PrintArgs, default_garment: String, size: String) -> PrintOptions {
    PrintOptions {
        seam: args.seam,
        hem: args.hem,
        edge_seams: args.seam_edges.clone(),
        paper: args.paper,
        fabric_width: args.fabric_width,
        garment: args.garment.clone().unwrap_or_else(|| default_garment.chars().take(garmentcode::io::MAX_NAME_CHARS).collect()),
        size,
    }
}

/// Every `--seam-edge` names a panel of `pattern` (from `what`) and one of its edges.
fn check_seam_edges(args: &PrintArgs, pattern: &garmentcode::Pattern, what: &str) -> Result<(), CliError> {
    for o in &args.seam_edges {
        let panel = pattern.panel(&o.panel).ok_or_else(|| CliError::Usage(format!("--seam-edge: no panel '{}' in {what}", o.panel)))?;
        if o.edge.is_some_and(|e| e >= panel.edges.len()) {
            return Err(CliError::Usage(format!("--seam-edge: panel '{}' has {} edges", o.panel, panel.edges.len())));
        }
    }
    Ok(())
}

/// A measurement in the report: cm with one decimal.
fn cm(x: f64) -> String {
    format!("{x:.1} cm")
}
