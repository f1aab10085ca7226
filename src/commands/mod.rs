//! Sub-commands of the `garmentcode` tool.

pub mod build;
pub mod check;
pub mod compare;
pub mod drape;
pub mod guide;
pub mod mesh;
pub mod print;
pub mod render;
pub mod sample;
pub mod schema;
pub mod serve;

use crate::output::OutputSet;
use garmentcode::Pattern;
use std::path::Path;

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

/// The largest input file read (design, body, design space, pattern): real ones
/// are well under a megabyte, and the bound keeps a wrong argument (a disk image,
/// `/dev/zero`) from filling memory.
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// The text of an input file of at most [`MAX_INPUT_BYTES`]; the error says why
/// not, without the path.
pub fn read_text(path: impl AsRef<Path>) -> Result<String, String> {
    use std::io::Read;
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(|e| e.to_string())?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(format!("larger than {} MB, which no input file is", MAX_INPUT_BYTES >> 20));
    }
    String::from_utf8(bytes).map_err(|_| "not UTF-8 text".to_string())
}

/// Read and parse a specification file, naming the file in errors.
pub fn read_pattern(path: &str) -> Result<Pattern, CliError> {
    let text = read_text(path).map_err(|e| CliError::Input(format!("{path}: cannot read: {e}")))?;
    Pattern::from_json(&text).map_err(|e| CliError::Input(format!("{path}: {e}")))
}

/// Add `pattern.svg` (and `pattern.png`) for a non-empty pattern, laid out as
/// asked.
pub fn add_drawings(set: &mut OutputSet, pattern: &Pattern, png: bool, layout: garmentcode::draw::Layout) -> garmentcode::Result<()> {
    add_drawings_with(set, pattern, png, &garmentcode::draw::DrawOptions { layout, ..Default::default() })
}

/// Add `pattern.svg` (and `pattern.png`) drawn with `opts`.
pub fn add_drawings_with(
    set: &mut OutputSet,
    pattern: &Pattern,
    png: bool,
    opts: &garmentcode::draw::DrawOptions,
) -> garmentcode::Result<()> {
    set.add("pattern.svg", garmentcode::draw::to_svg(pattern, opts)?);
    if png {
        set.add("pattern.png", png_drawing(pattern, opts)?);
    }
    Ok(())
}

/// `pattern.png`, with a warning when the image had to be drawn at a lower
/// resolution than asked (it would have exceeded [`garmentcode::draw::MAX_PNG_PIXELS`]).
pub fn png_drawing(pattern: &Pattern, opts: &garmentcode::draw::DrawOptions) -> garmentcode::Result<Vec<u8>> {
    let png = garmentcode::draw::render_png(pattern, opts)?;
    if png.px_per_cm < opts.px_per_cm {
        eprintln!(
            "warning: pattern.png drawn at {:.2} px per cm (about {:.0} dpi) instead of {:.2}: at most {} million pixels are drawn",
            png.px_per_cm,
            png.px_per_cm * 2.54,
            opts.px_per_cm,
            garmentcode::draw::MAX_PNG_PIXELS / 1_000_000
        );
    }
    Ok(png.bytes)
}

/// Add a box mesh's files (streamed into the folder when it is written, none held
/// whole in memory).
pub fn add_mesh(set: &mut OutputSet, mesh: garmentcode::mesh::BoxMesh) {
    let files = std::sync::Arc::new(garmentcode::mesh::write::MeshFiles::new(std::borrow::Cow::Owned(mesh)));
    for (i, name) in files.names().into_iter().enumerate() {
        let files = std::sync::Arc::clone(&files);
        set.add_streamed(&name, move |out| files.write(i, out));
    }
}

/// Write an output folder whole (see [`OutputSet::write_folder`]).
pub fn write_folder(set: &OutputSet, dir: &Path, force: bool) -> Result<(), CliError> {
    set.write_folder(dir, force).map_err(|e| CliError::Input(format!("cannot write {}: {e}", dir.display())))
}

/// A built-in name (also written with a `.yaml` extension) unless `arg` is an
/// existing file.
fn builtin_name<'a>(arg: &'a str, known: &[&str]) -> Option<&'a str> {
    if Path::new(arg).is_file() {
        return None;
    }
    let name = arg.strip_suffix(".yaml").unwrap_or(arg);
    known.contains(&name).then_some(name)
}

