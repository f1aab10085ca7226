//! A bounding-volume hierarchy over triangles: closest point (with the side of a closed
//! surface it lies on) and segment crossings.
//!
//! Written by hand rather than taken from `parry3d`: the drape needs two queries on
//! triangle soups in `f64` (the crate works in `f32` unless another crate, `parry3d-f64`, is
//! added, with `nalgebra`/`simba` behind it), and the sign of a distance from the
//! angle-weighted pseudo-normal of the closest feature, which it does not give. The tree is
//! built by median splits of the centroids, so it depends only on the triangles' order.

use garmentcode::Vec3;

/// Triangles per leaf.
const LEAF: usize = 4;

#[derive(Clone, Copy, Debug)]
struct Node {
    lo: Vec3,
    hi: Vec3,
    /// Leaf: first index into `order`; inner: index of the left child (the right one follows it).
    start: u32,
    /// Leaf: number of triangles; inner: 0.
    count: u32,
}

/// The feature of a triangle that a closest point lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Feature {
    /// Corner `k`.
    Vertex(usize),
    /// Edge from corner `k` to corner `k + 1`.
    Edge(usize),
    /// The interior.
    Face,
}

/// The closest point of a triangle set to a query point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Closest {
    /// The point on the surface.
    pub point: Vec3,
    /// Squared distance to it.
    pub dist2: f64,
    /// The triangle it lies on.
    pub face: usize,
    /// Where on the triangle.
    pub feature: Feature,
}

/// A BVH over a fixed list of triangles (their corners may move: see [`Bvh::refit`]).
#[derive(Clone, Debug)]
pub(crate) struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
    /// Box of each triangle (lower, upper corner), as of the last refit.
    boxes: Vec<(Vec3, Vec3)>,
}

fn bounds(t: &[Vec3; 3]) -> (Vec3, Vec3) {
    (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]))
}

/// Squared distance from `p` to the box `[lo, hi]`.
fn box_dist2(p: Vec3, lo: Vec3, hi: Vec3) -> f64 {
    let d = (lo - p).max(p - hi).max(Vec3::ZERO);
    d.length_squared()
}

