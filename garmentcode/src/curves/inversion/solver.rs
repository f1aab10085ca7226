//! Sequential quadratic programming solver for the sleeve-opening / hood inversion.
//!
//! The reference objective is
//!   f(x) = F(x) + (max_k |k(t_k; x)|)^2,   t_k = k/69, k = 0..69,
//!   F(x) = (L(x) - L*)^2 + |T0(x) - t0|^2 + |T1(x) - t1|^2 + 0.001 x4^2,
//! over the 5 shifts x. The max makes f non-smooth and rippled: as the curvature peak
//! slides between samples the sampled max oscillates, giving many close local minima.
//! That is what makes the reference's finite-difference L-BFGS-B chaotic.
//!
//! The first stage is always the smooth problem in (x, z)
//!   minimise F(x) + z^2  subject to  z >= |k(t; x)|  for every t in [0, 1]
//! (the 70 samples plus every local curvature maximum, located by Newton's method in t):
//! the ripple-free problem, whose minimiser moves smoothly with the inputs. Then, by mode:
//! * `Proximal` (default): a fixed number of proximal steps on the reference objective
//!   ([`super::proximal`]): continuous in the inputs;
//! * `Reference`: polish on the reference's 70 samples to convergence (the same SQP with
//!   the samples as the constraint set), the exact local minimiser of the reference
//!   objective in that basin, which jumps where the basin switches;
//! * `RippleFree`: nothing.
//!
//! Each SQP stage minimises a quadratic model of the Lagrangian subject to the
//! linearised curvature bounds (a 6-unknown QP solved exactly by a dual active-set
//! method, the `qp` module; convexified along the active bounds' normals when needed), with
//! exact analytic derivatives (B' and B'' are linear in x, so curvature gradients and
//! Hessians are closed-form; the length uses a fixed 64-point Gauss-Legendre rule, smooth
//! in x and ~1e-14 accurate on these curves), globalised by Levenberg-Marquardt damping
//! judged on the true objective, with a second-order correction. Near the solution it
//! converges quadratically. Stage 1 starts from arms laid along the target tangents
//! (see `Setup::initial_guess`). No randomness, no threads: bit-for-bit reproducible.

use super::bezier::{V2, cross, dot};
use super::gauss::{GL64_T, GL64_W};
use super::objective::{END_REG, N_SAMPLES, chord_dir, unit};
use super::qp;

/// Number of unknowns: shifts of P1 (x, y), P2 (x, y) and of the end along the chord.
pub(crate) const NX: usize = 5;
/// The reference's curvature samples.
pub(crate) const NS: usize = N_SAMPLES;
/// At most this many refined curvature peaks (a cubic has at most a few).
pub(crate) const NPEAK: usize = 6;
/// Constraint slots: samples, then peaks.
pub(crate) const NC: usize = NS + NPEAK;
/// Hard cap on SQP iterations per stage (far above what the logged vectors need).
const MAX_ITER: usize = 200;
/// Max damping increases per iteration before giving up.
const MAX_TRIES: usize = 40;
/// Below this relative predicted decrease a rejected step is rounding noise: stop.
const NOISE: f64 = 1e-12;
/// Damping decrease after a very successful step.
const LM_DECREASE: f64 = 10.0;
/// Initial arm length of the inner control points, as a fraction of the target length.
const INIT_ARM: f64 = 0.45;
/// Stage 1 stops when the model predicts less than this relative decrease.
pub(crate) const TOL_STAGE1: f64 = 1e-8;
/// Stage 2 (and the ripple-free mode) stop at the rounding level.
pub(crate) const TOL_STAGE2: f64 = 1e-15;

pub(crate) type Mat = [[f64; NX]; NX];

/// Weights of B'(t) = sum_j w_j P_j.
fn w1(t: f64) -> [f64; 4] {
    let u = 1.0 - t;
    [-3.0 * u * u, 3.0 * u * u - 6.0 * u * t, 6.0 * u * t - 3.0 * t * t, 3.0 * t * t]
}

/// Weights of B''(t) = sum_j v_j P_j.
fn w2(t: f64) -> [f64; 4] {
    let u = 1.0 - t;
    [6.0 * u, -12.0 * u + 6.0 * t, 6.0 * u - 12.0 * t, 6.0 * t]
}

/// Weights of the constant B'''.
const W3: [f64; 4] = [-6.0, 18.0, -18.0, 6.0];

/// Derivative of sum_j w_j P_j with respect to the 5 unknowns.
fn dirs(w: &[f64; 4], d: V2) -> [V2; NX] {
    [[w[1], 0.0], [0.0, w[1]], [w[2], 0.0], [0.0, w[2]], [w[3] * d[0], w[3] * d[1]]]
}

fn comb(w: &[f64; 4], p: &[V2; 4]) -> V2 {
    [w[0] * p[0][0] + w[1] * p[1][0] + w[2] * p[2][0] + w[3] * p[3][0], w[0] * p[0][1] + w[1] * p[1][1] + w[2] * p[2][1] + w[3] * p[3][1]]
}

