//! `garmentcode drape`, `build --formats ...,drape` and `sample --formats ...,drape` as a user
//! runs them: the files (read back), exit statuses, and clear errors with nothing written on
//! bad input. Drapes are cut short with `--max-frames` to keep the tests fast, except one.

use std::path::Path;

mod common;
use common::{code, run, scratch, stderr};

/// The waistband of the drape crate's test data (598 particles in the reference).
fn waistband() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("garmentcode-drape/tests/data/waistband_specification.json").display().to_string()
}

fn files_of(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap()
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap()) as usize
}

/// Reads a GLB back: checks the container (magic, version, lengths, chunk types) and
/// returns its JSON and binary chunk.
fn read_glb(bytes: &[u8]) -> (serde_json::Value, Vec<u8>) {
    assert_eq!(&bytes[0..4], b"glTF");
    assert_eq!(u32_at(bytes, 4), 2, "glTF version");
    assert_eq!(u32_at(bytes, 8), bytes.len(), "total length");
    let json_len = u32_at(bytes, 12);
    assert_eq!(&bytes[16..20], b"JSON");
    assert_eq!(json_len % 4, 0);
    let doc: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    let at = 20 + json_len;
    let bin_len = u32_at(bytes, at);
    assert_eq!(&bytes[at + 4..at + 8], b"BIN\0");
    assert_eq!(at + 8 + bin_len, bytes.len(), "chunks fill the file");
    (doc, bytes[at + 8..].to_vec())
}

/// Width and height of a PNG.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    (u32::from_be_bytes(bytes[16..20].try_into().unwrap()), u32::from_be_bytes(bytes[20..24].try_into().unwrap()))
}

fn lines_starting(text: &str, prefix: &str) -> Vec<String> {
    text.lines().filter(|l| l.starts_with(prefix)).map(str::to_string).collect()
}

/// The keys of a JSON object, nested objects as `key.sub`.
fn keys(v: &serde_json::Value, prefix: &str, out: &mut Vec<String>) {
    if let Some(map) = v.as_object() {
        for (k, x) in map {
            let path = format!("{prefix}{k}");
            out.push(path.clone());
            if k != "attachments" {
                keys(x, &format!("{path}."), out);
            }
        }
    }
}

