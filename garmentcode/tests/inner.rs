//! The operators inside a panel (`garmentcode::inner`): holes, inner lines, pieces
//! sewn on top, pleats and layers, through assembly into the flat pattern.

use garmentcode::inner::{PleatDirection, PleatKind, diamond_dart, facing, fold_line, keyhole, place_on, pleats, slit};
use garmentcode::{Arena, EdgePlace, EdgeSeq, HoleKind, Layer, LineKind, PanelId, PartExt, StitchRule, Vec2, Vec3};

fn rect(a: &mut Arena, name: &str, w: f64, h: f64) -> (PanelId, EdgeSeq) {
    let corners = [Vec2::ZERO, Vec2::new(0.0, h), Vec2::new(w, h), Vec2::new(w, 0.0)];
    let edges = EdgeSeq::from_points(a, &corners, true).unwrap();
    (a.panel_with_edges(name, edges.clone()), edges)
}

fn close(p: [f64; 2], q: [f64; 2]) -> bool {
    (p[0] - q[0]).abs() < 1e-9 && (p[1] - q[1]).abs() < 1e-9
}

#[test]
fn a_diamond_dart_is_a_hole_whose_upper_and_lower_sides_are_sewn_together() {
    let mut a = Arena::new();
    let (front, _) = rect(&mut a, "front", 30.0, 60.0);
    diamond_dart(&mut a, &front, "dart", Vec2::new(10.0, 30.0), 4.0, 20.0).unwrap();
    let p = a.assemble_panels(&[front], "dress").unwrap();
    let panel = &p.panels[0];
    assert!(panel.uses_extension());
    let hole = &panel.holes[0];
    // Written relative to the outline's first vertex (the origin here).
    let expected = [[10.0, 40.0], [12.0, 30.0], [10.0, 20.0], [8.0, 30.0]];
    assert!(hole.vertices.iter().zip(expected).all(|(v, e)| close(*v, e)), "{:?}", hole.vertices);
    assert_eq!(hole.edges.iter().map(|e| e.endpoints).collect::<Vec<_>>(), [[0, 1], [1, 2], [2, 3], [3, 0]]);
    // Upper sides (0 and 3) and lower sides (1 and 2), nothing on the outline.
    assert!(p.stitches.is_empty());
    let pairs: Vec<[usize; 2]> = p.inner_stitches.iter().map(|s| [s.sides[0].edge, s.sides[1].edge]).collect();
    assert_eq!(pairs, [[0, 3], [1, 2]]);
    assert!(p.inner_stitches.iter().flat_map(|s| &s.sides).all(|s| s.place == EdgePlace::Hole(0) && s.panel == "front"));
}

#[test]
fn holes_and_lines_move_with_the_panel_and_are_copied_with_it() {
    let mut a = Arena::new();
    let (front, _) = rect(&mut a, "front", 30.0, 40.0);
    slit(&mut a, &front, "welt", Vec2::new(10.0, 20.0), Vec2::new(20.0, 20.0), 1.0).unwrap();
    fold_line(&mut a, &front, "fold", Vec2::new(15.0, 0.0), Vec2::new(15.0, 40.0), 90.0).unwrap();
    front.translate_to(&mut a, Vec3::new(5.0, 100.0, 10.0));
    front.mirror(&mut a);
    let copy = front.deep_copy(&mut a);
    copy.set_name(&mut a, "copy");
    assert_eq!((copy.hole_count(&a), copy.line_count(&a)), (1, 1));
    assert_ne!(copy.hole_edges(&a, 0), front.hole_edges(&a, 0), "the copy has its own edges");
    let p = a.assemble_panels(&[front, copy], "top").unwrap();
    for panel in &p.panels {
        // After the mirror the outline spans x in [-30, 0]; the pivot moves to the
        // outline's first vertex: the slit stays 10..20 cm in from the same side.
        let outline_x: Vec<f64> = panel.vertices.iter().map(|v| v[0]).collect();
        let (lo, hi) = outline_x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| (l.min(*x), h.max(*x)));
        let xs: Vec<f64> = panel.holes[0].vertices.iter().map(|v| v[0]).collect();
        assert!(xs.iter().all(|x| *x > lo && *x < hi), "{xs:?} in {lo}..{hi}");
        let dist: Vec<f64> = xs.iter().map(|x| (hi - x).min(x - lo)).collect();
        assert!(dist.iter().all(|d| (*d - 10.0).abs() < 1e-9), "{dist:?}");
        let fold = &panel.lines[0];
        assert!(fold.vertices.iter().all(|v| (v[0] - (lo + hi) / 2.0).abs() < 1e-9), "{:?}", fold.vertices);
        assert_eq!(fold.kind, LineKind::Fold { angle: 90.0 });
    }
    assert_eq!(p.panels[0].holes[0].kind, HoleKind::Cut);
}

