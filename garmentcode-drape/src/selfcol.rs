//! Self-collision of the garment, as the reference's Warp fork does it: point–triangle and
//! edge–edge contacts found once per frame (on the frame-start positions, with a one-frame
//! look-ahead), then projected in every substep. Edges that already cross the garment
//! exempt their ends from new contacts, so existing crossings are not locked in.

use garmentcode::Vec3;

use crate::bvh::{Bvh, at, closest_on_triangle, segment_crosses};

/// One point–triangle contact: the particle, the triangle, and whether the particle was on
/// the back side of the triangle (the solver keeps it there).
pub(crate) struct PointTriangle {
    particle: usize,
    face: usize,
    back: bool,
}

/// One edge–edge contact: edge `a–b` (the one that moves), edge `e0–e1`, and the direction
/// from the first to the second at detection.
pub(crate) struct EdgeEdge {
    ends: [usize; 4],
    dir: Vec3,
}

/// The garment's collision mesh and this frame's contacts.
pub(crate) struct SelfCollision {
    faces: Vec<[usize; 3]>,
    /// Per face, whether it is the first face of each of its edges `k → k+1` (each edge is
    /// tested once, from that face).
    owns: Vec<[bool; 3]>,
    tris: Vec<[Vec3; 3]>,
    bvh: Bvh,
    intersecting: Vec<bool>,
    /// Edges crossing the garment now: `(k, l, face first crossed from k)`.
    pub crossings: Vec<(usize, usize, usize)>,
    point_triangle: Vec<PointTriangle>,
    edge_edge: Vec<EdgeEdge>,
    /// This frame's look-ahead of every particle, and its length.
    ahead: Vec<Vec3>,
    reach: Vec<f64>,
}

/// Closest points of segments `p1–q1` and `p2–q2` as parameters `(s, t)` along them, and
/// their distance (Ericson, *Real-Time Collision Detection*, 5.1.9).
fn closest_edge_edge(p1: Vec3, q1: Vec3, p2: Vec3, q2: Vec3, eps: f64) -> (f64, f64, f64) {
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.length_squared(), d2.length_squared(), d2.dot(r));
    let (s, t);
    if a <= eps && e <= eps {
        (s, t) = (0.0, 0.0);
    } else if a <= eps {
        (s, t) = (0.0, (f / e).clamp(0.0, 1.0));
    } else {
        let c = d1.dot(r);
        if e <= eps {
            (s, t) = ((-c / a).clamp(0.0, 1.0), 0.0);
        } else {
            let b = d1.dot(d2);
            let denom = a * e - b * b;
            let s0 = if denom != 0.0 { ((b * f - c * e) / denom).clamp(0.0, 1.0) } else { 0.0 };
            let t0 = (b * s0 + f) / e;
            if t0 < 0.0 {
                (s, t) = ((-c / a).clamp(0.0, 1.0), 0.0);
            } else if t0 > 1.0 {
                (s, t) = (((b - c) / a).clamp(0.0, 1.0), 1.0);
            } else {
                (s, t) = (s0, t0);
            }
        }
    }
    let dist = ((p1 + d1 * s) - (p2 + d2 * t)).length();
    (s, t, dist)
}

impl SelfCollision {
    /// The collision mesh of the garment's `faces` at positions `x`.
    pub fn new(faces: Vec<[usize; 3]>, x: &[Vec3]) -> SelfCollision {
        let tris: Vec<[Vec3; 3]> = faces.iter().map(|f| f.map(|i| x[i])).collect();
        let bvh = Bvh::new(&tris);
        let mut first: std::collections::HashMap<[usize; 2], usize> = std::collections::HashMap::new();
        let owns = faces
            .iter()
            .enumerate()
            .map(|(f, t)| {
                [0, 1, 2].map(|k| {
                    let (a, b) = (t[k], t[(k + 1) % 3]);
                    *first.entry([a.min(b), a.max(b)]).or_insert(f) == f
                })
            })
            .collect();
        SelfCollision {
            faces,
            owns,
            tris,
            bvh,
            intersecting: vec![false; x.len()],
            crossings: Vec::new(),
            point_triangle: Vec::new(),
            edge_edge: Vec::new(),
            ahead: Vec::new(),
            reach: Vec::new(),
        }
    }

