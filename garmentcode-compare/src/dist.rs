//! Point-set distances (`SegGrid`, `directed`, `hausdorff`, `_fast_pointwise`).
//!
//! The early exits (400 far points, `stop_above`) make the result a lower bound in failing
//! cases, and that bound appears in reasons and max_dev, so the visiting order and the grid
//! are the script's. 2D polylines are handled as 3D with z = 0, which gives bit-identical
//! sums (x + y + 0 == x + y) and a single grid layer.

use super::geom::{P2, P3, PanelGeom, dist2, dist3};
use super::py;
use std::collections::HashMap;

pub const FAST_SAMPLES_LINE: usize = 4;
pub const FAST_SAMPLES_CURVE: usize = 32;
const MAX_CELLS_PER_AXIS: i64 = 8;

/// Distance from p to segment ab (`_seg_dist`).
#[inline]
fn seg_dist(p: P3, a: P3, b: P3) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let den = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let t = if den == 0.0 { 0.0 } else { py::max(0.0, py::min(1.0, (ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2]) / den)) };
    (py::sq(ap[0] - t * ab[0]) + py::sq(ap[1] - t * ab[1]) + py::sq(ap[2] - t * ab[2])).sqrt()
}

#[inline]
fn cell_of(x: f64, cell: f64) -> i64 {
    (x / cell).floor() as i64
}

/// Uniform grid over short segments for nearest-segment queries.
pub struct SegGrid {
    pub cell: f64,
    segs: Vec<(P3, P3)>,
    grid: HashMap<(i64, i64, i64), Vec<usize>>,
    /// segments too long for the grid: checked on every query
    oversize: Vec<usize>,
}

impl SegGrid {
    pub fn new(polylines: &[Vec<P3>], cell: f64) -> SegGrid {
        let mut g = SegGrid { cell, segs: Vec::new(), grid: HashMap::new(), oversize: Vec::new() };
        for pl in polylines {
            for i in 0..pl.len().saturating_sub(1) {
                let (a, b) = (pl[i], pl[i + 1]);
                let k = g.segs.len();
                g.segs.push((a, b));
                let lo: [i64; 3] = std::array::from_fn(|j| cell_of(py::min(a[j], b[j]), cell));
                let hi: [i64; 3] = std::array::from_fn(|j| cell_of(py::max(a[j], b[j]), cell));
                if (0..3).any(|j| hi[j] - lo[j] >= MAX_CELLS_PER_AXIS) {
                    g.oversize.push(k);
                    continue;
                }
                for x in lo[0]..=hi[0] {
                    for y in lo[1]..=hi[1] {
                        for z in lo[2]..=hi[2] {
                            g.grid.entry((x, y, z)).or_default().push(k);
                        }
                    }
                }
            }
        }
        g
    }

    /// Nearest distance from p to the segments: exact when within one cell (the 3x3x3
    /// neighbourhood then holds the nearest segment), brute force otherwise.
    pub fn nearest(&self, p: P3) -> f64 {
        let c: [i64; 3] = std::array::from_fn(|j| cell_of(p[j], self.cell));
        let mut best = f64::INFINITY;
        for x in c[0] - 1..=c[0] + 1 {
            for y in c[1] - 1..=c[1] + 1 {
                for z in c[2] - 1..=c[2] + 1 {
                    if let Some(ks) = self.grid.get(&(x, y, z)) {
                        for &k in ks {
                            let (a, b) = self.segs[k];
                            let d = seg_dist(p, a, b);
                            if d < best {
                                best = d;
                            }
                        }
                    }
                }
            }
        }
        for &k in &self.oversize {
            let (a, b) = self.segs[k];
            let d = seg_dist(p, a, b);
            if d < best {
                best = d;
            }
        }
        if best <= self.cell {
            return best;
        }
        // far away: exact brute force (Python's min(): first minimum wins)
        let mut it = self.segs.iter().map(|&(a, b)| seg_dist(p, a, b));
        let first = it.next().unwrap_or(f64::INFINITY);
        it.fold(first, py::min)
    }
}

