//! Triangulation of one panel: interior points laid out in advance, a constrained
//! Delaunay triangulation (by `spade`) only where the layout needs one.
//!
//! The sampled outline is never split: the boundary stays exactly the sampled
//! polyline. Inside it go
//! - a **row**: one point over the middle of each outline segment, [`ROW_HEIGHT`]`·res`
//!   inside, so that the triangles on the outline are about isosceles (the reference's
//!   rest lengths of gathered seams depend on those triangles' shape), unless it comes
//!   close to the outline or to another row point (narrow parts, corners);
//! - an equilateral **lattice** of spacing [`LATTICE_SPACING`]`·res`, clipped to the
//!   panel by the even–odd rule, at least [`BOUNDARY_CLEARANCE`]`·res` farther from the
//!   outline than the row. Its triangles are output as they are.
//!
//! The constrained triangulation covers the strip between the outline and the lattice's
//! triangles: its points are the outline, the row and the lattice points on the border
//! of the lattice's triangles (or in none of them), its constraints the outline and
//! that border, so that by the even–odd rule the strip is inside and the lattice's
//! triangles are not (an outline that crosses itself or repeats a point is inserted
//! constraint by constraint instead, crossings becoming vertices, and every interior
//! point into the triangulation). Strip edges still longer than the size bound are split
//! at their midpoints until every edge is at most `1.43·res`, the reference mesher's size
//! criterion.
//!
//! This replaces quality refinement (spade's `refine`, Ruppert-style, which locates and
//! tests every candidate point): a lattice is already a quality mesh, and a bulk load of
//! the strip's few points is a fraction of the work.

use std::collections::VecDeque;

use spade::handles::{FixedFaceHandle, InnerTag};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use crate::Vec2;

/// Hash maps of the mesher: fast, fixed-seed hashing of small integer keys.
pub(crate) type HashMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::FixedState>;

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// Size bound of triangle edges, in units of the resolution.
pub const SIZE_BOUND: f64 = 1.43;

/// Spacing of the interior lattice, in units of the resolution.
const LATTICE_SPACING: f64 = 1.0;

/// Least distance of a lattice point from the row along the outline, in units of the resolution.
const BOUNDARY_CLEARANCE: f64 = 0.4;

/// Height of the row of points along the outline, in units of the resolution.
const ROW_HEIGHT: f64 = 0.75;

/// Least distance between points of the row along the outline, in units of the resolution.
const ROW_SPACING: f64 = 0.45;

/// A triangulated panel.
#[derive(Clone, Debug)]
pub(crate) struct PanelTriangulation {
    /// The boundary points as given, then points the triangulation added (crossing
    /// points of a self-crossing outline and interior points), in insertion order.
    pub points: Vec<Vec2>,
    /// Counter-clockwise index triples of the inside triangles.
    pub faces: Vec<[usize; 3]>,
}