    /// Finds the edges crossing the garment and, if `contacts`, this frame's contacts at
    /// positions `x`, velocities `v`: `edges` are the garment's springs, `gravity` and `dt`
    /// (one frame) the look-ahead, `r` the particle radius.
    pub fn detect(
        &mut self,
        x: &[Vec3],
        v: &[Vec3],
        inv_mass: &[f64],
        edges: &[([usize; 2], f64)],
        (gravity, dt, r): (Vec3, f64, f64),
        contacts: bool,
    ) {
        for (t, f) in self.tris.iter_mut().zip(&self.faces) {
            *t = f.map(|i| x[i]);
        }
        // One frame's look-ahead of every particle (the reference's prediction, gravity
        // times the inverse mass included) and its length.
        self.ahead.clear();
        self.ahead.extend((0..x.len()).map(|i| v[i] * dt + gravity * (inv_mass[i] * dt * dt)));
        self.reach.clear();
        self.reach.extend(self.ahead.iter().map(|a| a.length()));
        self.bvh.refit(&self.tris);
        // Ends of edges that cross the garment now.
        self.intersecting.fill(false);
        self.crossings.clear();
        for &([k, l], _) in edges {
            if let Some(face) = self.first_crossed(x, k, l) {
                self.intersecting[k] = true;
                self.intersecting[l] = true;
                self.crossings.push((k, l, face));
            }
        }
        self.point_triangle.clear();
        self.edge_edge.clear();
        if !contacts {
            return;
        }
        let (ahead, reach) = (&self.ahead, &self.reach);
        let margin = 2.0 * r + 0.5 * r;
        // Point–triangle: faces in a box of ±3r around each particle (the reference's
        // search) that the look-ahead brings within the margin.
        for (i, &p) in x.iter().enumerate() {
            if self.intersecting[i] {
                continue;
            }
            let h = Vec3::splat(3.0 * r);
            let (faces, tris, found) = (&self.faces, &self.tris, &mut self.point_triangle);
            self.bvh.for_each_in_box(p - h, p + h, |f| {
                let face = faces[f];
                if face.contains(&i) {
                    return;
                }
                let (w, _) = closest_on_triangle(p, &tris[f]);
                let pc = at(&tris[f], w);
                let dir = (pc - p).normalize_or_zero();
                let dc = ahead[face[0]] * w[0] + ahead[face[1]] * w[1] + ahead[face[2]] * w[2];
                let after = (pc - p).length() - ahead[i].dot(dir) + dc.dot(dir);
                if after < margin {
                    let n = (tris[f][1] - tris[f][0]).cross(tris[f][2] - tris[f][0]).normalize_or_zero();
                    found.push(PointTriangle { particle: i, face: f, back: n.dot(p - tris[f][0]) < 0.0 });
                }
            });
        }
        // Edge–edge: face edges of the faces in a cube of ±(|ab|/2 + 3r) around each
        // spring's midpoint (the reference's search) that the look-ahead brings within the
        // margin. Edges whose boxes are farther apart than the margin plus both look-aheads
        // cannot be, so when the spring's box grown by the margin and the largest
        // look-aheads fits in the cube, the tree is searched with that smaller box (and
        // faces outside the cube are skipped): the same contacts, fewer faces visited.
        let max_reach = reach.iter().fold(0.0f64, |m, &r| m.max(r));
        for &([a, b], _) in edges {
            if self.intersecting[a] || self.intersecting[b] {
                continue;
            }
            let (pa, pb) = (x[a], x[b]);
            let len = (pb - pa).length();
            let (lo, hi) = (pa.min(pb), pa.max(pb));
            let reach_ab = reach[a].max(reach[b]);
            let (mid, h) = ((pa + pb) / 2.0, Vec3::splat(len / 2.0 + 3.0 * r));
            let (cube_lo, cube_hi) = (mid - h, mid + h);
            let grow = Vec3::splat(margin + reach_ab + max_reach + 1e-9);
            let (near_lo, near_hi) = (lo - grow, hi + grow);
            let near = near_lo.cmpge(cube_lo).all() && near_hi.cmple(cube_hi).all();
            let (search_lo, search_hi) = if near { (near_lo, near_hi) } else { (cube_lo, cube_hi) };
            let (faces, owns, bvh, found) = (&self.faces, &self.owns, &self.bvh, &mut self.edge_edge);
            bvh.for_each_in_box(search_lo, search_hi, |f| {
                if near && !bvh.meets(f, cube_lo, cube_hi) {
                    return;
                }
                let face = faces[f];
                for k in 0..3 {
                    let (e0, e1) = (face[k], face[(k + 1) % 3]);
                    if !owns[f][k] || e0 == a || e0 == b || e1 == a || e1 == b {
                        continue;
                    }
                    let gap = (x[e0].min(x[e1]) - hi).max(lo - x[e0].max(x[e1])).max(Vec3::ZERO).length();
                    if gap - reach_ab - reach[e0].max(reach[e1]) > margin + 1e-9 {
                        continue;
                    }
                    let (ta, tb, dist) = closest_edge_edge(pa, pb, x[e0], x[e1], 1e-3);
                    // Near an end it is a point–triangle contact (the reference tests all four with |ab|).
                    if ta * len < r || (1.0 - ta) * len < r || tb * len < r || (1.0 - tb) * len < r || ta < 1e-5 {
                        continue;
                    }
                    let p_alpha = pa * (1.0 - ta) + pb * ta;
                    let p_beta = x[e0] * (1.0 - tb) + x[e1] * tb;
                    let dir = (p_beta - p_alpha).normalize_or_zero();
                    let d_alpha = (ahead[a] * (1.0 - ta) + ahead[b] * ta).dot(dir);
                    let d_beta = (ahead[e0] * (1.0 - tb) + ahead[e1] * tb).dot(dir);
                    if dist - d_alpha + d_beta < margin {
                        found.push(EdgeEdge { ends: [a, b, e0, e1], dir });
                    }
                }
            });
        }
    }