impl Bvh {
    /// The tree over `tris`.
    pub fn new(tris: &[[Vec3; 3]]) -> Bvh {
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * tris.len() / LEAF + 1),
            order: (0..tris.len() as u32).collect(),
            boxes: vec![(Vec3::ZERO, Vec3::ZERO); tris.len()],
        };
        if tris.is_empty() {
            return bvh;
        }
        let centroids: Vec<Vec3> = tris.iter().map(|t| (t[0] + t[1] + t[2]) / 3.0).collect();
        bvh.nodes.push(Node { lo: Vec3::ZERO, hi: Vec3::ZERO, start: 0, count: 0 });
        bvh.build(0, 0, tris.len(), &centroids);
        bvh.refit(tris);
        bvh
    }

    fn build(&mut self, node: usize, start: usize, end: usize, centroids: &[Vec3]) {
        if end - start <= LEAF {
            self.nodes[node].start = start as u32;
            self.nodes[node].count = (end - start) as u32;
            return;
        }
        let items = &mut self.order[start..end];
        let (lo, hi) = items.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &i| {
            let c = centroids[i as usize];
            (lo.min(c), hi.max(c))
        });
        let ext = hi - lo;
        let axis = if ext.x >= ext.y && ext.x >= ext.z {
            0
        } else if ext.y >= ext.z {
            1
        } else {
            2
        };
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |&a, &b| centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis]).then(a.cmp(&b)));
        let left = self.nodes.len();
        self.nodes[node].start = left as u32;
        self.nodes[node].count = 0;
        let empty = Node { lo: Vec3::ZERO, hi: Vec3::ZERO, start: 0, count: 0 };
        self.nodes.push(empty);
        self.nodes.push(empty);
        self.build(left, start, start + mid, centroids);
        self.build(left + 1, start + mid, end, centroids);
    }

    /// Recomputes the boxes for moved corners (same triangles, same order).
    pub fn refit(&mut self, tris: &[[Vec3; 3]]) {
        for (b, t) in self.boxes.iter_mut().zip(tris) {
            *b = bounds(t);
        }
        // Children always follow their parent, so a backward sweep sees them first.
        for n in (0..self.nodes.len()).rev() {
            let node = self.nodes[n];
            let (lo, hi) = if node.count > 0 {
                self.order[node.start as usize..(node.start + node.count) as usize]
                    .iter()
                    .map(|&i| self.boxes[i as usize])
                    .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), (a, b)| (lo.min(a), hi.max(b)))
            } else {
                let (l, r) = (self.nodes[node.start as usize], self.nodes[node.start as usize + 1]);
                (l.lo.min(r.lo), l.hi.max(r.hi))
            };
            self.nodes[n].lo = lo;
            self.nodes[n].hi = hi;
        }
    }

    /// The closest point of `tris` to `p` closer than `sqrt(max_dist2)`, if any.
    pub fn closest(&self, tris: &[[Vec3; 3]], p: Vec3, max_dist2: f64) -> Option<Closest> {
        let mut best: Option<Closest> = None;
        let mut bound = max_dist2;
        let mut stack = [0u32; 64];
        let mut top = 0;
        if self.nodes.is_empty() || box_dist2(p, self.nodes[0].lo, self.nodes[0].hi) > bound {
            return None;
        }
        stack[top] = 0;
        top += 1;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top] as usize];
            if box_dist2(p, node.lo, node.hi) > bound {
                continue;
            }
            if node.count > 0 {
                for &i in &self.order[node.start as usize..(node.start + node.count) as usize] {
                    let (w, feature) = closest_on_triangle(p, &tris[i as usize]);
                    let q = at(&tris[i as usize], w);
                    let d2 = (p - q).length_squared();
                    if d2 < bound || (d2 == bound && best.is_none()) {
                        bound = d2;
                        best = Some(Closest { point: q, dist2: d2, face: i as usize, feature });
                    }
                }
            } else {
                let (l, r) = (node.start, node.start + 1);
                let dl = box_dist2(p, self.nodes[l as usize].lo, self.nodes[l as usize].hi);
                let dr = box_dist2(p, self.nodes[r as usize].lo, self.nodes[r as usize].hi);
                // Nearer child last, so it is searched first.
                let (near, far) = if dl <= dr { (l, r) } else { (r, l) };
                if top + 2 > stack.len() {
                    // Deeper than any median-split tree of u32 triangles; never reached.
                    continue;
                }
                stack[top] = far;
                stack[top + 1] = near;
                top += 2;
            }
        }
        best
    }

    /// Whether the box of triangle `i` (as of the last refit) meets the box `[lo, hi]`.
    pub fn meets(&self, i: usize, lo: Vec3, hi: Vec3) -> bool {
        let (b_lo, b_hi) = self.boxes[i];
        !(b_hi.cmplt(lo).any() || b_lo.cmpgt(hi).any())
    }

    /// The box of triangle `i` (lower, upper corner) as of the last refit.
    pub fn face_box(&self, i: usize) -> (Vec3, Vec3) {
        self.boxes[i]
    }

    /// Each triangle's place in the tree's order (the order of [`Bvh::for_each_in_box`]).
    pub fn ranks(&self) -> Vec<u32> {
        let mut rank = vec![0; self.order.len()];
        for (k, &i) in self.order.iter().enumerate() {
            rank[i as usize] = k as u32;
        }
        rank
    }

    /// Calls `hit(face)` for every triangle whose box (as of the last refit) meets the box
    /// `[lo, hi]`, in the tree's order (leaves left to right: increasing [`Bvh::ranks`]).
    pub fn for_each_in_box(&self, lo: Vec3, hi: Vec3, mut hit: impl FnMut(usize)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let n = stack[top];
            let node = self.nodes[n as usize];
            if node.hi.cmplt(lo).any() || node.lo.cmpgt(hi).any() {
                continue;
            }
            if node.count > 0 {
                for &i in &self.order[node.start as usize..(node.start + node.count) as usize] {
                    if self.meets(i as usize, lo, hi) {
                        hit(i as usize);
                    }
                }
            } else if top + 2 <= stack.len() {
                stack[top] = node.start + 1;
                stack[top + 1] = node.start;
                top += 2;
            }
        }
    }
}

/// The closest point of triangle `t` to `p` as barycentric weights of its corners, and the
/// feature it lies on (Ericson, *Real-Time Collision Detection*, 5.1.5).
pub(crate) fn closest_on_triangle(p: Vec3, t: &[Vec3; 3]) -> ([f64; 3], Feature) {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return ([1.0, 0.0, 0.0], Feature::Vertex(0));
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return ([0.0, 1.0, 0.0], Feature::Vertex(1));
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return ([1.0 - v, v, 0.0], Feature::Edge(0));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return ([0.0, 0.0, 1.0], Feature::Vertex(2));
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return ([1.0 - w, 0.0, w], Feature::Edge(2));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return ([0.0, 1.0 - w, w], Feature::Edge(1));
    }
    let denom = va + vb + vc;
    if denom.abs() < 1e-300 {
        // A degenerate triangle: its first corner.
        return ([1.0, 0.0, 0.0], Feature::Vertex(0));
    }
    let (v, w) = (vb / denom, vc / denom);
    ([1.0 - v - w, v, w], Feature::Face)
}

