//! The built-in designs past the reference's language (`design.extension`): each
//! builds on every built-in body and passes the reference's checks, with the holes,
//! lines and stitches its constructs make; with the extension at its defaults, a
//! design is the reference's (its design space and samples are unchanged).

use garmentcode::mesh::BoxMesh;
use garmentcode::{EdgePlace, HoleKind, LineKind, PanelSpec, Params, Pattern, Sampler, Severity, sample_rng};
use garments::design::{BottomKind, Extension, PleatStyle, extended_design_space};
use garments::{Design, builtin};

fn build(name: &str, body: &str) -> Pattern {
    build_design(name, &builtin::design(name).unwrap(), body)
}

fn build_design(name: &str, design: &Design, body: &str) -> Pattern {
    let body = builtin::body(body).unwrap();
    let built = garments::build::build(design, &body, name).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(built.checks.passed(), "{name}: {:?}", built.checks.warnings());
    let problems = garmentcode::validate(&built.pattern);
    assert!(problems.iter().all(|p| p.severity != Severity::Error), "{name}: {problems:?}");
    built.pattern
}

#[test]
fn the_birch_dress_has_a_diamond_dart_in_each_bodice_panel() {
    for (body, _) in builtin::BODIES {
        let p = build("birch-dress", body);
        let darted: Vec<&str> = p.panels.iter().filter(|s| !s.holes.is_empty()).map(|s| s.name.as_str()).collect();
        let mut sorted = darted.clone();
        sorted.sort();
        assert_eq!(sorted, ["left_btorso", "left_ftorso", "right_btorso", "right_ftorso"], "{body}");
        for s in p.panels.iter().filter(|s| !s.holes.is_empty()) {
            let hole = &s.holes[0];
            assert_eq!((hole.kind, hole.edges.len()), (HoleKind::Dart, 4));
            // 3 cm wide, a third of the panel high.
            let xs: Vec<f64> = hole.vertices.iter().map(|v| v[0]).collect();
            let width = xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max) - xs.iter().cloned().fold(f64::INFINITY, f64::min);
            assert!((width - 3.0).abs() < 1e-6, "{body} {}: {width}", s.name);
        }
        // Two stitches per dart, between its own sides.
        assert_eq!(p.inner_stitches.len(), 8);
        assert!(p.inner_stitches.iter().all(|st| st.sides[0].panel == st.sides[1].panel && st.sides[0].place == EdgePlace::Hole(0)));
    }
}

#[test]
fn the_pleated_skirt_stitches_its_folded_width_to_the_band() {
    for (body, _) in builtin::BODIES {
        let p = build("pleated-skirt", body);
        // Three box pleats in front (two folds and a placement each), three knife
        // pleats at the back (a fold and a placement each).
        for (name, lines) in [("skirt_front", 9), ("skirt_back", 6)] {
            let s = p.panel(name).unwrap();
            let kinds: Vec<LineKind> = s.lines.iter().map(|l| l.kind).collect();
            assert_eq!(kinds.len(), lines, "{body} {name}");
            assert_eq!(kinds.iter().filter(|k| **k == LineKind::PleatPlacement).count(), 3);
        }
        // 3 pleats × 2 folds in front, 3 × 1 at the back, each 2.5 cm onto 2.5 cm, on
        // the outline.
        let pleat_stitches: Vec<_> =
            p.stitches.iter().filter(|st| st.sides[0].panel == st.sides[1].panel && st.sides[0].panel.starts_with("skirt_")).collect();
        assert_eq!(pleat_stitches.len(), 9, "{body}");
        for st in pleat_stitches {
            let panel = p.panel(&st.sides[0].panel).unwrap();
            for side in &st.sides {
                assert!((panel.edge_geom(side.edge).length() - 2.5).abs() < 1e-6);
            }
        }
        assert!(p.inner_stitches.is_empty());
    }
}