/// Value, gradient and Hessian (w.r.t. a) of |a/|a| - t|^2 = 2 - 2 t.a/|a| (t unit).
fn tangent_term(a: V2, t: V2) -> (f64, V2, [V2; 2]) {
    let r = dot(a, a).sqrt();
    let ta = dot(t, a);
    let r3 = r * r * r;
    let r5 = r3 * r * r;
    let mut g = [0.0; 2];
    let mut h = [[0.0; 2]; 2];
    for i in 0..2 {
        g[i] = -2.0 * (t[i] / r - ta * a[i] / r3);
        for j in 0..2 {
            let id = if i == j { 1.0 } else { 0.0 };
            h[i][j] = 2.0 * (t[i] * a[j] + a[i] * t[j] + ta * id) / r3 - 6.0 * ta * a[i] * a[j] / r5;
        }
    }
    (2.0 - 2.0 * ta / r, g, h)
}

/// Curve derivative data at one parameter t that does not depend on x.
#[derive(Clone, Copy)]
pub(crate) struct Sample {
    t: f64,
    /// B'(t) and B''(t) as weights on P0..P3.
    w1: [f64; 4],
    w2: [f64; 4],
    /// dB'/dx_i and dB''/dx_i (constant: B', B'' are linear in x).
    e1: [V2; NX],
    e2: [V2; NX],
}

impl Sample {
    fn new(t: f64, dir: V2) -> Sample {
        let w1 = w1(t);
        let w2 = w2(t);
        Sample { t, w1, w2, e1: dirs(&w1, dir), e2: dirs(&w2, dir) }
    }

    /// Signed curvature and its gradient in x.
    fn curv_grad(&self, p: &[V2; 4]) -> (f64, [f64; NX]) {
        let b1 = comb(&self.w1, p);
        let b2 = comb(&self.w2, p);
        let c = cross(b1, b2);
        let r = 1.0 / dot(b1, b1).sqrt();
        let r3 = r * r * r;
        let r5 = r3 * r * r;
        let mut g = [0.0; NX];
        for i in 0..NX {
            let dc = cross(self.e1[i], b2) + cross(b1, self.e2[i]);
            let dn = 2.0 * dot(b1, self.e1[i]);
            g[i] = dc * r3 - 1.5 * c * r5 * dn;
        }
        (c * r3, g)
    }

    /// Signed curvature only.
    fn curv(&self, p: &[V2; 4]) -> f64 {
        let b1 = comb(&self.w1, p);
        let b2 = comb(&self.w2, p);
        let n = dot(b1, b1);
        cross(b1, b2) / (n * n.sqrt())
    }

    /// Hessian of the signed curvature in x (closed form: k = c n^-3/2 with c, n
    /// bilinear/quadratic in x).
    fn curv_hess(&self, p: &[V2; 4]) -> Mat {
        let b1 = comb(&self.w1, p);
        let b2 = comb(&self.w2, p);
        let (e1, e2) = (&self.e1, &self.e2);
        let c = cross(b1, b2);
        let r = 1.0 / dot(b1, b1).sqrt();
        let r3 = r * r * r;
        let r5 = r3 * r * r;
        let r7 = r5 * r * r;
        let mut dc = [0.0; NX];
        let mut dn = [0.0; NX];
        for i in 0..NX {
            dc[i] = cross(e1[i], b2) + cross(b1, e2[i]);
            dn[i] = 2.0 * dot(b1, e1[i]);
        }
        let mut h = [[0.0; NX]; NX];
        for i in 0..NX {
            for j in i..NX {
                let ddc = cross(e1[i], e2[j]) + cross(e1[j], e2[i]);
                let ddn = 2.0 * dot(e1[i], e1[j]);
                h[i][j] = ddc * r3 - 1.5 * r5 * (dc[i] * dn[j] + dc[j] * dn[i]) - 1.5 * c * r5 * ddn + 3.75 * c * r7 * dn[i] * dn[j];
                h[j][i] = h[i][j];
            }
        }
        h
    }
}

/// Signed curvature and its first two t-derivatives at t (for locating peaks).
fn curv_t(t: f64, p: &[V2; 4]) -> (f64, f64, f64) {
    let b1 = comb(&w1(t), p);
    let b2 = comb(&w2(t), p);
    let b3 = comb(&W3, p);
    let c = cross(b1, b2);
    let ct = cross(b1, b3);
    let ctt = cross(b2, b3);
    let n = dot(b1, b1);
    let nt = 2.0 * dot(b1, b2);
    let ntt = 2.0 * dot(b2, b2) + 2.0 * dot(b1, b3);
    let r = 1.0 / n.sqrt();
    let r3 = r * r * r;
    let r5 = r3 * r * r;
    let r7 = r5 * r * r;
    let k = c * r3;
    let kt = ct * r3 - 1.5 * c * nt * r5;
    let ktt = ctt * r3 - 3.0 * ct * nt * r5 - 1.5 * c * ntt * r5 + 3.75 * c * nt * nt * r7;
    (k, kt, ktt)
}

