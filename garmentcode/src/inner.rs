//! Inside a panel: holes, inner lines, layers, and the operators that make them.
//!
//! The reference's panels are one outline each. These operators say what its paper
//! lists as out of reach (see [`Hole`](crate::Hole) and [`InnerLine`](crate::InnerLine)
//! for what is written):
//!
//! - [`diamond_dart`]: a diamond-shaped dart inside a panel, its sides stitched together;
//! - [`slit`] and [`keyhole`]: openings cut out of a panel;
//! - [`fold_line`]: a line the panel is folded along (a one-piece sleeve, a double cuff);
//! - [`place_on`]: a piece sewn on the face of a panel (a patch pocket), its edges
//!   stitched onto a placement line;
//! - [`pleats`]: knife or box pleats laid into an edge;
//! - [`PanelId::set_layer`] and [`facing`]: the layers of a double-layer component.
//!
//! Each takes its panel as a [`PanelPart`] (a panel or a panel class): a fold line on
//! an edge sequence, or a pocket placed on a component that has no panel surface, does
//! not compile. Holes and lines hold their own vertices (none shared with the outline),
//! move with the panel, and are copied with it. Interfaces may be made over their edges
//! like over outline edges ([`Arena::interface`]); a stitch with a side on a hole or a
//! line is written as an [`InnerStitch`](crate::InnerStitch).

use crate::arena::{Arena, EdgeId, EdgeSeq, InnerPath, PanelId, StitchRule};
use crate::component::{PanelPart, PartExt};
use crate::edge::Curve;
use crate::error::{Error, Result};
use crate::math::{Vec2, Vec3};
use crate::pattern::{HoleKind, Layer, LineKind};
use crate::remap::Remap;
use crate::rotation::Rotation;

impl PanelId {
    /// The panel's holes' and lines' edges.
    pub(crate) fn inner_edges(self, a: &Arena) -> impl Iterator<Item = &EdgeSeq> {
        let d = a.pd(self);
        d.holes.iter().map(|h| &h.edges).chain(d.lines.iter().map(|l| &l.edges))
    }

    /// Replace edge `orig` by `new` where the panel holds it: its outline, one of
    /// its holes or one of its lines.
    pub(crate) fn substitute_edge(self, a: &mut Arena, orig: EdgeId, new: &[EdgeId]) -> Result<()> {
        let d = a.pd_mut(self);
        if d.edges.index_of(orig).is_some() {
            return d.edges.substitute(orig, new);
        }
        let inner = d.holes.iter_mut().map(|h| &mut h.edges).chain(d.lines.iter_mut().map(|l| &mut l.edges));
        for seq in inner {
            if seq.index_of(orig).is_some() {
                return seq.substitute(orig, new);
            }
        }
        d.edges.substitute(orig, new)
    }

    /// Layer of the panel ([`Layer::Outer`] unless set).
    pub fn layer(self, a: &Arena) -> Layer {
        a.pd(self).layer
    }

    /// Make the panel a layer of a double-layer component (a facing or a lining).
    pub fn set_layer(self, a: &mut Arena, layer: Layer) {
        a.pd_mut(self).layer = layer;
    }

    /// Number of holes.
    pub fn hole_count(self, a: &Arena) -> usize {
        a.pd(self).holes.len()
    }

    /// Edges of hole `k` (a closed loop, in order).
    pub fn hole_edges(self, a: &Arena, k: usize) -> &EdgeSeq {
        &a.pd(self).holes[k].edges
    }

    /// Number of inner lines.
    pub fn line_count(self, a: &Arena) -> usize {
        a.pd(self).lines.len()
    }

    /// Edges of inner line `k` (an open chain, in order).
    pub fn line_edges(self, a: &Arena, k: usize) -> &EdgeSeq {
        &a.pd(self).lines[k].edges
    }

    /// Kind of inner line `k`.
    pub fn line_kind(self, a: &Arena, k: usize) -> LineKind {
        a.pd(self).lines[k].kind
    }

    /// Add a hole: `edges` must form a closed loop over vertices of their own, inside
    /// the outline. Returns its index.
    pub fn add_hole(self, a: &mut Arena, name: &str, kind: HoleKind, edges: EdgeSeq) -> Result<usize> {
        self.check_inner_name(a, name)?;
        if !edges.is_loop(a) || !edges.is_chained(a) {
            return Err(self.inner_error(a, name, "its edges do not form a closed loop"));
        }
        self.check_own_vertices(a, name, &edges)?;
        let mut around = edges.linearized_positions(a);
        if let Some(&first) = around.first() {
            around.push(first);
        }
        self.check_inside(a, name, &around)?;
        let d = a.pd_mut(self);
        d.holes.push(InnerPath { name: name.to_string(), kind, edges });
        Ok(d.holes.len() - 1)
    }

