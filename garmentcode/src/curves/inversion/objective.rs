//! The reference objective, evaluated as the reference evaluates it.

use super::bezier::{self, V2};

/// Number of curvature samples (t = linspace(0, 1, 70)).
pub const N_SAMPLES: usize = 70;
/// Weight of the end-point shift regulariser.
pub const END_REG: f64 = 0.001;

/// The terms of the objective at one candidate curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Terms {
    /// Arc length of the candidate curve (cm).
    pub length: f64,
    /// |unit_tangent(0) - t0| (the objective uses its square).
    pub tan0_err: f64,
    /// |unit_tangent(1) - t1|.
    pub tan1_err: f64,
    /// Max curvature over the 70 samples (1/cm).
    pub max_curvature: f64,
    /// The end-point shift along the chord (cm).
    pub end_shift: f64,
    /// The full objective value.
    pub value: f64,
}

/// Unit chord direction start -> end of the initial curve (the end moves along it).
pub fn chord_dir(cps: &[V2; 4]) -> V2 {
    let d = bezier::sub(cps[3], cps[0]);
    let n = bezier::norm(d);
    [d[0] / n, d[1] / n]
}

/// Normalise a target tangent as the reference does.
pub fn unit(v: V2) -> V2 {
    let n = bezier::norm(v);
    [v[0] / n, v[1] / n]
}

/// Control points after applying the 5 shift unknowns to the initial curve.
pub fn apply_shift(cps: &[V2; 4], shift: &[f64; 5]) -> [V2; 4] {
    let d = chord_dir(cps);
    [
        cps[0],
        [cps[1][0] + shift[0], cps[1][1] + shift[1]],
        [cps[2][0] + shift[2], cps[2][1] + shift[3]],
        [cps[3][0] + d[0] * shift[4], cps[3][1] + d[1] * shift[4]],
    ]
}

/// Recover the shift from final control points (s4 is the end's move along the chord).
pub fn shift_of(cps: &[V2; 4], fin: &[V2; 4]) -> [f64; 5] {
    let d = chord_dir(cps);
    [
        fin[1][0] - cps[1][0],
        fin[1][1] - cps[1][1],
        fin[2][0] - cps[2][0],
        fin[2][1] - cps[2][1],
        bezier::dot(bezier::sub(fin[3], cps[3]), d),
    ]
}

/// All objective terms for `shift` applied to the initial control points `cps`.
pub fn terms(cps: [V2; 4], t0: V2, t1: V2, target_len: f64, shift: [f64; 5]) -> Terms {
    let p = apply_shift(&cps, &shift);
    let t0 = unit(t0);
    let t1 = unit(t1);
    let length = bezier::length(&p);
    let e0 = bezier::sub(bezier::unit_tangent(&p, 0.0), t0);
    let e1 = bezier::sub(bezier::unit_tangent(&p, 1.0), t1);
    let tan0_err = e0[0].hypot(e0[1]);
    let tan1_err = e1[0].hypot(e1[1]);
    let mut max_curvature = f64::NEG_INFINITY;
    for t in bezier::sample_params() {
        max_curvature = max_curvature.max(bezier::curvature(&p, t));
    }
    let value = (length - target_len).powi(2)
        + tan0_err * tan0_err
        + tan1_err * tan1_err
        + max_curvature * max_curvature
        + END_REG * shift[4] * shift[4];
    Terms { length, tan0_err, tan1_err, max_curvature, end_shift: shift[4], value }
}

/// The reference objective value for `shift` applied to `cps`.
pub fn objective(cps: [V2; 4], t0: V2, t1: V2, target_len: f64, shift: [f64; 5]) -> f64 {
    terms(cps, t0, t1, target_len, shift).value
}

/// The objective of a finished curve `fin` (same start, end on the initial chord line).
pub fn objective_of(cps: [V2; 4], t0: V2, t1: V2, target_len: f64, fin: [V2; 4]) -> f64 {
    objective(cps, t0, t1, target_len, shift_of(&cps, &fin))
}