/// Stitches between two panels that pair points on opposite sides of the body
/// (more than 1 cm either side of its middle, x = 0): the ends of each stitch's
/// edges, paired as the box mesh pairs them (the first side's edge reversed, unless
/// the stitch is `right_wrong`), as `panel x ↔ panel x`.
fn crossed_stitches(p: &Pattern) -> Vec<String> {
    let mut crossed = Vec::new();
    for st in p.stitches.iter().filter(|st| st.sides[0].panel != st.sides[1].panel) {
        let ends = |k: usize| {
            let panel = p.panel(&st.sides[k].panel).unwrap();
            let e = panel.edge_geom(st.sides[k].edge);
            [panel.point_to_3d(e.start).x, panel.point_to_3d(e.end).x]
        };
        let (mut first, second) = (ends(0), ends(1));
        if !st.right_wrong {
            first.reverse();
        }
        for (x0, x1) in first.into_iter().zip(second) {
            if x0.abs() > 1.0 && x1.abs() > 1.0 && x0.signum() != x1.signum() {
                crossed.push(format!("{} {x0:.1} ↔ {} {x1:.1}", st.sides[0].panel, st.sides[1].panel));
            }
        }
    }
    crossed
}

#[test]
fn the_pleated_skirts_flat_parts_are_sewn_to_the_band_and_bodice_beside_them() {
    // The front panel is turned round when placed in front: before, its flat parts
    // were paired with the band's in mirror order (the band's left end with the
    // skirt's right part) and the drape knotted at the centre front.
    for (body, _) in builtin::BODIES {
        let p = build("pleated-skirt", body);
        assert_eq!(crossed_stitches(&p), Vec::<String>::new(), "{body}");
    }
    // On a fitted band, and on a bodice without a band; with knife pleats in front too.
    use garments::design::{UpperKind, WaistbandKind};
    let mut design = builtin::design("pleated-skirt").unwrap();
    for (upper, wb) in [(None, Some(WaistbandKind::FittedWB)), (Some(UpperKind::FittedShirt), None)] {
        (design.meta.upper, design.meta.wb) = (upper, wb);
        for style in [PleatStyle::BoxAndKnife, PleatStyle::KnifePleats, PleatStyle::BoxPleats] {
            design.extension.pleats.style = Some(style);
            let body = builtin::body("mean_all").unwrap();
            let p = garments::build::build(&design, &body, "pleated").unwrap().pattern;
            assert!(p.panel("skirt_front").is_some_and(|s| !s.lines.is_empty()));
            assert_eq!(crossed_stitches(&p), Vec::<String>::new(), "{upper:?} {wb:?} {style:?}");
        }
    }
}

#[test]
fn a_pocket_is_not_placed_across_a_dart() {
    // Sampled (`sample -n 6 -s 7 --extended`, sample 2): the chest pocket's corners lay
    // inside the fitted front panel but its sides crossed the side and waist darts, and
    // the pattern could not be meshed (`line_outside_panel`).
    let text = include_str!("data/pocket-across-darts.yaml");
    let design: Design = garmentcode::io::read_design(text, "pocket-across-darts.yaml", &extended_design_space()).unwrap();
    let built = garments::build::build(&design, &builtin::body("mean_all").unwrap(), "sampled").unwrap();
    let problems = garmentcode::validate(&built.pattern);
    assert!(problems.iter().all(|p| p.severity != Severity::Error), "{problems:?}");
    assert!(built.pattern.panel("right_ftorso_pocket").is_some());
}

#[test]
fn the_pocket_shirt_has_a_pocket_one_piece_sleeves_and_folded_cuffs() {
    for (body, _) in builtin::BODIES {
        let p = build("pocket-shirt", body);
        let pocket = p.panel("right_ftorso_pocket").unwrap_or_else(|| panic!("{body}: no pocket"));
        assert_eq!(pocket.edges.len(), 4);
        let front = p.panel("right_ftorso").unwrap();
        assert_eq!(front.lines.iter().map(|l| l.kind).collect::<Vec<_>>(), [LineKind::Placement]);
        let onto: Vec<_> = p.inner_stitches.iter().filter(|st| st.sides[1].place == EdgePlace::Line(0)).collect();
        assert_eq!(onto.len(), 3, "{body}: sides and bottom");
        // One panel per sleeve; four cuff panels, each with a fold line in the middle.
        assert!(p.panel("right_sleeve_f").is_some() && p.panel("right_sleeve_b").is_none(), "{body}");
        assert!(p.panel("left_sleeve_f").is_some() && p.panel("left_sleeve_b").is_none(), "{body}");
        let cuffs: Vec<_> = p.panels.iter().filter(|s| s.name.contains("cuff")).collect();
        assert_eq!(cuffs.len(), 4);
        for c in cuffs {
            assert_eq!(c.lines.len(), 1, "{}", c.name);
            assert_eq!(c.lines[0].kind, LineKind::Fold { angle: 180.0 });
        }
    }
}

