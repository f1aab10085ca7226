//! Deterministic replacement for the reference's `curve_match_tangents`, the inversion that
//! bends a cubic Bézier into a sleeve opening or a hood bottom.
//!
//! The reference minimises, with scipy's L-BFGS-B and finite differences,
//! `f = (length - target)^2 + |T(0) - t0|^2 + |T(1) - t1|^2 + (max of 70 curvature samples)^2
//! + 0.001 s4^2` over shifts of the two inner control points (s0..s3) and of the end along
//! the initial chord (s4). That run is chaotic: the max is non-smooth and, being taken over
//! samples, rippled. Here the ripple-free problem (curvature max over the whole curve) is
//! solved by SQP with exact derivatives, then refined on the reference objective by a fixed
//! number of proximal steps (see [`proximal`]).
//!
//! * [`match_tangents`] (default, [`Mode::Proximal`]): continuous in the inputs and never
//!   worse than the reference's result on the 574 logged calls; steep (not discontinuous)
//!   within a small input range where a curvature peak crosses a sample.
//! * [`match_tangents_reference`] ([`Mode::Reference`]): the reference objective minimised to
//!   convergence; never worse than the reference, but jumps by up to ~0.4 cm where the
//!   chosen ripple basin switches.
//! * [`match_tangents_smooth`] ([`Mode::RippleFree`]): the ripple-free objective; smooth, but
//!   worse than the reference on 161 of the 574 logged calls (by at most 0.37 %).
//! * [`objective`] / [`terms`]: the reference objective evaluated as svgpathtools does.

// Index loops mirror the maths; `!(a > b)` is used on purpose (it is also true for NaN).
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

mod bezier;
mod eig;
#[rustfmt::skip] // generated tables
mod gauss;
mod objective;
mod proximal;
mod qp;
mod solver;

pub use objective::{Terms, apply_shift, objective, objective_of, shift_of, terms};
pub use proximal::STEPS;
pub use solver::{Mode, Stats};

use solver::{Bound, NX, Setup, TOL_STAGE1, TOL_STAGE2, run};

/// A 2D point or vector (cm).
pub type V2 = [f64; 2];

/// Bend the cubic `cps` (absolute control points) so its end tangents approach `t0`, `t1`
/// (any length, normalised here) and its length approaches `target_len`, keeping the start
/// fixed and moving the end only along the initial chord. Returns the final control points.
///
/// Ripple-free solution refined by [`proximal::STEPS`] proximal steps on the reference's
/// objective: deterministic, continuous in all inputs, at least as good as the reference on
/// its own objective on every logged call.
///
/// Results are memoised per thread (a pure function of its inputs' bits: the memo
/// changes nothing but the time taken).
pub fn match_tangents(cps: [V2; 4], t0: V2, t1: V2, target_len: f64) -> [V2; 4] {
    let mut key = [0u64; 13];
    let inputs = cps.iter().flatten().chain(&t0).chain(&t1).chain(std::iter::once(&target_len));
    for (k, x) in key.iter_mut().zip(inputs) {
        *k = x.to_bits();
    }
    crate::memo::inversion(key, || match_tangents_with_stats(cps, t0, t1, target_len, Mode::Proximal).0)
}

/// Like [`match_tangents`] but minimises the reference objective to convergence (a local
/// minimum of the 70-sample objective): can jump where the ripple basin switches.
pub fn match_tangents_reference(cps: [V2; 4], t0: V2, t1: V2, target_len: f64) -> [V2; 4] {
    match_tangents_with_stats(cps, t0, t1, target_len, Mode::Reference).0
}

/// Like [`match_tangents`] but minimises the ripple-free objective (curvature maximum over
/// the whole curve instead of 70 samples): smooth in the inputs, slightly worse objective.
pub fn match_tangents_smooth(cps: [V2; 4], t0: V2, t1: V2, target_len: f64) -> [V2; 4] {
    match_tangents_with_stats(cps, t0, t1, target_len, Mode::RippleFree).0
}

/// Any mode, plus solver diagnostics.
pub fn match_tangents_with_stats(cps: [V2; 4], t0: V2, t1: V2, target_len: f64, mode: Mode) -> ([V2; 4], Stats) {
    let (shift, stats) = solve(cps, t0, t1, target_len, mode);
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

/// Solve the inversion; returns the 5 shifts and diagnostics.
pub fn solve(cps: [V2; 4], t0: V2, t1: V2, target: f64, mode: Mode) -> ([f64; NX], Stats) {
    solve_traced(cps, t0, t1, target, mode, false)
}

/// [`Mode::Proximal`] with a chosen number of proximal steps (for studying the trade-off:
/// more steps reach the ripple minima from closer to a ridge but make the map steeper).
pub fn solve_proximal(cps: [V2; 4], t0: V2, t1: V2, target: f64, steps: usize) -> ([f64; NX], Stats) {
    solve_impl(cps, t0, t1, target, Mode::Proximal, steps, false)
}

/// [`solve`], optionally printing one line per SQP trial step to stderr (debug aid).
pub fn solve_traced(cps: [V2; 4], t0: V2, t1: V2, target: f64, mode: Mode, trace: bool) -> ([f64; NX], Stats) {
    solve_impl(cps, t0, t1, target, mode, proximal::STEPS, trace)
}

fn solve_impl(cps: [V2; 4], t0: V2, t1: V2, target: f64, mode: Mode, steps: usize, trace: bool) -> ([f64; NX], Stats) {
    let s = Setup::new(cps, t0, t1, target);
    let mut st = Stats::default();
    // Fall back to the input curve if the guess is degenerate (never seen in practice).
    let mut x0 = s.initial_guess();
    if !s.objective(&x0, Bound::Envelope).is_finite() {
        x0 = [0.0; NX];
    }
    let x = if mode == Mode::RippleFree {
        let r = run(&s, x0, Bound::Envelope, TOL_STAGE2, 0, &mut st, trace);
        st.converged = r.ok;
        r.x
    } else if mode == Mode::Proximal {
        let r = run(&s, x0, Bound::Envelope, TOL_STAGE2, 0, &mut st, trace);
        st.converged = r.ok;
        match proximal::frozen_model(&s, &r) {
            Some(ginv) => proximal::refine(&s, r.x, &ginv, steps, &mut st),
            None => r.x,
        }
    } else {
        let r1 = run(&s, x0, Bound::Envelope, TOL_STAGE1, 0, &mut st, trace);
        let r2 = run(&s, r1.x, Bound::Samples, TOL_STAGE2, 1, &mut st, trace);
        st.converged = r1.ok && r2.ok;
        r2.x
    };
    // Degenerate input (e.g. non-finite values): return the input curve unchanged.
    if x.iter().all(|v| v.is_finite()) { (x, st) } else { ([0.0; NX], st) }
}
