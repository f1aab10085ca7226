//! Self-collision of the garment, as the reference's Warp fork does it: point–triangle and
//! edge–edge contacts found once per frame (on the frame-start positions, with a one-frame
//! look-ahead), then projected in every substep. Edges that already cross the garment
//! exempt their ends from new contacts, so existing crossings are not locked in.
//!
//! The searches ask which faces are near each spring: the tree is searched once per spring
//! and frame ([`NearLists`]), and once the garment moves slowly, with a margin, so that the
//! following frames test only the faces listed then, plus the few faces that have moved too
//! far since (a Verlet list): the same faces in the same order as the tree search, so the
//! same contacts, bit for bit.

use garmentcode::Vec3;

use crate::bvh::{Bvh, at, closest_on_triangle, segment_crosses};
use crate::par;

/// One point–triangle contact: the particle, the triangle, and whether the particle was on
/// the back side of the triangle (the solver keeps it there).
#[derive(Debug, PartialEq)]
pub(crate) struct PointTriangle {
    particle: usize,
    face: usize,
    back: bool,
}

/// One edge–edge contact: edge `a–b` (the one that moves), edge `e0–e1`, and the direction
/// from the first to the second at detection.
#[derive(Debug, PartialEq)]
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
    /// Each face's place in the tree's order.
    ranks: Vec<u32>,
    /// The faces near each spring, while the garment moves slowly.
    near: Option<NearLists>,
    /// Positions at the last search.
    last_x: Vec<Vec3>,
    /// Per particle, a spring it ends (`usize::MAX` for none).
    spring_of: Vec<usize>,
    /// Whether to list the faces near each spring (else every search is a tree search).
    lists: bool,
}

/// How far (cm) beyond its search cube the faces near a spring are listed. A face whose box
/// meets the cube now met the cube grown by three times the largest move of its corners and
/// the spring's ends since the list was made, so the list holds every face near the spring
/// while those moved less than `SKIN / 3` (a quarter is used: rounding).
const SKIN: f64 = 0.4;

/// Particles farther than this from where they were when the lists were made (cm) are
/// searched for in the tree again.
const MOVED: f64 = SKIN / 4.0;

/// The margin of lists made for one frame only (cm): rounding.
const ONCE: f64 = 1e-6;

/// The faces near each spring (the faces whose boxes met its search cube grown by [`SKIN`]
/// when the lists were made), kept while at most a tenth of the particles have moved more
/// than [`MOVED`] since; while the garment moves faster, made again every frame, without
/// the margin.
struct NearLists {
    /// The margin they were made with: [`SKIN`], or [`ONCE`] for lists of one frame.
    skin: f64,
    /// Positions when the lists were made.
    anchor: Vec<Vec3>,
    /// Ends of each spring.
    ends: Vec<[usize; 2]>,
    /// Faces of spring `s`: `faces[start[s]..start[s + 1]]`, in the tree's order.
    start: Vec<usize>,
    faces: Vec<u32>,
    /// Particles moved more than [`MOVED`] since, the faces with such a corner, the list of
    /// those faces and their tree.
    fast: Vec<bool>,
    fast_face: Vec<bool>,
    fast_faces: Vec<usize>,
    fast_bvh: Bvh,
    /// The cells of a coarse grid that the boxes of those faces meet: a search box meeting
    /// none of them meets none of those faces.
    fast_cells: Grid,
}

/// A coarse grid of cells over a box, each marked or not.
struct Grid {
    lo: Vec3,
    cell: f64,
    dims: [usize; 3],
    marked: Vec<bool>,
}

impl Grid {
    /// Cells of about 2 cm (at most 64 a side) over the box `[lo, hi]`, none marked.
    fn new(lo: Vec3, hi: Vec3) -> Grid {
        let cell = ((hi - lo).max_element() / 64.0).max(2.0);
        let dims = ((hi - lo) / cell).to_array().map(|d| d as usize + 1);
        Grid { lo, cell, dims, marked: vec![false; dims[0] * dims[1] * dims[2]] }
    }