/// Triangulates the region bounded by `segments` between `boundary` points, with the
/// open `lines` between them (inner lines of the format extension) as rows of edges
/// inside it that bound nothing. At most `max_interior` lattice points are laid out (an
/// error past that).
pub(crate) fn triangulate(
    boundary: &[Vec2],
    segments: &[[usize; 2]],
    lines: &[[usize; 2]],
    res: f64,
    max_interior: usize,
) -> Result<PanelTriangulation, String> {
    let max_len = SIZE_BOUND * res;
    // A resolution beyond the panel's size lays out points as for the panel's size (no
    // lattice, a row within the panel's reach), never at astronomical distances.
    let (lo, hi) =
        boundary.iter().fold((Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let layout_res = res.min((hi - lo).length());
    let (row, lattice) = interior_points(boundary, segments, lines, layout_res, max_interior)?;
    // The lattice's own triangles are kept as they are; the Delaunay triangulation only
    // fills the strip between the outline and them (the outline, the row, the lattice
    // points on the strip's inner border or in no lattice triangle), with the border's
    // edges as constraints: by the even–odd rule the strip is inside and the lattice's
    // triangles are not.
    let (lattice_faces, border) = lattice.triangles();
    let mut in_cdt = vec![true; lattice.points.len()];
    lattice_faces.iter().flatten().for_each(|&i| in_cdt[i] = false);
    border.iter().flatten().for_each(|&i| in_cdt[i] = true);
    // The outline is triangulated nudged too (equal points equally), and kept exact in the
    // output; by at most 0.1% of its spacing, which is below `res` when `res` exceeds the panel.
    let nudged: Vec<Vec2> = boundary.iter().map(|p| *p + nudge(p.x.to_bits(), p.y.to_bits(), layout_res)).collect();
    let mut all: Vec<Point2<f64>> = nudged.iter().chain(&row).map(|p| Point2::new(p.x, p.y)).collect();
    let mut cdt_index = vec![usize::MAX; lattice.points.len()];
    for (i, p) in lattice.points.iter().enumerate() {
        if in_cdt[i] {
            cdt_index[i] = all.len();
            all.push(Point2::new(p.x, p.y));
        }
    }
    let n_bulk = all.len();
    let mut edges: Vec<[usize; 2]> = segments.iter().chain(lines).copied().filter(|[a, b]| a != b).collect();
    edges.extend(border.iter().map(|e| e.map(|i| cdt_index[i])));
    let mut conflicts = false;
    let bulk = Cdt::try_bulk_load_cdt(all, edges, |_| conflicts = true).map_err(|e| format!("panel cannot be triangulated: {e:?}"))?;
    // Bulk loading keeps the vertex order unless points repeat: then, and for crossing
    // outlines, the outline goes in constraint by constraint and every interior point
    // into the triangulation.
    let (mut cdt, handle, crossing, lattice_faces) = if !conflicts && bulk.num_vertices() == n_bulk {
        (bulk, (0..boundary.len()).collect::<Vec<usize>>(), HashMap::default(), lattice_faces)
    } else {
        let mut cdt = Cdt::new();
        let mut handle = Vec::with_capacity(boundary.len());
        for p in &nudged {
            handle.push(cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("point ({}, {}) cannot be triangulated: {e:?}", p.x, p.y))?);
        }
        let all: Vec<[usize; 2]> = segments.iter().chain(lines).copied().collect();
        let crossing = add_outline(&mut cdt, &handle, &all);
        for p in row.iter().chain(&lattice.points) {
            cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("interior point cannot be inserted: {e:?}"))?;
        }
        cdt_index.clear();
        (cdt, handle.iter().map(|h| h.index()).collect(), crossing, Vec::new())
    };

    // Split inside edges longer than the size bound (never outline edges) at their midpoints.
    let budget = cdt.num_vertices() + 4 * boundary.len() + 1000;
    // The lines' constraints, which bound nothing (spade vertex indices, low first).
    let line_edges: std::collections::HashSet<[usize; 2]> = lines
        .iter()
        .map(|&[a, b]| {
            let (x, y) = (handle[a], handle[b]);
            [x.min(y), x.max(y)]
        })
        .collect();
    let mut inside = inside_faces(&cdt, &line_edges);
    for _ in 0..8 {
        let mut splits: Vec<Point2<f64>> = Vec::new();
        for f in &inside {
            for e in cdt.face(*f).adjacent_edges() {
                if e.is_constraint_edge() || e.length_2() <= max_len * max_len {
                    continue;
                }
                // Each undirected edge once: from its lower-index end, or from its only inside face.
                let [a, b] = [e.from(), e.to()];
                if a.fix().index() < b.fix().index() || e.rev().face().as_inner().is_none() {
                    let (pa, pb) = (a.position(), b.position());
                    splits.push(Point2::new((pa.x + pb.x) / 2.0, (pa.y + pb.y) / 2.0));
                }
            }
        }
        if splits.is_empty() {
            break;
        }
        if cdt.num_vertices() + splits.len() > budget {
            return Err("triangulation exceeds its size budget".into());
        }
        for p in splits {
            cdt.insert(p).map_err(|e| format!("refinement point cannot be inserted: {e:?}"))?;
        }
        inside = inside_faces(&cdt, &line_edges);
    }

    // Spade vertex index → output index: boundary vertices keep theirs, added vertices
    // used by inside faces are numbered after them in insertion order.
    let mut map: Vec<usize> = vec![usize::MAX; cdt.num_vertices()];
    for (i, &h) in handle.iter().enumerate() {
        if map[h] == usize::MAX {
            map[h] = i;
        }
    }
    let mut used = vec![false; cdt.num_vertices()];
    for f in &inside {
        for v in cdt.face(*f).vertices() {
            used[v.fix().index()] = true;
        }
    }
    // A crossing of two outline segments is no vertex of its own: like the reference,
    // it stands for the start of the segment whose insertion created it.
    for (&v, &a) in &crossing {
        map[v] = a;
    }
    let mut points = Vec::with_capacity(cdt.num_vertices() + lattice.points.len());
    points.extend_from_slice(boundary);
    for (i, v) in cdt.vertices().enumerate() {
        if map[i] == usize::MAX && used[i] {
            map[i] = points.len();
            let p = v.position();
            points.push(Vec2::new(p.x, p.y));
        }
    }
    let mut faces: Vec<[usize; 3]> = inside.iter().map(|f| cdt.face(*f).vertices().map(|v| map[v.fix().index()])).collect();
    // Then the lattice points inside the lattice's triangles, and those triangles.
    let mut lattice_out: Vec<usize> = cdt_index.iter().map(|&c| if c == usize::MAX { usize::MAX } else { map[c] }).collect();
    for f in &lattice_faces {
        for &i in f {
            if lattice_out[i] == usize::MAX {
                lattice_out[i] = points.len();
                points.push(lattice.points[i]);
            }
        }
        faces.push(f.map(|i| lattice_out[i]));
    }
    if !crossing.is_empty() {
        // Crossings mapped onto segment starts collapse or repeat faces.
        let mut seen = std::collections::HashSet::new();
        faces.retain(|&[a, b, c]| {
            let mut key = [a, b, c];
            key.sort_unstable();
            a != b && b != c && a != c && seen.insert(key)
        });
    }
    Ok(PanelTriangulation { points, faces })
}

