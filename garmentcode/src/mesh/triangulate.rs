//! Triangulation of one panel: interior points laid out in advance, then one constrained
//! Delaunay triangulation (by `spade`, bulk-loaded) of the outline and those points.
//!
//! The sampled outline is never split: the boundary stays exactly the sampled
//! polyline. Inside it go
//! - a **row**: one point over the middle of each outline segment, [`ROW_HEIGHT`]`·res`
//!   inside, so that the triangles on the outline are about isosceles (the reference's
//!   rest lengths of gathered seams depend on those triangles' shape), unless it comes
//!   close to the outline or to another row point (narrow parts, corners);
//! - **blue noise**: a fixed tile of Poisson-disk points (no two closer than
//!   `0.7·res`, made by dart throwing from a fixed seed and stored) repeated over the panel,
//!   kept inside the outline by the even–odd rule and at least
//!   [`BOUNDARY_CLEARANCE`]`·res` farther from the outline than the row.
//!
//! The outline is the triangulation's constraints and the even–odd rule decides what is
//! inside (an outline that crosses itself or repeats a point is inserted constraint by
//! constraint instead, crossings becoming vertices). Edges still longer than the size
//! bound are split at their midpoints until every edge is at most `1.43·res`, the
//! reference mesher's size criterion.
//!
//! Why noise: the reference's mesher (CGAL's Delaunay refinement) makes an irregular
//! interior, whose edges run in every direction. An equilateral lattice (this module's
//! first interior) puts every edge in three directions along straight lines, which a
//! cloth of nearly no bending stiffness folds along like hinges: draped, the t-shirt's
//! panels folded through themselves (`docs/drape.md`). The Delaunay triangulation of
//! blue noise has the refinement's character (edges of 0.8 to 1.4 `res` in every
//! direction, about the same number of points) without its search for bad triangles
//! (spade's `refine`, Ruppert-style, locates and tests every candidate point; laying out
//! the points and bulk loading them is a fraction of that work).

use std::collections::VecDeque;

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use crate::Vec2;

mod noise_tile;

/// Hash maps of the mesher: fast, fixed-seed hashing of small integer keys.
pub(crate) type HashMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::FixedState>;

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// Size bound of triangle edges, in units of the resolution.
pub const SIZE_BOUND: f64 = 1.43;

/// Least distance between two noise points, in units of the resolution.
#[cfg(test)]
const NOISE_DISTANCE: f64 = 0.7;

/// Side of the square tile of noise points repeated over the panel, in units of the resolution.
const TILE_SIDE: f64 = 24.0;

/// Height of the bands the noise points are sorted into, in units of the resolution
/// (a whole fraction of [`TILE_SIDE`]).
const BAND: f64 = 0.5;