    /// The cells of the box `[lo, hi]` (clipped to the grid): lowest and highest indices.
    fn range(&self, lo: Vec3, hi: Vec3) -> [[usize; 3]; 2] {
        let index = |p: Vec3| {
            let c = (p - self.lo) / self.cell;
            [0, 1, 2].map(|k| (c[k].max(0.0) as usize).min(self.dims[k] - 1))
        };
        [index(lo), index(hi)]
    }

    /// Calls `f(cell)` for every cell of the box `[lo, hi]`, until it returns true; whether it did.
    fn any(&self, lo: Vec3, hi: Vec3, mut f: impl FnMut(usize) -> bool) -> bool {
        let [a, b] = self.range(lo, hi);
        (a[0]..=b[0]).any(|i| (a[1]..=b[1]).any(|j| (a[2]..=b[2]).any(|k| f((i * self.dims[1] + j) * self.dims[2] + k))))
    }

    /// Marks the cells of the box `[lo, hi]`.
    fn mark(&mut self, lo: Vec3, hi: Vec3) {
        let mut cells = Vec::new();
        self.any(lo, hi, |c| {
            cells.push(c);
            false
        });
        for c in cells {
            self.marked[c] = true;
        }
    }

    /// Whether a cell of the box `[lo, hi]` is marked.
    fn meets(&self, lo: Vec3, hi: Vec3) -> bool {
        self.any(lo, hi, |c| self.marked[c])
    }
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

/// The search cube of edge `pa–pb`: its midpoint ± (|ab|/2 + `pad`).
fn cube(pa: Vec3, pb: Vec3, pad: f64) -> (Vec3, Vec3) {
    let (mid, h) = ((pa + pb) / 2.0, Vec3::splat((pb - pa).length() / 2.0 + pad));
    (mid - h, mid + h)
}

impl SelfCollision {
    /// The collision mesh of the garment's `faces` at positions `x`.
    pub fn new(faces: Vec<[usize; 3]>, x: &[Vec3]) -> SelfCollision {
        let tris: Vec<[Vec3; 3]> = faces.iter().map(|f| f.map(|i| x[i])).collect();
        let bvh = Bvh::new(&tris);
        let bvh_ranks = bvh.ranks();
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
            ranks: bvh_ranks,
            near: None,
            last_x: Vec::new(),
            spring_of: Vec::new(),
            lists: true,
        }
    }

