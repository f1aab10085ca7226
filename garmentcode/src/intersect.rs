//! Intersections of lines and Bézier curves, and the reference's self-intersection
//! check of panel outlines.
//!
//! The routines in [`parity::svgpath`](crate::parity::svgpath) agree with the ones the reference calls (svgpathtools) bit
//! for bit, including the order of results and their tolerances, so verdicts near
//! tangencies and shared vertices are the reference's. Arcs are replaced by 11
//! straight pieces first, as the reference does.

use crate::arena::{Arena, PanelId};
use crate::bezier::Bezier;
use crate::edge::{Curve, Edge, Segment};
use crate::parity::svgpath::{IntersectError, P, Seg, try_has_self_intersection, try_intersect};
use crate::pattern::PanelSpec;

fn p(v: crate::math::Vec2) -> P {
    [v.x, v.y]
}

/// The segment of an explicit line or Bézier (an arc becomes its chord; callers
/// linearise arcs first).
pub fn to_seg(s: &Segment) -> Seg {
    match s {
        Segment::Line(a, b) => Seg::Line([p(*a), p(*b)]),
        Segment::Bezier(Bezier::Quadratic(q)) => Seg::Quad(q.map(p)),
        Segment::Bezier(Bezier::Cubic(c)) => Seg::Cubic(c.map(p)),
        Segment::Arc(a) => Seg::Line([p(a.start), p(a.end)]),
    }
}

/// Parameter pairs where two segments meet, as svgpathtools reports them.
pub fn intersect(a: &Seg, b: &Seg) -> Result<Vec<(f64, f64)>, IntersectError> {
    try_intersect(a, b)
}

/// The reference's panel check: any intersection of two outline segments other
/// than at a shared end point. Inputs svgpathtools would raise on count as
/// intersecting (a broken outline is not a good one).
pub fn has_self_intersection(segs: &[Seg]) -> bool {
    try_has_self_intersection(segs).unwrap_or(true)
}

fn edge_segments(e: &Edge, out: &mut Vec<Seg>) {
    match e.curve {
        Curve::Arc { .. } => {
            let mut pts = Vec::with_capacity(12);
            pts.push(e.start);
            e.linearize_into(10, &mut pts);
            pts.push(e.end);
            out.extend(pts.windows(2).map(|w| Seg::Line([p(w[0]), p(w[1])])));
        }
        _ => out.push(to_seg(&e.segment())),
    }
}

/// Outline segments of a panel for the self-intersection check.
pub fn panel_segments(a: &Arena, panel: PanelId) -> Vec<Seg> {
    let mut out = Vec::with_capacity(panel.edges(a).len() + 32);
    for &e in panel.edges(a).iter() {
        let g = a.geom(e);
        let from = out.len();
        edge_segments(&g, &mut out);
        if out.len() - from > 1 {
            // An arc's pieces: their inner ends, for the reference's refusal of
            // pieces whose ends coincide.
            let inner: Vec<crate::math::Vec2> =
                out[from + 1..].iter().map(|s| crate::math::Vec2::new(s.start()[0], s.start()[1])).collect();
            a.note_linearization(g.start, &inner, g.end);
        }
    }
    out
}

/// Outline segments of a written panel (same construction as [`panel_segments`]).
pub fn spec_segments(panel: &PanelSpec) -> Vec<Seg> {
    let mut out = Vec::new();
    for i in 0..panel.edges.len() {
        edge_segments(&panel.edge_geom(i), &mut out);
    }
    out
}