/// The interior points: a row along the outline, one point over the middle of each
/// outline segment at [`ROW_HEIGHT`]`·res` (so the triangles on the outline are about
/// isosceles, as a quality mesher makes them), and the lattice inside that row.
fn interior_points(
    boundary: &[Vec2],
    segments: &[[usize; 2]],
    lines: &[[usize; 2]],
    res: f64,
    max_interior: usize,
) -> Result<(Vec<Vec2>, Lattice), String> {
    let (mut lo, mut hi) = (Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY));
    for p in boundary {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    let t = ROW_HEIGHT * res;
    let clearance = t + BOUNDARY_CLEARANCE * res;
    // Row and lattice keep clear of the lines as of the outline.
    let all: Vec<[usize; 2]> = segments.iter().chain(lines).copied().collect();
    let near = SegmentGrid::new(boundary, &all, lo, hi, clearance);
    let mut grid = PointGrid::new(lo, hi, ROW_SPACING * res);
    let mut row = Vec::new();
    // Inside is on the left of a counter-clockwise outline (positive area), else on the
    // right (the panel's normal, decided by its bounding-box corners, can disagree).
    let area2: f64 = segments.iter().map(|&[a, b]| boundary[a].perp_dot(boundary[b])).sum();
    let inward = if area2 < 0.0 { -1.0 } else { 1.0 };
    for &[a, b] in segments {
        let (pa, pb) = (boundary[a], boundary[b]);
        let d = pb - pa;
        let len = d.length();
        if len.is_nan() || len <= 0.0 {
            continue;
        }
        let q = (pa + pb) / 2.0 + inward * Vec2::new(-d.y, d.x) / len * t + nudge(a as u64, b as u64, res);
        if !near.within(q, 0.8 * t) && !grid.within(q) {
            grid.insert(q);
            row.push(q);
        }
    }
    // A lattice point is at least `BOUNDARY_CLEARANCE·res` farther from the outline than
    // any row point (a row point is at most `t` from it), so farther than `ROW_SPACING·res`
    // from every row point.
    Ok((row, Lattice::new(boundary, segments, &near, LATTICE_SPACING * res, clearance, [lo, hi], max_interior)?))
}