#[test]
fn drape_writes_every_file_reads_back_and_is_deterministic() {
    let dir = scratch("files");
    let spec = waistband();
    let o = run(&["drape", &spec, "--out", "a", "--max-frames", "60"], &dir);
    assert_eq!(code(&o), 3, "an unsettled drape exits 3: {}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("drape: frame 50/60"), "progress on stderr: {err}");
    assert!(err.contains("static_equilibrium"), "{err}");
    let a = dir.join("a");
    insta::assert_debug_snapshot!("drape_files", files_of(&a));

    let report = json(&a.join("waistband_drape.json"));
    let mut k = Vec::new();
    keys(&report, "", &mut k);
    insta::assert_debug_snapshot!("drape_json_keys", k);
    assert_eq!(report["converged"], false);
    assert_eq!(report["fails"], serde_json::json!(["static_equilibrium"]));
    assert_eq!(report["frames"], 60);
    assert_eq!(report["fabric"]["name"], "default");
    assert_eq!(report["body"]["mesh"], "the built-in mesh of body mean_all");
    assert_eq!(report["settings"]["max_frames"], 60);
    let p99 = report["strain"]["seam"]["p99"].as_f64().unwrap();
    assert!(p99.is_finite() && p99 >= report["strain"]["seam"]["p50"].as_f64().unwrap());

    // The draped OBJ: the box mesh's faces and texture coordinates, its vertices moved.
    let boxmesh = std::fs::read_to_string(a.join("waistband_boxmesh.obj")).unwrap();
    let sim = std::fs::read_to_string(a.join("waistband_sim.obj")).unwrap();
    assert_eq!(lines_starting(&sim, "f "), lines_starting(&boxmesh, "f "));
    assert_eq!(lines_starting(&sim, "vt "), lines_starting(&boxmesh, "vt "));
    let n_vertices = lines_starting(&sim, "v ").len();
    let n_faces = lines_starting(&sim, "f ").len();
    assert_eq!(report["vertices"], n_vertices);
    assert_ne!(lines_starting(&sim, "v "), lines_starting(&boxmesh, "v "), "the garment moved");

    // The GLB: garment then body, accessor counts those of the meshes, the data inside the buffer.
    let (doc, bin) = read_glb(&std::fs::read(a.join("waistband_sim.glb")).unwrap());
    assert_eq!(doc["asset"]["version"], "2.0");
    let meshes = doc["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 2);
    assert_eq!(meshes[0]["name"], "garment");
    let accessors = doc["accessors"].as_array().unwrap();
    let count = |mesh: usize, attr: &str| {
        let prim = &meshes[mesh]["primitives"][0];
        let i = if attr == "indices" { &prim["indices"] } else { &prim["attributes"][attr] };
        accessors[i.as_u64().unwrap() as usize]["count"].as_u64().unwrap() as usize
    };
    assert_eq!(count(0, "POSITION"), n_vertices);
    assert_eq!(count(0, "NORMAL"), n_vertices);
    assert_eq!(count(0, "indices"), 3 * n_faces);
    assert_eq!((count(1, "POSITION"), count(1, "indices")), (23_752, 3 * 47_500), "the mean_all body");
    for v in doc["bufferViews"].as_array().unwrap() {
        assert!(v["byteOffset"].as_u64().unwrap() + v["byteLength"].as_u64().unwrap() <= bin.len() as u64);
    }
    // Positions in metres: the first garment vertex is the OBJ's (cm) / 100.
    let first: Vec<f64> = lines_starting(&sim, "v ")[0].split_whitespace().skip(1).map(|x| x.parse().unwrap()).collect();
    let view = &doc["bufferViews"][accessors[0]["bufferView"].as_u64().unwrap() as usize];
    let off = view["byteOffset"].as_u64().unwrap() as usize;
    for k in 0..3 {
        let x = f32::from_le_bytes(bin[off + 4 * k..off + 4 * k + 4].try_into().unwrap());
        assert!((f64::from(x) - first[k] / 100.0).abs() < 1e-5, "coordinate {k}: {x} vs {}", first[k]);
    }

    for side in ["front", "back"] {
        assert_eq!(png_size(&std::fs::read(a.join(format!("waistband_render_{side}.png"))).unwrap()), (800, 800));
    }

    // Same input, same bytes (but the time in the report).
    let o = run(&["drape", &spec, "--out", "b", "--max-frames", "60", "--quiet"], &dir);
    assert_eq!(code(&o), 3);
    assert!(!stderr(&o).contains("drape: frame"), "--quiet: {}", stderr(&o));
    for f in ["waistband_sim.obj", "waistband_sim.glb", "waistband_render_front.png", "waistband_render_back.png"] {
        assert!(std::fs::read(a.join(f)).unwrap() == std::fs::read(dir.join("b").join(f)).unwrap(), "{f} differs");
    }
    // Its own folder is replaced without --force.
    let o = run(&["drape", &spec, "--out", "a", "--max-frames", "1", "-q"], &dir);
    assert_eq!(code(&o), 3, "{}", stderr(&o));
}

#[test]
fn drape_that_settles_exits_0() {
    let dir = scratch("settles");
    let o = run(&["drape", &waistband(), "--out", "a", "--fabric", "mid_bending", "-q"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let report = json(&dir.join("a/waistband_drape.json"));
    assert_eq!(report["converged"], true);
    assert_eq!(report["fails"], serde_json::json!([]));
    assert_eq!(report["fabric"]["garment_edge_ke"], 100.0);
    assert_eq!(report["self_intersections"], 0);
}

#[test]
fn build_drapes_a_design() {
    let dir = scratch("build");
    let o = run(&["build", "--formats", "json,drape", "--max-frames", "3", "--out", "a"], &dir);
    assert_eq!(code(&o), 3, "{}", stderr(&o));
    let files = files_of(&dir.join("a"));
    for f in [
        "specification.json",
        "t-shirt_boxmesh.obj",
        "t-shirt_sim.obj",
        "t-shirt_sim.glb",
        "t-shirt_drape.json",
        "t-shirt_render_front.png",
    ] {
        assert!(files.contains(&f.to_string()), "{f} in {files:?}");
    }
    assert_eq!(json(&dir.join("a/t-shirt_drape.json"))["frames"], 3);
}

/// A closed tetrahedron 1.7 m high (OBJ text, metres), or an open one without its last face.
fn tetrahedron(closed: bool) -> String {
    let mut s = "v 0 0 0\nv 0.3 0 0\nv 0 0 0.3\nv 0.1 1.7 0.1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n".to_string();
    if closed {
        s += "f 3 1 4\n";
    }
    s
}

#[test]
fn bad_input_is_a_clear_error_and_nothing_is_written() {
    let dir = scratch("bad");
    let spec = waistband();
    std::fs::write(dir.join("open.obj"), tetrahedron(false)).unwrap();
    std::fs::write(dir.join("nan.obj"), tetrahedron(true).replace("v 0.3 0 0", "v nan 0 0")).unwrap();
    std::fs::File::create(dir.join("huge.obj")).unwrap().set_len(65 << 20).unwrap();
    std::fs::write(dir.join("stiff.yaml"), "fabric:\n  spring_ke: 1e12\n  fabric_friction: -1\n").unwrap();
    std::fs::write(dir.join("typo.yaml"), "fabric:\n  garment_edg_ke: 5\n").unwrap();
    let zero_area = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/hardening/spec-zero-area-panel.json");
    let zero_area = zero_area.to_str().unwrap();
    let cases: [(Vec<&str>, &[&str]); 9] = [
        (vec![zero_area], &["spec-zero-area-panel.json", "cannot mesh the pattern"]),
        (vec![&spec, "--body-mesh", "open.obj"], &["open.obj", "must be a closed surface"]),
        (vec![&spec, "--body-mesh", "nan.obj"], &["nan.obj:2", "not finite"]),
        (vec![&spec, "--body-mesh", "huge.obj"], &["huge.obj", "at most 67108864"]),
        (
            vec![&spec, "--fabric", "stiff.yaml"],
            &["stiff.yaml: line 2: fabric.spring_ke = 1e12", "from 10 to 10000000", "line 3: fabric.fabric_friction = -1", "from 0 to 2"],
        ),
        (vec![&spec, "--fabric", "typo.yaml"], &["typo.yaml: line 2: fabric.garment_edg_ke", "did you mean `garment_edge_ke`"]),
        (vec![&spec, "--fabric", "mid-bending"], &["mid-bending", "did you mean mid_bending", "default, mid_bending, minimal_bending"]),
        (vec![&spec, "--max-frames", "0"], &["--max-frames"]),
        (vec![&spec, "--fabric", "/dev/zero"], &["/dev/zero", "larger than 64 MB"]),
    ];
    for (args, expected) in cases {
        let mut all = vec!["drape"];
        all.extend(args.iter().copied());
        all.extend(["--out", "out"]);
        let start = std::time::Instant::now();
        let o = run(&all, &dir);
        let err = stderr(&o);
        assert_eq!(code(&o), 2, "{all:?}: {err}");
        for e in expected {
            assert!(err.contains(e), "{all:?}: expected '{e}' in: {err}");
        }
        assert!(start.elapsed().as_secs() < 10, "{all:?} took {:?}", start.elapsed());
        assert!(!dir.join("out").exists(), "{all:?} wrote its output");
    }
}

/// `sample --formats json,mesh,drape` in both layouts: every sample with its drape files,
/// unsettled drapes (cut at 2 frames) and drapes on a body without a mesh recorded by
/// reason in `sample_info.json` and the summary, the other files kept; a rerun resumes.
#[test]
fn sample_drapes_in_both_layouts_and_records_failures() {
    let dir = scratch("sample");
    let common = ["sample", "--n", "2", "--seed", "5", "--formats", "json,mesh,drape", "--max-frames", "2", "--jobs", "2"];
    let o = run(&[&common[..], &["--out", "folders"]].concat(), &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stderr(&o).contains("2 drape(s) failed"), "{}", stderr(&o));
    let summary = std::fs::read_to_string(dir.join("folders/dataset_properties.yaml")).unwrap();
    assert!(
        summary.contains("drape:\n  draped: 2\n  failed: 2\n  by_reason:\n") && summary.contains("    static_equilibrium: 2\n"),
        "{summary}"
    );
    for i in 0..2 {
        let key = format!("rand_{i:07}");
        let folder = dir.join("folders").join(&key);
        let info = json(&folder.join("sample_info.json"));
        assert_eq!(info["drape"]["fails"][0], "static_equilibrium", "{info}");
        assert_eq!(info["drape"]["frames"], 2);
        assert_eq!(json(&folder.join(format!("{key}_drape.json")))["frames"], 2);
        for suffix in [&garmentcode::mesh::write::FILE_SUFFIXES[..], &garmentcode_drape::FILE_SUFFIXES[..]].concat() {
            assert!(folder.join(format!("{key}{suffix}")).is_file(), "{key}{suffix}");
        }
        assert!(summary.contains(&format!("    - {key}\n")), "{key} listed in {summary}");
    }
    // Resumed: nothing made again.
    let o = run(&[&common[..], &["--out", "folders"]].concat(), &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stderr(&o).contains("2 already there"), "{}", stderr(&o));
    // Shards: the same files per sample.
    let o = run(&[&common[..], &["--out", "shards", "--layout", "shards:2"]].concat(), &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = run(&["sample", "--unpack", "shards/shard-000000.tar", "--out", "unpacked"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for i in 0..2 {
        let key = format!("rand_{i:07}");
        assert_eq!(files_of(&dir.join("unpacked").join(&key)), files_of(&dir.join("folders").join(&key)));
    }

    // A replay drapes too.
    let o = run(&["sample", "--seed", "5", "--replay", "1", "--formats", "json,drape", "--max-frames", "2", "--out", "replay"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(json(&dir.join("replay/rand_0000001_drape.json"))["frames"], 2);
    assert!(dir.join("replay/rand_0000001_sim.glb").is_file());

    // A body without a mesh (until mannequins are made from measurements): the drape fails
    // as `body_mesh`, with its message; the sample keeps its other files.
    std::fs::write(dir.join("tall.yaml"), "body:\n  base: mean_all\n  height: 180\n").unwrap();
    let tall = [
        "sample",
        "--n",
        "1",
        "--seed",
        "5",
        "--formats",
        "json,mesh,drape",
        "--max-frames",
        "2",
        "--bodies",
        "tall.yaml",
        "--out",
        "tall",
    ];
    let o = run(&tall, &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let folder = dir.join("tall/rand_0000000");
    let info = json(&folder.join("sample_info.json"));
    assert!(folder.join("rand_0000000_boxmesh.obj").is_file());
    if info["drape"]["fails"] == serde_json::json!(["body_mesh"]) {
        assert!(info["drape"]["message"].as_str().unwrap().contains("--body-mesh"), "{info}");
        assert!(!folder.join("rand_0000000_sim.obj").exists());
        let summary = std::fs::read_to_string(dir.join("tall/dataset_properties.yaml")).unwrap();
        assert!(summary.contains("    body_mesh:\n    - rand_0000000\n") && summary.contains("give one with --body-mesh"), "{summary}");
    } else {
        assert_eq!(info["drape"]["fails"][0], "static_equilibrium", "{info}");
    }
}
