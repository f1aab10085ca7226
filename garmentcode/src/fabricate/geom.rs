//! Plane geometry for pattern pieces: rigid transforms, closed polylines, the
//! seam-allowance offset and the distances the tests measure.

use crate::math::Vec2;

/// A rigid (or mirrored) map of the plane: `p ↦ m·p + t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Xf {
    /// Columns of the linear part: images of the x and y unit vectors.
    pub cols: [Vec2; 2],
    /// Translation.
    pub t: Vec2,
}

impl Xf {
    /// The identity.
    pub const IDENTITY: Xf = Xf { cols: [Vec2::X, Vec2::Y], t: Vec2::ZERO };

    /// Rotation that turns the unit vector `dir` onto +y.
    pub fn rotate_onto_y(dir: Vec2) -> Xf {
        // Rotating by angle a maps dir to +y: a = 90° − angle(dir).
        let a = std::f64::consts::FRAC_PI_2 - dir.y.atan2(dir.x);
        let (s, c) = a.sin_cos();
        Xf { cols: [Vec2::new(c, s), Vec2::new(-s, c)], t: Vec2::ZERO }
    }

    /// Image of a point.
    pub fn apply(&self, p: Vec2) -> Vec2 {
        self.cols[0] * p.x + self.cols[1] * p.y + self.t
    }

    /// Image of a direction (no translation).
    pub fn apply_vec(&self, v: Vec2) -> Vec2 {
        self.cols[0] * v.x + self.cols[1] * v.y
    }

    /// `self` after `first`: `p ↦ self(first(p))`.
    pub fn after(&self, first: &Xf) -> Xf {
        Xf { cols: [self.apply_vec(first.cols[0]), self.apply_vec(first.cols[1])], t: self.apply(first.t) }
    }

    /// Translation by `t`.
    pub fn translate(t: Vec2) -> Xf {
        Xf { t, ..Xf::IDENTITY }
    }

    /// Mirror `x ↦ w − x`.
    pub fn mirror_x(w: f64) -> Xf {
        Xf { cols: [Vec2::new(-1.0, 0.0), Vec2::Y], t: Vec2::new(w, 0.0) }
    }

    /// Whether the map reverses orientation.
    pub fn is_mirror(&self) -> bool {
        self.cols[0].perp_dot(self.cols[1]) < 0.0
    }
}

/// Axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Lower corner.
    pub min: Vec2,
    /// Upper corner.
    pub max: Vec2,
}

impl Rect {
    /// Bounding box of points (a zero box at the origin when there are none).
    pub fn of(points: impl IntoIterator<Item = Vec2>) -> Rect {
        let mut it = points.into_iter();
        let Some(first) = it.next() else { return Rect { min: Vec2::ZERO, max: Vec2::ZERO } };
        it.fold(Rect { min: first, max: first }, |r, p| Rect { min: r.min.min(p), max: r.max.max(p) })
    }

    /// Width and height.
    pub fn size(&self) -> Vec2 {
        self.max - self.min
    }

    /// Smallest box holding both.
    pub fn union(&self, o: &Rect) -> Rect {
        Rect { min: self.min.min(o.min), max: self.max.max(o.max) }
    }

    /// The boxes share interior area.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.min.x < o.max.x && o.min.x < self.max.x && self.min.y < o.max.y && o.min.y < self.max.y
    }
}

/// Signed area of a closed polygon (positive counter-clockwise).
pub fn signed_area(poly: &[Vec2]) -> f64 {
    let n = poly.len();
    (0..n).map(|i| poly[i].perp_dot(poly[(i + 1) % n])).sum::<f64>() / 2.0
}

