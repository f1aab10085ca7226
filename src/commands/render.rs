//! `garmentcode render SPEC.json --out DIR [--no-png] [--layout placed|flat]`: re-emit
//! the pattern and draw it.

use crate::args::{Args, UsageError};
use crate::commands::{CliError, read_pattern};
use crate::output::OutputSet;
use std::path::PathBuf;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let out = args.value("out")?.ok_or_else(|| UsageError("render: --out DIR is required".into()))?;
    let no_png = args.switch("no-png");
    let layout = crate::commands::layout_arg(&mut args, "render")?;
    let files = args.finish()?;
    let [file] = files.as_slice() else {
        return Err(UsageError("render: expects exactly one SPEC.json file".into()).into());
    };
    let pattern = read_pattern(file)?;
    let mut set = OutputSet::default();
    set.add("specification.json", pattern.to_json().map_err(|e| CliError::Input(format!("{file}: {e}")))?);
    crate::commands::add_drawings(&mut set, &pattern, !no_png, layout).map_err(|e| CliError::Input(format!("{file}: {e}")))?;
    let dir = PathBuf::from(&out);
    set.write(&dir).map_err(|e| CliError::Input(format!("cannot write {}: {e}", dir.display())))?;
    eprintln!("wrote {}", dir.display());
    Ok(0)
}
