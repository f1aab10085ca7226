//! Edge curves as the box mesh reads them, their lengths and their samples.
//!
//! A relative control point `(u, v)` of an edge from `s` to `e` is the point
//! `s + u·d + v·d⊥` with `d = e − s` and `d⊥ = (−d.y, d.x)`: the y axis is not flipped
//! (the pattern drawer flips it, the mesher does not). Circular arcs follow the SVG
//! endpoint-to-centre conversion with the sweep flag equal to the edge's `right`.

use crate::Vec2;
use crate::{Curvature, PanelSpec};

/// One edge's curve in the panel's 2D frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MeshCurve {
    /// Straight segment.
    Line([Vec2; 2]),
    /// Quadratic Bézier.
    Quadratic([Vec2; 3]),
    /// Cubic Bézier.
    Cubic([Vec2; 4]),
    /// Circular arc: `centre + r·(cos(θ + tΔ), sin(θ + tΔ))`, angles in radians.
    Arc {
        /// Start and end points (exact).
        ends: [Vec2; 2],
        /// Centre.
        centre: Vec2,
        /// Radius (scaled up to half the chord if smaller).
        radius: f64,
        /// Angle of the start point.
        theta: f64,
        /// Signed angle swept.
        delta: f64,
    },
}

impl MeshCurve {
    /// The curve of edge `i` of a panel (endpoint indices must be valid).
    pub fn of_edge(panel: &PanelSpec, i: usize) -> MeshCurve {
        let e = &panel.edges[i];
        let s = panel.vertex(e.endpoints[0]);
        let t = panel.vertex(e.endpoints[1]);
        let d = t - s;
        let rel = |c: [f64; 2]| s + c[0] * d + c[1] * Vec2::new(-d.y, d.x);
        match &e.curvature {
            None => MeshCurve::Line([s, t]),
            Some(Curvature::Quadratic(c)) => MeshCurve::Quadratic([s, rel(*c), t]),
            Some(Curvature::Cubic(c1, c2)) => MeshCurve::Cubic([s, rel(*c1), rel(*c2), t]),
            Some(Curvature::Circle { radius, large_arc, right }) => arc(s, t, radius.abs(), *large_arc, *right),
        }
    }

    /// Start point.
    pub fn start(&self) -> Vec2 {
        match self {
            MeshCurve::Line(p) => p[0],
            MeshCurve::Quadratic(p) => p[0],
            MeshCurve::Cubic(p) => p[0],
            MeshCurve::Arc { ends, .. } => ends[0],
        }
    }

    /// End point.
    pub fn end(&self) -> Vec2 {
        match self {
            MeshCurve::Line(p) => p[1],
            MeshCurve::Quadratic(p) => p[2],
            MeshCurve::Cubic(p) => p[3],
            MeshCurve::Arc { ends, .. } => ends[1],
        }
    }

    /// Point at parameter `t ∈ [0, 1]`.
    pub fn point(&self, t: f64) -> Vec2 {
        let u = 1.0 - t;
        match self {
            MeshCurve::Line([a, b]) => *a + t * (*b - *a),
            MeshCurve::Quadratic([a, b, c]) => u * u * *a + 2.0 * u * t * *b + t * t * *c,
            MeshCurve::Cubic([a, b, c, d]) => u * u * u * *a + 3.0 * u * u * t * *b + 3.0 * u * t * t * *c + t * t * t * *d,
            MeshCurve::Arc { centre, radius, theta, delta, .. } => {
                let a = theta + t * delta;
                *centre + *radius * Vec2::new(a.cos(), a.sin())
            }
        }
    }

    /// Speed `|B'(t)|` of a Bézier (unused for lines and arcs).
    fn speed(&self, t: f64) -> f64 {
        let u = 1.0 - t;
        match self {
            MeshCurve::Quadratic([a, b, c]) => (2.0 * u * (*b - *a) + 2.0 * t * (*c - *b)).length(),
            MeshCurve::Cubic([a, b, c, d]) => (3.0 * u * u * (*b - *a) + 6.0 * u * t * (*c - *b) + 3.0 * t * t * (*d - *c)).length(),
            MeshCurve::Line([a, b]) => (*b - *a).length(),
            MeshCurve::Arc { radius, delta, .. } => radius * delta.abs(),
        }
    }

