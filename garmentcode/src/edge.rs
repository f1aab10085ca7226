//! Edges as values: two end points and a curvature stored relative to the chord.
//!
//! Storing control points in the edge's own frame (x along `start → end`, y along its
//! left perpendicular, both in chord lengths) lets a curve follow its end points when
//! they move: this is the representation of the reference and of its file format.
//! Topology (which edges share a vertex) lives in [`crate::arena`]; this module is pure
//! geometry.

use crate::arc::{self, SvgArc};
use crate::bezier::Bezier;
use crate::math::{Vec2, abs_to_rel, cabs, interior_params, norm, rel_to_abs, rotate2d};

/// Shape of an edge between its end points, in the edge's relative frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Curve {
    /// Straight segment.
    Line,
    /// Circular arc whose midpoint sits at relative height `cy` above the chord
    /// midpoint (positive: left of `start → end`).
    Arc {
        /// Relative height of the arc midpoint.
        cy: f64,
    },
    /// Quadratic Bézier with one relative control point.
    Quadratic(Vec2),
    /// Cubic Bézier with two relative control points (in curve order).
    Cubic(Vec2, Vec2),
}

impl Curve {
    /// The same shape traversed from the end to the start.
    pub fn reversed(self) -> Curve {
        let flip = |p: Vec2| Vec2::new(1.0 - p.x, -p.y);
        match self {
            Curve::Line => Curve::Line,
            Curve::Arc { cy } => Curve::Arc { cy: -cy },
            Curve::Quadratic(c) => Curve::Quadratic(flip(c)),
            Curve::Cubic(c1, c2) => Curve::Cubic(flip(c2), flip(c1)),
        }
    }

    /// The shape mirrored across its chord.
    pub fn reflected(self) -> Curve {
        let flip = |p: Vec2| Vec2::new(p.x, -p.y);
        match self {
            Curve::Line => Curve::Line,
            Curve::Arc { cy } => Curve::Arc { cy: -cy },
            Curve::Quadratic(c) => Curve::Quadratic(flip(c)),
            Curve::Cubic(c1, c2) => Curve::Cubic(flip(c1), flip(c2)),
        }
    }

    /// One-letter type code: `L`, `A`, `Q` or `C`.
    pub fn code(self) -> char {
        match self {
            Curve::Line => 'L',
            Curve::Arc { .. } => 'A',
            Curve::Quadratic(_) => 'Q',
            Curve::Cubic(..) => 'C',
        }
    }
}

/// An edge's geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// Start vertex.
    pub start: Vec2,
    /// End vertex.
    pub end: Vec2,
    /// Shape between the two.
    pub curve: Curve,
}

/// Explicit parametrisation of an edge for evaluation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    /// Straight segment `[start, end]`.
    Line(Vec2, Vec2),
    /// Circular arc.
    Arc(SvgArc),
    /// Bézier curve in absolute coordinates.
    Bezier(Bezier),
}

impl Segment {
    /// Point at parameter `t`.
    pub fn point(&self, t: f64) -> Vec2 {
        match self {
            Segment::Line(s, e) => *s + (*e - *s) * t,
            Segment::Arc(a) => a.point(t),
            Segment::Bezier(b) => b.point(t),
        }
    }

    /// First derivative at `t`.
    pub fn derivative(&self, t: f64) -> Vec2 {
        match self {
            Segment::Line(s, e) => *e - *s,
            Segment::Arc(a) => a.derivative(t),
            Segment::Bezier(b) => b.derivative(t),
        }
    }

    /// Length.
    pub fn length(&self) -> f64 {
        match self {
            Segment::Line(s, e) => cabs(*e - *s),
            Segment::Arc(a) => a.length(),
            Segment::Bezier(b) => b.length(),
        }
    }

    /// Parameter at arc length `s` from the start, `None` outside `[0, length]`.
    pub fn inverse_length(&self, s: f64) -> Option<f64> {
        match self {
            Segment::Line(..) | Segment::Arc(_) => {
                let len = self.length();
                if !(0.0..=len).contains(&s) {
                    None
                } else {
                    Some(s / len)
                }
            }
            Segment::Bezier(b) => b.inverse_length(s),
        }
    }
}

impl Edge {
    /// A straight edge.
    pub fn line(start: Vec2, end: Vec2) -> Edge {
        Edge { start, end, curve: Curve::Line }
    }

