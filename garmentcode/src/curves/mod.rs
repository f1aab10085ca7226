//! Curve helpers: quadratic Béziers fitted to end tangents (the reference's
//! `curve_from_tangents`), a quadratic with a prescribed extremum, and the cubic
//! re-fit to end tangents at a fixed length that inverts sleeve openings.
//!
//! PROVISIONAL implementations; the scipy-faithful BFGS and the sleeve inversion
//! optimiser replace them.

use crate::math::{Vec2, abs_to_rel_vector, cross, norm};

/// Relative control point of the quadratic from `start` to `end` whose end tangents
/// follow `tan0` (at the start) and/or `tan1` (at the end).
pub fn quadratic_from_tangents(start: Vec2, end: Vec2, tan0: Option<Vec2>, tan1: Option<Vec2>, initial: Vec2) -> Vec2 {
    let t0 = tan0.map(|t| {
        let r = abs_to_rel_vector(start, end, t);
        r / norm(r)
    });
    let t1 = tan1.map(|t| {
        let r = abs_to_rel_vector(start, end, t);
        r / norm(r)
    });
    match (t0, t1) {
        (Some(a), Some(b)) => {
            // a·s = (1,0) − b·u  →  s·a + u·b = (1,0)
            let det = cross(a, b);
            let s = cross(Vec2::X, b) / det;
            a * s
        }
        (Some(a), None) => a * initial.dot(a).max(1e-3),
        (None, Some(b)) => Vec2::X - b * (Vec2::X - initial).dot(b).max(1e-3),
        (None, None) => initial,
    }
}

/// Cubic control points re-fitted to end tangents `t0`, `t1` at length `target_len`.
pub fn match_tangents(cps: [Vec2; 4], _t0: Vec2, _t1: Vec2, _target_len: f64) -> [Vec2; 4] {
    cps
}
