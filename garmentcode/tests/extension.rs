//! The pattern format extension (issue 25; `docs/pattern-extension.md`): holes, inner
//! lines, layers and stitches on them, read and written in `specification.json`,
//! checked, drawn, printed and meshed. `tests/data/extension/specification.json` is a
//! small pattern using every construct: a diamond dart and a round keyhole in
//! `front`, a pocket's placement line on `front` with `pocket` stitched onto it, a
//! facing layer, a sleeve with a fold line and a skirt with a pleat's lines.

use garmentcode::mesh::FOLD_GAP;
use garmentcode::{EXTENSION_VERSION, EdgePlace, HoleKind, Layer, LineKind, Pattern};
use std::path::Path;

#[path = "support/ezdxf.rs"]
mod ezdxf;

/// An edit of the fixture's JSON.
type JsonEdit = Box<dyn FnOnce(&mut serde_json::Value)>;
/// An edit of the fixture's pattern.
type PatternEdit = Box<dyn FnOnce(&mut Pattern)>;

fn fixture_text() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/extension/specification.json")).expect("fixture")
}

fn fixture() -> Pattern {
    Pattern::from_json(&fixture_text()).expect("the fixture reads")
}

/// The fixture with one JSON edit applied, read back (the error, if any).
fn edited(edit: impl FnOnce(&mut serde_json::Value)) -> Result<Pattern, String> {
    let mut v: serde_json::Value = serde_json::from_str(&fixture_text()).expect("json");
    edit(&mut v);
    Pattern::from_json(&v.to_string()).map_err(|e| e.to_string())
}

#[test]
fn every_construct_reads() {
    let p = fixture();
    let front = p.panel("front").expect("front");
    assert_eq!(front.holes.len(), 2);
    assert_eq!((front.holes[0].name.as_str(), front.holes[0].kind), ("waist_dart", HoleKind::Dart));
    assert_eq!(front.holes[0].vertices[2], [12.0, 44.0]);
    assert_eq!(front.holes[1].kind, HoleKind::Cut);
    assert!(front.holes[1].edges[1].curvature.is_some());
    assert_eq!((front.lines[0].kind, front.lines[0].edges.len()), (LineKind::Placement, 3));
    assert_eq!(front.layer, Layer::Outer);
    assert_eq!(p.panel("front_facing").expect("facing").layer, Layer::Facing);
    assert_eq!(p.panel("sleeve").expect("sleeve").lines[0].kind, LineKind::Fold { angle: 180.0 });
    let skirt = p.panel("skirt").expect("skirt");
    assert_eq!(skirt.lines.iter().map(|l| l.kind).collect::<Vec<_>>(), [LineKind::PleatFold, LineKind::PleatPlacement]);
    assert_eq!(p.inner_stitches.len(), 5);
    assert_eq!(p.inner_stitches[0].sides[1].place, EdgePlace::Hole(0));
    assert_eq!((p.inner_stitches[2].sides[0].place, p.inner_stitches[2].sides[1].place), (EdgePlace::Outline, EdgePlace::Line(0)));
    assert!(p.inner_stitches[2].right_wrong && !p.inner_stitches[0].right_wrong);
    assert!(p.uses_extension());
    assert!(!p.properties.extra.iter().any(|(k, _)| k == "extension_version"), "the version is not kept as an unknown property");
}

#[test]
fn round_trip_is_byte_identical() {
    let text = fixture_text();
    assert_eq!(fixture().to_json().expect("writes"), text);
}

#[test]
fn a_pattern_without_the_extension_writes_none_of_it() {
    let mut p = fixture();
    for panel in &mut p.panels {
        panel.holes.clear();
        panel.lines.clear();
        panel.layer = Layer::Outer;
    }
    p.inner_stitches.clear();
    assert!(!p.uses_extension());
    let json = p.to_json().expect("writes");
    for key in ["holes", "lines", "layer", "inner_stitches", "extension_version"] {
        assert!(!json.contains(&format!("\"{key}\"")), "{key} written");
    }
    // A layer alone is the extension.
    p.panels[0].layer = Layer::Lining;
    let json = p.to_json().expect("writes");
    assert!(json.contains("\"layer\": \"lining\"") && json.contains(&format!("\"extension_version\": {EXTENSION_VERSION}")));
}

#[test]
fn other_units_scale_the_inner_geometry() {
    let p = edited(|v| {
        v["properties"]["units_in_meter"] = 1000.into();
    })
    .expect("reads");
    let front = p.panel("front").expect("front");
    assert_eq!(front.holes[0].vertices[2], [12.0 * 0.1, 44.0 * 0.1]);
    assert_eq!(front.lines[0].vertices[1], [24.0 * 0.1, 10.0 * 0.1]);
    assert!(
        matches!(front.holes[1].edges[0].curvature, Some(garmentcode::Curvature::Circle { radius, .. }) if (radius - 0.2).abs() < 1e-12)
    );
}