    /// Add an inner line: `edges` must form an open chain over vertices of their own
    /// (one edge or more), whose middle lies inside the outline. Returns its index.
    pub fn add_line(self, a: &mut Arena, name: &str, kind: LineKind, edges: EdgeSeq) -> Result<usize> {
        self.check_inner_name(a, name)?;
        if edges.is_empty() || (edges.len() > 1 && (!edges.is_chained(a) || edges.is_loop(a))) {
            return Err(self.inner_error(a, name, "its edges do not form an open chain"));
        }
        self.check_own_vertices(a, name, &edges)?;
        let mid = a.geom(edges[edges.len() / 2]).point(if edges.len() % 2 == 1 { 0.5 } else { 0.0 });
        self.check_inside(a, name, &[mid])?;
        let d = a.pd_mut(self);
        d.lines.push(InnerPath { name: name.to_string(), kind, edges });
        Ok(d.lines.len() - 1)
    }

    fn inner_error(self, a: &Arena, name: &str, why: &str) -> Error {
        Error::Design(format!("'{name}' in panel '{}': {why}", self.name(a)))
    }

    /// The panel moves, mirrors and copies a hole or line with its outline: they
    /// must not share a vertex (it would move twice).
    fn check_own_vertices(self, a: &Arena, name: &str, edges: &EdgeSeq) -> Result<()> {
        let new = edges.verts(a);
        let taken = std::iter::once(self.edges(a)).chain(self.inner_edges(a)).any(|seq| seq.verts(a).iter().any(|v| new.contains(v)));
        if taken {
            return Err(self.inner_error(
                a,
                name,
                "its edges share a vertex with the outline or another hole or line (make them over new vertices)",
            ));
        }
        Ok(())
    }

    fn check_inner_name(self, a: &Arena, name: &str) -> Result<()> {
        let d = a.pd(self);
        if d.holes.iter().any(|h| h.name == name) || d.lines.iter().any(|l| l.name == name) {
            return Err(self.inner_error(a, name, "the panel already has a hole or line of this name"));
        }
        Ok(())
    }

    /// Every point strictly inside the outline (linearised), and no segment between
    /// consecutive points crossing it (a dart's point between two corners of a
    /// pocket), else an error naming the panel, the hole or line and the point.
    fn check_inside(self, a: &Arena, name: &str, points: &[Vec2]) -> Result<()> {
        let outline = self.edges(a).linearized_positions(a);
        if let Some(p) = points.iter().find(|p| !inside(&outline, **p)) {
            return Err(self.inner_error(a, name, &format!("the point ({:.2}, {:.2}) is not inside the panel's outline", p.x, p.y)));
        }
        match points.windows(2).find(|w| crate::pattern::validate::inner::crosses_loop(w[0], w[1], &outline)) {
            Some(w) => Err(self.inner_error(
                a,
                name,
                &format!("from ({:.2}, {:.2}) to ({:.2}, {:.2}) it crosses the panel's outline", w[0].x, w[0].y, w[1].x, w[1].y),
            )),
            None => Ok(()),
        }
    }

    /// Signed area of the (linearised) outline: positive when it turns
    /// counter-clockwise, so that the inside is to the left of its edges.
    fn signed_area(self, a: &Arena) -> f64 {
        let q = self.edges(a).linearized_positions(a);
        (0..q.len()).map(|k| q[k].perp_dot(q[(k + 1) % q.len()])).sum::<f64>() / 2.0
    }
}

/// Whether `p` is inside the polygon `poly` (even-odd rule).
fn inside(poly: &[Vec2], p: Vec2) -> bool {
    let mut odd = false;
    for k in 0..poly.len() {
        let (u, v) = (poly[k], poly[(k + 1) % poly.len()]);
        if (u.y > p.y) != (v.y > p.y) && p.x < u.x + (p.y - u.y) / (v.y - u.y) * (v.x - u.x) {
            odd = !odd;
        }
    }
    odd
}

fn positive(what: &str, value: f64) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Error::Design(format!("{what} must be a positive number of cm, got {value}")))
    }
}

/// A diamond dart made by [`diamond_dart`].
#[derive(Clone, Debug, PartialEq)]
pub struct DiamondDart {
    /// Index of the dart's hole in its panel.
    pub hole: usize,
    /// The upper sides stitched together, then the lower sides.
    pub stitches: [StitchRule; 2],
}

