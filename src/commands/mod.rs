//! Sub-commands of the `garmentcode` tool.

pub mod check;
pub mod render;

use crate::args::UsageError;
use crate::output::OutputSet;
use garmentcode::Pattern;

/// Why a command failed.
#[derive(Debug)]
pub enum CliError {
    /// Wrong command line (exit 2).
    Usage(String),
    /// Unreadable or invalid input, or a design that cannot be built (exit 2).
    Input(String),
}

impl From<UsageError> for CliError {
    fn from(e: UsageError) -> Self {
        CliError::Usage(e.0)
    }
}

/// Read and parse a specification file, naming the file in errors.
pub fn read_pattern(path: &str) -> Result<Pattern, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::Input(format!("{path}: cannot read: {e}")))?;
    Pattern::from_json(&text).map_err(|e| CliError::Input(format!("{path}: {e}")))
}

/// Add `pattern.svg` (and `pattern.png`) for a non-empty pattern.
pub fn add_drawings(set: &mut OutputSet, pattern: &Pattern, png: bool) -> garmentcode::Result<()> {
    let opts = garmentcode::draw::DrawOptions::default();
    set.add("pattern.svg", garmentcode::draw::to_svg(pattern, &opts)?);
    if png {
        set.add("pattern.png", garmentcode::draw::to_png(pattern, &opts)?);
    }
    Ok(())
}
