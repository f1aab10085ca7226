//! Line searches used by scipy's BFGS, ported so that the BFGS path (and so the
//! point returned on flat objectives) matches scipy 1.17 step for step.
//!
//! * [`Dcsrch`]: MINPACK-2 `dcsrch`/`dcstep` (Moré & Thuente, "Line search
//!   algorithms with guaranteed sufficient decrease", ACM TOMS 20, 1994), in
//!   the form scipy uses for `line_search_wolfe1` (`scipy/optimize/_dcsrch.py`).
//! * [`wolfe2`]: scipy's pure-Python strong-Wolfe search (`scalar_search_wolfe2`
//!   with `_zoom`, `_cubicmin`, `_quadmin`), which scipy only runs when dcsrch
//!   fails.
//!
//! Python's `min`/`max` builtins, `np.sign` and `x ** 2` (libm `pow`, not
//! `x * x`) are mirrored by small helpers because they decide branches and the
//! last bits of trial steps.

use super::num::{py_max2, py_max3, py_min2, sign, sq_pow};

/// phi(alpha) = f(x + alpha p) and its derivative along p, evaluated by the
/// caller (which also keeps the gradient of the last `derphi` call).
pub(crate) trait LineFunction {
    fn phi(&mut self, alpha: f64) -> f64;
    fn derphi(&mut self, alpha: f64) -> f64;
}

/// Outcome of one scalar line search.
pub(crate) struct LineSearchOk {
    /// Accepted step length.
    pub alpha: f64,
    /// phi(alpha).
    pub phi: f64,
    /// True when the last gradient evaluation was made at `alpha`, so the
    /// caller's cached gradient is the one at the new point. (scipy's wolfe2
    /// reports no gradient when it stops on its iteration limit; BFGS then
    /// recomputes it.)
    pub grad_at_alpha: bool,
}

/// MINPACK-2 `dcsrch` state (one line search).
///
/// The search keeps an interval `[stx, sty]` that brackets a step satisfying
/// the sufficient-decrease (`ftol`) and curvature (`gtol`) conditions, and asks
/// for new trial steps by reverse communication (here: [`Dcsrch::iterate`]
/// returns `Task::Fg`).
pub(crate) struct Dcsrch {
    ftol: f64,
    gtol: f64,
    xtol: f64,
    stpmin: f64,
    stpmax: f64,
    brackt: bool,
    stage: u8,
    finit: f64,
    ginit: f64,
    gtest: f64,
    width: f64,
    width1: f64,
    stx: f64,
    fx: f64,
    gx: f64,
    sty: f64,
    fy: f64,
    gy: f64,
    stmin: f64,
    stmax: f64,
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Task {
    Start,
    /// Evaluate phi and phi' at the returned step and call again.
    Fg,
    Convergence,
    /// Any MINPACK warning (rounding errors, xtol, stpmax, stpmin).
    Warning,
    Error,
}

impl Dcsrch {
    pub fn new(ftol: f64, gtol: f64, xtol: f64, stpmin: f64, stpmax: f64) -> Self {
        Dcsrch {
            ftol,
            gtol,
            xtol,
            stpmin,
            stpmax,
            brackt: false,
            stage: 1,
            finit: 0.0,
            ginit: 0.0,
            gtest: 0.0,
            width: 0.0,
            width1: 0.0,
            stx: 0.0,
            fx: 0.0,
            gx: 0.0,
            sty: 0.0,
            fy: 0.0,
            gy: 0.0,
            stmin: 0.0,
            stmax: 0.0,
        }
    }

    /// Runs the whole search like scipy's `DCSRCH.__call__`: at most `maxiter`
    /// calls of the MINPACK routine (the first one only initialises). Returns
    /// the accepted step and phi there, or `None` on any warning, error,
    /// non-finite step or iteration limit (scipy then falls back to wolfe2).
    pub fn search(&mut self, lf: &mut impl LineFunction, alpha1: f64, phi0: f64, derphi0: f64, maxiter: usize) -> Option<(f64, f64)> {
        let mut stp = alpha1;
        let mut f = phi0;
        let mut g = derphi0;
        let mut task = Task::Start;
        for _ in 0..maxiter {
            let (new_stp, new_task) = self.iterate(stp, f, g, task);
            stp = new_stp;
            task = new_task;
            if !stp.is_finite() {
                return None;
            }
            if task == Task::Fg {
                f = lf.phi(stp);
                g = lf.derphi(stp);
            } else {
                return if task == Task::Convergence { Some((stp, f)) } else { None };
            }
        }
        None
    }

