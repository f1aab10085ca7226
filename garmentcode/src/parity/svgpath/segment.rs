//! Segment intersections that agree with svgpathtools 1.8.0 (MIT licence,
//! <https://github.com/mathandy/svgpathtools>), the library pygarment calls for
//! its panel self-intersection check.
//!
//! The algorithms are re-implemented here so that the *verdicts* (and, as far as
//! practical, the exact floating-point results and their order) match the
//! reference running on CPython 3.11 + numpy 1.26 (OpenBLAS/LAPACK 3.11):
//!
//! * line–line: 2×2 solve with the library's own formula and its parallel test
//!   `|den| <= 1e-8` (collinear overlaps are invisible);
//! * Bézier–line: the plane is shifted/rotated so the line lies on the +x axis
//!   (with CPython's complex division/multiplication), the roots of the
//!   Bézier's y-polynomial are found like `numpy.roots` (companion matrix
//!   eigenvalues: a port of LAPACK's DGEBAL + DGEHD2 + DLAHQR + DLANV2), real
//!   roots are those with `|imag| < 1e-8`, roots in `[0, 1]` are kept, the
//!   library's (index-confused) near-duplicate filter is applied, and the roots
//!   are visited in the iteration order of a CPython `set` of floats;
//! * Bézier–Bézier: recursive halving with bounding boxes, tolerance 1e-12,
//!   including the library's in-place list removal while iterating.
//!
//! Segments also offer what [`crate::svgpath`] needs to split SVG outlines the
//! library's way: curve bounding boxes, crops (de Casteljau) and scaling through
//! the power basis, with the library's arithmetic.
//!
//! Everything is `f64`; a point is `[x, y]` (the reference uses `x + iy`).

/// A 2-D point `[x, y]` (the reference's complex number `x + 1j*y`).
pub type P = [f64; 2];

/// A path segment in absolute coordinates, as svgpathtools' `Line`,
/// `QuadraticBezier` and `CubicBezier`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Straight segment (start, end).
    Line([P; 2]),
    /// Quadratic Bézier (start, control, end).
    Quad([P; 3]),
    /// Cubic Bézier (start, control 1, control 2, end).
    Cubic([P; 4]),
}

impl Seg {
    /// Control points (`bpoints()` in svgpathtools).
    pub fn points(&self) -> &[P] {
        match self {
            Seg::Line(p) => p,
            Seg::Quad(p) => p,
            Seg::Cubic(p) => p,
        }
    }

    /// Point at parameter `t` (svgpathtools' Horner forms, so the values are
    /// bit-identical to `seg.point(t)` for Béziers).
    pub fn point(&self, t: f64) -> P {
        bezier_point(self.points(), t)
    }

    /// Arc length. Only used to size the subdivision budget of the
    /// Bézier–Bézier routine, where its integer log2 is what matters.
    pub fn length(&self) -> f64 {
        match self {
            Seg::Line(p) => (p[1][0] - p[0][0]).hypot(p[1][1] - p[0][1]),
            Seg::Quad(p) => quad_length(p),
            Seg::Cubic(p) => cubic_length(p),
        }
    }

    /// First point.
    pub fn start(&self) -> P {
        self.points()[0]
    }

    /// Last point.
    pub fn end(&self) -> P {
        let p = self.points();
        p[p.len() - 1]
    }

    /// The same segment with its last point moved.
    pub fn with_end(&self, end: P) -> Seg {
        let mut s = *self;
        match &mut s {
            Seg::Line(p) => p[1] = end,
            Seg::Quad(p) => p[2] = end,
            Seg::Cubic(p) => p[3] = end,
        }
        s
    }

    /// Bounding box of the curve itself (`bbox()`): `[xmin, xmax, ymin, ymax]`.
    pub fn bbox(&self) -> [f64; 4] {
        match self {
            Seg::Line([a, b]) => {
                let (x0, x1) = min_max([a[0], b[0]].into_iter());
                let (y0, y1) = min_max([a[1], b[1]].into_iter());
                [x0, x1, y0, y1]
            }
            _ => bezier_bbox(&Bez::new(self.points())),
        }
    }

    /// The piece between the parameters `t0 < t1` (`cropped`): a line through its
    /// points at `t0` and `t1`; a curve by de Casteljau splits (`crop_bezier`).
    pub fn cropped(&self, t0: f64, t1: f64) -> Seg {
        if let Seg::Line(_) = self {
            return Seg::Line([self.point(t0), self.point(t1)]);
        }
        let pts = if t0 == 0.0 {
            split_bezier(self.points(), t1).0
        } else if t1 == 1.0 {
            split_bezier(self.points(), t0).1
        } else {
            // The library finds the end on the trimmed curve as the point closest to
            // `point(t1)`; for a curve trimmed at `t0` that is this parameter (up
            // to rounding).
            let right = split_bezier(self.points(), t0).1;
            split_bezier(&right, (t1 - t0) / (1.0 - t0)).0
        };
        seg_from_points(&pts)
    }

    /// Scaled by `s` about the origin (`scaled(s)`), the library's way: through the
    /// power basis (`bez2poly`, coefficients scaled, `poly2bez`), so the control
    /// points carry the same roundings. The points are then numpy `complex128`,
    /// whose division by 3 multiplies by the reciprocal.
    pub fn scaled(&self, s: f64) -> Seg {
        let add = |a: P, b: P| [a[0] + b[0], a[1] + b[1]];
        let sub = |a: P, b: P| [a[0] - b[0], a[1] - b[1]];
        let mul = |k: f64, a: P| [k * a[0], k * a[1]];
        let div = |a: P, k: f64| np_quot(a, [k, 0.0]);
        match *self {
            Seg::Line([p0, p1]) => {
                let (c0, c1) = (mul(s, sub(p1, p0)), mul(s, p0));
                Seg::Line([c1, add(c0, c1)])
            }
            Seg::Quad([p0, p1, p2]) => {
                let c0 = mul(s, add(sub(p0, mul(2.0, p1)), p2));
                let c1 = mul(s, mul(2.0, sub(p1, p0)));
                let c2 = mul(s, p0);
                Seg::Quad([c2, add(div(c1, 2.0), c2), add(add(c0, c1), c2)])
            }
            Seg::Cubic([p0, p1, p2, p3]) => {
                let c0 = mul(s, add(add(mul(-1.0, p0), mul(3.0, sub(p1, p2))), p3));
                let c1 = mul(s, mul(3.0, add(sub(p0, mul(2.0, p1)), p2)));
                let c2 = mul(s, mul(3.0, sub(p1, p0)));
                let c3 = mul(s, p0);
                Seg::Cubic([c3, add(div(c2, 3.0), c3), add(div(add(c1, mul(2.0, c2)), 3.0), c3), add(add(add(c0, c1), c2), c3)])
            }
        }
    }
}

/// The segment with these control points (2, 3 or 4 of them).
fn seg_from_points(p: &[P]) -> Seg {
    match *p {
        [a, b] => Seg::Line([a, b]),
        [a, b, c] => Seg::Quad([a, b, c]),
        [a, b, c, d] => Seg::Cubic([a, b, c, d]),
        _ => unreachable!("a segment has 2 to 4 points"),
    }
}

/// `split_bezier`: de Casteljau with `(1 - t)·a + t·b` at every level.
fn split_bezier(p: &[P], t: f64) -> (Vec<P>, Vec<P>) {
    let mut left = Vec::with_capacity(p.len());
    let mut right = Vec::with_capacity(p.len());
    let mut cur: Vec<P> = p.to_vec();
    loop {
        left.push(cur[0]);
        right.push(cur[cur.len() - 1]);
        if cur.len() == 1 {
            break;
        }
        cur = cur.windows(2).map(|w| [(1.0 - t) * w[0][0] + t * w[1][0], (1.0 - t) * w[0][1] + t * w[1][1]]).collect();
    }
    right.reverse();
    (left, right)
}

/// How the reference holds a segment's points. pygarment's `as_curve()` builds
/// segments from numpy arrays (`numpy.complex128` points); segments made from
/// Python `complex` values (e.g. `list_to_c`) use CPython's arithmetic. The two
/// differ in one place only: the complex division that builds the rotation in
/// the Bézier–line routine (numpy multiplies by a reciprocal, CPython divides),
/// so only the *line's* kind matters there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Num {
    /// `numpy.complex128` points (pygarment `Edge.as_curve()`): the default.
    #[default]
    Numpy,
    /// Python `complex` points.
    Python,
}

/// Situations in which svgpathtools raises instead of answering.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntersectError {
    /// A line with equal end points (`assert` in svgpathtools).
    DegenerateLine,
    /// Two equal segments of the same kind (`assert self != other_seg`).
    IdenticalSegments,
    /// All control points of a Bézier coincide (`ValueError` "bezier is nodal").
    NodalBezier,
    /// `bezier_intersections` ran out of subdivision levels (`Exception`).
    MaxIterations,
    /// `bezier_intersections` had more than [`MAX_PAIRS`] candidate pairs at one
    /// level: the curves overlap along a stretch (the reference's search grows
    /// fourfold per level there and never ends in practice).
    TooManyPairs,
}

