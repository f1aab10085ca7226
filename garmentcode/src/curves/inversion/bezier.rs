//! Cubic Bézier primitives with the same formulas svgpathtools uses
//! (derivatives, unit tangent, curvature) plus an accurate arc length.

use super::gauss::{GL16_T, GL16_W};

pub type V2 = [f64; 2];

#[inline]
pub fn sub(a: V2, b: V2) -> V2 {
    [a[0] - b[0], a[1] - b[1]]
}
#[inline]
pub fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
#[inline]
pub fn cross(a: V2, b: V2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
/// Euclidean norm as numpy's `linalg.norm` computes it (sqrt of the dot product).
#[inline]
pub fn norm(a: V2) -> f64 {
    dot(a, a).sqrt()
}

/// First derivative B'(t), written as svgpathtools writes it.
pub fn d1(p: &[V2; 4], t: f64) -> V2 {
    let u = 1.0 - t;
    let mut r = [0.0; 2];
    for c in 0..2 {
        r[c] = 3.0 * (p[1][c] - p[0][c]) * u * u + 6.0 * (p[2][c] - p[1][c]) * u * t + 3.0 * (p[3][c] - p[2][c]) * t * t;
    }
    r
}

/// Second derivative B''(t), written as svgpathtools writes it.
pub fn d2(p: &[V2; 4], t: f64) -> V2 {
    let u = 1.0 - t;
    let mut r = [0.0; 2];
    for c in 0..2 {
        r[c] = 6.0 * (u * (p[2][c] - 2.0 * p[1][c] + p[0][c]) + t * (p[3][c] - 2.0 * p[2][c] + p[1][c]));
    }
    r
}

/// Unit tangent B'/|B'| (no limit handling: the callers never pass a cusp at an end).
pub fn unit_tangent(p: &[V2; 4], t: f64) -> V2 {
    let d = d1(p, t);
    let l = d[0].hypot(d[1]);
    [d[0] / l, d[1] / l]
}

/// Unsigned curvature |x'y'' - y'x''| / |B'|^3.
pub fn curvature(p: &[V2; 4], t: f64) -> f64 {
    let a = d1(p, t);
    let b = d2(p, t);
    (a[0] * b[1] - a[1] * b[0]).abs() / (a[0] * a[0] + a[1] * a[1]).sqrt().powi(3)
}

/// The 70 curvature sample parameters, as numpy's `linspace(0, 1, 70)` produces them.
pub fn sample_params() -> [f64; 70] {
    let step = 1.0 / 69.0;
    let mut t = [0.0; 70];
    for (k, v) in t.iter_mut().enumerate() {
        *v = k as f64 * step;
    }
    t[69] = 1.0;
    t
}

/// |B'(t)|; a plain square root (not `hypot`): the length quadrature is far less
/// exact than the last bit, and this is the hot loop.
fn speed(p: &[V2; 4], t: f64) -> f64 {
    let d = d1(p, t);
    (d[0] * d[0] + d[1] * d[1]).sqrt()
}

fn gl16(p: &[V2; 4], a: f64, b: f64) -> f64 {
    let h = b - a;
    let mut s = 0.0;
    for i in 0..16 {
        s += GL16_W[i] * speed(p, a + h * GL16_T[i]);
    }
    s * h
}

fn adaptive(p: &[V2; 4], a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
    let m = 0.5 * (a + b);
    let left = gl16(p, a, m);
    let right = gl16(p, m, b);
    let both = left + right;
    if depth >= 40 || (both - whole).abs() <= tol {
        return both;
    }
    adaptive(p, a, m, left, 0.5 * tol, depth + 1) + adaptive(p, m, b, right, 0.5 * tol, depth + 1)
}

/// Arc length by adaptive 16-point Gauss-Legendre bisection, absolute accuracy ~1e-13.
///
/// svgpathtools integrates |B'| with QUADPACK; any quadrature this accurate gives the
/// same number to ~1e-12, which is all the objective needs.
pub fn length(p: &[V2; 4]) -> f64 {
    let whole = gl16(p, 0.0, 1.0);
    adaptive(p, 0.0, 1.0, whole, 1e-13, 0)
}