/// Least distance of a noise point from the row along the outline, in units of the resolution.
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
/// inside it that bound nothing. At most `max_interior` noise points are laid out (an
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
    // noise, a row within the panel's reach), never at astronomical distances.
    let (lo, hi) =
        boundary.iter().fold((Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let layout_res = res.min((hi - lo).length());
    let (row, noise) = interior_points(boundary, segments, lines, layout_res, max_interior)?;
    // The outline is triangulated nudged too (equal points equally), and kept exact in the
    // output; by at most 0.1% of its spacing, which is below `res` when `res` exceeds the panel.
    let nudged: Vec<Vec2> = boundary.iter().map(|p| *p + nudge(p.x.to_bits(), p.y.to_bits(), layout_res)).collect();
    let all: Vec<Point2<f64>> = nudged.iter().chain(&row).chain(&noise).map(|p| Point2::new(p.x, p.y)).collect();
    let n_bulk = all.len();
    let edges: Vec<[usize; 2]> = segments.iter().chain(lines).copied().filter(|[a, b]| a != b).collect();
    let mut conflicts = false;
    let bulk = Cdt::try_bulk_load_cdt(all, edges, |_| conflicts = true).map_err(|e| format!("panel cannot be triangulated: {e:?}"))?;
    // Bulk loading keeps the vertex order unless points repeat: then, and for crossing
    // outlines, the outline goes in constraint by constraint and every interior point
    // into the triangulation.
    let (mut cdt, handle, crossing) = if !conflicts && bulk.num_vertices() == n_bulk {
        (bulk, (0..boundary.len()).collect::<Vec<usize>>(), HashMap::default())
    } else {
        let mut cdt = Cdt::new();
        let mut handle = Vec::with_capacity(boundary.len());
        for p in &nudged {
            handle.push(cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("point ({}, {}) cannot be triangulated: {e:?}", p.x, p.y))?);
        }
        let constraints: Vec<[usize; 2]> = segments.iter().chain(lines).copied().collect();
        let crossing = add_outline(&mut cdt, &handle, &constraints);
        for p in row.iter().chain(&noise) {
            cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("interior point cannot be inserted: {e:?}"))?;
        }
        (cdt, handle.iter().map(|h| h.index()).collect(), crossing)
    };

    // Split inside edges longer than the size bound (never outline edges) at their
    // midpoints: first those of every inside face, then, round after round, those at the
    // vertices the last round added (every other edge was there before, short). An added
    // vertex and the faces its insertion makes or changes are inside (its cavity never
    // crosses a constraint), so the faces outside stay as they were.
    let budget = cdt.num_vertices() + 4 * boundary.len() + 1000;
    // The lines' constraints, which bound nothing (spade vertex indices, low first).
    let line_edges: std::collections::HashSet<[usize; 2]> = lines
        .iter()
        .map(|&[a, b]| {
            let (x, y) = (handle[a], handle[b]);
            [x.min(y), x.max(y)]
        })
        .collect();
    let mut is_inside = inside_faces(&cdt, &line_edges);
    let mut splits: Vec<Point2<f64>> = Vec::new();
    for f in cdt.inner_faces().filter(|f| is_inside[f.fix().index()]) {
        for e in f.adjacent_edges() {
            // Each undirected edge once: from its lower-index end, or from its only inside face.
            let [a, b] = [e.from().fix().index(), e.to().fix().index()];
            if !e.is_constraint_edge() && e.length_2() > max_len * max_len && (a < b || e.rev().face().as_inner().is_none()) {
                splits.push(midpoint(e.from().position(), e.to().position()));
            }
        }
    }
    for round in 1.. {
        if splits.is_empty() || round > 8 {
            break;
        }
        if cdt.num_vertices() + splits.len() > budget {
            return Err("triangulation exceeds its size budget".into());
        }
        let first_added = cdt.num_vertices();
        for p in splits.drain(..) {
            cdt.insert(p).map_err(|e| format!("refinement point cannot be inserted: {e:?}"))?;
        }
        for v in first_added..cdt.num_vertices() {
            for e in cdt.vertex(FixedVertexHandle::from_index(v)).out_edges() {
                // Between two added vertices, from the lower-index one.
                let to = e.to().fix().index();
                if !e.is_constraint_edge() && e.length_2() > max_len * max_len && (to < first_added || to > v) {
                    splits.push(midpoint(e.from().position(), e.to().position()));
                }
            }
        }
    }
    is_inside.resize(cdt.num_all_faces(), true);
    let inside: Vec<_> = cdt.inner_faces().filter(|f| is_inside[f.fix().index()]).collect();

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
        for v in f.vertices() {
            used[v.fix().index()] = true;
        }
    }
    // A crossing of two outline segments is no vertex of its own: like the reference,
    // it stands for the start of the segment whose insertion created it.
    for (&v, &a) in &crossing {
        map[v] = a;
    }
    let mut points = Vec::with_capacity(cdt.num_vertices());
    points.extend_from_slice(boundary);
    for (i, v) in cdt.vertices().enumerate() {
        if map[i] == usize::MAX && used[i] {
            map[i] = points.len();
            let p = v.position();
            points.push(Vec2::new(p.x, p.y));
        }
    }
    let mut faces: Vec<[usize; 3]> = inside.iter().map(|f| f.vertices().map(|v| map[v.fix().index()])).collect();
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
/// isosceles, as a quality mesher makes them), and blue noise inside that row.
fn interior_points(
    boundary: &[Vec2],
    segments: &[[usize; 2]],
    lines: &[[usize; 2]],
    res: f64,
    max_interior: usize,
) -> Result<(Vec<Vec2>, Vec<Vec2>), String> {
    let (mut lo, mut hi) = (Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY));
    for p in boundary {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    let t = ROW_HEIGHT * res;
    let clearance = t + BOUNDARY_CLEARANCE * res;
    // Row and noise keep clear of the lines as of the outline.
    let constraints: Vec<[usize; 2]> = segments.iter().chain(lines).copied().collect();
    let near = SegmentGrid::new(boundary, &constraints, lo, hi, clearance);
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
    // A noise point is at least `BOUNDARY_CLEARANCE·res` farther from the outline than
    // any row point (a row point is at most `t` from it), so farther than `ROW_SPACING·res`
    // from every row point.
    Ok((row, blue_noise(boundary, segments, &near, res, clearance, [lo, hi], max_interior)?))
}

