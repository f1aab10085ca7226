//! A faithful port of `scipy.optimize.minimize(f, x0)` with its defaults
//! (method BFGS, no gradient given), and the quadratic-Bezier tangent fit
//! that pygarment's `CurveEdgeFactory.curve_from_tangents` runs through it.
//!
//! Why a port and not any BFGS: with a single target tangent the fit has a
//! whole ray of exact minimisers, and which one is returned depends on the
//! exact optimiser path (finite differences, initial step, line search,
//! Hessian update). Everything here follows scipy 1.17.1 (`_optimize.py`
//! `_minimize_bfgs`, `_numdiff.py`, `_linesearch.py`, `_dcsrch.py`, the last a
//! Python translation of MINPACK-2 `dcsrch`/`dcstep` by Moré and Thuente),
//! down to evaluation order, so results agree with scipy to the last bits.
//!
//! Floating-point details mirrored on purpose (measured in the reference env:
//! numpy 1.26.4 with OpenBLAS 0.3.23 Haswell kernels, glibc 2.36 libm):
//! * `np.dot(H, g)` and `np.dot(A, B)` on 2x2 matrices use fused
//!   multiply-adds in OpenBLAS; 1-D dots and norms are plain sums;
//! * `x ** 2` is libm `pow`, which is not always `x * x`;
//! * the objective's complex arithmetic is CPython's.
//!
//! Parity therefore assumes the same libm (`pow`, `hypot`) as the reference.

mod linesearch;
mod num;

use self::linesearch::{Dcsrch, LineFunction, LineSearchOk, wolfe2};
use self::num::{C, dot, matmul, matvec, py_min2, sq_pow};

/// Result of [`minimize_bfgs`], the fields of scipy's `OptimizeResult` we use.
#[derive(Clone, Debug, PartialEq)]
pub struct BfgsResult {
    /// Final point.
    pub x: Vec<f64>,
    /// Objective at `x`.
    pub fun: f64,
    /// Number of BFGS iterations.
    pub nit: usize,
    /// Number of objective evaluations, finite differences included (scipy's
    /// `nfev`).
    pub nfev: usize,
    /// scipy's `success`: false on line-search failure ("precision loss"),
    /// iteration limit or NaN.
    pub success: bool,
}

/// `sqrt(machine epsilon)`: scipy's BFGS default `eps`, used as an *absolute*
/// forward-difference step (`abs_step`), not a relative one.
const FD_STEP: f64 = 1.4901161193847656e-08;
/// BFGS gradient tolerance on the infinity norm.
const GTOL: f64 = 1e-5;
/// Wolfe constants (sufficient decrease, curvature) for both line searches.
const C1: f64 = 1e-4;
const C2: f64 = 0.9;
/// dcsrch relative interval tolerance and step bounds as BFGS passes them.
const XTOL: f64 = 1e-14;
const AMIN: f64 = 1e-100;
const AMAX: f64 = 1e100;
/// `DCSRCH.__call__` iteration limit used by `scalar_search_wolfe1`.
const DCSRCH_MAXITER: usize = 100;

/// Objective with scipy's `ScalarFunction` caching: the value and the
/// finite-difference gradient are remembered for the last point only, and the
/// value at a point is reused as `f0` of the gradient there.
struct Objective<F> {
    f: F,
    x: Vec<f64>,
    fx: f64,
    f_ok: bool,
    g: Vec<f64>,
    g_ok: bool,
    nfev: usize,
    /// Scratch point for line-search trials and finite differences.
    tmp: Vec<f64>,
}

impl<F: FnMut(&[f64]) -> f64> Objective<F> {
    fn new(f: F, x0: &[f64]) -> Self {
        let n = x0.len();
        Objective { f, x: x0.to_vec(), fx: 0.0, f_ok: false, g: vec![0.0; n], g_ok: false, nfev: 0, tmp: vec![0.0; n] }
    }

    /// `np.array_equal(x, self.x)` test, then invalidate the caches.
    fn set_x(&mut self, x: &[f64]) {
        if !x.iter().zip(&self.x).all(|(a, b)| a == b) {
            self.x.copy_from_slice(x);
            self.f_ok = false;
            self.g_ok = false;
        }
    }

    fn update_fun(&mut self) {
        if !self.f_ok {
            self.fx = (self.f)(&self.x);
            self.nfev += 1;
            self.f_ok = true;
        }
    }

