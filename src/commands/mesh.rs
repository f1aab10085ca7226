//! `garmentcode mesh SPEC.json --out DIR [--resolution CM] [--name NAME] [--force]`: the
//! reference's simulation box mesh of a pattern and its files.

use std::path::Path;

use crate::cli::MeshArgs;
use crate::commands::{CliError, add_mesh, read_pattern, write_folder};
use crate::output::OutputSet;
use garmentcode::mesh::BoxMesh;

/// The file name prefix: the spec's name without `_specification.json`, or for a plain
/// `specification.json` its folder's name.
pub(crate) fn prefix(file: &str) -> String {
    let path = Path::new(file);
    let stem = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    if let Some(name) = stem.strip_suffix("_specification").filter(|n| !n.is_empty()) {
        return name.to_string();
    }
    if stem == "specification" {
        let folder =
            std::fs::canonicalize(path).ok().and_then(|p| p.parent().and_then(|d| d.file_name()).map(|n| n.to_string_lossy().into_owned()));
        if let Some(folder) = folder {
            return folder;
        }
    }
    stem
}

pub fn run(args: MeshArgs) -> Result<i32, CliError> {
    let file = &args.file;
    let mut pattern = read_pattern(file)?;
    if let Some(name) = &args.name {
        garmentcode::io::check_name("--name", name).map_err(|e| CliError::Usage(e.to_string()))?;
    }
    pattern.name = args.name.clone().unwrap_or_else(|| prefix(file));
    if pattern.name.is_empty() || pattern.name.contains(['/', '\\']) {
        return Err(CliError::Usage(format!("--name: '{}' is not a file name prefix", pattern.name)));
    }
    let mesh = BoxMesh::new(&pattern, args.resolution).map_err(|e| CliError::Input(format!("{file}: cannot mesh the pattern: {e}")))?;
    let summary =
        format!("{} vertices, {} of them on stitches, {} triangles", mesh.vertices.len(), mesh.n_stitch_vertices, mesh.faces.len());
    let mut set = OutputSet::default();
    set.add(&format!("{}_specification.json", pattern.name), pattern.to_json().map_err(|e| CliError::Input(format!("{file}: {e}")))?);
    add_mesh(&mut set, mesh);
    set.add_input(file);
    write_folder(&set, &args.out, args.force)?;
    eprintln!("wrote {} ({summary})", args.out.display());
    Ok(0)
}