/// For a curvature peak at sample s: d/dt of grad_x k, and d2k/dt2. The max over t of k
/// has Hessian Hess_x k - k_xt k_xt^T / k_tt (the peak moves with x).
pub(crate) fn curv_xt(s: &Sample, e3: &[V2; NX], p: &[V2; 4]) -> ([f64; NX], f64) {
    let b1 = comb(&s.w1, p);
    let b2 = comb(&s.w2, p);
    let b3 = comb(&W3, p);
    let c = cross(b1, b2);
    let ct = cross(b1, b3);
    let ctt = cross(b2, b3);
    let n = dot(b1, b1);
    let nt = 2.0 * dot(b1, b2);
    let ntt = 2.0 * dot(b2, b2) + 2.0 * dot(b1, b3);
    let r = 1.0 / n.sqrt();
    let r3 = r * r * r;
    let r5 = r3 * r * r;
    let r7 = r5 * r * r;
    let ktt = ctt * r3 - 3.0 * ct * nt * r5 - 1.5 * c * ntt * r5 + 3.75 * c * nt * nt * r7;
    let mut kxt = [0.0; NX];
    for i in 0..NX {
        let (e1, e2) = (s.e1[i], s.e2[i]);
        let dc = cross(e1, b2) + cross(b1, e2);
        let dn = 2.0 * dot(b1, e1);
        let dct = cross(e1, b3) + cross(b1, e3[i]);
        let dnt = 2.0 * (dot(b2, e1) + dot(b1, e2));
        // d/dt [dc r^3 - 1.5 c dn r^5]
        kxt[i] = dct * r3 - 1.5 * dc * nt * r5 - 1.5 * (ct * dn * r5 + c * dnt * r5 - 2.5 * c * dn * nt * r7);
    }
    (kxt, ktt)
}

/// Which curvature bound the solver enforces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bound {
    /// The reference's 70 samples only.
    Samples,
    /// Every t in [0, 1] (samples plus refined peaks): the ripple-free objective.
    Envelope,
}

/// Per-call constants: initial curve, targets, sample data.
pub(crate) struct Setup {
    p: [V2; 4],
    dir: V2,
    t0: V2,
    t1: V2,
    target: f64,
    /// The reference's samples t_k = k/69 (as numpy's linspace computes them).
    grid: [Sample; NS],
    /// dB'''/dx_i.
    pub(crate) e3: [V2; NX],
    /// The length quadrature's tables.
    quad: &'static Quadrature,
}

/// Tables of the fixed-rule length quadrature: the same for every call.
pub(crate) struct Quadrature {
    /// Bernstein weights of B' at the quadrature nodes, and dB'/dx_i there.
    gw1: [[f64; 4]; 64],
    /// dB'/dx_i at node q is c_i(q) * v_i with v_i in {ex, ey, ex, ey, dir}:
    /// gc[q][i] = weight * c_i, gcc[q][ij] = weight * c_i * c_j (upper triangle, row-major).
    gc: [[f64; NX]; 64],
    gcc: [[f64; 15]; 64],
}

static QUADRATURE: std::sync::LazyLock<Quadrature> = std::sync::LazyLock::new(|| {
    let gw1: [[f64; 4]; 64] = std::array::from_fn(|q| w1(GL64_T[q]));
    let gc: [[f64; NX]; 64] = std::array::from_fn(|q| {
        let w = &gw1[q];
        [w[1], w[1], w[2], w[2], w[3]].map(|c| GL64_W[q] * c)
    });
    let gcc = std::array::from_fn(|q| {
        let w = &gw1[q];
        let c = [w[1], w[1], w[2], w[2], w[3]];
        let mut out = [0.0; 15];
        let mut n = 0;
        for i in 0..NX {
            for j in i..NX {
                out[n] = GL64_W[q] * c[i] * c[j];
                n += 1;
            }
        }
        out
    });
    Quadrature { gw1, gc, gcc }
});

/// The curvature constraints at one iterate: 70 samples, then refined peaks.
#[derive(Clone, Copy)]
pub(crate) struct Cons {
    /// Peak samples (slots NS..NS+npeak).
    pub(crate) peaks: [Sample; NPEAK],
    pub(crate) npeak: usize,
    /// Signed curvature and gradient per slot; disabled slots are never binding.
    pub(crate) kap: [f64; NC],
    pub(crate) grad: [[f64; NX]; NC],
    pub(crate) enabled: [bool; NC],
}

impl Setup {
    pub(crate) fn new(cps: [V2; 4], t0: V2, t1: V2, target: f64) -> Setup {
        let dir = chord_dir(&cps);
        let step = 1.0 / (NS - 1) as f64;
        let grid = std::array::from_fn(|k| Sample::new(if k == NS - 1 { 1.0 } else { k as f64 * step }, dir));
        Setup { p: cps, dir, t0: unit(t0), t1: unit(t1), target, grid, e3: dirs(&W3, dir), quad: &QUADRATURE }
    }

    /// Control points for shift x.
    pub(crate) fn points(&self, x: &[f64; NX]) -> [V2; 4] {
        let p = &self.p;
        [
            p[0],
            [p[1][0] + x[0], p[1][1] + x[1]],
            [p[2][0] + x[2], p[2][1] + x[3]],
            [p[3][0] + self.dir[0] * x[4], p[3][1] + self.dir[1] * x[4]],
        ]
    }

    /// Starting point: inner control points on the target tangents, each at 0.45 x the
    /// target length from its end point (both tangent terms vanish; the arm length is an
    /// empirical middle between arc-like sleeves and S-shaped hoods), end not moved.
    /// A continuous function of the inputs, and closer to the optimum than the input curve.
    pub(crate) fn initial_guess(&self) -> [f64; NX] {
        let (p, h) = (&self.p, INIT_ARM * self.target);
        [
            p[0][0] + h * self.t0[0] - p[1][0],
            p[0][1] + h * self.t0[1] - p[1][1],
            p[3][0] - h * self.t1[0] - p[2][0],
            p[3][1] - h * self.t1[1] - p[2][1],
            0.0,
        ]
    }