#[test]
fn a_keyhole_is_a_slit_under_a_round_opening() {
    let mut a = Arena::new();
    let (back, _) = rect(&mut a, "back", 30.0, 40.0);
    keyhole(&mut a, &back, "keyhole", Vec2::new(15.0, 30.0), 2.0, 6.0, 1.0).unwrap();
    let hole = back.hole_edges(&a, 0).clone();
    let arc = a.geom(hole[3]);
    // The arc goes over the top of the circle.
    let top = arc.point(0.5);
    assert!((top - Vec2::new(15.0, 32.0)).length() < 1e-6, "{top}");
    assert!((a.geom(hole[1]).start.y - 22.0).abs() < 1e-9);
    // Too wide a slit, outside the panel: clear errors.
    let err = keyhole(&mut a, &back, "wide", Vec2::new(15.0, 10.0), 1.0, 3.0, 2.5).unwrap_err().to_string();
    assert!(err.contains("narrower"), "{err}");
    let err = keyhole(&mut a, &back, "out", Vec2::new(29.0, 10.0), 2.0, 3.0, 1.0).unwrap_err().to_string();
    assert!(err.contains("'out' in panel 'back'") && err.contains("not inside"), "{err}");
}

#[test]
fn a_fold_line_turns_by_0_to_180_degrees_and_lies_across_its_panel() {
    let mut a = Arena::new();
    let (cuff, _) = rect(&mut a, "cuff", 25.0, 12.0);
    let err = fold_line(&mut a, &cuff, "fold", Vec2::new(0.0, 6.0), Vec2::new(25.0, 6.0), 200.0).unwrap_err().to_string();
    assert!(err.contains("0 to 180"), "{err}");
    let err = fold_line(&mut a, &cuff, "fold", Vec2::new(30.0, 6.0), Vec2::new(40.0, 6.0), 180.0).unwrap_err().to_string();
    assert!(err.contains("not inside the panel's outline"), "{err}");
    fold_line(&mut a, &cuff, "fold", Vec2::new(0.0, 6.0), Vec2::new(25.0, 6.0), 180.0).unwrap();
    let err = fold_line(&mut a, &cuff, "fold", Vec2::new(0.0, 3.0), Vec2::new(25.0, 3.0), 180.0).unwrap_err().to_string();
    assert!(err.contains("already has a hole or line of this name"), "{err}");
    // A line over an outline vertex would move twice with the panel.
    let corner = a.start(cuff.edges(&a)[1]);
    let inside = a.vertex(Vec2::new(10.0, 6.0));
    let shared = a.edge(corner, inside, garmentcode::Curve::Line).unwrap();
    let err = cuff.add_line(&mut a, "shared", LineKind::Placement, EdgeSeq::from(shared)).unwrap_err().to_string();
    assert!(err.contains("share a vertex with the outline"), "{err}");
}

