//! The parameter derives: schema, defaults, typed access, design files and sampling.

use garmentcode::{Choice, Kind, Params, Range, Sampler, Value, sample_rng};

use garmentcode::io::{read_design, write_design};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
enum Style {
    Plain,
    #[param(rename = "flared-hem")]
    Flared,
}

/// A skirt.
#[derive(Clone, Debug, PartialEq, Params)]
struct Skirt {
    /// Length as a fraction of the leg.
    #[param(range = -0.2..=0.95, default = 0.2)]
    length: f64,
    /// Number of panels.
    #[param(range = 4..=15, default = 4, prob = 0.5)]
    panels: i64,
    /// Hem curvature.
    #[param(options = [-0.35, 0, 0.45], default = 0)]
    curve: f64,
    /// Style of the hem.
    #[param(default = Plain, prob = 0.3)]
    style: Style,
    /// Optional style.
    #[param(default = None, prob = 0.7, rename = "extra-style")]
    extra: Option<Style>,
    /// Slit.
    #[param(default = false, prob = 0.8)]
    slit: bool,
}

#[derive(Clone, Debug, PartialEq, Params)]
struct Design {
    #[param(rename = "flare-skirt")]
    skirt: Skirt,
    /// Waist ease.
    #[param(range = 1..=2, default = 1)]
    ease: f64,
}

#[test]
fn schema_lists_every_parameter_in_order() {
    let space = Design::design_space();
    let paths: Vec<&str> = space.params().iter().map(|p| p.path.as_str()).collect();
    assert_eq!(
        paths,
        [
            "flare-skirt.length",
            "flare-skirt.panels",
            "flare-skirt.curve",
            "flare-skirt.style",
            "flare-skirt.extra-style",
            "flare-skirt.slit",
            "ease"
        ]
    );
    let p = space.get("flare-skirt.panels").unwrap();
    assert_eq!(p.kind, Kind::Int);
    assert_eq!(p.range, Range::Numeric { lo: 4.0, hi: 15.0 });
    assert_eq!(p.default, Value::Int(4));
    assert_eq!(p.default_prob, Some(0.5));
    assert_eq!(p.description, "Number of panels.");
    let c = space.get("flare-skirt.curve").unwrap();
    assert_eq!(c.kind, Kind::Select);
    assert_eq!(c.range, Range::Options(vec![Value::Float(-0.35), Value::Float(0.0), Value::Float(0.45)]));
    let e = space.get("flare-skirt.extra-style").unwrap();
    assert_eq!(e.kind, Kind::SelectNull);
    assert_eq!(e.range, Range::Options(vec![Value::Str("Plain".into()), Value::Str("flared-hem".into()), Value::Null]));
    assert!(space.problems().is_empty(), "{:?}", space.problems());
}

#[test]
fn design_files_round_trip() {
    let space = Design::design_space();
    let mut d = Design::defaults();
    d.skirt.length = 0.73;
    d.skirt.extra = Some(Style::Flared);
    d.skirt.panels = 9;
    let text = write_design(&d, &space);
    let back: Design = read_design(&text, "mem.yaml", &space).unwrap();
    assert_eq!(back, d);
}

#[test]
fn bad_values_name_file_path_and_range() {
    let space = Design::design_space();
    let text = "design:\n  flare-skirt:\n    length:\n      v: 1.5\n    stile:\n      v: Plain\n";
    let err = read_design::<Design>(text, "my.yaml", &space).unwrap_err().to_string();
    assert!(err.contains("my.yaml"), "{err}");
    assert!(err.contains("design.flare-skirt.length") && err.contains("[-0.2, 0.95]"), "{err}");
    assert!(err.contains("design.flare-skirt.stile") && err.contains("did you mean design.flare-skirt.style"), "{err}");
}

#[test]
fn sampling_is_reproducible() {
    let sampler = Sampler::new(Design::design_space());
    let a: Design = sampler.sample(&mut sample_rng(42, 7));
    let b: Design = sampler.sample(&mut sample_rng(42, 7));
    assert_eq!(a, b);
    let c: Design = sampler.sample(&mut sample_rng(42, 8));
    assert_ne!(a, c);
}

/// A design whose second skirt is kept out of its schema whole.
#[derive(Clone, Debug, PartialEq, Params)]
struct WithHidden {
    skirt: Skirt,
    #[param(skip)]
    hidden: Skirt,
}

#[test]
fn a_skipped_group_is_out_of_the_schema_but_reachable_by_path() {
    let space = WithHidden::design_space();
    assert!(space.params().iter().all(|p| p.path.starts_with("skirt.")), "{:?}", space.params());
    assert_eq!(space.params().len(), 6);
    let mut d = WithHidden::defaults();
    assert_eq!(d.hidden, Skirt::defaults());
    assert_eq!(d.get_value(&["hidden", "panels"]), Some(Value::Int(4)));
    d.set_value(&["hidden", "panels"], &Value::Int(9)).unwrap();
    assert_eq!(d.hidden.panels, 9);
    // Its own schema is still there for whoever adds it (as `extended_design_space` does).
    let mut own = Vec::new();
    Skirt::describe("hidden", &mut own);
    assert_eq!(own.len(), 6);
}