/// The points of an equilateral lattice of spacing `h` inside the outline (even–odd rule)
/// and at least `clearance` away from it. Rows are `h·√3/2` apart, odd rows shifted by
/// `h/2`; a point's place is its row and its column in half spacings. Memory and time
/// go with the number of points and outline segments, not with the bounding box (a
/// ruffle can be a 3 cm ring of 5 m radius).
struct Lattice {
    /// Row by row, columns increasing within a row.
    points: Vec<Vec2>,
    /// Each point's column.
    column: Vec<u32>,
    /// Row `r`'s points are `row_start[r]..row_start[r + 1]`.
    row_start: Vec<usize>,
}

impl Lattice {
    fn new(
        boundary: &[Vec2],
        segments: &[[usize; 2]],
        near: &SegmentGrid,
        h: f64,
        clearance: f64,
        [lo, hi]: [Vec2; 2],
        max_points: usize,
    ) -> Result<Lattice, String> {
        let size = hi - lo;
        let dy = h * 3f64.sqrt() / 2.0;
        let mut lattice = Lattice { points: Vec::new(), column: Vec::new(), row_start: vec![0] };
        if !(size.x > 2.0 * clearance && size.y > 2.0 * clearance) {
            return Ok(lattice);
        }
        let rows = ((size.y - 2.0 * clearance) / dy).floor() as usize + 1;
        // Centred in the bounding box; columns counted from `k_min`.
        let y0 = lo.y + (size.y - (rows - 1) as f64 * dy) / 2.0;
        let cx = (lo.x + hi.x) / 2.0;
        let k_min = ((lo.x - cx) / h).floor() as i64 - 2;
        let row_y = |r: usize| y0 + r as f64 * dy;
        // Where each row crosses the outline (a segment crosses the rows within its
        // height: min(y) <= y < max(y)), sorted by row, then x.
        let mut crossings: Vec<(usize, f64)> = Vec::new();
        for &[a, b] in segments {
            let (pa, pb) = (boundary[a], boundary[b]);
            let (y_lo, y_hi) = (pa.y.min(pb.y), pa.y.max(pb.y));
            let first = (((y_lo - y0) / dy).floor().max(0.0) as usize).min(rows);
            for r in first..rows {
                let y = row_y(r);
                if y >= y_hi {
                    break;
                }
                if (pa.y <= y) != (pb.y <= y) {
                    crossings.push((r, pa.x + (y - pa.y) * (pb.x - pa.x) / (pb.y - pa.y)));
                }
            }
        }
        crossings.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let mut at = 0;
        for r in 0..rows {
            let end = at + crossings[at..].iter().take_while(|c| c.0 == r).count();
            let shift = if r % 2 == 0 { 0.0 } else { h / 2.0 };
            for span in crossings[at..end].chunks_exact(2) {
                let (x0, x1) = (span[0].1 + clearance, span[1].1 - clearance);
                if x1 < x0 {
                    continue;
                }
                // Columns cx + shift + k·h within [x0, x1].
                let k0 = ((x0 - cx - shift) / h).ceil() as i64;
                let k1 = ((x1 - cx - shift) / h).floor() as i64;
                for k in k0..=k1 {
                    let p = Vec2::new(cx + shift + k as f64 * h, row_y(r)) + nudge(r as u64, k as u64, h);
                    if !near.within(p, clearance) {
                        lattice.column.push((2 * (k - k_min) + (r % 2) as i64) as u32);
                        lattice.points.push(p);
                    }
                    if lattice.points.len() > max_points {
                        return Err(format!("too large to mesh at {} cm (over {max_points} more vertices)", h / LATTICE_SPACING));
                    }
                }
            }
            lattice.row_start.push(lattice.points.len());
            at = end;
        }
        Ok(lattice)
    }