/// Most candidate sub-curve pairs the Bézier–Bézier search keeps at one level.
/// Curves that meet at isolated points keep a few dozen; only curves overlapping
/// along a stretch come near it.
pub const MAX_PAIRS: usize = 4096;

impl std::fmt::Display for IntersectError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let s = match self {
            IntersectError::DegenerateLine => "line with equal end points",
            IntersectError::IdenticalSegments => "intersecting a segment with an equal segment",
            IntersectError::NodalBezier => "bezier is nodal",
            IntersectError::MaxIterations => "bezier_intersections has reached maximum iterations without terminating",
            IntersectError::TooManyPairs => "two curves overlap along a stretch (the intersection search was stopped)",
        };
        f.write_str(s)
    }
}

impl std::error::Error for IntersectError {}

/// Like [`intersect`](crate::intersect::intersect) but returns the reference's exceptions as errors.
/// Points are taken to be `numpy.complex128`, as in pygarment's curves.
pub fn try_intersect(a: &Seg, b: &Seg) -> Result<Vec<(f64, f64)>, IntersectError> {
    try_intersect_as(a, Num::Numpy, b, Num::Numpy)
}

/// [`try_intersect`] with the number kind of each segment's points given
/// explicitly (see [`Num`]); e.g. pygarment's `even_armhole_openings`
/// intersects a numpy-built Bézier with a Line of Python complexes.
pub fn try_intersect_as(a: &Seg, a_num: Num, b: &Seg, b_num: Num) -> Result<Vec<(f64, f64)>, IntersectError> {
    let mut out = Vec::new();
    intersect_into(a, a_num, b, b_num, &mut out)?;
    Ok(out)
}

/// [`try_intersect_as`] appending the parameter pairs to `out` (so that a caller
/// testing many pairs reuses one vector).
fn intersect_into(a: &Seg, a_num: Num, b: &Seg, b_num: Num, out: &mut Vec<(f64, f64)>) -> Result<(), IntersectError> {
    // Every `intersect` method starts with a control-point bounding-box reject
    // (strict comparisons: touching boxes go on to the real test).
    if !control_boxes_may_meet(a.points(), b.points()) {
        return Ok(());
    }
    match (a, b) {
        (Seg::Line(l1), Seg::Line(l2)) => line_line(l1, l2, out),
        (Seg::Line(l), Seg::Quad(_) | Seg::Cubic(_)) => {
            let first = out.len();
            bezier_by_line(b.points(), l, a_num, out)?;
            out[first..].iter_mut().for_each(|h| *h = (h.1, h.0));
            Ok(())
        }
        (Seg::Quad(_) | Seg::Cubic(_), Seg::Line(l)) => bezier_by_line(a.points(), l, b_num, out),
        _ => {
            // Quad–Quad and Cubic–(Quad|Cubic) assert inequality; Quad–Cubic
            // does not, but a quadratic never equals a cubic anyway.
            if a == b {
                return Err(IntersectError::IdenticalSegments);
            }
            let longer = a.length().max(b.length());
            bezier_intersections(a.points(), b.points(), longer, 1e-12, 1e-12, out)
        }
    }
}

/// [`has_self_intersection`](crate::intersect::has_self_intersection) returning the reference's exceptions as errors.
pub fn try_has_self_intersection(segs: &[Seg]) -> Result<bool, IntersectError> {
    // The control-point box reject that starts every `intersect` call, with each
    // segment's box computed once instead of once per pair (most pairs stop there).
    let boxes: Vec<ControlBox> = segs.iter().map(|s| ControlBox::of(s.points())).collect();
    let mut hits = Vec::new();
    for i1 in 0..segs.len() {
        for i2 in i1 + 1..segs.len() {
            if !boxes[i1].may_meet(&boxes[i2]) {
                continue;
            }
            hits.clear();
            intersect_into(&segs[i1], Num::Numpy, &segs[i2], Num::Numpy, &mut hits)?;
            let real_hit = hits.iter().any(|&(t1, t2)| {
                let (lo, hi) = if t2 < t1 { (t2, t1) } else { (t1, t2) };
                !((lo - 0.0).abs() < 1e-4 && (hi - 1.0).abs() < 1e-4)
            });
            if real_hit {
                return Ok(true);
            }
        }
    }
    Ok(false)
}

/// A short list kept on the stack: the polynomials, roots and parameters here
/// have a handful of entries, and a vector for each cost more than the
/// arithmetic. Pushing past `N` panics (the sizes are bounded by the degrees).
#[derive(Clone, Copy, Debug)]
struct Few<T: Copy + Default, const N: usize> {
    len: usize,
    items: [T; N],
}

impl<T: Copy + Default, const N: usize> Few<T, N> {
    fn new() -> Self {
        Few { len: 0, items: [T::default(); N] }
    }
    fn from_slice(s: &[T]) -> Self {
        let mut f = Self::new();
        s.iter().for_each(|&x| f.push(x));
        f
    }
    fn push(&mut self, x: T) {
        self.items[self.len] = x;
        self.len += 1;
    }
}

impl<T: Copy + Default, const N: usize> std::ops::Deref for Few<T, N> {
    type Target = [T];
    fn deref(&self) -> &[T] {
        &self.items[..self.len]
    }
}

fn min_max(v: impl Iterator<Item = f64>) -> (f64, f64) {
    // Python's min()/max() keep the first extreme value; with no NaNs the
    // value is what matters.
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for x in v {
        if x < lo {
            lo = x;
        }
        if x > hi {
            hi = x;
        }
    }
    (lo, hi)
}

/// The quick reject at the top of svgpathtools' `intersect` methods.
fn control_boxes_may_meet(s: &[P], o: &[P]) -> bool {
    ControlBox::of(s).may_meet(&ControlBox::of(o))
}

/// Per-axis extremes of a segment's control points.
struct ControlBox([(f64, f64); 2]);

impl ControlBox {
    fn of(points: &[P]) -> ControlBox {
        ControlBox([min_max(points.iter().map(|p| p[0])), min_max(points.iter().map(|p| p[1]))])
    }

    /// False when the boxes are apart on some axis (touching boxes may meet).
    fn may_meet(&self, other: &ControlBox) -> bool {
        for k in 0..2 {
            let (omin, omax) = other.0[k];
            let (smin, smax) = self.0[k];
            if omin > smax || omax < smin {
                return false;
            }
        }
        true
    }
}

// ---------------------------------------------------------------------------
// Line–line
// ---------------------------------------------------------------------------

