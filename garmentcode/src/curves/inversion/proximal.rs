//! Proximal refinement: from the ripple-free solution towards a local minimum of the
//! reference's 70-sample objective f70, by a map that is continuous in the inputs.
//!
//! Why: f70 is rippled. Along the direction that slides a curvature peak past the samples,
//! each sample's piece `F + k(t_k)^2` is concave (the sampled maximum dips while the peak
//! sits between samples), so f70's local minima sit where two samples tie, one per gap
//! between samples. Converging to one (`Mode::Reference`) jumps by up to ~0.4 cm of outline
//! when the ripple-free peak passes a sample. The ripple-free solution `x_s` is smooth in
//! the inputs but leaves the ripple gain (up to 0.37 %) unused.
//!
//! No continuous map avoids a transition there: on the ridge (peak exactly on a sample) f70
//! equals the ripple-free objective, so a continuous path from one tie to the next passes a
//! point no better than the ripple-free optimum. A continuous method can only make that
//! transition narrow (steep in the inputs); requirement "never worse than the reference"
//! then holds except for inputs within the transition, which is what the step count trades.
//!
//! Method: a fixed number of steps `x <- x + d`, each `d` the minimiser of the strictly
//! convex QP
//!   min_{d, z}  grad F(x).d + 1/2 d^T G d + z^2   s.t.  z >= |k_k(x)| + sign_k grad k_k(x).d
//! over the 70 samples, with `G` frozen at `x_s`: `G = L - theta A`, where `L` is the
//! Lagrangian Hessian of the ripple-free problem and `A = sum_j mult_j k_xt k_xt^T / |k_tt|`
//! the ripples' concavity (the moving-maximum term of each peak in `L`). A sample piece's
//! Hessian is `L - A`, so each step is one Newton step of the proximal subproblem
//! `min f70(x) + 1/2 |x - x_n|_P^2` with `P = (1 - theta) A`: proximal point with the weight
//! only on the ripple directions, each subproblem convex while `theta lambda < 1`
//! (`lambda` = largest eigenvalue of `M^-1 A`, M the ripple-free Hessian; 0.2-1.9 on the
//! logged calls). Along the ripple the distance from the ridge grows by
//! `lambda (1 - theta) / (1 - theta lambda)` per step (quadratic model); across it the steps
//! are Newton steps and settle in the tie within a few steps.
//!
//! Continuity: `x_s` moves continuously with the inputs; `G` comes from the KKT multipliers
//! on a canonical constraint set at `x_s` and from `lambda` through continuous functions, so
//! it does too; each step is the unique solution of a strictly convex QP whose data are
//! continuous in `x` and the inputs; a fixed number of steps composes continuous maps. No
//! line search, no damping decision, no convergence test.

use super::eig;
use super::qp;
use super::solver::{Mat, NC, NPEAK, NS, NX, RunOut, Setup, Stats, curv_xt, lagrangian_hessian};

/// Number of refinement steps: the fewest for which the result is at least as good as the
/// reference's on all 574 logged calls (6 fail on one: a hood whose ripple-free peak is
/// 0.006 sample spacings past a sample, 1.2e-4 worse than the reference there). More steps
/// make the transitions narrower and steeper.
pub const STEPS: usize = 8;

/// Samples below this fraction of the largest sampled curvature are left out of the step's
/// QP: a proximal step moves the curve by millimetres, which cannot double a sample's
/// curvature, so they are never binding and leaving them out changes no step.
const NEAR_MAX: f64 = 0.5;

/// Share of the ripple concavity taken off the model (at most): the proximal weight left
/// on the ripple directions is (1 - THETA) A, so each proximal subproblem stays convex while
/// lambda < 1 / THETA. 0 (the plain ripple-free Lagrangian) needs 16 steps for the same
/// result; 0.7 makes the transitions of strongly rippled curves twice as steep.
const THETA: f64 = 0.5;

/// Largest growth per step of the distance from a ridge: strongly rippled curves (lambda
/// above 1.15) get a smaller theta, even negative (extra proximal weight), so that the
/// transitions' steepness stays bounded (39 of the 574 logged calls).
const GROWTH: f64 = 1.35;

/// Eigenvalue floor of the frozen model, relative to its largest eigenvalue (keeps the QP
/// strictly convex; a continuous function of the matrix).
const EIG_FLOOR: f64 = 1e-10;