/// ` (did you mean NAME?)` for the closest of `known`, when it is close.
pub fn did_you_mean(arg: &str, known: &[&str]) -> String {
    let stem = Path::new(arg).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let best = known.iter().map(|k| (strsim::levenshtein(&stem, k).min(strsim::levenshtein(arg, k)), *k)).min();
    match best {
        Some((d, k)) if d <= 3 && d < k.len() => format!(" (did you mean {k}?)"),
        _ => String::new(),
    }
}

/// Where a design or body comes from: a built-in name, or a file's text.
enum Source<'a> {
    Builtin(&'a str),
    File(String),
}

/// `arg` as one of the `known` built-in names (also with `.yaml`), or the text of
/// the file it names; `what` is "design" or "body" for the error.
fn source<'a>(arg: &'a str, known: &[&str], what: &str) -> Result<Source<'a>, CliError> {
    if let Some(name) = builtin_name(arg, known) {
        return Ok(Source::Builtin(name));
    }
    if !Path::new(arg).exists() {
        return Err(CliError::Input(format!(
            "{arg}: no such {what} file, and not a built-in {what}{} (built-in: {})",
            did_you_mean(arg, known),
            known.join(", ")
        )));
    }
    read_text(arg).map(Source::File).map_err(|e| CliError::Input(format!("{arg}: cannot read: {e}")))
}

/// The design to build: a built-in name or a design file.
pub fn load_design(arg: &str) -> Result<(garments::Design, String), CliError> {
    let known: Vec<&str> = garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect();
    match source(arg, &known, "design")? {
        Source::Builtin(name) => Ok((garments::builtin::design(name).expect("a built-in design"), name.to_string())),
        Source::File(text) => {
            let d = garmentcode::io::read_design(&text, arg, &garments::design::extended_design_space())
                .map_err(|e| CliError::Input(e.to_string()))?;
            let stem = Path::new(arg).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "design".into());
            Ok((d, stem))
        }
    }
}

/// The body: a built-in name or a body file.
pub fn load_body(arg: &str) -> Result<(garmentcode::Body, String), CliError> {
    let known: Vec<&str> = garments::builtin::BODIES.iter().map(|(n, _)| *n).collect();
    match source(arg, &known, "body")? {
        Source::Builtin(name) => Ok((garments::builtin::body(name).expect("a built-in body"), name.to_string())),
        Source::File(text) => {
            let b = garments::builtin::body_from_yaml(&text, arg).map_err(|e| CliError::Input(e.to_string()))?;
            Ok((b, arg.to_string()))
        }
    }
}

/// `garmentcode completions SHELL`.
pub fn completions(args: crate::cli::CompletionsArgs) -> Result<i32, CliError> {
    use clap::CommandFactory;
    let mut cmd = crate::cli::Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cmd, "garmentcode", &mut script);
    out!("{}", with_files(args.shell, &String::from_utf8_lossy(&script)));
    Ok(0)
}

/// The completion script with file names offered beside the built-in design and
/// body names (clap's scripts offer only a value's listed names).
fn with_files(shell: clap_complete::Shell, script: &str) -> String {
    use clap_complete::Shell;
    let lists = [
        garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect::<Vec<_>>(),
        garments::builtin::BODIES.iter().map(|(n, _)| *n).collect(),
    ];
    let mut script = script.to_string();
    for names in lists.iter().map(|l| l.join(" ")) {
        let (from, to) = match shell {
            Shell::Bash => (
                format!("COMPREPLY=($(compgen -W \"{names}\" -- \"${{cur}}\"))"),
                format!("COMPREPLY=($(compgen -W \"{names}\" -- \"${{cur}}\") $(compgen -f -- \"${{cur}}\"))"),
            ),
            Shell::Zsh => (format!(":({names})'"), format!(":{{compadd {names}; _files}}'")),
            Shell::Fish => (
                format!("-r -f -a \"{}", names.split(' ').next().unwrap_or_default()),
                format!("-r -F -a \"{}", names.split(' ').next().unwrap_or_default()),
            ),
            _ => continue,
        };
        script = script.replace(&from, &to);
    }
    script
}
