//! Deterministic replacement for the reference's `curve_match_tangents`, the inversion that
//! bends a cubic Bézier into a sleeve opening or a hood bottom.
//!
//! The reference minimises, with scipy's L-BFGS-B and finite differences,
//! `f = (length - target)^2 + |T(0) - t0|^2 + |T(1) - t1|^2 + (max of 70 curvature samples)^2
//! + 0.001 s4^2` over shifts of the two inner control points (s0..s3) and of the end along
//! the initial chord (s4). That run is chaotic: the max is non-smooth and, being taken over
//! samples, rippled. Here the same objective is minimised to convergence by SQP with exact
//! derivatives, after a ripple-free stage that picks the basin smoothly (see [`solver`]).
//!
//! * [`match_tangents`]: the reference objective, never worse than the reference's result on
//!   the logged calls; continuous except where the 70-sample objective's own minimiser jumps
//!   between ripple basins (small jumps, ~0.1-0.2 cm).
//! * [`match_tangents_smooth`]: the ripple-free objective (curvature maximum over the whole
//!   curve); continuous, piecewise smooth in the inputs.
//! * [`objective`] / [`terms`]: the reference objective evaluated as svgpathtools does.

// Index loops mirror the maths; `!(a > b)` is used on purpose (it is also true for NaN).
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

mod bezier;
#[rustfmt::skip] // generated tables
mod gauss;
mod objective;
mod qp;
pub mod solver;

pub use objective::{Terms, apply_shift, objective, objective_of, shift_of, terms};
pub use solver::{Mode, Stats};

/// A 2D point or vector (cm).
pub type V2 = [f64; 2];

/// Bend the cubic `cps` (absolute control points) so its end tangents approach `t0`, `t1`
/// (any length, normalised here) and its length approaches `target_len`, keeping the start
/// fixed and moving the end only along the initial chord. Minimises the reference's own
/// objective (70 curvature samples); returns the final control points.
pub fn match_tangents(cps: [V2; 4], t0: V2, t1: V2, target_len: f64) -> [V2; 4] {
    match_tangents_with_stats(cps, t0, t1, target_len, Mode::Reference).0
}

/// Like [`match_tangents`] but minimises the ripple-free objective (curvature maximum over
/// the whole curve instead of 70 samples): fully continuous in the inputs.
pub fn match_tangents_smooth(cps: [V2; 4], t0: V2, t1: V2, target_len: f64) -> [V2; 4] {
    match_tangents_with_stats(cps, t0, t1, target_len, Mode::RippleFree).0
}

/// [`match_tangents`] / [`match_tangents_smooth`] plus solver diagnostics.
pub fn match_tangents_with_stats(cps: [V2; 4], t0: V2, t1: V2, target_len: f64, mode: Mode) -> ([V2; 4], Stats) {
    let (shift, stats) = solver::solve(cps, t0, t1, target_len, mode);
    (apply_shift(&cps, &shift), stats)
}

/// Arc length of a cubic Bézier (adaptive Gauss-Legendre, ~1e-13 absolute).
pub fn cubic_length(cps: &[V2; 4]) -> f64 {
    bezier::length(cps)
}

/// Unit tangent of a cubic Bézier at t.
pub fn cubic_unit_tangent(cps: &[V2; 4], t: f64) -> V2 {
    bezier::unit_tangent(cps, t)
}
