//! The `SIGGRAPH_logo` decorative side cut of the pencil skirt.
//!
//! * The split halves of the bundled logo outline against the reference's
//!   (`EdgeSeqFactory.halfs_from_svg`, recorded by `tools/gen_logo_data.py halves`
//!   for widths from 2 to 120, where different short pieces are left out).
//! * Whole garments using the cut (`tests/data/logo_cases`, recorded by
//!   `tools/gen_logo_data.py cases`) judged against the reference's patterns like the
//!   parity test.

use garmentcode::io::read_design;
use garmentcode::{Arena, Body, Curve, EdgeSeq, Params, Vec2};
use garmentcode_compare::{CompareOptions, compare_spec_texts};
use garments::build::{BuildError, build_in};
use garments::meta::check_param_combinations;
use garments::shapes::siggraph_logo;
use garments::{Design, builtin};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/logo_cases")
}

fn pt(v: &Value) -> Vec2 {
    Vec2::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

/// Largest coordinate difference between our chains and the reference's, or a
/// description of a structural difference.
fn compare_half(a: &Arena, ours: &[EdgeSeq], theirs: &Value) -> Result<f64, String> {
    let theirs = theirs.as_array().unwrap();
    let counts = |o: &[EdgeSeq]| o.iter().map(|s| s.len()).collect::<Vec<_>>();
    let their_counts: Vec<usize> = theirs.iter().map(|s| s.as_array().unwrap().len()).collect();
    if counts(ours) != their_counts {
        return Err(format!("edge counts {:?} vs {:?}", counts(ours), their_counts));
    }
    let mut dev: f64 = 0.0;
    let mut d = |p: Vec2, q: Vec2| dev = dev.max((p.x - q.x).abs()).max((p.y - q.y).abs());
    for (seq, their) in ours.iter().zip(theirs) {
        for (&e, te) in seq.iter().zip(their.as_array().unwrap()) {
            let g = a.geom(e);
            d(g.start, pt(&te["start"]));
            d(g.end, pt(&te["end"]));
            match (g.curve, te.get("controls")) {
                (Curve::Line, None) => {}
                (Curve::Cubic(c1, c2), Some(c)) => {
                    d(c1, pt(&c[0]));
                    d(c2, pt(&c[1]));
                }
                (c, t) => return Err(format!("curve {c:?} vs {t:?}")),
            }
        }
    }
    Ok(dev)
}

#[test]
fn logo_halves_match_the_reference() {
    let text = std::fs::read_to_string(data_dir().join("halves.json")).unwrap();
    let cases: Value = serde_json::from_str(&text).unwrap();
    let mut failures = Vec::new();
    let mut max_dev: f64 = 0.0;
    for case in cases.as_array().unwrap() {
        let width = case["width"].as_f64().unwrap();
        let mut a = Arena::new();
        let (left, right) = siggraph_logo(&mut a, width).unwrap();
        for (side, ours, theirs) in [("left", &left, &case["left"]), ("right", &right, &case["right"])] {
            match compare_half(&a, ours, theirs) {
                Ok(dev) if dev <= 1e-10 => max_dev = max_dev.max(dev),
                Ok(dev) => failures.push(format!("width {width} {side}: deviation {dev:e}")),
                Err(m) => failures.push(format!("width {width} {side}: {m}")),
            }
        }
    }
    eprintln!("largest deviation from the reference halves: {max_dev:e}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn logo_halves_are_upward_chains_of_the_requested_height() {
    for width in [5.0, 17.0625, 30.0] {
        let mut a = Arena::new();
        let (left, right) = siggraph_logo(&mut a, width).unwrap();
        assert_eq!((left.len(), right.len()), (4, 4));
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut center = Vec::new();
        for (side, seqs) in [("left", &left), ("right", &right)] {
            for s in seqs.iter() {
                assert!(s.len() == 1 || s.is_chained(&a), "{side} half not chained");
                assert!(!s.is_loop(&a));
                let (p, q) = s.shortcut(&a);
                // Openings run upward along the vertical middle line.
                assert!(q.y > p.y, "{side} opening points down");
                assert!((p.x - q.x).abs() < 1e-9, "{side} opening not vertical");
                center.push(p.x);
                for v in s.vert_positions(&a) {
                    lo = lo.min(v.y);
                    hi = hi.max(v.y);
                }
                let ([x0, x1, ..], _) = s.bbox_points(&a);
                // QUIRK (reference): the halves it calls "left" lie right of the
                // middle line, the "right" ones left of it.
                if side == "left" {
                    assert!(x0 >= p.x - 1e-9, "{side} half crosses the middle line");
                } else {
                    assert!(x1 <= p.x + 1e-9, "{side} half crosses the middle line");
                }
            }
        }
        assert!(center.iter().all(|&x| (x - center[0]).abs() < 1e-9));
        // The vertices span (nearly) the whole height: the extremes of the
        // outline lie on curves, so compare with the sampled outline.
        let (mut slo, mut shi) = (f64::INFINITY, f64::NEG_INFINITY);
        for s in left.iter().chain(right.iter()) {
            for p in s.linearized_positions_n(&a, Some(200)) {
                slo = slo.min(p.y);
                shi = shi.max(p.y);
            }
        }
        assert!((shi - slo - width).abs() < 1e-3 * width, "height {} vs {width}", shi - slo);
        assert!(hi - lo <= width + 1e-9);
    }
}

/// Every case under `tests/data/logo_cases`.
fn cases() -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(data_dir()).unwrap().map(|e| e.unwrap().path()).filter(|p| p.is_dir()).collect();
    out.sort();
    out
}

fn body_of(case: &Path) -> Body {
    let name = std::fs::read_to_string(case.join("body.txt")).unwrap().trim().to_string();
    let local = case.join(&name);
    if local.exists() {
        return Body::from_yaml(&std::fs::read_to_string(&local).unwrap(), &name).unwrap();
    }
    builtin::body(name.trim_end_matches(".yaml")).unwrap_or_else(|| panic!("unknown body {name}"))
}

fn judge(case: &Path, space: &garmentcode::DesignSpace, arena: &mut Arena) -> Vec<String> {
    let read = |f: &str| std::fs::read_to_string(case.join(f)).unwrap();
    let design: Design = read_design(&read("design.yaml"), "design.yaml", space).unwrap();
    let body = body_of(case);
    let mut problems = Vec::new();
    let checks: Option<Value> = case.join("checks.json").exists().then(|| serde_json::from_str(&read("checks.json")).unwrap());
    if let Some(checks) = &checks {
        let ours = match check_param_combinations(&design) {
            Ok(()) => "ok".to_string(),
            Err(m) => format!("IncorrectElementConfiguration: {m}"),
        };
        if checks["param_combinations"] != ours.as_str() {
            problems.push(format!("param_combinations: {ours} vs the reference's {}", checks["param_combinations"]));
        }
    }
    let result = build_in(arena, &design, &body, "pattern");
    if !case.join("specification.json").exists() {
        let reason = read("error.txt");
        match result {
            Ok(_) => problems.push(format!("built, but the reference rejects it: {}", reason.trim())),
            Err(BuildError::Empty) if reason.contains("empty pattern") => {}
            Err(e) => problems.push(format!("rejected for another reason: ours '{e}', the reference's '{}'", reason.trim())),
        }
        return problems;
    }
    let built = match result {
        Ok(b) => b,
        Err(e) => return vec![format!("rejected ({e}), but the reference builds it")],
    };
    let verdict = compare_spec_texts(&read("specification.json"), &built.pattern.to_json().unwrap(), &CompareOptions::default());
    if !verdict.pass {
        problems.push(format!("pattern differs: {}", verdict.reasons.join("; ")));
    }
    if let Some(checks) = &checks {
        let c = &built.checks;
        let num = |k: &str| checks[k].as_f64().unwrap();
        if (c.total_length - num("total_length")).abs() > 0.05 {
            problems.push(format!("total_length {} vs {}", c.total_length, num("total_length")));
        }
        for (k, v) in [("total_length_ok", c.total_length_ok), ("self_intersecting", c.self_intersecting)] {
            if checks[k].as_bool() != Some(v) {
                problems.push(format!("{k}: {v} vs the reference's {}", checks[k]));
            }
        }
    }
    problems
}

#[test]
fn logo_cases_match_the_reference() {
    let space = Design::design_space();
    let mut arena = Arena::new();
    let mut failures = Vec::new();
    let all = cases();
    for case in &all {
        let problems = judge(case, &space, &mut arena);
        if !problems.is_empty() {
            failures.push(format!("{}:\n  {}", case.file_name().unwrap().to_string_lossy(), problems.join("\n  ")));
        }
    }
    eprintln!("{} logo cases, {} failed", all.len(), failures.len());
    assert!(all.len() >= 8, "expected the recorded logo cases");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
