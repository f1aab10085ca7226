//! Reference parity: outlines made of SVG segments, handled the way svgpathtools 1.8.0 handles a
//! `Path`, and the reference's split of closed outlines into the halves on either
//! side of their vertical centre line (pygarment's `halfs_from_svg`), used by
//! decorative cuts drawn from an SVG picture.
//!
//! A path parameter `T ∈ [0, 1]` maps to a segment and its own parameter through
//! the segments' shares of the total arc length, as in the library; lengths are
//! exact to ~1e-13, so crossings and crops land where the reference's do.

use super::segment::{P, Seg, try_intersect};
use crate::arena::{Arena, EdgeSeq, VertexId};
use crate::bezier::Bezier;
use crate::edge::{Curve, Edge};
use crate::error::{Error, Result};
use crate::math::{Vec2, abs_to_rel};

/// A sequence of segments (svgpathtools' `Path`).
#[derive(Clone, Debug, PartialEq)]
pub struct SvgPath(pub Vec<Seg>);

/// A crossing of a path: path parameter `T`, segment index and segment parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Path parameter `T`.
    pub at: f64,
    /// Index of the segment.
    pub seg: usize,
    /// Parameter on the segment.
    pub t: f64,
}

fn v(p: P) -> Vec2 {
    Vec2::new(p[0], p[1])
}

/// Arc length of a segment (exact for lines, ~1e-13 for curves).
pub fn seg_length(s: &Seg) -> f64 {
    match *s {
        Seg::Line([a, b]) => (b[0] - a[0]).hypot(b[1] - a[1]),
        Seg::Quad([a, b, c]) => Bezier::Quadratic([v(a), v(b), v(c)]).length(),
        Seg::Cubic([a, b, c, d]) => Bezier::Cubic([v(a), v(b), v(c), v(d)]).length(),
    }
}

/// `numpy.isclose(a, b)` with its default tolerances.
fn np_isclose(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-8 + 1e-5 * b.abs()
}

fn geometry(msg: impl std::fmt::Display) -> Error {
    Error::Geometry(format!("svg path: {msg}"))
}

impl SvgPath {
    /// Bounding box of the curves: `[xmin, xmax, ymin, ymax]`.
    pub fn bbox(&self) -> [f64; 4] {
        bbox_of(self.0.iter().map(Seg::bbox))
    }

    /// Scaled about the origin; where a segment ended exactly at the next one's
    /// start, it still does (`transform_segments_together`; the closing joint is
    /// not looked at).
    pub fn scaled(&self, s: f64) -> SvgPath {
        let mut out: Vec<Seg> = self.0.iter().map(|g| g.scaled(s)).collect();
        for i in 0..self.0.len().saturating_sub(1) {
            if self.0[i].end() == self.0[i + 1].start() {
                out[i] = out[i].with_end(out[i + 1].start());
            }
        }
        SvgPath(out)
    }

    /// Each segment's share of the total length (`_lengths`).
    fn shares(&self) -> Vec<f64> {
        let lengths: Vec<f64> = self.0.iter().map(seg_length).collect();
        let total: f64 = lengths.iter().sum();
        if total == 0.0 { lengths } else { lengths.iter().map(|l| l / total).collect() }
    }

    /// Index of the first segment equal to segment `i` (the library looks
    /// segments up by value).
    fn index_of(&self, i: usize) -> usize {
        self.0.iter().position(|s| *s == self.0[i]).unwrap_or(i)
    }

    /// Path parameter of parameter `t` on segment `i` (`t2T`).
    fn path_param(&self, shares: &[f64], i: usize, t: f64) -> f64 {
        let start: f64 = shares[..i].iter().sum();
        let end = start + shares[i];
        (end - start) * t + start
    }

    /// Segment and segment parameter of the path parameter `T` (`T2t`).
    fn seg_param(&self, shares: &[f64], at: f64) -> Result<(usize, f64)> {
        if at == 1.0 {
            return Ok((self.0.len() - 1, 1.0));
        }
        if at == 0.0 {
            return Ok((0, 0.0));
        }
        let mut t0 = 0.0;
        for (i, &share) in shares.iter().enumerate() {
            let t1 = t0 + share;
            if t1 >= at {
                if share == 0.0 {
                    return Err(geometry("path parameter on a segment of zero length"));
                }
                return Ok((i, (at - t0) / share));
            }
            t0 = t1;
        }
        Err(geometry(format!("path parameter {at} beyond the path")))
    }