#[test]
fn the_extension_is_outside_the_references_design_space_and_its_samples() {
    let reference = Design::design_space();
    assert!(reference.params().iter().all(|p| !p.path.starts_with("extension")));
    let extended = extended_design_space();
    assert_eq!(&extended.params()[..reference.params().len()], reference.params());
    assert!(extended.params()[reference.params().len()..].iter().all(|p| p.path.starts_with("extension.")));
    // The same seed draws the same reference parameters in both spaces, and the
    // reference's space leaves the extension at its defaults.
    let (plain, wide) = (Sampler::new(reference), Sampler::new(extended));
    let mut any_extension = false;
    for i in 0..50 {
        let d: Design = plain.sample(&mut sample_rng(7, i));
        let e: Design = wide.sample(&mut sample_rng(7, i));
        assert_eq!(d.extension, Extension::defaults());
        assert_eq!(Design { extension: Extension::defaults(), ..e.clone() }, d);
        any_extension |= e.extension != Extension::defaults();
    }
    assert!(any_extension);
}

/// The corner of a sleeve panel where its top (fold line, or the seam of the two
/// panels as long as the fold) meets its cuff.
fn cuff_top_corner(p: &Pattern, panel: &str, top_length: f64) -> [f64; 2] {
    let sp = p.panel(panel).unwrap();
    let ends = |side: &garmentcode::StitchSide| sp.edges[side.edge].endpoints.map(|k| sp.vertices[k]);
    let mut top: Vec<[f64; 2]> =
        sp.lines.iter().filter(|l| matches!(l.kind, LineKind::Fold { .. })).flat_map(|l| l.vertices.clone()).collect();
    let mut cuff = Vec::new();
    for st in &p.stitches {
        for (mine, other) in [(&st.sides[0], &st.sides[1]), (&st.sides[1], &st.sides[0])] {
            if mine.panel != panel {
                continue;
            }
            if other.panel.contains("cuff") {
                cuff.extend(ends(mine));
            } else if other.panel.contains("sleeve") && (sp.edge_geom(mine.edge).length() - top_length).abs() < 1e-6 {
                top.extend(ends(mine));
            }
        }
    }
    *top.iter()
        .find(|t| cuff.iter().any(|c| (c[0] - t[0]).hypot(c[1] - t[1]) < 1e-6))
        .unwrap_or_else(|| panic!("{panel}: no cuff-top corner"))
}

/// Every stitch between a sleeve and a torso panel as (torso panel, torso edge,
/// distance from the sleeve's cuff-top corner to the sleeve vertex the box mesh pairs
/// with the torso edge's start), sorted: the same for one-piece and two-panel sleeves
/// when the sleeve is sewn into the armhole the same way round.
fn armhole_pairs(p: &Pattern, top_length: f64) -> Vec<(String, usize, String)> {
    let mut out = Vec::new();
    for st in &p.stitches {
        let [s0, s1] = &st.sides;
        let (sleeve, torso, sleeve_first) = match (s0.panel.contains("sleeve"), s1.panel.contains("torso")) {
            (true, true) => (s0, s1, true),
            _ if s1.panel.contains("sleeve") && s0.panel.contains("torso") => (s1, s0, false),
            _ => continue,
        };
        let sp: &PanelSpec = p.panel(&sleeve.panel).unwrap();
        let [start, end] = sp.edges[sleeve.edge].endpoints;
        // The box mesh reverses side 0 (no stitch here is right_wrong).
        assert!(!st.right_wrong);
        let paired = if sleeve_first { end } else { start };
        let corner = cuff_top_corner(p, &sleeve.panel, top_length);
        let v = sp.vertices[paired];
        let d = (v[0] - corner[0]).hypot(v[1] - corner[1]);
        out.push((torso.panel.clone(), torso.edge, format!("{d:.4}")));
    }
    out.sort();
    out
}