/// `G^-1` for the QP in `(d, z)`: `G` = the ripple-free Lagrangian Hessian at `x_s` minus
/// `theta A` (eigenvalues clipped at a floor), and 2 for `z^2`.
///
/// The multipliers are those of the ripple-free run's last QP: the KKT multipliers at `x_s`
/// on its canonical constraint set (see `Setup::find_peaks`), continuous in the inputs.
/// None only on numerical breakdown (then the ripple-free solution is returned).
pub(crate) fn frozen_model(s: &Setup, r: &RunOut) -> Option<qp::MatN> {
    let p = s.points(&r.x);
    let (_, _, hf) = s.smooth_full(&r.x, &p);
    let Some(pc) = &r.prev else { return spd_inverse(&hf) };
    let mut lag = lagrangian_hessian(s, &p, &hf, &r.mult, pc);
    // M = Hessian of the ripple-free objective F + z^2 (Lagrangian plus 2 sum_j w_j g_j g_j^T,
    // w_j = mult_j / 2z the multiplier shares): the metric in which ripples are measured.
    let z = (0..NC).filter(|&j| pc.enabled[j]).fold(0.0f64, |m, j| m.max(pc.kap[j].abs()));
    let mut m = lag;
    for j in (0..NC).filter(|&j| pc.enabled[j] && r.mult[j] > 0.0) {
        let g = &pc.grad[j];
        for a in 0..NX {
            for b in 0..NX {
                m[a][b] += r.mult[j] / z * g[a] * g[b];
            }
        }
    }
    let minv = spd_map(&m, |e| 1.0 / e);
    // Ripple concavity per peak: A_j = w_j u_j u_j^T (u = k_xt, w = mult / |k_tt|).
    let mut ripples = [([0.0; NX], 0.0); NPEAK];
    for (j, rj) in ripples.iter_mut().enumerate().take(pc.npeak) {
        let (u, ktt) = curv_xt(&pc.peaks[j], &s.e3, &p);
        if r.mult[NS + j] > 0.0 && ktt * pc.kap[NS + j].signum() < 0.0 {
            *rj = (u, r.mult[NS + j] / ktt.abs());
        }
    }
    // Ripple strength lambda = largest eigenvalue of M^-1 sum_j A_j, from the small matrix
    // sqrt(w_a w_b) u_a^T M^-1 u_b (same nonzero eigenvalues; peaks that ripple along the same
    // direction, as the two of a symmetric hood, add up).
    let b: [[f64; NPEAK]; NPEAK] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let ((ui, wi), (uj, wj)) = (ripples[i], ripples[j]);
            let q: f64 = (0..NX).map(|a| ui[a] * (0..NX).map(|c| minv[a][c] * uj[c]).sum::<f64>()).sum();
            (wi * wj).sqrt() * q
        })
    });
    let lambda = eig::jacobi(&b).0.iter().fold(0.0f64, |m, &e| m.max(e));
    let theta = if lambda > 0.0 { THETA.min((GROWTH - lambda) / (lambda * (GROWTH - 1.0))) } else { THETA };
    for (u, w) in ripples {
        for a in 0..NX {
            for c in 0..NX {
                lag[a][c] -= theta * w * u[a] * u[c];
            }
        }
    }
    spd_inverse(&lag)
}

/// V f(max(e, floor)) V^T for the eigen-decomposition V e V^T of the symmetric `h`.
fn spd_map(h: &Mat, f: impl Fn(f64) -> f64) -> Mat {
    let (ev, v) = eig::jacobi(h);
    let top = ev.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let fe = ev.map(|e| f(e.max(EIG_FLOOR * top)));
    std::array::from_fn(|i| std::array::from_fn(|j| (0..NX).map(|k| v[i][k] * fe[k] * v[j][k]).sum()))
}

/// Inverse of the QP Hessian [[h', 0], [0, 2]], h' = h with eigenvalues clipped at the floor.
fn spd_inverse(h: &Mat) -> Option<qp::MatN> {
    let hc = spd_map(h, |e| e);
    let mut g = [[0.0; qp::N]; qp::N];
    for i in 0..NX {
        g[i][..NX].copy_from_slice(&hc[i]);
    }
    g[NX][NX] = 2.0;
    qp::cholesky(&g, qp::N).map(|l| qp::inverse_from_cholesky(&l))
}

/// `steps` proximal steps from `xs` with the frozen model `ginv`.
pub(crate) fn refine(s: &Setup, xs: [f64; NX], ginv: &qp::MatN, steps: usize, st: &mut Stats) -> [f64; NX] {
    let mut x = xs;
    for _ in 0..steps {
        let p = s.points(&x);
        let mut g0 = [0.0; qp::N];
        g0[..NX].copy_from_slice(&s.smooth_grad(&x, &p));
        // The linearised bounds z >= |k| + sign(k) grad k . d of the samples near the max.
        let rows = s.sample_bounds_near_max(&p, NEAR_MAX);
        let n = rows.iter().filter(|r| r.is_some()).count();
        // Same QP either way (left-out rows are never binding); the small one is faster.
        let sol = if n <= SMALL { solve_rows::<SMALL>(ginv, &g0, &rows) } else { solve_rows::<NS>(ginv, &g0, &rows) };
        // A strictly convex QP whose constraints are always feasible (z free) has a solution;
        // None means numerical breakdown: stop where we are (counted, never seen).
        let Some(d) = sol else {
            st.qp_failures += 1;
            break;
        };
        for i in 0..NX {
            x[i] += d[i];
        }
        st.iterations[1] += 1;
    }
    x
}

/// Capacity of the small QP (rows near the max; more use the full 70-row QP).
const SMALL: usize = 24;

/// Solve the step QP with the given rows (|k|, sign(k) grad k) packed into `M` slots, in
/// sample order (so the dual active-set method adds them in the same order either way).
fn solve_rows<const M: usize>(ginv: &qp::MatN, g0: &[f64; qp::N], rows: &[Option<(f64, [f64; NX])>; NS]) -> Option<[f64; qp::N]> {
    let mut ca = [[0.0; qp::N]; M];
    let mut cb = [1.0; M];
    for (slot, (k, g)) in rows.iter().flatten().enumerate() {
        for i in 0..NX {
            ca[slot][i] = -g[i];
        }
        ca[slot][NX] = 1.0;
        cb[slot] = -k;
    }
    qp::solve(ginv, g0, &ca, &cb).map(|sol| sol.y)
}
