//! The `garmentcode` command line as a user runs it: outputs, exit codes, and clear
//! errors without panics or partial output folders on bad input.

use std::path::Path;

mod common;
use common::{code, run, scratch, stderr, stdout};

#[test]
fn build_default_writes_every_file_and_is_deterministic() {
    let dir = scratch("build_default");
    let o = run(&["build", "--out", "a"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for f in ["specification.json", "pattern.svg", "pattern.png", "design_params.yaml", "body_measurements.yaml", "checks.json"] {
        assert!(dir.join("a").join(f).metadata().unwrap().len() > 0, "{f} written");
    }
    assert!(stderr(&o).contains("t-shirt on mean_all"), "{}", stderr(&o));
    // The written design and body files reproduce the garment byte for byte.
    let o =
        run(&["build", "--design", "a/design_params.yaml", "--body", "a/body_measurements.yaml", "--name", "t-shirt", "--out", "b"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for f in ["specification.json", "pattern.svg", "pattern.png", "design_params.yaml", "body_measurements.yaml", "checks.json"] {
        let (x, y) = (std::fs::read(dir.join("a").join(f)).unwrap(), std::fs::read(dir.join("b").join(f)).unwrap());
        assert!(x == y, "{f} differs between the built-in design and its written files");
    }
    let checks: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("a/checks.json")).unwrap()).unwrap();
    for k in ["param_combinations", "total_length", "floor_length", "total_length_ok", "self_intersecting"] {
        assert!(checks.get(k).is_some(), "checks.json has {k}");
    }
    // The pattern passes `check`.
    let o = run(&["check", "a/specification.json"], &dir);
    assert_eq!(code(&o), 0, "{}", stdout(&o));
}

#[test]
fn build_named_designs_and_bodies() {
    let dir = scratch("build_named");
    for (design, body) in [("jumpsuit", "mean_male"), ("sundress", "f_smpl_average_A40")] {
        let o = run(&["build", "--design", design, "--body", body, "--out", design, "--no-png"], &dir);
        assert_eq!(code(&o), 0, "{}", stderr(&o));
        assert!(dir.join(design).join("specification.json").exists());
        assert!(!dir.join(design).join("pattern.png").exists(), "--no-png");
    }
    // The flat layout draws the same pattern differently; a bad layout is refused.
    let o = run(&["build", "--design", "jumpsuit", "--body", "mean_male", "--layout", "flat", "--out", "flat", "--no-png"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let read = |d: &str, f: &str| std::fs::read(dir.join(d).join(f)).unwrap();
    assert_eq!(read("flat", "specification.json"), read("jumpsuit", "specification.json"));
    assert_ne!(read("flat", "pattern.svg"), read("jumpsuit", "pattern.svg"));
    let o = run(&["build", "--layout", "diagonal", "--out", "bad"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("possible values: placed, flat"), "{}", stderr(&o));
}

/// Bad design files: each gives exit 2, names the file, the parameter path and
/// what is allowed, and writes nothing.
#[test]
fn bad_design_files_are_refused_clearly() {
    let dir = scratch("bad_designs");
    let cases: &[(&str, &str, &[&str])] = &[
        ("range.yaml", "design:\n  shirt:\n    length:\n      v: 9.0\n", &["range.yaml", "design.shirt.length", "[0.5, 3.5]"]),
        ("unknown.yaml", "design:\n  meta:\n    upperr:\n      v: Shirt\n", &["unknown.yaml", "design.meta.upperr", "design.meta.upper"]),
        ("option.yaml", "design:\n  meta:\n    upper:\n      v: Tunic\n", &["option.yaml", "design.meta.upper", "FittedShirt"]),
        ("malformed.yaml", "design:\n  meta:\n    upper: [\n", &["malformed.yaml", "line 3"]),
        ("nan.yaml", "design:\n  shirt:\n    length:\n      v: .nan\n", &["nan.yaml", "design.shirt.length", "finite"]),
        ("type.yaml", "design:\n  shirt:\n    strapless:\n      v: maybe\n", &["type.yaml", "design.shirt.strapless"]),
        ("notyaml.yaml", "\u{0}\u{1}binary", &["notyaml.yaml"]),
    ];
    for (file, text, expected) in cases {
        std::fs::write(dir.join(file), text).unwrap();
        let o = run(&["build", "--design", file, "--out", "out"], &dir);
        assert_eq!(code(&o), 2, "{file}: {}", stderr(&o));
        let err = stderr(&o);
        for e in *expected {
            assert!(err.contains(e), "{file}: '{e}' not in: {err}");
        }
        assert!(!dir.join("out").exists(), "{file}: nothing written");
    }
}

#[test]
fn bad_bodies_and_missing_files_are_refused_clearly() {
    let dir = scratch("bad_bodies");
    std::fs::write(dir.join("neg.yaml"), "body:\n  height: -3\n").unwrap();
    let o = run(&["build", "--body", "neg.yaml", "--out", "out"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("body.height") && stderr(&o).contains("plausible range"), "{}", stderr(&o));
    let o = run(&["build", "--body", "nobody", "--out", "out"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("mean_all"), "lists the built-in bodies: {}", stderr(&o));
    let o = run(&["build", "--design", "missing.yaml", "--out", "out"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("missing.yaml"));
    assert!(!dir.join("out").exists());
}

#[test]
fn a_body_file_may_give_a_few_measurements_over_a_built_in_body() {
    let dir = scratch("partial_body");
    std::fs::write(dir.join("me.yaml"), "body:\n  base: mean_female\n  waist: 70.0\n  hips: 101.5\n").unwrap();
    let o = run(&["build", "--body", "me.yaml", "--out", "out", "--no-png"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let written = std::fs::read_to_string(dir.join("out/body_measurements.yaml")).unwrap();
    let body = garmentcode::Body::from_yaml(&written, "written").unwrap();
    let base = garments::builtin::body("mean_female").unwrap();
    assert_eq!((body.waist, body.hips, body.height, body.arm_length), (70.0, 101.5, base.height, base.arm_length));
    // The same file gives the same body to `sample --bodies`.
    let o = run(&["sample", "-n", "1", "-s", "1", "--bodies", "me.yaml", "-o", "data"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let sampled = std::fs::read_to_string(dir.join("data/rand_0000000/body_measurements.yaml")).unwrap();
    assert_eq!(garmentcode::Body::from_yaml(&sampled, "s").unwrap().waist, 70.0);
    // Errors name the file, the line, the measurement and its range; an unknown
    // base gets a suggestion.
    std::fs::write(dir.join("bad.yaml"), "body:\n  base: mean_femal\n  waist: 7000\n").unwrap();
    let o = run(&["build", "--body", "bad.yaml", "--out", "bad"], &dir);
    assert_eq!(code(&o), 2);
    let err = stderr(&o);
    assert!(
        err.contains("bad.yaml: 2 problems\n  line 2: body.base: no built-in body `mean_femal` (did you mean `mean_female`?)"),
        "{err}"
    );
    assert!(err.contains("line 3: body.waist: 7000 cm is outside the plausible range"), "{err}");
    assert!(!dir.join("bad").exists());
}

#[test]
fn rejected_designs_write_nothing() {
    let dir = scratch("rejected");
    // No upper garment, waistband or bottom: the reference refuses an empty pattern.
    std::fs::write(dir.join("empty.yaml"), "design:\n  meta:\n    upper:\n      v: null\n").unwrap();
    let o = run(&["build", "--design", "empty.yaml", "--out", "out"], &dir);
    assert_ne!(code(&o), 0);
    assert!(stderr(&o).contains("empty garment"), "{}", stderr(&o));
    assert!(!dir.join("out").exists());
    // An existing output folder keeps its contents when a build is rejected.
    std::fs::create_dir_all(dir.join("kept")).unwrap();
    std::fs::write(dir.join("kept/specification.json"), "old").unwrap();
    let o = run(&["build", "--design", "empty.yaml", "--out", "kept"], &dir);
    assert_ne!(code(&o), 0);
    assert_eq!(std::fs::read_to_string(dir.join("kept/specification.json")).unwrap(), "old");
}

#[test]
fn strict_turns_failed_checks_into_rejections() {
    let dir = scratch("strict");
    // A long shirt over a long skirt reaches below the floor.
    let design = "design:\n  meta:\n    upper:\n      v: Shirt\n    bottom:\n      v: SkirtCircle\n  shirt:\n    length:\n      v: 3.5\n  flare-skirt:\n    length:\n      v: 0.95\n";
    std::fs::write(dir.join("long.yaml"), design).unwrap();
    let relaxed = run(&["build", "--design", "long.yaml", "--out", "relaxed", "--no-png"], &dir);
    assert_eq!(code(&relaxed), 0, "{}", stderr(&relaxed));
    let checks: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("relaxed/checks.json")).unwrap()).unwrap();
    if checks["total_length_ok"] == false {
        assert!(stderr(&relaxed).contains("warning"), "{}", stderr(&relaxed));
        let strict = run(&["build", "--design", "long.yaml", "--out", "strict", "--strict"], &dir);
        assert_eq!(code(&strict), 1, "{}", stderr(&strict));
        assert!(!dir.join("strict").exists());
    } else {
        panic!("the test design should be too long: {checks}");
    }
}

#[test]
fn check_reports_problems_as_text_and_json() {
    let dir = scratch("check");
    assert_eq!(code(&run(&["build", "--out", "t", "--no-png"], &dir)), 0);
    let spec: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("t/specification.json")).unwrap()).unwrap();

    let mut dangling = spec.clone();
    dangling["pattern"]["stitches"][0][0]["panel"] = "ghost".into();
    std::fs::write(dir.join("dangling.json"), serde_json::to_string(&dangling).unwrap()).unwrap();
    let o = run(&["check", "dangling.json"], &dir);
    assert_eq!(code(&o), 1);
    assert!(stdout(&o).contains("ghost"), "{}", stdout(&o));
    let o = run(&["check", "dangling.json", "--format", "json"], &dir);
    assert_eq!(code(&o), 1);
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let problems = report.as_array().or_else(|| report["problems"].as_array()).expect("a list of problems");
    assert!(problems.iter().any(|p| p["severity"] == "error" && p["kind"].is_string()), "{report}");

    let o = run(&["check", "t/specification.json", "--format", "json"], &dir);
    assert_eq!(code(&o), 0);
    let o = run(&["check", "t/specification.json", "--format", "xml"], &dir);
    assert_eq!(code(&o), 2);
}

#[test]
fn bad_pattern_files_are_refused_clearly() {
    let dir = scratch("bad_specs");
    assert_eq!(code(&run(&["build", "--out", "t", "--no-png"], &dir)), 0);
    let text = std::fs::read_to_string(dir.join("t/specification.json")).unwrap();
    let spec: serde_json::Value = serde_json::from_str(&text).unwrap();
    let panel = spec["pattern"]["panels"].as_object().unwrap().keys().next().unwrap().clone();
    let mut wrong_type = spec.clone();
    wrong_type["pattern"]["panels"][&panel]["vertices"][0][0] = "x".into();
    let mut bad_index = spec.clone();
    bad_index["pattern"]["panels"][&panel]["edges"][0]["endpoints"][0] = 9999.into();
    let files: Vec<(&str, String, &str)> = vec![
        ("truncated.json", text[..text.len() / 2].to_string(), "malformed JSON"),
        ("wrong_type.json", wrong_type.to_string(), "vertices[0][0]"),
        ("bad_index.json", bad_index.to_string(), "9999"),
        ("nan.json", text.replacen("0.0", "NaN", 1), "malformed JSON"),
        ("empty.json", String::new(), "malformed JSON"),
    ];
    for (file, content, expected) in &files {
        std::fs::write(dir.join(file), content).unwrap();
        for args in [vec!["check", file], vec!["render", file, "--out", "r"]] {
            let o = run(&args, &dir);
            let c = code(&o);
            assert!(c == 1 || c == 2, "{args:?}: exit {c}");
            let all = stderr(&o) + &stdout(&o);
            assert!(all.contains(expected), "{args:?}: '{expected}' not in {all}");
            assert!(!dir.join("r").exists(), "{args:?}: no partial output");
        }
    }
    let o = run(&["render", "missing.json", "--out", "r"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("missing.json"));
}

#[test]
fn render_re_emits_and_draws() {
    let dir = scratch("render");
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases/case-002/specification.json");
    let o = run(&["render", case.to_str().unwrap(), "--out", "r"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("r/pattern.svg")).unwrap();
    assert!(svg.starts_with("<?xml") || svg.starts_with("<svg"), "{}", &svg[..60]);
    assert!(std::fs::read(dir.join("r/pattern.png")).unwrap().starts_with(b"\x89PNG"));
    // Geometrically the same pattern as the reference wrote.
    let o = run(&["compare", case.to_str().unwrap(), "r/specification.json"], &dir);
    assert_eq!(code(&o), 0, "{}", stdout(&o));
    assert!(stdout(&o).contains("1 passed, 0 failed"));
}

#[test]
fn schema_formats() {
    let dir = scratch("schema");
    let o = run(&["schema"], &dir);
    assert_eq!(code(&o), 0);
    let yaml = stdout(&o);
    assert!(yaml.starts_with("design:\n"), "{}", &yaml[..40]);
    let o = run(&["schema", "--format", "json-schema"], &dir);
    assert_eq!(code(&o), 0);
    let schema: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(schema.get("properties").is_some() || schema.get("$defs").is_some(), "{schema}");
    let o = run(&["schema", "--format", "table"], &dir);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).lines().count() >= 120);
    let o = run(&["schema", "--format", "toml"], &dir);
    assert_eq!(code(&o), 2);
}

#[test]
fn compare_judges_case_folders() {
    let dir = scratch("compare");
    let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases");
    let one = |c: &str| cases.join(c).join("specification.json").to_str().unwrap().to_string();
    let o = run(&["compare", &one("case-001"), &one("case-001")], &dir);
    assert_eq!(code(&o), 0);
    let o = run(&["compare", &one("case-001"), &one("case-002")], &dir);
    assert_eq!(code(&o), 1);
    assert!(stdout(&o).contains("FAIL"));
    let o = run(&["compare", "--cases", cases.to_str().unwrap(), cases.to_str().unwrap()], &dir);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).contains("62 passed, 0 failed"), "{}", stdout(&o));
    let o = run(&["compare", "nope.json", &one("case-001")], &dir);
    assert_eq!(code(&o), 2);
}

#[test]
fn usage_errors() {
    let dir = scratch("usage");
    for args in [vec!["frobnicate"], vec!["build", "--bogus"], vec!["build"], vec!["check"], vec!["render", "x.json"], vec![]] {
        let o = run(&args, &dir);
        assert_eq!(code(&o), 2, "{args:?}");
    }
    let o = run(&["help"], &dir);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).contains("Usage:"));
}

#[test]
fn command_line_conventions() {
    let dir = scratch("conventions");
    let o = run(&["--version"], &dir);
    assert_eq!(code(&o), 0);
    assert_eq!(stdout(&o).trim(), format!("garmentcode {}", env!("CARGO_PKG_VERSION")));
    // Every command's help comes from its definition and lists every flag.
    let o = run(&["build", "--help"], &dir);
    assert_eq!(code(&o), 0);
    for flag in ["-d, --design", "-b, --body", "-o, --out", "-n, --name", "--strict", "--no-png", "--layout", "--force"] {
        assert!(stdout(&o).contains(flag), "{flag} in {}", stdout(&o));
    }
    for cmd in ["schema", "check", "render", "compare", "sample", "serve", "completions"] {
        let o = run(&[cmd, "--help"], &dir);
        assert_eq!(code(&o), 0, "{cmd}");
        assert!(stdout(&o).contains(&format!("Usage: garmentcode {cmd}")), "{cmd}: {}", stdout(&o));
    }
    // Unknown flags are named; commands and flags get suggestions.
    let o = run(&["build", "--ot", "x"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("'--ot'"), "{}", stderr(&o));
    let o = run(&["biuld"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("similar subcommand exists: 'build'"), "{}", stderr(&o));
    let o = run(&["build", "--stirct", "-o", "x"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("--strict"), "{}", stderr(&o));
    // Built-in names: suggestions, and the name of a body file works too.
    let o = run(&["build", "--design", "t-shrt", "-o", "x"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("did you mean t-shirt?"), "{}", stderr(&o));
    let o = run(&["build", "--body", "mean_femal", "-o", "x"], &dir);
    assert!(stderr(&o).contains("did you mean mean_female?"), "{}", stderr(&o));
    let o = run(&["build", "--body", "mean_all.yaml", "-o", "with_ext", "--no-png"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o2 = run(&["build", "-b", "mean_all", "-o", "without_ext", "--no-png"], &dir);
    assert_eq!(code(&o2), 0);
    let read = |d: &str| std::fs::read(dir.join(d).join("specification.json")).unwrap();
    assert_eq!(read("with_ext"), read("without_ext"));
    // Shell completions.
    for shell in ["bash", "zsh", "fish"] {
        let o = run(&["completions", shell], &dir);
        assert_eq!(code(&o), 0, "{shell}");
        assert!(stdout(&o).contains("garmentcode") && stdout(&o).contains("design"), "{shell}");
    }
}

#[test]
fn schema_prints_the_design_space_and_presets_are_designs_that_build() {
    let dir = scratch("schema_builds");
    // The design space: at its defaults nothing is chosen, and building it says what to do.
    let o = run(&["schema"], &dir);
    assert_eq!(code(&o), 0);
    std::fs::write(dir.join("space.yaml"), o.stdout).unwrap();
    let o = run(&["build", "--design", "space.yaml", "-o", "out", "--no-png"], &dir);
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    assert!(stderr(&o).contains("empty garment") && stderr(&o).contains("schema --design t-shirt"), "{}", stderr(&o));
    assert!(!dir.join("out").exists());
    // A preset, written with every range and probability, builds the preset.
    let o = run(&["schema", "--design", "t-shirt"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    std::fs::write(dir.join("t.yaml"), o.stdout).unwrap();
    assert_eq!(code(&run(&["build", "--design", "t.yaml", "--name", "t-shirt", "-o", "a", "--no-png"], &dir)), 0);
    assert_eq!(code(&run(&["build", "--design", "t-shirt", "-o", "b", "--no-png"], &dir)), 0);
    let spec = |d: &str| std::fs::read(dir.join(d).join("specification.json")).unwrap();
    assert!(spec("a") == spec("b"), "the preset's design file builds the preset");
    // --design goes with the design-file format only.
    assert_eq!(code(&run(&["schema", "--design", "t-shirt", "--format", "table"], &dir)), 2);
    // A preset past the reference keeps its extension and builds the same garment.
    let o = run(&["schema", "--design", "pocket-shirt"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).contains("one_piece:"), "{}", stdout(&o));
    std::fs::write(dir.join("p.yaml"), o.stdout).unwrap();
    assert_eq!(code(&run(&["build", "--design", "p.yaml", "--name", "pocket-shirt", "-o", "c", "--no-png"], &dir)), 0);
    assert_eq!(code(&run(&["build", "--design", "pocket-shirt", "-o", "d", "--no-png"], &dir)), 0);
    assert!(spec("c") == spec("d"), "the extended preset builds the preset");
}

#[test]
fn schema_extended_adds_the_extension_after_the_references_parameters() {
    let dir = scratch("schema_extended");
    let o = run(&["schema", "--format", "table"], &dir);
    let plain: Vec<String> = stdout(&o).lines().map(|l| l.split_whitespace().next().unwrap().to_string()).collect();
    assert!(plain.iter().all(|p| !p.starts_with("extension.")));
    let o = run(&["schema", "--format", "table", "--extended"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let wide: Vec<String> = stdout(&o).lines().map(|l| l.split_whitespace().next().unwrap().to_string()).collect();
    assert_eq!(&wide[..plain.len()], &plain[..]);
    assert!(wide[plain.len()..].iter().all(|p| p.starts_with("extension.")));
    assert!(wide.iter().any(|p| p == "extension.sleeve.one_piece"));
    let o = run(&["schema", "--format", "json-schema", "--extended"], &dir);
    assert_eq!(code(&o), 0);
    let schema: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(schema.to_string().contains("one_piece"));
    let o = run(&["schema", "--extended"], &dir);
    std::fs::write(dir.join("space.yaml"), o.stdout).unwrap();
    let space = garmentcode::DesignSpace::from_yaml(
        &std::fs::read_to_string(dir.join("space.yaml")).unwrap(),
        "space.yaml",
        &garments::design::extended_design_space(),
    )
    .unwrap();
    let paths = |s: &garmentcode::DesignSpace| s.params().iter().map(|p| p.path.clone()).collect::<Vec<_>>();
    assert_eq!(paths(&space), paths(&garments::design::extended_design_space()));
}

#[test]
fn schema_equals_the_references_default_design_space_parameter_by_parameter() {
    let dir = scratch("schema_reference");
    let o = run(&["schema"], &dir);
    assert_eq!(code(&o), 0);
    let ours = String::from_utf8(o.stdout).unwrap();
    let reference = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/reference_default.yaml")).unwrap();
    let base = <garments::Design as garmentcode::Params>::design_space();
    let ours = garmentcode::DesignSpace::from_yaml(&ours, "schema", &base).unwrap();
    let reference = garmentcode::DesignSpace::from_yaml(&reference, "default.yaml", &base).unwrap();
    assert_eq!(ours.params().len(), reference.params().len());
    assert_eq!(ours.params().len(), 122);
    // Values compare as the reference compares them (`0 == 0.0`: one option list
    // of the reference mixes `0` with floats).
    let same = |x: &garmentcode::Value, y: &garmentcode::Value| x.loosely_eq(y);
    let same_range = |x: &garmentcode::Range, y: &garmentcode::Range| match (x, y) {
        (garmentcode::Range::Options(a), garmentcode::Range::Options(b)) => a.len() == b.len() && a.iter().zip(b).all(|(a, b)| same(a, b)),
        _ => x == y,
    };
    for (a, b) in ours.params().iter().zip(reference.params()) {
        assert_eq!(a.path, b.path);
        assert_eq!((a.kind, a.default_prob), (b.kind, b.default_prob), "{}", a.path);
        assert!(same_range(&a.range, &b.range) && same(&a.default, &b.default), "{}: {a:?} against {b:?}", a.path);
    }
}

#[test]
fn check_strict_and_build_strict_agree() {
    let dir = scratch("strict_agree");
    for (design, _) in [("t-shirt", 0), ("fitted-dress", 0), ("sundress", 0), ("shirt-dress", 0), ("jumpsuit", 0)] {
        let b = run(&["build", "--design", design, "--strict", "-o", design, "--no-png"], &dir);
        let built = code(&b) == 0;
        let spec = format!("{design}/specification.json");
        if built {
            let c = run(&["check", "--strict", &spec], &dir);
            assert_eq!(code(&c), 0, "{design}: build --strict accepts it, check --strict must too: {}", stdout(&c));
        }
    }
}

#[test]
fn render_refuses_structural_errors_unless_forced() {
    let dir = scratch("render_force");
    assert_eq!(code(&run(&["build", "-o", "t", "--no-png"], &dir)), 0);
    let mut spec: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("t/specification.json")).unwrap()).unwrap();
    let panel = spec["pattern"]["panels"].as_object().unwrap().keys().next().unwrap().clone();
    // Edge 0 ends where edge 2 starts: the outline no longer closes.
    let e2_start = spec["pattern"]["panels"][&panel]["edges"][2]["endpoints"][0].clone();
    spec["pattern"]["panels"][&panel]["edges"][0]["endpoints"][1] = e2_start;
    std::fs::write(dir.join("open.json"), spec.to_string()).unwrap();
    let c = run(&["check", "open.json"], &dir);
    assert_eq!(code(&c), 1);
    assert!(stdout(&c).contains("open_loop"), "{}", stdout(&c));
    let o = run(&["render", "open.json", "-o", "r"], &dir);
    assert_eq!(code(&o), 1);
    assert!(stderr(&o).contains("open_loop") && stderr(&o).contains("--force"), "{}", stderr(&o));
    assert!(!dir.join("r").exists());
    let o = run(&["render", "open.json", "-o", "r", "--force"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(dir.join("r/pattern.svg").exists());
}

#[test]
fn output_folders_are_replaced_whole_and_foreign_ones_refused() {
    let dir = scratch("folders");
    assert_eq!(code(&run(&["build", "-o", "out"], &dir)), 0);
    assert!(dir.join("out/pattern.png").exists());
    // A rebuild without the PNG leaves no PNG of the previous design behind.
    assert_eq!(code(&run(&["build", "--design", "sundress", "-o", "out", "--no-png"], &dir)), 0);
    assert!(!dir.join("out/pattern.png").exists());
    // A folder with someone else's files is refused, and left as it was.
    std::fs::create_dir_all(dir.join("mine")).unwrap();
    std::fs::write(dir.join("mine/thesis.tex"), "precious").unwrap();
    let o = run(&["build", "-o", "mine"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("thesis.tex") && stderr(&o).contains("--force"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(dir.join("mine/thesis.tex")).unwrap(), "precious");
    let o = run(&["build", "-o", "mine", "--force", "--no-png"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(!dir.join("mine/thesis.tex").exists());
    // Leftovers of a killed run are removed by the next run on that folder.
    std::fs::create_dir_all(dir.join(".out.tmp-4000000000")).unwrap();
    assert_eq!(code(&run(&["build", "-o", "out", "--no-png"], &dir)), 0);
    assert!(!dir.join(".out.tmp-4000000000").exists());
}

#[test]
fn a_re_render_never_deletes_an_edited_design_file() {
    let dir = scratch("rerender");
    assert_eq!(code(&run(&["build", "-o", "build"], &dir)), 0);
    let design = dir.join("build/design_params.yaml");
    let edited = std::fs::read_to_string(&design).unwrap() + "# my fitting notes\n";
    std::fs::write(&design, &edited).unwrap();
    // `render` writes no design file: it would delete the edited one, so it refuses.
    let o = run(&["render", "build/specification.json", "-o", "build"], &dir);
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    assert!(stderr(&o).contains("design_params.yaml") && stderr(&o).contains("--force"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&design).unwrap(), edited);
    for f in ["body_measurements.yaml", "checks.json"] {
        assert!(dir.join("build").join(f).exists(), "{f} kept");
    }
    // Building the edited design file into its own folder reads it: allowed.
    let o = run(&["build", "-d", "build/design_params.yaml", "-o", "build"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // Unchanged files of the tool's own are replaced as before.
    let o = run(&["render", "build/specification.json", "-o", "build"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(!design.exists() && dir.join("build/specification.json").exists());
}

#[test]
fn what_build_writes_the_other_commands_read() {
    // Level shoulders make the back neckline an arc of a radius beyond 100 m: it is
    // written as the straight edge it is, which check, render, mesh and print read.
    let dir = scratch("level_shoulders");
    let body = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("garments/data/bodies/mean_all.yaml")).unwrap();
    let level: String = body
        .lines()
        .map(|l| if l.trim_start().starts_with("shoulder_incl:") { "  shoulder_incl: 0.001".to_string() } else { l.to_string() } + "\n")
        .collect();
    assert_ne!(body, level);
    std::fs::write(dir.join("level.yaml"), level).unwrap();
    for design in ["t-shirt", "shirt-dress", "jumpsuit"] {
        let o = run(&["build", "-d", design, "-b", "level.yaml", "-o", design, "--no-png"], &dir);
        assert_eq!(code(&o), 0, "{design}: {}", stderr(&o));
        let spec = format!("{design}/specification.json");
        for args in [vec!["check", &spec], vec!["render", &spec, "-o", "r", "--no-png"], vec!["print", &spec, "-o", "p"]] {
            let o = run(&args, &dir);
            assert_eq!(code(&o), 0, "{args:?}: {}", stderr(&o));
        }
    }
}

#[test]
fn check_on_a_yaml_file_says_what_the_file_is() {
    let dir = scratch("check_yaml");
    assert_eq!(code(&run(&["build", "-o", "out", "--no-png"], &dir)), 0);
    let o = run(&["check", "out/design_params.yaml"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("YAML design file") && stderr(&o).contains("build --design"), "{}", stderr(&o));
    let o = run(&["check", "out/body_measurements.yaml"], &dir);
    assert!(stderr(&o).contains("YAML body file"), "{}", stderr(&o));
}

#[test]
fn many_body_problems_come_one_a_line_and_huge_values_are_cut_short() {
    let dir = scratch("body_problems");
    let bad: String = garmentcode::MEASUREMENTS.iter().map(|m| format!("  {}: -1\n", m.name)).collect();
    std::fs::write(dir.join("bad.yaml"), format!("body:\n{bad}")).unwrap();
    let o = run(&["build", "-b", "bad.yaml", "-o", "out"], &dir);
    assert_eq!(code(&o), 2);
    let err = stderr(&o);
    assert!(err.lines().count() >= 20 && err.lines().all(|l| l.len() < 300), "{err}");
    // A 10 MB value and a number of 309 digits are quoted short.
    let huge = "x".repeat(10 << 20);
    std::fs::write(dir.join("huge.yaml"), format!("body:\n  height: {huge}\n  waist: 1e308\n")).unwrap();
    let o = run(&["build", "-b", "huge.yaml", "-o", "out"], &dir);
    assert_eq!(code(&o), 2);
    let err = stderr(&o);
    assert!(err.len() < 4000 && err.contains("(10485760 characters)") && err.contains("1e308"), "{}", &err[..err.len().min(4000)]);
    // In a pattern: a huge string where a keyword goes, a huge number of units.
    assert_eq!(code(&run(&["build", "-o", "t", "--no-png"], &dir)), 0);
    let mut spec: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("t/specification.json")).unwrap()).unwrap();
    spec["properties"]["curvature_coords"] = serde_json::json!(huge);
    std::fs::write(dir.join("cc.json"), spec.to_string()).unwrap();
    spec["properties"]["curvature_coords"] = serde_json::json!("relative");
    spec["properties"]["units_in_meter"] = serde_json::json!(1e308);
    std::fs::write(dir.join("units.json"), spec.to_string()).unwrap();
    for (file, shown) in [("cc.json", "(10485760 characters)"), ("units.json", "got 1e308")] {
        let o = run(&["check", file], &dir);
        assert_eq!(code(&o), 2);
        assert!(stderr(&o).len() < 400 && stderr(&o).contains(shown), "{}", &stderr(&o)[..stderr(&o).len().min(400)]);
    }
    let design = format!("design:\n  meta:\n    upper:\n      v: {huge}\n  waistband:\n    waist:\n      v: 1e308\n");
    std::fs::write(dir.join("huge_design.yaml"), design).unwrap();
    let o = run(&["build", "-d", "huge_design.yaml", "-o", "out"], &dir);
    assert_eq!(code(&o), 2);
    let err = stderr(&o);
    assert!(err.len() < 4000 && err.contains("characters)"), "{}", &err[..err.len().min(4000)]);
}

#[test]
fn labels_and_names_have_a_maximum_length() {
    let dir = scratch("labels");
    assert_eq!(code(&run(&["build", "-o", "out", "--no-png"], &dir)), 0);
    let long = "L".repeat(100_000);
    for args in [
        vec!["print", "out/specification.json", "-o", "p", "--garment", &long],
        vec!["print", "out/specification.json", "-o", "p", "--size", &long],
        vec!["mesh", "out/specification.json", "-o", "m", "--name", &long],
        vec!["build", "-o", "b", "--name", &long],
    ] {
        let t = std::time::Instant::now();
        let o = run(&args, &dir);
        assert_eq!(code(&o), 2, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("longer than 100 characters") && stderr(&o).len() < 1000, "{}", stderr(&o));
        assert!(t.elapsed().as_secs() < 10);
    }
    assert!(!dir.join("p").exists() && !dir.join("m").exists() && !dir.join("b").exists());
    // A pattern whose panel names are that long is refused when read.
    let mut spec: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("out/specification.json")).unwrap()).unwrap();
    let panels = spec["pattern"]["panels"].as_object_mut().unwrap();
    let first = panels.keys().next().unwrap().clone();
    let panel = panels.remove(&first).unwrap();
    panels.insert(long.clone(), panel);
    std::fs::write(dir.join("long.json"), spec.to_string()).unwrap();
    let o = run(&["check", "long.json"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("longer than 100 characters"), "{}", stderr(&o));
}

#[test]
fn build_warnings_explain_the_references_internal_errors() {
    let dir = scratch("explained");
    // A ruffled skirt without a waistband: the reference refuses the combination.
    let design = "design:\n  meta:\n    upper:\n      v: null\n    wb:\n      v: null\n    bottom:\n      v: Skirt2\n  skirt:\n    ruffle:\n      v: 1.5\n";
    std::fs::write(dir.join("ruffles.yaml"), design).unwrap();
    let o = run(&["build", "--design", "ruffles.yaml", "-o", "out", "--no-png"], &dir);
    assert_eq!(code(&o), 0);
    let err = stderr(&o);
    assert!(!err.contains("ERROR::"), "{err}");
    assert!(err.contains("design filter: the reference refuses this combination of parameters (Skirt2 ruffles + belt)"), "{err}");
    // checks.json keeps the reference's wording.
    assert!(std::fs::read_to_string(dir.join("out/checks.json")).unwrap().contains("ERROR::IncorrectParams::Skirt2 ruffles + belt"));
}

#[test]
fn mesh_writes_the_reference_files_and_replaces_its_own_folder() {
    let dir = scratch("mesh");
    let o = run(&["build", "--out", "shirt"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = run(&["mesh", "shirt/specification.json", "--out", "m"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for suffix in std::iter::once("_specification.json").chain(garmentcode::mesh::write::FILE_SUFFIXES) {
        assert!(dir.join("m").join(format!("shirt{suffix}")).metadata().unwrap().len() > 0, "shirt{suffix} written");
    }
    let obj = std::fs::read_to_string(dir.join("m/shirt_boxmesh.obj")).unwrap();
    let seg = std::fs::read_to_string(dir.join("m/shirt_sim_segmentation.txt")).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), seg.lines().count(), "one segmentation line per vertex");
    // Deterministic, and a rerun (coarser) replaces its own folder without --force.
    let o = run(&["mesh", "shirt/specification.json", "--out", "m2", "--name", "shirt"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(obj, std::fs::read_to_string(dir.join("m2/shirt_boxmesh.obj")).unwrap());
    let o = run(&["mesh", "shirt/specification.json", "--out", "m", "--resolution", "2"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let coarse = std::fs::read_to_string(dir.join("m/shirt_boxmesh.obj")).unwrap();
    assert!(coarse.len() < obj.len() / 2, "a coarser mesh");
    // Bad input: a clear error, nothing written.
    let o = run(&["mesh", "shirt/specification.json", "--out", "m3", "--resolution", "0"], &dir);
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    assert!(stderr(&o).contains("resolution"), "{}", stderr(&o));
    assert!(!dir.join("m3").exists());
}

/// `build --formats` chooses the drawings and the simulation mesh; the mesh files are
/// those `garmentcode mesh` writes for the built pattern, byte for byte.
#[test]
fn build_formats_choose_drawings_and_the_mesh() {
    let dir = scratch("build_formats");
    let o = run(&["build", "--formats", "json,svg,mesh", "--out", "a"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let a = dir.join("a");
    assert!(a.join("pattern.svg").is_file() && !a.join("pattern.png").exists(), "svg without png");
    let mesh_files: Vec<String> = std::fs::read_dir(&a)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("t-shirt_"))
        .collect();
    assert_eq!(mesh_files.len(), garmentcode::mesh::write::FILE_SUFFIXES.len(), "{mesh_files:?}");
    let o = run(&["mesh", "a/specification.json", "--name", "t-shirt", "--out", "m"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for f in &mesh_files {
        let (x, y) = (std::fs::read(a.join(f)).unwrap(), std::fs::read(dir.join("m").join(f)).unwrap());
        assert!(x == y, "{f} differs from `garmentcode mesh`");
    }
    // Unknown formats and resolutions are usage errors; nothing is written.
    let o = run(&["build", "--formats", "json,stl", "--out", "b"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("possible values: json, svg, png, mesh"), "{}", stderr(&o));
    let o = run(&["build", "--formats", "mesh", "--mesh-resolution", "0", "--out", "b"], &dir);
    assert_eq!(code(&o), 2);
    assert!(!dir.join("b").exists());
}

#[test]
fn print_writes_the_printable_pattern() {
    let dir = scratch("print");
    let spec = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases/t-shirt-mean_all/specification.json");
    let spec = spec.to_str().unwrap();
    let o = run(&["print", spec, "--out", "out", "--paper", "letter", "--seam", "1.5", "--hem", "3", "--size", "mean_all"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let names = ["pattern-tiled.pdf", "pattern-sheet.pdf", "pattern-sheet.svg", "pattern.dxf", "cutting-layout.svg", "cutting-layout.txt"];
    for n in names {
        assert!(dir.join("out").join(n).is_file(), "{n} missing");
    }
    let report = std::fs::read_to_string(dir.join("out/cutting-layout.txt")).unwrap();
    assert!(report.contains("Fabric length needed") && report.contains("Cut 1 on fold"), "{report}");
    let svg = std::fs::read_to_string(dir.join("out/pattern-sheet.svg")).unwrap();
    assert!(svg.contains("Size: mean_all") && svg.contains("Seam allowance 1.5 cm included, hems 3 cm"));
    // The same again gives the same bytes (and replaces its own folder).
    let first: Vec<Vec<u8>> = names.iter().map(|n| std::fs::read(dir.join("out").join(n)).unwrap()).collect();
    assert_eq!(
        code(&run(&["print", spec, "--out", "out", "--paper", "letter", "--seam", "1.5", "--hem", "3", "--size", "mean_all"], &dir)),
        0
    );
    let again: Vec<Vec<u8>> = names.iter().map(|n| std::fs::read(dir.join("out").join(n)).unwrap()).collect();
    assert!(first == again);
    // Bad options are refused clearly.
    for (args, want) in [
        (vec!["--paper", "a3"], "a4, letter, a0 or roll"),
        (vec!["--seam=-1"], "non-negative"),
        (vec!["--seam-edge", "nope=2"], "no panel 'nope'"),
        (vec!["--seam-edge", "right_ftorso:99=2"], "has 7 edges"),
    ] {
        let mut all = vec!["print", spec, "--out", "bad"];
        all.extend(args);
        let o = run(&all, &dir);
        assert_eq!(code(&o), 2, "{all:?}");
        assert!(stderr(&o).contains(want), "{all:?}: {}", stderr(&o));
        assert!(!dir.join("bad").exists());
    }
}

#[test]
fn build_formats_print_writes_the_same_files() {
    let dir = scratch("build_print");
    let o = run(&["build", "--design", "t-shirt", "--out", "b", "--formats", "json,print"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(dir.join("b/pattern.dxf").is_file() && dir.join("b/pattern-tiled.pdf").is_file() && !dir.join("b/pattern.svg").exists());
    let dxf = std::fs::read_to_string(dir.join("b/pattern.dxf")).unwrap();
    assert!(dxf.contains("AC1009") && dxf.contains("Size: mean_all"));
}

/// Width, height and colour type from a PNG's IHDR chunk.
fn png_header(png: &[u8]) -> (u32, u32, u8) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |i: usize| u32::from_be_bytes([png[i], png[i + 1], png[i + 2], png[i + 3]]);
    (be(16), be(20), png[25])
}

#[test]
fn png_resolution_and_background_are_chosen() {
    let dir = scratch("png_dpi");
    assert_eq!(code(&run(&["build", "--out", "default"], &dir)), 0);
    let o = run(&["build", "--out", "fine", "--dpi", "76.2", "--background", "white"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let (w0, h0, _) = png_header(&std::fs::read(dir.join("default/pattern.png")).unwrap());
    let (w1, h1, _) = png_header(&std::fs::read(dir.join("fine/pattern.png")).unwrap());
    // 76.2 dpi is 30 px per cm: ten times the default 3.
    assert!((w1 as f64 / w0 as f64 - 10.0).abs() < 0.1 && (h1 as f64 / h0 as f64 - 10.0).abs() < 0.1, "{w0}x{h0} vs {w1}x{h1}");
    // The same drawing otherwise: the SVG does not change.
    assert_eq!(std::fs::read(dir.join("default/pattern.svg")).unwrap(), std::fs::read(dir.join("fine/pattern.svg")).unwrap());
    let o = run(&["render", "default/specification.json", "--out", "r", "--dpi", "0"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("dots per inch"), "{}", stderr(&o));
}

#[test]
fn a_huge_drawing_is_drawn_smaller_with_a_warning() {
    // A pattern in units of a third of a metre is 33 times larger in cm: its PNG
    // at 3 px per cm would be 11,219 × 10,603 px (490 MB while drawn).
    let dir = scratch("huge_png");
    assert_eq!(code(&run(&["build", "-o", "out", "--no-png"], &dir)), 0);
    let mut spec: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("out/specification.json")).unwrap()).unwrap();
    spec["properties"]["units_in_meter"] = serde_json::json!(3);
    std::fs::write(dir.join("u3.json"), spec.to_string()).unwrap();
    let o = run(&["render", "u3.json", "-o", "u3"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stderr(&o).contains("warning: pattern.png drawn at") && stderr(&o).contains("25 million pixels"), "{}", stderr(&o));
    let (w, h, _) = png_header(&std::fs::read(dir.join("u3/pattern.png")).unwrap());
    assert!(u64::from(w) * u64::from(h) <= garmentcode::draw::MAX_PNG_PIXELS && w > 4000, "{w} × {h}");
}

#[test]
fn bash_completion_offers_built_in_names_and_files() {
    let dir = scratch("completion");
    let o = run(&["completions", "bash"], &dir);
    assert_eq!(code(&o), 0);
    std::fs::write(dir.join("c.bash"), &o.stdout).unwrap();
    std::fs::write(dir.join("tshirt-mine.yaml"), "").unwrap();
    let complete = |words: &str, cur: &str, prev: &str| {
        let script = format!(
            "source c.bash; COMP_WORDS=({words}); COMP_CWORD=$((${{#COMP_WORDS[@]}} - 1)); _garmentcode garmentcode {cur} {prev}; echo \"${{COMPREPLY[@]}}\""
        );
        match std::process::Command::new("bash").arg("-c").arg(script).current_dir(&dir).output() {
            Ok(o) => Some(String::from_utf8_lossy(&o.stdout).trim().to_string()),
            Err(_) => None,
        }
    };
    let Some(design) = complete("garmentcode build --design t", "t", "--design") else {
        eprintln!("SKIPPED: no bash on this machine");
        return;
    };
    assert_eq!(design, "t-shirt tshirt-mine.yaml");
    assert_eq!(complete("garmentcode build --body mean_", "mean_", "--body").unwrap(), "mean_all mean_female mean_male");
    assert_eq!(complete("garmentcode schema -d jump", "jump", "-d").unwrap(), "jumpsuit");
    // zsh and fish offer files beside the names too.
    let zsh = stdout(&run(&["completions", "zsh"], &dir));
    assert!(zsh.contains(":{compadd t-shirt fitted-dress sundress shirt-dress jumpsuit birch-dress pleated-skirt pocket-shirt; _files}'"));
    let fish = stdout(&run(&["completions", "fish"], &dir));
    assert!(fish.contains("-l design") && fish.contains("-r -F -a \"t-shirt"));
}

#[test]
fn a_size_run_prints_every_size_nested_and_names_the_sizes_it_leaves_out() {
    let dir = scratch("size_run");
    let chart = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/size-charts/en13402-women-168.yaml");
    let o = run(&["print", "t-shirt", "--size-chart", chart.to_str().unwrap(), "--out", "run"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for n in ["pattern-tiled.pdf", "pattern-sheet.pdf", "pattern-sheet.svg", "pattern.dxf", "size-run.txt"] {
        assert!(dir.join("run").join(n).is_file(), "{n} missing");
    }
    let sizes = ["80", "84", "88", "92", "96"];
    let dxf_text = std::fs::read_to_string(dir.join("run/pattern.dxf")).unwrap();
    let dxf = garmentcode::fabricate::read_dxf(&dxf_text).unwrap();
    // One block per piece and size, each with its Size: field, all sizes of a piece
    // inserted at one point (nested).
    assert_eq!(dxf.blocks.len(), 4 * sizes.len());
    for b in &dxf.blocks {
        let size = b.name.rsplit('_').next().unwrap();
        assert!(sizes.contains(&size), "{}", b.name);
        assert!(b.entities.iter().any(|e| e.kind == "TEXT" && e.text == format!("Size: {size}")), "{}", b.name);
    }
    let inserts: Vec<_> = dxf.entities.iter().filter(|e| e.kind == "INSERT").collect();
    assert_eq!(inserts.len(), dxf.blocks.len());
    for piece in inserts.chunks(sizes.len()) {
        assert!(piece.iter().all(|i| i.points == piece[0].points), "the sizes of a piece are nested");
    }
    assert!(dxf.entities.iter().any(|e| e.kind == "TEXT" && e.text == "Size List: 80 84 88 92 96"));
    // Bigger sizes cut bigger pieces.
    let width = |name: &str| {
        let b = dxf.blocks.iter().find(|b| b.name == name).unwrap();
        let cut = b.entities.iter().find(|e| e.kind == "POLYLINE" && e.layer == "1").unwrap();
        let xs = cut.points.iter().map(|p| p.x);
        xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min)
    };
    assert!(width("right_ftorso_96") > width("right_ftorso_88") && width("right_ftorso_88") > width("right_ftorso_80"));
    let svg = std::fs::read_to_string(dir.join("run/pattern-sheet.svg")).unwrap();
    assert!(svg.contains(">size 80</text>") && svg.contains("Sizes: 80, 84, 88, 92, 96"), "a legend and the sizes on the labels");
    // ezdxf reads it, with every size's blocks (as in garmentcode's own DXF test; SKIPPED without ezdxf).
    let script = "import sys, json, ezdxf\ndoc = ezdxf.readfile(sys.argv[1])\nprint(json.dumps([len(doc.audit().errors), sorted({t.dxf.text for b in doc.blocks for t in b if t.dxftype() == 'TEXT' and t.dxf.text.startswith('Size:')})]))";
    if let Some(v) = common::ezdxf::read_back(
        "a_size_run_prints_every_size_nested_and_names_the_sizes_it_leaves_out",
        &dir.join("run/pattern.dxf"),
        script,
    ) {
        assert_eq!(v, serde_json::json!([0, ["Size: 80", "Size: 84", "Size: 88", "Size: 92", "Size: 96"]]));
    }
    // A size whose design fails is named with the reason; the others are written.
    std::fs::write(dir.join("tiny.yaml"), "body:\n  base: mean_female\n  height: 82\n").unwrap();
    let o = run(&["print", "jumpsuit", "--sizes", "mean_female,tiny.yaml,mean_male", "--out", "j"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stderr(&o).contains("warning: size tiny: left out: too long"), "{}", stderr(&o));
    let report = std::fs::read_to_string(dir.join("j/size-run.txt")).unwrap();
    assert!(
        report.contains("mean_female: printed") && report.contains("tiny: left out: too long") && report.contains("mean_male: printed"),
        "{report}"
    );
    let dxf = garmentcode::fabricate::read_dxf(&std::fs::read_to_string(dir.join("j/pattern.dxf")).unwrap()).unwrap();
    assert!(dxf.blocks.iter().all(|b| !b.name.ends_with("_tiny")));
    // Nothing built: refused, nothing written. A specification is not a design.
    let o = run(&["print", "jumpsuit", "--sizes", "tiny.yaml", "--out", "none"], &dir);
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(!dir.join("none").exists());
    let spec = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases/t-shirt-mean_all/specification.json");
    let o = run(&["print", spec.to_str().unwrap(), "--sizes", "mean_all", "--out", "none"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("a size run builds the design on every size"), "{}", stderr(&o));
    let o = run(&["print", "t-shirt", "--sizes", "mean_all", "--seam-edge", "nope=2", "--out", "none"], &dir);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("--seam-edge: no panel 'nope' in t-shirt (size mean_all)"), "{}", stderr(&o));
    assert!(!dir.join("none").exists());
    let o = run(&["print", "t-shirt", "--sizes", "mean_all", "--size-chart", "x.yaml", "--out", "none"], &dir);
    assert_eq!(code(&o), 2, "--sizes and --size-chart exclude each other");
}

#[test]
fn guide_writes_the_measuring_guide_for_a_body() {
    let dir = scratch("guide");
    std::fs::write(dir.join("me.yaml"), "body:\n  base: mean_female\n  units: in\n  height: 65\n  waist: 29\n").unwrap();
    let o = run(&["guide", "--body", "me.yaml", "--out", "g"], &dir);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let html = std::fs::read_to_string(dir.join("g/measuring-guide.html")).unwrap();
    assert!(html.contains("drawn on me.yaml") && html.contains("me.yaml: 73.66 cm"), "the body's own values, in cm");
    for m in garmentcode::MEASUREMENTS {
        assert!(html.contains(&format!(r#"id="{}""#, m.name)), "{}", m.name);
        let svg = std::fs::read_to_string(dir.join(format!("g/figure-{}.svg", m.name))).unwrap();
        assert!(svg.contains(r#"class="tape""#), "{}", m.name);
    }
    // Again into the same folder: its own files are replaced.
    assert_eq!(code(&run(&["guide", "--out", "g"], &dir)), 0);
    assert!(std::fs::read_to_string(dir.join("g/measuring-guide.html")).unwrap().contains("drawn on mean_all"));
}

#[test]
fn the_designs_past_the_reference_build_and_write_their_extension() {
    let dir = scratch("extension_designs");
    for design in ["birch-dress", "pleated-skirt", "pocket-shirt"] {
        let o = run(&["build", "--design", design, "-o", design, "--no-png"], &dir);
        assert_eq!(code(&o), 0, "{design}: {}", stderr(&o));
        let written = std::fs::read_to_string(dir.join(design).join("design_params.yaml")).unwrap();
        assert!(written.contains("extension:"), "{design}: the design is written with its extension");
    }
    // A design within the reference's space is written without it.
    let o = run(&["build", "--design", "t-shirt", "-o", "t-shirt", "--no-png"], &dir);
    assert_eq!(code(&o), 0);
    assert!(!std::fs::read_to_string(dir.join("t-shirt/design_params.yaml")).unwrap().contains("extension"));
}
