//! The example garments build, pass validation, fit the body they were made for,
//! and emit pinned patterns: the runtime-only skirt (`examples/skirt_runtime.rs`)
//! and the paper's skirt written with the macros (`examples/paper_skirt.rs`).

#[allow(dead_code)]
#[path = "../examples/skirt_runtime.rs"]
mod skirt_runtime;

#[allow(dead_code)]
#[path = "../examples/paper_skirt.rs"]
mod paper_skirt;

#[allow(dead_code)]
#[path = "../examples/birch_dress.rs"]
mod birch_dress;

use garmentcode::{Arena, PartExt, Severity, validate};

#[test]
fn birch_dress_has_diamond_darts_that_take_in_the_waist() {
    let body = garments::builtin::body(garments::builtin::DEFAULT_BODY).unwrap();
    let mut a = Arena::new();
    let dress = birch_dress::SheathDress::new(&mut a, &body).unwrap();
    // Side seams and shoulders match without splitting.
    for rule in &dress.seams {
        assert!(rule.is_matching(&a));
        assert_eq!(rule.a.len(&a), rule.b.len(&a));
    }
    let pattern = dress.assemble(&mut a, "birch_dress").unwrap();
    assert_eq!(pattern.panels.len(), 2);
    assert_eq!(pattern.stitches.len(), 2 + 2 + 1 + 1);
    // Two darts per panel, two seams per dart, each between sides of its own hole.
    assert_eq!(pattern.inner_stitches.len(), 8);
    let w_bust = (body.bust + birch_dress::EASE) / 2.0;
    let w_waist = (body.waist + birch_dress::EASE) / 2.0;
    for p in &pattern.panels {
        assert_eq!(p.holes.len(), 2, "{}", p.name);
        // Their widths add up to what the waist lacks of the bust.
        let widths: f64 = p
            .holes
            .iter()
            .map(|h| {
                let xs = h.vertices.iter().map(|v| v[0]);
                xs.clone().fold(f64::NEG_INFINITY, f64::max) - xs.fold(f64::INFINITY, f64::min)
            })
            .sum();
        assert!((widths - (w_bust - w_waist)).abs() < 1e-6, "{}: {widths}", p.name);
    }
    let problems = validate(&pattern);
    assert!(problems.iter().all(|p| p.severity != Severity::Error), "{problems:?}");
}

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

#[test]
fn paper_skirt_builds_from_its_design_file() {
    use garmentcode::io::{read_design, write_design};
    use garmentcode::{Body, Interfaces, Params};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let space = paper_skirt::Design::design_space();
    let text = std::fs::read_to_string(root.join("examples/data/paper_skirt.yaml")).unwrap();
    let design: paper_skirt::Design = read_design(&text, "paper_skirt.yaml", &space).unwrap();
    assert_eq!(design.skirt.n_panels, 8);
    // The design file is in the reference's format, and writing it back keeps it.
    assert_eq!(write_design(&design, &space), text);
    let body_text = std::fs::read_to_string(root.join("garments/data/bodies/mean_all.yaml")).unwrap();
    let body = Body::from_yaml(&body_text, "mean_all.yaml").unwrap();

    let mut a = Arena::new();
    let skirt = paper_skirt::FlareSkirt::new(&mut a, &body, &design.skirt).unwrap();
    assert_eq!(skirt.interfaces(), [("top", skirt.top)]);
    // Every panel is a ThinSkirtPanel with interfaces of its own panel.
    for p in &skirt.panels {
        assert_eq!(p.interfaces().iter().map(|(n, _)| *n).collect::<Vec<_>>(), ["right", "top", "left"]);
        assert!(p.interfaces().iter().all(|(_, i)| i.panels(&a) == [p.panel]));
    }
    assert!((skirt.top.length(&a) - body.waist).abs() < 1e-9, "the waistline is the body's waist");
    let pattern = skirt.assemble(&mut a, "paper_skirt").unwrap();
    let names: Vec<&str> = pattern.panels.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names.len(), 8);
    assert!(names.iter().all(|n| n.starts_with("skirt_")), "{names:?}");
    assert_eq!(pattern.stitches.len(), 8, "each panel sewn to the next, around");
    let problems = validate(&pattern);
    assert!(problems.is_empty(), "{problems:?}");
    insta::assert_snapshot!("paper_skirt", pattern.to_json().unwrap());

    // Retargeting: the same design on another body fits that body's waist.
    let other =
        Body::from_yaml(&std::fs::read_to_string(root.join("garments/data/bodies/mean_male.yaml")).unwrap(), "mean_male.yaml").unwrap();
    let mut a = Arena::new();
    let skirt = paper_skirt::FlareSkirt::new(&mut a, &other, &design.skirt).unwrap();
    assert!((skirt.top.length(&a) - other.waist).abs() < 1e-9);
}