    /// Arc length of the whole curve (Béziers: adaptive Gauss–Legendre to about 1e-13 cm,
    /// or 1e-14 of the length beyond 10 cm).
    pub fn length(&self) -> f64 {
        match self {
            MeshCurve::Line([a, b]) => (*b - *a).length(),
            MeshCurve::Arc { radius, delta, .. } => radius * delta.abs(),
            _ => self.length_between(0.0, 1.0),
        }
    }

    /// The length the reference's vertex count `⌈length / res⌉ + 1` rounds up: a line's by
    /// `hypot` (Python's `abs` of a complex number), a quadratic's by svgpathtools' closed
    /// form, which loses up to a few 1e-9 cm on nearly straight curves (an edge of a
    /// whole number of cm that bends by a micrometre gets the count of the straight
    /// edge). Cubics and arcs are integrated by the reference as exactly as here.
    pub fn reference_length(&self) -> f64 {
        let p = |v: Vec2| [v.x, v.y];
        let len = match self {
            MeshCurve::Line([a, b]) => (b.x - a.x).hypot(b.y - a.y),
            MeshCurve::Quadratic(q) => crate::parity::svgpath::quad_length(&q.map(p)),
            _ => self.length(),
        };
        if len.is_finite() { len } else { self.length() }
    }

    fn length_between(&self, a: f64, b: f64) -> f64 {
        let whole = gauss(|t| self.speed(t), a, b);
        let mut budget = MAX_SUBDIVISIONS;
        adaptive(&|t| self.speed(t), a, b, whole, 1e-13f64.max(LENGTH_TOLERANCE * whole.abs()), &mut budget)
    }

