//! Curve helpers: quadratic Béziers fitted to end tangents (the reference's
//! `curve_from_tangents`), a quadratic through a prescribed extremum, and the cubic
//! re-fit to end tangents at a fixed length that inverts sleeve openings.

pub mod inversion;

pub use crate::arc::{cy_from_angle, cy_from_radius, cy_from_three_points, is_large, midpoint, rel_radius, svg_arc, sweep_angle};
use crate::bezier::Bezier;
use crate::edge::{Curve, Edge};
use crate::math::{Vec2, abs_to_rel_vector, norm};

/// The quadratic from `start` to `end` (its relative control point) whose end tangents
/// follow `tan0` (at the start) and/or `tan1` (at the end), found from `initial` as
/// the reference finds it (scipy's BFGS on the tangent misfit). With one tangent
/// every point of a ray fits exactly; the optimiser's path decides which one, so
/// the path is reproduced faithfully.
///
/// Fits are memoised per thread, like
/// [`match_tangents`]: the result is a pure function of the inputs' bits.
///
/// ```
/// use garmentcode::curves::quadratic_from_tangents;
/// use garmentcode::{Curve, Vec2};
///
/// // Leave at 45° up, arrive at 45° down: the control point is above the chord's middle.
/// let (start, end) = (Vec2::ZERO, Vec2::new(10.0, 0.0));
/// let tangents = (Some(Vec2::new(1.0, 1.0)), Some(Vec2::new(1.0, -1.0)));
/// let Curve::Quadratic(c) = quadratic_from_tangents(start, end, tangents.0, tangents.1, Vec2::new(0.3, 0.2)) else {
///     unreachable!()
/// };
/// assert!((c - Vec2::new(0.5, 0.5)).length() < 1e-4);
/// ```
pub fn quadratic_from_tangents(start: Vec2, end: Vec2, tan0: Option<Vec2>, tan1: Option<Vec2>, initial: Vec2) -> Curve {
    let rel = |t: Vec2| {
        let r = abs_to_rel_vector(start, end, t);
        let n = norm(r);
        [r.x / n, r.y / n]
    };
    let (t0, t1) = (tan0.map(rel), tan1.map(rel));
    let given = u64::from(t0.is_some()) | u64::from(t1.is_some()) << 1;
    let [t0x, t0y] = t0.unwrap_or_default().map(f64::to_bits);
    let [t1x, t1y] = t1.unwrap_or_default().map(f64::to_bits);
    let key = [given, t0x, t0y, t1x, t1y, initial.x.to_bits(), initial.y.to_bits()];
    let cp = crate::memo::tangent_fit(key, || crate::parity::bfgs::fit_quadratic_tangents(t0, t1, [initial.x, initial.y]));
    Curve::Quadratic(Vec2::new(cp[0], cp[1]))
}

/// The quadratic (its relative control point in the edge frame, from (0,0) to (1,0))
/// whose extremum (the point farthest from the chord) is the relative point `p`:
/// `B(½) = p` with the control point straight above the chord midpoint, i.e.
/// control `(p.x·2 − ½, 2·p.y)` when `p.x = ½`; in general the control point is
/// found so that the curve's y-extremum lies at `p`.
///
/// ```
/// use garmentcode::curves::quadratic_with_extremum;
/// use garmentcode::{Curve, Edge, Vec2};
///
/// let curve = quadratic_with_extremum(Vec2::new(0.5, 0.2)).unwrap();
/// assert_eq!(curve, Curve::Quadratic(Vec2::new(0.5, 0.4)));
/// let edge = Edge { start: Vec2::ZERO, end: Vec2::new(10.0, 0.0), curve };
/// assert!((edge.point(0.5) - Vec2::new(5.0, 2.0)).length() < 1e-12);
/// assert_eq!(quadratic_with_extremum(Vec2::new(0.5, 0.0)), None);
/// ```
pub fn quadratic_with_extremum(p: Vec2) -> Option<Curve> {
    // For B(t) = 2t(1−t)c + t²(1,0): y(t) = 2t(1−t)c_y has its extremum at t = ½
    // with value c_y/2, where x(½) = c_x/2 + ¼. So c = (2(p_x − ¼), 2 p_y).
    if !(0.0..=1.0).contains(&p.x) || p.y == 0.0 {
        return None;
    }
    Some(Curve::Quadratic(Vec2::new(2.0 * (p.x - 0.25), 2.0 * p.y)))
}

/// The cubic `edge` re-fitted to end tangents `t0`, `t1` at length `target_len`,
/// its start fixed and its end moved along the initial chord: the sleeve-opening
/// and hood inversion (the reference's `curve_match_tangents`), minimising the
/// reference's own objective deterministically (see [`inversion`]). A line or
/// quadratic edge is first raised to the cubic of the same shape.
///
/// ```
/// use garmentcode::curves::match_tangents;
/// use garmentcode::{Edge, Vec2};
///
/// let chord = Edge::line(Vec2::ZERO, Vec2::new(10.0, 0.0));
/// let fitted = match_tangents(&chord, Vec2::new(1.0, 1.0), Vec2::new(1.0, -1.0), 12.0);
/// assert_eq!(fitted.start, Vec2::ZERO);
/// assert!((fitted.length() - 12.0).abs() < 0.1);
/// assert_eq!(fitted.curve.code(), 'C');
/// ```
pub fn match_tangents(edge: &Edge, t0: Vec2, t1: Vec2, target_len: f64) -> Edge {
    let (s, e) = (edge.start, edge.end);
    let [c1, c2] = match edge.abs_controls()[..] {
        [c1, c2] => [c1, c2],
        [q] => [s + (q - s) * (2.0 / 3.0), e + (q - e) * (2.0 / 3.0)],
        _ => [s + (e - s) / 3.0, s + (e - s) * (2.0 / 3.0)],
    };
    let p = [s, c1, c2, e].map(|v| [v.x, v.y]);
    let fitted = inversion::match_tangents(p, [t0.x, t0.y], [t1.x, t1.y], target_len).map(|q| Vec2::new(q[0], q[1]));
    Edge::from_bezier(&Bezier::Cubic(fitted))
}