    fn fun(&mut self, x: &[f64]) -> f64 {
        self.set_x(x);
        self.update_fun();
        self.fx
    }

    /// Forward differences as `approx_derivative(method='2-point',
    /// abs_step=eps)`: step `h = 1.49e-8` whatever `x_i` is (0.5 or 0 alike),
    /// divided by the representable increment `(x_i + h) - x_i`; only when
    /// that increment is 0 (|x_i| >~ 1e8) scipy switches to the relative step
    /// `sqrt(eps) * sign(x_i) * max(1, |x_i|)`.
    fn grad(&mut self, x: &[f64]) -> &[f64] {
        self.set_x(x);
        if !self.g_ok {
            self.update_fun();
            let f0 = self.fx;
            for i in 0..self.x.len() {
                let xi = self.x[i];
                let mut h = FD_STEP;
                if (xi + h) - xi == 0.0 {
                    let sign = if xi >= 0.0 { 1.0 } else { -1.0 };
                    h = FD_STEP * sign * xi.abs().max(1.0);
                }
                self.tmp.copy_from_slice(&self.x);
                self.tmp[i] = xi + h;
                let fi = (self.f)(&self.tmp);
                self.nfev += 1;
                let dx = (xi + h) - xi;
                self.g[i] = (fi - f0) / dx;
            }
            self.g_ok = true;
        }
        &self.g
    }
}

/// phi(a) = f(xk + a pk) for the line searches; keeps the gradient of the
/// last `derphi` call like scipy's `gval[0]`.
struct Line<'a, F> {
    obj: &'a mut Objective<F>,
    xk: &'a [f64],
    pk: &'a [f64],
    point: Vec<f64>,
    last_grad: Vec<f64>,
}

impl<F: FnMut(&[f64]) -> f64> Line<'_, F> {
    fn set_point(&mut self, alpha: f64) {
        for ((p, x), d) in self.point.iter_mut().zip(self.xk).zip(self.pk) {
            *p = x + alpha * d;
        }
    }
}

impl<F: FnMut(&[f64]) -> f64> LineFunction for Line<'_, F> {
    fn phi(&mut self, alpha: f64) -> f64 {
        self.set_point(alpha);
        self.obj.fun(&self.point)
    }
    fn derphi(&mut self, alpha: f64) -> f64 {
        self.set_point(alpha);
        let g = self.obj.grad(&self.point);
        self.last_grad.copy_from_slice(g);
        dot(&self.last_grad, self.pk)
    }
}

/// scipy's `_line_search_wolfe12`: MINPACK dcsrch first, scipy's wolfe2 only
/// if dcsrch fails. Returns the step, phi there and the gradient there.
fn line_search_wolfe12<F: FnMut(&[f64]) -> f64>(
    obj: &mut Objective<F>,
    xk: &[f64],
    pk: &[f64],
    gfk: &[f64],
    old_fval: f64,
    old_old_fval: f64,
) -> Option<(LineSearchOk, Vec<f64>)> {
    let n = xk.len();
    let derphi0 = dot(gfk, pk);
    // Initial step from the last decrease (Nocedal & Wright eq. 3.60), capped
    // at 1; the first BFGS iteration fakes old_old_fval so that it is ~1/|g|.
    let mut alpha1 = 1.0;
    if derphi0 != 0.0 {
        alpha1 = py_min2(1.0, 1.01 * 2.0 * (old_fval - old_old_fval) / derphi0);
        if alpha1 < 0.0 {
            alpha1 = 1.0;
        }
    }
    let mut line = Line { obj, xk, pk, point: vec![0.0; n], last_grad: gfk.to_vec() };

    let mut dcsrch = Dcsrch::new(C1, C2, XTOL, AMIN, AMAX);
    if let Some((alpha, phi)) = dcsrch.search(&mut line, alpha1, old_fval, derphi0, DCSRCH_MAXITER) {
        return Some((LineSearchOk { alpha, phi, grad_at_alpha: true }, line.last_grad));
    }
    // Fallback (scipy passes only c1, c2 and amax; the initial step is the same).
    let ls = wolfe2(&mut line, old_fval, derphi0, alpha1, C1, C2, AMAX)?;
    Some((ls, line.last_grad))
}

