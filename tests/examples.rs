//! The runtime-only example garment (`examples/skirt_runtime.rs`) builds, passes
//! validation, fits the body it was made for, and emits a pinned pattern.

#[allow(dead_code)]
#[path = "../examples/skirt_runtime.rs"]
mod skirt_runtime;

use garmentcode::pattern::{Severity, validate};
use garmentcode::{Arena, PartExt};

#[test]
fn runtime_skirt_builds_and_fits() {
    let mut a = Arena::new();
    let skirt = skirt_runtime::build(&mut a).unwrap();
    // The waist interface is every gore's top minus its dart: the body's waist.
    assert!((skirt.waist.length(&a) - skirt_runtime::WAIST).abs() < 1e-9);
    assert_eq!(skirt.waist.len(&a), 2 * skirt_runtime::GORES);
    // Neighbouring gores meet: each seam joins sides of equal length.
    for rule in &skirt.seams {
        assert!(rule.is_matching(&a));
    }
    let pattern = skirt.assemble(&mut a, "gored_skirt").unwrap();
    assert_eq!(pattern.panels.len(), skirt_runtime::GORES);
    // Side seams plus one dart per gore.
    assert_eq!(pattern.stitches.len(), 2 * skirt_runtime::GORES);
    let problems = validate(&pattern);
    assert!(problems.iter().all(|p| p.severity != Severity::Error), "{problems:?}");
    assert!(problems.is_empty(), "no warnings either: {problems:?}");
    // The gores sit around the waist, at the waist level, all facing outwards.
    // The gores hang from the waist level.
    for p in &pattern.panels {
        let top = p.vertices.iter().map(|v| p.point_to_3d(garmentcode::Vec2::from(*v)).y).fold(f64::NEG_INFINITY, f64::max);
        assert!((top - skirt_runtime::WAIST_LEVEL).abs() < 1e-6, "{}: top at {top}", p.name);
    }
    insta::assert_snapshot!("skirt_runtime", pattern.to_json().unwrap());
}
