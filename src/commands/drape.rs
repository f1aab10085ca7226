//! `garmentcode drape SPEC.json|DESIGN --out DIR [--body NAME|FILE.yaml] [--body-mesh FILE.obj]
//! [--fabric NAME|FILE.yaml] [--resolution CM] [--max-frames N] [--max-seconds S]`: the
//! garment draped on a body, with the box mesh files, and the drape files [`drape_files`]
//! makes (shared with `build --formats drape` and `sample --formats drape`).

use std::io::IsTerminal;
use std::path::Path;
use std::time::Instant;

use crate::cli::DrapeArgs;
use crate::commands::{CliError, load_body, load_design, read_pattern, read_text, write_folder};
use crate::output::OutputSet;
use garmentcode::mesh::BoxMesh;
use garmentcode_drape::render::{Side, render_png};
use garmentcode_drape::{BodyMesh, Fabric, Next, Progress, Settings, Stats, Strain, drape_with_progress, glb, sim_obj};
use serde_json::{Value, json};

/// Exit status of a drape that did not settle or failed one of the reference's limits (its
/// files are written).
pub const EXIT_UNSETTLED: i32 = 3;

/// The reference's limits on a finished drape (`max_body_collisions`, `max_self_collisions`):
/// above them it records the simulation as failed.
pub const MAX_BODY_PENETRATIONS: usize = 35;
/// See [`MAX_BODY_PENETRATIONS`].
pub const MAX_SELF_INTERSECTIONS: usize = 300;

/// What a drape needs besides the garment.
pub struct DrapeSetup<'a> {
    /// The body mesh.
    pub body: &'a BodyMesh,
    /// Where the body mesh comes from ([`body_mesh_source`] or the file), for the record.
    pub body_source: &'a str,
    /// The measurements (attachment planes) and their label.
    pub measurements: (&'a garmentcode::Body, &'a str),
    /// The fabric.
    pub fabric: &'a Fabric,
    /// Frame limit (the reference's 2400 when `None`).
    pub max_frames: Option<usize>,
    /// Time limit of the simulation (s).
    pub max_seconds: f64,
    /// Threads of the simulation (0: every core; 1 when drapes run side by side, as
    /// `sample --jobs J` does). The result does not depend on it.
    pub threads: usize,
}

/// A finished drape: its files and figures.
pub struct Draped {
    /// `NAME_sim.obj`, `NAME_sim.glb`, `NAME_drape.json`, `NAME_render_front.png`,
    /// `NAME_render_back.png` (the suffixes of [`garmentcode_drape::FILE_SUFFIXES`]).
    pub files: Vec<(String, Vec<u8>)>,
    /// The simulation's figures.
    pub stats: Stats,
    /// Why the reference would count it as failed (its names: `static_equilibrium`,
    /// `simulation_timeout`, `cloth_body_intersection`, `cloth_self_intersection`); empty
    /// when it settled within the limits.
    pub fails: Vec<&'static str>,
}

/// The settings of a drape of `pattern` with `setup`.
fn settings(pattern: &garmentcode::Pattern, setup: &DrapeSetup) -> Settings {
    let mut s = setup.fabric.apply(Settings::for_body(setup.measurements.0).with_panel_labels(pattern));
    if let Some(n) = setup.max_frames {
        s.max_frames = n;
    }
    s.threads = setup.threads;
    s
}