    /// Smooth part F(x) (length, tangents, end regulariser), value only.
    fn smooth_value(&self, x: &[f64; NX], p: &[V2; 4]) -> f64 {
        let mut len = 0.0;
        for q in 0..64 {
            let b1 = comb(&self.quad.gw1[q], p);
            len += GL64_W[q] * dot(b1, b1).sqrt();
        }
        let a = [p[1][0] - p[0][0], p[1][1] - p[0][1]];
        let b = [p[3][0] - p[2][0], p[3][1] - p[2][1]];
        let dl = len - self.target;
        dl * dl + tangent_term(a, self.t0).0 + tangent_term(b, self.t1).0 + END_REG * x[4] * x[4]
    }

    /// Smooth part F(x) with gradient and (full, symmetric) Hessian.
    pub(crate) fn smooth_full(&self, x: &[f64; NX], p: &[V2; 4]) -> (f64, [f64; NX], Mat) {
        let mut g = [0.0; NX];
        let mut h = [[0.0; NX]; NX];
        // Length and its derivatives by the fixed quadrature rule. With u = B'/|B'|,
        // d|B'|/dx_i = c_i u.v_i and d2|B'|/dx_i dx_j = c_i c_j v_i^T (I - u u^T) v_j / |B'|.
        let d = self.dir;
        let mut len = 0.0;
        let mut gl = [0.0; NX];
        let mut hl = [0.0; 15];
        for q in 0..64 {
            let b1 = comb(&self.quad.gw1[q], p);
            let s = dot(b1, b1).sqrt();
            len += GL64_W[q] * s;
            let (ux, uy) = (b1[0] / s, b1[1] / s);
            let ud = ux * d[0] + uy * d[1];
            let uv = [ux, uy, ux, uy, ud];
            let c = &self.quad.gc[q];
            for i in 0..NX {
                gl[i] += c[i] * uv[i];
            }
            // v_i^T M v_j for M = (I - u u^T) / s and v in {ex, ey, dir}.
            let (mxx, mxy, myy) = ((1.0 - ux * ux) / s, -ux * uy / s, (1.0 - uy * uy) / s);
            let (mxd, myd) = (mxx * d[0] + mxy * d[1], mxy * d[0] + myy * d[1]);
            let mdd = d[0] * mxd + d[1] * myd;
            let m = [
                mxx, mxy, mxx, mxy, mxd, // i = 0 (ex) with j = 0..4
                myy, mxy, myy, myd, // i = 1 (ey) with j = 1..4
                mxx, mxy, mxd, // i = 2 (ex) with j = 2..4
                myy, myd, // i = 3 (ey) with j = 3..4
                mdd, // i = 4 (dir) with j = 4
            ];
            let cc = &self.quad.gcc[q];
            for n in 0..15 {
                hl[n] += cc[n] * m[n];
            }
        }
        let hl = {
            let mut full = [[0.0; NX]; NX];
            let mut n = 0;
            for i in 0..NX {
                for j in i..NX {
                    full[i][j] = hl[n];
                    n += 1;
                }
            }
            full
        };
        let dl = len - self.target;
        for i in 0..NX {
            g[i] += 2.0 * dl * gl[i];
            for j in i..NX {
                h[i][j] += 2.0 * gl[i] * gl[j] + 2.0 * dl * hl[i][j];
            }
        }
        // Start tangent: a = P1 - P0 has identity Jacobian in (x0, x1).
        let a = [p[1][0] - p[0][0], p[1][1] - p[0][1]];
        let (v0, g0, h0) = tangent_term(a, self.t0);
        for i in 0..2 {
            g[i] += g0[i];
            for j in i..2 {
                h[i][j] += h0[i][j];
            }
        }
        // End tangent: b = P3 - P2 depends on x2, x3 (minus identity) and x4 (along dir).
        let b = [p[3][0] - p[2][0], p[3][1] - p[2][1]];
        let (v1, g1, h1) = tangent_term(b, self.t1);
        let jb: [V2; NX] = [[0.0, 0.0], [0.0, 0.0], [-1.0, 0.0], [0.0, -1.0], self.dir];
        for i in 2..NX {
            g[i] += g1[0] * jb[i][0] + g1[1] * jb[i][1];
            for j in i..NX {
                let mut s = 0.0;
                for r in 0..2 {
                    for c in 0..2 {
                        s += jb[i][r] * h1[r][c] * jb[j][c];
                    }
                }
                h[i][j] += s;
            }
        }
        g[4] += 2.0 * END_REG * x[4];
        h[4][4] += 2.0 * END_REG;
        for i in 0..NX {
            for j in 0..i {
                h[i][j] = h[j][i];
            }
        }
        (dl * dl + v0 + v1 + END_REG * x[4] * x[4], g, h)
    }

    /// Gradient of the smooth part F(x) only (the proximal steps need no Hessian).
    pub(crate) fn smooth_grad(&self, x: &[f64; NX], p: &[V2; 4]) -> [f64; NX] {
        let d = self.dir;
        let mut len = 0.0;
        let mut gl = [0.0; NX];
        for q in 0..64 {
            let b1 = comb(&self.quad.gw1[q], p);
            let s = dot(b1, b1).sqrt();
            len += GL64_W[q] * s;
            let (ux, uy) = (b1[0] / s, b1[1] / s);
            let uv = [ux, uy, ux, uy, ux * d[0] + uy * d[1]];
            let c = &self.quad.gc[q];
            for i in 0..NX {
                gl[i] += c[i] * uv[i];
            }
        }
        let dl = len - self.target;
        let mut g: [f64; NX] = std::array::from_fn(|i| 2.0 * dl * gl[i]);
        let a = [p[1][0] - p[0][0], p[1][1] - p[0][1]];
        let (_, g0, _) = tangent_term(a, self.t0);
        g[0] += g0[0];
        g[1] += g0[1];
        let b = [p[3][0] - p[2][0], p[3][1] - p[2][1]];
        let (_, g1, _) = tangent_term(b, self.t1);
        g[2] -= g1[0];
        g[3] -= g1[1];
        g[4] += g1[0] * d[0] + g1[1] * d[1] + 2.0 * END_REG * x[4];
        g
    }