#[test]
fn reading_errors_name_the_json_path() {
    let cases: Vec<(JsonEdit, &str)> = vec![
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["holes"][0]["kind"] = "slit".into()),
            "pattern.panels.front.holes[0].kind: expected \"cut\" or \"dart\"",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["sleeve"]["lines"][0]["kind"] = "crease".into()),
            "pattern.panels.sleeve.lines[0].kind: expected \"fold\"",
        ),
        (
            Box::new(|v| drop(v["pattern"]["panels"]["sleeve"]["lines"][0].as_object_mut().unwrap().remove("angle"))),
            "pattern.panels.sleeve.lines[0].angle: missing",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["holes"][0]["vertices"][1] = serde_json::json!([1.0])),
            "pattern.panels.front.holes[0].vertices[1]: expected 2 numbers",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["lines"][0]["edges"][0]["endpoints"] = serde_json::json!([0])),
            "pattern.panels.front.lines[0].edges[0].endpoints: expected 2 vertex indices",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["layer"] = "inner".into()),
            "pattern.panels.front.layer: expected \"outer\", \"facing\" or \"lining\"",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["holes"][0]["name"] = 3.into()),
            "pattern.panels.front.holes[0].name: expected a string",
        ),
        (
            Box::new(|v| v["pattern"]["inner_stitches"][0][1]["line"] = 0.into()),
            "pattern.inner_stitches[0][1]: a side is on a \"hole\" or on a \"line\"",
        ),
        (
            Box::new(|v| v["pattern"]["inner_stitches"][1][0]["hole"] = (-1).into()),
            "pattern.inner_stitches[1][0].hole: expected a non-negative integer",
        ),
        (
            Box::new(|v| v["pattern"]["stitches"][0][0]["hole"] = 0.into()),
            "pattern.stitches[0][0]: a side on a hole or an inner line belongs in pattern.inner_stitches",
        ),
        (
            Box::new(|v| v["properties"]["extension_version"] = 2.into()),
            "properties.extension_version: expected a format extension version from 1 to 1",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["holes"][0]["vertices"][0] = serde_json::json!([1e6, 0.0])),
            "pattern.panels.front: coordinate 1e6 cm is beyond",
        ),
        (
            Box::new(|v| v["pattern"]["panels"]["front"]["holes"][1]["edges"][1]["curvature"]["params"] = serde_json::json!([1e7, 1, 0])),
            "pattern.panels.front.holes[1].edges[1].curvature: a control point",
        ),
    ];
    for (edit, expected) in cases {
        let err = edited(edit).expect_err(expected);
        assert!(err.contains(expected), "{err:?} does not say {expected:?}");
    }
}

#[test]
fn counts_are_bounded() {
    let err = edited(|v| {
        let hole = v["pattern"]["panels"]["front"]["holes"][0].clone();
        v["pattern"]["panels"]["front"]["holes"] = serde_json::Value::Array(vec![hole; 101]);
    })
    .expect_err("101 holes");
    assert!(err.contains("pattern.panels.front.holes: 101 items, at most 100"), "{err}");
    let err = edited(|v| {
        let s = v["pattern"]["inner_stitches"][0].clone();
        v["pattern"]["inner_stitches"] = serde_json::Value::Array(vec![s; 1001]);
    })
    .expect_err("1001 stitches");
    assert!(err.contains("pattern.inner_stitches: 1001 stitches, at most 1000"), "{err}");
    // Hole and line edges count with the outline's.
    let err = edited(|v| {
        let line = &mut v["pattern"]["panels"]["sleeve"]["lines"][0];
        line["vertices"] = serde_json::Value::Array((0..500).map(|i| serde_json::json!([i as f64 * 0.1, 15.0])).collect());
        line["edges"] = serde_json::Value::Array((0..499).map(|i| serde_json::json!({"endpoints": [i, i + 1]})).collect());
    })
    .expect_err("503 edges");
    assert!(err.contains("pattern.panels.sleeve: 503 edges, at most 500"), "{err}");
}

