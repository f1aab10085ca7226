//! Small dense strictly convex QP solver (Goldfarb-Idnani dual active-set method).
//!
//! minimise 1/2 y^T G y + g0^T y  subject to  a_k^T y + b_k >= 0,  k = 0..m.
//!
//! The dual method starts at the unconstrained minimiser and adds the most violated
//! constraint, dropping others when their multiplier would turn negative; with at most
//! N unknowns the active set stays tiny, so every quantity is recomputed from scratch
//! from G^-1 (simple and deterministic; the cost is negligible at N = 6).

/// Problem dimension (5 shifts + the curvature bound).
pub const N: usize = 6;
pub type MatN = [[f64; N]; N];

/// Cholesky factor L (lower) of a symmetric matrix; None if not numerically PD.
pub fn cholesky(a: &MatN, n: usize) -> Option<MatN> {
    let mut l = [[0.0; N]; N];
    for i in 0..n {
        for j in 0..=i {
            let mut s = a[i][j];
            for k in 0..j {
                s -= l[i][k] * l[j][k];
            }
            if i == j {
                if !(s > 1e-13 * a[i][i].abs()) || !s.is_finite() {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    Some(l)
}

/// Solve L L^T x = b for the leading n x n block.
pub fn chol_solve(l: &MatN, n: usize, b: &[f64; N]) -> [f64; N] {
    let mut y = [0.0; N];
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i][k] * y[k];
        }
        y[i] = s / l[i][i];
    }
    let mut x = [0.0; N];
    for i in (0..n).rev() {
        let mut s = y[i];
        for k in i + 1..n {
            s -= l[k][i] * x[k];
        }
        x[i] = s / l[i][i];
    }
    x
}

fn matvec(m: &MatN, v: &[f64; N]) -> [f64; N] {
    let mut r = [0.0; N];
    for i in 0..N {
        for j in 0..N {
            r[i] += m[i][j] * v[j];
        }
    }
    r
}

fn dotn(a: &[f64; N], b: &[f64; N]) -> f64 {
    (0..N).map(|i| a[i] * b[i]).sum()
}

/// Solution of the QP: minimiser and one multiplier per constraint (0 if inactive).
pub struct QpSolution<const M: usize> {
    pub y: [f64; N],
    pub mult: [f64; M],
}

/// Solve the QP given G^-1 (`ginv`). Returns None if infeasible or on breakdown.
pub fn solve<const M: usize>(ginv: &MatN, g0: &[f64; N], a: &[[f64; N]; M], b: &[f64; M]) -> Option<QpSolution<M>> {
    // Unconstrained minimiser.
    let mut y = matvec(ginv, g0);
    for v in y.iter_mut() {
        *v = -*v;
    }
    // G^-1 a_k, computed on demand for constraints that enter the active set.
    let mut act: [usize; N] = [0; N];
    let mut uact = [0.0; N];
    let mut ginv_a: [[f64; N]; N] = [[0.0; N]; N];
    let mut q = 0usize;
    for _outer in 0..(4 * M + 20) {
        // Most violated constraint (first index on ties: deterministic).
        let mut p = usize::MAX;
        let mut worst = 0.0;
        for k in 0..M {
            let s = dotn(&a[k], &y) + b[k];
            let tol = 1e-14 * (1.0 + b[k].abs());
            if s < -tol && s < worst {
                worst = s;
                p = k;
            }
        }
        if p == usize::MAX {
            let mut mult = [0.0; M];
            for i in 0..q {
                mult[act[i]] = uact[i];
            }
            return Some(QpSolution { y, mult });
        }
        let np = a[p];
        let gnp = matvec(ginv, &np);
        let mut up = 0.0;
        loop {
            // r = (N^T G^-1 N)^-1 N^T G^-1 n_p ; z = G^-1 n_p - G^-1 N r.
            let mut r = [0.0; N];
            let mut z = gnp;
            if q > 0 {
                let mut mq = [[0.0; N]; N];
                let mut rhs = [0.0; N];
                for i in 0..q {
                    for j in 0..q {
                        mq[i][j] = dotn(&a[act[i]], &ginv_a[j]);
                    }
                    rhs[i] = dotn(&a[act[i]], &gnp);
                }
                let l = cholesky(&mq, q)?;
                r = chol_solve(&l, q, &rhs);
                for i in 0..q {
                    for c in 0..N {
                        z[c] -= r[i] * ginv_a[i][c];
                    }
                }
            }
            // Dual (partial) step limit: an active multiplier reaching zero.
            let mut t1 = f64::INFINITY;
            let mut l_out = usize::MAX;
            for i in 0..q {
                if r[i] > 0.0 {
                    let t = uact[i] / r[i];
                    if t < t1 {
                        t1 = t;
                        l_out = i;
                    }
                }
            }
            // Primal (full) step: makes constraint p active.
            let zn = dotn(&z, &np);
            let sp = dotn(&np, &y) + b[p];
            let t2 = if zn > 1e-15 * dotn(&gnp, &np).abs() { -sp / zn } else { f64::INFINITY };
            let t = t1.min(t2);
            if !t.is_finite() {
                return None;
            }
            if t2.is_finite() {
                for c in 0..N {
                    y[c] += t * z[c];
                }
            }
            for i in 0..q {
                uact[i] -= t * r[i];
            }
            up += t;
            if t2 <= t1 {
                if q == N {
                    return None;
                }
                act[q] = p;
                uact[q] = up;
                ginv_a[q] = gnp;
                q += 1;
                break;
            }
            // Drop constraint l_out and retry adding p.
            for i in l_out..q - 1 {
                act[i] = act[i + 1];
                uact[i] = uact[i + 1];
                ginv_a[i] = ginv_a[i + 1];
            }
            q -= 1;
        }
    }
    None
}

/// G^-1 from the Cholesky factor of G (column by column).
pub fn inverse_from_cholesky(l: &MatN) -> MatN {
    let mut inv = [[0.0; N]; N];
    for c in 0..N {
        let mut e = [0.0; N];
        e[c] = 1.0;
        let col = chol_solve(l, N, &e);
        for r in 0..N {
            inv[r][c] = col[r];
        }
    }
    inv
}

#[cfg(test)]
mod tests {
    use super::*;

    /// min |y - c|^2 / 2 subject to sum(y) >= 1 and y0 <= 0: projection with a known answer.
    #[test]
    fn small_projection() {
        let mut g = [[0.0; N]; N];
        for i in 0..N {
            g[i][i] = 1.0;
        }
        let l = cholesky(&g, N).unwrap();
        let ginv = inverse_from_cholesky(&l);
        let c = [0.5, 0.0, 0.0, 0.0, 0.0, 0.0];
        let g0 = c.map(|v| -v);
        let mut a = [[0.0; N]; 2];
        a[0] = [1.0; N];
        a[1][0] = -1.0;
        let b = [-1.0, 0.0];
        let sol = solve(&ginv, &g0, &a, &b).unwrap();
        // y0 = 0 active; the rest share the remaining unit sum equally.
        assert!(sol.y[0].abs() < 1e-14);
        for i in 1..N {
            assert!((sol.y[i] - 0.2).abs() < 1e-14);
        }
        assert!((sol.mult[0] - 0.2).abs() < 1e-14 && (sol.mult[1] - 0.7).abs() < 1e-14);
    }
}