/// Drapes `mesh` (the box mesh of `pattern`) as `setup` says and makes its files, calling
/// `on_frame` after every frame. An error (settings out of range, a simulation that
/// diverged) says why; nothing is made then.
pub fn drape_files(
    pattern: &garmentcode::Pattern,
    mesh: &BoxMesh,
    setup: &DrapeSetup,
    mut on_frame: impl FnMut(&Progress),
) -> Result<Draped, String> {
    let settings = settings(pattern, setup);
    let start = Instant::now();
    let mut timed_out = false;
    let result = drape_with_progress(mesh, setup.body, &settings, |p| {
        on_frame(p);
        if start.elapsed().as_secs_f64() > setup.max_seconds {
            timed_out = true;
            return Next::Stop;
        }
        Next::Continue
    })
    .map_err(|e| e.to_string())?;
    if let Some(i) = result.positions.iter().position(|p| !p.is_finite()) {
        return Err(format!("the simulation diverged (vertex {i} is not finite after {} frames)", result.stats.frames));
    }
    let stats = result.stats.clone();
    let mut fails = Vec::new();
    if timed_out {
        fails.push("simulation_timeout");
    } else if !stats.converged {
        fails.push("static_equilibrium");
    }
    if stats.body_penetrations > MAX_BODY_PENETRATIONS {
        fails.push("cloth_body_intersection");
    }
    if stats.self_intersections > MAX_SELF_INTERSECTIONS {
        fails.push("cloth_self_intersection");
    }
    let name = mesh.file_prefix();
    let x = &result.positions;
    let report = report_json(mesh, x, &stats, &fails, &settings, setup);
    let files = vec![
        (format!("{name}_sim.obj"), sim_obj(mesh, x).into_bytes()),
        (format!("{name}_sim.glb"), glb(mesh, x, Some(setup.body))),
        (format!("{name}_drape.json"), report.into_bytes()),
        (format!("{name}_render_front.png"), render_png(mesh, x, Some(setup.body), Side::Front)),
        (format!("{name}_render_back.png"), render_png(mesh, x, Some(setup.body), Side::Back)),
    ];
    Ok(Draped { files, stats, fails })
}

/// `NAME_drape.json`.
fn report_json(mesh: &BoxMesh, x: &[garmentcode::Vec3], stats: &Stats, fails: &[&str], s: &Settings, setup: &DrapeSetup) -> String {
    let strain = Strain::of(mesh, x);
    let (lo, hi) = setup.body.bounds();
    let attachments: Vec<Value> = s
        .attachments
        .iter()
        .map(|a| {
            json!({
                "label": a.label, "point": a.point.to_array(), "normal": a.normal.to_array(),
                "stiffness": a.stiffness, "damping": a.damping,
            })
        })
        .collect();
    let fabric: serde_json::Map<String, Value> = std::iter::once(("name".to_string(), json!(setup.fabric.name)))
        .chain(setup.fabric.values().map(|(k, v)| (k.to_string(), json!(v))))
        .collect();
    let v = json!({
        "name": mesh.file_prefix(),
        "converged": stats.converged,
        "at_rest": stats.at_rest,
        "fails": fails,
        "frames": stats.frames,
        "seconds": (stats.seconds * 1000.0).round() / 1000.0,
        "vertices": mesh.vertices.len(),
        "faces": mesh.faces.len(),
        "non_static_vertices": stats.non_static_vertices,
        "body_penetrations": stats.body_penetrations,
        "self_intersections": stats.self_intersections,
        "strain": {
            "about": "|length / rest length - 1| of the mesh edges: stitch edges against their 2D pattern lengths, the others against the box mesh",
            "seam": { "edges": strain.seam_edges, "p50": strain.seam_p50, "p99": strain.seam_p99 },
            "fabric": { "edges": strain.fabric_edges, "p50": strain.fabric_p50, "p99": strain.fabric_p99 },
        },
        "body": {
            "measurements": setup.measurements.1,
            "mesh": setup.body_source,
            "vertices": setup.body.vertices.len(),
            "faces": setup.body.faces.len(),
            "height_cm": hi.y - lo.y,
        },
        "fabric": fabric,
        "settings": {
            "resolution_cm": mesh.resolution,
            "fps": s.fps, "substeps": s.substeps, "max_frames": s.max_frames, "max_seconds": setup.max_seconds,
            "zero_gravity_frames": s.zero_gravity_frames, "gravity": s.gravity,
            "particle_radius": s.particle_radius, "body_friction": s.body_friction, "body_thickness": s.body_thickness,
            "contact_margin": s.contact_margin, "contact_relaxation": s.contact_relaxation,
            "damping": s.damping, "damping_velocity": s.damping_velocity, "max_velocity": s.max_velocity,
            "attachment_frames": s.attachment_frames, "attachments": attachments,
            "static_threshold": s.static_threshold, "non_static_percent": s.non_static_percent,
            "body_drag": s.body_drag, "reference_margin": s.reference_margin, "self_collision": s.self_collision,
            "untangle": s.untangle, "untangle_frames": s.untangle_frames,
            "max_body_penetrations": MAX_BODY_PENETRATIONS, "max_self_intersections": MAX_SELF_INTERSECTIONS,
        },
    });
    serde_json::to_string_pretty(&v).expect("a JSON value serialises") + "\n"
}

