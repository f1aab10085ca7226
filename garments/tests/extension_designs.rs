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
        // Two box pleats in front (two folds and a placement each), two knife
        // pleats at the back (a fold and a placement each).
        for (name, lines) in [("skirt_front", 6), ("skirt_back", 4)] {
            let s = p.panel(name).unwrap();
            let kinds: Vec<LineKind> = s.lines.iter().map(|l| l.kind).collect();
            assert_eq!(kinds.len(), lines, "{body} {name}");
            assert_eq!(kinds.iter().filter(|k| **k == LineKind::PleatPlacement).count(), 2);
        }
        // 2 pleats × 2 folds in front, 2 × 1 at the back, each 2.5 cm onto 2.5 cm, on
        // the outline.
        let pleat_stitches: Vec<_> =
            p.stitches.iter().filter(|st| st.sides[0].panel == st.sides[1].panel && st.sides[0].panel.starts_with("skirt_")).collect();
        assert_eq!(pleat_stitches.len(), 6, "{body}");
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

/// Per pleat stitch of a box mesh: how far behind its skirt panel (towards the body,
/// cm) the stitch's own vertices start (those no other stitch merged), sorted, less
/// how far behind it the vertex shared with the flat parts' seam does.
fn pleat_ridges(p: &Pattern) -> Vec<(String, Vec<f64>)> {
    use garmentcode::mesh::VertexLabel;
    let mesh = BoxMesh::new(p, 1.0).unwrap();
    let mut ridges = Vec::new();
    for (k, st) in mesh.stitches.iter().enumerate() {
        let (pi, name) = (st.sides[0].0, &mesh.panels[st.sides[0].0].name);
        if st.sides[1].0 != pi || !name.starts_with("skirt_") {
            continue;
        }
        // The panel's plane: its own vertices' mean z (in front of the body or behind it).
        let own: Vec<f64> =
            mesh.vertices.iter().zip(&mesh.labels).filter(|(_, l)| **l == VertexLabel::Panel(pi)).map(|(v, _)| v.z).collect();
        let plane = own.iter().sum::<f64>() / own.len() as f64;
        let behind = |z: f64| (plane - z) * plane.signum();
        let mut top = None;
        let mut depths = Vec::new();
        for (v, l) in mesh.vertices.iter().zip(&mesh.labels) {
            let VertexLabel::Stitch(ks) = l else { continue };
            if ks.iter().all(|&j| j == k) {
                depths.push(behind(v.z));
            } else if ks.contains(&k) {
                top = Some(behind(v.z));
            }
        }
        let top = top.expect("a pleat meets the flat parts");
        let mut ridge: Vec<f64> = depths.iter().map(|d| d - top).collect();
        ridge.sort_by(f64::total_cmp);
        ridges.push((name.clone(), ridge));
    }
    ridges
}

