//! Drapes a pattern and writes the box mesh files and `<name>_sim.obj` into a folder, for
//! judging with the reference's tools:
//!
//! `cargo run --release -p garmentcode-drape --example drape_case -- SPEC.json BODY.obj BODY.yaml OUT_DIR [MAX_FRAMES [BODY_PARTS.json]]`
//!
//! `BODY.obj` may also be the name of a built-in body (`mean_all`, ...): its mesh and parts.
//!
//! `DRAPE_THREADS=N` runs on N threads (default: all; the positions do not depend on it).
//!
//! Experiments: `DRAPE_SELF_COLLISION=0` turns self-collision off; `DRAPE_UNTANGLE=0` leaves
//! new crossings alone (as the reference does); `DRAPE_SETTLE=1` runs on after the release until
//! the garment is static (`Settings::stop_at_release` off); `DRAPE_TRACE=K` writes the garment every K
//! frames as `OUT_DIR/trace/FRAME_sim.obj` (to see where crossings start); `DRAPE_JITTER=CM`
//! moves the interior vertices of every panel by up to CM in the panel's plane; `DRAPE_BOXMESH=CASE_DIR`
//! drapes the reference's own box mesh of a case folder instead of ours (its
//! `CASE_boxmesh.obj`, `CASE_sim_segmentation.txt`, `CASE_vertex_labels.yaml`, and the rest
//! lengths of `CASE_orig_lens.pickle` written as `i j length` lines to `OUT_DIR/orig_lens.txt`,
//! e.g. with `python3 -c "import pickle,sys; [print(i, j, l) for (i, j), l in pickle.load(open(sys.argv[1], 'rb')).items()]"`);
//! only `OUT_DIR/<case>_sim.obj` is written then (copy the case's other files next to it to judge).
//! `DRAPE_STATS=FROM` prints a line per frame to stderr (frame index from 0, vertices moving more
//! than the static threshold, max and mean speed in cm/s, mean y of `lower_interface`, body
//! contacts: the columns of the reference's trace, see docs/drape.md; then the crossings found
//! at the frame's start) and writes the positions of
//! frames `FROM` on as little-endian `f32` triples to `OUT_DIR/trace/ours_FRAME.f32`.

use std::path::Path;

use garmentcode::mesh::{BoxMesh, MeshFace, VertexLabel};
use garmentcode_drape::{BodyMesh, Next, Settings, drape_with_progress, sim_obj};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [spec, body, measurements, out, rest @ ..] = args.as_slice() else {
        return Err("usage: drape_case SPEC.json BODY.obj|BODY_NAME BODY.yaml OUT_DIR [MAX_FRAMES [BODY_PARTS.json]]".into());
    };
    let out = Path::new(out);
    let pattern = garmentcode::Pattern::from_json(&std::fs::read_to_string(spec)?)?;
    let mut mesh = BoxMesh::new(&pattern, garmentcode::mesh::DEFAULT_RESOLUTION)?;
    let reference = std::env::var("DRAPE_BOXMESH").ok();
    if let Some(dir) = &reference {
        mesh = reference_mesh(mesh, Path::new(dir), &out.join("orig_lens.txt"))?;
    }
    let measurements = garmentcode::Body::from_yaml(&std::fs::read_to_string(measurements)?, measurements)?;
    if let Some(amount) = std::env::var("DRAPE_JITTER").ok().and_then(|a| a.parse::<f64>().ok()) {
        jitter(&mut mesh, amount);
    }
    let mut body = match body.strip_suffix(".obj") {
        Some(_) => BodyMesh::load(body.as_ref())?,
        None => BodyMesh::for_body(body, &measurements)?,
    };
    if let Some(parts) = rest.get(1) {
        body = body.with_parts_json(&std::fs::read_to_string(parts)?, parts)?;
    }
    let mut settings = Settings::for_body(&measurements).with_panel_labels(&pattern);
    if let Some(frames) = rest.first() {
        settings.max_frames = frames.parse()?;
    }
    if let Some(threads) = std::env::var("DRAPE_THREADS").ok().and_then(|t| t.parse().ok()) {
        settings.threads = threads;
    }
    if std::env::var("DRAPE_SELF_COLLISION").is_ok_and(|v| v == "0") {
        settings.self_collision = false;
    }
    if std::env::var("DRAPE_SETTLE").is_ok_and(|v| v == "1") {
        settings.stop_at_release = false;
    }
    if std::env::var("DRAPE_UNTANGLE").is_ok_and(|v| v == "0") {
        settings.untangle = false;
    }
    std::fs::create_dir_all(out)?;
    let trace: Option<usize> = std::env::var("DRAPE_TRACE").ok().and_then(|k| k.parse().ok()).filter(|&k| k > 0);
    let mut written = Ok(());
    let stats_from: Option<usize> = std::env::var("DRAPE_STATS").ok().and_then(|k| k.parse().ok());
    let lower: Vec<usize> = mesh.vertex_labels.iter().find(|(l, _)| l == "lower_interface").map(|(_, v)| v.clone()).unwrap_or_default();
    let mut last = mesh.vertices.clone();
    if stats_from.is_some() {
        eprintln!("frame nonstatic maxspeed meanspeed lower_y contacts crossings");
    }
    let result = drape_with_progress(&mesh, &body, &settings, |progress| {
        if let Some(from) = stats_from {
            let frame = progress.frame - 1;
            let speeds: Vec<f64> = progress.positions.iter().zip(&last).map(|(a, b)| (*a - *b).length() * settings.fps).collect();
            let lower_y = lower.iter().map(|&i| progress.positions[i].y).sum::<f64>() / lower.len().max(1) as f64;
            eprintln!(
                "{frame} {} {:.4} {:.5} {lower_y:.4} {} {}",
                progress.non_static_vertices,
                speeds.iter().fold(0.0f64, |m, &s| m.max(s)),
                speeds.iter().sum::<f64>() / speeds.len() as f64,
                progress.body_contacts,
                progress.crossings
            );
            last.copy_from_slice(progress.positions);
            if frame >= from {
                let bytes: Vec<u8> =
                    progress.positions.iter().flat_map(|p| [p.x as f32, p.y as f32, p.z as f32]).flat_map(f32::to_le_bytes).collect();
                let dir = out.join("trace");
                written = written
                    .clone()
                    .and(std::fs::create_dir_all(&dir).map_err(|e| e.to_string()))
                    .and(std::fs::write(dir.join(format!("ours_{frame:05}.f32")), bytes).map_err(|e| e.to_string()));
            }
        }
        if let Some(k) = trace
            && progress.frame % k == 0
        {
            eprintln!("frame {}: {} vertices moving", progress.frame, progress.non_static_vertices);
            let dir = out.join("trace");
            written = written.clone().and(std::fs::create_dir_all(&dir).map_err(|e| e.to_string())).and(
                std::fs::write(dir.join(format!("{:05}_sim.obj", progress.frame)), sim_obj(&mesh, progress.positions))
                    .map_err(|e| e.to_string()),
            );
        }
        Next::Continue
    })?;
    written?;
    if reference.is_some() {
        let mut obj = String::new();
        for p in &result.positions {
            obj += &format!("v {} {} {}\n", p.x as f32, p.y as f32, p.z as f32);
        }
        for f in &mesh.faces {
            obj += &format!("f {} {} {}\n", f.vertices[0] + 1, f.vertices[1] + 1, f.vertices[2] + 1);
        }
        std::fs::write(out.join(format!("{}_sim.obj", mesh.name)), obj)?;
    } else {
        mesh.write_files(out)?;
        std::fs::write(out.join(format!("{}_sim.obj", mesh.file_prefix())), sim_obj(&mesh, &result.positions))?;
    }
    println!("{} vertices: {:?}", mesh.vertices.len(), result.stats);
    Ok(())
}