    /// Crossings with a segment (`Path.intersect`), in the order of the path's
    /// segments; a crossing repeated at a joint (within 1e-12) is kept once.
    pub fn intersect(&self, other: &Seg) -> Result<Vec<Crossing>> {
        let shares = self.shares();
        let mut found = Vec::new();
        for (i, seg) in self.0.iter().enumerate() {
            for (t, _) in try_intersect(seg, other).map_err(geometry)? {
                found.push(Crossing { at: self.path_param(&shares, self.index_of(i), t), seg: i, t });
            }
        }
        let pts: Vec<P> = found.iter().map(|c| self.0[c.seg].point(c.t)).collect();
        let mut dup = vec![false; found.len()];
        for i in 0..pts.len() {
            for j in i + 1..pts.len() {
                if (pts[i][0] - pts[j][0]).hypot(pts[i][1] - pts[j][1]) < 1e-12 {
                    dup[j] = true;
                }
            }
        }
        Ok(found.into_iter().zip(dup).filter(|(_, d)| !d).map(|(c, _)| c).collect())
    }

    /// The piece between the path parameters `from < to` (`cropped`; the
    /// library's other cases, which wrap around a closed path, are not needed here).
    pub fn cropped(&self, from: f64, to: f64) -> Result<SvgPath> {
        if !(0.0 <= from && from < to && to <= 1.0) {
            return Err(geometry(format!("cannot crop a path to [{from}, {to}]")));
        }
        let n = self.0.len();
        let shares = self.shares();
        let (i1, t1) = if to == 1.0 {
            (n - 1, 1.0)
        } else {
            let (i, t) = self.seg_param(&shares, to)?;
            // An end at the very start of a segment is the end of the previous one.
            if np_isclose(t, 0.0) { ((self.index_of(i) + n - 1) % n, 1.0) } else { (self.index_of(i), t) }
        };
        let (i0, t0) = if from == 0.0 {
            (0, 0.0)
        } else {
            let (i, t) = self.seg_param(&shares, from)?;
            // `isclose(t, 1)` is relative: anything within 1e-5 of the end moves on.
            if np_isclose(t, 1.0) { ((self.index_of(i) + 1) % n, 0.0) } else { (self.index_of(i), t) }
        };
        let crop = |i: usize, a: f64, b: f64| -> Result<Seg> {
            if a < b || matches!(self.0[i], Seg::Line(_)) {
                Ok(self.0[i].cropped(a, b))
            } else {
                Err(geometry(format!("cannot crop a curve to [{a}, {b}]")))
            }
        };
        if i0 == i1 {
            return Ok(SvgPath(vec![crop(i0, t0, t1)?]));
        }
        let mut out = vec![crop(i0, t0, 1.0)?];
        out.extend(self.0.iter().take(i1).skip(i0 + 1).copied());
        if t1 != 0.0 {
            out.push(crop(i1, 0.0, t1)?);
        }
        Ok(SvgPath(out))
    }
}

fn bbox_of(boxes: impl Iterator<Item = [f64; 4]>) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY];
    for x in boxes {
        b = [b[0].min(x[0]), b[1].max(x[1]), b[2].min(x[2]), b[3].max(x[3])];
    }
    b
}

/// Bounding box of several paths.
pub fn bbox_paths(paths: &[SvgPath]) -> [f64; 4] {
    bbox_of(paths.iter().map(SvgPath::bbox))
}