    /// The first garment triangle without either end that edge `k–l` crosses, from `k`.
    pub fn first_crossed(&self, x: &[Vec3], k: usize, l: usize) -> Option<usize> {
        let mut first: Option<(f64, usize)> = None;
        self.bvh.for_each_in_box(x[k].min(x[l]), x[k].max(x[l]), |f| {
            if self.faces[f].contains(&k) || self.faces[f].contains(&l) {
                return;
            }
            if let Some(t) = segment_crosses(x[k], x[l] - x[k], &self.tris[f])
                && first.is_none_or(|(best, _)| t < best)
            {
                first = Some((t, f));
            }
        });
        first.map(|(_, f)| f)
    }

    /// The garment's triangles (vertex ids).
    pub fn faces(&self) -> &[[usize; 3]] {
        &self.faces
    }

    /// Adds this frame's contact corrections at the predicted positions `x` to `delta`.
    pub fn project(&self, x: &[Vec3], inv_mass: &[f64], r: f64, delta: &mut [Vec3]) {
        for c in &self.point_triangle {
            let [i0, i1, i2] = self.faces[c.face];
            let t = [x[i0], x[i1], x[i2]];
            let p = x[c.particle];
            let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
            let n = if c.back { -n } else { n };
            let (w, _) = closest_on_triangle(p, &t);
            let depth = n.dot(p - at(&t, w)) - 2.0 * r;
            if depth < 0.0 {
                // The reference's triangle gradients reduce to −n̂ on the first corner (its
                // other terms carry a factor 1 − |n̂|² = 0).
                let wp = inv_mass[c.particle];
                let denom = wp + inv_mass[i0] * n.length_squared();
                if denom.abs() > 1e-5 {
                    delta[c.particle] += n * (wp * -depth / denom);
                }
            }
        }
        for c in &self.edge_edge {
            let [a, b, e0, e1] = c.ends;
            let (ta, tb, _) = closest_edge_edge(x[a], x[b], x[e0], x[e1], 1e-3);
            let p_alpha = x[a] * (1.0 - ta) + x[b] * ta;
            let p_beta = x[e0] * (1.0 - tb) + x[e1] * tb;
            let mut dir = (p_beta - p_alpha).normalize_or_zero();
            if dir.dot(c.dir) < 0.0 {
                dir = -dir;
            }
            let depth = (p_beta - p_alpha).dot(dir) - 2.0 * r;
            if depth < 0.0 {
                let g = [1.0 - ta, ta, 1.0 - tb, tb];
                let denom: f64 = (0..4).map(|k| inv_mass[c.ends[k]] * g[k] * g[k]).sum();
                if denom.abs() > 1e-5 {
                    let dl = -depth / denom;
                    delta[a] -= dir * (inv_mass[a] * dl * g[0]);
                    delta[b] -= dir * (inv_mass[b] * dl * g[1]);
                }
            }
        }
    }
}