#[test]
fn a_patch_pocket_lies_on_its_panel_at_the_placement_line() {
    let mut a = Arena::new();
    let (front, _) = rect(&mut a, "front", 40.0, 60.0);
    front.translate_to(&mut a, Vec3::new(-20.0, 90.0, 15.0));
    let (pocket, pe) = rect(&mut a, "pocket", 12.0, 14.0);
    let sewn = a.interface(pocket, EdgeSeq::from(vec![pe[2], pe[3], pe[0]]));
    let placed = place_on(&mut a, &pocket, sewn, &front, Vec2::new(28.0, 40.0), 30.0).unwrap();
    // The line is the pocket's sides and bottom, turned by 30° about the pocket's
    // centre, which sits at (28, 40).
    let (s, c) = 30f64.to_radians().sin_cos();
    let turn = |p: Vec2| Vec2::new(28.0, 40.0) + Vec2::new(c * (p.x - 6.0) - s * (p.y - 7.0), s * (p.x - 6.0) + c * (p.y - 7.0));
    let line_points = placed.line.edges.vert_positions(&a);
    let corners = [Vec2::new(12.0, 14.0), Vec2::new(12.0, 0.0), Vec2::ZERO, Vec2::new(0.0, 14.0)];
    let mut expected: Vec<Vec2> = corners.iter().map(|p| turn(*p)).collect();
    if (line_points[0] - expected[0]).length() > 1e-6 {
        expected.reverse();
    }
    for (p, q) in line_points.iter().zip(&expected) {
        assert!((*p - *q).length() < 1e-9, "{line_points:?} vs {expected:?}");
    }
    // In 3D each pocket corner lies 0.3 cm outside the front, over its line point.
    let normal = front.norm(&a);
    let line = placed.stitch.b;
    assert_eq!(line.len(&a), 3);
    for (e, l) in sewn.edges(&a).iter().zip(line.edges(&a).iter()) {
        let (g, h) = (a.geom(*e), a.geom(*l));
        for (v, q) in [(g.start, h.start), (g.end, h.end)] {
            let off = pocket.point_to_3d(&a, v) - front.point_to_3d(&a, q);
            assert!((off - 0.3 * normal).length() < 1e-9, "{off} vs {normal}");
        }
    }
    let p = a.assemble_panels(&[front, pocket], "shirt").unwrap();
    assert_eq!(p.inner_stitches.len(), 3);
    let mut on_line = Vec::new();
    for st in &p.inner_stitches {
        assert_eq!((st.sides[0].panel.as_str(), st.sides[0].place), ("pocket", EdgePlace::Outline));
        assert_eq!((st.sides[1].panel.as_str(), st.sides[1].place), ("front", EdgePlace::Line(0)));
        on_line.push(st.sides[1].edge);
    }
    // Every line edge once, in the line's order or the opposite.
    assert!(on_line == [0, 1, 2] || on_line == [2, 1, 0], "{on_line:?}");
    // The pocket lies on the front's face, its edges along the line in the same
    // direction: sewn as they are (`right_wrong`), not reversed as between panels that
    // face each other, or the box mesh would pair each corner with the opposite one.
    assert!(p.inner_stitches.iter().all(|st| st.right_wrong));
    let mesh = garmentcode::mesh::BoxMesh::new(&p, 1.0).unwrap();
    let pocket_corners: Vec<Vec3> = corners.iter().map(|c| pocket.point_to_3d(&a, *c)).collect();
    for corner in pocket_corners {
        // Each corner of the sewn edges has a merged stitch vertex within 0.5 cm of it.
        let nearest = mesh.vertices[..mesh.n_stitch_vertices].iter().map(|v| (*v - corner).length()).fold(f64::INFINITY, f64::min);
        assert!(nearest < 0.5, "pocket corner {corner}: nearest stitch vertex {nearest} cm away");
    }
    // A pocket off the panel is refused.
    let (other, oe) = rect(&mut a, "other", 12.0, 14.0);
    let sewn = a.interface(other, oe.clone());
    let err = place_on(&mut a, &other, sewn, &front, Vec2::new(38.0, 40.0), 0.0).unwrap_err().to_string();
    assert!(err.contains("'other_placement' in panel 'front'") && err.contains("not inside"), "{err}");
}

#[test]
fn a_stitch_onto_a_line_splits_the_line_not_the_outline() {
    let mut a = Arena::new();
    let (front, fe) = rect(&mut a, "front", 40.0, 60.0);
    let line = fold_line(&mut a, &front, "flounce", Vec2::new(5.0, 30.0), Vec2::new(35.0, 30.0), 0.0).unwrap();
    let (flounce, ge) = rect(&mut a, "flounce", 30.0, 10.0);
    // Two edges (the bottom split in two) onto the one-edge line.
    let bottom = a.subdivide(ge[3], &[0.5, 0.5], true).unwrap();
    flounce.edges_mut(&mut a).substitute(ge[3], &bottom).unwrap();
    let on_line = a.interface(front, line.edges.clone());
    let flounce_side = a.interface(flounce, EdgeSeq(bottom));
    let rule = StitchRule::new(&mut a, flounce_side, on_line).unwrap();
    front.add_stitch(&mut a, rule);
    assert_eq!(front.line_edges(&a, 0).len(), 2);
    assert_eq!(front.edges(&a), &fe, "the outline is untouched");
    let p = a.assemble_panels(&[front, flounce], "dress").unwrap();
    assert_eq!(p.panels[0].lines[0].vertices.len(), 3);
    assert_eq!(p.inner_stitches.len(), 2);
}

