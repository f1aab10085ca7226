//! `garmentcode build`: a garment from a design and a body into a folder.

use crate::cli::{BuildArgs, BuildFormat};
use crate::commands::{CliError, load_body, load_design, write_folder};
use crate::output::OutputSet;
use garmentcode::Params;
use garmentcode::io::write_design;
use garmentcode::mesh::BoxMesh;
use garments::Design;
use garments::build::build;

pub fn run(args: BuildArgs) -> Result<i32, CliError> {
    let (design, design_label) = load_design(&args.design)?;
    let (body, body_label) = load_body(&args.body)?;
    let name = args.name.unwrap_or_else(|| design_label.clone());
    let built = build(&design, &body, &name).map_err(|e| CliError::Input(format!("{design_label} on {body_label}: {e}")))?;
    let warnings = built.checks.warnings();
    for w in &warnings {
        eprintln!("warning: {}", garmentcode_cli::explain_warning(w));
    }
    if args.strict && !warnings.is_empty() {
        return Err(CliError::Rejected(format!(
            "{design_label} on {body_label}: rejected by --strict ({} failed check(s)); nothing written",
            warnings.len()
        )));
    }
    let mut set = OutputSet::default();
    set.add("specification.json", built.pattern.to_json().map_err(|e| CliError::Input(e.to_string()))?);
    let wants = |f: BuildFormat| args.formats.contains(&f);
    let opts = args.png.draw_options(args.layout.into());
    if wants(BuildFormat::Svg) {
        set.add("pattern.svg", garmentcode::draw::to_svg(&built.pattern, &opts).map_err(|e| CliError::Input(e.to_string()))?);
    }
    if wants(BuildFormat::Png) && !args.no_png {
        set.add("pattern.png", garmentcode::draw::to_png(&built.pattern, &opts).map_err(|e| CliError::Input(e.to_string()))?);
    }
    if wants(BuildFormat::Mesh) {
        let mesh = BoxMesh::new(&built.pattern, args.mesh_resolution)
            .map_err(|e| CliError::Input(format!("{design_label} on {body_label}: cannot mesh: {e}")))?;
        for (file, bytes) in mesh.files() {
            set.add(&file, bytes);
        }
    }
    if wants(BuildFormat::Print) {
        let opts = garmentcode::fabricate::PrintOptions { garment: name.clone(), size: body_label.clone(), ..Default::default() };
        let files = garmentcode::fabricate::files(&built.pattern, &opts)
            .map_err(|e| CliError::Input(format!("{design_label} on {body_label}: cannot print: {e}")))?;
        for (file, bytes) in files {
            set.add(&file, bytes);
        }
    }
    set.add("design_params.yaml", write_design(&design, &Design::design_space()));
    set.add("body_measurements.yaml", body.to_yaml());
    set.add("checks.json", built.checks.to_json());
    write_folder(&set, &args.out, args.force)?;
    eprintln!(
        "wrote {}: {} panels, {} stitches ({design_label} on {body_label})",
        args.out.display(),
        built.pattern.panels.len(),
        built.pattern.stitches.len()
    );
    Ok(0)
}
