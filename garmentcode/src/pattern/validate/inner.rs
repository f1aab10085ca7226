//! The structural checks of a panel's holes and inner lines (the format extension):
//! well-formed loops and chains, holes inside the outline and apart from each other,
//! lines inside the panel, fold lines across it, names unique.

use super::ProblemKind;
use crate::math::Vec2;
use crate::pattern::extension::sample;
use crate::pattern::{EdgeSpec, LineKind, PanelSpec, arc_radius_too_small, edge_geometry};

/// Points per curved edge of the polygons the checks compare.
const STEPS: usize = 32;
/// How far (cm) a point may be from the outline and still count as on it (a fold
/// line's end), and how near a hole may come to the outline or another hole.
const TOLERANCE: f64 = 0.05;

/// Report the problems of `panel`'s holes and lines through `report`. `outline_ok`:
/// the outline is sound (the geometric checks need it).
pub(super) fn check_panel(panel: &PanelSpec, outline_ok: bool, report: &mut dyn FnMut(ProblemKind, String)) {
    let mut names: Vec<&str> = Vec::new();
    for name in panel.holes.iter().map(|h| &h.name).chain(panel.lines.iter().map(|l| &l.name)) {
        if names.contains(&name.as_str()) {
            report(ProblemKind::DuplicateName, format!("two holes or lines are named '{name}'"));
        }
        names.push(name);
    }
    for line in &panel.lines {
        let angle = match line.kind {
            LineKind::Fold { angle } => angle,
            _ => continue,
        };
        if !(0.0..=180.0).contains(&angle) {
            report(ProblemKind::FoldAngleOutOfRange, format!("fold line '{}': angle {angle}° is outside 0 to 180°", line.name));
        }
    }
    let holes_ok: Vec<bool> =
        panel.holes.iter().map(|h| well_formed(&format!("hole '{}'", h.name), &h.vertices, &h.edges, true, report)).collect();
    let lines_ok: Vec<bool> =
        panel.lines.iter().map(|l| well_formed(&format!("line '{}'", l.name), &l.vertices, &l.edges, false, report)).collect();
    if !outline_ok {
        return;
    }
    let outline = sample(&panel.vertices, &panel.edges, STEPS);
    let polygons: Vec<Option<Vec<Vec2>>> =
        panel.holes.iter().zip(&holes_ok).map(|(h, ok)| ok.then(|| sample(&h.vertices, &h.edges, STEPS))).collect();
    for (i, hole) in panel.holes.iter().enumerate() {
        let Some(poly) = &polygons[i] else { continue };
        let what = format!("hole '{}'", hole.name);
        let inside = poly.iter().filter(|q| contains(&outline, **q)).count();
        if inside == 0 {
            report(ProblemKind::HoleOutsidePanel, format!("{what} lies outside the outline"));
            continue;
        }
        if inside < poly.len() || loops_meet(poly, &outline) {
            report(ProblemKind::HoleCrossing, format!("{what} crosses or touches the outline"));
            continue;
        }
        if self_crossing(poly) {
            report(ProblemKind::HoleCrossing, format!("{what} crosses itself"));
            continue;
        }
        for (j, other) in polygons.iter().enumerate().take(i) {
            let Some(other) = other else { continue };
            if loops_meet(poly, other) || contains(other, poly[0]) || contains(poly, other[0]) {
                report(ProblemKind::HoleCrossing, format!("{what} crosses, touches or holds hole '{}'", panel.holes[j].name));
            }
        }
    }
    for (line, _) in panel.lines.iter().zip(&lines_ok).filter(|(_, ok)| **ok) {
        let what = format!("line '{}'", line.name);
        let pts = line.polyline(STEPS);
        let near = |q: Vec2| distance_to_loop(&outline, q) <= TOLERANCE;
        let midpoints = pts.windows(2).map(|w| (w[0] + w[1]) * 0.5);
        let leaves = pts.iter().copied().chain(midpoints).any(|q| !contains(&outline, q) && !near(q))
            || pts.windows(2).any(|w| crosses_loop(w[0], w[1], &outline));
        if leaves {
            report(ProblemKind::LineOutsidePanel, format!("{what} leaves the panel"));
        } else if matches!(line.kind, LineKind::Fold { .. }) && !(near(pts[0]) && near(pts[pts.len() - 1])) {
            report(ProblemKind::FoldNotAcross, format!("fold {what} does not cross the panel: both its ends must lie on the outline"));
        }
    }
}

