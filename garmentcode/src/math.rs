//! Small numeric helpers shared by the geometry modules.
//!
//! The formulas follow the reference implementation operation by operation where the
//! order of floating-point operations can change a discrete decision later on (exact
//! vertex merging, integer truncation of pivots, matching tolerances).

use crate::error::{Error, Result};

/// 2D point or vector (panel-local coordinates, centimetres).
pub(crate) type Vec2 = glam::DVec2;
/// 3D point or vector (world coordinates, centimetres).
pub(crate) type Vec3 = glam::DVec3;

/// `|a - b| < tol`, the reference's default comparison (`tol = 1e-4`).
#[inline]
pub fn close_enough(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() < tol
}

/// Linear interpolation `(1 - f)·a + f·b`; like the reference, a factor outside
/// `[0, 1]` is an error rather than an extrapolation.
pub fn lerp(a: f64, b: f64, f: f64) -> Result<f64> {
    if !(0.0..=1.0).contains(&f) {
        return Err(Error::Geometry(format!("linear interpolation expects a factor in [0, 1], got {f}")));
    }
    Ok((1.0 - f) * a + f * b)
}

/// `(−v.y, v.x)`: the vector rotated by +90°, the "left" side of a direction.
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// 2D cross product `a.x·b.y − a.y·b.x`.
#[inline]
pub fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Euclidean norm as numpy computes it (`sqrt(x·x + y·y)`).
#[inline]
pub fn norm(v: Vec2) -> f64 {
    (v.x * v.x + v.y * v.y).sqrt()
}

/// Magnitude of a complex number as Python's `abs(complex)` computes it (`hypot`).
#[inline]
pub fn cabs(v: Vec2) -> f64 {
    v.x.hypot(v.y)
}

/// Rotate `v` by `angle` radians counter-clockwise (`R2D(angle) · v`).
#[inline]
pub fn rotate2d(v: Vec2, angle: f64) -> Vec2 {
    let (s, c) = angle.sin_cos();
    Vec2::new(c * v.x + (-s) * v.y, s * v.x + c * v.y)
}

/// Signed angle from `v1` to `v2` in `[−π, π]`, positive counter-clockwise.
///
/// Like the reference garment-code helper the cosine is *not* clamped (nearly
/// parallel vectors may give NaN) and the sign is applied only when
/// `|cross| > 1e-5`.
pub fn vector_angle(v1: Vec2, v2: Vec2) -> f64 {
    let cos = v1.dot(v2) / (norm(v1) * norm(v2));
    let mut angle = cos.acos();
    let c = cross(v1, v2);
    if c.abs() > 1e-5 {
        angle *= c.signum();
    }
    angle
}

/// As [`vector_angle`] but with the cosine clamped to `[−1, 1]` (the variant the
/// reference's drawing code uses).
pub fn vector_angle_clamped(v1: Vec2, v2: Vec2) -> f64 {
    let cos = (v1.dot(v2) / (norm(v1) * norm(v2))).clamp(-1.0, 1.0);
    let mut angle = cos.acos();
    let c = cross(v1, v2);
    if c.abs() > 1e-5 {
        angle *= c.signum();
    }
    angle
}

/// Point given in the frame of the edge `start → end` (x along the chord, y along
/// its left perpendicular, both in chord-length units) to absolute coordinates.
#[inline]
pub fn rel_to_abs(start: Vec2, end: Vec2, rel: Vec2) -> Vec2 {
    let d = end - start;
    let abs_start = start + rel.x * d;
    abs_start + rel.y * perp(d)
}

/// Absolute point to the frame of the edge `start → end` (inverse of [`rel_to_abs`]).
pub fn abs_to_rel(start: Vec2, end: Vec2, point: Vec2) -> Vec2 {
    abs_to_rel_vector(start, end, point - start)
}

/// Vector (not a point) expressed in the frame of the edge `start → end`.
pub fn abs_to_rel_vector(start: Vec2, end: Vec2, v: Vec2) -> Vec2 {
    let d = end - start;
    let len = norm(d);
    let projected_len = d.dot(v) / len;
    let x = projected_len / len;
    let vert = v - d * x;
    let y = norm(vert) / len * cross(d, v).signum_or_zero();
    Vec2::new(x, y)
}

/// `numpy.sign`: −1, 0 or 1 (0 for ±0, NaN for NaN).
pub trait SignumOrZero {
    /// Sign with zero mapped to zero, as numpy's `sign`.
    fn signum_or_zero(self) -> f64;
}

impl SignumOrZero for f64 {
    #[inline]
    fn signum_or_zero(self) -> f64 {
        if self > 0.0 {
            1.0
        } else if self < 0.0 {
            -1.0
        } else if self.is_nan() {
            f64::NAN
        } else {
            0.0
        }
    }
}

/// Python's `int()` of a float: truncation toward zero.
#[inline]
pub fn trunc(x: f64) -> f64 {
    x.trunc()
}

/// `numpy.linspace(0, 1, n, endpoint=False)[1:]`: the interior sample parameters
/// `k/n` for `k = 1..n`, computed as numpy does (`k · (1/n)`).
pub fn interior_params(n: usize) -> impl Iterator<Item = f64> {
    let step = 1.0 / n as f64;
    (1..n).map(move |k| k as f64 * step)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_frame_round_trip() {
        let s = Vec2::new(1.0, 2.0);
        let e = Vec2::new(4.0, -2.0);
        for p in [Vec2::new(3.0, 7.0), Vec2::new(-2.0, 0.5), Vec2::new(2.5, 0.0)] {
            let r = abs_to_rel(s, e, p);
            let back = rel_to_abs(s, e, r);
            assert!((back - p).length() < 1e-12, "{p} -> {r} -> {back}");
        }
        // Left of the direction is positive y.
        let r = abs_to_rel(Vec2::ZERO, Vec2::X, Vec2::new(0.5, 1.0));
        assert_eq!(r, Vec2::new(0.5, 1.0));
    }

    #[test]
    fn angles_are_signed_counter_clockwise() {
        let a = vector_angle(Vec2::X, Vec2::Y);
        assert!((a - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let b = vector_angle(Vec2::Y, Vec2::X);
        assert!((b + std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }

    #[test]
    fn lerp_rejects_extrapolation() {
        assert_eq!(lerp(2.0, 4.0, 0.5).unwrap(), 3.0);
        assert!(lerp(2.0, 4.0, 1.5).is_err());
    }

    #[test]
    fn interior_params_match_numpy_linspace() {
        let v: Vec<f64> = interior_params(10).collect();
        assert_eq!(v.len(), 9);
        assert_eq!(v[0], 0.1);
        assert_eq!(v[2], 3.0 * 0.1);
    }
}