/// `max |g_i|` as `np.amax(np.abs(g))` (NaN propagates).
fn inf_norm(g: &[f64]) -> f64 {
    let mut m = 0.0f64;
    for v in g {
        let a = v.abs();
        if a.is_nan() {
            return f64::NAN;
        }
        if a > m {
            m = a;
        }
    }
    m
}

/// `np.linalg.norm(v)`: `sqrt(v . v)`.
fn norm2(v: &[f64]) -> f64 {
    dot(v, v).sqrt()
}

/// Minimises `f` from `x0` exactly like `scipy.optimize.minimize(f, x0)`
/// (BFGS, forward-difference gradient with absolute step sqrt(eps), H0 = I,
/// gtol 1e-5 on the infinity norm, maxiter 200 n, MINPACK-2 line search with
/// c1 = 1e-4, c2 = 0.9 and scipy's wolfe2 fallback).
pub fn minimize_bfgs(f: impl FnMut(&[f64]) -> f64, x0: &[f64]) -> BfgsResult {
    let n = x0.len();
    let mut obj = Objective::new(f, x0);
    let mut old_fval = obj.fun(x0);
    let mut gfk = obj.grad(x0).to_vec();

    let maxiter = 200 * n;
    let mut k = 0;
    let mut hk = vec![0.0; n * n];
    for i in 0..n {
        hk[i * n + i] = 1.0;
    }
    // Sets the initial step guess to dx ~ 1 (scipy's comment).
    let mut old_old_fval = old_fval + norm2(&gfk) / 2.0;
    let mut xk = x0.to_vec();
    let mut line_search_failed = false;
    let mut gnorm = inf_norm(&gfk);

    while gnorm > GTOL && k < maxiter {
        let pk: Vec<f64> = matvec(&hk, &gfk, n).into_iter().map(|v| -v).collect();
        let Some((ls, gfkp1)) = line_search_wolfe12(&mut obj, &xk, &pk, &gfk, old_fval, old_old_fval) else {
            line_search_failed = true;
            break;
        };
        old_old_fval = old_fval;
        old_fval = ls.phi;

        let alpha = ls.alpha;
        let sk: Vec<f64> = pk.iter().map(|p| alpha * p).collect();
        for (x, s) in xk.iter_mut().zip(&sk) {
            *x += s;
        }
        let gfkp1 = if ls.grad_at_alpha { gfkp1 } else { obj.grad(&xk).to_vec() };
        let yk: Vec<f64> = gfkp1.iter().zip(&gfk).map(|(a, b)| a - b).collect();
        gfk = gfkp1;
        k += 1;
        gnorm = inf_norm(&gfk);
        if gnorm <= GTOL {
            break;
        }
        // scipy's xrtol test with xrtol = 0: stops only on a zero step.
        if alpha * norm2(&pk) <= 0.0 * (0.0 + norm2(&xk)) {
            break;
        }
        if !old_fval.is_finite() {
            line_search_failed = true;
            break;
        }

        // BFGS inverse-Hessian update H = (I - rho s y^T) H (I - rho y s^T) + rho s s^T,
        // with scipy's guard rho = 1000 when y.s == 0.
        let rhok_inv = dot(&yk, &sk);
        let rhok = if rhok_inv == 0.0 { 1000.0 } else { 1.0 / rhok_inv };
        let eye = |i: usize, j: usize| if i == j { 1.0 } else { 0.0 };
        let mut a1 = vec![0.0; n * n];
        let mut a2 = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a1[i * n + j] = eye(i, j) - sk[i] * yk[j] * rhok;
                a2[i * n + j] = eye(i, j) - yk[i] * sk[j] * rhok;
            }
        }
        let mut h_new = matmul(&a1, &matmul(&hk, &a2, n), n);
        for i in 0..n {
            for j in 0..n {
                h_new[i * n + j] += rhok * sk[i] * sk[j];
            }
        }
        hk = h_new;
    }

    let success = !line_search_failed && k < maxiter && !(gnorm.is_nan() || old_fval.is_nan() || xk.iter().any(|v| v.is_nan()));
    BfgsResult { x: xk, fun: old_fval, nit: k, nfev: obj.nfev, success }
}