    /// Chord vector `end − start`.
    pub fn chord(&self) -> Vec2 {
        self.end - self.start
    }

    /// Length of the chord.
    pub fn chord_length(&self) -> f64 {
        norm(self.end - self.start)
    }

    /// Relative point to absolute coordinates in this edge's frame.
    pub fn to_abs(&self, rel: Vec2) -> Vec2 {
        rel_to_abs(self.start, self.end, rel)
    }

    /// Absolute point to this edge's relative frame.
    pub fn to_rel(&self, p: Vec2) -> Vec2 {
        abs_to_rel(self.start, self.end, p)
    }

    /// Explicit parametrisation for evaluation.
    pub fn segment(&self) -> Segment {
        match self.curve {
            Curve::Line => Segment::Line(self.start, self.end),
            Curve::Arc { cy } => Segment::Arc(arc::svg_arc(self.start, self.end, cy)),
            Curve::Quadratic(c) => Segment::Bezier(Bezier::Quadratic([self.start, self.to_abs(c), self.end])),
            Curve::Cubic(c1, c2) => {
                Segment::Bezier(Bezier::Cubic([self.start, self.to_abs(c1), self.to_abs(c2), self.end]))
            }
        }
    }

    /// The Bézier curve in the edge's own frame, from (0,0) to (1,0).
    fn relative_bezier(&self) -> Option<Bezier> {
        let (o, x) = (Vec2::ZERO, Vec2::X);
        match self.curve {
            Curve::Quadratic(c) => Some(Bezier::Quadratic([o, c, x])),
            Curve::Cubic(c1, c2) => Some(Bezier::Cubic([o, c1, c2, x])),
            _ => None,
        }
    }

    /// Arc length.
    pub fn length(&self) -> f64 {
        match self.curve {
            Curve::Line => self.chord_length(),
            Curve::Arc { cy } => arc::rel_radius(cy) * self.chord_length() * arc::sweep_angle(cy),
            _ => self.segment().length(),
        }
    }

    /// Point at curve parameter `t`.
    pub fn point(&self, t: f64) -> Vec2 {
        self.segment().point(t)
    }

    /// Arc-length midpoint (the arc's midpoint for arcs, the chord midpoint for lines).
    pub fn midpoint(&self) -> Vec2 {
        match self.curve {
            Curve::Line => (self.start + self.end) / 2.0,
            Curve::Arc { cy } => arc::midpoint(self.start, self.end, cy),
            _ => {
                let seg = self.segment();
                let t = seg.inverse_length(seg.length() / 2.0).unwrap_or(0.5);
                seg.point(t)
            }
        }
    }

    /// Radius, large-arc flag and "right" flag of an arc edge.
    pub fn arc_radius_flags(&self) -> Option<(f64, bool, bool)> {
        match self.curve {
            Curve::Arc { cy } => Some((arc::rel_radius(cy) * self.chord_length(), arc::is_large(cy), cy < 0.0)),
            _ => None,
        }
    }

    /// Radius, swept angle (radians) and "right" flag of an arc edge.
    pub fn arc_radius_angle(&self) -> Option<(f64, f64, bool)> {
        match self.curve {
            Curve::Arc { cy } => Some((arc::rel_radius(cy) * self.chord_length(), arc::sweep_angle(cy), cy < 0.0)),
            _ => None,
        }
    }

    /// Absolute control points of a Bézier edge (empty for lines and arcs).
    pub fn abs_controls(&self) -> Vec<Vec2> {
        match self.curve {
            Curve::Quadratic(c) => vec![self.to_abs(c)],
            Curve::Cubic(c1, c2) => vec![self.to_abs(c1), self.to_abs(c2)],
            _ => Vec::new(),
        }
    }

    /// The edge traversed backwards.
    pub fn reversed(&self) -> Edge {
        Edge { start: self.end, end: self.start, curve: self.curve.reversed() }
    }

