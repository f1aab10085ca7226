//! The command line on a pattern using the format extension
//! (`garmentcode/tests/data/extension/specification.json`): `check` counts its inner
//! stitches and names its errors; `render`, `print` and `mesh` write it.

use std::path::{Path, PathBuf};
use std::process::Command;

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("garmentcode/tests/data/extension/specification.json")
}

fn run(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_garmentcode")).args(args).output().expect("runs");
    (out.status.code().unwrap_or(-1), format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)))
}

#[test]
fn check_counts_inner_stitches_and_names_extension_errors() {
    let file = fixture();
    let (code, out) = run(&["check", file.to_str().expect("path")]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("5 panels, 1 stitches and 5 inner stitches: 0 error(s), 0 warning(s)"), "{out}");

    let dir = std::env::temp_dir().join(format!("garmentcode-extension-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let bad = dir.join("specification.json");
    let text = std::fs::read_to_string(&file).expect("fixture").replacen("\"angle\": 180.0", "\"angle\": 200.0", 1);
    std::fs::write(&bad, text).expect("write");
    let (code, out) = run(&["check", bad.to_str().expect("path"), "--format", "json"]);
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json report");
    assert_eq!(v["problems"][0]["kind"], "fold_angle_out_of_range", "{v}");
    assert_eq!(v["problems"][0]["panel"], "sleeve", "{v}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn render_print_and_mesh_write_an_extended_pattern() {
    let file = fixture();
    let dir = std::env::temp_dir().join(format!("garmentcode-extension-out-{}", std::process::id()));
    for (cmd, written) in [("render", "pattern.svg"), ("print", "pattern.dxf"), ("mesh", "extension_vertex_labels.yaml")] {
        let out_dir = dir.join(cmd);
        let mut args = vec![cmd, file.to_str().expect("path"), "-o", out_dir.to_str().expect("path"), "-f"];
        if cmd == "mesh" {
            args.extend(["--name", "extension"]);
        }
        let (code, out) = run(&args);
        assert_eq!(code, 0, "{cmd}: {out}");
        let text = std::fs::read_to_string(out_dir.join(written)).unwrap_or_else(|e| panic!("{cmd}: {written}: {e}"));
        let expected = match cmd {
            "render" => "class=\"fold\"",
            "print" => "POINT\r\n  8\r\n13\r\n",
            _ => "fold_sleeve_underarm:",
        };
        assert!(text.contains(expected), "{cmd}: {written} lacks {expected:?}");
    }
    // render writes the specification back unchanged.
    assert_eq!(std::fs::read(dir.join("render/specification.json")).expect("spec"), std::fs::read(&file).expect("fixture"));
    let _ = std::fs::remove_dir_all(&dir);
}