/// Cut a diamond dart into a panel: a closed loop through the top and bottom tips
/// (`length` apart, about `center`, vertical in the panel's frame) and the two side
/// points (`width` apart), written as a [`HoleKind::Dart`] whose upper sides are
/// stitched together and whose lower sides are stitched together (added to the
/// panel's stitches, like an edge dart's).
///
/// ```
/// use garmentcode::inner::diamond_dart;
/// use garmentcode::{Arena, EdgePlace, EdgeSeq, HoleKind, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 60.0), Vec2::new(30.0, 60.0), Vec2::new(30.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let front = a.panel_with_edges("front", outline);
/// let dart = diamond_dart(&mut a, &front, "waist_dart", Vec2::new(10.0, 30.0), 3.0, 24.0)?;
/// let pattern = a.assemble_panels(&[front], "dress")?;
/// let hole = &pattern.panels[0].holes[dart.hole];
/// assert_eq!((hole.name.as_str(), hole.kind, hole.edges.len()), ("waist_dart", HoleKind::Dart, 4));
/// // Two stitches, each between two sides of the dart.
/// assert_eq!(pattern.inner_stitches.len(), 2);
/// assert!(pattern.inner_stitches.iter().all(|s| s.sides.iter().all(|d| d.place == EdgePlace::Hole(0))));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn diamond_dart<P: PanelPart>(a: &mut Arena, panel: &P, name: &str, center: Vec2, width: f64, length: f64) -> Result<DiamondDart> {
    positive("a diamond dart's width", width)?;
    positive("a diamond dart's length", length)?;
    let panel = panel.panel_id();
    let (w, l) = (width / 2.0, length / 2.0);
    // Top, one side, bottom, the other side: sides 0 and 3 meet at the top, 1 and 2 at
    // the bottom, each pair running in opposite directions as a seam's sides do.
    let points = [center + Vec2::new(0.0, l), center + Vec2::new(w, 0.0), center - Vec2::new(0.0, l), center - Vec2::new(w, 0.0)];
    let edges = EdgeSeq::from_points(a, &points, true)?;
    let hole = panel.add_hole(a, name, HoleKind::Dart, edges.clone())?;
    let stitch = |a: &mut Arena, i: usize, j: usize| -> Result<StitchRule> {
        let (s, t) = (a.interface(panel, edges[i]), a.interface(panel, edges[j]));
        let rule = StitchRule::new(a, s, t)?;
        panel.add_stitch(a, rule);
        Ok(rule)
    };
    let stitches = [stitch(a, 0, 3)?, stitch(a, 1, 2)?];
    Ok(DiamondDart { hole, stitches })
}

/// Cut a slit out of a panel: a narrow opening `width` wide from `from` to `to`
/// (a [`HoleKind::Cut`] of four straight edges). Returns the hole's index.
///
/// ```
/// use garmentcode::inner::slit;
/// use garmentcode::{Arena, EdgeSeq, HoleKind, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 40.0), Vec2::new(30.0, 40.0), Vec2::new(30.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let front = a.panel_with_edges("front", outline);
/// slit(&mut a, &front, "welt", Vec2::new(10.0, 20.0), Vec2::new(22.0, 20.0), 1.0)?;
/// let pattern = a.assemble_panels(&[front], "shirt")?;
/// assert_eq!(pattern.panels[0].holes[0].kind, HoleKind::Cut);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn slit<P: PanelPart>(a: &mut Arena, panel: &P, name: &str, from: Vec2, to: Vec2, width: f64) -> Result<usize> {
    positive("a slit's width", width)?;
    positive("a slit's length", (to - from).length())?;
    let along = (to - from).normalize();
    let side = Vec2::new(-along.y, along.x) * (width / 2.0);
    let points = [from + side, from - side, to - side, to + side];
    let edges = EdgeSeq::from_points(a, &points, true)?;
    panel.panel_id().add_hole(a, name, HoleKind::Cut, edges)
}

/// Cut a keyhole out of a panel: a round opening of `radius` about `center` with a
/// slit `width` wide and `slit_length` long below it (in the panel's frame): a
/// [`HoleKind::Cut`] of three straight edges and one arc. Returns the hole's index.
///
/// ```
/// use garmentcode::inner::keyhole;
/// use garmentcode::{Arena, EdgeSeq, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 40.0), Vec2::new(30.0, 40.0), Vec2::new(30.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let back = a.panel_with_edges("back", outline);
/// keyhole(&mut a, &back, "keyhole", Vec2::new(15.0, 30.0), 1.5, 6.0, 0.6)?;
/// assert_eq!(a.assemble_panels(&[back], "top")?.panels[0].holes[0].edges.len(), 4);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn keyhole<P: PanelPart>(
    a: &mut Arena,
    panel: &P,
    name: &str,
    center: Vec2,
    radius: f64,
    slit_length: f64,
    width: f64,
) -> Result<usize> {
    positive("a keyhole's radius", radius)?;
    positive("a keyhole's slit length", slit_length)?;
    positive("a keyhole's slit width", width)?;
    if width >= 2.0 * radius {
        return Err(Error::Design(format!("a keyhole's slit ({width} cm) must be narrower than its round opening ({} cm)", 2.0 * radius)));
    }
    let w = width / 2.0;
    let meet = center.y - (radius * radius - w * w).sqrt();
    let bottom = center.y - radius - slit_length;
    let points =
        [Vec2::new(center.x - w, meet), Vec2::new(center.x - w, bottom), Vec2::new(center.x + w, bottom), Vec2::new(center.x + w, meet)];
    let mut edges = EdgeSeq::from_points(a, &points, false)?;
    let (last, first) = (a.end(edges.last_edge()), a.start(edges[0]));
    // Around the top of the circle, from the slit's right side back to its left.
    let cy = crate::arc::cy_from_radius(points[3], points[0], radius, true, true);
    edges.push(a.edge(last, first, Curve::Arc { cy })?);
    panel.panel_id().add_hole(a, name, HoleKind::Cut, edges)
}

