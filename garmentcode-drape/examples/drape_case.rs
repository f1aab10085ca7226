//! Drapes a pattern and writes the box mesh files and `<name>_sim.obj` into a folder, for
//! judging with the reference's tools:
//!
//! `cargo run --release -p garmentcode-drape --example drape_case -- SPEC.json BODY.obj BODY.yaml OUT_DIR [MAX_FRAMES [BODY_PARTS.json]]`

use garmentcode_drape::{BodyMesh, Settings, drape, sim_obj};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [spec, body, measurements, out, rest @ ..] = args.as_slice() else {
        return Err("usage: drape_case SPEC.json BODY.obj BODY.yaml OUT_DIR [MAX_FRAMES [BODY_PARTS.json]]".into());
    };
    let pattern = garmentcode::Pattern::from_json(&std::fs::read_to_string(spec)?)?;
    let mesh = garmentcode::mesh::BoxMesh::new(&pattern, garmentcode::mesh::DEFAULT_RESOLUTION)?;
    let mut body = BodyMesh::load(body.as_ref())?;
    if let Some(parts) = rest.get(1) {
        body = body.with_parts_json(&std::fs::read_to_string(parts)?, parts)?;
    }
    let measurements = garmentcode::Body::from_yaml(&std::fs::read_to_string(measurements)?, measurements)?;
    let mut settings = Settings::for_body(&measurements).with_panel_labels(&pattern);
    if let Some(frames) = rest.first() {
        settings.max_frames = frames.parse()?;
    }
    // Experiments: DRAPE_SELF_COLLISION=0 turns self-collision off.
    if std::env::var("DRAPE_SELF_COLLISION").is_ok_and(|v| v == "0") {
        settings.self_collision = false;
    }
    let result = drape(&mesh, &body, &settings)?;
    let out = std::path::Path::new(out);
    mesh.write_files(out)?;
    std::fs::write(out.join(format!("{}_sim.obj", mesh.file_prefix())), sim_obj(&mesh, &result.positions))?;
    println!("{} vertices: {:?}", mesh.vertices.len(), result.stats);
    Ok(())
}