/// The fabric of `--fabric`: a built-in name, or a fabric file.
pub fn load_fabric(arg: &str) -> Result<Fabric, CliError> {
    let builtin = garmentcode_drape::fabric::BUILTIN;
    let name = arg.strip_suffix(".yaml").unwrap_or(arg);
    if !Path::new(arg).is_file() && builtin.contains(&name) {
        return Fabric::builtin(name).map_err(|e| CliError::Input(e.to_string()));
    }
    if !Path::new(arg).exists() {
        return Err(CliError::Input(format!(
            "{arg}: no such fabric file, and not a built-in fabric{} (built-in: {})",
            crate::commands::did_you_mean(arg, &builtin),
            builtin.join(", ")
        )));
    }
    let text = read_text(arg).map_err(|e| CliError::Input(format!("{arg}: cannot read: {e}")))?;
    Fabric::from_yaml(&text, arg).map_err(|e| CliError::Input(e.to_string()))
}

/// The body mesh: `--body-mesh FILE.obj`, or the mesh of the body `name` (its measurements
/// `body`); with where it came from.
pub fn load_body_mesh(file: Option<&Path>, name: &str, body: &garmentcode::Body) -> Result<(BodyMesh, String), CliError> {
    match file {
        Some(f) => BodyMesh::load(f).map(|m| (m, f.display().to_string())).map_err(|e| CliError::Input(e.to_string())),
        None => {
            let name = body_mesh_name(name, body);
            BodyMesh::for_body(&name, body).map(|m| (m, body_mesh_source(&name))).map_err(|e| CliError::Input(e.to_string()))
        }
    }
}

/// The name to ask [`BodyMesh::for_body`] for the body `name` with measurements `body`:
/// `name` itself when it is a built-in body with exactly those measurements (its own
/// mesh), else a name no built-in body has (a mannequin of the measurements), so that
/// an edited body or a body file named like a built-in one is not draped on the
/// built-in mesh.
pub fn body_mesh_name(name: &str, body: &garmentcode::Body) -> String {
    let unnamed = |b: &garmentcode::Body| garmentcode::Body { body_sample: None, ..b.clone() };
    match garments::builtin::body(name) {
        Some(builtin) if unnamed(&builtin) == unnamed(body) => name.to_string(),
        Some(_) => format!("{name} (edited)"),
        None => name.to_string(),
    }
}

/// How `NAME_drape.json` names the mesh [`BodyMesh::for_body`] gives for the body `name`.
pub fn body_mesh_source(name: &str) -> String {
    if garmentcode_drape::body::BUILTIN.iter().any(|(n, _)| *n == name) {
        format!("the built-in mesh of body {name}")
    } else {
        format!("a mannequin made from the measurements of {name}")
    }
}

/// A progress line on stderr every 50 frames (overwritten in place on a terminal).
pub struct ProgressLine {
    tty: bool,
    quiet: bool,
}

impl ProgressLine {
    /// Progress for a run, silent when `quiet`.
    pub fn new(quiet: bool) -> ProgressLine {
        ProgressLine { tty: std::io::stderr().is_terminal(), quiet }
    }

    /// Shows frame `p` when due.
    pub fn frame(&mut self, p: &Progress) {
        if self.quiet || !p.frame.is_multiple_of(50) {
            return;
        }
        let line = format!("drape: frame {}/{} ({} vertices moving)", p.frame, p.max_frames, p.non_static_vertices);
        if self.tty {
            eprint!("\r{line}\x1b[K");
        } else {
            eprintln!("{line}");
        }
    }

    /// Ends a line left open on a terminal.
    pub fn finish(&self) {
        if self.tty && !self.quiet {
            eprint!("\r\x1b[K");
        }
    }
}