/// An inner line made by [`fold_line`] or [`place_on`].
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// Index of the line in its panel.
    pub index: usize,
    /// The line's edges (interfaces may be made over them).
    pub edges: EdgeSeq,
}

/// Mark a fold line on a panel, straight from `from` to `to` (points on or inside
/// the outline, its middle inside): the panel is folded along it by `angle` degrees
/// (0 to 180; see [`LineKind::Fold`]). A one-piece sleeve or a double cuff is one
/// panel with a fold line.
///
/// ```
/// use garmentcode::inner::fold_line;
/// use garmentcode::{Arena, EdgeSeq, LineKind, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 12.0), Vec2::new(25.0, 12.0), Vec2::new(25.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let cuff = a.panel_with_edges("cuff", outline);
/// fold_line(&mut a, &cuff, "fold", Vec2::new(0.0, 6.0), Vec2::new(25.0, 6.0), 180.0)?;
/// let pattern = a.assemble_panels(&[cuff], "cuff")?;
/// assert_eq!(pattern.panels[0].lines[0].kind, LineKind::Fold { angle: 180.0 });
/// assert_eq!(pattern.panels[0].lines[0].vertices, [[0.0, 6.0], [25.0, 6.0]]);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn fold_line<P: PanelPart>(a: &mut Arena, panel: &P, name: &str, from: Vec2, to: Vec2, angle: f64) -> Result<Line> {
    if !(0.0..=180.0).contains(&angle) {
        return Err(Error::Design(format!("the fold '{name}' turns by {angle}°: a fold's angle is 0 to 180 degrees")));
    }
    let edges = EdgeSeq::from(a.line(from, to)?);
    let index = panel.panel_id().add_line(a, name, LineKind::Fold { angle }, edges.clone())?;
    Ok(Line { index, edges })
}

