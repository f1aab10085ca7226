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
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PointTriangle {
    particle: usize,
    face: usize,
    back: bool,
}

/// One edge–edge contact: edge `a–b` (the one that moves), edge `e0–e1`, and the direction
/// from the first to the second at detection.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// Per spring, the face it crosses first (`u32::MAX`: none).
    crossed: Vec<u32>,
    /// This frame's contacts: those of particle `i` are `point_triangle[point_start[i]..point_start[i + 1]]`,
    /// those of spring `s` are `edge_edge[edge_start[s]..edge_start[s + 1]]`.
    point_triangle: Vec<PointTriangle>,
    point_start: Vec<usize>,
    edge_edge: Vec<EdgeEdge>,
    edge_start: Vec<usize>,
    /// Per particle, its position and look-ahead when its neighbourhood's contacts were last
    /// searched for (see [`STIR`]), and whether it has moved more than [`STIR`] from there.
    quiet_x: Vec<Vec3>,
    quiet_ahead: Vec<Vec3>,
    stirred: Vec<bool>,
    /// Springs searched for again in the last frame, and particles stirred.
    searched: (usize, usize),
    /// This frame's look-ahead of every particle, and its length.
    ahead: Vec<Vec3>,
    reach: Vec<f64>,
    /// The longest look-ahead of each face's corners.
    face_reach: Vec<f64>,
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

