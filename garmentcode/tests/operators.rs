//! Small components that use every operator, assembled into flat patterns: the
//! emitted `specification.json` is pinned by insta snapshots, and each test also
//! checks the geometric facts the operator promises.

use garmentcode::curves::{match_tangents, quadratic_with_extremum};
use garmentcode::ops::{
    CornerCut, Cut, DartSize, EdgeSide, ShapeOrder, cut_corner, cut_into_edge, cut_many_into_edge, dart_shape, distribute_horizontally,
    distribute_y, side_with_cut,
};
use garmentcode::{
    Align, Arena, Component, Curve, Edge, EdgeSeq, Gather, InterfaceId, Interfaces, PanelId, PartExt, Pattern, Rotation, Severity,
    StitchRule, Vec2, Vec3, validate,
};

fn v2(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

/// A rectangle panel with an interface on each side.
#[derive(Clone, Component)]
struct Rect {
    #[panel]
    panel: PanelId,
    #[interface]
    bottom: InterfaceId,
    #[interface]
    right: InterfaceId,
    #[interface]
    top: InterfaceId,
    #[interface]
    left: InterfaceId,
}

/// A rectangle `w × h` with its pivot at the top centre (edges bottom, right, top,
/// left: counter-clockwise).
fn rectangle(a: &mut Arena, name: &str, w: f64, h: f64) -> Rect {
    let edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(w, 0.0), v2(w, h), v2(0.0, h)], true).unwrap();
    let panel = a.panel_with_edges(name, edges.clone());
    panel.set_pivot(a, v2(w / 2.0, h), false);
    Rect {
        panel,
        bottom: a.interface(panel, edges[0]),
        right: a.interface(panel, edges[1]),
        top: a.interface(panel, edges[2]),
        left: a.interface(panel, edges[3]),
    }
}

/// A skirt gore sewn by parts of its sides and gathered at the top.
#[derive(Clone, Component)]
struct Gore {
    #[panel]
    panel: PanelId,
    #[interface]
    right: InterfaceId,
    #[interface]
    left: InterfaceId,
    #[interface]
    top: InterfaceId,
}

/// A tiny component: a list of panels plus stitches.
struct Group {
    panels: Vec<PanelId>,
    stitches: Vec<StitchRule>,
}

impl garmentcode::Part for Group {
    fn node(&self) -> garmentcode::Node<'_> {
        garmentcode::Node::Component(self)
    }
}

impl garmentcode::Component for Group {
    fn name(&self) -> String {
        "group".into()
    }
    fn for_each_part(&self, f: &mut dyn FnMut(&dyn garmentcode::Part)) {
        for p in &self.panels {
            f(p)
        }
    }
    fn stitches(&self) -> Vec<StitchRule> {
        self.stitches.clone()
    }
}