/// Whether a hole's loop (`closed`) or a line's chain is well formed: at least one
/// edge (two for a loop), valid vertex indices, each edge starting where the one before
/// ends, no edge of zero length. Reports what is not.
fn well_formed(what: &str, vertices: &[[f64; 2]], edges: &[EdgeSpec], closed: bool, report: &mut dyn FnMut(ProblemKind, String)) -> bool {
    let least = if closed { 2 } else { 1 };
    if edges.len() < least {
        report(ProblemKind::EmptyPanel, format!("{what} has {} edges (at least {least})", edges.len()));
        return false;
    }
    for (i, e) in edges.iter().enumerate() {
        if let Some(v) = e.endpoints.iter().find(|v| **v >= vertices.len()) {
            report(ProblemKind::VertexOutOfRange, format!("{what} edge {i}: vertex {v} does not exist (it has {})", vertices.len()));
            return false;
        }
    }
    let n = edges.len();
    for (i, e) in edges.iter().enumerate() {
        if (closed || i + 1 < n) && e.endpoints[1] != edges[(i + 1) % n].endpoints[0] {
            report(
                ProblemKind::OpenLoop,
                format!(
                    "{what} edge {i} ends at vertex {} but edge {} starts at vertex {}",
                    e.endpoints[1],
                    (i + 1) % n,
                    edges[(i + 1) % n].endpoints[0]
                ),
            );
            return false;
        }
        let g = edge_geometry(vertices, e);
        if (g.start - g.end).length() < 1e-4 {
            report(ProblemKind::DegenerateEdge, format!("{what} edge {i}: start and end coincide"));
            return false;
        }
        if let Some(message) = arc_radius_too_small(vertices, e) {
            report(ProblemKind::ArcRadiusTooSmall, format!("{what} edge {i}: {message}"));
            return false;
        }
    }
    true
}

/// Even-odd test of `q` against the closed polygon `poly`.
fn contains(poly: &[Vec2], q: Vec2) -> bool {
    let mut inside = false;
    for (k, a) in poly.iter().enumerate() {
        let b = poly[(k + 1) % poly.len()];
        if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

fn distance_to_segment(a: Vec2, b: Vec2, q: Vec2) -> f64 {
    let d = b - a;
    let t = if d.length_squared() > 0.0 { ((q - a).dot(d) / d.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (a + d * t - q).length()
}

fn distance_to_loop(poly: &[Vec2], q: Vec2) -> f64 {
    (0..poly.len()).map(|k| distance_to_segment(poly[k], poly[(k + 1) % poly.len()], q)).fold(f64::INFINITY, f64::min)
}

/// Where segments `a0 a1` and `b0 b1` meet, as parameters along each, if they do (not
/// parallel).
fn meet(a0: Vec2, a1: Vec2, b0: Vec2, b1: Vec2) -> Option<(f64, f64)> {
    let (r, s) = (a1 - a0, b1 - b0);
    let den = r.perp_dot(s);
    if den.abs() < 1e-12 * r.length() * s.length() {
        return None;
    }
    let t = (b0 - a0).perp_dot(s) / den;
    let u = (b0 - a0).perp_dot(r) / den;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some((t, u))
}

/// Whether two closed polygons come within [`TOLERANCE`] of each other (they cross
/// or touch).
fn loops_meet(a: &[Vec2], b: &[Vec2]) -> bool {
    let seg = |p: &[Vec2], k: usize| (p[k], p[(k + 1) % p.len()]);
    (0..a.len()).any(|i| {
        let (a0, a1) = seg(a, i);
        (0..b.len()).any(|j| {
            let (b0, b1) = seg(b, j);
            meet(a0, a1, b0, b1).is_some() || distance_to_segment(b0, b1, a0) <= TOLERANCE
        })
    })
}

/// Whether two non-adjacent sides of a closed polygon cross.
fn self_crossing(p: &[Vec2]) -> bool {
    let n = p.len();
    (0..n).any(|i| ((i + 2)..n).filter(|j| (j + 1) % n != i).any(|j| meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]).is_some()))
}

/// Whether segment `a0 a1` of a line crosses the outline away from its own ends
/// (an end on the outline is allowed: a fold line's, a pleat line's from the waist).
pub(crate) fn crosses_loop(a0: Vec2, a1: Vec2, outline: &[Vec2]) -> bool {
    let len = (a1 - a0).length();
    if len == 0.0 {
        return false;
    }
    let margin = TOLERANCE / len;
    (0..outline.len()).any(|k| {
        let (b0, b1) = (outline[k], outline[(k + 1) % outline.len()]);
        matches!(meet(a0, a1, b0, b1), Some((t, _)) if t > margin && t < 1.0 - margin)
    })
}