    /// Local maxima of |k| over t near grid maxima, refined by Newton's method in t.
    /// Returns the peaks and marks the grid samples of each peak's bracket as disabled (the
    /// peak dominates them).
    fn find_peaks(&self, p: &[V2; 4], kap: &[f64; NS], enabled: &mut [bool; NC]) -> ([Sample; NPEAK], usize) {
        let mut peaks = [self.grid[0]; NPEAK];
        let mut n = 0;
        for k in 0..NS {
            let a = kap[k].abs();
            let left_ok = k == 0 || a > kap[k - 1].abs();
            let right_ok = k == NS - 1 || a >= kap[k + 1].abs();
            if !(left_ok && right_ok) || n == NPEAK {
                continue;
            }
            let lo = self.grid[k.saturating_sub(1)].t;
            let hi = self.grid[(k + 1).min(NS - 1)].t;
            let sg = kap[k].signum();
            let mut t = self.grid[k].t;
            for _ in 0..8 {
                let (_, kt, ktt) = curv_t(t, p);
                let (gt, gtt) = (sg * kt, sg * ktt);
                if !(gtt < 0.0) {
                    break;
                }
                let tn = (t - gt / gtt).clamp(lo, hi);
                let done = (tn - t).abs() <= 1e-15;
                t = tn;
                if done {
                    break;
                }
            }
            // Every refined maximum is kept, also one that sits on a sample (value equal to
            // the grid value up to rounding): the constraint set, and the multipliers the
            // proximal stage takes from it, must not depend on rounding there.
            peaks[n] = Sample::new(t, self.dir);
            n += 1;
            for j in k.saturating_sub(1)..=(k + 1).min(NS - 1) {
                enabled[j] = false;
            }
        }
        (peaks, n)
    }

    /// Curvature constraints at p (with refined peaks for `Bound::Envelope`), values and
    /// gradients.
    pub(crate) fn constraints(&self, p: &[V2; 4], bound: Bound) -> Cons {
        let mut c = Cons { peaks: [self.grid[0]; NPEAK], npeak: 0, kap: [0.0; NC], grad: [[0.0; NX]; NC], enabled: [false; NC] };
        for k in 0..NS {
            let (v, g) = self.grid[k].curv_grad(p);
            c.kap[k] = v;
            c.grad[k] = g;
            c.enabled[k] = true;
        }
        if bound == Bound::Envelope {
            let mut kap = [0.0; NS];
            kap.copy_from_slice(&c.kap[..NS]);
            let (peaks, n) = self.find_peaks(p, &kap, &mut c.enabled);
            c.peaks = peaks;
            c.npeak = n;
            for j in 0..n {
                let (v, g) = peaks[j].curv_grad(p);
                c.kap[NS + j] = v;
                c.grad[NS + j] = g;
                c.enabled[NS + j] = true;
            }
        }
        c
    }

    /// For each sample whose |k| is at least `frac` of the largest sampled |k|: |k| and the
    /// gradient of |k| (sign(k) grad k); None for the others (their gradients are not computed).
    pub(crate) fn sample_bounds_near_max(&self, p: &[V2; 4], frac: f64) -> [Option<(f64, [f64; NX])>; NS] {
        // Compare squared curvatures c^2 / n^3 (no square roots for the samples left out).
        let mut k2 = [0.0; NS];
        let mut top = 0.0f64;
        for k in 0..NS {
            let b1 = comb(&self.grid[k].w1, p);
            let b2 = comb(&self.grid[k].w2, p);
            let (c, n) = (cross(b1, b2), dot(b1, b1));
            k2[k] = c * c / (n * n * n);
            top = top.max(k2[k]);
        }
        std::array::from_fn(|k| {
            (k2[k] >= frac * frac * top).then(|| {
                let (v, g) = self.grid[k].curv_grad(p);
                (v.abs(), g.map(|gi| v.signum() * gi))
            })
        })
    }

    /// The objective as the solver sees it (fixed-rule length; max of |k| over the whole
    /// curve for `Bound::Envelope`, else over the 70 samples).
    pub(crate) fn objective(&self, x: &[f64; NX], bound: Bound) -> f64 {
        let p = self.points(x);
        let mut kap = [0.0; NS];
        let mut zmax = 0.0f64;
        for k in 0..NS {
            kap[k] = self.grid[k].curv(&p);
            zmax = zmax.max(kap[k].abs());
        }
        if bound == Bound::Envelope {
            let mut en = [true; NC];
            let (peaks, n) = self.find_peaks(&p, &kap, &mut en);
            for s in &peaks[..n] {
                zmax = zmax.max(s.curv(&p).abs());
            }
        }
        let f = self.smooth_value(x, &p) + zmax * zmax;
        if f.is_finite() { f } else { f64::INFINITY }
    }