#[test]
fn non_finite_covers_the_inner_geometry() {
    let mut p = fixture();
    assert_eq!(p.non_finite(), None);
    p.panels[0].holes[1].vertices[1][0] = f64::NAN;
    assert_eq!(p.non_finite().as_deref(), Some("panel 'front' hole 1 vertex 1"));
    let mut p = fixture();
    p.panels[0].lines[0].vertices[0][1] = f64::INFINITY;
    assert_eq!(p.non_finite().as_deref(), Some("panel 'front' line 0 vertex 0"));
    let mut p = fixture();
    let sleeve = p.panels.iter_mut().find(|s| s.name == "sleeve").expect("sleeve");
    sleeve.lines[0].kind = LineKind::Fold { angle: f64::NAN };
    assert_eq!(p.non_finite().as_deref(), Some("panel 'sleeve' line 0 fold angle"));
    assert!(p.to_json().is_err(), "a NaN is not written");
    let mut p = fixture();
    p.panels[0].holes[1].edges[0].curvature = Some(garmentcode::Curvature::Circle { radius: f64::NAN, large_arc: false, right: false });
    assert_eq!(p.non_finite().as_deref(), Some("panel 'front' holes[1].edges[0] curvature"));
}

// ---------------------------------------------------------------- check

/// The structural errors of the fixture after `edit`, as (kind, panel, message).
fn errors_after(edit: impl FnOnce(&mut Pattern)) -> Vec<(garmentcode::ProblemKind, String, String)> {
    let mut p = fixture();
    edit(&mut p);
    garmentcode::structural_errors(&p).into_iter().map(|e| (e.kind, e.panel.unwrap_or_default(), e.message)).collect()
}

fn panel_mut<'a>(p: &'a mut Pattern, name: &str) -> &'a mut garmentcode::PanelSpec {
    p.panels.iter_mut().find(|x| x.name == name).expect("panel")
}

#[test]
fn the_fixture_checks_clean() {
    let p = fixture();
    assert_eq!(garmentcode::validate(&p), []);
}

#[test]
fn check_reports_each_extension_error() {
    use garmentcode::ProblemKind as K;
    let cases: Vec<(PatternEdit, K, &str, &str)> = vec![
        (
            Box::new(|p| panel_mut(p, "front").holes[1].vertices = vec![[58.0, 50.0], [62.0, 50.0]]),
            K::HoleOutsidePanel,
            "front",
            "hole 'keyhole' lies outside the outline",
        ),
        (
            Box::new(|p| panel_mut(p, "front").holes[0].vertices[1] = [45.0, 32.0]),
            K::HoleCrossing,
            "front",
            "hole 'waist_dart' crosses or touches the outline",
        ),
        (
            Box::new(|p| panel_mut(p, "front").holes[1].vertices = vec![[11.0, 30.0], [15.0, 30.0]]),
            K::HoleCrossing,
            "front",
            "hole 'keyhole' crosses, touches or holds hole 'waist_dart'",
        ),
        (
            Box::new(|p| panel_mut(p, "front").holes[1].vertices = vec![[11.5, 32.0], [12.5, 32.0]]),
            K::HoleCrossing,
            "front",
            "hole 'keyhole' crosses, touches or holds hole 'waist_dart'",
        ),
        (Box::new(|p| panel_mut(p, "front").holes[0].vertices.swap(1, 2)), K::HoleCrossing, "front", "hole 'waist_dart' crosses itself"),
        (
            Box::new(|p| panel_mut(p, "front").lines[0].vertices[2] = [50.0, 10.0]),
            K::LineOutsidePanel,
            "front",
            "line 'pocket' leaves the panel",
        ),
        (
            Box::new(|p| panel_mut(p, "sleeve").lines[0].vertices[1] = [40.0, 15.0]),
            K::FoldNotAcross,
            "sleeve",
            "fold line 'underarm' does not cross the panel",
        ),
        (
            Box::new(|p| panel_mut(p, "sleeve").lines[0].kind = LineKind::Fold { angle: 200.0 }),
            K::FoldAngleOutOfRange,
            "sleeve",
            "fold line 'underarm': angle 200° is outside 0 to 180°",
        ),
        (
            Box::new(|p| panel_mut(p, "skirt").lines[1].name = "pleat_0_fold".into()),
            K::DuplicateName,
            "skirt",
            "two holes or lines are named 'pleat_0_fold'",
        ),
        (
            Box::new(|p| panel_mut(p, "front").holes[0].edges[2].endpoints[1] = 7),
            K::VertexOutOfRange,
            "front",
            "hole 'waist_dart' edge 2: vertex 7 does not exist (it has 4)",
        ),
        (
            Box::new(|p| panel_mut(p, "front").holes[0].edges[3].endpoints[1] = 1),
            K::OpenLoop,
            "front",
            "hole 'waist_dart' edge 3 ends at vertex 1 but edge 0 starts at vertex 0",
        ),
        (
            Box::new(|p| panel_mut(p, "front").lines[0].edges[1].endpoints = [2, 3]),
            K::OpenLoop,
            "front",
            "line 'pocket' edge 0 ends at vertex 1 but edge 1 starts at vertex 2",
        ),
        (Box::new(|p| panel_mut(p, "sleeve").lines[0].edges.clear()), K::EmptyPanel, "sleeve", "line 'underarm' has 0 edges (at least 1)"),
        (
            Box::new(|p| p.inner_stitches[0].sides[0].panel = "back".into()),
            K::UnknownPanel,
            "back",
            "inner stitch 0: no panel with this name",
        ),
        (
            Box::new(|p| p.inner_stitches[1].sides[1].place = EdgePlace::Hole(5)),
            K::UnknownHoleOrLine,
            "front",
            "inner stitch 1: hole 5 does not exist (the panel has 2 holes and 1 lines)",
        ),
        (
            Box::new(|p| p.inner_stitches[2].sides[1].edge = 9),
            K::EdgeOutOfRange,
            "front",
            "inner stitch 2: edge 9 of line 0 does not exist (it has 3 edges)",
        ),
        (
            Box::new(|p| p.inner_stitches[1].sides[1].edge = 0),
            K::EdgeStitchedTwice,
            "front",
            "inner stitch 1: edge 0 of hole 0 is already used by inner stitch 0",
        ),
        (
            Box::new(|p| {
                p.inner_stitches[2].sides[0] = garmentcode::InnerSide { panel: "front".into(), place: EdgePlace::Outline, edge: 2 }
            }),
            K::EdgeStitchedTwice,
            "front",
            "inner stitch 2: edge 2 of the outline is already used by stitch 0",
        ),
        (
            Box::new(|p| {
                for e in &mut panel_mut(p, "front").holes[1].edges {
                    e.curvature = Some(garmentcode::Curvature::Circle { radius: 1.0, large_arc: false, right: false });
                }
            }),
            K::ArcRadiusTooSmall,
            "front",
            "hole 'keyhole' edge 0: arc radius 1 cm is under half the distance between its ends: no circle of that radius joins them (at least 2 cm)",
        ),
        (
            Box::new(|p| {
                panel_mut(p, "front").edges[0].curvature =
                    Some(garmentcode::Curvature::Circle { radius: 5.0, large_arc: false, right: true })
            }),
            K::ArcRadiusTooSmall,
            "front",
            "arc radius 5 cm is under half the distance between its ends: no circle of that radius joins them (at least 20 cm)",
        ),
    ];
    for (edit, kind, panel, message) in cases {
        let errors = errors_after(edit);
        assert!(
            errors.iter().any(|(k, p, m)| *k == kind && p == panel && m.starts_with(message)),
            "expected {kind:?} on {panel}: {message:?}; got {errors:?}"
        );
        assert!(errors.iter().all(|(k, ..)| *k == kind), "only {kind:?} expected: {errors:?}");
    }
}