/// The points of the blue-noise tile, scaled by `res` and repeated over the plane from
/// `lo`, that lie inside the outline (even–odd rule) and at least `clearance` away from
/// it. The plane is cut into bands of [`BAND`]`·res`; where a band's middle line crosses
/// the outline gives the band's inside spans, which hold exactly its points inside the
/// outline that are farther from it than half a band. Memory and time go with the number
/// of points and outline segments, not with the bounding box (a ruffle can be a 3 cm ring
/// of 5 m radius).
fn blue_noise(
    boundary: &[Vec2],
    segments: &[[usize; 2]],
    near: &SegmentGrid,
    res: f64,
    clearance: f64,
    [lo, hi]: [Vec2; 2],
    max_points: usize,
) -> Result<Vec<Vec2>, String> {
    let size = hi - lo;
    let mut points = Vec::new();
    if !(size.x > 2.0 * clearance && size.y > 2.0 * clearance) {
        return Ok(points);
    }
    let tile = noise_tile();
    let (band, side) = (BAND * res, TILE_SIDE * res);
    let bands = (size.y / band).ceil() as usize;
    let band_y = |j: usize| lo.y + (j as f64 + 0.5) * band;
    // Where each band's middle line crosses the outline (a segment crosses the lines
    // within its height: min(y) <= y < max(y)), sorted by band, then x.
    let mut crossings: Vec<(usize, f64)> = Vec::new();
    for &[a, b] in segments {
        let (pa, pb) = (boundary[a], boundary[b]);
        let (y_lo, y_hi) = (pa.y.min(pb.y), pa.y.max(pb.y));
        let first = (((y_lo - lo.y) / band - 0.5).floor().max(0.0) as usize).min(bands);
        for j in first..bands {
            let y = band_y(j);
            if y >= y_hi {
                break;
            }
            if (pa.y <= y) != (pb.y <= y) {
                crossings.push((j, pa.x + (y - pa.y) * (pb.x - pa.x) / (pb.y - pa.y)));
            }
        }
    }
    crossings.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    // A point at least `clearance` from the outline is at least `clearance − band/2`
    // from it along its band's middle line.
    let margin = clearance - band / 2.0;
    let mut at = 0;
    for j in 0..bands {
        let end = at + crossings[at..].iter().take_while(|c| c.0 == j).count();
        let in_tile = &tile.bands[j % tile.bands.len()];
        let y = lo.y + (j / tile.bands.len()) as f64 * side;
        for span in crossings[at..end].chunks_exact(2) {
            let (x0, x1) = (span[0].1 + margin, span[1].1 - margin);
            if x1 < x0 {
                continue;
            }
            // Copies of the tile from column c0 to c1, their points with x in [x0, x1].
            let (c0, c1) = (((x0 - lo.x) / side).floor() as i64, ((x1 - lo.x) / side).floor() as i64);
            for c in c0..=c1 {
                let x = lo.x + c as f64 * side;
                let first = in_tile.partition_point(|q| x + q.x * res < x0);
                for q in in_tile[first..].iter().take_while(|q| x + q.x * res <= x1) {
                    let p = Vec2::new(x, y) + *q * res;
                    if !near.within(p, clearance) {
                        points.push(p);
                    }
                    if points.len() > max_points {
                        return Err(format!("too large to mesh at {res} cm (over {max_points} more vertices)"));
                    }
                }
            }
        }
        at = end;
    }
    Ok(points)
}

