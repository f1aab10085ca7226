//! Scalar helpers that reproduce the exact floating-point behaviour of the
//! Python/numpy expressions used by scipy and svgpathtools.

/// `x ** y` as Python and numpy compute it: a call to the C library's `pow`.
///
/// glibc's `pow(x, 2.0)` is *not* always the correctly rounded `x * x` (about
/// 1 in 1000 arguments differ in the last bit), and LLVM would rewrite
/// `powf(x, 2.0)` into `x * x`; hiding the exponent behind `black_box` keeps
/// the library call.
#[inline]
pub(crate) fn pow(x: f64, y: f64) -> f64 {
    x.powf(std::hint::black_box(y))
}

/// `x ** 2` in Python/numpy (see [`pow`]).
#[inline]
pub(crate) fn sq_pow(x: f64) -> f64 {
    pow(x, 2.0)
}

/// Python's `max(a, b)`: `b` only if `b > a` (so a NaN first argument wins).
#[inline]
pub(crate) fn py_max2(a: f64, b: f64) -> f64 {
    if b > a { b } else { a }
}

/// Python's `min(a, b)`: `b` only if `b < a`.
#[inline]
pub(crate) fn py_min2(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// Python's `max(a, b, c)`.
#[inline]
pub(crate) fn py_max3(a: f64, b: f64, c: f64) -> f64 {
    py_max2(py_max2(a, b), c)
}

/// `np.sign` (NaN stays NaN).
#[inline]
pub(crate) fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else if x == 0.0 {
        0.0
    } else {
        f64::NAN
    }
}

/// `np.dot` of two 1-D float64 vectors: plain left-to-right sum of products
/// (measured bit-identical to OpenBLAS `ddot` for n = 2 in the reference env).
#[inline]
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut s = 0.0;
    for (x, y) in a.iter().zip(b) {
        s += x * y;
    }
    s
}

/// One row of `np.dot(M, v)` for a 2x2 `M`, i.e. `m0*v0 + m1*v1` as OpenBLAS
/// `dgemv` computes it in the reference env: `fma(m0, v0, m1*v1)`.
#[inline]
pub(crate) fn dot2_gemv(m0: f64, v0: f64, m1: f64, v1: f64) -> f64 {
    m0.mul_add(v0, m1 * v1)
}

/// Row-major `M @ v` as `np.dot` computes it. For n = 2 this mirrors OpenBLAS
/// `dgemv` (see [`dot2_gemv`]). For n >= 3 the kernel's order was not
/// identified, so a plain sum is used (results then agree with scipy to
/// ~1e-9, not bitwise; pygarment only minimises in 2-D).
pub(crate) fn matvec(m: &[f64], v: &[f64], n: usize) -> Vec<f64> {
    (0..n)
        .map(|r| {
            let row = &m[r * n..(r + 1) * n];
            if n == 2 { dot2_gemv(row[0], v[0], row[1], v[1]) } else { dot(row, v) }
        })
        .collect()
}

/// Row-major `A @ B` as `np.dot` computes it with OpenBLAS `dgemm` in the
/// reference env: each entry accumulates forward with fused multiply-adds,
/// `c = fma(a2, b2, fma(a1, b1, a0*b0))` (verified bitwise for n = 2, 3, 4).
pub(crate) fn matmul(a: &[f64], b: &[f64], n: usize) -> Vec<f64> {
    let mut c = vec![0.0; n * n];
    for r in 0..n {
        for col in 0..n {
            let mut acc = a[r * n] * b[col];
            for k in 1..n {
                acc = a[r * n + k].mul_add(b[k * n + col], acc);
            }
            c[r * n + col] = acc;
        }
    }
    c
}

/// Minimal complex number with CPython's `complex` arithmetic (3.11: an int or
/// float operand is first converted to `complex(x, 0)`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct C {
    pub re: f64,
    pub im: f64,
}

impl C {
    pub const fn new(re: f64, im: f64) -> C {
        C { re, im }
    }
    pub fn add(self, o: C) -> C {
        C::new(self.re + o.re, self.im + o.im)
    }
    pub fn sub(self, o: C) -> C {
        C::new(self.re - o.re, self.im - o.im)
    }
    /// CPython `_Py_c_prod`.
    pub fn mul(self, o: C) -> C {
        C::new(self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re)
    }
    /// CPython `_Py_c_quot` (Smith's algorithm); `None` for division by zero
    /// (Python raises `ZeroDivisionError`).
    pub fn div(self, b: C) -> Option<C> {
        let abs_br = b.re.abs();
        let abs_bi = b.im.abs();
        if abs_br >= abs_bi {
            if abs_br == 0.0 {
                return None;
            }
            let ratio = b.im / b.re;
            let denom = b.re + b.im * ratio;
            Some(C::new((self.re + self.im * ratio) / denom, (self.im - self.re * ratio) / denom))
        } else if abs_bi >= abs_br {
            let ratio = b.re / b.im;
            let denom = b.re * ratio + b.im;
            Some(C::new((self.re * ratio + self.im) / denom, (self.im * ratio - self.re) / denom))
        } else {
            Some(C::new(f64::NAN, f64::NAN))
        }
    }
    /// `abs(z)`: CPython and numpy both call libm `hypot`.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }
}