    /// |k| at the constraint locations of `c`, evaluated at p (for the second-order
    /// correction).
    fn values_at(&self, c: &Cons, p: &[V2; 4]) -> [f64; NC] {
        let mut v = [0.0; NC];
        for k in 0..NS {
            v[k] = self.grid[k].curv(p).abs();
        }
        for j in 0..c.npeak {
            v[NS + j] = c.peaks[j].curv(p).abs();
        }
        v
    }
}

/// Diagnostics of one solve.
#[derive(Clone, Copy, Debug, Default)]
pub struct Stats {
    /// SQP iterations of stage 1 (ripple-free) and stage 2 (polish, or proximal steps).
    pub iterations: [usize; 2],
    /// Objective evaluations at trial points.
    pub trials: usize,
    /// Second-order corrections accepted.
    pub soc: usize,
    /// Max-norm of the Lagrangian gradient at the end.
    pub kkt: f64,
    /// True if the SQP stages stopped because the model predicted no further decrease.
    pub converged: bool,
    /// Proximal steps cut short by a QP breakdown (never seen; the map stays continuous
    /// only without them).
    pub qp_failures: usize,
}

/// Which problem to solve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Default: the ripple-free solution refined by [`super::proximal::STEPS`] proximal
    /// steps on the reference objective. Continuous in the inputs, never worse than the
    /// reference on the logged calls; steep (not discontinuous) where a curvature peak
    /// crosses a sample.
    Proximal,
    /// The reference objective (70 curvature samples) minimised to convergence, in the basin
    /// picked by the ripple-free solution: never worse than the reference on its own
    /// objective, but jumps (up to ~0.4 cm) where the chosen ripple basin switches.
    Reference,
    /// The ripple-free objective (max curvature over the whole curve): continuous and
    /// piecewise smooth in the inputs, slightly higher reference objective at times.
    RippleFree,
}

/// Lagrangian Hessian: the smooth part plus the multiplier-weighted curvature Hessians of
/// the bounds that were active in the previous QP (at their locations then). A peak's bound
/// is the max over t, whose Hessian has the extra term -k_xt k_xt^T / k_tt.
pub(crate) fn lagrangian_hessian(s: &Setup, p: &[V2; 4], hf: &Mat, mult: &[f64; NC], prev: &Cons) -> Mat {
    let mut bm = *hf;
    for j in 0..NC {
        if mult[j] <= 0.0 {
            continue;
        }
        let smp = if j < NS { &s.grid[j] } else { &prev.peaks[j - NS] };
        let sg = prev.kap[j].signum();
        let mut hk = smp.curv_hess(p);
        if j >= NS {
            let (kxt, ktt) = curv_xt(smp, &s.e3, p);
            if ktt * sg < 0.0 {
                for a in 0..NX {
                    for b in 0..NX {
                        hk[a][b] -= kxt[a] * kxt[b] / ktt;
                    }
                }
            }
        }
        for a in 0..NX {
            for b in 0..NX {
                bm[a][b] += mult[j] * sg * hk[a][b];
            }
        }
    }
    bm
}

/// The linearised bounds as QP constraints in y = (d, zeta):
/// zeta - s_j grad_j . d - |k_j| >= 0 (disabled slots: 0 . y + 1 >= 0, never binding).
pub(crate) fn linearised_bounds(c: &Cons) -> ([[f64; qp::N]; NC], [f64; NC]) {
    let mut ca = [[0.0; qp::N]; NC];
    let mut cb = [1.0; NC];
    for j in 0..NC {
        if c.enabled[j] {
            let sg = c.kap[j].signum();
            for i in 0..NX {
                ca[j][i] = -sg * c.grad[j][i];
            }
            ca[j][NX] = 1.0;
            cb[j] = -c.kap[j].abs();
        }
    }
    (ca, cb)
}

/// A convex version of the QP model: the Lagrangian Hessian may be indefinite along the
/// normals of the active bounds (only its restriction to their null space must be
/// positive). Adding rho * sum (a_j.y + b_j)^2 over the bounds active last time keeps the
/// QP's minimiser on that face unchanged but makes the QP convex. Returns G^-1 and the
/// shifted linear term, or None if no rho makes G positive definite.
fn convexify(
    g: &qp::MatN,
    g0: &[f64; qp::N],
    ca: &[[f64; qp::N]; NC],
    cb: &[f64; NC],
    active: &[bool; NC],
) -> Option<(qp::MatN, [f64; qp::N])> {
    let any = active.iter().any(|&a| a);
    for rho in [0.0, 1.0, 1e3, 1e6] {
        if rho > 0.0 && !any {
            break;
        }
        let (mut gr, mut g0r) = (*g, *g0);
        for j in 0..NC {
            if rho > 0.0 && active[j] {
                for a in 0..qp::N {
                    g0r[a] += rho * cb[j] * ca[j][a];
                    for b in 0..qp::N {
                        gr[a][b] += rho * ca[j][a] * ca[j][b];
                    }
                }
            }
        }
        if let Some(l) = qp::cholesky(&gr, qp::N) {
            return Some((qp::inverse_from_cholesky(&l), g0r));
        }
    }
    None
}

/// Result of one SQP run: the final point, whether it stopped on the convergence test,
/// and the multipliers of the last accepted QP with the constraint set they belong to.
pub(crate) struct RunOut {
    pub(crate) x: [f64; NX],
    pub(crate) ok: bool,
    pub(crate) mult: [f64; NC],
    pub(crate) prev: Option<Cons>,
}