/// A square of blue noise (Poisson-disk points: no two closer than `NOISE_DISTANCE`,
/// every spot within about that distance of one), [`TILE_SIDE`] on a side in units of the
/// resolution and periodic, so that copies side by side join seamlessly; its points are
/// cut into bands of [`BAND`], each sorted by x.
struct NoiseTile {
    bands: Vec<Vec<Vec2>>,
}

/// The tile: its points ([`noise_tile::POINTS`], made by dart throwing, see
/// `dart_throwing`) sorted into bands once.
fn noise_tile() -> &'static NoiseTile {
    static TILE: std::sync::OnceLock<NoiseTile> = std::sync::OnceLock::new();
    TILE.get_or_init(|| {
        let side = TILE_SIDE;
        let points = noise_tile::POINTS.iter().map(|&[x, y]| Vec2::new(x, y));
        let n_bands = (side / BAND).round() as usize;
        let mut bands = vec![Vec::new(); n_bands];
        for p in points {
            bands[((p.y / BAND) as usize).min(n_bands - 1)].push(p);
        }
        bands.iter_mut().for_each(|b| b.sort_by(|p, q| p.x.total_cmp(&q.x)));
        NoiseTile { bands }
    })
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

/// Which faces (by index) are inside the outline by the even–odd rule: a face's level is
/// the number of constraints crossed on the way from the outer face (not counting
/// `lines`, which bound nothing); odd levels are inside.
fn inside_faces(cdt: &Cdt, lines: &std::collections::HashSet<[usize; 2]>) -> Vec<bool> {
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
    parity.into_iter().map(|p| p == Some(true)).collect()
}

/// The middle of `a` and `b`.
fn midpoint(a: Point2<f64>, b: Point2<f64>) -> Point2<f64> {
    Point2::new((a.x + b.x) / 2.0, (a.y + b.y) / 2.0)
}

/// A fixed pseudo-random offset of at most 0.1% of `scale` per coordinate, keyed by `a`
/// and `b`. A row over a straight outline is full of cocircular points (isosceles
/// trapezoids): each such test sends the triangulation's exact predicates to their slow
/// arithmetic, which nudged points avoid.
fn nudge(a: u64, b: u64, scale: f64) -> Vec2 {
    (hashed(a, b) - Vec2::splat(0.5)) * 2e-3 * scale
}