/// Make two panels sewn along a straight edge each one panel folded there (a
/// one-piece sleeve from a front and a back sleeve panel): `second`'s outline is
/// laid beside `first`'s across `first_edge` (its `second_edge` onto `first_edge`,
/// their ends paired as a seam pairs them, start to end; mirrored when the two
/// outlines turn opposite ways) and joined to it, and a fold line `name` turning by
/// `angle` degrees replaces the two edges. `second`'s holes, lines, inner stitches and
/// the interfaces over its edges move to `first`; `second` is left without edges, and
/// the caller drops it from its component with any stitch between the two edges.
///
/// In 3D the joined panel lies between where the two were: the fold midway between
/// the two edges, `first`'s part turned about it by `(180 − angle) / 2` degrees
/// outward (along its normal), so that the fold opens the two parts symmetrically.
/// Edges keep their directions, so every stitch pairs its edges as before. The
/// placement is final (join panels last): its local origin is moved to the outline's
/// first vertex, and its rotation is stored as readers of the file take it (the
/// reference writes Euler angles in one order and reads them in the other).
///
/// ```
/// use garmentcode::inner::join_at_fold;
/// use garmentcode::{Arena, EdgeSeq, LineKind, Vec2};
///
/// let mut a = Arena::new();
/// // Two sleeve halves below their tops (edge 3 of the front, 0 of the back), their
/// // outlines turning opposite ways as a front and back panel's do.
/// let front = EdgeSeq::from_points(&mut a, &[Vec2::ZERO, Vec2::new(0.0, -20.0), Vec2::new(40.0, -20.0), Vec2::new(40.0, 0.0)], true)?;
/// let back = EdgeSeq::from_points(&mut a, &[Vec2::ZERO, Vec2::new(40.0, 0.0), Vec2::new(40.0, -22.0), Vec2::new(0.0, -22.0)], true)?;
/// let (f, b) = (a.panel_with_edges("front", front.clone()), a.panel_with_edges("back", back.clone()));
/// let fold = join_at_fold(&mut a, &f, front[3], &b, back[0], "fold", 90.0)?;
/// let pattern = a.assemble_panels(&[f], "sleeve")?;
/// let sleeve = &pattern.panels[0];
/// assert_eq!((sleeve.edges.len(), sleeve.lines[fold.index].kind), (6, LineKind::Fold { angle: 90.0 }));
/// // The back part lies above the fold, mirrored: 20 + 22 cm high.
/// let ys: Vec<f64> = sleeve.vertices.iter().map(|v| v[1]).collect();
/// assert_eq!(ys.iter().cloned().fold(f64::MIN, f64::max) - ys.iter().cloned().fold(f64::MAX, f64::min), 42.0);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn join_at_fold<P: PanelPart, Q: PanelPart>(
    a: &mut Arena,
    first: &P,
    first_edge: EdgeId,
    second: &Q,
    second_edge: EdgeId,
    name: &str,
    angle: f64,
) -> Result<Line> {
    let (first, second) = (first.panel_id(), second.panel_id());
    let refuse = |a: &Arena, why: &str| Error::Design(format!("joining '{}' to '{}' at a fold: {why}", second.name(a), first.name(a)));
    if first == second {
        return Err(refuse(a, "a panel cannot be joined to itself"));
    }
    if !(0.0..=180.0).contains(&angle) {
        return Err(refuse(a, &format!("the fold turns by {angle}°: a fold's angle is 0 to 180 degrees")));
    }
    let (Some(i), Some(j)) = (first.edges(a).index_of(first_edge), second.edges(a).index_of(second_edge)) else {
        return Err(refuse(a, "each edge must be on its panel's outline"));
    };
    if a.curve(first_edge) != Curve::Line || a.curve(second_edge) != Curve::Line {
        return Err(refuse(a, "a fold is straight: both edges must be straight"));
    }
    let (lf, lb) = (a.edge_length(first_edge), a.edge_length(second_edge));
    if (lf - lb).abs() > 1e-6 * lf.max(1.0) {
        return Err(refuse(a, &format!("the edges are {lf:.4} and {lb:.4} cm long: they must be as long")));
    }
    let (s_f, e_f) = (a.pos(a.start(first_edge)), a.pos(a.end(first_edge)));
    let (s_b, e_b) = (a.pos(a.start(second_edge)), a.pos(a.end(second_edge)));
    let (w_s, w_e) = (first.point_to_3d(a, s_f), first.point_to_3d(a, e_f));
    let (w_es, w_ss) = (second.point_to_3d(a, e_b), second.point_to_3d(a, s_b));
    // `first`'s part lies left of its edge when its outline turns counter-clockwise.
    let ccw = first.signed_area(a) >= 0.0;
    let left = Vec2::new(s_f.y - e_f.y, e_f.x - s_f.x);
    let inward = first.point_to_3d(a, s_f + if ccw { left } else { -left }) - w_s;
    let normal = first.norm(a);
    // The outlines, each opened at its edge: from the edge's end round to its start.
    let open = |seq: &EdgeSeq, k: usize| EdgeSeq((1..seq.len()).map(|d| seq[(k + d) % seq.len()]).collect());
    let (f_chain, b_chain) = (open(first.edges(a), i), open(second.edges(a), j));
    // The map taking `second`'s edge onto `first`'s (s_b to e_f, e_b to s_f), a
    // mirror when the outlines turn opposite ways, so that the joined outline turns
    // one way and `second`'s part lies across the fold.
    let mirror = ccw != (second.signed_area(a) >= 0.0);
    let (u_b, u_f) = ((e_b - s_b).normalize(), (s_f - e_f).normalize());
    let map = |p: Vec2| {
        let d = p - s_b;
        let d = if mirror { 2.0 * d.dot(u_b) * u_b - d } else { d };
        // Rotate u_b onto u_f.
        let (c, s) = (u_b.dot(u_f), u_b.perp_dot(u_f));
        e_f + Vec2::new(c * d.x - s * d.y, s * d.x + c * d.y)
    };
    let moved: Vec<EdgeId> = b_chain.iter().copied().chain(second.inner_edges(a).flat_map(|s| s.iter().copied())).collect();
    let mut verts: Vec<_> = moved.iter().flat_map(|e| [a.start(*e), a.end(*e)]).collect();
    verts.sort();
    verts.dedup();
    for v in verts {
        let p = map(a.pos(v));
        a.set_pos(v, p);
    }
    if mirror {
        moved.iter().for_each(|e| a.reflect_edge_features(*e));
    }
    // Join: the second chain runs from s_f round to e_f, over `first`'s vertices there.
    let (vs, ve) = (a.start(first_edge), a.end(first_edge));
    a.set_start(b_chain[0], vs);
    a.set_end(b_chain.last_edge(), ve);
    let mut joined = f_chain;
    joined.extend(b_chain.iter().copied());
    // Everything of `second` moves to `first`.
    a.pd_mut(second).edges = EdgeSeq::new();
    let (holes, lines) = (std::mem::take(&mut a.pd_mut(second).holes), std::mem::take(&mut a.pd_mut(second).lines));
    let (stitches, interfaces) = (std::mem::take(&mut a.pd_mut(second).stitches), std::mem::take(&mut a.pd_mut(second).interfaces));
    for d in a.interfaces.iter_mut() {
        d.panels.iter_mut().filter(|p| **p == second).for_each(|p| *p = first);
    }
    let d = a.pd_mut(first);
    d.edges = joined;
    d.holes.extend(holes);
    d.lines.extend(lines);
    d.stitches.extend(stitches);
    d.interfaces.extend(interfaces);
    // The fold, with `second`'s part to its right (the part a fold turns).
    let (from, to) = if ccw { (s_f, e_f) } else { (e_f, s_f) };
    let line = fold_line(a, &first, name, from, to, angle)?;
    // In 3D: turned about the fold, outward, and moved midway between the two edges.
    let axis = (w_e - w_s).normalize();
    let side = if axis.cross(inward).dot(normal) >= 0.0 { 1.0 } else { -1.0 };
    let turn = Rotation::from_rotvec(axis * (side * (180.0 - angle) / 2.0).to_radians());
    let shift = ((w_s + w_es) / 2.0 + (w_e + w_ss) / 2.0) / 2.0 - (w_s + w_e) / 2.0;
    let d = a.pd(first);
    let rotation = turn.compose(&d.rotation);
    let translation = turn.apply(d.translation - w_s) + w_s + shift;
    // The local origin at the outline's first vertex, exactly, so that assembling
    // (which moves it there, truncated) leaves the placement as it is.
    let origin = a.pos(a.start(first.edges(a)[0]));
    let mut verts = first.edges(a).verts(a);
    verts.extend(first.inner_edges(a).flat_map(|s| s.verts(a)));
    verts.sort();
    verts.dedup();
    for v in verts {
        let p = a.pos(v) - origin;
        a.set_pos(v, p);
    }
    // Turned about more than one axis: readers of the file (the box mesh, the
    // reference's simulator) take the written angles as Rz·Ry·Rx where the writer
    // writes Rx·Ry·Rz (a reference quirk, kept for parity), so the rotation is stored
    // as the one whose written angles readers take for this turn.
    let m = rotation.matrix();
    let zyx = [m.y_axis.z.atan2(m.z_axis.z), (-m.x_axis.z).clamp(-1.0, 1.0).asin(), m.x_axis.y.atan2(m.x_axis.x)];
    let d = a.pd_mut(first);
    d.translation = rotation.apply(Vec3::new(origin.x, origin.y, 0.0)) + translation;
    d.rotation = Rotation::from_euler_xyz(zyx);
    Ok(line)
}