/// SQP from `x0` on the objective with the curvature bound `bound`.
pub(crate) fn run(s: &Setup, x0: [f64; NX], bound: Bound, tol: f64, stage: usize, st: &mut Stats, trace: bool) -> RunOut {
    let mut x = x0;
    let mut f = s.objective(&x, bound);
    // Multipliers of the last accepted QP and the constraint set they belong to.
    let mut mult = [0.0; NC];
    let mut prev: Option<Cons> = None;
    // Levenberg-Marquardt damping (0 = plain SQP step).
    let mut lm = 0.0f64;
    for iter in 0..MAX_ITER {
        st.iterations[stage] = iter + 1;
        let p = s.points(&x);
        let (fs, gf, hf) = s.smooth_full(&x, &p);
        let cons = s.constraints(&p, bound);
        let lm_floor = 1e-6 * (0..NX).fold(1e-12f64, |a, i| a.max(hf[i][i].abs()));
        let bm = match &prev {
            Some(pc) => lagrangian_hessian(s, &p, &hf, &mult, pc),
            None => hf,
        };
        // KKT residual with the current multipliers (diagnostic).
        let mut kkt = gf;
        for j in (0..NC).filter(|&j| cons.enabled[j]) {
            for i in 0..NX {
                kkt[i] += mult[j] * cons.kap[j].signum() * cons.grad[j][i];
            }
        }
        st.kkt = kkt.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let (ca, cb) = linearised_bounds(&cons);
        let mut g0 = [0.0; qp::N];
        g0[..NX].copy_from_slice(&gf);
        let mut active = [false; NC];
        for j in 0..NC {
            active[j] = prev.is_some() && mult[j] > 0.0 && cons.enabled[j];
        }
        let mut accepted = false;
        for _ in 0..MAX_TRIES {
            // Damped model Hessian, block diagonal with the z^2 term.
            let mut bt = [[0.0; qp::N]; qp::N];
            for i in 0..NX {
                bt[i][..NX].copy_from_slice(&bm[i]);
                bt[i][i] += lm;
            }
            bt[NX][NX] = 2.0;
            let Some((ginv, g0r)) = convexify(&bt, &g0, &ca, &cb, &active) else {
                lm = (4.0 * lm).max(lm_floor);
                continue;
            };
            let Some(sol) = qp::solve(&ginv, &g0r, &ca, &cb) else {
                lm = (4.0 * lm).max(lm_floor);
                continue;
            };
            let mut d = [0.0; NX];
            d.copy_from_slice(&sol.y[..NX]);
            // Predicted objective at the step (the convexifying penalty vanishes on the
            // active face, so it is left out).
            let mut quad = 0.0;
            for i in 0..NX {
                for j in 0..NX {
                    quad += d[i] * bt[i][j] * d[j];
                }
            }
            let model = fs + (0..NX).map(|i| gf[i] * d[i]).sum::<f64>() + 0.5 * quad + sol.y[NX] * sol.y[NX];
            let pred = f - model;
            if !(pred > tol * f) {
                return RunOut { x, ok: true, mult, prev };
            }
            let mut xt = x;
            for i in 0..NX {
                xt[i] += d[i];
            }
            st.trials += 1;
            let mut ft = s.objective(&xt, bound);
            let mut rho = (f - ft) / pred;
            if rho < 0.1 && ft.is_finite() {
                // Second-order correction: re-linearise the bounds around the actual
                // curvature at x + d and re-solve (against the Maratos effect).
                let kt = s.values_at(&cons, &s.points(&xt));
                let mut cb2 = cb;
                for j in (0..NC).filter(|&j| cons.enabled[j]) {
                    let lin: f64 = (0..NX).map(|i| ca[j][i] * d[i]).sum();
                    cb2[j] = -(kt[j] + lin);
                }
                if let Some(sol2) = qp::solve(&ginv, &g0r, &ca, &cb2) {
                    let mut xs = x;
                    for i in 0..NX {
                        xs[i] += sol2.y[i];
                    }
                    st.trials += 1;
                    let f2 = s.objective(&xs, bound);
                    if (f - f2) / pred >= 0.1 {
                        st.soc += 1;
                        (xt, ft, rho) = (xs, f2, (f - f2) / pred);
                    }
                }
            }
            if trace {
                eprintln!(
                    "s{stage} it {iter:3} f {f:.12e} lm {lm:.2e} pred {pred:.2e} rho {rho:.4} |d| {:.2e} kkt {:.2e} act {:?}",
                    d.iter().fold(0.0f64, |a, v| a.max(v.abs())),
                    st.kkt,
                    (0..NC)
                        .filter(|&j| sol.mult[j] > 0.0)
                        .map(|j| 69.0 * if j < NS { s.grid[j].t } else { cons.peaks[j - NS].t })
                        .collect::<Vec<_>>()
                );
            }
            if rho >= 0.1 {
                (x, f, mult, prev) = (xt, ft, sol.mult, Some(cons));
                if rho > 0.75 {
                    lm = if lm <= lm_floor { 0.0 } else { lm / LM_DECREASE };
                }
                accepted = true;
                break;
            }
            if pred <= NOISE * f {
                // Nothing left to gain above rounding noise (f has ~1e-17 absolute noise).
                return RunOut { x, ok: true, mult, prev };
            }
            // Rejected: damp harder. Besides the usual x4, make the damping at least 3x the
            // model curvature along the rejected step, which shortens a step that ran along
            // a flat direction by ~4x at once instead of after many x4 rounds.
            let dd: f64 = d.iter().map(|v| v * v).sum();
            lm = (4.0 * lm).max(lm_floor).max(3.0 * quad / dd.max(1e-300));
        }
        if !accepted {
            return RunOut { x, ok: false, mult, prev };
        }
    }
    RunOut { x, ok: false, mult, prev }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup() -> Setup {
        // A T-shirt-like sleeve inversion (initial curve and targets).
        let cps = [[10.03, 24.0], [-0.06, 21.15], [11.93, 10.12], [3.74, -1.24]];
        Setup::new(cps, [0.0, -1.0], [-0.22, -0.97], 29.1)
    }

    const X: [f64; NX] = [3.0, -5.0, -2.0, -1.5, 0.7];

    fn rel(a: f64, b: f64, scale: f64) -> f64 {
        (a - b).abs() / scale.max(1e-300)
    }

    #[test]
    fn smooth_part_derivatives_match_finite_differences() {
        let s = setup();
        let (f, g, h) = s.smooth_full(&X, &s.points(&X));
        assert!(rel(f, s.smooth_value(&X, &s.points(&X)), f) < 1e-12);
        let e = 1e-6;
        for i in 0..NX {
            let (mut xp, mut xm) = (X, X);
            xp[i] += e;
            xm[i] -= e;
            let fd = (s.smooth_value(&xp, &s.points(&xp)) - s.smooth_value(&xm, &s.points(&xm))) / (2.0 * e);
            assert!(rel(fd, g[i], g[i].abs() + 1e-3) < 1e-6, "grad {i}: {fd} vs {}", g[i]);
            let (_, gp, _) = s.smooth_full(&xp, &s.points(&xp));
            let (_, gm, _) = s.smooth_full(&xm, &s.points(&xm));
            for j in 0..NX {
                let fd = (gp[j] - gm[j]) / (2.0 * e);
                assert!(rel(fd, h[i][j], h[i][j].abs() + 1e-3) < 1e-6, "hess {i}{j}: {fd} vs {}", h[i][j]);
            }
        }
    }

    #[test]
    fn smooth_gradient_matches_full() {
        let s = setup();
        let p = s.points(&X);
        let (_, g, _) = s.smooth_full(&X, &p);
        let g2 = s.smooth_grad(&X, &p);
        for i in 0..NX {
            assert!(rel(g[i], g2[i], g[i].abs() + 1e-12) < 1e-13, "{i}: {} vs {}", g[i], g2[i]);
        }
    }

    #[test]
    fn curvature_derivatives_match_finite_differences() {
        let s = setup();
        let p = s.points(&X);
        let e = 1e-6;
        for k in [0, 17, 40, 69] {
            let smp = &s.grid[k];
            let (kap, g) = smp.curv_grad(&p);
            assert!(rel(kap, smp.curv(&p), kap.abs()) < 1e-13);
            let h = smp.curv_hess(&p);
            for i in 0..NX {
                let (mut xp, mut xm) = (X, X);
                xp[i] += e;
                xm[i] -= e;
                let (pp, pm) = (s.points(&xp), s.points(&xm));
                let fd = (smp.curv(&pp) - smp.curv(&pm)) / (2.0 * e);
                assert!(rel(fd, g[i], g[i].abs() + 1e-4) < 1e-6);
                let (gp, gm) = (smp.curv_grad(&pp).1, smp.curv_grad(&pm).1);
                for j in 0..NX {
                    let fd = (gp[j] - gm[j]) / (2.0 * e);
                    assert!(rel(fd, h[i][j], h[i][j].abs() + 1e-5) < 1e-6, "k {k} hess {i}{j}");
                }
            }
        }
    }

    #[test]
    fn curvature_t_derivatives_match_finite_differences() {
        let s = setup();
        let p = s.points(&X);
        let e = 1e-6;
        for t in [0.1, 0.37, 0.8] {
            let (k, kt, ktt) = curv_t(t, &p);
            let smp = Sample::new(t, s.dir);
            assert!(rel(k, smp.curv(&p), k.abs()) < 1e-12);
            let (kp, ktp, _) = curv_t(t + e, &p);
            let (km, ktm, _) = curv_t(t - e, &p);
            assert!(rel((kp - km) / (2.0 * e), kt, kt.abs() + 1e-4) < 1e-6);
            assert!(rel((ktp - ktm) / (2.0 * e), ktt, ktt.abs() + 1e-4) < 1e-6);
            let (kxt, ktt2) = curv_xt(&smp, &s.e3, &p);
            assert!(rel(ktt2, ktt, ktt.abs()) < 1e-12);
            let gp = Sample::new(t + e, s.dir).curv_grad(&p).1;
            let gm = Sample::new(t - e, s.dir).curv_grad(&p).1;
            for i in 0..NX {
                let fd = (gp[i] - gm[i]) / (2.0 * e);
                assert!(rel(fd, kxt[i], kxt[i].abs() + 1e-4) < 1e-6, "kxt {i}: {fd} vs {}", kxt[i]);
            }
        }
    }

    #[test]
    fn peaks_are_local_maxima_of_the_curvature() {
        let s = setup();
        let p = s.points(&X);
        let c = s.constraints(&p, Bound::Envelope);
        assert!(c.npeak >= 1);
        for pk in &c.peaks[..c.npeak] {
            let a = pk.curv(&p).abs();
            for dt in [-1e-4, 1e-4] {
                assert!(curv_t(pk.t + dt, &p).0.abs() <= a);
            }
        }
    }
}