#[test]
fn a_one_piece_sleeve_is_one_panel_folded_over_the_arm_and_sewn_in_as_two() {
    let one_piece = builtin::design("pocket-shirt").unwrap();
    let mut two_panels = one_piece.clone();
    two_panels.extension.sleeve.one_piece = false;
    for (body, _) in builtin::BODIES {
        let p = build_design("pocket-shirt", &one_piece, body);
        let q = build_design("pocket-shirt", &two_panels, body);
        assert_eq!(p.panels.len() + 2, q.panels.len(), "{body}: the back sleeve panels are gone");
        // The top seams are folds now; every other seam stays.
        assert_eq!(p.stitches.len() + 2, q.stitches.len(), "{body}");
        for side in ["right", "left"] {
            let s = p.panel(&format!("{side}_sleeve_f")).unwrap();
            let folds: Vec<_> = s.lines.iter().filter(|l| matches!(l.kind, LineKind::Fold { .. })).collect();
            assert_eq!(folds.len(), 1, "{body} {side}");
            assert_eq!(folds[0].kind, LineKind::Fold { angle: 90.0 });
            // The fold's ends are corners of the outline, and the outline lies on both
            // sides of it (front and back halves).
            let (a, b) = (folds[0].vertices[0], folds[0].vertices[1]);
            for end in [a, b] {
                let on = s.vertices.iter().any(|v| (v[0] - end[0]).hypot(v[1] - end[1]) < 1e-6);
                assert!(on, "{body} {side}: fold end {end:?} not on the outline");
            }
            let side_of = |v: &[f64; 2]| (b[0] - a[0]) * (v[1] - a[1]) - (b[1] - a[1]) * (v[0] - a[0]);
            assert!(s.vertices.iter().any(|v| side_of(v) > 1.0) && s.vertices.iter().any(|v| side_of(v) < -1.0));
        }
        // Sewn into the armhole exactly as the two panels are.
        let fold = &p.panel("right_sleeve_f").unwrap().lines[0].vertices;
        let top_length = (fold[1][0] - fold[0][0]).hypot(fold[1][1] - fold[0][1]);
        assert_eq!(armhole_pairs(&p, top_length), armhole_pairs(&q, top_length), "{body}");
        // The box mesh turns the back half over the arm and sews it.
        let mesh = BoxMesh::new(&p, 1.0).unwrap_or_else(|e| panic!("{body}: {e}"));
        assert!(mesh.n_stitch_vertices > 0);
    }
    // A standing shoulder puts a corner in the top: refused, naming the parameters.
    let mut standing = one_piece.clone();
    standing.sleeve.standing_shoulder = true;
    standing.sleeve.sleeve_angle = 40;
    let err = garments::build::build(&standing, &builtin::body("mean_all").unwrap(), "s").unwrap_err().to_string();
    assert!(err.contains("extension.sleeve.one_piece") && err.contains("sleeve.standing_shoulder"), "{err}");
}

#[test]
fn hip_pockets_sit_on_every_kind_of_skirt() {
    let kinds = [
        BottomKind::SkirtCircle,
        BottomKind::AsymmSkirtCircle,
        BottomKind::GodetSkirt,
        BottomKind::Skirt2,
        BottomKind::SkirtManyPanels,
        BottomKind::PencilSkirt,
        BottomKind::SkirtLevels,
    ];
    for kind in kinds {
        let mut d = Design::defaults();
        d.meta.bottom = Some(kind);
        d.meta.wb = Some(garments::design::WaistbandKind::StraightWB);
        d.extension.pockets.skirt = true;
        let name = format!("{kind:?}");
        let p = build_design(&name, &d, "mean_all");
        let pockets: Vec<&str> = p.panels.iter().filter(|s| s.name.contains("_pocket_")).map(|s| s.name.as_str()).collect();
        assert_eq!(pockets.len(), 2, "{name}: {pockets:?}");
        // Each sewn by its sides and bottom onto a placement line of a skirt panel.
        let placements: usize = p.panels.iter().map(|s| s.lines.iter().filter(|l| l.kind == LineKind::Placement).count()).sum();
        assert_eq!(placements, 2, "{name}");
        assert_eq!(p.inner_stitches.len(), 6, "{name}");
        BoxMesh::new(&p, 1.0).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}