#[test]
fn knife_pleats_leave_the_folded_width_to_stitch() {
    let mut a = Arena::new();
    let (skirt, e) = rect(&mut a, "skirt", 60.0, 50.0);
    // The top edge runs from (0, 50) to (60, 50).
    let waist = a.interface(skirt, e[1]);
    let laid = pleats(&mut a, &skirt, "waist", e[1], 3, 4.0, PleatKind::Knife(PleatDirection::Forward), 15.0).unwrap();
    assert!((waist.length(&a) - 36.0).abs() < 1e-9);
    assert_eq!(waist.edges(&a), &laid.flat);
    // Pleats centred at 10, 30, 50 cm, 8 cm wide: folds at 6, 26, 46, laid at 14, 34, 54.
    let xs: Vec<(f64, LineKind)> = laid.lines.iter().map(|l| (a.geom(l.edges[0]).start.x, skirt.line_kind(&a, l.index))).collect();
    let want = [6.0, 14.0, 26.0, 34.0, 46.0, 54.0];
    for (k, (x, kind)) in xs.iter().enumerate() {
        assert!((x - want[k]).abs() < 1e-9, "{xs:?}");
        assert_eq!(*kind, if k % 2 == 0 { LineKind::PleatFold } else { LineKind::PleatPlacement });
    }
    // Lines go down into the panel.
    let end = a.geom(laid.lines[0].edges[0]).end;
    assert!((end - Vec2::new(6.0, 35.0)).length() < 1e-9, "{end}");
    // A band of the folded width stitched to the waist meets only the flat parts.
    let (band, be) = rect(&mut a, "band", 36.0, 4.0);
    let band_side = a.interface(band, be[3]);
    let seam = StitchRule::new(&mut a, waist, band_side).unwrap();
    band.add_stitch(&mut a, seam);
    let p = a.assemble_panels(&[skirt, band], "skirt").unwrap();
    // Three pleat stitches (4 cm onto 4 cm) and four band pieces.
    assert_eq!(p.stitches.len(), 3 + 4);
    assert!(p.inner_stitches.is_empty());
    let skirt_spec = &p.panels[0];
    for s in &p.stitches[..3] {
        let l: Vec<f64> = s.sides.iter().map(|d| skirt_spec.edge_geom(d.edge).length()).collect();
        assert!(l.iter().all(|x| (x - 4.0).abs() < 1e-9), "{l:?}");
    }
}

#[test]
fn box_pleats_fold_toward_each_other_and_too_many_are_refused() {
    let mut a = Arena::new();
    let (skirt, e) = rect(&mut a, "skirt", 60.0, 50.0);
    let laid = pleats(&mut a, &skirt, "waist", e[1], 2, 3.0, PleatKind::BoxPleat, 10.0).unwrap();
    assert_eq!((laid.stitches.len(), laid.lines.len()), (4, 6));
    assert!((laid.flat.length(&a) - 36.0).abs() < 1e-9);
    let kinds: Vec<LineKind> = laid.lines.iter().map(|l| skirt.line_kind(&a, l.index)).collect();
    assert_eq!(kinds[..3], [LineKind::PleatFold, LineKind::PleatPlacement, LineKind::PleatFold]);
    let (other, o) = rect(&mut a, "other", 20.0, 50.0);
    let err = pleats(&mut a, &other, "waist", o[1], 3, 2.0, PleatKind::BoxPleat, 10.0).unwrap_err().to_string();
    assert!(err.contains("do not fit an edge of 20.00 cm in panel 'other': 1 to 2 fit"), "{err}");
}

#[test]
fn a_facing_is_a_copy_on_the_facing_layer() {
    let mut a = Arena::new();
    let (collar, ce) = rect(&mut a, "collar", 40.0, 8.0);
    let inside = facing(&mut a, &collar);
    let (outer_top, inner_top) = (a.interface(collar, ce[1]), a.interface(inside, inside.edges(&a)[1]));
    let rule = StitchRule::new(&mut a, outer_top, inner_top).unwrap();
    collar.add_stitch(&mut a, rule);
    let p = a.assemble_panels(&[collar, inside], "collar").unwrap();
    assert_eq!(p.panels.iter().map(|s| s.layer).collect::<Vec<_>>(), [Layer::Outer, Layer::Facing]);
    assert_eq!(p.panels[1].name, "collar_facing");
    assert_eq!(p.stitches.len(), 1);
    assert!(p.uses_extension());
}
