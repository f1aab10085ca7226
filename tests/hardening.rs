//! Bad input found by testing and fuzzing (issue 16's reproducers): each must be a
//! clear error, quickly, never a hang, a panic or a huge allocation. Timings are
//! asserted loosely (a few seconds on a loaded machine); each finished in
//! milliseconds when written.

use garmentcode::{Body, Pattern};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/hardening").join(name)
}

fn bodies(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("garments/data/bodies").join(name)).unwrap()
}

fn design(name: &str) -> garments::Design {
    use garmentcode::Params;
    let text = std::fs::read_to_string(data(name)).unwrap();
    garmentcode::io::read_design(&text, name, &garments::Design::design_space()).unwrap()
}

/// A body file with one measurement replaced.
fn body_with(base: &str, key: &str, value: &str) -> String {
    let text = bodies(base);
    let mut found = false;
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            if l.trim_start().starts_with(&format!("{key}:")) {
                found = true;
                format!("  {key}: {value}")
            } else {
                l.to_string()
            }
        })
        .collect();
    assert!(found, "{key} in {base}");
    lines.join("\n") + "\n"
}

/// Run `f`, asserting it returns within `limit`.
fn within<T>(limit: Duration, what: &str, f: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let out = f();
    assert!(start.elapsed() < limit, "{what} took {:?}", start.elapsed());
    out
}

const FAST: Duration = Duration::from_secs(5);

mod common;
use common::{run as cli, scratch};

#[test]
fn a_body_in_metres_is_refused_at_once_with_a_hint() {
    let dir = scratch("metres");
    let o = within(FAST, "build", || {
        cli(
            &[
                "build",
                "--design",
                data("case-021-design.yaml").to_str().unwrap(),
                "--body",
                data("mean_female-leg_circ-in-metres.yaml").to_str().unwrap(),
                "--out",
                "out",
            ],
            &dir,
        )
    });
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("body.leg_circ: 0.606592 cm is outside the plausible range"), "{err}");
    assert!(err.contains("looks like metres"), "{err}");
    assert!(!dir.join("out").exists());
}

#[test]
fn geometry_from_a_body_in_metres_still_finishes_quickly() {
    // Past the body check (a tool setting the value directly): the build must end
    // in bounded time, with or without a pattern.
    let mut body = Body::from_yaml(&bodies("mean_female.yaml"), "mean_female").unwrap();
    body.set("leg_circ", 0.606592);
    let d = design("case-021-design.yaml");
    let _ = within(FAST, "build", || garments::build::build(&d, &body, "metres"));
}

#[test]
fn a_dart_narrower_than_the_tolerance_is_an_error_not_a_panic() {
    let d = design("case-048-design.yaml");
    for v in [0.3, 0.1, 0.01] {
        let mut body = Body::from_yaml(&bodies("mean_female.yaml"), "mean_female").unwrap();
        body.set("bust_points", v);
        let r = within(FAST, "build", || garments::build::build(&d, &body, "narrow"));
        let e = r.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains("too narrow"), "bust_points {v}: {e}");
    }
    // And through a body file, the range check names it first.
    let text = body_with("mean_female.yaml", "bust_points", "0.3");
    let e = Body::from_yaml(&text, "b.yaml").unwrap_err().to_string();
    assert!(e.contains("body.bust_points: 0.3 cm is outside the plausible range 6 to 40 cm"), "{e}");
}

#[test]
fn every_measurement_far_out_of_range_is_refused_naming_it() {
    for m in garmentcode::MEASUREMENTS {
        for v in ["0.000001", "1000000.0", "-1.0"] {
            if m.unit == "deg" && v == "0.000001" {
                continue; // a tiny angle is a plausible angle
            }
            let text = if m.optional && !bodies("mean_female.yaml").contains(m.name) {
                bodies("mean_female.yaml").replace("body:\n", &format!("body:\n  {}: {v}\n", m.name))
            } else {
                body_with("mean_female.yaml", m.name, v)
            };
            let e = Body::from_yaml(&text, "b.yaml").unwrap_err().to_string();
            assert!(e.contains(&format!("body.{}: ", m.name)) && e.contains("plausible range"), "{} = {v}: {e}", m.name);
        }
    }
}

#[test]
fn absurd_numbers_in_a_specification_are_refused() {
    let spec = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases/case-001/specification.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&spec).unwrap();
    let edit = |f: &dyn Fn(&mut serde_json::Value)| {
        let mut v = v.clone();
        f(&mut v);
        serde_json::to_string(&v).unwrap()
    };
    let first_panel =
        |v: &mut serde_json::Value| -> serde_json::Value { v["pattern"]["panels"].as_object().unwrap().values().next().unwrap().clone() };
    let set_panel = |v: &mut serde_json::Value, p: serde_json::Value| {
        let name = v["pattern"]["panels"].as_object().unwrap().keys().next().unwrap().clone();
        v["pattern"]["panels"][name] = p;
    };
    let cases: Vec<(&str, String)> = vec![
        (
            "beyond",
            edit(&|v| {
                let mut p = first_panel(v);
                p["vertices"][0][0] = serde_json::json!(1e308);
                set_panel(v, p);
            }),
        ),
        (
            "control point",
            edit(&|v| {
                let mut p = first_panel(v);
                p["edges"][0]["curvature"] = serde_json::json!({"type": "cubic", "params": [[1e200, 3.0], [0.5, -1e200]]});
                set_panel(v, p);
            }),
        ),
        ("units_in_meter", edit(&|v| v["properties"]["units_in_meter"] = serde_json::json!(1e-300))),
        (
            "at most 500 are accepted",
            edit(&|v| {
                let mut p = first_panel(v);
                let e = p["edges"][0].clone();
                p["edges"] = serde_json::Value::Array(vec![e; 501]);
                set_panel(v, p);
            }),
        ),
        (
            "edges in all: at most 5000 are accepted",
            edit(&|v| {
                let mut p = first_panel(v);
                let e = p["edges"][0].clone();
                p["edges"] = serde_json::Value::Array(vec![e; 500]);
                for k in 0..11 {
                    v["pattern"]["panels"][format!("copy_{k}")] = p.clone();
                }
            }),
        ),
    ];
    for (expect, text) in cases {
        let e = within(FAST, "parse", || Pattern::from_json(&text)).unwrap_err().to_string();
        assert!(e.contains(expect), "{expect}: {e}");
    }
}

