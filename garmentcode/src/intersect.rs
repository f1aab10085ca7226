//! Intersections of lines and Bézier curves, and the reference's self-intersection
//! check of panel outlines.
//!
//! PROVISIONAL: generic subdivision-based intersections; to be replaced by the
//! faithful port of svgpathtools' routines.

use crate::arena::{Arena, PanelId};
use crate::bezier::Bezier;
use crate::edge::{Curve, Edge, Segment};
use crate::math::Vec2;
use crate::pattern::PanelSpec;

/// A segment of an outline for intersection tests.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Straight segment.
    Line([Vec2; 2]),
    /// Quadratic Bézier.
    Quad([Vec2; 3]),
    /// Cubic Bézier.
    Cubic([Vec2; 4]),
}

impl Seg {
    /// From an edge's explicit parametrisation (arcs are not supported here: callers
    /// linearise them first).
    pub fn from_segment(s: &Segment) -> Seg {
        match s {
            Segment::Line(a, b) => Seg::Line([*a, *b]),
            Segment::Bezier(Bezier::Quadratic(p)) => Seg::Quad(*p),
            Segment::Bezier(Bezier::Cubic(p)) => Seg::Cubic(*p),
            Segment::Arc(a) => Seg::Line([a.start, a.end]),
        }
    }

    fn point(&self, t: f64) -> Vec2 {
        match self {
            Seg::Line([a, b]) => *a + (*b - *a) * t,
            Seg::Quad(p) => Bezier::Quadratic(*p).point(t),
            Seg::Cubic(p) => Bezier::Cubic(*p).point(t),
        }
    }

    fn points(&self) -> &[Vec2] {
        match self {
            Seg::Line(p) => p,
            Seg::Quad(p) => p,
            Seg::Cubic(p) => p,
        }
    }
}

/// Parameter pairs `(t_a, t_b)` where `a` and `b` meet.
pub fn intersect(a: &Seg, b: &Seg) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    recurse(a, (0.0, 1.0), b, (0.0, 1.0), 0, &mut out);
    out
}

fn bbox(s: &Seg, r: (f64, f64)) -> (Vec2, Vec2) {
    let n = 8;
    let mut lo = Vec2::splat(f64::INFINITY);
    let mut hi = Vec2::splat(f64::NEG_INFINITY);
    for k in 0..=n {
        let p = s.point(r.0 + (r.1 - r.0) * k as f64 / n as f64);
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let pad = (hi - lo).length() * 0.05 + 1e-12;
    (lo - pad, hi + pad)
}

fn recurse(a: &Seg, ra: (f64, f64), b: &Seg, rb: (f64, f64), depth: u32, out: &mut Vec<(f64, f64)>) {
    if let (Seg::Line(p), Seg::Line(q)) = (a, b) {
        if let Some((t, u)) = line_line(p, q) {
            out.push((t, u));
        }
        return;
    }
    let (alo, ahi) = bbox(a, ra);
    let (blo, bhi) = bbox(b, rb);
    if alo.x > bhi.x || blo.x > ahi.x || alo.y > bhi.y || blo.y > ahi.y {
        return;
    }
    if depth > 40 || ((ahi - alo).length() < 1e-10 && (bhi - blo).length() < 1e-10) {
        let (t, u) = ((ra.0 + ra.1) / 2.0, (rb.0 + rb.1) / 2.0);
        if !out.iter().any(|(x, y)| (x - t).abs() < 1e-6 && (y - u).abs() < 1e-6) {
            out.push((t, u));
        }
        return;
    }
    let ma = (ra.0 + ra.1) / 2.0;
    let mb = (rb.0 + rb.1) / 2.0;
    for sa in [(ra.0, ma), (ma, ra.1)] {
        for sb in [(rb.0, mb), (mb, rb.1)] {
            recurse(a, sa, b, sb, depth + 1, out);
        }
    }
}

fn line_line(p: &[Vec2; 2], q: &[Vec2; 2]) -> Option<(f64, f64)> {
    let d1 = p[1] - p[0];
    let d2 = q[1] - q[0];
    let den = d1.x * d2.y - d1.y * d2.x;
    if den.abs() <= 1e-8 {
        return None;
    }
    let w = q[0] - p[0];
    let t = (w.x * d2.y - w.y * d2.x) / den;
    let u = (w.x * d1.y - w.y * d1.x) / den;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some((t, u))
}

/// The reference's check: any intersection of two outline segments other than at a
/// shared end point (parameters within 1e-4 of 0 and 1).
pub fn has_self_intersection(segs: &[Seg]) -> bool {
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            for (t1, t2) in intersect(&segs[i], &segs[j]) {
                let (lo, hi) = if t2 < t1 { (t2, t1) } else { (t1, t2) };
                if !(lo.abs() < 1e-4 && (hi - 1.0).abs() < 1e-4) {
                    return true;
                }
            }
        }
    }
    let _ = Seg::points;
    false
}

fn edge_segments(e: &Edge, out: &mut Vec<Seg>) {
    match e.curve {
        Curve::Arc { .. } => {
            let mut pts = vec![e.start];
            pts.extend(e.linearize(10));
            pts.push(e.end);
            for w in pts.windows(2) {
                out.push(Seg::Line([w[0], w[1]]));
            }
        }
        _ => out.push(Seg::from_segment(&e.segment())),
    }
}

/// Outline segments of a panel for the self-intersection check.
pub fn panel_segments(a: &Arena, p: PanelId) -> Vec<Seg> {
    let mut out = Vec::new();
    for &e in p.edges(a).iter() {
        edge_segments(&a.geom(e), &mut out);
    }
    out
}

/// Outline segments of a written panel (same construction as [`panel_segments`]).
pub fn spec_segments(p: &PanelSpec) -> Vec<Seg> {
    let mut out = Vec::new();
    for i in 0..p.edges.len() {
        edge_segments(&p.edge_geom(i), &mut out);
    }
    out
}
