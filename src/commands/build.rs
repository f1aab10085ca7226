//! `garmentcode build`: a garment from a design and a body into a folder.

use crate::cli::{BuildArgs, BuildFormat};
use crate::commands::drape::{DrapeSetup, EXIT_UNSETTLED, ProgressLine, drape_files, load_body_mesh, load_fabric};
use crate::commands::{CliError, load_body, load_design, write_folder};
use crate::output::OutputSet;
use garmentcode::io::write_design;
use garmentcode::mesh::BoxMesh;
use garments::Design;
use garments::build::build;

pub fn run(args: BuildArgs) -> Result<i32, CliError> {
    let (design, design_label) = load_design(&args.design)?;
    let (body, body_label) = load_body(&args.body)?;
    let name = args.name.clone().unwrap_or_else(|| design_label.clone());
    let built = build(&design, &body, &name).map_err(|e| CliError::Input(format!("{design_label} on {body_label}: {e}")))?;
    let warnings = built.checks.warnings();
    for w in &warnings {
        eprintln!("warning: {}", crate::explain_warning(w));
    }
    if args.strict && !warnings.is_empty() {
        return Err(CliError::Rejected(format!(
            "{design_label} on {body_label}: rejected by --strict ({} failed check(s)); nothing written",
            warnings.len()
        )));
    }
    let wanted: Vec<BuildFormat> = args.formats.iter().copied().filter(|&f| !(f == BuildFormat::Png && args.no_png)).collect();
    let origin = Origin { design: &design, body: &body, checks: &built.checks };
    let draw = args.png.draw_options(args.layout.into());
    let print = garmentcode::fabricate::PrintOptions { garment: name.clone(), size: body_label.clone(), ..Default::default() };
    let drape = wanted.contains(&BuildFormat::Drape);
    // The drape adds the mesh files itself, meshing once.
    let others: Vec<BuildFormat> = wanted.iter().copied().filter(|&f| !(drape && f == BuildFormat::Mesh)).collect();
    let mut set = files(&built.pattern, Some(origin), &others, &draw, args.mesh_resolution, &print)
        .map_err(|e| CliError::Input(format!("{design_label} on {body_label}: {e}")))?;
    let mut status = 0;
    if drape {
        let fails = add_drape(&mut set, &built.pattern, &args, (&body, &body_label))?;
        if !fails.is_empty() {
            eprintln!("drape failed the reference's checks: {} (exit status {EXIT_UNSETTLED})", fails.join(", "));
            status = EXIT_UNSETTLED;
        }
        set.add_input(&args.sim.fabric);
        if let Some(f) = &args.body_mesh {
            set.add_input(f);
        }
    }
    set.add_input(&args.design);
    set.add_input(&args.body);
    write_folder(&set, &args.out, args.force)?;
    eprintln!(
        "wrote {}: {} panels, {} stitches ({design_label} on {body_label})",
        args.out.display(),
        built.pattern.panels.len(),
        built.pattern.stitches.len()
    );
    Ok(status)
}

/// `--formats ...,drape`: the box mesh files and the drape files of `pattern` on `body`
/// (measurements and label); returns the reference's failure reasons of the drape.
fn add_drape(
    set: &mut OutputSet,
    pattern: &garmentcode::Pattern,
    args: &BuildArgs,
    body: (&garmentcode::Body, &str),
) -> Result<Vec<&'static str>, CliError> {
    let fail = |e: String| CliError::Input(format!("{}: {e}", pattern.name));
    let fabric = load_fabric(&args.sim.fabric)?;
    let (body_mesh, source) = load_body_mesh(args.body_mesh.as_deref(), body.1, body.0)?;
    let mesh = BoxMesh::new(pattern, args.mesh_resolution).map_err(|e| fail(format!("cannot mesh the pattern: {e}")))?;
    let setup = DrapeSetup {
        body: &body_mesh,
        body_source: &source,
        measurements: body,
        fabric: &fabric,
        max_frames: args.sim.max_frames.map(|n| n as usize),
        max_seconds: args.sim.max_seconds,
        threads: 0,
    };
    let mut progress = ProgressLine::new(false);
    let draped = drape_files(pattern, &mesh, &setup, |p| progress.frame(p));
    progress.finish();
    let draped = draped.map_err(|e| fail(format!("cannot drape on {}: {e}", body_mesh.name)))?;
    for (file, bytes) in mesh.files().into_iter().chain(draped.files) {
        set.add(&file, bytes);
    }
    Ok(draped.fails)
}

/// What a built pattern was made of, for the files that record it.
#[derive(Clone, Copy)]
pub struct Origin<'a> {
    /// The design.
    pub design: &'a Design,
    /// The body.
    pub body: &'a garmentcode::Body,
    /// The validity checks of the build.
    pub checks: &'a garments::build::Checks,
}

/// The files `build` writes for a pattern, in the asked formats: the specification,
/// the drawings (drawn with `draw`), the mesh files, the printable pattern (with
/// `print`), and (for a pattern built here, with its `origin`) the design, the body
/// and the checks. An error says what failed (the caller names the design).
pub fn files(
    pattern: &garmentcode::Pattern,
    origin: Option<Origin>,
    formats: &[BuildFormat],
    draw: &garmentcode::draw::DrawOptions,
    mesh_resolution: f64,
    print: &garmentcode::fabricate::PrintOptions,
) -> Result<OutputSet, String> {
    let mut set = OutputSet::default();
    set.add("specification.json", pattern.to_json().map_err(|e| e.to_string())?);
    if formats.contains(&BuildFormat::Svg) {
        set.add("pattern.svg", garmentcode::draw::to_svg(pattern, draw).map_err(|e| e.to_string())?);
    }
    if formats.contains(&BuildFormat::Png) {
        set.add("pattern.png", crate::commands::png_drawing(pattern, draw).map_err(|e| e.to_string())?);
    }
    if formats.contains(&BuildFormat::Mesh) {
        let mesh = BoxMesh::new(pattern, mesh_resolution).map_err(|e| format!("cannot mesh the pattern: {e}"))?;
        crate::commands::add_mesh(&mut set, mesh);
    }
    if formats.contains(&BuildFormat::Print) {
        for (file, bytes) in garmentcode::fabricate::files(pattern, print).map_err(|e| format!("cannot print: {e}"))? {
            set.add(&file, bytes);
        }
    }
    if let Some(o) = origin {
        set.add("design_params.yaml", write_design(o.design, &garments::design::space_of(o.design)));
        set.add("body_measurements.yaml", o.body.to_yaml());
        set.add("checks.json", o.checks.to_json());
    }
    Ok(set)
}
