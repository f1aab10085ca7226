//! `garmentcode print SPEC.json --out DIR [--paper ...] [--seam CM] [--hem CM]
//! [--seam-edge PANEL[:EDGE]=CM]... [--fabric-width CM]`: the pattern as pieces to
//! print, cut and sew (see `garmentcode::fabricate`).

use crate::cli::PrintArgs;
use crate::commands::{CliError, read_pattern, write_folder};
use crate::output::OutputSet;
use garmentcode::fabricate::{PrintOptions, files};

pub fn run(args: PrintArgs) -> Result<i32, CliError> {
    let file = &args.file;
    let pattern = read_pattern(file)?;
    for o in &args.seam_edges {
        let panel = pattern.panel(&o.panel).ok_or_else(|| CliError::Usage(format!("--seam-edge: no panel '{}' in {file}", o.panel)))?;
        if o.edge.is_some_and(|e| e >= panel.edges.len()) {
            return Err(CliError::Usage(format!("--seam-edge: panel '{}' has {} edges", o.panel, panel.edges.len())));
        }
    }
    let opts = PrintOptions {
        seam: args.seam,
        hem: args.hem,
        edge_seams: args.seam_edges.clone(),
        paper: args.paper,
        fabric_width: args.fabric_width,
        garment: args
            .garment
            .clone()
            .unwrap_or_else(|| crate::commands::mesh::prefix(file).chars().take(garmentcode::io::MAX_NAME_CHARS).collect()),
        size: args.size.clone(),
    };
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
