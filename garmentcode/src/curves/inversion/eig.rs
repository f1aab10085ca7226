//! Symmetric eigen-decomposition of a small matrix (cyclic Jacobi), used to make a model
//! Hessian positive definite by a continuous matrix function (eigenvalue clipping).

/// Jacobi sweeps (see [`jacobi`]).
const SWEEPS: usize = 6;

/// Eigenvalues and eigenvectors (columns of the returned matrix) of the symmetric `a`.
///
/// A fixed number of cyclic Jacobi sweeps (no convergence test, so no input-dependent
/// decision): convergence is quadratic; on 5x5 matrices with eigenvalues spread over nine
/// decades five sweeps reach rounding level (see the test), six leave a margin.
pub fn jacobi<const N: usize>(a: &[[f64; N]; N]) -> ([f64; N], [[f64; N]; N]) {
    let mut m = *a;
    let mut v = [[0.0; N]; N];
    for i in 0..N {
        v[i][i] = 1.0;
    }
    for _sweep in 0..SWEEPS {
        for p in 0..N {
            for q in p + 1..N {
                let apq = m[p][q];
                if apq == 0.0 {
                    continue;
                }
                // Rotation angle that zeroes m[p][q] (Golub & Van Loan, Alg. 8.4.1).
                let tau = (m[q][q] - m[p][p]) / (2.0 * apq);
                let t = tau.signum() / (tau.abs() + (1.0 + tau * tau).sqrt());
                let t = if tau == 0.0 { 1.0 } else { t };
                let c = 1.0 / (1.0 + t * t).sqrt();
                let s = t * c;
                for k in 0..N {
                    let (mkp, mkq) = (m[k][p], m[k][q]);
                    m[k][p] = c * mkp - s * mkq;
                    m[k][q] = s * mkp + c * mkq;
                }
                for k in 0..N {
                    let (mpk, mqk) = (m[p][k], m[q][k]);
                    m[p][k] = c * mpk - s * mqk;
                    m[q][k] = s * mpk + c * mqk;
                }
                for k in 0..N {
                    let (vkp, vkq) = (v[k][p], v[k][q]);
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
    }
    (std::array::from_fn(|i| m[i][i]), v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An ill-conditioned 5x5 (eigenvalues 1 .. 1e-9, like the solver's Hessians) is
    /// reconstructed to rounding level by the fixed number of sweeps.
    #[test]
    fn fixed_sweeps_reach_rounding_level() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut worst_l, mut worst_r) = (0.0f64, 0.0f64);
        for _ in 0..200 {
            // Random orthogonal Q by Gram-Schmidt, A = Q diag(d) Q^T.
            let mut q = [[0.0; 5]; 5];
            for c in 0..5 {
                let mut v: [f64; 5] = std::array::from_fn(|_| rnd());
                for p in 0..c {
                    let d: f64 = (0..5).map(|i| v[i] * q[i][p]).sum();
                    for i in 0..5 {
                        v[i] -= d * q[i][p];
                    }
                }
                let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
                for i in 0..5 {
                    q[i][c] = v[i] / n;
                }
            }
            let d = [1.0, 3e-3, 1e-5, -2e-7, 1e-9];
            let a: [[f64; 5]; 5] = std::array::from_fn(|i| std::array::from_fn(|j| (0..5).map(|k| q[i][k] * d[k] * q[j][k]).sum()));
            let (l, v) = jacobi(&a);
            let mut ls = l;
            ls.sort_by(|x, y| y.partial_cmp(x).unwrap());
            let mut ds = d;
            ds.sort_by(|x, y| y.partial_cmp(x).unwrap());
            for k in 0..5 {
                worst_l = worst_l.max((ls[k] - ds[k]).abs());
            }
            for i in 0..5 {
                for j in 0..5 {
                    let r: f64 = (0..5).map(|k| v[i][k] * l[k] * v[j][k]).sum();
                    worst_r = worst_r.max((r - a[i][j]).abs());
                }
            }
        }
        println!("eigenvalue error {worst_l:.2e}, reconstruction error {worst_r:.2e}");
        assert!(worst_l < 1e-14 && worst_r < 1e-14);
    }

    #[test]
    fn reconstructs_a_symmetric_matrix() {
        let a = [[4.0, 1.0, -2.0], [1.0, -3.0, 0.5], [-2.0, 0.5, 1e-6]];
        let (l, v) = jacobi(&a);
        for i in 0..3 {
            for j in 0..3 {
                let r: f64 = (0..3).map(|k| v[i][k] * l[k] * v[j][k]).sum();
                assert!((r - a[i][j]).abs() < 1e-14, "{i}{j}");
                let o: f64 = (0..3).map(|k| v[k][i] * v[k][j]).sum();
                assert!((o - if i == j { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        }
    }
}