/// Assemble, check there are no validation errors, and return pattern and JSON.
fn assemble(a: &mut Arena, g: &Group, name: &str) -> (Pattern, String) {
    let pattern = g.assemble(a, name).unwrap();
    let errors: Vec<_> = validate(&pattern).into_iter().filter(|p| p.severity == Severity::Error).collect();
    assert!(errors.is_empty(), "{name}: {errors:?}");
    let json = pattern.to_json().unwrap();
    // The emitted file reads back into the same pattern.
    assert_eq!(Pattern::from_json(&json).unwrap().to_json().unwrap(), json);
    (pattern, json)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Bodice block: an armhole (cubic) projected onto the shoulder corner, a curved
/// neckline (quadratic with a prescribed lowest point) cut into the top edge, a
/// mirrored back, and side and shoulder seams.
#[test]
fn bodice_block_corner_and_edge_projection() {
    let mut a = Arena::new();
    let a = &mut a;
    let front_rect = rectangle(a, "front", 24.0, 40.0);
    let front = front_rect.panel;
    let e = front.edges(a).clone();
    let corner = a.interface(front, EdgeSeq(vec![e[1], e[2]]));

    // Armhole: a cubic from the underarm up to the shoulder, 8 cm wide, 18 cm deep.
    let armhole = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(-8.0, 18.0)], false).unwrap();
    a.set_curve(armhole[0], Curve::Cubic(v2(0.3, -0.1), v2(0.8, -0.35)));
    let before = front.edges(a).length(a);
    let CornerCut { shape: arm_edges, interface: arm_iface } = cut_corner(a, &armhole, corner).unwrap();
    assert_eq!(arm_edges.len(), 1);
    let arm = a.geom(arm_edges[0]);
    assert!(close((arm.end - arm.start).length(), (8f64 * 8.0 + 18.0 * 18.0).sqrt(), 1e-9));
    assert!(front.edges(a).is_loop(a));
    assert!(front.edges(a).length(a) != before);
    assert_eq!(front.interfaces(a).last(), Some(&arm_iface), "the cut's interface belongs to the panel");

    // Neckline: a quadratic 9 cm wide whose extremum lies 9 cm below its chord, cut
    // into the top edge 4 cm from its end (the top edge runs right to left).
    let top = front_rect.top.edges(a)[0];
    let curve = quadratic_with_extremum(v2(0.5, -1.0)).unwrap();
    let neck = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(9.0, 0.0)], false).unwrap();
    a.set_curve(neck[0], curve);
    let top_len = a.edge_length(top);
    let cut = cut_into_edge(a, &neck, top, top_len - 4.5 - 4.0, EdgeSide::Left).unwrap();
    let mut outline = front.edges(a).clone();
    outline.substitute(top, cut.edges.as_slice()).unwrap();
    front.set_edges(a, outline);
    let lowest = a.geom(cut.shape[0]).linearize(200).iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    // The panel's origin is its pivot, the top centre: the neckline dips 9 cm.
    assert!(close(lowest, -9.0, 5e-3), "neckline bottom at {lowest}");
    let shoulder = a.interface(front, cut.leftovers[0]);

    // Back: a deep copy mirrored to the other side of the body.
    front.translate_to(a, Vec3::new(0.0, 140.0, 15.0));
    let back_rect = front_rect.deep_copy(a);
    let back = back_rect.panel;
    back.set_name(a, "back");
    assert!(back_rect.interfaces().iter().all(|(_, i)| i.panels(a) == [back]), "the copy has interfaces of its own");
    back.translate_to(a, Vec3::new(0.0, 140.0, -15.0));
    back.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, 180.0, 0.0]));
    back.mirror(a);
    back.mirror(a);
    let back_shoulder =
        a.interface(back, back.edges(a).iter().copied().find(|&e| a.edge_length(e) == a.geom(cut.leftovers[0]).length()).unwrap());

    let stitches = vec![StitchRule::new(a, front_rect.left, back_rect.left).unwrap(), StitchRule::new(a, shoulder, back_shoulder).unwrap()];
    let group = Group { panels: vec![front, back], stitches };
    let (pattern, json) = assemble(a, &group, "bodice_block");
    assert_eq!(pattern.panels.len(), 2);
    assert_eq!(pattern.stitches.len(), 2);
    insta::assert_snapshot!("bodice_block", json);
}

