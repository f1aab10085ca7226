//! Refined constrained Delaunay triangulation of one panel (by `spade`).
//!
//! The sampled outline is the constraint set; refinement never splits a constraint,
//! so the boundary stays exactly the sampled polyline. Inside is the even–odd rule
//! across constraints (a doubly covered region of a self-crossing outline is outside).
//! After `spade`'s quality refinement (minimum angle ≈ 20.7°, an area bound) the
//! remaining inside edges longer than the size bound are split at their midpoints and
//! the mesh is refined again, so every inside edge ends up at most `1.43·res` long
//! (the reference mesher's size criterion).

use std::collections::{HashMap, VecDeque};

use spade::handles::{FixedFaceHandle, InnerTag};
use spade::{AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation};

use crate::Vec2;

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;
type VertexHandle<'a> = spade::handles::VertexHandle<'a, Point2<f64>, (), spade::CdtEdge<()>, ()>;

/// Size bound of triangle edges, in units of the resolution.
pub const SIZE_BOUND: f64 = 1.43;

/// A triangulated panel.
#[derive(Clone, Debug)]
pub(crate) struct PanelTriangulation {
    /// The boundary points as given, then points the triangulation added (crossing
    /// points of a self-crossing outline and interior points), in insertion order.
    pub points: Vec<Vec2>,
    /// Counter-clockwise index triples of the inside triangles.
    pub faces: Vec<[usize; 3]>,
}