    /// `n ≥ 2` points at uniform arc length (lines and arcs: uniform parameter, the
    /// same thing); the first and last are the exact end points.
    pub fn samples(&self, n: usize) -> Vec<Vec2> {
        let n = n.max(2);
        let mut out = Vec::with_capacity(n);
        out.push(self.start());
        match self {
            MeshCurve::Line(_) | MeshCurve::Arc { .. } => {
                for k in 1..n - 1 {
                    out.push(self.point(k as f64 / (n - 1) as f64));
                }
            }
            _ => {
                // Cumulative lengths at fixed breakpoints, then Newton (bisection-guarded)
                // inside the bracketing piece.
                const PIECES: usize = 32;
                let mut cum = [0.0; PIECES + 1];
                for i in 0..PIECES {
                    cum[i + 1] = cum[i] + self.length_between(i as f64 / PIECES as f64, (i + 1) as f64 / PIECES as f64);
                }
                let total = cum[PIECES];
                for k in 1..n - 1 {
                    let target = total * k as f64 / (n - 1) as f64;
                    let i = cum.partition_point(|&c| c <= target).clamp(1, PIECES) - 1;
                    let (mut lo, mut hi) = (i as f64 / PIECES as f64, (i + 1) as f64 / PIECES as f64);
                    let base = (cum[i], lo);
                    let mut t = lo + (hi - lo) * ((target - cum[i]) / (cum[i + 1] - cum[i]).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
                    for _ in 0..60 {
                        let f = base.0 + self.length_between(base.1, t) - target;
                        if f.abs() <= 1e-12f64.max(LENGTH_TOLERANCE * total) {
                            break;
                        }
                        if f > 0.0 {
                            hi = t;
                        } else {
                            lo = t;
                        }
                        let sp = self.speed(t);
                        let newton = t - f / sp;
                        t = if sp > 0.0 && newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
                    }
                    out.push(self.point(t));
                }
            }
        }
        out.push(self.end());
        out
    }
}

/// The SVG endpoint → centre parametrisation (rotation 0, `rx = ry = r`) of svgpathtools.
fn arc(s: Vec2, e: Vec2, r: f64, large_arc: bool, sweep: bool) -> MeshCurve {
    let h = (s - e) / 2.0;
    let mut r = r;
    let check = h.length_squared() / (r * r);
    if check > 1.0 {
        r *= check.sqrt();
    }
    let tmp = r * r * h.length_squared();
    let radicand = (r.powi(4) - tmp) / tmp;
    let radical = if radicand.abs() <= 1e-8 { 0.0 } else { radicand.max(0.0).sqrt() };
    let k = if large_arc == sweep { -radical } else { radical };
    let cp = k * Vec2::new(h.y, -h.x);
    let centre = cp + (s + e) / 2.0;
    let clip = |v: f64| v.clamp(-1.0, 1.0);
    let u1 = Vec2::new(clip((h.x - cp.x) / r), clip((h.y - cp.y) / r));
    let u2 = Vec2::new(clip((-h.x - cp.x) / r), clip((-h.y - cp.y) / r));
    let theta = if u1.y > 0.0 {
        u1.x.acos()
    } else if u1.y < 0.0 {
        -u1.x.acos()
    } else if u1.x > 0.0 {
        0.0
    } else {
        std::f64::consts::PI
    };
    let det = u1.perp_dot(u2);
    let dot = clip(u1.dot(u2));
    let mut delta = if det > 0.0 {
        dot.acos()
    } else if det < 0.0 {
        -dot.acos()
    } else if dot > 0.0 {
        0.0
    } else {
        std::f64::consts::PI
    };
    let full = 2.0 * std::f64::consts::PI;
    if !sweep && delta >= 0.0 {
        delta -= full;
    } else if large_arc && delta <= 0.0 {
        delta += full;
    }
    MeshCurve::Arc { ends: [s, e], centre, radius: r, theta, delta }
}

/// 10-point Gauss–Legendre quadrature of `f` over `[a, b]`.
fn gauss(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const X: [f64; 5] =
        [0.148_874_338_981_631_2, 0.433_395_394_129_247_2, 0.679_409_568_299_024_4, 0.865_063_366_688_984_5, 0.973_906_528_517_171_7];
    const W: [f64; 5] =
        [0.295_524_224_714_752_9, 0.269_266_719_309_996_4, 0.219_086_362_515_982_04, 0.149_451_349_150_580_6, 0.066_671_344_308_688_14];
    let (m, h) = ((a + b) / 2.0, (b - a) / 2.0);
    h * X.iter().zip(W).map(|(x, w)| w * (f(m - h * x) + f(m + h * x))).sum::<f64>()
}

/// Relative accuracy of Bézier lengths beyond 10 cm, 1e-13 cm below (an absolute
/// accuracy is out of reach of f64 on long curves: a 90 m edge has a unit in the last
/// place of 1.8e-12 cm, and the sums of a quadrature lose a few).
const LENGTH_TOLERANCE: f64 = 1e-14;

/// Most bisections of one length integral: sharp turns (a control point hundreds of edge
/// lengths away) need a few dozen; past the budget the halves are taken as they are,
/// so that any curve is measured in bounded time.
const MAX_SUBDIVISIONS: u32 = 2000;

/// Adaptive bisection of [`gauss`] until two halves agree with the whole (to `tol`,
/// halved on each level), at most `budget` bisections in all.
fn adaptive(f: &dyn Fn(f64) -> f64, a: f64, b: f64, whole: f64, tol: f64, budget: &mut u32) -> f64 {
    let m = (a + b) / 2.0;
    let (l, r) = (gauss(f, a, m), gauss(f, m, b));
    if *budget == 0 || (l + r - whole).abs() <= tol || !(m > a && m < b) {
        return l + r;
    }
    *budget -= 1;
    adaptive(f, a, m, l, tol / 2.0, budget) + adaptive(f, m, b, r, tol / 2.0, budget)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_length_matches_closed_form() {
        let c = MeshCurve::Quadratic([Vec2::ZERO, Vec2::new(5.0, 8.0), Vec2::new(10.0, 0.0)]);
        // closed form of a parabola arc y = 16/10 x (1 - x/10)... compare with dense polyline
        let dense: f64 = (0..200_000).map(|i| (c.point((i + 1) as f64 / 2e5) - c.point(i as f64 / 2e5)).length()).sum();
        assert!((c.length() - dense).abs() < 1e-6);
    }

    #[test]
    fn samples_are_uniform_in_arc_length() {
        let c = MeshCurve::Cubic([Vec2::ZERO, Vec2::new(1.0, 9.0), Vec2::new(12.0, -3.0), Vec2::new(10.0, 0.0)]);
        let s = c.samples(9);
        assert_eq!(s[0], c.start());
        assert_eq!(s[8], c.end());
        // Each piece's arc length is a ninth... an eighth of the total: check by bisecting the parameter.
        let total = c.length();
        let mut prev = 0.0;
        for p in &s[1..8] {
            // Find t of p by dense search, then its arc length.
            let t = (0..=10_000)
                .map(|i| i as f64 / 1e4)
                .min_by(|a, b| (c.point(*a) - *p).length().total_cmp(&(c.point(*b) - *p).length()))
                .unwrap();
            let l = c.length_between(0.0, t);
            assert!((l - prev - total / 8.0).abs() < 1e-2, "{l} {prev}");
            prev = l;
        }
    }

    #[test]
    fn a_control_point_900_edge_lengths_away_is_measured_in_bounded_time() {
        // The reference's closed form, against the adaptive quadrature (which went on
        // forever here: 1e-13 cm is below the precision of a 70 m length).
        let (s, e) = (Vec2::new(39.1358, 0.0), Vec2::ZERO);
        let d = e - s;
        let c = MeshCurve::Quadratic([s, s + 0.5 * d + 900.0 * Vec2::new(-d.y, d.x), e]);
        let started = std::time::Instant::now();
        let (exact, closed) = (c.length(), c.reference_length());
        assert!((exact - closed).abs() < 1e-9 * closed, "{exact} vs {closed}");
        let samples = c.samples(1000);
        assert!(started.elapsed().as_secs() < 5, "{:?}", started.elapsed());
        // Chords of equal arcs: none longer than the arc, most as long (not at the hairpin turn).
        let arc = exact / 999.0;
        let chords: Vec<f64> = samples.windows(2).map(|w| (w[1] - w[0]).length()).collect();
        assert!(chords.iter().all(|&c| c <= arc * (1.0 + 1e-9)), "a chord longer than its arc");
        assert!(chords.iter().filter(|&&c| c > arc * 0.999).count() > 990, "uneven samples");
    }

    #[test]
    fn vertex_counts_round_the_reference_lengths_up() {
        // A 46 cm line whose square root of squares is 46.00000000000001 (hypot: 46).
        let line = MeshCurve::Line([Vec2::ZERO, Vec2::new(45.548304191955516, 6.430550927960048)]);
        assert_eq!(line.reference_length(), 46.0);
        assert!(line.length() > 46.0);
        // A 40 cm edge bent by 0.2 µm: 40.00000000003 cm long, 39.9999999997 by the closed form.
        let bent = MeshCurve::Quadratic([Vec2::ZERO, Vec2::new(20.0, 4e-5), Vec2::new(40.0, 0.0)]);
        assert!(bent.length() > 40.0 && bent.reference_length() < 40.0, "{} {}", bent.length(), bent.reference_length());
    }

    #[test]
    fn half_circle_arc() {
        let c = arc(Vec2::new(0.0, 0.0), Vec2::new(10.0, 0.0), 5.0, false, true);
        assert!((c.length() - 5.0 * std::f64::consts::PI).abs() < 1e-9);
        let mid = c.point(0.5);
        assert!((mid - Vec2::new(5.0, -5.0)).length() < 1e-9 || (mid - Vec2::new(5.0, 5.0)).length() < 1e-9);
    }
}