/// Moves every interior vertex of every panel (but those of faces along a seam) by up to
/// `amount` cm in its panel's plane (a fixed pseudo-random offset per vertex), so that the
/// mesh is no longer a lattice.
fn jitter(mesh: &mut BoxMesh, amount: f64) {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    // Vertices of faces along a seam keep their place: their rest lengths are given.
    let fixed: std::collections::HashSet<usize> = mesh.rest_lengths.iter().flat_map(|(e, _)| *e).collect();
    for panel in &mesh.panels {
        for local in panel.n_boundary..panel.points.len() {
            let offset = garmentcode::Vec2::new(next(), next()) * amount;
            if !fixed.contains(&panel.global[local]) {
                mesh.vertices[panel.global[local]] = panel.to_3d(panel.points[local] + offset);
            }
        }
    }
}

/// Our box mesh's panels with the vertices, faces, segmentation, labels and rest lengths of
/// the reference's box mesh in `dir` (enough to drape it, not to write its files).
fn reference_mesh(ours: BoxMesh, dir: &Path, rest_lengths: &Path) -> Result<BoxMesh, Box<dyn std::error::Error>> {
    let case = dir.file_name().and_then(|n| n.to_str()).ok_or("case folder name")?.to_string();
    let read = |suffix: &str| std::fs::read_to_string(dir.join(format!("{case}_{suffix}")));
    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for line in read("boxmesh.obj")?.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let c: Vec<f64> = words.map(str::parse).collect::<Result<_, _>>()?;
                vertices.push(garmentcode::Vec3::new(c[0], c[1], c[2]));
            }
            Some("f") => {
                let v: Vec<usize> =
                    words.map(|w| w.split('/').next().unwrap_or("").parse::<usize>().map(|i| i - 1)).collect::<Result<_, _>>()?;
                faces.push(MeshFace { vertices: [v[0], v[1], v[2]], uvs: [0; 3], panel: 0 });
            }
            _ => {}
        }
    }
    let labels: Vec<VertexLabel> = read("sim_segmentation.txt")?
        .lines()
        .map(|l| match ours.panels.iter().position(|p| p.name == l.trim()) {
            Some(p) => Ok(VertexLabel::Panel(p)),
            None if l.starts_with("stitch") => Ok(VertexLabel::Stitch(vec![0])),
            None => Err(format!("unknown panel {l}")),
        })
        .collect::<Result<_, _>>()?;
    let mut vertex_labels: Vec<(String, Vec<usize>)> = Vec::new();
    for line in read("vertex_labels.yaml")?.lines() {
        if let Some(id) = line.trim().strip_prefix("- ") {
            vertex_labels.last_mut().ok_or("labels")?.1.push(id.parse()?);
        } else if let Some(name) = line.trim().strip_suffix(':') {
            vertex_labels.push((name.to_string(), Vec::new()));
        }
    }
    let rest_lengths = std::fs::read_to_string(rest_lengths)?
        .lines()
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            Ok(([w[0].parse()?, w[1].parse()?], w[2].parse()?))
        })
        .collect::<Result<_, Box<dyn std::error::Error>>>()?;
    Ok(BoxMesh { name: case, vertices, labels, n_stitch_vertices: 0, faces, rest_lengths, vertex_labels, ..ours })
}