/// Skirt yoke: darts projected into a curved waist edge (one `cut_into_edge`, and
/// several at once with `cut_many_into_edge`), copies distributed around the body,
/// a side cut left open, and the waist gathered onto a band placed by interface.
#[test]
fn distributed_gores_with_darts_and_gathered_waist() {
    let mut a = Arena::new();
    let a = &mut a;
    // A gore whose waist is a shallow arc.
    let corners = [v2(0.0, 0.0), v2(4.0, 30.0), v2(20.0, 30.0), v2(24.0, 0.0)];
    let s = EdgeSeq::from_points(a, &corners, true).unwrap();
    a.set_curve(s[1], Curve::Arc { cy: 0.05 });
    let gore = a.panel_with_edges("gore", s.clone());
    gore.set_pivot(a, v2(12.0, 30.0), false);

    // Two darts side by side, drawn with vertical openings, cut into the waist.
    let mut shapes = Vec::new();
    for x in [0.0, 5.0] {
        let d = EdgeSeq::from_points(a, &[v2(0.0, x), v2(7.0, x + 0.75), v2(0.0, x + 1.5)], false).unwrap();
        shapes.push(d);
    }
    let waist_len = a.edge_length(s[1]);
    let cut = cut_many_into_edge(a, &shapes, s[1], waist_len / 2.0, EdgeSide::Right, ShapeOrder::AsDrawn).unwrap();
    assert_eq!(cut.shape.len(), 4, "two darts of two legs");
    assert!(close(cut.leftovers.length(a) + 1.5 + 1.5, waist_len, 0.05), "{} vs {waist_len}", cut.leftovers.length(a));
    let mut outline = s.clone();
    outline.substitute(s[1], cut.edges.as_slice()).unwrap();
    gore.set_edges(a, outline.clone());
    let l0 = a.interface(gore, cut.shape[0]);
    let l1 = a.interface(gore, cut.shape[1]);
    let rule = StitchRule::new(a, l0, l1).unwrap();
    gore.add_stitch(a, rule);
    let l2 = a.interface(gore, cut.shape[2]);
    let l3 = a.interface(gore, cut.shape[3]);
    let rule = StitchRule::new(a, l2, l3).unwrap();
    gore.add_stitch(a, rule);

    // The right side is sewn only below an opening of a fifth of its length at the top.
    let (bottom_right, top_right) = (a.start(outline[0]), a.end(outline[0]));
    let side = side_with_cut(a, bottom_right, top_right, 0.0, 0.2).unwrap();
    assert_eq!(side.len(), 2);
    assert!(close(side.length(a), 30.2654919008431, 1e-9));
    outline.substitute(outline[0], side.as_slice()).unwrap();
    gore.set_edges(a, outline.clone());
    let sewn_right = a.interface(gore, side[0]);
    // The left side likewise, so that the sewn parts of neighbouring sides match.
    let left_edge = outline.at(-2);
    let (top_left, bottom_left) = (a.start(left_edge), a.end(left_edge));
    let left_side = side_with_cut(a, top_left, bottom_left, 0.2, 0.0).unwrap();
    outline.substitute(left_edge, left_side.as_slice()).unwrap();
    gore.set_edges(a, outline.clone());
    let sewn_left = a.interface(gore, left_side[1]);
    let waist: Vec<_> = cut.leftovers.iter().copied().collect();
    let waist_iface = a.interface(gore, EdgeSeq(waist));
    let gore = Gore { panel: gore, right: sewn_right, left: sewn_left, top: waist_iface };

    gore.translate_to(a, Vec3::new(-15.0, 100.0, 0.0));
    gore.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, -90.0, 0.0]));
    let gores = distribute_y(a, gore, 4, "gore");
    assert_eq!(gores.iter().map(|g| g.panel.name(a).to_string()).collect::<Vec<_>>(), ["gore_0", "gore_1", "gore_2", "gore_3"]);
    assert_eq!(gores[3].panel.stitches(a).len(), 2, "copies keep their darts");
    let t1 = gores[1].panel.translation(a);
    let t0 = gores[0].panel.translation(a);
    assert!(close(t1.length(), t0.length(), 1e-9), "copies keep their distance to the axis");

    let mut stitches = Vec::new();
    for i in 0..4 {
        stitches.push(StitchRule::new(a, gores[i].left, gores[(i + 1) % 4].right).unwrap());
    }
    // Each gore's waist is gathered twofold onto a flat band.
    let tops: Vec<_> = gores
        .iter()
        .map(|g| {
            let edges = g.top.edges(a).clone();
            a.interface_gathered(g.panel, edges, Gather::Uniform(2.0)).unwrap()
        })
        .collect();
    let skirt_waist = a.interface_from(&tops);
    assert_eq!(skirt_waist.ruffle(a).len(), 4);
    let band = rectangle(a, "band", skirt_waist.length(a) / 2.0, 5.0);
    let band_bottom = band.bottom;
    band.translate_to(a, Vec3::new(0.0, 0.0, 20.0));
    band.place_by_interface(a, band_bottom, skirt_waist, 2.0, Align::Center);
    let (blo, _) = band.bbox3d(a);
    let (_, shi) = gores[0].bbox3d(a);
    assert!(blo.y > shi.y - 1e-6, "the band sits above the skirt ({} vs {})", blo.y, shi.y);
    a.set_edge_label(band.panel.edges(a)[0], "waistband");
    stitches.push(StitchRule::new(a, skirt_waist, band_bottom).unwrap());
    let mut panels: Vec<PanelId> = gores.iter().map(|g| g.panel).collect();
    panels.push(band.panel);
    let group = Group { panels, stitches };
    let (pattern, json) = assemble(a, &group, "gathered_gores");
    assert_eq!(pattern.panels.len(), 5);
    insta::assert_snapshot!("gathered_gores", json);
}

