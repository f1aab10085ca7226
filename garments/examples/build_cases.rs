//! Build every reference case of a folder (design.yaml + body.txt) into an output
//! folder of `specification.json` / `error.txt`, for comparison with the reference.
//!
//! `cargo run -p garments --example build_cases -- tests/data/cases out/cases`

use garmentcode::io::read_design;
use garmentcode::{Arena, Params, PartExt};
use garments::{Design, MetaGarment, builtin};
use std::path::Path;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (src, dst) = (Path::new(&args[0]), Path::new(&args[1]));
    let space = Design::design_space();
    let mut names: Vec<_> = std::fs::read_dir(src).unwrap().map(|e| e.unwrap().path()).filter(|p| p.is_dir()).collect();
    names.sort();
    for case in names {
        let name = case.file_name().unwrap().to_string_lossy().to_string();
        let out = dst.join(&name);
        std::fs::create_dir_all(&out).unwrap();
        let _ = std::fs::remove_file(out.join("specification.json"));
        let _ = std::fs::remove_file(out.join("error.txt"));
        let design_text = std::fs::read_to_string(case.join("design.yaml")).unwrap();
        let design: Design = read_design(&design_text, "design.yaml", &space).unwrap();
        let body_name = std::fs::read_to_string(case.join("body.txt")).unwrap().trim().trim_end_matches(".yaml").to_string();
        let body = builtin::body(&body_name).unwrap();
        let mut a = Arena::new();
        let result = MetaGarment::new(&mut a, &body, &design).and_then(|g| g.assemble(&mut a, &name));
        match result {
            Ok(p) if !p.is_empty() => std::fs::write(out.join("specification.json"), p.to_json().unwrap()).unwrap(),
            Ok(_) => std::fs::write(out.join("error.txt"), "empty pattern").unwrap(),
            Err(e) => {
                std::fs::write(out.join("error.txt"), e.to_string()).unwrap();
                println!("{name}: {e}");
            }
        }
    }
}