#[test]
fn placement_lines_take_more_than_one_stitch_per_edge() {
    // A pocket and its flap both sewn along the placement line's top.
    let errors = errors_after(|p| {
        let mut s = p.inner_stitches[3].clone();
        s.sides[0].edge = 3;
        p.inner_stitches.push(s);
    });
    assert_eq!(errors, []);
}

#[test]
fn a_fold_line_across_a_curved_outline_is_accepted() {
    // The sleeve's far side bulges (a quadratic edge); the fold line ends on the curve.
    let errors = errors_after(|p| {
        let sleeve = panel_mut(p, "sleeve");
        sleeve.edges[1].curvature = Some(garmentcode::Curvature::Quadratic([0.5, 0.2]));
        // The quadratic's point at its middle: x = 50 + 0.2 * 30 * ... sampled from the edge itself.
        let mid = sleeve.edge_geom(1).point(0.5);
        sleeve.lines[0].vertices[1] = [mid.x, mid.y];
    });
    assert_eq!(errors, []);
}

// ---------------------------------------------------------------- drawings

/// The SVG drawing of the fixture: holes cut out with the even-odd rule, the dart a
/// dashed loop, the fold line dash-dot with its label, placement and pleat lines
/// dashed; a snapshot of the whole document.
#[test]
fn drawing_shows_every_construct() {
    use garmentcode::draw::{DrawOptions, to_svg};
    let svg = to_svg(&fixture(), &DrawOptions::default()).expect("draws");
    let front = svg.lines().find(|l| l.starts_with("<g id=\"front\">")).expect("front group");
    assert!(front.contains("fill-rule=\"evenodd\""), "{front}");
    // The keyhole is a second subpath of the outline: two arcs, closed.
    assert_eq!(front.matches(" Z").count(), 2, "{front}");
    assert_eq!(front.matches(" A 2,2 ").count(), 2, "{front}");
    let line = |class: &str| svg.lines().find(|l| l.starts_with(&format!("<path class=\"{class}\""))).unwrap_or_else(|| panic!("{class}"));
    assert!(
        line("dart").contains("stroke-dasharray=\"0.8 0.4\"")
            && line("dart").ends_with("Z\" fill=\"none\" stroke=\"rgb(51,51,51)\" stroke-width=\"0.15\" stroke-dasharray=\"0.8 0.4\"/>")
    );
    assert!(line("fold").contains("stroke-dasharray=\"1.6 0.4 0.3 0.4\""));
    assert!(line("placement").contains("data-name=\"pocket\"") && line("placement").contains("stroke-dasharray=\"0.6 0.4\""));
    assert!(line("pleat-fold").contains("stroke-dasharray=\"1.6 0.6\""));
    assert!(line("pleat-placement").contains("stroke-dasharray=\"0.2 0.4\""));
    assert!(svg.contains("<g class=\"mark-labels\" font-family=\"sans-serif\">\n<text") && svg.contains(">fold</text>"));
    // Panels without the extension are drawn as before.
    let pocket = svg.lines().find(|l| l.starts_with("<g id=\"pocket\">")).expect("pocket group");
    assert!(pocket.ends_with("stroke-width=\"0.2\"/></g>") && !pocket.contains("evenodd"), "{pocket}");
    insta::assert_snapshot!("extension_svg", svg);
}