    /// Interior points of the default-or-given linearisation: `n` points at equal
    /// parameter steps for lines and arcs, at equal arc-length steps for Béziers.
    pub fn linearize(&self, n: usize) -> Vec<Vec2> {
        if n == 0 {
            return Vec::new();
        }
        match self.curve {
            Curve::Line | Curve::Arc { .. } => {
                let seg = self.segment();
                interior_params(n + 1).map(|t| seg.point(t)).collect()
            }
            _ => {
                let rel = self.relative_bezier().expect("Bézier edge");
                arc_length_params(self.curve, n, |ts| ts.iter().map(|&t| self.to_abs(rel.point(t))).collect())
            }
        }
    }

    /// Default number of interior linearisation points (0 for lines, 9 for curves).
    pub fn default_linearization(&self) -> usize {
        match self.curve {
            Curve::Line => 0,
            _ => 9,
        }
    }

    /// Split into pieces at cumulative parameter fractions (`by_length = false`) or
    /// arc-length fractions (`by_length = true`). Fractions are used as given (their
    /// sum must be 1, checked by the caller). Piece end points are computed on the
    /// curve; the caller re-links the first start and last end to the original
    /// vertices and the interior ones to shared new vertices.
    pub fn split(&self, fractions: &[f64], by_length: bool) -> Vec<Edge> {
        match self.curve {
            Curve::Line => {
                let d = self.chord();
                let mut out = Vec::with_capacity(fractions.len());
                let mut prev = self.start;
                for (i, f) in fractions.iter().enumerate() {
                    let next = if i + 1 == fractions.len() {
                        self.end
                    } else {
                        Vec2::new(prev.x + f.abs() * d.x, prev.y + f.abs() * d.y)
                    };
                    out.push(Edge::line(prev, next));
                    prev = next;
                }
                out
            }
            Curve::Arc { cy } => {
                let whole = arc::svg_arc(self.start, self.end, cy);
                let mut covered = 0.0;
                let mut out = Vec::with_capacity(fractions.len());
                for &f in fractions {
                    let piece = whole.crop(covered, covered + f);
                    covered += f;
                    let cy = arc::cy_from_radius(piece.start, piece.end, piece.radius, piece.large_arc, piece.sweep);
                    out.push(Edge { start: piece.start, end: piece.end, curve: Curve::Arc { cy } });
                }
                out
            }
            _ => {
                let Segment::Bezier(b) = self.segment() else { unreachable!() };
                let total = b.length();
                let mut covered = 0.0;
                let mut prev_t = 0.0;
                let mut out = Vec::with_capacity(fractions.len());
                for &f in fractions {
                    covered += f;
                    let piece = if by_length {
                        let next_t = if (covered - 1.0).abs() < 1e-15 {
                            1.0
                        } else {
                            b.inverse_length((total * covered).min(total)).unwrap_or(1.0)
                        };
                        let p = b.crop(prev_t, next_t);
                        prev_t = next_t;
                        p
                    } else {
                        b.crop(covered - f, covered.min(1.0))
                    };
                    out.push(Edge::from_bezier(&piece));
                }
                out
            }
        }
    }

    /// A Bézier edge from absolute control points (relative controls computed
    /// against its own chord).
    pub fn from_bezier(b: &Bezier) -> Edge {
        match *b {
            Bezier::Quadratic([s, c, e]) => Edge { start: s, end: e, curve: Curve::Quadratic(abs_to_rel(s, e, c)) },
            Bezier::Cubic([s, c1, c2, e]) => {
                Edge { start: s, end: e, curve: Curve::Cubic(abs_to_rel(s, e, c1), abs_to_rel(s, e, c2)) }
            }
        }
    }

    /// Rotate the end point about the start by `angle` radians.
    pub fn rotated(&self, angle: f64) -> Edge {
        Edge { end: self.start + rotate2d(self.end - self.start, angle), ..*self }
    }
}


/// Memo of Bézier arc-length parameters, per thread: the curve parameters of `n`
/// points at equal arc-length steps depend only on the relative control points
/// (unchanged by the moves, rotations and mirrors that placement applies), and
/// placement re-linearises the same curves many times (every `autonorm`). Finding
/// them (Newton on adaptive quadrature) is most of the cost of building a
/// garment; the memo returns the very same numbers, only sooner.
mod arc_memo {
    use std::cell::RefCell;
    use std::collections::HashMap;

    /// Control-point bits, point count and degree.
    pub type Key = [u64; 6];

    /// Entries kept before the memo starts over (a garment needs a few hundred).
    pub const CAPACITY: usize = 4096;