/// Tiers: copies distributed in a row, a tier placed below another, a gathered
/// interface (ratio 1.5) stitched to a flat one, and a sleeve-like cubic re-fitted
/// to end tangents at fixed length.
#[test]
fn tiers_rows_and_tangent_matching() {
    let mut a = Arena::new();
    let a = &mut a;
    let upper = rectangle(a, "upper", 40.0, 20.0);
    upper.translate_to(a, Vec3::new(0.0, 100.0, 20.0));
    let lower = rectangle(a, "lower", 60.0, 25.0);
    lower.translate_to(a, Vec3::new(0.0, 0.0, 20.0));
    lower.place_below(a, &upper, 3.0);
    let (ulo, _) = upper.bbox3d(a);
    let (_, lhi) = lower.bbox3d(a);
    assert!(close(ulo.y - lhi.y, 3.0, 1e-9));

    let lower_top_edges = lower.top.edges(a).clone();
    let ruffled = a.interface_gathered(lower.panel, lower_top_edges, 1.5).unwrap();
    let upper_bottom = upper.bottom;
    let tier_seam = StitchRule::new(a, upper_bottom, ruffled).unwrap();

    // A row of three pockets, 12 cm apart (towards the wearer's right, as the
    // reference steps along its panel's normal × up).
    let pocket = rectangle(a, "pocket", 8.0, 8.0);
    pocket.translate_to(a, Vec3::new(-12.0, 80.0, 25.0));
    let pockets = distribute_horizontally(a, pocket, 3, 12.0, "pocket");
    let xs: Vec<f64> = pockets.iter().map(|p| p.panel.translation(a).x).collect();
    assert!(close(xs[0] - xs[1], 12.0, 1e-9) && close(xs[1] - xs[2], 12.0, 1e-9), "{xs:?}");

    // The hem becomes a cubic fitted to given end tangents at the hem's length.
    let hem = lower.bottom.edges(a)[0];
    let g = a.geom(hem);
    let rel = |p: Vec2| garmentcode::math::abs_to_rel(g.start, g.end, p);
    let initial = Edge { curve: Curve::Cubic(rel(g.start + v2(20.0, -4.0)), rel(g.end + v2(-20.0, -4.0))), ..g };
    let fitted = match_tangents(&initial, v2(1.0, -0.3).normalize(), v2(1.0, 0.3).normalize(), 64.0);
    assert!(close(fitted.length(), 64.0, 0.01), "fitted length {}", fitted.length());
    assert!(close(fitted.start.distance(g.start), 0.0, 1e-9), "the start stays put");
    a.set_pos(a.end(hem), fitted.end);
    a.set_curve(hem, fitted.curve);

    let mut panels = vec![upper.panel, lower.panel];
    panels.extend(pockets.iter().map(|p| p.panel));
    let group = Group { panels, stitches: vec![tier_seam] };
    let (pattern, json) = assemble(a, &group, "tiers");
    assert_eq!(pattern.panels.len(), 5);
    insta::assert_snapshot!("tiers", json);
}

/// A dart made by the factory from its side length is inserted with `add_dart`,
/// which stitches its legs; the panel records the stitch and the leftovers keep
/// the original length minus the dart's width.
#[test]
fn panel_dart_is_stitched() {
    let mut a = Arena::new();
    let a = &mut a;
    let rect = rectangle(a, "panel", 30.0, 20.0);
    let p = rect.panel;
    let dart = dart_shape(a, 3.0, DartSize::Side(10.0)).unwrap();
    let top = rect.top.edges(a)[0];
    let Cut { edges, leftovers, .. } = p.add_dart(a, &dart, top, 10.0, EdgeSide::Left).unwrap();
    assert_eq!(edges.len(), 4);
    assert!(close(leftovers.length(a), 27.0, 1e-9));
    assert!(close(a.edge_length(edges[1]), 10.0, 1e-9) && close(a.edge_length(edges[2]), 10.0, 1e-9));
    let mut outline = p.edges(a).clone();
    outline.substitute(top, edges.as_slice()).unwrap();
    p.set_edges(a, outline);
    assert_eq!(p.stitches(a).len(), 1);
    let group = Group { panels: vec![p], stitches: Vec::new() };
    let (pattern, json) = assemble(a, &group, "dart");
    assert_eq!(pattern.stitches.len(), 1);
    insta::assert_snapshot!("dart", json);
}

/// `check_outline` is a no-op unless the arena is set to stop at self-intersections;
/// then it names the panel whose outline crosses itself, and still passes a clean one.
#[test]
fn outline_check_stops_only_when_asked() {
    let mut a = Arena::new();
    // A bow tie: the loop's second and fourth edges cross at (1, 0.5).
    let bow = EdgeSeq::from_points(&mut a, &[v2(0.0, 0.0), v2(2.0, 0.0), v2(0.0, 1.0), v2(2.0, 1.0)], true).unwrap();
    let bow = a.panel_with_edges("bow", bow);
    let square = rectangle(&mut a, "square", 2.0, 1.0);
    assert!(bow.is_self_intersecting(&a) && !square.is_self_intersecting(&a));
    assert_eq!(bow.check_outline(&a), Ok(()));
    a.stop_at_self_intersection(true);
    let err = bow.check_outline(&a).unwrap_err();
    assert_eq!(err, garmentcode::Error::SelfIntersecting { panel: "bow".into() });
    assert_eq!(err.to_string(), "self-intersection: the outline of panel 'bow' crosses itself");
    assert_eq!(square.panel.check_outline(&a), Ok(()));
    // The setting outlives clearing the arena for the next garment.
    a.clear();
    let bow = EdgeSeq::from_points(&mut a, &[v2(0.0, 0.0), v2(2.0, 0.0), v2(0.0, 1.0), v2(2.0, 1.0)], true).unwrap();
    let bow = a.panel_with_edges("bow", bow);
    assert!(bow.check_outline(&a).is_err());
}