    /// The point at `row`, `column`, if any.
    fn at(&self, row: usize, column: usize) -> Option<usize> {
        let range = self.row_start.get(row..row + 2)?;
        let columns = &self.column[range[0]..range[1]];
        columns.binary_search(&u32::try_from(column).ok()?).ok().map(|i| range[0] + i)
    }

    /// The lattice's triangles (counter-clockwise) whose three corners are points, and
    /// the edges on the border of their union (in exactly one of them), directed as in
    /// their triangle. Per point at `(r, c)`: the upper triangle `(r, c) (r, c+2) (r+1, c+1)`
    /// and the lower one `(r, c) (r+1, c+1) (r+1, c−1)`.
    fn triangles(&self) -> (Vec<[usize; 3]>, Vec<[usize; 2]>) {
        let upper = |r: usize, c: usize| Some([self.at(r, c)?, self.at(r, c + 2)?, self.at(r + 1, c + 1)?]);
        let lower = |r: usize, c: usize| Some([self.at(r, c)?, self.at(r + 1, c + 1)?, self.at(r + 1, c.checked_sub(1)?)?]);
        let (mut faces, mut border) = (Vec::new(), Vec::new());
        let mut push = |f: [usize; 3], across: [Option<[usize; 3]>; 3]| {
            faces.push(f);
            for k in 0..3 {
                if across[k].is_none() {
                    border.push([f[k], f[(k + 1) % 3]]);
                }
            }
        };
        let rows = self.row_start.len() - 1;
        for r in 0..rows.saturating_sub(1) {
            for i in self.row_start[r]..self.row_start[r + 1] {
                let c = self.column[i] as usize;
                // The triangles across each edge, in the edges' order.
                if let Some(f) = upper(r, c) {
                    push(f, [r.checked_sub(1).and_then(|q| lower(q, c + 1)), lower(r, c + 2), lower(r, c)]);
                }
                if let Some(f) = lower(r, c) {
                    push(f, [upper(r, c), upper(r + 1, c - 1), c.checked_sub(2).and_then(|c| upper(r, c))]);
                }
            }
        }
        (faces, border)
    }
}

/// Outline segments bucketed by the cells of a uniform grid that their bounding boxes,
/// grown by the query distance, touch: a distance query reads one cell.
struct SegmentGrid<'a> {
    points: &'a [Vec2],
    segments: &'a [[usize; 2]],
    lo: Vec2,
    cell: f64,
    columns: usize,
    rows: usize,
    /// Cell `c`'s segments are `items[start[c]..start[c + 1]]`.
    start: Vec<usize>,
    items: Vec<u32>,
}