    thread_local! {
        pub static MEMO: RefCell<HashMap<Key, Vec<f64>>> = RefCell::new(HashMap::new());
    }
}

/// Calls `f` with the parameters of the `n` interior points at equal arc-length
/// steps of a Bézier edge's relative curve (computed once per curve and thread).
fn arc_length_params<R>(curve: Curve, n: usize, f: impl FnOnce(&[f64]) -> R) -> R {
    let (key, rel): (arc_memo::Key, Bezier) = match curve {
        Curve::Quadratic(c) => ([c.x.to_bits(), c.y.to_bits(), 0, 0, n as u64, 2], Bezier::Quadratic([Vec2::ZERO, c, Vec2::X])),
        Curve::Cubic(c1, c2) => {
            ([c1.x.to_bits(), c1.y.to_bits(), c2.x.to_bits(), c2.y.to_bits(), n as u64, 3], Bezier::Cubic([Vec2::ZERO, c1, c2, Vec2::X]))
        }
        _ => unreachable!("only Bézier edges have arc-length parameters"),
    };
    arc_memo::MEMO.with(|memo| {
        let mut memo = memo.borrow_mut();
        if let Some(ts) = memo.get(&key) {
            return f(ts);
        }
        let len = rel.length();
        let ts: Vec<f64> = interior_params(n + 1).map(|u| rel.inverse_length(u * len).unwrap_or(u)).collect();
        let out = f(&ts);
        if memo.len() >= arc_memo::CAPACITY {
            memo.clear();
        }
        memo.insert(key, ts);
        out
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn worked_example_edges() {
        // pattern-format.md §12.
        let q = Edge { start: v(30., 0.), end: v(30., 40.), curve: Curve::Quadratic(v(0.5, -0.1)) };
        assert!((q.abs_controls()[0] - v(34., 20.)).length() < 1e-12);
        assert!((q.length() - 40.2651).abs() < 1e-4);
        let c = Edge { start: v(30., 40.), end: v(0., 40.), curve: Curve::Cubic(v(0.25, 0.1), v(0.75, -0.1)) };
        let abs = c.abs_controls();
        assert!((abs[0] - v(22.5, 37.)).length() < 1e-12);
        assert!((abs[1] - v(7.5, 43.)).length() < 1e-12);
        assert!((c.length() - 30.2935).abs() < 1e-4);
    }

    #[test]
    fn reversal_keeps_geometry() {
        for curve in [Curve::Quadratic(v(0.3, 0.4)), Curve::Cubic(v(0.2, -0.3), v(0.9, 0.5)), Curve::Arc { cy: 0.3 }] {
            let e = Edge { start: v(1., 1.), end: v(5., 3.), curve };
            let r = e.reversed();
            for k in 0..=4 {
                let t = k as f64 / 4.0;
                assert!((e.point(t) - r.point(1.0 - t)).length() < 1e-9, "{curve:?} at {t}");
            }
            assert!((e.length() - r.length()).abs() < 1e-12);
        }
    }

    #[test]
    fn split_keeps_length() {
        for curve in [Curve::Line, Curve::Quadratic(v(0.3, 0.4)), Curve::Cubic(v(0.2, -0.3), v(0.9, 0.5)), Curve::Arc { cy: -0.7 }] {
            let e = Edge { start: v(1., 1.), end: v(5., 3.), curve };
            let parts = e.split(&[0.25, 0.5, 0.25], true);
            let total: f64 = parts.iter().map(|p| p.length()).sum();
            assert!((total - e.length()).abs() < 1e-9, "{curve:?}: {total} vs {}", e.length());
            let first = parts[0].length() / e.length();
            assert!((first - 0.25).abs() < 1e-9, "{curve:?}: {first}");
            assert!((parts[2].end - e.end).length() < 1e-9);
        }
    }

    #[test]
    fn linearization_is_uniform_in_length() {
        let e = Edge { start: v(0., 0.), end: v(10., 0.), curve: Curve::Cubic(v(0.1, 0.5), v(0.6, -0.4)) };
        let pts = e.linearize(9);
        assert_eq!(pts.len(), 9);
        let seg = e.segment();
        let t = seg.inverse_length(e.length() * 0.3).unwrap();
        assert!((pts[2] - seg.point(t)).length() < 1e-9);
    }
}
