//! Sub-commands of the `garmentcode` tool.

pub mod build;
pub mod check;
pub mod compare;
pub mod render;
pub mod sample;
pub mod schema;
pub mod serve;

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
    /// A valid design rejected by a requested check (exit 1).
    Rejected(String),
    /// Work started but did not complete (exit 1).
    Failed(String),
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

/// Add `pattern.svg` (and `pattern.png`) for a non-empty pattern, laid out as
/// asked.
pub fn add_drawings(set: &mut OutputSet, pattern: &Pattern, png: bool, layout: garmentcode::draw::Layout) -> garmentcode::Result<()> {
    let opts = garmentcode::draw::DrawOptions { layout, ..Default::default() };
    set.add("pattern.svg", garmentcode::draw::to_svg(pattern, &opts)?);
    if png {
        set.add("pattern.png", garmentcode::draw::to_png(pattern, &opts)?);
    }
    Ok(())
}

/// The design to build: a built-in name, a design file, or the default t-shirt.
pub fn load_design(arg: Option<&str>) -> Result<(garments::Design, String), CliError> {
    use garmentcode::Params;
    let name = arg.unwrap_or(garments::builtin::DEFAULT_DESIGN);
    if let Some(d) = garments::builtin::design(name) {
        return Ok((d, name.to_string()));
    }
    if !std::path::Path::new(name).exists() {
        let known: Vec<&str> = garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect();
        return Err(CliError::Input(format!("{name}: no such design file, and not a built-in design (built-in: {})", known.join(", "))));
    }
    let text = std::fs::read_to_string(name).map_err(|e| CliError::Input(format!("{name}: cannot read: {e}")))?;
    let d = garmentcode::io::read_design(&text, name, &garments::Design::design_space()).map_err(|e| CliError::Input(e.to_string()))?;
    let stem = std::path::Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "design".into());
    Ok((d, stem))
}

/// The body: a built-in name, a body file, or the neutral body.
pub fn load_body(arg: Option<&str>) -> Result<(garmentcode::Body, String), CliError> {
    let name = arg.unwrap_or(garments::builtin::DEFAULT_BODY);
    if let Some(b) = garments::builtin::body(name) {
        return Ok((b, name.to_string()));
    }
    if !std::path::Path::new(name).exists() {
        let known: Vec<&str> = garments::builtin::BODIES.iter().map(|(n, _)| *n).collect();
        return Err(CliError::Input(format!("{name}: no such body file, and not a built-in body (built-in: {})", known.join(", "))));
    }
    let text = std::fs::read_to_string(name).map_err(|e| CliError::Input(format!("{name}: cannot read: {e}")))?;
    let b = garmentcode::Body::from_yaml(&text, name).map_err(|e| CliError::Input(e.to_string()))?;
    Ok((b, name.to_string()))
}

/// `--layout placed|flat` (default placed, the reference's drawing).
pub fn layout_arg(args: &mut crate::args::Args, command: &str) -> Result<garmentcode::draw::Layout, CliError> {
    match args.value("layout")? {
        None => Ok(garmentcode::draw::Layout::Placed),
        Some(v) => v.parse().map_err(|e| CliError::Usage(format!("{command} --layout: {e}"))),
    }
}