    /// One call of MINPACK-2 `dcsrch`: given phi (`f`) and phi' (`g`) at `stp`,
    /// either stops or returns the next trial step with `Task::Fg`.
    pub fn iterate(&mut self, mut stp: f64, f: f64, g: f64, task: Task) -> (f64, Task) {
        const P5: f64 = 0.5;
        const P66: f64 = 0.66;
        const XTRAPL: f64 = 1.1;
        const XTRAPU: f64 = 4.0;

        if task == Task::Start {
            let bad = stp < self.stpmin
                || stp > self.stpmax
                || g >= 0.0
                || self.ftol < 0.0
                || self.gtol < 0.0
                || self.xtol < 0.0
                || self.stpmin < 0.0
                || self.stpmax < self.stpmin;
            if bad {
                return (stp, Task::Error);
            }
            self.brackt = false;
            self.stage = 1;
            self.finit = f;
            self.ginit = g;
            self.gtest = self.ftol * self.ginit;
            self.width = self.stpmax - self.stpmin;
            self.width1 = self.width / P5;
            self.stx = 0.0;
            self.fx = self.finit;
            self.gx = self.ginit;
            self.sty = 0.0;
            self.fy = self.finit;
            self.gy = self.ginit;
            self.stmin = 0.0;
            self.stmax = stp + XTRAPU * stp;
            return (stp, Task::Fg);
        }

        let ftest = self.finit + stp * self.gtest;
        if self.stage == 1 && f <= ftest && g >= 0.0 {
            self.stage = 2;
        }
        // Warnings first, then convergence overrides them (as in MINPACK).
        let mut out = Task::Fg;
        if self.brackt && (stp <= self.stmin || stp >= self.stmax) {
            out = Task::Warning; // rounding errors prevent progress
        }
        if self.brackt && self.stmax - self.stmin <= self.xtol * self.stmax {
            out = Task::Warning; // xtol test satisfied
        }
        if stp == self.stpmax && f <= ftest && g <= self.gtest {
            out = Task::Warning; // stp = stpmax
        }
        if stp == self.stpmin && (f > ftest || g >= self.gtest) {
            out = Task::Warning; // stp = stpmin
        }
        if f <= ftest && g.abs() <= self.gtol * -self.ginit {
            out = Task::Convergence;
        }
        if out != Task::Fg {
            return (stp, out);
        }

        if self.stage == 1 && f <= self.fx && f > ftest {
            // Stage 1 with a lower but not sufficiently lower value: step on the
            // modified function psi(a) = phi(a) - a * gtest.
            let fm = f - stp * self.gtest;
            let mut fxm = self.fx - self.stx * self.gtest;
            let mut fym = self.fy - self.sty * self.gtest;
            let gm = g - self.gtest;
            let mut gxm = self.gx - self.gtest;
            let mut gym = self.gy - self.gtest;
            let mut st = StepState { stx: self.stx, fx: fxm, dx: gxm, sty: self.sty, fy: fym, dy: gym, brackt: self.brackt };
            stp = dcstep(&mut st, stp, fm, gm, self.stmin, self.stmax);
            self.stx = st.stx;
            fxm = st.fx;
            gxm = st.dx;
            self.sty = st.sty;
            fym = st.fy;
            gym = st.dy;
            self.brackt = st.brackt;
            self.fx = fxm + self.stx * self.gtest;
            self.fy = fym + self.sty * self.gtest;
            self.gx = gxm + self.gtest;
            self.gy = gym + self.gtest;
        } else {
            let mut st =
                StepState { stx: self.stx, fx: self.fx, dx: self.gx, sty: self.sty, fy: self.fy, dy: self.gy, brackt: self.brackt };
            stp = dcstep(&mut st, stp, f, g, self.stmin, self.stmax);
            self.stx = st.stx;
            self.fx = st.fx;
            self.gx = st.dx;
            self.sty = st.sty;
            self.fy = st.fy;
            self.gy = st.dy;
            self.brackt = st.brackt;
        }

        // Force a sufficient decrease of the bracket width.
        if self.brackt {
            if (self.sty - self.stx).abs() >= P66 * self.width1 {
                stp = self.stx + P5 * (self.sty - self.stx);
            }
            self.width1 = self.width;
            self.width = (self.sty - self.stx).abs();
        }
        if self.brackt {
            self.stmin = py_min2(self.stx, self.sty);
            self.stmax = py_max2(self.stx, self.sty);
        } else {
            self.stmin = stp + XTRAPL * (stp - self.stx);
            self.stmax = stp + XTRAPU * (stp - self.stx);
        }
        stp = clip(stp, self.stpmin, self.stpmax);
        // If no further progress is possible, let stp be the best point so far.
        if self.brackt && (stp <= self.stmin || stp >= self.stmax || self.stmax - self.stmin <= self.xtol * self.stmax) {
            stp = self.stx;
        }
        (stp, Task::Fg)
    }
}

/// `np.clip` on a scalar (NaN passes through).
fn clip(x: f64, lo: f64, hi: f64) -> f64 {
    let y = if x < lo { lo } else { x };
    if y > hi { hi } else { y }
}

/// Interval end points handed to and updated by [`dcstep`].
struct StepState {
    stx: f64,
    fx: f64,
    dx: f64,
    sty: f64,
    fy: f64,
    dy: f64,
    brackt: bool,
}

/// MINPACK-2 `dcstep`: safeguarded cubic/quadratic trial step and update of
/// the bracketing interval. Returns the new trial step.
fn dcstep(s: &mut StepState, stp: f64, fp: f64, dp: f64, stpmin: f64, stpmax: f64) -> f64 {
    let (stx, fx, dx, sty, fy, dy) = (s.stx, s.fx, s.dx, s.sty, s.fy, s.dy);
    let sgnd = sign(dp) * sign(dx);
    let stpf;
    if fp > fx {
        // Case 1: higher function value; the minimum is bracketed.
        let theta = 3.0 * (fx - fp) / (stp - stx) + dx + dp;
        let sm = py_max3(theta.abs(), dx.abs(), dp.abs());
        let mut gamma = sm * (sq_pow(theta / sm) - (dx / sm) * (dp / sm)).sqrt();
        if stp < stx {
            gamma = -gamma;
        }
        let p = (gamma - dx) + theta;
        let q = ((gamma - dx) + gamma) + dp;
        let r = p / q;
        let stpc = stx + r * (stp - stx);
        let stpq = stx + ((dx / ((fx - fp) / (stp - stx) + dx)) / 2.0) * (stp - stx);
        stpf = if (stpc - stx).abs() <= (stpq - stx).abs() { stpc } else { stpc + (stpq - stpc) / 2.0 };
        s.brackt = true;
    } else if sgnd < 0.0 {
        // Case 2: derivatives of opposite sign; the minimum is bracketed.
        let theta = 3.0 * (fx - fp) / (stp - stx) + dx + dp;
        let sm = py_max3(theta.abs(), dx.abs(), dp.abs());
        let mut gamma = sm * (sq_pow(theta / sm) - (dx / sm) * (dp / sm)).sqrt();
        if stp > stx {
            gamma = -gamma;
        }
        let p = (gamma - dp) + theta;
        let q = ((gamma - dp) + gamma) + dx;
        let r = p / q;
        let stpc = stp + r * (stx - stp);
        let stpq = stp + (dp / (dp - dx)) * (stx - stp);
        stpf = if (stpc - stp).abs() > (stpq - stp).abs() { stpc } else { stpq };
        s.brackt = true;
    } else if dp.abs() < dx.abs() {
        // Case 3: same sign, derivative magnitude decreases.
        let theta = 3.0 * (fx - fp) / (stp - stx) + dx + dp;
        let sm = py_max3(theta.abs(), dx.abs(), dp.abs());
        let mut gamma = sm * py_max2(0.0, sq_pow(theta / sm) - (dx / sm) * (dp / sm)).sqrt();
        if stp > stx {
            gamma = -gamma;
        }
        let p = (gamma - dp) + theta;
        let q = (gamma + (dx - dp)) + gamma;
        let r = p / q;
        let stpc = if r < 0.0 && gamma != 0.0 {
            stp + r * (stx - stp)
        } else if stp > stx {
            stpmax
        } else {
            stpmin
        };
        let stpq = stp + (dp / (dp - dx)) * (stx - stp);
        if s.brackt {
            let mut v = if (stpc - stp).abs() < (stpq - stp).abs() { stpc } else { stpq };
            v = if stp > stx { py_min2(stp + 0.66 * (sty - stp), v) } else { py_max2(stp + 0.66 * (sty - stp), v) };
            stpf = v;
        } else {
            let v = if (stpc - stp).abs() > (stpq - stp).abs() { stpc } else { stpq };
            stpf = clip(v, stpmin, stpmax);
        }
    } else {
        // Case 4: same sign, derivative magnitude does not decrease.
        if s.brackt {
            let theta = 3.0 * (fp - fy) / (sty - stp) + dy + dp;
            let sm = py_max3(theta.abs(), dy.abs(), dp.abs());
            let mut gamma = sm * (sq_pow(theta / sm) - (dy / sm) * (dp / sm)).sqrt();
            if stp > sty {
                gamma = -gamma;
            }
            let p = (gamma - dp) + theta;
            let q = ((gamma - dp) + gamma) + dy;
            let r = p / q;
            stpf = stp + r * (sty - stp);
        } else if stp > stx {
            stpf = stpmax;
        } else {
            stpf = stpmin;
        }
    }

    // Update the interval that contains a minimizer.
    if fp > fx {
        s.sty = stp;
        s.fy = fp;
        s.dy = dp;
    } else {
        if sgnd < 0.0 {
            s.sty = stx;
            s.fy = fx;
            s.dy = dx;
        }
        s.stx = stp;
        s.fx = fp;
        s.dx = dp;
    }
    stpf
}

/// scipy's `scalar_search_wolfe2` (Nocedal & Wright, Algorithm 3.5) with
/// `amax` and no extra condition. `alpha1` is the initial step already
/// computed by the caller (same formula as scipy), `maxiter` = 10.
pub(crate) fn wolfe2(
    lf: &mut impl LineFunction,
    phi0: f64,
    derphi0: f64,
    alpha1_init: f64,
    c1: f64,
    c2: f64,
    amax: f64,
) -> Option<LineSearchOk> {
    const MAXITER: usize = 10;
    let mut alpha0 = 0.0;
    let mut alpha1 = py_min2(alpha1_init, amax);
    let mut phi_a1 = lf.phi(alpha1);
    let mut phi_a0 = phi0;
    let mut derphi_a0 = derphi0;
    for i in 0..MAXITER {
        if alpha1 == 0.0 || alpha0 > amax {
            return None;
        }
        let not_first_iteration = i > 0;
        if phi_a1 > phi0 + c1 * alpha1 * derphi0 || (phi_a1 >= phi_a0 && not_first_iteration) {
            return zoom(alpha0, alpha1, phi_a0, phi_a1, derphi_a0, lf, phi0, derphi0, c1, c2);
        }
        let derphi_a1 = lf.derphi(alpha1);
        if derphi_a1.abs() <= -c2 * derphi0 {
            return Some(LineSearchOk { alpha: alpha1, phi: phi_a1, grad_at_alpha: true });
        }
        if derphi_a1 >= 0.0 {
            return zoom(alpha1, alpha0, phi_a1, phi_a0, derphi_a1, lf, phi0, derphi0, c1, c2);
        }
        let alpha2 = py_min2(2.0 * alpha1, amax);
        alpha0 = alpha1;
        alpha1 = alpha2;
        phi_a0 = phi_a1;
        phi_a1 = lf.phi(alpha1);
        derphi_a0 = derphi_a1;
    }
    // Iteration limit: scipy accepts the last step but reports no gradient.
    Some(LineSearchOk { alpha: alpha1, phi: phi_a1, grad_at_alpha: false })
}

/// scipy's `_zoom` (Nocedal & Wright, Algorithm 3.6), at most 11 trials.
#[allow(clippy::too_many_arguments)]
fn zoom(
    mut a_lo: f64,
    mut a_hi: f64,
    mut phi_lo: f64,
    mut phi_hi: f64,
    mut derphi_lo: f64,
    lf: &mut impl LineFunction,
    phi0: f64,
    derphi0: f64,
    c1: f64,
    c2: f64,
) -> Option<LineSearchOk> {
    const MAXITER: usize = 10;
    const DELTA1: f64 = 0.2; // cubic interpolant check
    const DELTA2: f64 = 0.1; // quadratic interpolant check
    let mut phi_rec = phi0;
    let mut a_rec = 0.0;
    let mut i = 0;
    loop {
        let dalpha = a_hi - a_lo;
        let (a, b) = if dalpha < 0.0 { (a_hi, a_lo) } else { (a_lo, a_hi) };
        let mut a_j = None;
        let mut cchk = 0.0;
        if i > 0 {
            cchk = DELTA1 * dalpha;
            a_j = cubicmin(a_lo, phi_lo, derphi_lo, a_hi, phi_hi, a_rec, phi_rec);
        }
        let use_quad = match a_j {
            None => true,
            Some(v) => i == 0 || v > b - cchk || v < a + cchk,
        };
        if use_quad {
            let qchk = DELTA2 * dalpha;
            a_j = quadmin(a_lo, phi_lo, derphi_lo, a_hi, phi_hi);
            a_j = match a_j {
                Some(v) if !(v > b - qchk || v < a + qchk) => Some(v),
                _ => Some(a_lo + 0.5 * dalpha),
            };
        }
        let a_j = a_j.unwrap();
        let phi_aj = lf.phi(a_j);
        if phi_aj > phi0 + c1 * a_j * derphi0 || phi_aj >= phi_lo {
            phi_rec = phi_hi;
            a_rec = a_hi;
            a_hi = a_j;
            phi_hi = phi_aj;
        } else {
            let derphi_aj = lf.derphi(a_j);
            if derphi_aj.abs() <= -c2 * derphi0 {
                return Some(LineSearchOk { alpha: a_j, phi: phi_aj, grad_at_alpha: true });
            }
            if derphi_aj * (a_hi - a_lo) >= 0.0 {
                phi_rec = phi_hi;
                a_rec = a_hi;
                a_hi = a_lo;
                phi_hi = phi_lo;
            } else {
                phi_rec = phi_lo;
                a_rec = a_lo;
            }
            a_lo = a_j;
            phi_lo = phi_aj;
            derphi_lo = derphi_aj;
        }
        i += 1;
        if i > MAXITER {
            return None;
        }
    }
}

/// Returns `Some(v)` when `v` is finite. scipy evaluates the interpolants under
/// `np.errstate(raise)`: any overflow, division by zero or invalid operation
/// makes them return `None`; every such event leaves a non-finite intermediate
/// that reaches the result, so checking intermediates for finiteness is
/// equivalent.
fn finite(v: f64) -> Option<f64> {
    if v.is_finite() { Some(v) } else { None }
}

/// scipy's `_cubicmin`: minimiser of the cubic through (a, fa), (b, fb),
/// (c, fc) with slope fpa at a. The 2x2 product is done like OpenBLAS dgemv
/// (see [`super::num::dot2_gemv`]).
fn cubicmin(a: f64, fa: f64, fpa: f64, b: f64, fb: f64, c: f64, fc: f64) -> Option<f64> {
    let cc = fpa;
    let db = finite(b - a)?;
    let dc = finite(c - a)?;
    let denom = finite(sq_pow(finite(db * dc)?) * finite(db - dc)?)?;
    let d00 = finite(sq_pow(dc))?;
    let d01 = -finite(sq_pow(db))?;
    let d10 = -finite(super::num::pow(dc, 3.0))?;
    let d11 = finite(super::num::pow(db, 3.0))?;
    let v0 = finite(fb - fa - cc * db)?;
    let v1 = finite(fc - fa - cc * dc)?;
    let big_a = finite(super::num::dot2_gemv(d00, v0, d01, v1))?;
    let big_b = finite(super::num::dot2_gemv(d10, v0, d11, v1))?;
    let big_a = finite(big_a / denom)?;
    let big_b = finite(big_b / denom)?;
    let radical = finite(big_b * big_b - 3.0 * big_a * cc)?;
    let xmin = a + (-big_b + finite(radical.sqrt())?) / finite(3.0 * big_a)?;
    finite(xmin)
}

/// scipy's `_quadmin`: minimiser of the parabola through (a, fa), (b, fb)
/// with slope fpa at a.
fn quadmin(a: f64, fa: f64, fpa: f64, b: f64, fb: f64) -> Option<f64> {
    let d = fa;
    let c = fpa;
    let db = finite(b - a * 1.0)?;
    let bb = finite(finite(fb - d - c * db)? / finite(db * db)?)?;
    let xmin = a - finite(c / finite(2.0 * bb)?)?;
    finite(xmin)
}