/// A piece sewn on the face of a panel, made by [`place_on`].
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// The placement line on the target panel.
    pub line: Line,
    /// The piece's edges stitched onto the line.
    pub stitch: StitchRule,
}

/// Sew a piece (a patch pocket, a flounce) on the face of a panel: the piece is
/// placed on `target`'s outer side, the centre of its bounding box at `at` in the
/// target's frame and turned by `angle` degrees in the target's plane; its edges
/// `sewn` (an interface of the piece: a pocket's sides and bottom) are copied onto
/// the target as a [`LineKind::Placement`] line and stitched onto it (the line's
/// edges run as the piece's edges do).
///
/// ```
/// use garmentcode::inner::place_on;
/// use garmentcode::{Arena, EdgePlace, EdgeSeq, LineKind, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 60.0), Vec2::new(40.0, 60.0), Vec2::new(40.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let front = a.panel_with_edges("front", outline);
/// let square = [Vec2::ZERO, Vec2::new(0.0, 14.0), Vec2::new(12.0, 14.0), Vec2::new(12.0, 0.0)];
/// let pocket_edges = EdgeSeq::from_points(&mut a, &square, true)?;
/// let pocket = a.panel_with_edges("pocket", pocket_edges.clone());
/// // Sides and bottom (all but the top, edge 1).
/// let sewn = a.interface(pocket, EdgeSeq::from(vec![pocket_edges[2], pocket_edges[3], pocket_edges[0]]));
/// let placed = place_on(&mut a, &pocket, sewn, &front, Vec2::new(28.0, 40.0), 10.0)?;
/// assert_eq!(placed.line.edges.len(), 3);
/// let pattern = a.assemble_panels(&[front, pocket], "shirt")?;
/// assert_eq!(pattern.panel("front").unwrap().lines[0].kind, LineKind::Placement);
/// assert_eq!(pattern.inner_stitches.len(), 3);
/// assert_eq!(pattern.inner_stitches[0].sides[1].place, EdgePlace::Line(0));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn place_on<P: PanelPart, Q: PanelPart>(
    a: &mut Arena,
    piece: &P,
    sewn: crate::InterfaceId,
    target: &Q,
    at: Vec2,
    angle: f64,
) -> Result<Placement> {
    const GAP: f64 = 0.3;
    let (piece, target) = (piece.panel_id(), target.panel_id());
    if !angle.is_finite() {
        return Err(Error::Design(format!("the angle of '{}' on '{}' must be a number of degrees", piece.name(a), target.name(a))));
    }
    let (lo, hi) = piece.bbox(a);
    let origin = (lo + hi) / 2.0;
    let turn = Rotation::from_euler_xyz_degrees([0.0, 0.0, angle]);
    let rotation = target.rotation(a).compose(&turn);
    let world = target.point_to_3d(a, at) + GAP * target.norm(a);
    let r_origin = rotation.apply(Vec3::new(origin.x, origin.y, 0.0));
    piece.rotate_to(a, rotation);
    piece.translate_to(a, world - r_origin);
    // The line: the sewn edges as they now lie, in the target's frame (in the
    // interface's order; as a chain, in the opposite order when the placement turned
    // the piece's loop round).
    let sewn_copy = sewn.edges(a).clone().copy(a);
    let (s, c) = angle.to_radians().sin_cos();
    let mut verts: Vec<_> = sewn_copy.iter().flat_map(|e| [a.start(*e), a.end(*e)]).collect();
    verts.sort();
    verts.dedup();
    for v in verts {
        let p = a.pos(v) - origin;
        a.set_pos(v, at + Vec2::new(c * p.x - s * p.y, s * p.x + c * p.y));
    }
    let mut edges = sewn_copy.clone();
    if edges.len() > 1 && !edges.is_chained(a) {
        edges.0.reverse();
    }
    let name = format!("{}_placement", piece.name(a));
    target.check_inside(a, &name, &edges.linearized_positions(a))?;
    let index = target.add_line(a, &name, LineKind::Placement, edges.clone())?;
    // The piece lies on the panel's face, its sewn edges running along the line in the
    // same direction: the seam pairs them as they are (`right_wrong`), not reversed as
    // between two panels facing each other.
    let line = a.interface(target, sewn_copy).set_right_wrong(a, true);
    let stitch = StitchRule::new(a, sewn, line)?;
    target.add_stitch(a, stitch);
    Ok(Placement { line: Line { index, edges }, stitch })
}