/// Triangulates the region bounded by `segments` between `boundary` points.
pub(crate) fn triangulate(boundary: &[Vec2], segments: &[[usize; 2]], res: f64) -> Result<PanelTriangulation, String> {
    let mut cdt = Cdt::new();
    let mut handle = Vec::with_capacity(boundary.len());
    for p in boundary {
        let h = cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("point ({}, {}) cannot be triangulated: {e:?}", p.x, p.y))?;
        handle.push(h);
    }
    let mut crossing = add_outline(&mut cdt, &handle, segments);
    let max_len = SIZE_BOUND * res;
    // Area of an equilateral triangle somewhat below the size bound: CGAL's size
    // criterion yields triangles of about this size.
    let max_area = 3f64.sqrt() / 4.0 * (0.85 * max_len).powi(2);
    let region = bbox_area(boundary);
    let budget = (8.0 * region / (res * res)) as usize + 10 * boundary.len() + 1000;
    let params = || {
        RefinementParameters::<f64>::new()
            .with_angle_limit(AngleLimit::from_radius_to_shortest_edge_ratio(2f64.sqrt()))
            .with_max_allowed_area(max_area)
            .exclude_outer_faces(true)
            .with_max_additional_vertices(budget)
    };
    cdt.refine(params());
    for _ in 0..8 {
        let inside = inside_faces(&cdt);
        let mut splits: Vec<Point2<f64>> = Vec::new();
        for f in &inside {
            for e in cdt.face(*f).adjacent_edges() {
                if e.is_constraint_edge() || e.length_2() <= max_len * max_len {
                    continue;
                }
                // Each undirected edge once: from its lower-index end.
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
        if cdt.num_vertices() + splits.len() > boundary.len() + 2 * budget {
            return Err("triangulation exceeds its size budget".into());
        }
        for p in splits {
            cdt.insert(p).map_err(|e| format!("refinement point cannot be inserted: {e:?}"))?;
        }
        cdt.refine(params());
    }

    // Points the refinement put on the outline (on a constraint) are dropped and the
    // panel triangulated afresh from the outline and the interior points.
    let is_input = {
        let mut v = vec![false; cdt.num_vertices()];
        handle.iter().for_each(|h| v[h.index()] = true);
        v
    };
    // On the outline: an end of a constraint, or within 1% of the resolution of a
    // constraint edge opposite to it in one of its triangles.
    let eps = 0.01 * res;
    let on_outline = |v: VertexHandle| {
        v.out_edges().any(|e| {
            if e.is_constraint_edge() {
                return true;
            }
            let opposite = e.next();
            !e.face().is_outer() && opposite.is_constraint_edge() && {
                let [a, b] = [opposite.from().position(), opposite.to().position()];
                segment_distance(v.position(), a, b) < eps
            }
        })
    };
    if cdt.vertices().any(|v| !is_input[v.fix().index()] && on_outline(v)) {
        let inside = inside_faces(&cdt);
        let mut used = vec![false; cdt.num_vertices()];
        for f in &inside {
            for v in cdt.face(*f).vertices() {
                used[v.fix().index()] = true;
            }
        }
        let interior: Vec<Point2<f64>> = cdt
            .vertices()
            .filter(|v| used[v.fix().index()] && !is_input[v.fix().index()] && !on_outline(*v))
            .map(|v| v.position())
            .collect();
        let distinct = handle.iter().enumerate().all(|(i, h)| h.index() == i);
        if crossing.is_empty() && distinct {
            // Outline without crossings or repeated points: bulk loading keeps the vertex order.
            let mut all: Vec<Point2<f64>> = boundary.iter().map(|p| Point2::new(p.x, p.y)).collect();
            all.extend(interior);
            let edges: Vec<[usize; 2]> = segments.iter().copied().filter(|[a, b]| a != b).collect();
            cdt = Cdt::bulk_load_cdt(all, edges).map_err(|e| format!("panel cannot be triangulated: {e:?}"))?;
        } else {
            cdt = Cdt::new();
            handle.clear();
            for p in boundary {
                handle.push(cdt.insert(Point2::new(p.x, p.y)).map_err(|e| format!("point cannot be triangulated: {e:?}"))?);
            }
            crossing = add_outline(&mut cdt, &handle, segments);
            for p in interior {
                cdt.insert(p).map_err(|e| format!("interior point cannot be inserted: {e:?}"))?;
            }
        }
    }

    let inside = inside_faces(&cdt);
    // Spade vertex index → output index: boundary vertices keep theirs, added vertices
    // used by inside faces are numbered after them in insertion order.
    let mut map: Vec<usize> = vec![usize::MAX; cdt.num_vertices()];
    for (i, h) in handle.iter().enumerate() {
        if map[h.index()] == usize::MAX {
            map[h.index()] = i;
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
    let mut points = boundary.to_vec();
    for (i, v) in cdt.vertices().enumerate() {
        if map[i] == usize::MAX && used[i] {
            map[i] = points.len();
            let p = v.position();
            points.push(Vec2::new(p.x, p.y));
        }
    }
    let mut seen = std::collections::HashSet::new();
    let faces = inside
        .iter()
        .map(|f| cdt.face(*f).vertices().map(|v| map[v.fix().index()]))
        .filter(|[a, b, c]| a != b && b != c && a != c)
        .filter(|f| {
            let mut key = *f;
            key.sort_unstable();
            seen.insert(key)
        })
        .collect();
    Ok(PanelTriangulation { points, faces })
}

/// Adds the outline segments as constraints, splitting crossing ones; returns the
/// vertices created at crossings, each with the local id of the segment start that
/// created it.
fn add_outline(cdt: &mut Cdt, handle: &[spade::handles::FixedVertexHandle], segments: &[[usize; 2]]) -> HashMap<usize, usize> {
    let mut crossing = HashMap::new();
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
/// constraints crossed on the way from the outer face; odd levels are inside.
fn inside_faces(cdt: &Cdt) -> Vec<FixedFaceHandle<InnerTag>> {
    let n = cdt.num_all_faces();
    let mut parity: Vec<Option<bool>> = vec![None; n];
    let mut queue = VecDeque::new();
    for e in cdt.convex_hull() {
        for d in [e, e.rev()] {
            if let Some(f) = d.face().as_inner() {
                let odd = d.is_constraint_edge();
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
                    parity[g.fix().index()] = Some(odd ^ e.is_constraint_edge());
                    queue.push_back(g.fix());
                }
            }
        }
    }
    cdt.inner_faces().filter(|f| parity[f.fix().index()] == Some(true)).map(|f| f.fix()).collect()
}

/// Distance of `p` to the segment `a b`.
fn segment_distance(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    let (p, a, b) = (Vec2::new(p.x, p.y), Vec2::new(a.x, a.y), Vec2::new(b.x, b.y));
    let d = b - a;
    let t = if d.length_squared() > 0.0 { ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + t * d)).length()
}

fn bbox_area(points: &[Vec2]) -> f64 {
    let (mut lo, mut hi) = (Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY));
    for p in points {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    ((hi - lo).x * (hi - lo).y).max(0.0)
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
        let t = triangulate(&pts, &segs, 1.0).unwrap();
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