    /// Keeps, makes or drops the lists of faces near each spring for positions `x` (after
    /// the tree's refit); `r` is the particle radius.
    fn update_near(&mut self, x: &[Vec3], edges: &[([usize; 2], f64)], r: f64, threads: usize) {
        let n = x.len();
        let moved = |from: &[Vec3], i: usize| (x[i] - from[i]).length() > MOVED;
        if let Some(near) = &mut self.near {
            for (i, fast) in near.fast.iter_mut().enumerate() {
                *fast = moved(&near.anchor, i);
            }
            if near.skin < SKIN || near.fast.iter().filter(|&&f| f).count() * 10 > n {
                self.near = None;
            }
        }
        if self.near.is_none() && self.lists {
            // List the faces near each spring: with the margin when the garment moved slowly
            // since the last frame, else for this frame only (one search per spring serves the
            // crossing, point and edge searches).
            let slow = self.last_x.len() == n && (0..n).filter(|&i| moved(&self.last_x, i)).count() * 10 <= n;
            let skin = if slow { SKIN } else { ONCE };
            let lists = par::chunks(threads, edges.len(), |range| {
                let (mut counts, mut faces) = (Vec::with_capacity(range.len()), Vec::new());
                for &([a, b], _) in &edges[range] {
                    let (lo, hi) = cube(x[a], x[b], 3.0 * r + skin);
                    let before = faces.len();
                    self.bvh.for_each_in_box(lo, hi, |f| faces.push(f as u32));
                    counts.push(faces.len() - before);
                }
                (counts, faces)
            });
            let mut start = Vec::with_capacity(edges.len() + 1);
            start.push(0);
            for (counts, _) in &lists {
                for c in counts {
                    start.push(start[start.len() - 1] + c);
                }
            }
            self.near = Some(NearLists {
                skin,
                anchor: x.to_vec(),
                ends: edges.iter().map(|&(e, _)| e).collect(),
                start,
                faces: lists.into_iter().flat_map(|(_, f)| f).collect(),
                fast: vec![false; n],
                fast_face: Vec::new(),
                fast_faces: Vec::new(),
                fast_bvh: Bvh::new(&[]),
                fast_cells: Grid::new(Vec3::ZERO, Vec3::ZERO),
            });
            if self.spring_of.len() != n {
                self.spring_of = vec![usize::MAX; n];
                for (s, &([a, b], _)) in edges.iter().enumerate().rev() {
                    self.spring_of[a] = s;
                    self.spring_of[b] = s;
                }
            }
        }
        self.last_x.clear();
        self.last_x.extend_from_slice(x);
        if let Some(near) = &mut self.near {
            near.fast_face.clear();
            near.fast_face.extend(self.faces.iter().map(|f| f.iter().any(|&i| near.fast[i])));
            near.fast_faces.clear();
            near.fast_faces.extend((0..self.faces.len()).filter(|&f| near.fast_face[f]));
            let tris: Vec<[Vec3; 3]> = near.fast_faces.iter().map(|&f| self.tris[f]).collect();
            near.fast_bvh = Bvh::new(&tris);
            let bounds = |t: &[Vec3; 3]| (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]));
            let (lo, hi) =
                self.tris.iter().map(bounds).fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), (a, b)| (lo.min(a), hi.max(b)));
            near.fast_cells = Grid::new(lo, hi);
            for t in &tris {
                let (a, b) = bounds(t);
                near.fast_cells.mark(a, b);
            }
        }
    }

    /// Calls `hit(face)` for every face whose box meets `[lo, hi]`, in the tree's order, as
    /// `self.bvh.for_each_in_box` does; with `spring`, a spring whose search cube holds the
    /// box, from the faces listed near it and the faces that have moved since.
    fn for_each_near(&self, spring: Option<usize>, lo: Vec3, hi: Vec3, mut hit: impl FnMut(usize)) {
        let near = self.near.as_ref().zip(spring).filter(|&(near, s)| {
            s != usize::MAX && {
                let [a, b] = near.ends[s];
                !near.fast[a] && !near.fast[b]
            }
        });
        let Some((near, s)) = near else { return self.bvh.for_each_in_box(lo, hi, hit) };
        let mut moved = Vec::new();
        if near.fast_cells.meets(lo, hi) {
            near.fast_bvh.for_each_in_box(lo, hi, |k| moved.push(near.fast_faces[k]));
        }
        moved.sort_unstable_by_key(|&f| self.ranks[f]);
        let mut moved = moved.into_iter().peekable();
        for &f in &near.faces[near.start[s]..near.start[s + 1]] {
            let f = f as usize;
            if near.fast_face[f] || !self.bvh.meets(f, lo, hi) {
                continue;
            }
            while let Some(&g) = moved.peek()
                && self.ranks[g] < self.ranks[f]
            {
                hit(g);
                moved.next();
            }
            hit(f);
        }
        moved.for_each(hit);
    }

    /// Finds the edges crossing the garment and, if `contacts`, this frame's contacts at
    /// positions `x`, velocities `v`: `edges` are the garment's springs, `gravity` and `dt`
    /// (one frame) the look-ahead, `r` the particle radius; on up to `threads` threads, with
    /// the same result whatever their number.
    pub fn detect(
        &mut self,
        x: &[Vec3],
        v: &[Vec3],
        inv_mass: &[f64],
        edges: &[([usize; 2], f64)],
        (gravity, dt, r): (Vec3, f64, f64),
        contacts: bool,
        threads: usize,
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
        self.update_near(x, edges, r, threads);
        // Ends of edges that cross the garment now.
        self.crossings = par::flat(threads, edges.len(), |range| {
            range
                .filter_map(|s| {
                    let [k, l] = edges[s].0;
                    Some((k, l, self.first_crossed_near(x, Some(s), k, l)?))
                })
                .collect()
        });
        self.intersecting.fill(false);
        for &(k, l, _) in &self.crossings {
            self.intersecting[k] = true;
            self.intersecting[l] = true;
        }
        self.point_triangle.clear();
        self.edge_edge.clear();
        if !contacts {
            return;
        }
        let margin = 2.0 * r + 0.5 * r;
        self.point_triangle = par::flat(threads, x.len(), |range| {
            let mut found = Vec::new();
            for i in range {
                self.point_contacts(x, i, margin, r, &mut found);
            }
            found
        });
        let max_reach = self.reach.iter().fold(0.0f64, |m, &r| m.max(r));
        self.edge_edge = par::flat(threads, edges.len(), |range| {
            let mut found = Vec::new();
            for s in range {
                self.edge_contacts(x, (s, edges[s].0), (margin, r, max_reach), &mut found);
            }
            found
        });
    }

    /// Point–triangle contacts of particle `i`: faces in a box of ±3r around it (the
    /// reference's search) that the look-ahead brings within `margin`.
    fn point_contacts(&self, x: &[Vec3], i: usize, margin: f64, r: f64, found: &mut Vec<PointTriangle>) {
        if self.intersecting[i] {
            return;
        }
        let (ahead, p, h) = (&self.ahead, x[i], Vec3::splat(3.0 * r));
        let (faces, tris) = (&self.faces, &self.tris);
        self.for_each_near(self.spring_of.get(i).copied(), p - h, p + h, |f| {
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

    /// Edge–edge contacts of spring `a–b`: face edges of the faces in a cube of
    /// ±(|ab|/2 + 3r) around its midpoint (the reference's search) that the look-ahead
    /// brings within `margin`. Edges whose boxes are farther apart than the margin plus both
    /// look-aheads (at most `max_reach` for the other edge) cannot be, so when the spring's
    /// box grown by the margin and the look-aheads fits in the cube, the tree is searched with
    /// that smaller box (and faces outside the cube are skipped): the same contacts, fewer
    /// faces visited.
    fn edge_contacts(
        &self,
        x: &[Vec3],
        (s, [a, b]): (usize, [usize; 2]),
        (margin, r, max_reach): (f64, f64, f64),
        found: &mut Vec<EdgeEdge>,
    ) {
        if self.intersecting[a] || self.intersecting[b] {
            return;
        }
        let (ahead, reach) = (&self.ahead, &self.reach);
        let (pa, pb) = (x[a], x[b]);
        let len = (pb - pa).length();
        let (lo, hi) = (pa.min(pb), pa.max(pb));
        let reach_ab = reach[a].max(reach[b]);
        let (cube_lo, cube_hi) = cube(pa, pb, 3.0 * r);
        let grow = Vec3::splat(margin + reach_ab + max_reach + 1e-9);
        let (near_lo, near_hi) = (lo - grow, hi + grow);
        let near = near_lo.cmpge(cube_lo).all() && near_hi.cmple(cube_hi).all();
        let (search_lo, search_hi) = if near { (near_lo, near_hi) } else { (cube_lo, cube_hi) };
        let (faces, owns, bvh) = (&self.faces, &self.owns, &self.bvh);
        self.for_each_near(Some(s), search_lo, search_hi, |f| {
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

    /// The first garment triangle without either end that edge `k–l` crosses, from `k`.
    pub fn first_crossed(&self, x: &[Vec3], k: usize, l: usize) -> Option<usize> {
        self.first_crossed_near(x, None, k, l)
    }

    /// [`SelfCollision::first_crossed`] for the edge of `spring`, if it is one.
    fn first_crossed_near(&self, x: &[Vec3], spring: Option<usize>, k: usize, l: usize) -> Option<usize> {
        let mut first: Option<(f64, usize)> = None;
        self.for_each_near(spring, x[k].min(x[l]), x[k].max(x[l]), |f| {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Faces, positions, springs.
    type Sheets = (Vec<[usize; 3]>, Vec<Vec3>, Vec<([usize; 2], f64)>);

    /// Two 12 × 12 cm sheets of 1 cm squares, one 0.2 cm above the other and shifted, gently waved.
    fn sheets() -> Sheets {
        let (mut faces, mut x, mut edges) = (Vec::new(), Vec::new(), Vec::new());
        let side = 13;
        for sheet in 0..2 {
            let base = x.len();
            for i in 0..side {
                for j in 0..side {
                    let (a, b) = (i as f64, j as f64);
                    let offset = Vec3::new(0.5, 0.2, 0.3) * sheet as f64;
                    x.push(offset + Vec3::new(a, 0.05 * (a * 0.7 + b * 1.3).sin(), b));
                }
            }
            let id = |i: usize, j: usize| base + i * side + j;
            for i in 0..side - 1 {
                for j in 0..side - 1 {
                    faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                    faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
                }
            }
        }
        let mut keys = std::collections::BTreeSet::new();
        for f in &faces {
            for k in 0..3 {
                keys.insert([f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3])]);
            }
        }
        edges.extend(keys.into_iter().map(|e| (e, 1.0)));
        (faces, x, edges)
    }

    #[test]
    fn listed_faces_find_what_the_tree_finds() {
        let (faces, x0, edges) = sheets();
        let n = x0.len();
        let (v, inv_mass) = (vec![Vec3::new(0.0, -1.0, 0.0); n], vec![10.0; n]);
        let step = (Vec3::new(0.0, -981.0, 0.0), 1.0 / 60.0, 0.1);
        // Frame by frame: lists for one frame, then small moves (lists kept), then a few
        // particles moving far (searched in the tree again, the others from the lists), then
        // too many (lists for one frame again).
        let frame = |k: usize| -> Vec<Vec3> {
            x0.iter()
                .enumerate()
                .map(|(i, p)| {
                    let far = if (k == 3 && i % 17 == 0) || (k == 4 && i % 3 == 0) { 0.3 } else { 0.0 };
                    *p + Vec3::new(0.01 * k as f64, -0.02 * k as f64 - far, 0.005 * (i % 5) as f64 * k as f64)
                })
                .collect()
        };
        let mut listed = SelfCollision::new(faces.clone(), &x0);
        for k in 0..5 {
            let x = frame(k);
            listed.detect(&x, &v, &inv_mass, &edges, step, true, 2);
            match k {
                0 | 4 => assert!(listed.near.as_ref().is_some_and(|l| l.skin == ONCE)),
                1 | 2 => assert!(listed.near.as_ref().is_some_and(|l| l.skin == SKIN && l.fast_faces.is_empty())),
                _ => assert!(
                    listed
                        .near
                        .as_ref()
                        .is_some_and(|l| l.skin == SKIN && !l.fast_faces.is_empty() && l.fast_faces.len() < faces.len() / 2)
                ),
            }
            let mut tree = SelfCollision::new(faces.clone(), &x0);
            tree.lists = false;
            tree.detect(&x, &v, &inv_mass, &edges, step, true, 1);
            assert!(tree.near.is_none());
            assert!(!tree.point_triangle.is_empty() && !tree.edge_edge.is_empty(), "frame {k}: some contacts");
            assert_eq!(listed.point_triangle, tree.point_triangle, "frame {k}");
            assert_eq!(listed.edge_edge, tree.edge_edge, "frame {k}");
            assert_eq!(listed.crossings, tree.crossings, "frame {k}");
        }
    }
}
