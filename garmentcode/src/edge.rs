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
///
/// ```
/// use garmentcode::{Curve, Vec2};
///
/// let c = Curve::Cubic(Vec2::new(0.25, 0.3), Vec2::new(0.5, 0.1));
/// assert_eq!(c.code(), 'C');
/// assert_eq!(c.reversed(), Curve::Cubic(Vec2::new(0.5, -0.1), Vec2::new(0.75, -0.3)));
/// assert_eq!(c.reversed().reversed(), c);
/// assert_eq!(Curve::Arc { cy: 0.3 }.reflected(), Curve::Arc { cy: -0.3 });
/// ```
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
///
/// ```
/// use garmentcode::{Curve, Edge, Vec2};
/// use std::f64::consts::PI;
///
/// let line = Edge::line(Vec2::ZERO, Vec2::new(2.0, 0.0));
/// assert_eq!((line.length(), line.midpoint()), (2.0, Vec2::new(1.0, 0.0)));
/// // A half circle: the arc's midpoint is half a chord to the left of the chord.
/// let arc = Edge { curve: Curve::Arc { cy: 0.5 }, ..line };
/// assert!((arc.length() - PI).abs() < 1e-6);
/// assert!((arc.midpoint() - Vec2::new(1.0, 1.0)).length() < 1e-9);
/// ```
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
                if !(0.0..=len).contains(&s) { None } else { Some(s / len) }
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
            Curve::Cubic(c1, c2) => Segment::Bezier(Bezier::Cubic([self.start, self.to_abs(c1), self.to_abs(c2), self.end])),
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
                let Segment::Bezier(b) = self.segment() else { unreachable!("Bézier edge") };
                let total = b.length();
                let t = b.inverse_length_given_total(total / 2.0, total).unwrap_or(0.5);
                b.point(t)
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
        let mut out = Vec::with_capacity(n);
        self.linearize_into(n, &mut out);
        out
    }

    /// As [`Edge::linearize`], appending the points to `out`.
    ///
    /// Memoised per thread (see `memo`): bounding boxes, normals and placements
    /// linearise the same edges over and over while a garment is built. Each Bézier
    /// point costs an inverse arc length (several adaptive quadratures), each arc
    /// point a few transcendental functions. In the relative frame a Bézier's points
    /// depend on its shape alone, not on where the end points are, so they are kept
    /// per shape and mapped to absolute coordinates per call; an arc's points are
    /// kept per exact geometry.
    pub fn linearize_into(&self, n: usize, out: &mut Vec<Vec2>) {
        if n == 0 {
            return;
        }
        let bits = |v: Vec2| [v.x.to_bits(), v.y.to_bits()];
        match self.curve {
            Curve::Line => {
                let seg = self.segment();
                out.extend(interior_params(n + 1).map(|t| seg.point(t)));
            }
            Curve::Arc { cy } => {
                let [sx, sy] = bits(self.start);
                let [ex, ey] = bits(self.end);
                let key = ([sx, sy, ex, ey, cy.to_bits(), 0], b'A', n);
                let make = || {
                    let seg = self.segment();
                    interior_params(n + 1).map(|t| seg.point(t)).collect()
                };
                crate::memo::edge_points(key, make, |pts| out.extend_from_slice(pts));
            }
            Curve::Quadratic(_) | Curve::Cubic(..) => self.linearize_bezier(n, out),
        }
    }

    /// Equal-arc-length points of a Bézier edge, from the memoised points of its
    /// relative shape in one orientation.
    ///
    /// A curve and its reverse have the same points in the opposite order (a
    /// mirrored panel's loop is reversed to keep its normal outward), so the points
    /// are always computed along the orientation with the smaller shape key and
    /// read backwards for the other: one entry serves both, and the result is a
    /// function of the edge alone, whatever was computed before.
    fn linearize_bezier(&self, n: usize, out: &mut Vec<Vec2>) {
        let reversed = self.reversed();
        let (own, back) = (self.shape_key(n), reversed.shape_key(n));
        if back.0 < own.0 {
            let from = out.len();
            reversed.linearize_oriented(n, back, out);
            out[from..].reverse();
        } else {
            self.linearize_oriented(n, own, out);
        }
    }

    /// Whether the shape is stored mirrored across the chord, and the memo key of
    /// the stored shape.
    ///
    /// A shape and its mirror image across the chord (the curves of a mirrored
    /// panel) share one entry, kept for the one whose first control point is not
    /// below the chord.
    fn shape_key(&self, n: usize) -> (crate::memo::EdgeKey, bool) {
        let first_y = match self.curve {
            Curve::Quadratic(c) | Curve::Cubic(c, _) => c.y,
            Curve::Line | Curve::Arc { .. } => unreachable!("Bézier edge"),
        };
        let flip = first_y < 0.0;
        let curve = if flip { self.curve.reflected() } else { self.curve };
        let bits = |v: Vec2| [v.x.to_bits(), v.y.to_bits()];
        let key = match curve {
            Curve::Quadratic(c) => ([bits(c)[0], bits(c)[1], 0, 0, 0, 0], b'Q', n),
            Curve::Cubic(c1, c2) => ([bits(c1)[0], bits(c1)[1], bits(c2)[0], bits(c2)[1], 0, 0], b'C', n),
            Curve::Line | Curve::Arc { .. } => unreachable!("Bézier edge"),
        };
        (key, flip)
    }

    /// [`Edge::linearize_bezier`] along this orientation. Mirroring negates every
    /// y input; the speeds (hence lengths and parameters) use only squares of y
    /// differences and come out bit for bit the same, and every y value computed
    /// from the negated inputs is exactly the negated value, except that a zero may
    /// differ in sign. So the mirrored points are the entry's with y negated, unless
    /// one of them is zero: then the points are computed directly. `(key, flip)`
    /// is this edge's [`Edge::shape_key`].
    fn linearize_oriented(&self, n: usize, (key, flip): (crate::memo::EdgeKey, bool), out: &mut Vec<Vec2>) {
        let shape = if flip { Edge { curve: self.curve.reflected(), ..*self } } else { *self };
        let done = crate::memo::edge_points(
            key,
            || shape.relative_linearization(n),
            |pts| {
                if !flip {
                    out.extend(pts.iter().map(|p| self.to_abs(*p)));
                } else if pts.iter().all(|p| p.y != 0.0) {
                    out.extend(pts.iter().map(|p| self.to_abs(Vec2::new(p.x, -p.y))));
                } else {
                    return false;
                }
                true
            },
        );
        if !done {
            out.extend(self.relative_linearization(n).into_iter().map(|p| self.to_abs(p)));
        }
    }

    /// `n` points at equal arc-length steps on the relative Bézier curve.
    fn relative_linearization(&self, n: usize) -> Vec<Vec2> {
        let rel = self.relative_bezier().expect("Bézier edge");
        let len = rel.length();
        let targets: Vec<f64> = interior_params(n + 1).map(|f| f * len).collect();
        rel.inverse_lengths_sorted(&targets, len).into_iter().map(|t| rel.point(t)).collect()
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
                    let next = if i + 1 == fractions.len() { self.end } else { Vec2::new(prev.x + f.abs() * d.x, prev.y + f.abs() * d.y) };
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
                            b.inverse_length_given_total((total * covered).min(total), total).unwrap_or(1.0)
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
            Bezier::Cubic([s, c1, c2, e]) => Edge { start: s, end: e, curve: Curve::Cubic(abs_to_rel(s, e, c1), abs_to_rel(s, e, c2)) },
        }
    }

    /// Rotate the end point about the start by `angle` radians.
    pub fn rotated(&self, angle: f64) -> Edge {
        Edge { end: self.start + rotate2d(self.end - self.start, angle), ..*self }
    }
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

    /// A reversed edge's points are the edge's in the opposite order (to rounding).
    #[test]
    fn reversed_edge_has_the_points_backwards() {
        let e = Edge { start: v(3., 1.), end: v(13., -2.), curve: Curve::Cubic(v(0.1, 0.5), v(0.6, -0.4)) };
        let forward = e.linearize(9);
        let backward = e.reversed().linearize(9);
        for (p, q) in forward.iter().zip(backward.iter().rev()) {
            assert!((*p - *q).length() < 1e-12, "{p} vs {q}");
        }
    }

    /// The memoised linearisation (mirror images and reversed curves sharing an
    /// entry) gives the bits of the direct computation, shapes with zero
    /// coordinates included, whatever the memo held before.
    #[test]
    fn memoised_linearization_is_the_direct_one() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 1.6
        };
        let oriented = |e: &Edge| -> Vec<Vec2> { e.relative_linearization(9).into_iter().map(|p| e.to_abs(p)).collect() };
        let direct = |e: &Edge| -> Vec<Vec2> {
            let r = e.reversed();
            if r.shape_key(9).0 < e.shape_key(9).0 { oriented(&r).into_iter().rev().collect() } else { oriented(e) }
        };
        for k in 0..400 {
            let (a, b, c, d) = (next(), next(), next(), next());
            let zero = |x: f64| {
                if k % 7 == 0 {
                    0.0
                } else if k % 11 == 0 {
                    -0.0
                } else {
                    x
                }
            };
            let (start, end) = (v(next() * 50.0, next() * 50.0), v(next() * 50.0 + 60.0, next() * 50.0));
            for curve in [
                Curve::Cubic(v(a, b), v(c, zero(d))),
                Curve::Cubic(v(a, zero(b)), v(c, d)),
                Curve::Quadratic(v(a, zero(b))),
                Curve::Cubic(v(0.3, 0.0), v(0.7, -0.0)),
            ] {
                for e in [Edge { start, end, curve }, Edge { start, end, curve: curve.reflected() }] {
                    let bits = |p: &[Vec2]| p.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect::<Vec<_>>();
                    let mirrored = Edge { curve: e.curve.reflected(), ..e };
                    for earlier in [None, Some(mirrored), Some(e.reversed()), Some(mirrored.reversed())] {
                        crate::memo::clear();
                        if let Some(other) = earlier {
                            let _ = other.linearize(9); // fill the shared entry from a relative
                        }
                        assert_eq!(bits(&e.linearize(9)), bits(&direct(&e)), "{e:?} after {earlier:?}");
                    }
                }
            }
        }
    }
}