/// Inner stitches get numbered markers too, numbered on after the stitches (as the
/// box mesh's `stitch_K` labels), on their hole or line edges.
#[test]
fn drawing_numbers_inner_stitches_after_the_stitches() {
    use garmentcode::draw::{DrawOptions, to_svg};
    let p = fixture();
    let (n, m) = (p.stitches.len(), p.inner_stitches.len());
    assert!(m > 0);
    let svg = to_svg(&p, &DrawOptions::default()).expect("draws");
    let groups: Vec<&str> = svg.lines().filter(|l| l.starts_with("<g class=\"stitch\" ")).collect();
    let mut expected: Vec<String> = Vec::new();
    for (i, st) in p.stitches.iter().enumerate() {
        for s in &st.sides {
            expected.push(format!("<g class=\"stitch\" data-stitch=\"{i}\" data-panel=\"{}\" data-edge=\"{}\">", s.panel, s.edge));
        }
    }
    for (j, st) in p.inner_stitches.iter().enumerate() {
        for s in &st.sides {
            let place = match s.place {
                EdgePlace::Outline => String::new(),
                EdgePlace::Hole(k) => format!(" data-hole=\"{k}\""),
                EdgePlace::Line(k) => format!(" data-line=\"{k}\""),
            };
            expected.push(format!(
                "<g class=\"stitch\" data-stitch=\"{}\" data-panel=\"{}\"{place} data-edge=\"{}\">",
                n + j,
                s.panel,
                s.edge
            ));
        }
    }
    assert_eq!(groups, expected);
    // Each numbered: the last inner stitch's number is on the sheet.
    assert!(svg.contains(&format!(">{}</text>", n + m - 1)));
}

/// The PNG: the keyhole is an opening (transparent), the dart's inside is fabric.
#[cfg(feature = "png")]
#[test]
fn png_leaves_cut_holes_open() {
    use garmentcode::draw::{DrawOptions, to_png, to_svg};
    let opts = DrawOptions { px_per_cm: 10.0, ..Default::default() };
    let p = fixture();
    let svg = to_svg(&p, &opts).expect("svg");
    let vb: Vec<f64> = svg
        .split("viewBox=\"")
        .nth(1)
        .expect("viewBox")
        .split('"')
        .next()
        .expect("value")
        .split(' ')
        .map(|x| x.parse().expect("number"))
        .collect();
    let png = to_png(&p, &opts).expect("png");
    let mut reader = png::Decoder::new(std::io::Cursor::new(png)).read_info().expect("png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("frame");
    // Sheet point of front's local (x, y): the panel is unrotated at (-20, 90).
    let at = |x: f64, y: f64| {
        let (i, j) = (((x - 20.0 - vb[0]) * 10.0) as usize, ((-(y + 90.0) - vb[1]) * 10.0) as usize);
        let k = 4 * (j * info.width as usize + i);
        [buf[k], buf[k + 1], buf[k + 2], buf[k + 3]]
    };
    assert_eq!(at(30.0, 50.0), [0, 0, 0, 0], "the keyhole is open");
    assert_eq!(at(12.0, 40.0), [227, 175, 186, 255], "inside the dart is fabric");
    assert_eq!(at(30.0, 45.0), [227, 175, 186, 255], "around the keyhole is fabric");
}

// ---------------------------------------------------------------- print and DXF-AAMA

/// The fixture's DXF-AAMA file, and its blocks read back by our reader.
fn fixture_dxf() -> (String, garmentcode::fabricate::DxfDrawing) {
    use garmentcode::fabricate::{PrintOptions, files, read_dxf};
    let out = files(&fixture(), &PrintOptions::default()).expect("prints");
    let text = String::from_utf8(out.into_iter().find(|(n, _)| n == "pattern.dxf").expect("dxf").1).expect("ascii");
    let d = read_dxf(&text).expect("reads back");
    (text, d)
}

fn on_layer<'a>(
    d: &'a garmentcode::fabricate::DxfDrawing,
    block: &str,
    kind: &str,
    layer: &str,
) -> Vec<&'a garmentcode::fabricate::DxfEntity> {
    let b = d.blocks.iter().find(|b| b.name == block).unwrap_or_else(|| panic!("block {block}"));
    b.entities.iter().filter(|e| e.kind == kind && e.layer == layer).collect()
}