/// Which way a knife pleat's fold is laid, along the pleated edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PleatDirection {
    /// Toward the edge's end.
    Forward,
    /// Toward the edge's start.
    Backward,
}

/// Knife or box pleats (see [`pleats`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PleatKind {
    /// One fold per pleat, all laid the same way; takes twice its depth of edge.
    Knife(PleatDirection),
    /// A box pleat: two folds per pleat laid toward each other; takes four times
    /// its depth.
    BoxPleat,
}

/// Pleats laid into an edge by [`pleats`].
#[derive(Clone, Debug, PartialEq)]
pub struct Pleats {
    /// The parts of the edge left flat, in order: what is stitched to the next piece.
    pub flat: EdgeSeq,
    /// The pleats' inner segments stitched onto each other (one per fold).
    pub stitches: Vec<StitchRule>,
    /// The fold and placement lines, in order along the edge.
    pub lines: Vec<Line>,
}

/// Lay `count` pleats of `depth` into `edge` of a panel, evenly spaced, each marked
/// `length` into the panel by its fold (lines named `{name}_{pleat}_fold_{k}` and
/// `{name}_{pleat}_placement_{k}`) ([`LineKind::PleatFold`]) and placement
/// ([`LineKind::PleatPlacement`]) lines. The edge is split at the pleat points; each
/// pleat's two inner segments (`depth` long) are stitched onto each other, and every
/// interface over the edge keeps only the flat parts, so what it stitches is the
/// folded width: the edge's length less `2 × depth` per knife pleat and `4 × depth`
/// per box pleat.
///
/// ```
/// use garmentcode::inner::{PleatDirection, PleatKind, pleats};
/// use garmentcode::{Arena, EdgeSeq, LineKind, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 50.0), Vec2::new(60.0, 50.0), Vec2::new(60.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let skirt = a.panel_with_edges("skirt", edges.clone());
/// let waist = a.interface(skirt, edges[1]);
/// let laid = pleats(&mut a, &skirt, "waist", edges[1], 3, 4.0, PleatKind::Knife(PleatDirection::Forward), 15.0)?;
/// // 60 cm less three pleats of 2 × 4 cm.
/// assert!((waist.length(&a) - 36.0).abs() < 1e-9);
/// assert_eq!((laid.stitches.len(), laid.lines.len()), (3, 6));
/// let pattern = a.assemble_panels(&[skirt], "skirt")?;
/// assert_eq!(pattern.stitches.len(), 3);
/// assert_eq!(pattern.panels[0].lines[0].kind, LineKind::PleatFold);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn pleats<P: PanelPart>(
    a: &mut Arena,
    panel: &P,
    name: &str,
    edge: EdgeId,
    count: usize,
    depth: f64,
    kind: PleatKind,
    length: f64,
) -> Result<Pleats> {
    positive("a pleat's depth", depth)?;
    positive("a pleat's length", length)?;
    let panel = panel.panel_id();
    let total = a.edge_length(edge);
    let folds_per_pleat = if kind == PleatKind::BoxPleat { 2 } else { 1 };
    let width = 2.0 * depth * folds_per_pleat as f64;
    if count == 0 || count as f64 * width >= total {
        return Err(Error::Design(format!(
            "{count} pleat(s) of depth {depth} cm ({width} cm of edge each) do not fit an edge of {total:.2} cm in panel '{}': 1 to {} fit",
            panel.name(a),
            ((total / width).ceil() as usize).saturating_sub(1)
        )));
    }
    let seg = 2 * folds_per_pleat;
    // Break points along the edge (cm from its start): each pleat's segments.
    let mut cuts = Vec::with_capacity(count * (seg + 1));
    for i in 0..count {
        let start = (i as f64 + 0.5) * total / count as f64 - width / 2.0;
        cuts.extend((0..=seg).map(|k| start + k as f64 * depth));
    }
    let mut bounds = vec![0.0];
    bounds.extend(cuts.iter().copied());
    bounds.push(total);
    let fractions: Vec<f64> = bounds.windows(2).map(|w| (w[1] - w[0]) / total).collect();
    let pieces = a.subdivide(edge, &fractions, true)?;
    panel.substitute_edge(a, edge, &pieces)?;
    // Pieces: flat, then per pleat `seg` segments and a flat part.
    let flat: Vec<EdgeId> = pieces.iter().copied().step_by(seg + 1).collect();
    for i in panel.interfaces(a).to_vec() {
        if i.edges(a).index_of(edge).is_some() {
            i.substitute(a, edge, &flat, panel)?;
        }
    }
    let mut stitches = Vec::with_capacity(count * folds_per_pleat);
    for p in 0..count {
        for f in 0..folds_per_pleat {
            let first = p * (seg + 1) + 1 + 2 * f;
            let (s, t) = (a.interface(panel, pieces[first]), a.interface(panel, pieces[first + 1]));
            let rule = StitchRule::new(a, s, t)?;
            panel.add_stitch(a, rule);
            stitches.push(rule);
        }
    }
    // Fold and placement lines, perpendicular to the edge, into the panel.
    let geom = a.geom(edge).segment();
    let inward = if panel.signed_area(a) >= 0.0 { 1.0 } else { -1.0 };
    let mut lines = Vec::new();
    for p in 0..count {
        let at = |k: usize| cuts[p * (seg + 1) + k];
        let marks: Vec<(f64, LineKind)> = match kind {
            PleatKind::Knife(PleatDirection::Forward) => vec![(at(0), LineKind::PleatFold), (at(2), LineKind::PleatPlacement)],
            PleatKind::Knife(PleatDirection::Backward) => vec![(at(0), LineKind::PleatPlacement), (at(2), LineKind::PleatFold)],
            PleatKind::BoxPleat => vec![(at(0), LineKind::PleatFold), (at(2), LineKind::PleatPlacement), (at(4), LineKind::PleatFold)],
        };
        for (k, (s, kind)) in marks.into_iter().enumerate() {
            let t = geom.inverse_length(s).unwrap_or(0.5);
            let (point, tangent) = (geom.point(t), geom.derivative(t).normalize());
            let into = inward * Vec2::new(-tangent.y, tangent.x);
            let tag = if kind == LineKind::PleatFold { "fold" } else { "placement" };
            let name = format!("{name}_{p}_{tag}_{k}");
            panel.check_inside(a, &name, &[point + length * into])?;
            let edges = EdgeSeq::from(a.line(point, point + length * into)?);
            let index = panel.add_line(a, &name, kind, edges.clone())?;
            lines.push(Line { index, edges });
        }
    }
    Ok(Pleats { flat: EdgeSeq(flat), stitches, lines })
}