/// The point of triangle `t` with barycentric weights `w`.
pub(crate) fn at(t: &[Vec3; 3], w: [f64; 3]) -> Vec3 {
    t[0] * w[0] + t[1] * w[1] + t[2] * w[2]
}

/// Where segment `[o, o + d]` crosses the interior of triangle `t`, as a parameter in
/// `(0, 1)` along it (Möller–Trumbore, strict), if it does.
pub(crate) fn segment_crosses(o: Vec3, d: Vec3, t: &[Vec3; 3]) -> Option<f64> {
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det.abs() <= 1e-12 {
        return None;
    }
    let inv = 1.0 / det;
    let s = o - t[0];
    let u = s.dot(p) * inv;
    let q = s.cross(e1);
    let v = d.dot(q) * inv;
    let tt = e2.dot(q) * inv;
    let eps = 1e-9;
    (u > eps && v > eps && u + v < 1.0 - eps && tt > eps && tt < 1.0 - eps).then_some(tt)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> Vec<[Vec3; 3]> {
        let mut tris = Vec::new();
        for i in 0..10 {
            for j in 0..10 {
                let (x, z) = (i as f64, j as f64);
                let p = |dx: f64, dz: f64| Vec3::new(x + dx, (x + dx) * 0.1, z + dz);
                tris.push([p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)]);
                tris.push([p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]);
            }
        }
        tris
    }

    #[test]
    fn closest_matches_brute_force() {
        let tris = grid();
        let bvh = Bvh::new(&tris);
        for k in 0..200 {
            let f = k as f64;
            let p = Vec3::new((f * 0.37) % 12.0 - 1.0, (f * 0.53) % 3.0 - 1.0, (f * 0.71) % 12.0 - 1.0);
            let brute = tris.iter().map(|t| (p - at(t, closest_on_triangle(p, t).0)).length_squared()).fold(f64::INFINITY, f64::min);
            let hit = bvh.closest(&tris, p, f64::INFINITY).unwrap();
            assert!((hit.dist2 - brute).abs() < 1e-12, "{p}: {} vs {brute}", hit.dist2);
        }
        assert!(bvh.closest(&tris, Vec3::new(5.0, 100.0, 5.0), 1.0).is_none());
        // An empty tree finds nothing.
        let empty = Bvh::new(&[]);
        assert!(empty.closest(&[], Vec3::ZERO, f64::INFINITY).is_none());
        empty.for_each_in_box(Vec3::splat(-1.0), Vec3::ONE, |_| panic!("no triangle"));
    }

    #[test]
    fn box_queries_report_exactly_the_triangles_whose_boxes_meet() {
        let tris = grid();
        let bvh = Bvh::new(&tris);
        let ranks = bvh.ranks();
        for k in 0..100 {
            let f = k as f64;
            let c = Vec3::new((f * 0.37) % 12.0 - 1.0, (f * 0.53) % 3.0 - 1.0, (f * 0.71) % 12.0 - 1.0);
            let (lo, hi) = (c - Vec3::splat(0.3 + f * 0.01), c + Vec3::splat(0.3 + f * 0.01));
            let mut found = Vec::new();
            bvh.for_each_in_box(lo, hi, |i| found.push(i));
            assert!(found.windows(2).all(|w| ranks[w[0]] < ranks[w[1]]), "in the tree's order");
            found.sort_unstable();
            let brute: Vec<usize> = (0..tris.len())
                .filter(|&i| {
                    let (a, b) = bounds(&tris[i]);
                    !(b.cmplt(lo).any() || a.cmpgt(hi).any())
                })
                .collect();
            assert_eq!(found, brute, "box around {c}");
        }
    }

    #[test]
    fn segments_cross_only_through_the_interior() {
        let t = [Vec3::ZERO, Vec3::X, Vec3::Z];
        assert_eq!(segment_crosses(Vec3::new(0.2, -1.0, 0.2), Vec3::new(0.0, 2.0, 0.0), &t), Some(0.5));
        assert_eq!(segment_crosses(Vec3::new(0.2, 0.5, 0.2), Vec3::new(0.0, 2.0, 0.0), &t), None);
        assert_eq!(segment_crosses(Vec3::new(0.8, -1.0, 0.8), Vec3::new(0.0, 2.0, 0.0), &t), None);
    }
}