impl<'a> SegmentGrid<'a> {
    fn new(points: &'a [Vec2], segments: &'a [[usize; 2]], lo: Vec2, hi: Vec2, reach: f64) -> Self {
        // Cells twice the query distance (at most a million of them).
        let size = hi - lo;
        let cell = (2.0 * reach).max((size.x * size.y / 1e6).sqrt()).max(1e-9);
        let columns = ((size.x / cell) as usize + 1).min(1 << 12);
        let rows = ((size.y / cell) as usize + 1).min(1 << 12);
        let cell = cell.max(size.x / columns as f64).max(size.y / rows as f64);
        let mut grid = SegmentGrid { points, segments, lo, cell, columns, rows, start: vec![0; columns * rows + 1], items: Vec::new() };
        for pass in 0..2 {
            let mut fill = grid.start.clone();
            for (s, &[a, b]) in segments.iter().enumerate() {
                let (pa, pb) = (points[a], points[b]);
                let (c0, r0) = grid.cell_of(pa.min(pb) - Vec2::splat(reach));
                let (c1, r1) = grid.cell_of(pa.max(pb) + Vec2::splat(reach));
                for r in r0..=r1 {
                    for c in c0..=c1 {
                        let i = r * columns + c;
                        if pass == 0 {
                            grid.start[i + 1] += 1;
                        } else {
                            grid.items[fill[i]] = s as u32;
                            fill[i] += 1;
                        }
                    }
                }
            }
            if pass == 0 {
                for i in 0..columns * rows {
                    grid.start[i + 1] += grid.start[i];
                }
                grid.items = vec![0; grid.start[columns * rows]];
            }
        }
        grid
    }

    fn cell_of(&self, p: Vec2) -> (usize, usize) {
        let q = (p - self.lo) / self.cell;
        let c = (q.x.max(0.0) as usize).min(self.columns - 1);
        let r = (q.y.max(0.0) as usize).min(self.rows - 1);
        (c, r)
    }

    /// Whether some segment comes closer to `p` than `d`.
    fn within(&self, p: Vec2, d: f64) -> bool {
        let (c, r) = self.cell_of(p);
        let i = r * self.columns + c;
        self.items[self.start[i]..self.start[i + 1]].iter().any(|&s| {
            let [a, b] = self.segments[s as usize];
            segment_distance(p, self.points[a], self.points[b]) < d
        })
    }
}

/// Adds the outline segments as constraints, splitting crossing ones; returns the
/// vertices created at crossings, each with the local id of the segment start that
/// created it.
fn add_outline(cdt: &mut Cdt, handle: &[spade::handles::FixedVertexHandle], segments: &[[usize; 2]]) -> HashMap<usize, usize> {
    let mut crossing = HashMap::default();
    for &[a, b] in segments {
        if handle[a] != handle[b] {
            let before = cdt.num_vertices();
            cdt.add_constraint_and_split(handle[a], handle[b], |p| p);
            for v in before..cdt.num_vertices() {
                crossing.insert(v, a);
            }
        }
    }
    crossing
}

/// Inner faces inside the outline by the even–odd rule: a face's level is the number of
/// constraints crossed on the way from the outer face (not counting `lines`, which
/// bound nothing); odd levels are inside.
fn inside_faces(cdt: &Cdt, lines: &std::collections::HashSet<[usize; 2]>) -> Vec<FixedFaceHandle<InnerTag>> {
    let bounds = |e: spade::handles::DirectedEdgeHandle<_, _, _, _>| {
        let (a, b) = (e.from().fix().index(), e.to().fix().index());
        e.is_constraint_edge() && (lines.is_empty() || !lines.contains(&[a.min(b), a.max(b)]))
    };
    let n = cdt.num_all_faces();
    let mut parity: Vec<Option<bool>> = vec![None; n];
    let mut queue = VecDeque::new();
    for e in cdt.convex_hull() {
        for d in [e, e.rev()] {
            if let Some(f) = d.face().as_inner() {
                let odd = bounds(d);
                if parity[f.fix().index()].is_none() {
                    parity[f.fix().index()] = Some(odd);
                    queue.push_back(f.fix());
                }
            }
        }
    }
    while let Some(f) = queue.pop_front() {
        let odd = parity[f.index()].unwrap_or(false);
        for e in cdt.face(f).adjacent_edges() {
            if let Some(g) = e.rev().face().as_inner() {
                if parity[g.fix().index()].is_none() {
                    parity[g.fix().index()] = Some(odd ^ bounds(e));
                    queue.push_back(g.fix());
                }
            }
        }
    }
    cdt.inner_faces().filter(|f| parity[f.fix().index()] == Some(true)).map(|f| f.fix()).collect()
}