/// Distance from `p` to the segment `a`–`b`.
pub fn point_segment_distance(p: Vec2, a: Vec2, b: Vec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 { ((p - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (a + ab * t - p).length()
}

/// Distance from `p` to a closed polyline.
pub fn distance_to_closed(p: Vec2, poly: &[Vec2]) -> f64 {
    let n = poly.len();
    (0..n).map(|i| point_segment_distance(p, poly[i], poly[(i + 1) % n])).fold(f64::INFINITY, f64::min)
}

/// The point of a closed polyline nearest to `p`.
pub fn nearest_on_closed(p: Vec2, poly: &[Vec2]) -> Vec2 {
    let n = poly.len();
    let mut best = (f64::INFINITY, p);
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let ab = b - a;
        let len2 = ab.length_squared();
        let t = if len2 > 0.0 { ((p - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
        let q = a + ab * t;
        let d = (q - p).length();
        if d < best.0 {
            best = (d, q);
        }
    }
    best.1
}

/// Even-odd point-in-polygon test.
pub fn inside(p: Vec2, poly: &[Vec2]) -> bool {
    let n = poly.len();
    let mut c = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            c = !c;
        }
    }
    c
}

/// Proper intersection of segments `a0`–`a1` and `b0`–`b1`: the parameters on both.
fn segment_intersection(a0: Vec2, a1: Vec2, b0: Vec2, b1: Vec2) -> Option<(f64, f64)> {
    let (r, s) = (a1 - a0, b1 - b0);
    let den = r.perp_dot(s);
    if den.abs() < 1e-15 {
        return None;
    }
    let q = b0 - a0;
    let (t, u) = (q.perp_dot(s) / den, q.perp_dot(r) / den);
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some((t, u))
}

/// Intersection of the lines through `a` along `da` and through `b` along `db`:
/// the parameters along both.
fn line_intersection(a: Vec2, da: Vec2, b: Vec2, db: Vec2) -> Option<(f64, f64)> {
    let den = da.perp_dot(db);
    if den.abs() < 1e-12 {
        return None;
    }
    let q = b - a;
    Some((q.perp_dot(db) / den, q.perp_dot(da) / den))
}

/// One offset edge: its points at the allowance from the sew line, and the sew
/// line's tangent at both ends (for the corner joins).
pub struct OffsetEdge {
    /// Offset points along the edge, in edge order.
    pub points: Vec<Vec2>,
    /// Unit tangent at the start.
    pub t0: Vec2,
    /// Unit tangent at the end.
    pub t1: Vec2,
    /// The allowance of this edge.
    pub d: f64,
}

/// The closed cut line around offset edges given in loop order (the sew line
/// counter-clockwise), with outer corners mitred: the two offset lines extended
/// until they meet, or, when one offset already crosses the other's extension (an
/// edge meeting a fold at a sharp angle), the first trimmed back to that crossing;
/// squared off when the mitre would run further than three allowances from the sew
/// corner. At inner corners and tight inward curves the offsets cross; the loops
/// this leaves are cut away.
pub fn join_offsets(edges: &[OffsetEdge], corners: &[Vec2]) -> Vec<Vec2> {
    let n = edges.len();
    let mut pts: Vec<Vec<Vec2>> = edges.iter().map(|e| e.points.clone()).collect();
    let mut joins: Vec<Vec<Vec2>> = vec![Vec::new(); n];
    let outward = |t: Vec2| Vec2::new(t.y, -t.x);
    for i in 0..n {
        let j = (i + 1) % n;
        let (a, b) = (&edges[i], &edges[j]);
        let (pa, pb) = (*a.points.last().expect("offset points"), b.points[0]);
        // Only a left turn of the counter-clockwise sew line (an outer corner)
        // leaves a gap between the offsets.
        if (pb - pa).length() < 1e-9 || a.t1.perp_dot(b.t0) <= 1e-9 {
            continue;
        }
        let corner = corners[j];
        let reach = a.d.max(b.d);
        let near = |x: Vec2| (x - corner).length() <= 3.0 * reach;
        match line_intersection(pa, a.t1, pb, b.t0) {
            Some((s, u)) if s >= 0.0 && u <= 0.0 && near(pa + a.t1 * s) => joins[i].push(pa + a.t1 * s),
            Some((s, u)) if s >= 0.0 && u > 0.0 && near(pa + a.t1 * s) => {
                // b's offset starts beyond a's extended line: drop its points out there.
                let (x, na) = (pa + a.t1 * s, outward(a.t1));
                let keep = pts[j].iter().position(|q| (*q - x).dot(na) <= 0.0).unwrap_or(pts[j].len() - 1);
                pts[j].drain(..keep);
                joins[i].push(x);
            }
            Some((s, u)) if s < 0.0 && u <= 0.0 && near(pb + b.t0 * u) => {
                // The mirror case: a's offset ends beyond b's extended line.
                let (x, nb) = (pb + b.t0 * u, outward(b.t0));
                let last = pts[i].iter().rposition(|q| (*q - x).dot(nb) <= 0.0).unwrap_or(0);
                pts[i].truncate(last + 1);
                joins[i].push(x);
            }
            _ => {
                joins[i].push(pa + a.t1 * reach);
                joins[i].push(pb - b.t0 * reach);
            }
        }
    }
    let mut out = Vec::new();
    for i in 0..n {
        out.extend_from_slice(&pts[i]);
        out.extend_from_slice(&joins[i]);
    }
    remove_loops(out)
}

/// Cut away the small loops of a closed polyline that crosses itself: at each
/// crossing the shorter of the two closed parts (by number of points) is replaced
/// by the crossing point.
pub fn remove_loops(mut p: Vec<Vec2>) -> Vec<Vec2> {
    let mut i = 0;
    while i < p.len() {
        let n = p.len();
        if n < 4 {
            break;
        }
        let (a0, a1) = (p[i], p[(i + 1) % n]);
        let mut fixed = false;
        for j in (i + 2)..n {
            if (j + 1) % n == i {
                continue;
            }
            let (b0, b1) = (p[j], p[(j + 1) % n]);
            if let Some((t, _)) = segment_intersection(a0, a1, b0, b1) {
                let x = a0 + (a1 - a0) * t;
                // Points i+1..=j form one side, the rest the other.
                let inner = j - i;
                if inner <= n - inner {
                    p.splice(i + 1..=j, [x]);
                } else {
                    let mut kept = vec![x];
                    kept.extend_from_slice(&p[i + 1..=j]);
                    p = kept;
                    i = 0;
                }
                fixed = true;
                break;
            }
        }
        if !fixed {
            i += 1;
        }
    }
    dedup_closed(p)
}

/// Drop consecutive duplicate points (closing point included).
pub fn dedup_closed(mut p: Vec<Vec2>) -> Vec<Vec2> {
    p.dedup_by(|a, b| (*a - *b).length() < 1e-9);
    while p.len() > 1 && (p[0] - p[p.len() - 1]).length() < 1e-9 {
        p.pop();
    }
    p
}