#[test]
fn overlapping_curves_stop_the_intersection_search() {
    use garmentcode::parity::svgpath::{IntersectError, Seg, try_intersect as intersect};
    let c = [[0.0, 0.0], [30.0, 40.0], [70.0, -40.0], [100.0, 0.0]];
    // The same curve traversed backwards: equal everywhere, unequal as segments.
    let back = [c[3], c[2], c[1], c[0]];
    let r = within(FAST, "intersect", || intersect(&Seg::Cubic(c), &Seg::Cubic(back)));
    assert_eq!(r, Err(IntersectError::TooManyPairs));
}

#[test]
fn the_absurd_specification_reproducers_are_refused_by_check_and_render() {
    let dir = scratch("absurd_specs");
    for (file, expect) in [
        ("spec-vertex-1e308.json", "beyond"),
        ("spec-huge-control-points.json", "control point"),
        ("spec-units-1e-300.json", "units_in_meter"),
    ] {
        let path = data(file);
        for args in [vec!["check", path.to_str().unwrap()], vec!["render", path.to_str().unwrap(), "-o", "r"]] {
            let o = within(FAST, file, || cli(&args, &dir));
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
            assert!(err.contains(expect), "{args:?}: {err}");
        }
    }
}

#[test]
fn a_design_with_270_000_keys_reads_in_linear_time_with_a_short_error() {
    use garmentcode::Params;
    let mut text = String::from("design:\n");
    for i in 0..270_000 {
        text.push_str(&format!("  k{i}: 1\n"));
    }
    let space = garments::Design::design_space();
    let e = within(FAST, "read_design", || garmentcode::io::read_design::<garments::Design>(&text, "many.yaml", &space)).unwrap_err();
    let shown = e.to_string();
    assert!(shown.len() < 10_000, "{} bytes of error", shown.len());
    assert!(shown.contains("270000 problems") && shown.contains("... and 269980 more"), "{}", &shown[..300.min(shown.len())]);
    // Duplicate keys are still found among many.
    let dup = format!("{text}  k5: 2\n");
    let e = garmentcode::io::read_design::<garments::Design>(&dup, "dup.yaml", &space).unwrap_err().to_string();
    assert!(e.contains("duplicate mapping key"), "{}", &e[..200.min(e.len())]);
}

#[test]
fn an_endless_input_file_is_refused_at_a_bound() {
    if !Path::new("/dev/zero").exists() {
        eprintln!("skipped: this system has no /dev/zero");
        return;
    }
    let dir = scratch("endless_input");
    for args in [
        vec!["build", "-d", "/dev/zero", "-o", "out"],
        vec!["build", "-b", "/dev/zero", "-o", "out"],
        vec!["check", "/dev/zero"],
        vec!["mesh", "/dev/zero", "-o", "out"],
        vec!["sample", "--n", "2", "--seed", "1", "--design-space", "/dev/zero", "--out", "out"],
    ] {
        let o = within(FAST, &args.join(" "), || cli(&args, &dir));
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("/dev/zero") && err.contains("larger than 64 MB"), "{args:?}: {err}");
        assert!(!dir.join("out").exists(), "{args:?} wrote its output");
    }
}

/// `mesh` refuses what `check` calls errors (a panel scaled down to 1e-9 cm, one that
/// encloses no area, one of two corners), as `render` does, and bounds its work: a panel
/// at the coordinate limit is refused at once with the resolution that fits, an edge
/// bulging 900 edge lengths out is measured and meshed; each within seconds.
#[test]
fn mesh_refuses_what_check_rejects_and_bounds_its_work() {
    let dir = scratch("mesh_bounds");
    for (file, kind) in [
        ("spec-mesh-tiny-panel.json", "degenerate_edge"),
        ("spec-zero-area-panel.json", "zero_area"),
        ("spec-two-vertex-panel.json", "empty_panel"),
    ] {
        let path = data(file);
        let path = path.to_str().unwrap();
        let o = within(FAST, file, || cli(&["check", path], &dir));
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "check {file}: {out}");
        assert!(out.contains(&format!("error[{kind}]")), "check {file}: {out}");
        for args in [vec!["render", path, "-o", "out"], vec!["mesh", path, "-o", "out"]] {
            let o = within(FAST, file, || cli(&args, &dir));
            let err = String::from_utf8_lossy(&o.stderr);
            assert_ne!(o.status.code(), Some(0), "{args:?}: {err}");
            assert!(err.contains(file) && err.contains(kind), "{args:?}: {err}");
            assert!(!dir.join("out").exists(), "{args:?} wrote its output");
        }
    }
    let file = "spec-mesh-100m-panel.json";
    let o = within(FAST, file, || cli(&["mesh", data(file).to_str().unwrap(), "-o", "out"], &dir));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains(file) && err.contains("mesh it at 22 cm or coarser"), "{err}");
    assert!(!dir.join("out").exists(), "wrote its output");
    let file = data("spec-mesh-far-control-point.json");
    let o = within(FAST, "far control point", || cli(&["mesh", file.to_str().unwrap(), "-o", "out", "-r", "5"], &dir));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
}
