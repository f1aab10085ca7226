//! `garmentcode render SPEC.json --out DIR [--no-png] [--layout placed|flat] [--force]`:
//! re-emit the pattern and draw it.

use crate::cli::RenderArgs;
use crate::commands::{CliError, read_pattern, write_folder};
use crate::output::OutputSet;
use garmentcode::{Severity, validate};

pub fn run(args: RenderArgs) -> Result<i32, CliError> {
    let file = &args.file;
    let pattern = read_pattern(file)?;
    let errors: Vec<String> = validate(&pattern).iter().filter(|p| p.severity == Severity::Error).map(|p| p.to_string()).collect();
    if !errors.is_empty() {
        if !args.force {
            let shown: Vec<&str> = errors.iter().take(5).map(String::as_str).collect();
            return Err(CliError::Rejected(format!(
                "{file}: {} structural error(s), nothing drawn (`garmentcode check` lists them; --force draws anyway):\n  {}",
                errors.len(),
                shown.join("\n  ")
            )));
        }
        eprintln!("warning: {file}: drawing a pattern with {} structural error(s) (--force)", errors.len());
    }
    let mut set = OutputSet::default();
    set.add("specification.json", pattern.to_json().map_err(|e| CliError::Input(format!("{file}: {e}")))?);
    crate::commands::add_drawings_with(&mut set, &pattern, !args.no_png, &args.png.draw_options(args.layout.into()))
        .map_err(|e| CliError::Input(format!("{file}: {e}")))?;
    set.add_input(file);
    write_folder(&set, &args.out, args.force)?;
    eprintln!("wrote {}", args.out.display());
    Ok(0)
}