/// A facing of a panel: a copy ([`Arena::copy_part`]) named `{name}_facing` on the
/// [`Layer::Facing`] layer, at the same place. Stitch it to the outer panel along the
/// edges they share (a cuff's or collar's outer edges) to make a double layer.
///
/// ```
/// use garmentcode::inner::facing;
/// use garmentcode::{Arena, EdgeSeq, Layer, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 8.0), Vec2::new(40.0, 8.0), Vec2::new(40.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let collar = a.panel_with_edges("collar", outline);
/// let inside = facing(&mut a, &collar);
/// assert_eq!((inside.name(&a), inside.layer(&a)), ("collar_facing", Layer::Facing));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn facing<P: PanelPart + Remap>(a: &mut Arena, part: &P) -> P {
    let copy = a.copy_part(part);
    let p = copy.panel_id();
    let name = format!("{}_facing", p.name(a));
    p.set_name(a, &name);
    p.set_layer(a, Layer::Facing);
    copy
}

impl Arena {
    /// Assemble loose panels (no component around them) into a pattern, with their
    /// own stitches: for tests and small examples.
    pub fn assemble_panels(&mut self, panels: &[PanelId], name: &str) -> Result<crate::Pattern> {
        let parts: Vec<&dyn crate::Part> = panels.iter().map(|p| p as &dyn crate::Part).collect();
        let group = Loose(parts);
        group.assemble(self, name)
    }
}

/// Loose panels as a component.
struct Loose<'a>(Vec<&'a dyn crate::Part>);

impl crate::Component for Loose<'_> {
    fn name(&self) -> String {
        "panels".into()
    }
    fn for_each_part(&self, f: &mut dyn FnMut(&dyn crate::Part)) {
        self.0.iter().for_each(|p| f(*p))
    }
    fn stitches(&self) -> Vec<StitchRule> {
        Vec::new()
    }
}

impl crate::Part for Loose<'_> {
    fn node(&self) -> crate::Node<'_> {
        crate::Node::Component(self)
    }
}