#[test]
fn dxf_carries_every_construct_on_its_aama_layer() {
    let (_, d) = fixture_dxf();
    assert_eq!(d.layers, ["0", "1", "4", "6", "7", "8", "11", "13", "14"]);
    // Layer 11: the keyhole, a closed circle of radius 2 cm (20 mm).
    let cutouts = on_layer(&d, "front", "POLYLINE", "11");
    assert_eq!(cutouts.len(), 1);
    assert!(cutouts[0].closed);
    let pts = &cutouts[0].points;
    let centre = pts.iter().copied().sum::<garmentcode::Vec2>() / pts.len() as f64;
    assert!(pts.iter().all(|q| ((*q - centre).length() - 20.0).abs() < 0.01), "{pts:?}");
    // Layer 13: drill holes at the dart's four points and the pocket's four corners (a 12 × 14 cm U).
    let drills: Vec<garmentcode::Vec2> = on_layer(&d, "front", "POINT", "13").iter().map(|e| e.points[0]).collect();
    assert_eq!(drills.len(), 8);
    let (dart, pocket) = drills.split_at(4);
    let size = |q: &[garmentcode::Vec2]| {
        let (lo, hi) = q.iter().fold((q[0], q[0]), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        hi - lo
    };
    let s = size(dart);
    assert!(
        (size(pocket) - garmentcode::Vec2::new(120.0, 140.0)).length() < 1e-6
            || (size(pocket) - garmentcode::Vec2::new(140.0, 120.0)).length() < 1e-6
    );
    // The dart's points drilled 1 cm inside its tips (24 cm apart) and a third of the way in at its sides (3 cm apart).
    assert!((s.max_element() - 220.0).abs() < 1e-6 && (s.min_element() - 20.0).abs() < 1e-6, "{s:?}");
    // Layer 8: the dart (closed loop) and the pocket's placement line; layer 6: the sleeve's fold.
    assert_eq!(on_layer(&d, "front", "POLYLINE", "8").len(), 2);
    let mirror = on_layer(&d, "sleeve", "POLYLINE", "6");
    assert_eq!(mirror.len(), 1);
    assert!(((mirror[0].points[0] - mirror[0].points[1]).length() - 500.0).abs() < 1e-6, "the 50 cm fold line");
    // Layer 4: a notch where each pleat line meets the waist (the skirt has no seams).
    assert_eq!(on_layer(&d, "skirt", "LINE", "4").len(), 2);
    assert_eq!(on_layer(&d, "skirt", "POLYLINE", "8").len(), 2);
    // Nothing of it on the panels without the extension.
    assert!(on_layer(&d, "pocket", "POINT", "13").is_empty() && on_layer(&d, "pocket", "POLYLINE", "8").is_empty());
}

#[test]
fn dxf_without_the_extension_keeps_its_layers() {
    use garmentcode::fabricate::{PrintOptions, files, read_dxf};
    let mut p = fixture();
    for panel in &mut p.panels {
        panel.holes.clear();
        panel.lines.clear();
    }
    p.inner_stitches.clear();
    let out = files(&p, &PrintOptions::default()).expect("prints");
    let d = read_dxf(std::str::from_utf8(&out[3].1).expect("ascii")).expect("reads");
    assert_eq!(d.layers, ["0", "1", "4", "6", "7", "8", "14"]);
}

#[test]
fn dxf_with_the_extension_reads_in_ezdxf() {
    let (text, _) = fixture_dxf();
    let script = r#"
import sys, json
import ezdxf
doc = ezdxf.readfile(sys.argv[1])
front = doc.blocks.get("front")
count = {}
for e in front:
    key = e.dxftype() + ":" + e.dxf.layer
    count[key] = count.get(key, 0) + 1
print(json.dumps({"errors": len(doc.audit().errors), "front": count, "layers": sorted(l.dxf.name for l in doc.layers)}))
"#;
    let Some(v) = ezdxf::read_back_text("dxf_with_the_extension_reads_in_ezdxf", &text, script) else { return };
    assert_eq!(v["errors"], 0, "{v}");
    assert_eq!(v["front"]["POINT:13"], 8, "{v}");
    assert_eq!(v["front"]["POLYLINE:11"], 1, "{v}");
    assert_eq!(v["front"]["POLYLINE:8"], 2, "{v}");
    assert!(v["layers"].as_array().expect("layers").iter().any(|l| l == "11"), "{v}");
}

// ---------------------------------------------------------------- box mesh

fn fixture_mesh(edit: impl FnOnce(&mut Pattern)) -> garmentcode::mesh::BoxMesh {
    let mut p = fixture();
    p.name = "extension".into();
    edit(&mut p);
    garmentcode::mesh::BoxMesh::new(&p, 1.0).expect("meshes")
}

fn panel_index(m: &garmentcode::mesh::BoxMesh, name: &str) -> usize {
    m.panels.iter().position(|p| p.name == name).expect("panel")
}

fn face_area(panel: &garmentcode::mesh::PanelMesh) -> f64 {
    panel
        .faces
        .iter()
        .map(|f| (panel.points[f[1]] - panel.points[f[0]]).perp_dot(panel.points[f[2]] - panel.points[f[0]]).abs() / 2.0)
        .sum()
}

/// Whether the panel's faces have an edge between local vertices `a` and `b`.
fn has_edge(panel: &garmentcode::mesh::PanelMesh, a: usize, b: usize) -> bool {
    panel.faces.iter().any(|f| (0..3).any(|k| (f[k] == a && f[(k + 1) % 3] == b) || (f[k] == b && f[(k + 1) % 3] == a)))
}

#[test]
fn mesh_leaves_holes_open() {
    let m = fixture_mesh(|_| {});
    let front = &m.panels[panel_index(&m, "front")];
    // 40 × 60 less the diamond dart (3 × 24 / 2) and the keyhole: a circle of radius 2
    // sampled at 14 points (a polygon inside the circle, 4π − 1.7% of it).
    let area = face_area(front);
    let keyhole = 14.0 / 2.0 * 4.0 * (std::f64::consts::TAU / 14.0).sin();
    let expected = 2400.0 - 36.0 - keyhole;
    assert!((area - expected).abs() < 1e-6, "{area} vs {expected}");
    for f in &front.faces {
        let c = (front.points[f[0]] + front.points[f[1]] + front.points[f[2]]) / 3.0;
        assert!((c - garmentcode::Vec2::new(30.0, 50.0)).length() > 1.9, "a face in the keyhole at {c:?}");
        let in_dart = (c.x - 12.0).abs() / 1.5 + (c.y - 32.0).abs() / 12.0 < 0.99;
        assert!(!in_dart, "a face in the dart at {c:?}");
    }
}

#[test]
fn mesh_keeps_inner_lines_as_rows_of_edges() {
    let m = fixture_mesh(|_| {});
    for (panel, first) in [("front", 4 + 4 + 2), ("sleeve", 4), ("skirt", 4)] {
        let pm = &m.panels[panel_index(&m, panel)];
        let lines = &pm.edges[first..];
        assert!(!lines.is_empty());
        for e in lines {
            for w in e.local.windows(2) {
                assert!(has_edge(pm, w[0], w[1]), "{panel}: no mesh edge {w:?}");
            }
        }
    }
    // The fold line crosses the sleeve: its ends are outline vertices, 51 vertices 1 cm apart.
    let sleeve = &m.panels[panel_index(&m, "sleeve")];
    let fold = &sleeve.edges[4].local;
    assert_eq!(fold.len(), 51);
    let outline: Vec<usize> = sleeve.edges[..4].iter().flat_map(|e| e.local.clone()).collect();
    assert!(outline.contains(&fold[0]) && outline.contains(&fold[50]));
    // Both sides of the line are meshed (it bounds nothing).
    let area = face_area(sleeve);
    assert!((area - 1500.0).abs() < 1e-6, "{area}");
}

#[test]
fn mesh_turns_the_part_right_of_a_fold() {
    // The sleeve's underarm fold runs along +x at y = 15: the part at y < 15 turns.
    let local = |m: &garmentcode::mesh::BoxMesh, v: garmentcode::Vec3| {
        let s = &m.panels[panel_index(m, "sleeve")];
        s.rotation.transpose() * (v - s.translation)
    };
    let flat = fixture_mesh(|p| panel_mut(p, "sleeve").lines[0].kind = LineKind::Fold { angle: 0.0 });
    let folded = fixture_mesh(|_| {});
    let square = fixture_mesh(|p| panel_mut(p, "sleeve").lines[0].kind = LineKind::Fold { angle: 90.0 });
    let si = panel_index(&folded, "sleeve");
    let s = &folded.panels[si];
    let mut turned = 0;
    for l in 0..s.points.len() {
        let q = s.points[l];
        let a = local(&flat, flat.vertices[flat.panels[si].global[l]]);
        let b = local(&folded, folded.vertices[s.global[l]]);
        let c = local(&square, square.vertices[square.panels[si].global[l]]);
        assert!((a - garmentcode::Vec3::new(q.x, q.y, 0.0)).length() < 1e-9, "flat at 0°");
        if q.y < 15.0 {
            turned += 1;
            // 180°: mirrored over the line onto the left part, FOLD_GAP behind it (less
            // within FOLD_GAP of the line); 90°: straight down from it, half as far off
            // its side.
            let gap = FOLD_GAP * ((15.0 - q.y) / FOLD_GAP).min(1.0);
            assert!((b - garmentcode::Vec3::new(q.x, 30.0 - q.y, -gap)).length() < 1e-9, "{b:?} for {q:?}");
            assert!((c - garmentcode::Vec3::new(q.x, 15.0 - gap / 2.0, q.y - 15.0)).length() < 1e-9, "{c:?} for {q:?}");
        } else {
            assert!((b - a).length() < 1e-9 && (c - a).length() < 1e-9, "the left part stays");
        }
    }
    assert!(turned > 500, "{turned} vertices turned");
}

#[test]
fn mesh_stitches_inner_stitches() {
    let m = fixture_mesh(|_| {});
    assert_eq!(m.stitches.len(), 6, "1 stitch, then 5 inner stitches");
    let front = &m.panels[panel_index(&m, "front")];
    let pocket = &m.panels[panel_index(&m, "pocket")];
    // The pocket's sides are merged with the placement line's vertices, starts with starts (right_wrong).
    for k in 0..3 {
        let line = &front.edges[10 + k].local;
        let side = &pocket.edges[k].local;
        assert_eq!(line.len(), side.len());
        for (i, (a, b)) in line.iter().zip(side).enumerate() {
            assert_eq!(front.global[*a], pocket.global[*b]);
            // Corners shared with the stitch before keep its label, as in the reference.
            if i > 0 && i + 1 < line.len() {
                let v = front.global[*a];
                assert_eq!(m.segmentation_label(v), format!("stitch_{}", 3 + k));
            }
        }
    }
    // The dart's sides are sewn: edge 0 (bottom right) to edge 3 (bottom left), end to start.
    let (e0, e3) = (&front.edges[4].local, &front.edges[7].local);
    for (a, b) in e0.iter().rev().zip(e3.iter()) {
        assert_eq!(front.global[*a], front.global[*b]);
    }
    // Rest lengths are stored for the faces on the dart's seam.
    let dart_vertex = front.global[e0[e0.len() / 2]];
    assert!(m.rest_lengths.iter().any(|(k, _)| k.contains(&dart_vertex)));
}

#[test]
fn mesh_names_lines_holes_and_layers() {
    let m = fixture_mesh(|_| {});
    let label =
        |name: &str| m.vertex_labels.iter().find(|(l, _)| l == name).map(|(_, ids)| ids.clone()).unwrap_or_else(|| panic!("no {name}"));
    assert_eq!(label("fold_sleeve_underarm").len(), 51);
    assert_eq!(label("line_front_pocket").len(), 15 + 12 + 14);
    assert!(label("hole_front_keyhole").len() >= 12);
    let facing = &m.panels[panel_index(&m, "front_facing")];
    let mut ids = facing.global.clone();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(label("layer_facing"), ids);
    assert!(!m.vertex_labels.iter().any(|(l, _)| l.starts_with("layer_outer")));
}

/// A malformed hole is refused by every output with the reason, never a panic.
#[test]
fn outputs_refuse_a_malformed_hole() {
    let mut p = fixture();
    panel_mut(&mut p, "front").holes[0].edges[2].endpoints[1] = 7;
    let svg = garmentcode::draw::to_svg(&p, &Default::default()).expect_err("not drawn").to_string();
    assert!(svg.contains("cannot draw panel 'front': hole 'waist_dart': edge 2 refers to vertex 7"), "{svg}");
    let print = garmentcode::fabricate::files(&p, &Default::default()).expect_err("not printed").to_string();
    assert!(print.contains("structural errors") && print.contains("hole 'waist_dart' edge 2: vertex 7 does not exist"), "{print}");
    let mesh = garmentcode::mesh::BoxMesh::new(&p, 1.0).expect_err("not meshed");
    assert!(matches!(&mesh, garmentcode::mesh::MeshError::Structural(m) if m.contains("hole 'waist_dart' edge 2")), "{mesh}");
}
