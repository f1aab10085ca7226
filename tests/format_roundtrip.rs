//! Every reference `specification.json` reads back into a `Pattern`, passes
//! validation without errors, and re-emits to a file that reads back to the same
//! pattern (bit-exact numbers).

use garmentcode::{Pattern, Severity, validate};
use std::path::PathBuf;

fn cases() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases");
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.is_dir()).collect();
    out.sort();
    out
}

#[test]
fn reference_specs_round_trip() {
    let mut n = 0;
    for case in cases() {
        let spec = case.join("specification.json");
        if !spec.exists() {
            continue;
        }
        let text = std::fs::read_to_string(&spec).unwrap();
        let p = Pattern::from_json(&text).unwrap_or_else(|e| panic!("{}: {e}", spec.display()));
        assert!(!p.panels.is_empty());
        let written = p.to_json().unwrap();
        let back = Pattern::from_json(&written).unwrap();
        assert!(p == back, "{}: the re-emitted pattern differs from the original", spec.display());
        assert_eq!(written, back.to_json().unwrap(), "writing is deterministic");
        n += 1;
    }
    assert_eq!(n, 57, "57 reference cases have a pattern");
}

#[test]
fn reference_specs_have_no_errors() {
    for case in cases() {
        let spec = case.join("specification.json");
        if !spec.exists() {
            continue;
        }
        let p = Pattern::from_json(&std::fs::read_to_string(&spec).unwrap()).unwrap();
        let errors: Vec<_> = validate(&p).into_iter().filter(|x| x.severity == Severity::Error).collect();
        assert!(errors.is_empty(), "{}: {errors:?}", spec.display());
    }
}

#[test]
fn self_intersection_verdicts_agree_with_the_reference() {
    use garmentcode::ProblemKind;
    let mut flagged = 0;
    for case in cases() {
        let spec = case.join("specification.json");
        if !spec.exists() {
            continue;
        }
        let p = Pattern::from_json(&std::fs::read_to_string(&spec).unwrap()).unwrap();
        let checks: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(case.join("checks.json")).unwrap()).unwrap();
        let expected = checks["self_intersecting"].as_bool().unwrap();
        let ours = validate(&p).iter().any(|x| x.kind == ProblemKind::SelfIntersection);
        assert_eq!(ours, expected, "{}", case.display());
        flagged += usize::from(ours);
    }
    assert!(flagged > 15, "about a third of the cases are flagged, got {flagged}");
}