/// `Line.intersect(Line)`, with the library's formula so results are
/// bit-identical. Parallel test is `np.isclose(den, 0)`, i.e. `|den| <= 1e-8`
/// in absolute terms (so short, nearly parallel lines count as parallel).
fn line_line(s: &[P; 2], o: &[P; 2], out: &mut Vec<(f64, f64)>) -> Result<(), IntersectError> {
    if o[0] == o[1] || s[0] == s[1] {
        return Err(IntersectError::DegenerateLine);
    }
    if s == o {
        return Err(IntersectError::IdenticalSegments);
    }
    let a = (s[0][0], s[1][0]);
    let b = (s[0][1], s[1][1]);
    let c = (o[0][0], o[1][0]);
    let d = (o[0][1], o[1][1]);
    let denom = (a.1 - a.0) * (d.0 - d.1) - (b.1 - b.0) * (c.0 - c.1);
    if denom.abs() <= 1e-8 {
        return Ok(());
    }
    let t1 = (c.0 * (b.0 - d.1) - c.1 * (b.0 - d.0) - a.0 * (d.0 - d.1)) / denom;
    let t2 = -(a.1 * (b.0 - d.0) - a.0 * (b.1 - d.0) - c.0 * (b.0 - b.1)) / denom;
    if (0.0..=1.0).contains(&t1) && (0.0..=1.0).contains(&t2) {
        out.push((t1, t2));
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// CPython arithmetic helpers
// ---------------------------------------------------------------------------

/// CPython 3.11 `_Py_c_prod` (no FMA), used by `complex * complex`.
fn c_prod(a: P, b: P) -> P {
    [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]
}

/// numpy 1.26 `CDOUBLE_divide` (Smith's algorithm with a reciprocal), used by
/// `x / numpy.complex128`.
fn np_quot(a: P, b: P) -> P {
    let abs_br = b[0].abs();
    let abs_bi = b[1].abs();
    if abs_br >= abs_bi {
        if abs_br == 0.0 && abs_bi == 0.0 {
            [a[0] / abs_br, a[1] / abs_br]
        } else {
            let rat = b[1] / b[0];
            let scl = 1.0 / (b[0] + b[1] * rat);
            [(a[0] + a[1] * rat) * scl, (a[1] - a[0] * rat) * scl]
        }
    } else {
        let rat = b[0] / b[1];
        let scl = 1.0 / (b[1] + b[0] * rat);
        [(a[0] * rat + a[1]) * scl, (a[1] * rat - a[0]) * scl]
    }
}

/// CPython 3.11 `_Py_c_quot` (Smith's algorithm), used by `x / complex`.
fn c_quot(a: P, b: P) -> P {
    let abs_br = b[0].abs();
    let abs_bi = b[1].abs();
    if abs_br >= abs_bi {
        if abs_br == 0.0 {
            [0.0, 0.0]
        } else {
            let ratio = b[1] / b[0];
            let denom = b[0] + b[1] * ratio;
            [(a[0] + a[1] * ratio) / denom, (a[1] - a[0] * ratio) / denom]
        }
    } else if abs_bi >= abs_br {
        let ratio = b[0] / b[1];
        let denom = b[0] * ratio + b[1];
        [(a[0] * ratio + a[1]) / denom, (a[1] * ratio - a[0]) / denom]
    } else {
        [f64::NAN, f64::NAN]
    }
}

/// CPython's `x ** 2` for a float: the C library's `pow`, which is not always
/// equal to `x * x` (glibc's pow is not correctly rounded). `black_box` keeps the
/// optimiser from rewriting `powf(x, 2)` into `x * x`.
fn py_sq(x: f64) -> f64 {
    x.abs().powf(std::hint::black_box(2.0))
}

/// CPython 3.11's `hash(float)` (`_Py_HashDouble`); NaN hashes by address in
/// CPython and is mapped to 0 here.
pub fn py_float_hash(v: f64) -> i64 {
    const BITS: u32 = 61;
    const MODULUS: u64 = (1u64 << BITS) - 1;
    if !v.is_finite() {
        return if v.is_nan() {
            0
        } else if v > 0.0 {
            314159
        } else {
            -314159
        };
    }
    let (mut m, mut e) = frexp(v);
    let mut sign: i64 = 1;
    if m < 0.0 {
        sign = -1;
        m = -m;
    }
    let mut x: u64 = 0;
    while m != 0.0 {
        x = ((x << 28) & MODULUS) | (x >> (BITS - 28));
        m *= 268435456.0;
        e -= 28;
        let y = m as u64;
        m -= y as f64;
        x += y;
        if x >= MODULUS {
            x -= MODULUS;
        }
    }
    let e = if e >= 0 { (e % BITS as i32) as u32 } else { BITS - 1 - ((-1 - e) % BITS as i32) as u32 };
    x = ((x << e) & MODULUS) | (x >> (BITS - e));
    let x = (x as i64).wrapping_mul(sign);
    if x == -1 { -2 } else { x }
}

/// C `frexp`: `v = m * 2^e` with `0.5 <= |m| < 1`.
fn frexp(v: f64) -> (f64, i32) {
    if v == 0.0 || !v.is_finite() {
        return (v, 0);
    }
    let mut bits = v.to_bits();
    let mut ef = ((bits >> 52) & 0x7ff) as i32;
    let mut adj = 0;
    if ef == 0 {
        // subnormal: scale into the normal range first
        let s = v * f64::from_bits(0x4350000000000000); // 2^54
        bits = s.to_bits();
        ef = ((bits >> 52) & 0x7ff) as i32;
        adj = -54;
    }
    let m = f64::from_bits((bits & !(0x7ffu64 << 52)) | (1022u64 << 52));
    (m, ef - 1022 + adj)
}

/// Iteration order of `set(values)` in CPython 3.11 for at most 4 floats
/// (small table of 8 slots, no resize): open addressing with the perturbed
/// probe `i = (5 i + 1 + perturb) & 7`, `perturb >>= 5`. Equal values
/// (including `0.0 == -0.0`) keep the first one inserted.
pub fn py_set_order(values: &[f64]) -> Vec<f64> {
    set_order(values).to_vec()
}

/// [`py_set_order`] on the stack.
fn set_order(values: &[f64]) -> Few<f64, 4> {
    assert!(values.len() <= 4, "set emulation is for the small table only");
    const MASK: usize = 7;
    let mut table: [Option<(i64, f64)>; 8] = [None; 8];
    for &x in values {
        let h = py_float_hash(x);
        let mut i = (h as u64 as usize) & MASK;
        let mut perturb = h as u64;
        loop {
            match table[i] {
                None => {
                    table[i] = Some((h, x));
                    break;
                }
                Some((eh, ek)) if eh == h && ek == x => break,
                Some(_) => {}
            }
            perturb >>= 5;
            i = (i.wrapping_mul(5).wrapping_add(1).wrapping_add(perturb as usize)) & MASK;
        }
    }
    let mut out = Few::new();
    table.iter().flatten().for_each(|&(_, x)| out.push(x));
    out
}

// ---------------------------------------------------------------------------
// numpy.roots (companion matrix + LAPACK dgeev, eigenvalues only)
// ---------------------------------------------------------------------------

/// `numpy.roots(p)` for real coefficients (highest degree first), degree <= 3
/// after stripping leading zeros: `(re, im)` pairs in numpy's order. Leading
/// zeros are dropped, trailing zeros become exact zero roots at the end.
pub fn np_roots(p: &[f64]) -> Vec<(f64, f64)> {
    // The trailing zeros are zero roots after the others (any number of them).
    let Some(last) = p.iter().rposition(|&c| c != 0.0) else { return Vec::new() };
    let mut out = complex_roots(&p[..=last]).to_vec();
    out.extend(std::iter::repeat_n((0.0, 0.0), p.len() - last - 1));
    out
}

/// [`np_roots`] on the stack, for at most five coefficients (the port's
/// matrices are at most 4×4, so there are at most four roots).
fn complex_roots(p: &[f64]) -> Few<(f64, f64), 4> {
    debug_assert!(p.len() <= 5, "complex_roots: at most five coefficients");
    let first = p.iter().position(|&c| c != 0.0);
    let Some(first) = first else {
        return Few::new();
    };
    let Some(last) = p.iter().rposition(|&c| c != 0.0) else { return Few::new() };
    let trailing = p.len() - last - 1;
    let q = &p[first..=last];
    let mut out = Few::new();
    let n = q.len() - 1; // companion size
    if n == 1 {
        // A 1×1 companion matrix is its own eigenvalue (LAPACK returns the
        // entry untouched): skip the machinery, same bits.
        out.push((-q[1] / q[0], 0.0));
    } else if n >= 2 {
        assert!(n <= lapack::MAXN, "np_roots: degree too high for this port");
        let mut a = lapack::Mat::zeros(n);
        for j in 1..=n {
            a.set(1, j, -q[j] / q[0]);
        }
        for i in 2..=n {
            a.set(i, i - 1, 1.0);
        }
        let (wr, wi) = lapack::eigvals_fixed(&mut a);
        for k in 1..=n {
            out.push((wr[k], wi[k]));
        }
    }
    for _ in 0..trailing {
        out.push((0.0, 0.0));
    }
    out
}

/// svgpathtools' `polyroots(p, realroots=True, condition)`: real parts of roots
/// with `|imag| < 1e-8`, filtered by `condition`, then its near-duplicate
/// filter. QUIRK kept: the filter records the index of the *pair* in
/// `combinations(roots, 2)` and drops the root with that index, so for three
/// roots a close pair (0, 2) drops root 1.
pub fn polyroots_real(p: &[f64], condition: impl Fn(f64) -> bool) -> Vec<f64> {
    let roots: Vec<f64> = np_roots(p).into_iter().filter(|&(_, im)| im.abs() < 1e-8).map(|(re, _)| re).filter(|&r| condition(r)).collect();
    let mut out = Vec::new();
    keep_distinct(&roots, |r| out.push(r));
    out
}

/// [`polyroots_real`] on the stack, for at most five coefficients.
fn real_roots(p: &[f64], condition: impl Fn(f64) -> bool) -> Few<f64, 4> {
    let mut roots: Few<f64, 4> = Few::new();
    for &(re, im) in complex_roots(p).iter() {
        if im.abs() < 1e-8 && condition(re) {
            roots.push(re);
        }
    }
    let mut out = Few::new();
    keep_distinct(&roots, |r| out.push(r));
    out
}

/// The library's near-duplicate filter of [`polyroots_real`], passing the kept
/// roots to `keep` in order (QUIRK: pair indices drop roots, see there).
fn keep_distinct(roots: &[f64], mut keep: impl FnMut(f64)) {
    let n = roots.len();
    let mut small = [false; 8];
    let mut large = Vec::new();
    let dropped: &mut [bool] = if n <= small.len() {
        &mut small[..n]
    } else {
        large.resize(n, false);
        &mut large
    };
    let mut idx = 0;
    for i in 0..n {
        for j in i + 1..n {
            let (r1, r2) = (roots[i], roots[j]);
            if (r1 - r2).abs() < 1e-8 + 1e-5 * r2.abs() && idx < n {
                dropped[idx] = true;
            }
            idx += 1;
        }
    }
    for (i, &r) in roots.iter().enumerate() {
        if !dropped[i] {
            keep(r);
        }
    }
}

/// svgpathtools' `polyroots01`: real roots in the closed interval [0, 1].
pub fn polyroots01(p: &[f64]) -> Vec<f64> {
    polyroots_real(p, |r| (0.0..=1.0).contains(&r))
}

/// [`polyroots01`] on the stack, for at most five coefficients.
fn real_roots01(p: &[f64]) -> Few<f64, 4> {
    real_roots(p, |r| (0.0..=1.0).contains(&r))
}

/// Minimal ports of the LAPACK 3.11 routines behind `numpy.linalg.eigvals`
/// (DGEEV with JOBVL = JOBVR = 'N': DGEBAL 'B', DGEHD2, DHSEQR -> DLAHQR,
/// DLANV2). Matrices are tiny (n <= 4), column-major, indexed from 1 like the
/// Fortran so the code can be checked line by line against LAPACK.
#[doc(hidden)]
#[allow(clippy::needless_range_loop, clippy::too_many_arguments)]
pub mod lapack {
    pub const MAXN: usize = 4;
    const SAFMIN: f64 = f64::MIN_POSITIVE; // DLAMCH('S')
    const EPS: f64 = f64::EPSILON * 0.5; // DLAMCH('E')
    const ULP: f64 = f64::EPSILON; // DLAMCH('P')

    /// Whether the BLAS-2 kernels (dgemv/dger in DLARF) fuse multiply-adds.
    /// OpenBLAS' Haswell/SkylakeX kernels do; chosen by comparison with numpy.
    pub const BLAS_FMA: bool = false;

    #[derive(Clone, Copy)]
    pub struct Mat {
        pub n: usize,
        a: [f64; MAXN * MAXN],
    }

    impl Mat {
        pub fn zeros(n: usize) -> Mat {
            Mat { n, a: [0.0; MAXN * MAXN] }
        }
        #[inline]
        pub fn get(&self, i: usize, j: usize) -> f64 {
            self.a[(i - 1) + (j - 1) * self.n]
        }
        #[inline]
        pub fn set(&mut self, i: usize, j: usize, v: f64) {
            self.a[(i - 1) + (j - 1) * self.n] = v;
        }
        fn swap(&mut self, i1: usize, j1: usize, i2: usize, j2: usize) {
            let t = self.get(i1, j1);
            self.set(i1, j1, self.get(i2, j2));
            self.set(i2, j2, t);
        }
    }

    #[inline]
    fn sign(a: f64, b: f64) -> f64 {
        a.abs().copysign(b)
    }

    #[inline]
    fn madd(a: f64, b: f64, c: f64) -> f64 {
        // c + a*b as a BLAS kernel computes it
        if BLAS_FMA { a.mul_add(b, c) } else { c + a * b }
    }

    /// DNRM2. OpenBLAS' x86-64 kernel sums squares in x87 extended precision;
    /// a double-double sum with a corrected square root gives the same
    /// (correctly rounded) result in all but pathological cases.
    pub fn dnrm2(x: &[f64]) -> f64 {
        let (mut hi, mut lo) = (0.0f64, 0.0f64);
        for &v in x {
            let p = v * v;
            let pe = v.mul_add(v, -p);
            let s = hi + p;
            let bb = s - hi;
            let se = (hi - (s - bb)) + (p - bb);
            hi = s;
            lo += se + pe;
        }
        let s = hi + lo;
        let e = lo - (s - hi);
        if s <= 0.0 {
            return 0.0;
        }
        let r = s.sqrt();
        // one Newton correction on the double-double value
        let res = (-r).mul_add(r, s) + e;
        r + res / (2.0 * r)
    }

    /// IDAMAX: first index (1-based) of the largest |x|.
    fn idamax(x: &[f64]) -> usize {
        let mut best = 0;
        let mut bv = -1.0;
        for (k, &v) in x.iter().enumerate() {
            if v.abs() > bv {
                bv = v.abs();
                best = k;
            }
        }
        best + 1
    }

    /// DLAPY2: sqrt(x^2 + y^2) the LAPACK 3.11 way.
    pub fn dlapy2(x: f64, y: f64) -> f64 {
        if x.is_nan() {
            return x;
        }
        if y.is_nan() {
            return y;
        }
        let xa = x.abs();
        let ya = y.abs();
        let w = xa.max(ya);
        let z = xa.min(ya);
        if z == 0.0 || w > f64::MAX {
            w
        } else {
            let q = z / w;
            w * (1.0 + q * q).sqrt()
        }
    }

    /// DLARFG: Householder reflector for (alpha, x); returns tau, updates
    /// alpha (to beta) and x (to v(2:n)).
    pub fn dlarfg(alpha: &mut f64, x: &mut [f64]) -> f64 {
        if x.is_empty() {
            return 0.0;
        }
        let mut xnorm = dnrm2(x);
        if xnorm == 0.0 {
            return 0.0;
        }
        let mut beta = -sign(dlapy2(*alpha, xnorm), *alpha);
        let safmin = SAFMIN / EPS;
        let mut knt = 0;
        if beta.abs() < safmin {
            let rsafmn = 1.0 / safmin;
            loop {
                knt += 1;
                for v in x.iter_mut() {
                    *v *= rsafmn;
                }
                beta *= rsafmn;
                *alpha *= rsafmn;
                if !(beta.abs() < safmin && knt < 20) {
                    break;
                }
            }
            xnorm = dnrm2(x);
            beta = -sign(dlapy2(*alpha, xnorm), *alpha);
        }
        let tau = (beta - *alpha) / beta;
        let scal = 1.0 / (*alpha - beta);
        for v in x.iter_mut() {
            *v *= scal;
        }
        for _ in 0..knt {
            beta *= safmin;
        }
        *alpha = beta;
        tau
    }

    /// DGEBAL with JOB = 'B' (permute, then scale by powers of two).
    /// Returns (ilo, ihi).
    fn dgebal(a: &mut Mat) -> (usize, usize) {
        let n = a.n;
        let mut scale = [0.0f64; MAXN + 1];
        let mut k = 1usize;
        let mut l = n;
        if n == 0 {
            return (1, 0);
        }
        // Search for rows isolating an eigenvalue and push them down.
        'rows: loop {
            let mut found = None;
            for j in (1..=l).rev() {
                let isolated = (1..=l).all(|i| i == j || a.get(j, i) == 0.0);
                if isolated {
                    found = Some(j);
                    break;
                }
            }
            let Some(j) = found else { break 'rows };
            let m = l;
            scale[m] = j as f64;
            if j != m {
                for r in 1..=l {
                    a.swap(r, j, r, m);
                }
                for c in k..=n {
                    a.swap(j, c, m, c);
                }
            }
            if l == 1 {
                return (k, l);
            }
            l -= 1;
        }
        // Search for columns isolating an eigenvalue and push them left.
        loop {
            let mut found = None;
            for j in k..=l {
                let isolated = (k..=l).all(|i| i == j || a.get(i, j) == 0.0);
                if isolated {
                    found = Some(j);
                    break;
                }
            }
            let Some(j) = found else { break };
            let m = k;
            scale[m] = j as f64;
            if j != m {
                for r in 1..=l {
                    a.swap(r, j, r, m);
                }
                for c in k..=n {
                    a.swap(j, c, m, c);
                }
            }
            k += 1;
        }
        for s in scale.iter_mut().take(l + 1).skip(k) {
            *s = 1.0;
        }
        // Iterative scaling.
        const SCLFAC: f64 = 2.0;
        const FACTOR: f64 = 0.95;
        let sfmin1 = SAFMIN / ULP;
        let sfmax1 = 1.0 / sfmin1;
        let sfmin2 = sfmin1 * SCLFAC;
        let sfmax2 = 1.0 / sfmin2;
        loop {
            let mut noconv = false;
            for i in k..=l {
                let mut buf = [0.0f64; MAXN];
                let m = l + 1 - k;
                for t in 0..m {
                    buf[t] = a.get(k + t, i);
                }
                let mut c = dnrm2(&buf[..m]);
                for t in 0..m {
                    buf[t] = a.get(i, k + t);
                }
                let mut r = dnrm2(&buf[..m]);
                for t in 0..l {
                    buf[t] = a.get(t + 1, i);
                }
                let ica = idamax(&buf[..l]);
                let mut ca = a.get(ica, i).abs();
                for t in 0..=n - k {
                    buf[t] = a.get(i, k + t);
                }
                let ira = idamax(&buf[..=n - k]);
                let mut ra = a.get(i, ira + k - 1).abs();
                if c == 0.0 || r == 0.0 {
                    continue;
                }
                let mut g = r / SCLFAC;
                let mut f = 1.0f64;
                let s = c + r;
                while !(c >= g || f.max(c).max(ca) >= sfmax2 || r.min(g).min(ra) <= sfmin2) {
                    if (c + f + ca + r + g + ra).is_nan() {
                        return (k, l); // LAPACK reports an error; not reachable for finite input
                    }
                    f *= SCLFAC;
                    c *= SCLFAC;
                    ca *= SCLFAC;
                    r /= SCLFAC;
                    g /= SCLFAC;
                    ra /= SCLFAC;
                }
                g = c / SCLFAC;
                while !(g < r || r.max(ra) >= sfmax2 || f.min(c).min(g).min(ca) <= sfmin2) {
                    f /= SCLFAC;
                    c /= SCLFAC;
                    g /= SCLFAC;
                    ca /= SCLFAC;
                    r *= SCLFAC;
                    ra *= SCLFAC;
                }
                if c + r >= FACTOR * s {
                    continue;
                }
                if f < 1.0 && scale[i] < 1.0 && f * scale[i] <= sfmin1 {
                    continue;
                }
                if f > 1.0 && scale[i] > 1.0 && scale[i] >= sfmax1 / f {
                    continue;
                }
                let g = 1.0 / f;
                scale[i] *= f;
                noconv = true;
                for cc in k..=n {
                    a.set(i, cc, a.get(i, cc) * g);
                }
                for rr in 1..=l {
                    a.set(rr, i, a.get(rr, i) * f);
                }
            }
            if !noconv {
                break;
            }
        }
        (k, l)
    }

    /// DLARF applied with v = (1, v2..) and tau; `left` selects H*C, else C*H.
    /// C is the block rows r0..r1, columns c0..c1 of `a`.
    fn dlarf(a: &mut Mat, left: bool, v: &[f64], tau: f64, r0: usize, r1: usize, c0: usize, c1: usize) {
        if tau == 0.0 {
            return;
        }
        let m = r1 + 1 - r0;
        let n = c1 + 1 - c0;
        let mut lastv = if left { m } else { n };
        while lastv > 0 && v[lastv - 1] == 0.0 {
            lastv -= 1;
        }
        let c = |a: &Mat, i: usize, j: usize| a.get(r0 + i - 1, c0 + j - 1);
        if left {
            // ILADLC(lastv, n): last non-zero column of C(1:lastv, :)
            let lastc = if n == 0 {
                0
            } else if c(a, 1, n) != 0.0 || c(a, lastv.max(1), n) != 0.0 {
                n
            } else {
                (1..=n).rev().find(|&j| (1..=lastv).any(|i| c(a, i, j) != 0.0)).unwrap_or(0)
            };
            if lastv == 0 {
                return;
            }
            // work = C^T v  (DGEMV 'T'), then C -= tau v work^T (DGER)
            let mut work = [0.0f64; MAXN];
            for (j, w) in work.iter_mut().enumerate().take(lastc) {
                let mut t = 0.0;
                for i in 1..=lastv {
                    t = madd(c(a, i, j + 1), v[i - 1], t);
                }
                *w = t;
            }
            for (j, &w) in work.iter().enumerate().take(lastc) {
                let temp = -tau * w;
                for i in 1..=lastv {
                    let (ri, cj) = (r0 + i - 1, c0 + j);
                    a.set(ri, cj, madd(v[i - 1], temp, a.get(ri, cj)));
                }
            }
        } else {
            // ILADLR(m, lastv): last non-zero row of C(:, 1:lastv)
            let lastc = if m == 0 {
                0
            } else if c(a, m, 1) != 0.0 || c(a, m, lastv.max(1)) != 0.0 {
                m
            } else {
                let mut best = 0;
                for j in 1..=lastv {
                    let mut i = m;
                    while i >= 1 && c(a, i.max(1), j) == 0.0 {
                        i -= 1;
                    }
                    best = best.max(i);
                }
                best
            };
            if lastv == 0 {
                return;
            }
            // work = C v (DGEMV 'N'), then C -= tau work v^T (DGER)
            let mut work = [0.0f64; MAXN];
            for (i, w) in work.iter_mut().enumerate().take(lastc) {
                let mut t = 0.0;
                for j in 1..=lastv {
                    t = madd(c(a, i + 1, j), v[j - 1], t);
                }
                *w = t;
            }
            for j in 1..=lastv {
                let temp = -tau * v[j - 1];
                for (i, &w) in work.iter().enumerate().take(lastc) {
                    let (ri, cj) = (r0 + i, c0 + j - 1);
                    a.set(ri, cj, madd(w, temp, a.get(ri, cj)));
                }
            }
        }
    }

    /// DGEHD2: reduce rows/columns ilo..ihi to upper Hessenberg form.
    fn dgehd2(a: &mut Mat, ilo: usize, ihi: usize) {
        let n = a.n;
        for i in ilo..ihi {
            let len = ihi - i; // order of the reflector
            let mut alpha = a.get(i + 1, i);
            let mut x = [0.0f64; MAXN];
            for t in 0..len - 1 {
                x[t] = a.get(i + 2 + t, i);
            }
            let tau = dlarfg(&mut alpha, &mut x[..len - 1]);
            for t in 0..len - 1 {
                a.set(i + 2 + t, i, x[t]);
            }
            a.set(i + 1, i, alpha);
            let mut v = [0.0f64; MAXN];
            v[0] = 1.0;
            v[1..len].copy_from_slice(&x[..len - 1]);
            dlarf(a, false, &v[..len], tau, 1, ihi, i + 1, ihi);
            dlarf(a, true, &v[..len], tau, i + 1, ihi, i + 1, n);
        }
    }

    /// DLANV2 (LAPACK 3.11): Schur factorisation of a real 2×2 block; returns
    /// (rt1r, rt1i, rt2r, rt2i).
    pub fn dlanv2(mut a: f64, mut b: f64, mut c: f64, mut d: f64) -> (f64, f64, f64, f64) {
        const MULTPL: f64 = 4.0;
        let eps = ULP;
        let safmn2 = 2f64.powi(-485); // BASE**INT(LOG(SAFMIN/EPS)/LOG(BASE)/2)
        let safmx2 = 1.0 / safmn2;
        if c == 0.0 {
        } else if b == 0.0 {
            std::mem::swap(&mut a, &mut d);
            b = -c;
            c = 0.0;
        } else if (a - d) == 0.0 && sign(1.0, b) != sign(1.0, c) {
        } else {
            let mut temp = a - d;
            let mut p = 0.5 * temp;
            let bcmax = b.abs().max(c.abs());
            let bcmis = b.abs().min(c.abs()) * sign(1.0, b) * sign(1.0, c);
            let mut scale = p.abs().max(bcmax);
            let mut z = (p / scale) * p + (bcmax / scale) * bcmis;
            if z >= MULTPL * eps {
                // Real eigenvalues.
                z = p + sign(scale.sqrt() * z.sqrt(), p);
                a = d + z;
                d -= (bcmax / z) * bcmis;
                b -= c;
                c = 0.0;
            } else {
                // Complex or (almost) equal real eigenvalues: equalise the diagonal.
                let mut count = 0;
                let mut sigma = b + c;
                loop {
                    count += 1;
                    scale = temp.abs().max(sigma.abs());
                    if scale >= safmx2 {
                        sigma *= safmn2;
                        temp *= safmn2;
                        if count <= 20 {
                            continue;
                        }
                    }
                    if scale <= safmn2 {
                        sigma *= safmx2;
                        temp *= safmx2;
                        if count <= 20 {
                            continue;
                        }
                    }
                    break;
                }
                p = 0.5 * temp;
                let mut tau = dlapy2(sigma, temp);
                let cs = (0.5 * (1.0 + sigma.abs() / tau)).sqrt();
                let sn = -(p / (tau * cs)) * sign(1.0, sigma);
                let aa = a * cs + b * sn;
                let bb = -a * sn + b * cs;
                let cc = c * cs + d * sn;
                let dd = -c * sn + d * cs;
                a = aa * cs + cc * sn;
                b = bb * cs + dd * sn;
                c = -aa * sn + cc * cs;
                d = -bb * sn + dd * cs;
                temp = 0.5 * (a + d);
                a = temp;
                d = temp;
                if c != 0.0 {
                    if b != 0.0 {
                        if sign(1.0, b) == sign(1.0, c) {
                            // Real eigenvalues.
                            let sab = b.abs().sqrt();
                            let sac = c.abs().sqrt();
                            p = sign(sab * sac, c);
                            tau = 1.0 / (b + c).abs().sqrt();
                            let _ = tau;
                            a = temp + p;
                            d = temp - p;
                            b -= c;
                            c = 0.0;
                        }
                    } else {
                        b = -c;
                        c = 0.0;
                    }
                }
            }
        }
        let (rt1i, rt2i) = if c == 0.0 {
            (0.0, 0.0)
        } else {
            let v = b.abs().sqrt() * c.abs().sqrt();
            (v, -v)
        };
        (a, rt1i, d, rt2i)
    }

    /// DLAHQR with WANTT = WANTZ = false (eigenvalues only) on rows/columns
    /// ilo..ihi. Returns false if it did not converge.
    fn dlahqr(h: &mut Mat, ilo: usize, ihi: usize, wr: &mut [f64], wi: &mut [f64]) -> bool {
        const DAT1: f64 = 3.0 / 4.0;
        const DAT2: f64 = -0.4375;
        const KEXSH: usize = 10;
        let n = h.n;
        if n == 0 {
            return true;
        }
        if ilo == ihi {
            wr[ilo] = h.get(ilo, ilo);
            wi[ilo] = 0.0;
            return true;
        }
        if ihi >= 3 {
            for j in ilo..=ihi - 3 {
                h.set(j + 2, j, 0.0);
                h.set(j + 3, j, 0.0);
            }
        }
        if ilo + 2 <= ihi {
            h.set(ihi, ihi - 2, 0.0);
        }
        let nh = ihi - ilo + 1;
        let smlnum = SAFMIN * (nh as f64 / ULP);
        let itmax = 30 * nh.max(10);
        let mut kdefl = 0usize;
        let mut i = ihi;
        loop {
            let mut l = ilo;
            if i < ilo {
                return true;
            }
            let mut split = false;
            for _its in 0..=itmax {
                // Look for a single small subdiagonal element.
                let mut k = i;
                while k > l {
                    let hkk1 = h.get(k, k - 1).abs();
                    if hkk1 <= smlnum {
                        break;
                    }
                    let mut tst = h.get(k - 1, k - 1).abs() + h.get(k, k).abs();
                    if tst == 0.0 {
                        if k >= ilo + 2 {
                            tst += h.get(k - 1, k - 2).abs();
                        }
                        if k < ihi {
                            tst += h.get(k + 1, k).abs();
                        }
                    }
                    if hkk1 <= ULP * tst {
                        let ab = hkk1.max(h.get(k - 1, k).abs());
                        let ba = hkk1.min(h.get(k - 1, k).abs());
                        let aa = h.get(k, k).abs().max((h.get(k - 1, k - 1) - h.get(k, k)).abs());
                        let bb = h.get(k, k).abs().min((h.get(k - 1, k - 1) - h.get(k, k)).abs());
                        let s = aa + ab;
                        if ba * (ab / s) <= smlnum.max(ULP * (bb * (aa / s))) {
                            break;
                        }
                    }
                    k -= 1;
                }
                l = k;
                if l > ilo {
                    h.set(l, l - 1, 0.0);
                }
                if l + 1 >= i {
                    split = true;
                    break;
                }
                kdefl += 1;
                let i1 = l;
                let i2 = i;
                let (mut h11, mut h12, mut h21, mut h22);
                if kdefl.is_multiple_of(2 * KEXSH) {
                    let s = h.get(i, i - 1).abs() + h.get(i - 1, i - 2).abs();
                    h11 = DAT1 * s + h.get(i, i);
                    h12 = DAT2 * s;
                    h21 = s;
                    h22 = h11;
                } else if kdefl.is_multiple_of(KEXSH) {
                    let s = h.get(l + 1, l).abs() + h.get(l + 2, l + 1).abs();
                    h11 = DAT1 * s + h.get(l, l);
                    h12 = DAT2 * s;
                    h21 = s;
                    h22 = h11;
                } else {
                    h11 = h.get(i - 1, i - 1);
                    h21 = h.get(i, i - 1);
                    h12 = h.get(i - 1, i);
                    h22 = h.get(i, i);
                }
                let s = h11.abs() + h12.abs() + h21.abs() + h22.abs();
                let (rt1r, rt1i, rt2r, rt2i);
                if s == 0.0 {
                    rt1r = 0.0;
                    rt1i = 0.0;
                    rt2r = 0.0;
                    rt2i = 0.0;
                } else {
                    h11 /= s;
                    h21 /= s;
                    h12 /= s;
                    h22 /= s;
                    let tr = (h11 + h22) / 2.0;
                    let det = (h11 - tr) * (h22 - tr) - h12 * h21;
                    let rtdisc = det.abs().sqrt();
                    if det >= 0.0 {
                        rt1r = tr * s;
                        rt2r = rt1r;
                        rt1i = rtdisc * s;
                        rt2i = -rt1i;
                    } else {
                        let a1 = tr + rtdisc;
                        let a2 = tr - rtdisc;
                        let r = if (a1 - h22).abs() <= (a2 - h22).abs() { a1 * s } else { a2 * s };
                        rt1r = r;
                        rt2r = r;
                        rt1i = 0.0;
                        rt2i = 0.0;
                    }
                }
                // Look for two consecutive small subdiagonal elements.
                let mut m = i - 2;
                let mut v = [0.0f64; 3];
                loop {
                    let mut h21s = h.get(m + 1, m);
                    let s = (h.get(m, m) - rt2r).abs() + rt2i.abs() + h21s.abs();
                    h21s = h.get(m + 1, m) / s;
                    v[0] = h21s * h.get(m, m + 1) + (h.get(m, m) - rt1r) * ((h.get(m, m) - rt2r) / s) - rt1i * (rt2i / s);
                    v[1] = h21s * (h.get(m, m) + h.get(m + 1, m + 1) - rt1r - rt2r);
                    v[2] = h21s * h.get(m + 2, m + 1);
                    let s = v[0].abs() + v[1].abs() + v[2].abs();
                    v[0] /= s;
                    v[1] /= s;
                    v[2] /= s;
                    if m == l {
                        break;
                    }
                    let h00 = h.get(m, m - 1).abs() * (v[1].abs() + v[2].abs());
                    let h01 = ULP * v[0].abs() * (h.get(m - 1, m - 1).abs() + h.get(m, m).abs() + h.get(m + 1, m + 1).abs());
                    if h00 <= h01 {
                        break;
                    }
                    m -= 1;
                }
                // Double-shift QR step.
                for k in m..i {
                    let nr = 3.min(i - k + 1);
                    if k > m {
                        for t in 0..nr {
                            v[t] = h.get(k + t, k - 1);
                        }
                    }
                    let (head, tail) = v.split_at_mut(1);
                    let t1 = dlarfg(&mut head[0], &mut tail[..nr - 1]);
                    if k > m {
                        h.set(k, k - 1, v[0]);
                        h.set(k + 1, k - 1, 0.0);
                        if k + 1 < i {
                            h.set(k + 2, k - 1, 0.0);
                        }
                    } else if m > l {
                        h.set(k, k - 1, h.get(k, k - 1) * (1.0 - t1));
                    }
                    let v2 = v[1];
                    let t2 = t1 * v2;
                    if nr == 3 {
                        let v3 = v[2];
                        let t3 = t1 * v3;
                        for j in k..=i2 {
                            let sum = h.get(k, j) + v2 * h.get(k + 1, j) + v3 * h.get(k + 2, j);
                            h.set(k, j, h.get(k, j) - sum * t1);
                            h.set(k + 1, j, h.get(k + 1, j) - sum * t2);
                            h.set(k + 2, j, h.get(k + 2, j) - sum * t3);
                        }
                        for j in i1..=(k + 3).min(i) {
                            let sum = h.get(j, k) + v2 * h.get(j, k + 1) + v3 * h.get(j, k + 2);
                            h.set(j, k, h.get(j, k) - sum * t1);
                            h.set(j, k + 1, h.get(j, k + 1) - sum * t2);
                            h.set(j, k + 2, h.get(j, k + 2) - sum * t3);
                        }
                    } else if nr == 2 {
                        for j in k..=i2 {
                            let sum = h.get(k, j) + v2 * h.get(k + 1, j);
                            h.set(k, j, h.get(k, j) - sum * t1);
                            h.set(k + 1, j, h.get(k + 1, j) - sum * t2);
                        }
                        for j in i1..=i {
                            let sum = h.get(j, k) + v2 * h.get(j, k + 1);
                            h.set(j, k, h.get(j, k) - sum * t1);
                            h.set(j, k + 1, h.get(j, k + 1) - sum * t2);
                        }
                    }
                }
            }
            if !split {
                return false;
            }
            if l == i {
                wr[i] = h.get(i, i);
                wi[i] = 0.0;
            } else if l + 1 == i {
                let (r1r, r1i, r2r, r2i) = dlanv2(h.get(i - 1, i - 1), h.get(i - 1, i), h.get(i, i - 1), h.get(i, i));
                wr[i - 1] = r1r;
                wi[i - 1] = r1i;
                wr[i] = r2r;
                wi[i] = r2i;
            }
            kdefl = 0;
            i = l - 1; // l >= ilo >= 1
        }
    }

    /// Eigenvalues as numpy.linalg.eigvals computes them (DGEEV 'N','N').
    /// Returned in LAPACK's order (0-based vectors of length n).
    pub fn eigvals(a: &mut Mat) -> (Vec<f64>, Vec<f64>) {
        let n = a.n;
        let (wr, wi) = eigvals_fixed(a);
        (wr[1..=n].to_vec(), wi[1..=n].to_vec())
    }

    /// [`eigvals`] into arrays indexed from 1 like the Fortran (entries past
    /// `n` are zero).
    pub(super) fn eigvals_fixed(a: &mut Mat) -> ([f64; MAXN + 1], [f64; MAXN + 1]) {
        let n = a.n;
        let mut wr = [0.0f64; MAXN + 1];
        let mut wi = [0.0f64; MAXN + 1];
        let (ilo, ihi) = dgebal(a);
        if ihi > ilo {
            dgehd2(a, ilo, ihi);
        }
        // DHSEQR: eigenvalues isolated by the balancing.
        for i in 1..ilo {
            wr[i] = a.get(i, i);
        }
        for i in ihi + 1..=n {
            wr[i] = a.get(i, i);
        }
        if ilo == ihi {
            wr[ilo] = a.get(ilo, ilo);
            wi[ilo] = 0.0;
        } else if !dlahqr(a, ilo, ihi, &mut wr, &mut wi) {
            // LAPACK would fall back to DLAQR0; never observed for n <= 3.
            for k in 1..=n {
                wr[k] = f64::NAN;
                wi[k] = f64::NAN;
            }
        }
        (wr, wi)
    }
}

// ---------------------------------------------------------------------------
// Bézier helpers (svgpathtools' bezier.py)
// ---------------------------------------------------------------------------

/// `bezier_point` for one coordinate (Horner forms of the library).
fn bezier_point_1d(p: &[f64], t: f64) -> f64 {
    match p.len() {
        4 => p[0] + t * (3.0 * (p[1] - p[0]) + t * (3.0 * (p[0] + p[2]) - 6.0 * p[1] + t * (-p[0] + 3.0 * (p[1] - p[2]) + p[3]))),
        3 => p[0] + t * (2.0 * (p[1] - p[0]) + t * (p[0] - 2.0 * p[1] + p[2])),
        2 => p[0] + t * (p[1] - p[0]),
        _ => p[0],
    }
}

/// `bezier_point` on points; complex arithmetic with a real `t` is
/// component-wise for finite values.
fn bezier_point(p: &[P], t: f64) -> P {
    let mut xs = [0.0; 4];
    let mut ys = [0.0; 4];
    for (k, q) in p.iter().enumerate() {
        xs[k] = q[0];
        ys[k] = q[1];
    }
    [bezier_point_1d(&xs[..p.len()], t), bezier_point_1d(&ys[..p.len()], t)]
}

/// `bezier2polynomial` for one real coordinate, highest degree first.
fn bezier2poly(p: &[f64]) -> Few<f64, 4> {
    match p.len() {
        4 => Few::from_slice(&[-p[0] + 3.0 * (p[1] - p[2]) + p[3], 3.0 * (p[0] - 2.0 * p[1] + p[2]), 3.0 * (p[1] - p[0]), p[0]]),
        3 => Few::from_slice(&[p[0] - 2.0 * p[1] + p[2], 2.0 * (p[1] - p[0]), p[0]]),
        2 => Few::from_slice(&[p[1] - p[0], p[0]]),
        _ => Few::from_slice(p),
    }
}

/// `numpy.poly1d(c).deriv().coeffs` (leading zeros trimmed first).
fn poly_deriv(c: &[f64]) -> Few<f64, 4> {
    let first = c.iter().position(|&x| x != 0.0).unwrap_or(c.len());
    let c = &c[first..];
    if c.len() <= 1 {
        return Few::from_slice(&[0.0]);
    }
    let n = c.len() - 1;
    let mut out = Few::new();
    (0..n).for_each(|k| out.push(c[k] * (n - k) as f64));
    out
}

/// `numpy.polyval` (Horner from a zero start).
fn polyval(c: &[f64], t: f64) -> f64 {
    let mut y = 0.0;
    for &ci in c {
        y = y * t + ci;
    }
    y
}

/// `bezier_real_minmax` for a cubic's coordinate (closed form for the
/// derivative roots unless the cubic term vanishes, then `polyroots01`).
fn cubic_real_minmax(a: &[f64; 4]) -> (f64, f64) {
    let mut ext: Few<f64, 8> = Few::from_slice(&[0.0, 1.0]);
    let denom = a[0] - 3.0 * a[1] + 3.0 * a[2] - a[3];
    if denom.abs() > 1e-12 {
        let delta = py_sq(a[1]) - (a[0] + a[1]) * a[2] + py_sq(a[2]) + (a[0] - a[1]) * a[3];
        if delta >= 0.0 {
            let sqdelta = delta.sqrt();
            let tau = a[0] - 2.0 * a[1] + a[2];
            let r1 = (tau + sqdelta) / denom;
            let r2 = (tau - sqdelta) / denom;
            if 0.0 < r1 && r1 < 1.0 {
                ext.push(r1);
            }
            if 0.0 < r2 && r2 < 1.0 {
                ext.push(r2);
            }
        }
    } else {
        let d = poly_deriv(&bezier2poly(a));
        real_roots01(&d).iter().for_each(|&r| ext.push(r));
    }
    min_max(ext.iter().map(|&t| bezier_point_1d(a, t)))
}

/// `bezier_bounding_box` as (xmin, xmax, ymin, ymax).
fn bezier_bbox(b: &Bez) -> [f64; 4] {
    let pts = b.pts();
    if pts.len() == 4 {
        let xs = [pts[0][0], pts[1][0], pts[2][0], pts[3][0]];
        let ys = [pts[0][1], pts[1][1], pts[2][1], pts[3][1]];
        let (x0, x1) = cubic_real_minmax(&xs);
        let (y0, y1) = cubic_real_minmax(&ys);
        return [x0, x1, y0, y1];
    }
    // Quadratic (or lower): power-basis polynomial, roots of its derivative
    // in the open interval, values by numpy.polyval.
    let mut out = [0.0; 4];
    for k in 0..2 {
        let mut cs: Few<f64, 4> = Few::new();
        pts.iter().for_each(|p| cs.push(p[k]));
        let poly = bezier2poly(&cs);
        let mut ext: Few<f64, 8> = Few::from_slice(&[0.0, 1.0]);
        real_roots(&poly_deriv(&poly), |r| 0.0 < r && r < 1.0).iter().for_each(|&r| ext.push(r));
        let (lo, hi) = min_max(ext.iter().map(|&t| polyval(&poly, t)));
        out[2 * k] = lo;
        out[2 * k + 1] = hi;
    }
    out
}

fn boxes_intersect(b1: &[f64; 4], b2: &[f64; 4]) -> bool {
    // interval_intersection_width(...) > 0 for both axes: touching boxes
    // (zero overlap width) do not intersect.
    let w = |a: f64, b: f64, c: f64, d: f64| 0f64.max(b.min(d) - a.max(c));
    w(b1[0], b1[1], b2[0], b2[1]) > 0.0 && w(b1[2], b1[3], b2[2], b2[3]) > 0.0
}

fn box_area(b: &[f64; 4]) -> f64 {
    (b[1] - b[0]) * (b[3] - b[2])
}

/// A sub-curve of the subdivision (2..=4 control points).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bez {
    n: usize,
    p: [P; 4],
}

impl Bez {
    fn new(pts: &[P]) -> Bez {
        let mut p = [[0.0; 2]; 4];
        p[..pts.len()].copy_from_slice(pts);
        Bez { n: pts.len(), p }
    }
    fn pts(&self) -> &[P] {
        &self.p[..self.n]
    }
}

fn avg2(a: f64, b: f64) -> f64 {
    // split_bezier computes (1 - t)*a + t*b with t = 0.5
    0.5 * a + 0.5 * b
}

/// `halve_bezier`: the cubic closed form, de Casteljau (`split_bezier`) else.
fn halve(b: &Bez) -> (Bez, Bez) {
    let p = b.pts();
    if p.len() == 4 {
        let f = |k: usize| {
            let (p0, p1, p2, p3) = (p[0][k], p[1][k], p[2][k], p[3][k]);
            let mid = (p0 + 3.0 * p1 + 3.0 * p2 + p3) / 8.0;
            ([p0, (p0 + p1) / 2.0, (p0 + 2.0 * p1 + p2) / 4.0, mid], [mid, (p1 + 2.0 * p2 + p3) / 4.0, (p2 + p3) / 2.0, p3])
        };
        let (lx, rx) = f(0);
        let (ly, ry) = f(1);
        let mk = |x: [f64; 4], y: [f64; 4]| Bez::new(&[[x[0], y[0]], [x[1], y[1]], [x[2], y[2]], [x[3], y[3]]]);
        return (mk(lx, ly), mk(rx, ry));
    }
    // de Casteljau with t = 0.5
    let mut left: Few<P, 4> = Few::new();
    let mut right: Few<P, 4> = Few::new();
    let mut cur: Few<P, 4> = Few::from_slice(p);
    loop {
        left.push(cur[0]);
        right.push(cur[cur.len() - 1]);
        if cur.len() == 1 {
            break;
        }
        let mut next: Few<P, 4> = Few::new();
        cur.windows(2).for_each(|w| next.push([avg2(w[0][0], w[1][0]), avg2(w[0][1], w[1][1])]));
        cur = next;
    }
    right.items[..right.len].reverse();
    (Bez::new(&left), Bez::new(&right))
}

#[derive(Clone, Copy)]
struct BPair {
    b1: Bez,
    b2: Bez,
    t1: f64,
    t2: f64,
}

/// `bezier_intersections(bez1, bez2, longer_length, tol, tol_deC)`.
///
/// QUIRK kept: when a pair has converged, the library removes from the list it
/// is iterating every pair sharing a sub-curve with it (compared by value),
/// which shifts the positions of both the inner and outer iterations (CPython
/// list iterators are index based); pairs skipped that way are neither
/// processed nor subdivided. This is reproduced with plain indices.
fn bezier_intersections(
    bez1: &[P],
    bez2: &[P],
    longer_length: f64,
    tol: f64,
    tol_dec: f64,
    out: &mut Vec<(f64, f64)>,
) -> Result<(), IntersectError> {
    let maxits = (1.0 - (tol_dec / longer_length).ln() / 2f64.ln()).ceil();
    let mut pair_list = vec![BPair { b1: Bez::new(bez1), b2: Bez::new(bez2), t1: 0.5, t2: 0.5 }];
    let mut approx_points: Vec<P> = Vec::new();
    let mut k: i32 = 0;
    while !pair_list.is_empty() && (k as f64) < maxits {
        let mut new_pairs = Vec::new();
        let delta = 0.5f64.powi(k + 2);
        let mut i = 0;
        while i < pair_list.len() {
            let pair = pair_list[i];
            i += 1;
            let bb1 = bezier_bbox(&pair.b1);
            let bb2 = bezier_bbox(&pair.b2);
            if !boxes_intersect(&bb1, &bb2) {
                continue;
            }
            if box_area(&bb1) < tol_dec && box_area(&bb2) < tol_dec {
                let point = bezier_point(bez1, pair.t1);
                let known = approx_points.iter().any(|y| (point[0] - y[0]).hypot(point[1] - y[1]) < tol);
                if !known {
                    approx_points.push(point);
                    out.push((pair.t1, pair.t2));
                }
                let mut j = 0;
                while j < pair_list.len() {
                    let o = pair_list[j];
                    j += 1;
                    if pair.b1 == o.b1 || pair.b2 == o.b2 || pair.b1 == o.b2 || pair.b2 == o.b1 {
                        // `list.remove` while both loops iterate by index: the
                        // next element of each loop is skipped, as in CPython.
                        pair_list.remove(j - 1);
                    }
                }
            } else {
                let (c11, c12) = halve(&pair.b1);
                let (c21, c22) = halve(&pair.b2);
                let (t11, t12) = (pair.t1 - delta, pair.t1 + delta);
                let (t21, t22) = (pair.t2 - delta, pair.t2 + delta);
                new_pairs.push(BPair { b1: c11, b2: c21, t1: t11, t2: t21 });
                new_pairs.push(BPair { b1: c11, b2: c22, t1: t11, t2: t22 });
                new_pairs.push(BPair { b1: c12, b2: c21, t1: t12, t2: t21 });
                new_pairs.push(BPair { b1: c12, b2: c22, t1: t12, t2: t22 });
            }
        }
        if new_pairs.len() > MAX_PAIRS {
            return Err(IntersectError::TooManyPairs);
        }
        pair_list = new_pairs;
        k += 1;
    }
    if k as f64 >= maxits {
        return Err(IntersectError::MaxIterations);
    }
    Ok(())
}

/// `bezier_by_line_intersections(bezier, line)`: `(t_bezier, t_line)` pairs.
fn bezier_by_line(bez: &[P], line: &[P; 2], line_num: Num, out: &mut Vec<(f64, f64)>) -> Result<(), IntersectError> {
    if line[0] == line[1] {
        return Err(IntersectError::DegenerateLine);
    }
    if bez.iter().all(|p| *p == bez[0]) {
        return Err(IntersectError::NodalBezier);
    }
    let end = [line[1][0] - line[0][0], line[1][1] - line[0][1]];
    let line_length = end[0].hypot(end[1]);
    // `line_length / shifted_line_end`: the line's number type decides which
    // division runs.
    let rot = match line_num {
        Num::Numpy => np_quot([line_length, 0.0], end),
        Num::Python => c_quot([line_length, 0.0], end),
    };
    let n = bez.len();
    let mut xs = [0.0; 4];
    let mut ys = [0.0; 4];
    for (k, z) in bez.iter().enumerate() {
        let shifted = [z[0] - line[0][0], z[1] - line[0][1]];
        let tz = c_prod(rot, shifted);
        xs[k] = tz[0];
        ys[k] = tz[1];
    }
    let roots = real_roots01(&bezier2poly(&ys[..n]));
    for &t in set_order(&roots).iter() {
        let xval = bezier_point_1d(&xs[..n], t);
        if 0.0 <= xval && xval <= line_length {
            out.push((t, xval / line_length));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Lengths (the subdivision budget depends on them, and the box mesh's vertex counts)
// ---------------------------------------------------------------------------

/// `QuadraticBezier.length()` of svgpathtools: its closed form, bit for bit (which
/// loses digits on nearly straight curves: the reference's count of mesh vertices on
/// an edge rounds this value up).
pub fn quad_length(p: &[P; 3]) -> f64 {
    let a = [p[0][0] - 2.0 * p[1][0] + p[2][0], p[0][1] - 2.0 * p[1][1] + p[2][1]];
    let b = [2.0 * (p[1][0] - p[0][0]), 2.0 * (p[1][1] - p[0][1])];
    let abs_a = a[0].hypot(a[1]);
    let abs_b = b[0].hypot(b[1]);
    if abs_a < 1e-12 {
        return abs_b;
    }
    let c2 = 4.0 * (a[0] * a[0] + a[1] * a[1]);
    let c1 = 4.0 * (a[0] * b[0] + a[1] * b[1]);
    let c0 = b[0] * b[0] + b[1] * b[1];
    let beta = c1 / (2.0 * c2);
    let gamma = c0 / c2 - beta * beta;
    let dq1 = (c2 + c1 + c0).sqrt();
    let dq0 = c0.sqrt();
    let num = c2.sqrt() * (1.0 + beta) + dq1;
    let den = c2.sqrt() * beta + dq0;
    let lg = if den != 0.0 { (num / den).ln() } else { 0.0 };
    let s = ((1.0 + beta) * dq1 - beta * dq0 + gamma * c2.sqrt() * lg) / 2.0;
    if s.is_nan() {
        // back-tracking degenerate quadratic (the library's special branch)
        let tstar = abs_b / (2.0 * abs_a);
        return if 1.0 < tstar {
            abs_a * (0.0 - 1.0) - abs_b * (0.0 - 1.0)
        } else if tstar < 0.0 {
            abs_a - abs_b
        } else {
            abs_a * 1.0 - abs_b + abs_b * abs_b / (2.0 * abs_a)
        };
    }
    s
}

/// Cubic length by composite Gauss–Legendre quadrature (the reference uses
/// QUADPACK to 1e-12; only log2 of the value matters here).
fn cubic_length(p: &[P; 4]) -> f64 {
    const X: [f64; 5] = [0.0, -0.5384693101056831, 0.5384693101056831, -0.906179845938664, 0.906179845938664];
    const W: [f64; 5] = [0.5688888888888889, 0.47862867049936647, 0.47862867049936647, 0.23692688505639228, 0.23692688505639228];
    let d = |t: f64| {
        let mt = 1.0 - t;
        let dx = 3.0 * (mt * mt * (p[1][0] - p[0][0]) + 2.0 * mt * t * (p[2][0] - p[1][0]) + t * t * (p[3][0] - p[2][0]));
        let dy = 3.0 * (mt * mt * (p[1][1] - p[0][1]) + 2.0 * mt * t * (p[2][1] - p[1][1]) + t * t * (p[3][1] - p[2][1]));
        dx.hypot(dy)
    };
    let m = 64;
    let h = 1.0 / m as f64;
    let mut s = 0.0;
    for k in 0..m {
        let c = (k as f64 + 0.5) * h;
        for q in 0..5 {
            s += W[q] * d(c + 0.5 * h * X[q]);
        }
    }
    s * 0.5 * h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn float_hash_matches_cpython_examples() {
        // values printed by CPython 3.11: hash(x)
        assert_eq!(py_float_hash(0.0), 0);
        assert_eq!(py_float_hash(1.0), 1);
        assert_eq!(py_float_hash(-1.0), -2);
        assert_eq!(py_float_hash(0.5), 1152921504606846976);
        assert_eq!(py_float_hash(1.5), 1152921504606846977);
    }

    #[test]
    fn line_line_crossing() {
        let a = Seg::Line([[0.0, 0.0], [2.0, 2.0]]);
        let b = Seg::Line([[0.0, 2.0], [2.0, 0.0]]);
        assert_eq!(try_intersect(&a, &b).unwrap(), vec![(0.5, 0.5)]);
    }

    #[test]
    fn shared_vertex_is_ignored() {
        let segs = [Seg::Line([[0.0, 0.0], [1.0, 0.0]]), Seg::Line([[1.0, 0.0], [0.0, 1.0]]), Seg::Line([[0.0, 1.0], [0.0, 0.0]])];
        assert!(!try_has_self_intersection(&segs).unwrap());
    }
}