/// A fixed pseudo-random offset of at most 0.1% of `scale` per coordinate, keyed by `a`
/// and `b`. A lattice is full of collinear points, and a row over a straight outline of
/// cocircular ones (isosceles trapezoids): each such test sends the triangulation's exact
/// predicates to their slow arithmetic, which nudged points avoid.
fn nudge(a: u64, b: u64, scale: f64) -> Vec2 {
    let unit = |salt: u64| {
        let z = a.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ b.wrapping_mul(0xC2B2_AE3D_27D4_EB4F) ^ salt;
        let z = (z ^ (z >> 31)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        (z >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    Vec2::new(unit(1), unit(2)) * 2e-3 * scale
}

/// Points in the cells of a uniform grid, for "is any point closer than the cell size" queries.
struct PointGrid {
    lo: Vec2,
    cell: f64,
    columns: usize,
    rows: usize,
    cells: HashMap<usize, Vec<Vec2>>,
}

impl PointGrid {
    fn new(lo: Vec2, hi: Vec2, cell: f64) -> Self {
        let size = hi - lo;
        let columns = (size.x / cell) as usize + 1;
        let rows = (size.y / cell) as usize + 1;
        PointGrid { lo, cell, columns, rows, cells: HashMap::default() }
    }

    fn cell_of(&self, p: Vec2) -> (usize, usize) {
        let q = (p - self.lo) / self.cell;
        ((q.x.max(0.0) as usize).min(self.columns - 1), (q.y.max(0.0) as usize).min(self.rows - 1))
    }

    fn insert(&mut self, p: Vec2) {
        let (c, r) = self.cell_of(p);
        self.cells.entry(r * self.columns + c).or_default().push(p);
    }

    /// Whether a point of the grid is closer to `p` than the cell size.
    fn within(&self, p: Vec2) -> bool {
        let (c, r) = self.cell_of(p);
        (r.saturating_sub(1)..=(r + 1).min(self.rows - 1)).any(|r| {
            (c.saturating_sub(1)..=(c + 1).min(self.columns - 1))
                .any(|c| self.cells.get(&(r * self.columns + c)).is_some_and(|v| v.iter().any(|q| (*q - p).length() < self.cell)))
        })
    }
}

/// Distance of `p` to the segment `a b`.
fn segment_distance(p: Vec2, a: Vec2, b: Vec2) -> f64 {
    let d = b - a;
    let t = if d.length_squared() > 0.0 { ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + t * d)).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(n: usize, side: f64) -> (Vec<Vec2>, Vec<[usize; 2]>) {
        let mut pts = Vec::new();
        let corners = [Vec2::new(0.0, 0.0), Vec2::new(side, 0.0), Vec2::new(side, side), Vec2::new(0.0, side)];
        for k in 0..4 {
            for i in 0..n {
                pts.push(corners[k] + (corners[(k + 1) % 4] - corners[k]) * (i as f64 / n as f64));
            }
        }
        let m = pts.len();
        let segs = (0..m).map(|i| [i, (i + 1) % m]).collect();
        (pts, segs)
    }

    #[test]
    fn square_is_covered_with_short_edges() {
        let (pts, segs) = square(10, 10.0);
        let t = triangulate(&pts, &segs, &[], 1.0, 1000).unwrap();
        let area: f64 = t.faces.iter().map(|f| (t.points[f[1]] - t.points[f[0]]).perp_dot(t.points[f[2]] - t.points[f[0]]) / 2.0).sum();
        assert!((area - 100.0).abs() < 1e-9, "{area}");
        for f in &t.faces {
            for k in 0..3 {
                assert!((t.points[f[k]] - t.points[f[(k + 1) % 3]]).length() <= SIZE_BOUND + 1e-9);
            }
        }
        assert!(t.points.len() > pts.len());
    }
}