fn directed<'a>(points: impl Iterator<Item = &'a P3>, grid: &SegGrid, max_far: Option<usize>, stop_above: Option<f64>) -> f64 {
    let mut worst = 0.0;
    let mut far = 0;
    for &p in points {
        let d = grid.nearest(p);
        if d > worst {
            worst = d;
            if stop_above.is_some_and(|s| d > s) {
                break; // verdict known
            }
        }
        if d > grid.cell {
            far += 1;
            if max_far.is_some_and(|m| far > m) {
                break; // clearly failing; enough evidence
            }
        }
    }
    worst
}

/// Symmetric Hausdorff distance of two sets of polylines. Unless exact, gives up
/// (returning a lower bound that is > cell) once 400 points are farther than cell.
/// With stop_above, returns a lower bound as soon as the distance is known to exceed it.
pub fn hausdorff(a: &[Vec<P3>], b: &[Vec<P3>], cell: f64, exact: bool, stop_above: Option<f64>) -> f64 {
    let (ga, gb) = (SegGrid::new(a, cell), SegGrid::new(b, cell));
    let mf = if exact { None } else { Some(400) };
    let d = directed(a.iter().flatten(), &gb, mf, stop_above);
    if stop_above.is_some_and(|s| d > s) {
        return d;
    }
    py::max(d, directed(b.iter().flatten(), &ga, mf, stop_above))
}

pub fn lift(polys: &[Vec<P2>]) -> Vec<Vec<P3>> {
    polys.iter().map(|pl| pl.iter().map(|p| [p[0], p[1], 0.0]).collect()).collect()
}

/// Try to find an edge-to-edge correspondence (cyclic shift, maybe reversed).
/// Returns (dev2d, dev3d) upper bounds of the Hausdorff distances, or None.
pub fn fast_pointwise(pe: &PanelGeom, pa: &PanelGeom) -> Option<(f64, f64)> {
    let n = pe.edges.len();
    if n != pa.edges.len() {
        return None;
    }
    let mut best: Option<(f64, f64)> = None;
    let maxb = |b: (f64, f64)| py::max(b.0, b.1);
    let s0 = pe.edges[0].s;
    for rev in [false, true] {
        let seq: Vec<&_> = if rev { pa.edges.iter().rev().collect() } else { pa.edges.iter().collect() };
        for k in 0..n {
            let cand = seq[k];
            let cs = if rev { cand.e } else { cand.s };
            if let Some(b) = best {
                if dist2(s0, cs) >= b.0 {
                    continue;
                }
            }
            let (mut dev2, mut dev3) = (0.0f64, 0.0f64);
            let mut ok = true;
            for i in 0..n {
                let ee = &pe.edges[i];
                let ea = seq[(k + i) % n];
                let m = if ee.kind == super::geom::Kind::Line && ea.kind == super::geom::Kind::Line {
                    FAST_SAMPLES_LINE
                } else {
                    FAST_SAMPLES_CURVE
                };
                for q in 0..=m {
                    let t = q as f64 / m as f64;
                    let p1 = ee.point(t);
                    let p2 = ea.point(if rev { 1.0 - t } else { t });
                    let d2 = dist2(p1, p2);
                    let d3 = dist3(pe.to3d(p1), pa.to3d(p2));
                    if d2 > dev2 {
                        dev2 = d2;
                    }
                    if d3 > dev3 {
                        dev3 = d3;
                    }
                }
                if let Some(b) = best {
                    if py::max(dev2, dev3) >= maxb(b) {
                        ok = false;
                        break;
                    }
                }
            }
            if ok && best.is_none_or(|b| py::max(dev2, dev3) < maxb(b)) {
                best = Some((dev2, dev3));
            }
        }
    }
    best
}
