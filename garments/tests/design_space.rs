//! The design space equals the reference's default design file in every parameter's
//! path, type, range or options, default and probability (figures from the
//! reference's `default.yaml`, 122 parameters, in document order).

use garmentcode::{Kind, Params, Range, Value};
use garments::Design;

#[derive(Debug)]
enum V {
    N,
    B(bool),
    F(f64),
    S(&'static str),
}
use V::*;

fn same(v: &V, x: &Value) -> bool {
    match (v, x) {
        (N, Value::Null) => true,
        (B(a), Value::Bool(b)) => a == b,
        (F(a), _) => x.as_f64() == Some(*a),
        (S(a), Value::Str(b)) => a == b,
        _ => false,
    }
}

/// Path, type, range, default value and sampling probability of one parameter.
type Row = (&'static str, &'static str, &'static [V], V, Option<f64>);

#[rustfmt::skip]
const REFERENCE: &[Row] = &[
    ("meta.upper", "select_null", &[S("FittedShirt"), S("Shirt"), N], N, Some(0.3)),
    ("meta.wb", "select_null", &[S("StraightWB"), S("FittedWB"), N], N, Some(0.5)),
    ("meta.bottom", "select_null", &[S("SkirtCircle"), S("AsymmSkirtCircle"), S("GodetSkirt"), S("Pants"), S("Skirt2"), S("SkirtManyPanels"), S("PencilSkirt"), S("SkirtLevels"), N], N, Some(0.3)),
    ("waistband.waist", "float", &[F(1.0), F(2.0)], F(1.0), Some(0.7)),
    ("waistband.width", "float", &[F(0.1), F(1.0)], F(0.2), Some(0.5)),
    ("shirt.strapless", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("shirt.length", "float", &[F(0.5), F(3.5)], F(1.2), Some(0.7)),
    ("shirt.width", "float", &[F(1.0), F(1.3)], F(1.05), Some(0.4)),
    ("shirt.flare", "float", &[F(0.7), F(1.6)], F(1.0), Some(0.4)),
    ("collar.f_collar", "select", &[S("CircleNeckHalf"), S("CurvyNeckHalf"), S("VNeckHalf"), S("SquareNeckHalf"), S("TrapezoidNeckHalf"), S("CircleArcNeckHalf"), S("Bezier2NeckHalf")], S("CircleNeckHalf"), Some(0.4)),
    ("collar.b_collar", "select", &[S("CircleNeckHalf"), S("CurvyNeckHalf"), S("VNeckHalf"), S("SquareNeckHalf"), S("TrapezoidNeckHalf"), S("CircleArcNeckHalf"), S("Bezier2NeckHalf")], S("CircleNeckHalf"), Some(0.8)),
    ("collar.width", "float", &[F(-0.5), F(1.0)], F(0.2), Some(0.4)),
    ("collar.fc_depth", "float", &[F(0.3), F(2.0)], F(0.4), Some(0.3)),
    ("collar.bc_depth", "float", &[F(0.0), F(2.0)], F(0.0), Some(0.4)),
    ("collar.fc_angle", "int", &[F(70.0), F(110.0)], F(95.0), None),
    ("collar.bc_angle", "int", &[F(70.0), F(110.0)], F(95.0), None),
    ("collar.f_bezier_x", "float", &[F(0.05), F(0.95)], F(0.3), Some(0.4)),
    ("collar.f_bezier_y", "float", &[F(0.05), F(0.95)], F(0.55), Some(0.4)),
    ("collar.b_bezier_x", "float", &[F(0.05), F(0.95)], F(0.15), Some(0.4)),
    ("collar.b_bezier_y", "float", &[F(0.05), F(0.95)], F(0.1), Some(0.4)),
    ("collar.f_flip_curve", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("collar.b_flip_curve", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("collar.component.style", "select_null", &[S("Turtle"), S("SimpleLapel"), S("Hood2Panels"), N], N, Some(0.6)),
    ("collar.component.depth", "int", &[F(2.0), F(8.0)], F(7.0), None),
    ("collar.component.lapel_standing", "bool", &[B(true), B(false)], B(false), None),
    ("collar.component.hood_depth", "float", &[F(1.0), F(2.0)], F(1.0), Some(0.6)),
    ("collar.component.hood_length", "float", &[F(1.0), F(1.5)], F(1.0), Some(0.6)),
    ("sleeve.sleeveless", "bool", &[B(true), B(false)], B(true), Some(0.7)),
    ("sleeve.armhole_shape", "select", &[S("ArmholeSquare"), S("ArmholeAngle"), S("ArmholeCurve")], S("ArmholeCurve"), Some(0.7)),
    ("sleeve.length", "float", &[F(0.1), F(1.15)], F(0.3), None),
    ("sleeve.connecting_width", "float", &[F(0.0), F(2.0)], F(0.2), Some(0.6)),
    ("sleeve.end_width", "float", &[F(0.2), F(2.0)], F(1.0), Some(0.4)),
    ("sleeve.sleeve_angle", "int", &[F(10.0), F(50.0)], F(10.0), None),
    ("sleeve.opening_dir_mix", "float", &[F(-0.9), F(0.8)], F(0.1), Some(1.0)),
    ("sleeve.standing_shoulder", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("sleeve.standing_shoulder_len", "float", &[F(4.0), F(10.0)], F(5.0), None),
    ("sleeve.connect_ruffle", "float", &[F(1.0), F(2.0)], F(1.0), Some(0.4)),
    ("sleeve.smoothing_coeff", "float", &[F(0.1), F(0.4)], F(0.25), Some(0.8)),
    ("sleeve.cuff.type", "select_null", &[S("CuffBand"), S("CuffSkirt"), S("CuffBandSkirt"), N], N, None),
    ("sleeve.cuff.top_ruffle", "float", &[F(1.0), F(3.0)], F(1.0), None),
    ("sleeve.cuff.cuff_len", "float", &[F(0.05), F(0.9)], F(0.1), Some(0.7)),
    ("sleeve.cuff.skirt_fraction", "float", &[F(0.1), F(0.9)], F(0.5), Some(0.5)),
    ("sleeve.cuff.skirt_flare", "float", &[F(1.0), F(2.0)], F(1.2), None),
    ("sleeve.cuff.skirt_ruffle", "float", &[F(1.0), F(1.5)], F(1.0), Some(0.3)),
    ("left.enable_asym", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("left.shirt.strapless", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("left.shirt.width", "float", &[F(1.0), F(1.3)], F(1.0), Some(0.4)),
    ("left.shirt.flare", "float", &[F(0.7), F(1.6)], F(1.0), Some(0.4)),
    ("left.collar.f_collar", "select", &[S("CircleNeckHalf"), S("CurvyNeckHalf"), S("VNeckHalf"), S("SquareNeckHalf"), S("TrapezoidNeckHalf"), S("CircleArcNeckHalf"), S("Bezier2NeckHalf")], S("CircleNeckHalf"), Some(0.4)),
    ("left.collar.b_collar", "select", &[S("CircleNeckHalf"), S("CurvyNeckHalf"), S("VNeckHalf"), S("SquareNeckHalf"), S("TrapezoidNeckHalf"), S("CircleArcNeckHalf"), S("Bezier2NeckHalf")], S("CircleNeckHalf"), Some(0.8)),
    ("left.collar.width", "float", &[F(0.0), F(1.0)], F(0.5), Some(0.4)),
    ("left.collar.fc_angle", "int", &[F(70.0), F(110.0)], F(95.0), None),
    ("left.collar.bc_angle", "int", &[F(70.0), F(110.0)], F(95.0), None),
    ("left.collar.f_bezier_x", "float", &[F(0.05), F(0.95)], F(0.5), Some(0.4)),
    ("left.collar.f_bezier_y", "float", &[F(0.05), F(0.95)], F(0.3), None),
    ("left.collar.b_bezier_x", "float", &[F(0.05), F(0.95)], F(0.5), Some(0.4)),
    ("left.collar.b_bezier_y", "float", &[F(0.05), F(0.95)], F(0.3), None),
    ("left.collar.f_flip_curve", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("left.collar.b_flip_curve", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("left.sleeve.sleeveless", "bool", &[B(true), B(false)], B(true), Some(0.7)),
    ("left.sleeve.armhole_shape", "select", &[S("ArmholeSquare"), S("ArmholeAngle"), S("ArmholeCurve")], S("ArmholeCurve"), Some(0.7)),
    ("left.sleeve.length", "float", &[F(0.1), F(1.15)], F(0.3), None),
    ("left.sleeve.connecting_width", "float", &[F(0.0), F(2.0)], F(0.2), Some(0.6)),
    ("left.sleeve.end_width", "float", &[F(0.2), F(2.0)], F(1.0), Some(0.4)),
    ("left.sleeve.sleeve_angle", "int", &[F(10.0), F(50.0)], F(10.0), None),
    ("left.sleeve.opening_dir_mix", "float", &[F(-0.9), F(0.8)], F(0.2), Some(1.0)),
    ("left.sleeve.standing_shoulder", "bool", &[B(true), B(false)], B(false), Some(0.8)),
    ("left.sleeve.standing_shoulder_len", "float", &[F(4.0), F(10.0)], F(5.0), None),
    ("left.sleeve.connect_ruffle", "float", &[F(1.0), F(2.0)], F(1.0), Some(0.4)),
    ("left.sleeve.smoothing_coeff", "float", &[F(0.1), F(0.4)], F(0.25), Some(0.8)),
    ("left.sleeve.cuff.type", "select_null", &[S("CuffBand"), S("CuffSkirt"), S("CuffBandSkirt"), N], N, None),
    ("left.sleeve.cuff.top_ruffle", "float", &[F(1.0), F(2.0)], F(1.0), None),
    ("left.sleeve.cuff.cuff_len", "float", &[F(0.05), F(0.9)], F(0.1), Some(0.7)),
    ("left.sleeve.cuff.skirt_fraction", "float", &[F(0.1), F(0.9)], F(0.5), Some(0.5)),
    ("left.sleeve.cuff.skirt_flare", "float", &[F(1.0), F(2.0)], F(1.2), None),
    ("left.sleeve.cuff.skirt_ruffle", "float", &[F(1.0), F(1.5)], F(1.0), Some(0.3)),
    ("skirt.length", "float", &[F(-0.2), F(0.95)], F(0.2), None),
    ("skirt.rise", "float", &[F(0.5), F(1.0)], F(1.0), Some(0.3)),
    ("skirt.ruffle", "float", &[F(1.0), F(2.0)], F(1.3), Some(0.3)),
    ("skirt.bottom_cut", "float", &[F(0.0), F(0.9)], F(0.0), Some(0.3)),
    ("skirt.flare", "int", &[F(0.0), F(20.0)], F(0.0), Some(0.5)),
    ("flare-skirt.length", "float", &[F(-0.2), F(0.95)], F(0.2), None),
    ("flare-skirt.rise", "float", &[F(0.5), F(1.0)], F(1.0), Some(0.3)),
    ("flare-skirt.suns", "float", &[F(0.1), F(1.95)], F(0.75), None),
    ("flare-skirt.skirt-many-panels.n_panels", "int", &[F(4.0), F(15.0)], F(4.0), None),
    ("flare-skirt.skirt-many-panels.panel_curve", "select", &[F(-0.35), F(-0.25), F(-0.15), F(0.0), F(0.15), F(0.25), F(0.35), F(0.45)], F(0.0), None),
    ("flare-skirt.asymm.front_length", "float", &[F(0.1), F(0.9)], F(0.5), Some(0.5)),
    ("flare-skirt.cut.add", "bool", &[B(true), B(false)], B(false), Some(0.6)),
    ("flare-skirt.cut.depth", "float", &[F(0.05), F(0.95)], F(0.5), Some(0.6)),
    ("flare-skirt.cut.width", "float", &[F(0.05), F(0.4)], F(0.1), None),
    ("flare-skirt.cut.place", "float", &[F(-1.0), F(1.0)], F(-0.5), None),
    ("godet-skirt.base", "select", &[S("Skirt2"), S("PencilSkirt")], S("PencilSkirt"), Some(0.7)),
    ("godet-skirt.insert_w", "int", &[F(10.0), F(50.0)], F(15.0), None),
    ("godet-skirt.insert_depth", "int", &[F(10.0), F(50.0)], F(20.0), None),
    ("godet-skirt.num_inserts", "select", &[F(4.0), F(6.0), F(8.0), F(10.0), F(12.0)], F(4.0), None),
    ("godet-skirt.cuts_distance", "int", &[F(0.0), F(10.0)], F(5.0), None),
    ("pencil-skirt.length", "float", &[F(0.2), F(0.95)], F(0.4), None),
    ("pencil-skirt.rise", "float", &[F(0.5), F(1.0)], F(1.0), Some(0.3)),
    ("pencil-skirt.flare", "float", &[F(0.6), F(1.5)], F(1.0), Some(0.3)),
    ("pencil-skirt.low_angle", "int", &[F(-30.0), F(30.0)], F(0.0), Some(0.7)),
    ("pencil-skirt.front_slit", "float", &[F(0.0), F(0.9)], F(0.0), Some(0.4)),
    ("pencil-skirt.back_slit", "float", &[F(0.0), F(0.9)], F(0.0), Some(0.4)),
    ("pencil-skirt.left_slit", "float", &[F(0.0), F(0.9)], F(0.0), Some(0.6)),
    ("pencil-skirt.right_slit", "float", &[F(0.0), F(0.9)], F(0.0), Some(0.6)),
    ("pencil-skirt.style_side_cut", "select_null", &[S("Sun"), S("SIGGRAPH_logo")], N, Some(1.0)),
    ("levels-skirt.base", "select", &[S("Skirt2"), S("PencilSkirt"), S("SkirtCircle"), S("AsymmSkirtCircle")], S("PencilSkirt"), None),
    ("levels-skirt.level", "select", &[S("Skirt2"), S("SkirtCircle"), S("AsymmSkirtCircle")], S("Skirt2"), None),
    ("levels-skirt.num_levels", "int", &[F(1.0), F(5.0)], F(1.0), None),
    ("levels-skirt.level_ruffle", "float", &[F(1.0), F(1.7)], F(1.0), None),
    ("levels-skirt.length", "float", &[F(0.2), F(0.95)], F(0.5), None),
    ("levels-skirt.rise", "float", &[F(0.5), F(1.0)], F(1.0), Some(0.3)),
    ("levels-skirt.base_length_frac", "float", &[F(0.2), F(0.8)], F(0.5), None),
    ("pants.length", "float", &[F(0.2), F(0.9)], F(0.3), None),
    ("pants.width", "float", &[F(1.0), F(1.5)], F(1.0), Some(0.5)),
    ("pants.flare", "float", &[F(0.5), F(1.2)], F(1.0), Some(0.3)),
    ("pants.rise", "float", &[F(0.5), F(1.0)], F(1.0), Some(0.3)),
    ("pants.cuff.type", "select_null", &[S("CuffBand"), S("CuffSkirt"), S("CuffBandSkirt"), N], N, Some(0.5)),
    ("pants.cuff.top_ruffle", "float", &[F(1.0), F(2.0)], F(1.0), None),
    ("pants.cuff.cuff_len", "float", &[F(0.05), F(0.9)], F(0.1), Some(0.3)),
    ("pants.cuff.skirt_fraction", "float", &[F(0.1), F(0.9)], F(0.5), None),
    ("pants.cuff.skirt_flare", "float", &[F(1.0), F(2.0)], F(1.2), None),
    ("pants.cuff.skirt_ruffle", "float", &[F(1.0), F(1.5)], F(1.0), None),
];

#[test]
fn design_space_equals_the_reference_default_design() {
    let space = Design::design_space();
    let ours = space.params();
    assert_eq!(ours.len(), REFERENCE.len(), "number of parameters");
    for (p, (path, ty, range, default, prob)) in ours.iter().zip(REFERENCE) {
        assert_eq!(p.path, *path, "parameter order");
        assert_eq!(p.kind, Kind::parse(ty).unwrap(), "{path}: type");
        match &p.range {
            Range::Numeric { lo, hi } => {
                assert!(
                    range.len() == 2 && same(&range[0], &Value::Float(*lo)) && same(&range[1], &Value::Float(*hi)),
                    "{path}: range {range:?} vs [{lo}, {hi}]"
                )
            }
            Range::Options(opts) => {
                assert_eq!(opts.len(), range.len(), "{path}: options {range:?} vs {opts:?}");
                for (o, r) in opts.iter().zip(range.iter()) {
                    assert!(same(r, o), "{path}: option {r:?} vs {o:?}");
                }
            }
        }
        assert!(same(default, &p.default), "{path}: default {default:?} vs {:?}", p.default);
        assert_eq!(p.default_prob, *prob, "{path}: default_prob");
        assert!(!p.description.is_empty(), "{path}: has a description");
    }
    assert!(space.problems().is_empty(), "{:?}", space.problems());
}

/// Every reference case's design file reads into the typed design and writes back
/// with every value kept (the written file reads to the same values and the same
/// design, and writing is stable).
#[test]
fn design_files_keep_every_value_through_read_and_write() {
    use garmentcode::io::{read_design, read_design_values, write_design};
    let space = Design::design_space();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases");
    let mut n = 0;
    for case in std::fs::read_dir(dir).unwrap() {
        let file = case.unwrap().path().join("design.yaml");
        if !file.exists() {
            continue;
        }
        let text = std::fs::read_to_string(&file).unwrap();
        let values = read_design_values(&text, "design.yaml", &space).unwrap();
        let design: Design = read_design(&text, "design.yaml", &space).unwrap();
        let written = write_design(&design, &space);
        let values_back = read_design_values(&written, "written.yaml", &space).unwrap();
        assert_eq!(values.len(), space.params().len(), "{}: every parameter present", file.display());
        for ((p1, v1), (p2, v2)) in values.iter().zip(&values_back) {
            assert_eq!(p1, p2);
            assert!(v1.loosely_eq(v2), "{}: {p1} was {v1:?}, written back as {v2:?}", file.display());
        }
        let back: Design = read_design(&written, "written.yaml", &space).unwrap();
        assert_eq!(back, design);
        assert_eq!(write_design(&back, &space), written, "writing is stable");
        n += 1;
    }
    assert_eq!(n, 62);
}