/// Each closed path cut by the vertical line through the middle of the paths'
/// common bounding box into a "left" and a "right" part (`split_half_svg_paths`;
/// see the quirk inside for which is which). Every path must cross that line
/// exactly twice. One part runs between the crossings, the other from the
/// second crossing on through the path's start to the first one.
pub fn split_halves(paths: &[SvgPath]) -> Result<(Vec<SvgPath>, Vec<SvgPath>)> {
    let bbox = bbox_paths(paths);
    let center_x = (bbox[0] + bbox[1]) / 2.0;
    let line = Seg::Line([[center_x, bbox[2]], [center_x, bbox[3]]]);
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for p in paths {
        let hits = p.intersect(&line)?;
        if hits.len() != 2 {
            return Err(geometry(format!("an outline crosses its vertical middle line {} times, not twice", hits.len())));
        }
        let (mut from, mut to) = (hits[0].at, hits[1].at);
        if to < from {
            std::mem::swap(&mut from, &mut to);
        }
        let mut side_1 = p.cropped(from, to)?;
        let mut side_2 = p.cropped(to, 1.0)?;
        side_2.0.extend(p.cropped(0.0, from)?.0);
        // QUIRK: the reference tells the halves apart by comparing the part's
        // bbox()[2], its *lowest y*, with the middle x. For the SIGGRAPH logo this
        // consistently files the parts lying right of the middle line under
        // "left" and those left of it under "right".
        if side_1.bbox()[2] > center_x {
            std::mem::swap(&mut side_1, &mut side_2);
        }
        right.push(side_2);
        left.push(side_1);
    }
    Ok((left, right))
}

/// A chain of edges from a path (`from_svg_path`): segments shorter than
/// `dist_tol` are left out, and every edge starts where the previous one ends
/// (each start must lie within `dist_tol` of that end in both coordinates). The
/// curves keep their shape relative to their chords.
pub fn edge_seq_from_path(a: &mut Arena, path: &SvgPath, dist_tol: f64) -> Result<EdgeSeq> {
    let mut out = EdgeSeq::new();
    let mut prev_end: Option<(VertexId, Vec2)> = None;
    for seg in &path.0 {
        if seg_length(seg).abs() < dist_tol {
            continue;
        }
        let (start, end) = (v(seg.start()), v(seg.end()));
        let curve = match *seg {
            Seg::Line(_) => Curve::Line,
            Seg::Quad([_, c, _]) => Curve::Quadratic(abs_to_rel(start, end, v(c))),
            Seg::Cubic([_, c1, c2, _]) => Curve::Cubic(abs_to_rel(start, end, v(c1)), abs_to_rel(start, end, v(c2))),
        };
        let e = match prev_end {
            None => a.add_edge(Edge { start, end, curve })?,
            Some((vert, pos)) => {
                if (start.x - pos.x).abs() >= dist_tol || (start.y - pos.y).abs() >= dist_tol {
                    return Err(geometry("the outline is not chained"));
                }
                crate::arena::check_distinct(start, end)?;
                let end_v = a.vertex(end);
                a.edge(vert, end_v, curve)?
            }
        };
        prev_end = Some((a.end(e), end));
        out.push(e);
    }
    Ok(out)
}