/// Unit tangent of the quadratic Bezier `p0 -> p1 -> p2` at `t` (0 or 1) as
/// svgpathtools computes it: `d = 2*((p1-p0)*(1-t) + (p2-p1)*t)`, `d/abs(d)`
/// with CPython complex arithmetic.
fn quad_unit_tangent(p0: C, p1: C, p2: C, t: f64) -> C {
    let w0 = C::new(1.0 - t, 0.0);
    let w1 = C::new(t, 0.0);
    let d = C::new(2.0, 0.0).mul(p1.sub(p0).mul(w0).add(p2.sub(p1).mul(w1)));
    match d.div(C::new(d.abs(), 0.0)) {
        Some(u) => u,
        // Zero derivative: svgpathtools takes the limit of d/|d|. In the edge
        // frame (p0 = 0, p2 = 1) this happens only for p1 = p0 at t = 0 or
        // p1 = p2 at t = 1, and the limit is the chord direction (1, 0).
        None => C::new(1.0, 0.0),
    }
}

/// The `_fit_tangents` objective in the edge frame: for the quadratic Bezier
/// (0,0) -> `cp` -> (1,0), `|T(0) - t0|^2 + |T(1) - t1|^2` over the given
/// targets, evaluated in svgpathtools/numpy order.
pub fn tangent_objective(cp: [f64; 2], t0: Option<[f64; 2]>, t1: Option<[f64; 2]>) -> f64 {
    let p0 = C::new(0.0, 0.0);
    let p1 = C::new(cp[0], cp[1]);
    let p2 = C::new(1.0, 0.0);
    // target = t[0] + 1j * t[1] (numpy float64 + Python complex)
    let target = |t: [f64; 2]| C::new(t[0], 0.0).add(C::new(0.0, 1.0).mul(C::new(t[1], 0.0)));
    let mut fin = 0.0;
    if let Some(t) = t0 {
        fin += sq_pow(quad_unit_tangent(p0, p1, p2, 0.0).sub(target(t)).abs());
    }
    if let Some(t) = t1 {
        fin += sq_pow(quad_unit_tangent(p0, p1, p2, 1.0).sub(target(t)).abs());
    }
    fin
}

/// Control point of the quadratic Bezier (0,0) -> cp -> (1,0) (edge frame)
/// that `curve_from_tangents` obtains: BFGS on [`tangent_objective`] from
/// `x0` (the call site's `initial_guess`, default `[0.5, 0]`). `t0`/`t1` are
/// the target tangents already in the edge frame and normalised.
pub fn fit_quadratic_tangents(t0: Option<[f64; 2]>, t1: Option<[f64; 2]>, x0: [f64; 2]) -> [f64; 2] {
    let r = minimize_bfgs(|x| tangent_objective([x[0], x[1]], t0, t1), &x0);
    [r.x[0], r.x[1]]
}

/// Closed-form two-tangent fit: the intersection of the ray from (0,0) along
/// `t0` with the ray from (1,0) along `-t1` (edge frame), i.e. the exact zero
/// of [`tangent_objective`]. `None` when the tangents are parallel or the rays
/// do not meet ahead of both ends (then the objective has no zero and only the
/// BFGS result is meaningful).
pub fn quadratic_from_two_tangents(t0: [f64; 2], t1: [f64; 2]) -> Option<[f64; 2]> {
    // Solve a * t0 + b * t1 = (1, 0) for a, b > 0 (Cramer's rule).
    let det = t0[0] * t1[1] - t0[1] * t1[0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let a = t1[1] / det;
    let b = -t0[1] / det;
    if a > 0.0 && b > 0.0 { Some([a * t0[0], a * t0[1]]) } else { None }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_bowl() {
        let r = minimize_bfgs(|x| (x[0] - 1.0).powi(2) + 10.0 * (x[1] + 2.0).powi(2), &[0.0, 0.0]);
        assert!(r.success);
        assert!((r.x[0] - 1.0).abs() < 1e-5 && (r.x[1] + 2.0).abs() < 1e-5, "{r:?}");
    }

    #[test]
    fn closed_form_zero() {
        let s = 0.5f64.sqrt();
        let cp = quadratic_from_two_tangents([s, s], [s, -s]).unwrap();
        assert!((cp[0] - 0.5).abs() < 1e-15 && (cp[1] - 0.5).abs() < 1e-15);
        assert!(tangent_objective(cp, Some([s, s]), Some([s, -s])) < 1e-30);
        assert!(quadratic_from_two_tangents([s, s], [s, s]).is_none());
    }
}