pub fn run(args: DrapeArgs) -> Result<i32, CliError> {
    let (measurements, body_label) = load_body(&args.body)?;
    let fabric = load_fabric(&args.sim.fabric)?;
    if let Some(name) = &args.name {
        garmentcode::io::check_name("--name", name).map_err(|e| CliError::Usage(e.to_string()))?;
    }
    let is_pattern = args.garment.ends_with(".json");
    let mut set = OutputSet::default();
    let mut pattern = if is_pattern {
        let mut p = read_pattern(&args.garment)?;
        p.name = crate::commands::mesh::prefix(&args.garment);
        p
    } else {
        let (design, label) = load_design(&args.garment)?;
        let built =
            garments::build::build(&design, &measurements, &label).map_err(|e| CliError::Input(format!("{label} on {body_label}: {e}")))?;
        for w in built.checks.warnings() {
            eprintln!("warning: {}", crate::explain_warning(&w));
        }
        built.pattern
    };
    if let Some(name) = &args.name {
        pattern.name = name.clone();
    }
    if pattern.name.is_empty() || pattern.name.contains(['/', '\\']) {
        return Err(CliError::Usage(format!("--name: '{}' is not a file name prefix", pattern.name)));
    }
    let (body, body_source) = load_body_mesh(args.body_mesh.as_deref(), &body_label, &measurements)?;
    let mesh =
        BoxMesh::new(&pattern, args.resolution).map_err(|e| CliError::Input(format!("{}: cannot mesh the pattern: {e}", args.garment)))?;
    let setup = DrapeSetup {
        body: &body,
        body_source: &body_source,
        measurements: (&measurements, &body_label),
        fabric: &fabric,
        max_frames: args.sim.max_frames.map(|n| n as usize),
        max_seconds: args.sim.max_seconds,
        threads: 0,
    };
    let mut progress = ProgressLine::new(args.quiet);
    let draped = drape_files(&pattern, &mesh, &setup, |p| progress.frame(p));
    progress.finish();
    let draped = draped.map_err(|e| CliError::Input(format!("{}: cannot drape on {}: {e}", args.garment, body.name)))?;
    set.add(
        &format!("{}_specification.json", pattern.name),
        pattern.to_json().map_err(|e| CliError::Input(format!("{}: {e}", args.garment)))?,
    );
    for (name, bytes) in mesh.files().into_iter().chain(draped.files) {
        set.add(&name, bytes);
    }
    for input in [Some(args.garment.as_str()), Some(args.body.as_str()), Some(args.sim.fabric.as_str())].into_iter().flatten() {
        set.add_input(input);
    }
    if let Some(f) = &args.body_mesh {
        set.add_input(f);
    }
    write_folder(&set, &args.out, args.force)?;
    let s = &draped.stats;
    eprintln!(
        "wrote {}: {} vertices draped in {} frames ({:.2} s), {}; {} body penetrations, {} self-intersections",
        args.out.display(),
        mesh.vertices.len(),
        s.frames,
        s.seconds,
        match (s.converged, s.at_rest) {
            (true, true) => "settled".to_string(),
            (true, false) => format!(
                "stopped after the attachments' release as the reference's drapes stop, {} vertices still moving",
                s.non_static_vertices
            ),
            (false, _) => "did not settle".to_string(),
        },
        s.body_penetrations,
        s.self_intersections
    );
    if draped.fails.is_empty() {
        Ok(0)
    } else {
        eprintln!("drape failed the reference's checks: {} (exit status {EXIT_UNSETTLED})", draped.fails.join(", "));
        Ok(EXIT_UNSETTLED)
    }
}

#[cfg(test)]
mod body_mesh_tests {
    use super::body_mesh_name;

    #[test]
    fn only_a_built_in_body_as_it_is_drapes_on_its_built_in_mesh() {
        let mut body = garments::builtin::body("mean_all").unwrap();
        body.body_sample = Some("mean_all_apart".into());
        assert_eq!(body_mesh_name("mean_all", &body), "mean_all", "the sampler's pose name does not matter");
        body.waist += 10.0;
        assert_eq!(body_mesh_name("mean_all", &body), "mean_all (edited)", "an edited body gets a mannequin");
        assert_eq!(body_mesh_name("me", &body), "me");
    }
}