#[test]
fn a_pleats_layers_start_folded_behind_the_skirt_in_the_box_mesh() {
    // Before, each pleat's stitched pairs all started at the one point where its two
    // pieces meet, in the panel's plane: the folded layers lay flat on each other and
    // crossed in the drape (200 crossing edges in the 4 cm below the waist).
    let mut design = builtin::design("pleated-skirt").unwrap();
    for style in [PleatStyle::BoxAndKnife, PleatStyle::KnifePleats, PleatStyle::BoxPleats] {
        design.extension.pleats.style = Some(style);
        for (body, _) in builtin::BODIES {
            let p = build_design("pleated-skirt", &design, body);
            let ridges = pleat_ridges(&p);
            assert_eq!(
                ridges.len(),
                if style == PleatStyle::BoxPleats {
                    8
                } else if style == PleatStyle::KnifePleats {
                    4
                } else {
                    6
                }
            );
            for (name, ridge) in ridges {
                // A ridge going back from where the pleat meets the flat parts, a pair
                // every 0.83 cm (2.5 cm at 1 cm, 4 vertices a side), to the pleat's
                // depth (2.5 cm) at its inner fold.
                let steps: Vec<f64> = ridge.windows(2).map(|w| w[1] - w[0]).collect();
                assert!(ridge.len() == 3 && steps.iter().all(|d| (d - 2.5 / 3.0).abs() < 1e-6), "{style:?} {body} {name}: {ridge:?}");
                assert!((ridge[2] - 2.5).abs() < 1e-6, "{style:?} {body} {name}: {ridge:?}");
            }
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

/// Per pocket stitch of a box mesh: the pocket, and the farthest apart (cm) any two of
/// its vertices that the stitch merges start (the pocket's edge and the placement
/// line under it, paired as the box mesh pairs them).
fn pocket_stitch_spans(mesh: &BoxMesh) -> Vec<(String, f64)> {
    let mut spans = Vec::new();
    for st in &mesh.stitches {
        let [(p0, e0), (p1, e1)] = st.sides;
        let (a, b) = (&mesh.panels[p0], &mesh.panels[p1]);
        if !a.name.contains("pocket") && !b.name.contains("pocket") {
            continue;
        }
        let mut r0 = a.edges[e0].local.clone();
        if !st.right_wrong {
            r0.reverse();
        }
        let span =
            r0.iter().zip(&b.edges[e1].local).map(|(&i, &j)| (a.to_3d(a.points[i]) - b.to_3d(b.points[j])).length()).fold(0.0, f64::max);
        spans.push((format!("{} / {}", a.name, b.name), span));
    }
    spans
}

#[test]
fn a_trouser_pocket_lies_on_the_front_of_each_leg_its_corners_on_the_lines_corners() {
    // Sampled (`sample -n 6 -s 7 --extended`, sample 3): the pocket on the mirrored leg
    // crumpled in the drape, its stitches pairing corner with corner.
    for (body, _) in builtin::BODIES {
        let mut d = Design::defaults();
        d.meta.bottom = Some(BottomKind::Pants);
        d.extension.pockets.pants = true;
        let p = build_design("pocket-trousers", &d, body);
        let mesh = BoxMesh::new(&p, 1.0).unwrap();
        let spans = pocket_stitch_spans(&mesh);
        assert_eq!(spans.len(), 6, "{body}");
        for (pair, span) in &spans {
            // Each pocket vertex starts beside the line's vertex it is sewn to (the pocket
            // lies 0.3 cm off the leg).
            assert!(*span < 1.0, "{body} {pair}: {span:.2} cm");
        }
        // On the outer face of the leg: in front of it.
        for leg in ["pant_f_r", "pant_f_l"] {
            let z = |name: &str| {
                let pm = mesh.panels.iter().find(|m| m.name == name).unwrap();
                pm.points.iter().map(|q| pm.to_3d(*q).z).sum::<f64>() / pm.points.len() as f64
            };
            let pocket = format!("{leg}_pocket");
            // The leg's mean z is over the whole leg; the pocket sits near its top, where the
            // leg is furthest forward: compare with the placement line's own points.
            let spec = p.panel(leg).unwrap();
            let line = &spec.lines[0];
            let line_z =
                line.vertices.iter().map(|v| spec.point_to_3d(garmentcode::Vec2::from(*v)).z).sum::<f64>() / line.vertices.len() as f64;
            assert!(z(&pocket) > line_z, "{body} {pocket}: z {:.2} behind its line's {line_z:.2} (leg {:.2})", z(&pocket), z(leg));
        }
    }
}

#[test]
fn a_doubled_cuff_folds_its_free_half_inside_onto_the_half_sewn_on() {
    // Before, the back cuff panel (its outline running the other way) turned its half
    // sewn to the sleeve instead of its free half, and the front and back folded to
    // opposite faces: the two layers crossed at the side seams (352 crossing edges in
    // the drape).
    let p = build("pocket-shirt", "mean_all");
    let mesh = BoxMesh::new(&p, 1.0).unwrap();
    for side in ["right", "left"] {
        let names = [format!("sl_{side}_cuff_f"), format!("sl_{side}_cuff_b")];
        let panels: Vec<&garmentcode::mesh::PanelMesh> = names.iter().map(|n| mesh.panels.iter().find(|m| &m.name == n).unwrap()).collect();
        let plain =
            |m: &garmentcode::mesh::PanelMesh, q: garmentcode::Vec2| m.rotation * garmentcode::Vec3::new(q.x, q.y, 0.0) + m.translation;
        // The cuff's middle: between its front and back panels.
        let all: Vec<garmentcode::Vec3> = panels.iter().flat_map(|m| m.points.iter().map(|q| plain(m, *q))).collect();
        let middle = all.iter().copied().sum::<garmentcode::Vec3>() / all.len() as f64;
        for (name, m) in names.iter().zip(&panels) {
            // The edge sewn to the sleeve stays where it was placed.
            let sewn = p
                .stitches
                .iter()
                .flat_map(|st| [(&st.sides[0], &st.sides[1]), (&st.sides[1], &st.sides[0])])
                .find(|(s, o)| &s.panel == name && o.panel.contains("sleeve"))
                .unwrap()
                .0
                .edge;
            for &l in &m.edges[sewn].local {
                assert!((m.to_3d(m.points[l]) - plain(m, m.points[l])).length() < 1e-9, "{name}: its seam to the sleeve moved");
            }
            // The turned half lies on the inner side, towards the cuff's middle, FOLD_GAP
            // off the half sewn on.
            let turned: Vec<f64> = m
                .points
                .iter()
                .filter(|q| (m.to_3d(**q) - plain(m, **q)).length() > 1.5)
                .map(|q| {
                    let (now, was) = (m.to_3d(*q), plain(m, *q));
                    let inward = (middle - was).z.signum();
                    (now.z - was.z) * inward
                })
                .collect();
            assert!(turned.len() > 50, "{name}: {} points turned", turned.len());
            let off: Vec<&f64> = turned.iter().filter(|d| (*d - garmentcode::mesh::FOLD_GAP).abs() > 1e-6).collect();
            assert!(off.is_empty(), "{name}: {} of {} off: {:?}", off.len(), turned.len(), &off[..off.len().min(8)]);
        }
    }
}

/// Width of a panel's outline, cm.
fn outline_width(p: &Pattern, panel: &str) -> f64 {
    let xs = p.panel(panel).unwrap().vertices.iter().map(|v| v[0]);
    xs.clone().fold(f64::NEG_INFINITY, f64::max) - xs.fold(f64::INFINITY, f64::min)
}

#[test]
fn a_pencil_skirts_hip_ease_widens_its_front_and_back_by_the_ease() {
    for (body, _) in builtin::BODIES {
        let mut design = builtin::design("birch-dress").unwrap();
        design.extension.fit.hip_ease = 0.0;
        let fitted = build_design("birch-dress", &design, body);
        design.extension.fit.hip_ease = 6.0;
        let eased = build_design("birch-dress", &design, body);
        for (panel, half) in [("skirt_front", 3.0), ("skirt_back", 3.0)] {
            let grown = outline_width(&eased, panel) - outline_width(&fitted, panel);
            assert!((grown - half).abs() < 1e-9, "{body} {panel}: {grown} cm wider");
        }
    }
}

/// How many of the box mesh's edges cross one of its triangles (as the drape judge counts
/// them, [`garmentcode_drape::crossing_edges`]), among those on a face of a panel `on`
/// accepts or crossing such a face first.
fn crossing_edges(mesh: &BoxMesh, on: impl Fn(&str) -> bool) -> usize {
    let chosen: Vec<bool> = mesh.faces.iter().map(|f| on(&mesh.panels[f.panel].name)).collect();
    let on_chosen: std::collections::BTreeSet<[usize; 2]> = mesh
        .faces
        .iter()
        .zip(&chosen)
        .filter(|(_, c)| **c)
        .flat_map(|(f, _)| {
            let v = f.vertices;
            (0..3).map(move |k| [v[k].min(v[(k + 1) % 3]), v[k].max(v[(k + 1) % 3])])
        })
        .collect();
    garmentcode_drape::crossing_edges(mesh, &mesh.vertices)
        .into_iter()
        .filter(|(edge, face)| chosen[*face] || on_chosen.contains(edge))
        .count()
}

#[test]
fn a_doubled_cuffs_layers_start_apart_in_the_box_mesh() {
    // Before, the cuff's half sewn on turned steeply to its seam with the sleeve (merged
    // halfway to the sleeve) while the folded half ran on flat to its free edge, right
    // under that seam, and the front and back inner layers' opposite gaps cancelled at the
    // side seams: about 312 edges crossed in or into the cuffs (445 in the whole box mesh).
    // 8 are left, 4 at one corner of two of the cuffs, where the vertex merged from the
    // sleeve and both side seams pulls a face of the outer layer over the inner one; the
    // drape undoes them (the pocket-shirt's drape ends with none).
    let p = build("pocket-shirt", "mean_all");
    let mesh = BoxMesh::new(&p, 1.0).unwrap();
    let crossing = crossing_edges(&mesh, |name| name.contains("cuff"));
    assert!(crossing <= 8, "{crossing} edges cross in or into the cuffs");
}