/// Closed outlines drawn in SVG coordinates (y down) turned into the chains of a
/// decorative cut, split down the middle (`halfs_from_svg`): scaled to
/// `target_height` (about the origin), split into left and right halves, each half
/// made a chain of edges (segments shorter than 0.05 left out), mirrored so that y
/// points up, and turned so that its opening runs upward.
pub fn halves_from_outlines(a: &mut Arena, outlines: &[SvgPath], target_height: Option<f64>) -> Result<(Vec<EdgeSeq>, Vec<EdgeSeq>)> {
    let paths: Vec<SvgPath> = match target_height {
        Some(h) => {
            let bbox = bbox_paths(outlines);
            let scale = h / (bbox[3] - bbox[2]);
            outlines.iter().map(|p| p.scaled(scale)).collect()
        }
        None => outlines.to_vec(),
    };
    let (left, right) = split_halves(&paths)?;
    let bbox = bbox_paths(&paths);
    let center_y = (bbox[2] + bbox[3]) / 2.0;
    let mut convert = |halves: &[SvgPath]| -> Result<Vec<EdgeSeq>> {
        let mut out = Vec::with_capacity(halves.len());
        for h in halves {
            let mut seq = edge_seq_from_path(a, h, 0.05)?;
            if seq.is_empty() {
                return Err(geometry("an outline half is shorter than 0.05"));
            }
            seq.reflect(a, Vec2::new(bbox[0], center_y), Vec2::new(bbox[1], center_y));
            let (s, e) = seq.shortcut(a);
            if e.y - s.y < 0.0 {
                seq.reverse(a);
            }
            out.push(seq);
        }
        Ok(out)
    };
    let l = convert(&left)?;
    let r = convert(&right)?;
    Ok((l, r))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(pts: &[P]) -> SvgPath {
        SvgPath(pts.windows(2).map(|w| Seg::Line([w[0], w[1]])).collect())
    }

    fn square() -> SvgPath {
        lines(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 0.0]])
    }

    #[test]
    fn crossings_and_crops_use_length_shares() {
        let sq = square();
        let hits = sq.intersect(&Seg::Line([[1.0, 0.0], [1.0, 2.0]])).unwrap();
        let at: Vec<(f64, usize, f64)> = hits.iter().map(|c| (c.at, c.seg, c.t)).collect();
        assert_eq!(at, vec![(0.125, 0, 0.5), (0.625, 2, 0.5)]);
        let mid = sq.cropped(0.125, 0.625).unwrap();
        assert_eq!(mid, lines(&[[1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 2.0]]));
        // A crop ending at a joint ends with the segment before it.
        assert_eq!(sq.cropped(0.0, 0.5).unwrap(), lines(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]]));
        assert!(sq.cropped(0.5, 0.5).is_err());
    }

    #[test]
    fn cubic_crop_and_scale_keep_the_curve() {
        let c = Seg::Cubic([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]);
        let piece = c.cropped(0.25, 0.75);
        for k in 0..=4 {
            let u = k as f64 / 4.0;
            let (p, q) = (piece.point(u), c.point(0.25 + 0.5 * u));
            assert!((p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12);
        }
        let s = c.scaled(2.5);
        for (p, q) in s.points().iter().zip(c.points()) {
            assert!((p[0] - 2.5 * q[0]).abs() < 1e-12 && (p[1] - 2.5 * q[1]).abs() < 1e-12);
        }
        assert_eq!(c.bbox(), [0.0, 4.0, 0.0, 1.5]);
    }

    #[test]
    fn square_splits_into_two_upward_chains() {
        let mut a = Arena::new();
        let (left, right) = halves_from_outlines(&mut a, &[square()], Some(4.0)).unwrap();
        assert_eq!((left.len(), right.len()), (1, 1));
        // "Left" is the part right of the middle line (the reference's quirk).
        assert_eq!(left[0].vert_positions(&a), vec![Vec2::new(2.0, 0.0), Vec2::new(4.0, 0.0), Vec2::new(4.0, 4.0), Vec2::new(2.0, 4.0)]);
        assert_eq!(right[0].vert_positions(&a), vec![Vec2::new(2.0, 0.0), Vec2::new(0.0, 0.0), Vec2::new(0.0, 4.0), Vec2::new(2.0, 4.0)]);
        assert!(left[0].is_chained(&a) && right[0].is_chained(&a));
    }

    #[test]
    fn short_segments_are_left_out_and_the_chain_closed_over_them() {
        let mut a = Arena::new();
        let p = lines(&[[0.0, 0.0], [1.0, 0.0], [1.03, 0.0], [1.03, 1.0]]);
        let seq = edge_seq_from_path(&mut a, &p, 0.05).unwrap();
        assert_eq!(seq.len(), 2);
        assert!(seq.is_chained(&a));
        assert_eq!(seq.vert_positions(&a), vec![Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.03, 1.0)]);
        let gap = lines(&[[0.0, 0.0], [1.0, 0.0], [1.2, 0.0], [1.2, 1.0]]);
        assert!(edge_seq_from_path(&mut a, &gap, 0.05).is_ok());
        let broken = SvgPath(vec![Seg::Line([[0.0, 0.0], [1.0, 0.0]]), Seg::Line([[1.2, 0.0], [1.2, 1.0]])]);
        assert!(edge_seq_from_path(&mut a, &broken, 0.05).is_err());
    }

    #[test]
    fn an_outline_must_cross_the_middle_twice() {
        // A crossing at a joint of two segments counts once.
        let w = lines(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.5], [3.0, 2.0], [4.0, 0.0], [0.0, 0.0]]);
        let line = Seg::Line([[2.0, 0.0], [2.0, 2.0]]);
        assert_eq!(w.intersect(&line).unwrap().len(), 2);
        assert!(split_halves(&[w]).is_ok());
        // A "C" opening to the right crosses its middle line four times.
        let c = lines(&[[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [1.0, 1.0], [1.0, 2.0], [4.0, 2.0], [4.0, 3.0], [0.0, 3.0], [0.0, 0.0]]);
        assert!(split_halves(&[c]).is_err());
    }
}