/// A fixed pseudo-random point of the unit square, keyed by `a` and `b`.
fn hashed(a: u64, b: u64) -> Vec2 {
    let unit = |salt: u64| {
        let z = a.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ b.wrapping_mul(0xC2B2_AE3D_27D4_EB4F) ^ salt;
        let z = (z ^ (z >> 31)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        (z >> 11) as f64 / (1u64 << 53) as f64
    };
    Vec2::new(unit(1), unit(2))
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

/// Blue noise on the torus of side [`TILE_SIDE`] by dart throwing (Bridson's algorithm)
/// from a fixed seed: points no closer than `NOISE_DISTANCE`, each tried 30 times for a
/// neighbour in the annulus between that distance and twice it. It made
/// [`noise_tile::POINTS`] (a test checks that it still does): the tile is stored, since
/// making it (about 3 ms) costs more than meshing a small garment.
#[cfg(test)]
fn dart_throwing() -> Vec<Vec2> {
    let (side, r) = (TILE_SIDE, NOISE_DISTANCE);
    // Background grid of cells r/√2 (at most one point each), on the torus.
    let n = (side / (r / 2f64.sqrt())).floor() as usize;
    let cell = side / n as f64;
    let mut cells: Vec<Option<Vec2>> = vec![None; n * n];
    let cell_of = |p: Vec2| ((p.x / cell) as usize % n, (p.y / cell) as usize % n);
    // The cell `i − 2` on the torus, for `i` in `0..n + 4`; the shortest offset on the torus.
    let around: Vec<usize> = (0..n + 4).map(|i| (i + n - 2) % n).collect();
    let wrap = |d: f64| {
        if d > side / 2.0 {
            d - side
        } else if d < -side / 2.0 {
            d + side
        } else {
            d
        }
    };
    let mut draws = 0u64;
    let mut random = || {
        draws += 1;
        hashed(draws, 0x5EED)
    };
    let first = random() * side;
    let mut points = vec![first];
    let (c, r0) = cell_of(first);
    cells[r0 * n + c] = Some(first);
    let mut active = vec![0usize];
    while !active.is_empty() {
        let pick = ((random().x * active.len() as f64) as usize).min(active.len() - 1);
        let centre = points[active[pick]];
        let found = (0..30).find_map(|_| {
            // A candidate in the annulus between r and 2r around the centre.
            let u = random();
            let (radius, angle) = (r * (1.0 + 3.0 * u.x).sqrt(), std::f64::consts::TAU * u.y);
            let q = centre + Vec2::new(radius * angle.cos(), radius * angle.sin());
            let q = Vec2::new(q.x.rem_euclid(side), q.y.rem_euclid(side));
            let (cx, cy) = cell_of(q);
            let free = around[cy..cy + 5].iter().all(|&row| {
                around[cx..cx + 5].iter().all(|&column| {
                    cells[row * n + column].is_none_or(|p| Vec2::new(wrap(p.x - q.x), wrap(p.y - q.y)).length_squared() >= r * r)
                })
            });
            free.then_some((q, cx, cy))
        });
        match found {
            Some((q, cx, cy)) => {
                cells[cy * n + cx] = Some(q);
                active.push(points.len());
                points.push(q);
            }
            None => {
                active.swap_remove(pick);
            }
        }
    }
    points
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

    /// Edge directions of the inside edges not on the outline, counted in 12 bins of 15°.
    fn direction_histogram(t: &PanelTriangulation, n_boundary: usize) -> [usize; 12] {
        let mut bins = [0; 12];
        for f in &t.faces {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                if a < b && (a >= n_boundary || b >= n_boundary) {
                    let d = t.points[b] - t.points[a];
                    let angle = d.y.atan2(d.x).rem_euclid(std::f64::consts::PI).to_degrees();
                    bins[((angle / 15.0) as usize).min(11)] += 1;
                }
            }
        }
        bins
    }

    /// The interior is irregular, as the reference's Delaunay refinement makes it: no
    /// direction is favoured (a lattice puts nearly every edge in three directions, along
    /// which the cloth folds like a hinge), and no edge exceeds the size bound.
    #[test]
    fn interior_edges_run_in_every_direction() {
        let (pts, segs) = square(40, 40.0);
        let t = triangulate(&pts, &segs, &[], 1.0, 100_000).unwrap();
        let bins = direction_histogram(&t, pts.len());
        let (least, most) = (*bins.iter().min().unwrap(), *bins.iter().max().unwrap());
        assert!(most as f64 <= 1.6 * least as f64, "edge directions by 15°: {bins:?}");
        // About the reference's density: 2/√3 points per res² (an equilateral mesh of edge res).
        let density = (t.points.len() - pts.len()) as f64 / 1600.0;
        assert!((1.0..1.3).contains(&density), "{density} points per cm²");
    }

    /// The noise tile is a Poisson-disk set on the torus: no two points closer than
    /// `NOISE_DISTANCE`, and no empty spot farther than twice that from every point.
    #[test]
    fn the_noise_tile_is_blue_noise() {
        let points: Vec<Vec2> = noise_tile().bands.iter().flatten().copied().collect();
        let wrap = |d: f64| d - TILE_SIDE * (d / TILE_SIDE).round();
        let dist = |p: Vec2, q: Vec2| Vec2::new(wrap(p.x - q.x), wrap(p.y - q.y)).length();
        for (i, p) in points.iter().enumerate() {
            for q in &points[i + 1..] {
                assert!(dist(*p, *q) >= NOISE_DISTANCE, "{p:?} {q:?}");
            }
        }
        for k in 0..48 * 48 {
            let spot = Vec2::new((k % 48) as f64, (k / 48) as f64) * (TILE_SIDE / 48.0);
            assert!(points.iter().any(|p| dist(*p, spot) < 2.0 * NOISE_DISTANCE), "{spot:?}");
        }
    }

    /// The stored tile is what the dart throwing makes, bit for bit.
    #[test]
    fn the_stored_tile_is_the_dart_throwings() {
        let made: Vec<[u64; 2]> = dart_throwing().iter().map(|p| [p.x.to_bits(), p.y.to_bits()]).collect();
        let stored: Vec<[u64; 2]> = noise_tile::POINTS.iter().map(|p| p.map(f64::to_bits)).collect();
        assert_eq!(made, stored);
    }
}