/// While the lists are kept, the crossing and contacts of a spring (and the point contacts
/// of its ends) are searched for again only when a particle near it (an end, a corner of a
/// face whose box meets its search cube) has moved, or changed its look-ahead, by more than
/// this (cm) since the particle's neighbourhood was last searched; elsewhere the last
/// frame's are kept. The particles of a kept pair are then within `2·STIR` of where they were
/// when it was searched (the same for their look-aheads), so a pair left out, whose predicted
/// gap was at least the contact margin (2.5r = 0.25 cm), now has one of at least
/// `0.25 − 8·STIR` = 0.2 cm, the 2r the contacts keep: it would not be pushed if it were
/// listed. Once the garment has landed, most of its particles move less than this in a
/// frame, and half the springs or more are not searched again.
const STIR: f64 = 0.00625;

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

    /// The same grid with no cell marked.
    fn cleared(&self) -> Grid {
        Grid { lo: self.lo, cell: self.cell, dims: self.dims, marked: vec![false; self.marked.len()] }
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

/// Every item of `0..n` on up to `threads` threads: `find(i, out)` appends item `i`'s finds
/// to `out`. All the finds in item order, and where each item's begin (`n + 1` offsets).
fn per_item<T: Send>(threads: usize, n: usize, find: impl Fn(usize, &mut Vec<T>) + Sync) -> (Vec<usize>, Vec<T>) {
    let chunks = par::chunks(threads, n, |range| {
        let (mut counts, mut found) = (Vec::with_capacity(range.len()), Vec::new());
        for i in range {
            let before = found.len();
            find(i, &mut found);
            counts.push(found.len() - before);
        }
        (counts, found)
    });
    let mut start = Vec::with_capacity(n + 1);
    start.push(0);
    for (counts, _) in &chunks {
        for c in counts {
            start.push(start[start.len() - 1] + c);
        }
    }
    (start, chunks.into_iter().flat_map(|(_, f)| f).collect())
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
            crossed: Vec::new(),
            point_triangle: Vec::new(),
            point_start: Vec::new(),
            edge_edge: Vec::new(),
            edge_start: Vec::new(),
            quiet_x: Vec::new(),
            quiet_ahead: Vec::new(),
            stirred: Vec::new(),
            searched: (0, 0),
            ahead: Vec::new(),
            reach: Vec::new(),
            face_reach: Vec::new(),
            ranks: bvh_ranks,
            near: None,
            last_x: Vec::new(),
            spring_of: Vec::new(),
            lists: true,
        }
    }

    /// Keeps, makes or drops the lists of faces near each spring for positions `x` (after
    /// the tree's refit); `r` is the particle radius. Whether lists with the margin were kept
    /// from an earlier frame.
    fn update_near(&mut self, x: &[Vec3], edges: &[([usize; 2], f64)], r: f64, threads: usize) -> bool {
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
        let kept = self.near.is_some();
        if self.near.is_none() && self.lists {
            // List the faces near each spring: with the margin when the garment moved slowly
            // since the last frame, else for this frame only (one search per spring serves the
            // crossing, point and edge searches).
            let slow = self.last_x.len() == n && (0..n).filter(|&i| moved(&self.last_x, i)).count() * 10 <= n;
            let skin = if slow { SKIN } else { ONCE };
            let (start, faces) = per_item(threads, edges.len(), |s, faces| {
                let [a, b] = edges[s].0;
                let (lo, hi) = cube(x[a], x[b], 3.0 * r + skin);
                self.bvh.for_each_in_box(lo, hi, |f| faces.push(f as u32));
            });
            self.near = Some(NearLists {
                skin,
                anchor: x.to_vec(),
                ends: edges.iter().map(|&(e, _)| e).collect(),
                start,
                faces,
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
        kept && self.near.as_ref().is_some_and(|near| near.skin == SKIN)
    }

    /// Per spring, whether a particle that may be near it is stirred: an end, or a corner of
    /// a face whose box meets its cube grown by `2·STIR` (a face that is not stirred has
    /// moved less than that since the spring was last searched for). The faces are those on
    /// its list and the moved ones.
    fn stirred_springs(&self, near: &NearLists, x: &[Vec3], r: f64, threads: usize) -> Vec<bool> {
        let stirred_face: Vec<bool> = self.faces.iter().map(|f| f.iter().any(|&i| self.stirred[i])).collect();
        let mut cells = near.fast_cells.cleared();
        for &f in near.fast_faces.iter().filter(|&&f| stirred_face[f]) {
            let (lo, hi) = self.bvh.face_box(f);
            cells.mark(lo, hi);
        }
        par::flat(threads, near.ends.len(), |range| {
            range
                .map(|s| {
                    let [a, b] = near.ends[s];
                    if self.stirred[a] || self.stirred[b] || near.fast[a] || near.fast[b] {
                        return true;
                    }
                    let (lo, hi) = cube(x[a], x[b], 3.0 * r + 2.0 * STIR);
                    let listed = &near.faces[near.start[s]..near.start[s + 1]];
                    if listed.iter().any(|&f| stirred_face[f as usize] && self.bvh.meets(f as usize, lo, hi)) {
                        return true;
                    }
                    let mut moved = false;
                    if cells.meets(lo, hi) {
                        near.fast_bvh.for_each_in_box(lo, hi, |k| moved |= stirred_face[near.fast_faces[k]]);
                    }
                    moved
                })
                .collect()
        })
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
        self.face_reach.clear();
        self.face_reach.extend(self.faces.iter().map(|f| f.iter().fold(0.0f64, |m, &i| m.max(self.reach[i]))));
        self.bvh.refit(&self.tris);
        let kept = self.update_near(x, edges, r, threads);
        // Where the last frame's finds may be kept: nothing near a spring stirred since.
        let n = x.len();
        let reuse = kept && self.edge_start.len() == edges.len() + 1 && self.point_start.len() == n + 1;
        if reuse {
            for i in 0..n {
                self.stirred[i] = (x[i] - self.quiet_x[i]).length() > STIR || (self.ahead[i] - self.quiet_ahead[i]).length() > STIR;
                if self.stirred[i] {
                    self.quiet_x[i] = x[i];
                    self.quiet_ahead[i] = self.ahead[i];
                }
            }
        } else {
            self.stirred = vec![true; n];
            self.quiet_x = x.to_vec();
            self.quiet_ahead = self.ahead.clone();
        }
        let stirred = match (&self.near, reuse) {
            (Some(near), true) => self.stirred_springs(near, x, r, threads),
            _ => vec![true; edges.len()],
        };
        // The face each edge crosses first (the ends of edges that cross the garment now).
        self.crossed = par::flat(threads, edges.len(), |range| {
            range
                .map(|s| match stirred[s] {
                    true => self.first_crossed_near(x, Some(s), edges[s].0[0], edges[s].0[1]).map_or(u32::MAX, |f| f as u32),
                    false => self.crossed[s],
                })
                .collect()
        });
        self.crossings.clear();
        self.crossings
            .extend(edges.iter().zip(&self.crossed).filter(|&(_, &f)| f != u32::MAX).map(|(&([k, l], _), &f)| (k, l, f as usize)));
        let was = std::mem::replace(&mut self.intersecting, vec![false; n]);
        for &(k, l, _) in &self.crossings {
            self.intersecting[k] = true;
            self.intersecting[l] = true;
        }
        if !contacts {
            self.point_triangle.clear();
            self.edge_edge.clear();
            self.point_start.clear();
            self.edge_start.clear();
            return;
        }
        let changed = |i: usize| was[i] != self.intersecting[i];
        let margin = 2.0 * r + 0.5 * r;
        let (point_start, point_triangle) = per_item(threads, n, |i, found| {
            let s = self.spring_of.get(i).copied().unwrap_or(usize::MAX);
            if !reuse || s == usize::MAX || stirred[s] || changed(i) {
                self.point_contacts(x, i, margin, r, found);
            } else {
                found.extend_from_slice(&self.point_triangle[self.point_start[i]..self.point_start[i + 1]]);
            }
        });
        let max_reach = self.reach.iter().fold(0.0f64, |m, &r| m.max(r));
        let (edge_start, edge_edge) = per_item(threads, edges.len(), |s, found| {
            let [a, b] = edges[s].0;
            if stirred[s] || changed(a) || changed(b) {
                self.edge_contacts(x, (s, [a, b]), (margin, r, max_reach), found);
            } else {
                found.extend_from_slice(&self.edge_edge[self.edge_start[s]..self.edge_start[s + 1]]);
            }
        });
        self.searched = (stirred.iter().filter(|&&s| s).count(), self.stirred.iter().filter(|&&s| s).count());
        (self.point_start, self.point_triangle, self.edge_start, self.edge_edge) = (point_start, point_triangle, edge_start, edge_edge);
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
    /// that smaller box (and faces outside the cube are skipped); a face whose box is that far
    /// from the spring's is skipped whole. The same contacts, fewer faces visited.
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
        let (faces, owns, bvh, face_reach) = (&self.faces, &self.owns, &self.bvh, &self.face_reach);
        // Whether the box `[b_lo, b_hi]` is farther from the spring's box than the margin plus
        // the look-aheads `reach_ab + reach` (squared distances: no square root per face).
        let far = |b_lo: Vec3, b_hi: Vec3, reach: f64| {
            let limit = margin + 1e-9 + reach_ab + reach;
            (b_lo - hi).max(lo - b_hi).max(Vec3::ZERO).length_squared() > limit * limit
        };
        self.for_each_near(Some(s), search_lo, search_hi, |f| {
            if near && !bvh.meets(f, cube_lo, cube_hi) {
                return;
            }
            let (f_lo, f_hi) = bvh.face_box(f);
            if far(f_lo, f_hi, face_reach[f]) {
                return;
            }
            let face = faces[f];
            for k in 0..3 {
                let (e0, e1) = (face[k], face[(k + 1) % 3]);
                if !owns[f][k] || e0 == a || e0 == b || e1 == a || e1 == b {
                    continue;
                }
                if far(x[e0].min(x[e1]), x[e0].max(x[e1]), reach[e0].max(reach[e1])) {
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

    use crate::sheets::two_sheets;

    /// Two 12 × 12 cm sheets of 1 cm squares, one 0.2 cm above the other and shifted, gently
    /// waved, falling: both list tests' set-up.
    struct Falling {
        faces: Vec<[usize; 3]>,
        x0: Vec<Vec3>,
        edges: Vec<([usize; 2], f64)>,
        v: Vec<Vec3>,
        inv_mass: Vec<f64>,
    }

    const STEP: (Vec3, f64, f64) = (Vec3::new(0.0, -981.0, 0.0), 1.0 / 60.0, 0.1);

    impl Falling {
        fn new() -> Falling {
            let (faces, x0, edges) = two_sheets(13, Vec3::new(0.5, 0.2, 0.3), |a, b| 0.05 * (a * 0.7 + b * 1.3).sin());
            let n = x0.len();
            Falling { faces, x0, edges, v: vec![Vec3::new(0.0, -1.0, 0.0); n], inv_mass: vec![10.0; n] }
        }

        /// Detection with the lists, kept from frame to frame, at `x`.
        fn listed(&self, listed: &mut SelfCollision, x: &[Vec3]) {
            listed.detect(x, &self.v, &self.inv_mass, &self.edges, STEP, true, 2);
        }

        /// What the tree alone finds at `x` (no lists), with some contacts.
        fn tree(&self, x: &[Vec3]) -> SelfCollision {
            let mut tree = SelfCollision::new(self.faces.clone(), &self.x0);
            tree.lists = false;
            tree.detect(x, &self.v, &self.inv_mass, &self.edges, STEP, true, 1);
            assert!(tree.near.is_none());
            assert!(!tree.point_triangle.is_empty() && !tree.edge_edge.is_empty(), "some contacts");
            tree
        }
    }

    #[test]
    fn listed_faces_find_what_the_tree_finds() {
        let s = Falling::new();
        let (faces, x0) = (&s.faces, &s.x0);
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
        let mut listed = SelfCollision::new(faces.clone(), x0);
        for k in 0..5 {
            let x = frame(k);
            s.listed(&mut listed, &x);
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
            let tree = s.tree(&x);
            assert_eq!(listed.point_triangle, tree.point_triangle, "frame {k}");
            assert_eq!(listed.edge_edge, tree.edge_edge, "frame {k}");
            assert_eq!(listed.crossings, tree.crossings, "frame {k}");
        }
    }

    #[test]
    fn contacts_are_searched_again_only_near_stirred_particles() {
        let s = Falling::new();
        let (faces, x0, edges) = (&s.faces, &s.x0, &s.edges);
        // Frame 0 lists the faces for one frame, frame 1 with the margin; from frame 2 on a few
        // particles jump by 0.09 cm (less than MOVED: still searched from the lists) or, from
        // frame 3, by 0.3 cm (searched in the tree), and particle 0, a corner, creeps by
        // 0.004 cm a frame.
        let frame = |k: usize| -> Vec<Vec3> {
            x0.iter()
                .enumerate()
                .map(|(i, p)| {
                    let jump = match (k, (i + 1) % 151, (i + 5) % 211) {
                        (2.., 0, _) => Vec3::new(0.0, -0.09, 0.0),
                        (3.., _, 0) => Vec3::new(0.0, 0.3, 0.0),
                        _ => Vec3::ZERO,
                    };
                    let creep = if i == 0 { -0.004 * k.saturating_sub(1) as f64 } else { 0.0 };
                    *p + jump + Vec3::new(creep, 0.0, 0.0)
                })
                .collect()
        };
        let mut listed = SelfCollision::new(faces.clone(), x0);
        for k in 0..6 {
            let x = frame(k);
            s.listed(&mut listed, &x);
            let tree = s.tree(&x);
            let (searched, _) = listed.searched;
            if k >= 2 {
                assert!(0 < searched && searched < edges.len() / 2, "frame {k}: {searched} of {} springs searched", edges.len());
                // The creeping corner is stirred each time it is STIR from where it last was.
                assert_eq!(listed.stirred[0], k == 3 || k == 5, "frame {k}");
            } else {
                assert_eq!(searched, edges.len(), "frame {k}");
            }
            assert_eq!(listed.point_triangle, tree.point_triangle, "frame {k}");
            assert_eq!(listed.crossings, tree.crossings, "frame {k}");
            // The same pairs; the directions kept from an earlier frame for the creeping corner's.
            let ends = |c: &SelfCollision| c.edge_edge.iter().map(|e| e.ends).collect::<Vec<_>>();
            assert_eq!(ends(&listed), ends(&tree), "frame {k}");
            for (a, b) in listed.edge_edge.iter().zip(&tree.edge_edge) {
                assert!((a.dir - b.dir).length() < 0.01 && (a.dir == b.dir || a.ends.contains(&0)), "frame {k}: {a:?} {b:?}");
            }
        }
    }
}
