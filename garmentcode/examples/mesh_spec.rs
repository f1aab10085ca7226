//! Meshes specification files into box-mesh files:
//! `cargo run -p garmentcode --example mesh_spec -- OUT_DIR SPEC.json...` writes
//! `OUT_DIR/<name>/<name>_boxmesh.obj` etc. for each spec, `<name>` being the spec's
//! file name without `_specification.json` (or its folder's name for `specification.json`).

use std::path::Path;

use garmentcode::Pattern;
use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some((out, specs)) = args.split_first() else {
        eprintln!("usage: mesh_spec OUT_DIR SPEC.json...");
        std::process::exit(2);
    };
    let mut failed = 0;
    for spec in specs {
        let path = Path::new(spec);
        let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        let name = match stem.strip_suffix("_specification") {
            Some(n) => n.to_string(),
            None => path.parent().and_then(|p| p.file_name()).map_or(stem.clone(), |n| n.to_string_lossy().into_owned()),
        };
        let text = std::fs::read_to_string(path).expect("readable specification");
        let mut pattern = Pattern::from_json(&text).expect("a specification");
        pattern.name = name.clone();
        let dir = Path::new(out).join(&name);
        std::fs::create_dir_all(&dir).expect("output folder");
        match BoxMesh::new(&pattern, DEFAULT_RESOLUTION) {
            Ok(mesh) => {
                mesh.write_files(&dir).expect("writable output");
                println!("{name}: {} vertices, {} faces", mesh.vertices.len(), mesh.faces.len());
            }
            Err(e) => {
                failed += 1;
                println!("{name}: error: {e}");
            }
        }
    }
    if failed > 0 {
        eprintln!("{failed} failed");
    }
}
