//! Edge sequences: ordered lists of edges, usually chained (each edge starts where the
//! previous one ends), with the list operations and geometric transforms garment
//! programs use.
//!
//! "Chained" and "loop" are decided by vertex identity, not by coordinates, exactly as
//! in the reference; a sequence is a list of edge ids, so slicing or copying the list
//! never copies geometry (use [`EdgeSeq::copy`] for that).

use crate::arena::{Arena, EdgeId, EdgeSeq, VertexId};
use crate::edge::Curve;
use crate::error::{Error, Result};
use crate::math::{Vec2, norm, rotate2d};

impl EdgeSeq {
    /// An empty sequence.
    pub fn new() -> EdgeSeq {
        EdgeSeq(Vec::new())
    }

    /// Straight edges through the given vertices (consecutive edges share them);
    /// `closed` adds the edge back to the first vertex.
    pub fn polyline(a: &mut Arena, verts: &[VertexId], closed: bool) -> Result<EdgeSeq> {
        let mut seq = EdgeSeq::new();
        for w in verts.windows(2) {
            seq.push(a.edge(w[0], w[1], Curve::Line)?);
        }
        if closed {
            let (last, first) = (*verts.last().expect("vertices"), verts[0]);
            seq.push(a.edge(last, first, Curve::Line)?);
        }
        Ok(seq)
    }

    /// Straight edges through new vertices at the given points.
    pub fn from_points(a: &mut Arena, points: &[Vec2], closed: bool) -> Result<EdgeSeq> {
        let verts: Vec<VertexId> = points.iter().map(|p| a.vertex(*p)).collect();
        EdgeSeq::polyline(a, &verts, closed)
    }

    /// First edge.
    pub fn first_edge(&self) -> EdgeId {
        self.0[0]
    }

    /// Last edge.
    pub fn last_edge(&self) -> EdgeId {
        *self.0.last().expect("non-empty edge sequence")
    }

    /// Edge at `i`, negative indices counting from the end.
    pub fn at(&self, i: isize) -> EdgeId {
        let n = self.0.len() as isize;
        self.0[(if i < 0 { n + i } else { i }) as usize]
    }

    /// Sub-sequence `[from, to)` with Python-style negative indices; a new list over
    /// the same edges.
    pub fn slice(&self, from: isize, to: isize) -> EdgeSeq {
        let n = self.0.len() as isize;
        let norm_i = |i: isize| (if i < 0 { (n + i).max(0) } else { i.min(n) }) as usize;
        let (f, t) = (norm_i(from), norm_i(to));
        EdgeSeq(if f < t { self.0[f..t].to_vec() } else { Vec::new() })
    }

    /// Position of an edge (by identity).
    pub fn index_of(&self, e: EdgeId) -> Option<usize> {
        self.0.iter().position(|x| *x == e)
    }

    /// Replace the edge `orig` by the edges `new`, in place.
    pub fn substitute(&mut self, orig: EdgeId, new: &[EdgeId]) -> Result<()> {
        let i = self.index_of(orig).ok_or_else(|| Error::Geometry("substitute: edge not in sequence".into()))?;
        self.substitute_at(i, new);
        Ok(())
    }

    /// Replace the edge at position `i` by the edges `new`.
    pub fn substitute_at(&mut self, i: usize, new: &[EdgeId]) {
        self.0.splice(i..=i, new.iter().copied());
    }

    /// Remove an edge (by identity).
    pub fn remove_edge(&mut self, e: EdgeId) -> Result<()> {
        let i = self.index_of(e).ok_or_else(|| Error::Geometry("remove: edge not in sequence".into()))?;
        self.0.remove(i);
        Ok(())
    }

    /// Total length.
    pub fn length(&self, a: &Arena) -> f64 {
        self.0.iter().map(|e| a.edge_length(*e)).sum()
    }

    /// Length of every edge.
    pub fn lengths(&self, a: &Arena) -> Vec<f64> {
        self.0.iter().map(|e| a.edge_length(*e)).collect()
    }

    /// Length fractions of the edges.
    pub fn fractions(&self, a: &Arena) -> Vec<f64> {
        let l = self.lengths(a);
        let total: f64 = l.iter().sum();
        l.iter().map(|x| x / total).collect()
    }

    /// The first edge starts at the vertex where the last one ends.
    pub fn is_loop(&self, a: &Arena) -> bool {
        self.0.len() > 1 && a.start(self.0[0]) == a.end(self.last_edge())
    }

    /// Every edge starts at the vertex where the previous one ends.
    pub fn is_chained(&self, a: &Arena) -> bool {
        self.0.len() >= 2 && self.0.windows(2).all(|w| a.start(w[1]) == a.end(w[0]))
    }

    /// Distinct vertices in traversal order (identity based; a closing vertex that
    /// repeats the first one is not repeated).
    pub fn verts(&self, a: &Arena) -> Vec<VertexId> {
        let mut out = Vec::with_capacity(self.0.len() + 1);
        if self.0.is_empty() {
            return out;
        }
        out.push(a.start(self.0[0]));
        for &e in &self.0 {
            let s = a.start(e);
            if *out.last().expect("non-empty") != s {
                out.push(s);
            }
            out.push(a.end(e));
        }
        if out.len() > 1 && out[0] == *out.last().expect("non-empty") {
            out.pop();
        }
        out
    }

    /// Positions of [`EdgeSeq::verts`].
    pub fn vert_positions(&self, a: &Arena) -> Vec<Vec2> {
        self.verts(a).into_iter().map(|v| a.pos(v)).collect()
    }

    /// Start of the first edge and end of the last one.
    pub fn shortcut(&self, a: &Arena) -> (Vec2, Vec2) {
        (a.pos(a.start(self.0[0])), a.pos(a.end(self.last_edge())))
    }

    /// Reverse the order of the edges and the direction of every edge, in place.
    pub fn reverse(&mut self, a: &mut Arena) -> &mut Self {
        self.0.reverse();
        for &e in &self.0 {
            a.reverse_edge(e);
        }
        self
    }

    /// Move every vertex by `shift`.
    pub fn translate_by(&self, a: &mut Arena, shift: Vec2) -> &Self {
        for v in self.verts(a) {
            let p = a.pos(v);
            a.set_pos(v, Vec2::new(p.x + shift.x, p.y + shift.y));
        }
        self
    }

    /// Translate so that the first edge starts at `origin`.
    pub fn snap_to(&self, a: &mut Arena, origin: Vec2) -> &Self {
        let start = a.pos(a.start(self.0[0]));
        self.translate_by(a, Vec2::new(origin.x - start.x, origin.y - start.y))
    }

    /// Rotate every vertex by `angle` radians about the start of the first edge.
    pub fn rotate(&self, a: &mut Arena, angle: f64) -> &Self {
        let start = a.pos(a.start(self.0[0]));
        self.snap_to(a, Vec2::ZERO);
        for v in self.verts(a) {
            let p = a.pos(v);
            a.set_pos(v, rotate2d(p, angle));
        }
        self.snap_to(a, start);
        self
    }

    /// (The reference's `extend`.) Stretch (factor > 1) or shrink along the direction from the chain's start to its
    /// end, keeping the first vertex fixed; curves follow their chords.
    pub fn stretch(&self, a: &mut Arena, factor: f64) -> &Self {
        let (first, last) = if self.is_chained(a) {
            (a.pos(a.start(self.0[0])), a.pos(a.end(self.last_edge())))
        } else {
            // The reference works on a re-chained copy to find the direction.
            let chained = self.chained_order(a);
            if chained.is_loop(a) {
                return self;
            }
            (a.pos(a.start(chained.0[0])), a.pos(a.end(chained.last_edge())))
        };
        let line = last - first;
        let dir = line / norm(line);
        let verts = self.verts(a);
        let fixed = a.pos(verts[0]);
        for v in verts {
            let p = a.pos(v);
            let proj = (p - fixed).dot(dir) * dir;
            a.set_pos(v, p - (1.0 - factor) * proj);
        }
        self
    }

    /// Reflect across the line through `v0` and `v1` (curvatures mirrored too).
    pub fn reflect(&self, a: &mut Arena, v0: Vec2, v1: Vec2) -> &Self {
        let vec = v1 - v0;
        let u = vec / norm(vec);
        let m00 = 1.0 - 2.0 * u.y * u.y;
        let m01 = 2.0 * u.x * u.y;
        let m11 = -1.0 + 2.0 * u.y * u.y;
        for v in self.verts(a) {
            let p = a.pos(v) - v0;
            a.set_pos(v, Vec2::new(m00 * p.x + m01 * p.y, m01 * p.x + m11 * p.y) + v0);
        }
        for &e in &self.0 {
            a.reflect_edge_features(e);
        }
        self
    }

    /// Set the label of every edge.
    pub fn propagate_label(&self, a: &mut Arena, label: &str) {
        for &e in &self.0 {
            a.set_edge_label(e, label);
        }
    }

    /// Deep copy: new edges and vertices with the same sharing.
    pub fn copy(&self, a: &mut Arena) -> EdgeSeq {
        EdgeSeq(a.copy_edges(&self.0))
    }

    /// A copy whose edges are re-oriented to form a chain where they were reversed
    /// individually.
    pub fn chained_order(&self, a: &mut Arena) -> EdgeSeq {
        let c = self.copy(a);
        for i in 0..c.len() {
            let meets_previous_end = i > 0 && a.end(c[i]) == a.end(c[i - 1]);
            let meets_next_start = i + 1 < c.len() && (a.start(c[i]) == a.start(c[i + 1]) || a.start(c[i]) == a.end(c[i + 1]));
            if meets_previous_end || meets_next_start {
                a.reverse_edge(c[i]);
            }
        }
        c
    }

    /// Close the loop with a straight edge if it is not closed.
    pub fn close_loop(&mut self, a: &mut Arena) -> Result<&mut Self> {
        if !self.is_loop(a) {
            let (last, first) = (a.end(self.last_edge()), a.start(self.0[0]));
            let e = a.edge(last, first, Curve::Line)?;
            self.0.push(e);
        }
        Ok(self)
    }

    /// Positions of the vertices of the default linearisation of every edge, in
    /// traversal order with identity-based de-duplication (the reference's point set
    /// for bounding boxes).
    pub fn linearized_positions(&self, a: &Arena) -> Vec<Vec2> {
        self.linearized_positions_n(a, None)
    }

    /// As [`EdgeSeq::linearized_positions`] with `n` interior points on every edge
    /// (straight ones included) when given.
    pub fn linearized_positions_n(&self, a: &Arena, n: Option<usize>) -> Vec<Vec2> {
        let mut out = Vec::new();
        self.linearized_positions_into(a, n, &mut out);
        out
    }

    /// Calls `f` with [`EdgeSeq::linearized_positions_n`], in a buffer reused
    /// from call to call (bounding boxes and normals are computed many times
    /// while a garment is built and only read the points).
    pub(crate) fn with_linearized_positions<R>(&self, a: &Arena, n: Option<usize>, f: impl FnOnce(&[Vec2]) -> R) -> R {
        thread_local! {
            static SCRATCH: std::cell::Cell<Vec<Vec2>> = const { std::cell::Cell::new(Vec::new()) };
        }
        // Taken out while in use, so a nested call simply gets a new buffer.
        let mut buf = SCRATCH.take();
        buf.clear();
        self.linearized_positions_into(a, n, &mut buf);
        let r = f(&buf);
        SCRATCH.set(buf);
        r
    }

    /// [`EdgeSeq::linearized_positions_n`] into `out` (emptied first).
    fn linearized_positions_into(&self, a: &Arena, n: Option<usize>, out: &mut Vec<Vec2>) {
        out.clear();
        if self.0.is_empty() {
            return;
        }
        // Sized once: growing by doubling cost several reallocations per call.
        let points = |e: EdgeId| n.unwrap_or(if a.curve(e) == Curve::Line { 0 } else { 9 });
        out.reserve(1 + self.0.iter().map(|&e| 2 + points(e)).sum::<usize>());
        let first = a.start(self.0[0]);
        let mut last_id = Some(first);
        out.push(a.pos(first));
        for &e in &self.0 {
            let (s, t) = (a.start(e), a.end(e));
            if last_id != Some(s) {
                out.push(a.pos(s));
            }
            a.linearized_points_into(e, n, out);
            out.push(a.pos(t));
            last_id = Some(t);
        }
        if out.len() > 1 && last_id == Some(first) {
            out.pop();
        }
    }

    /// The bounding box of the linearised sequence and the reference's "bounding box
    /// points" (the vertices lying on it, in order; completed to three points when
    /// only two are found), used to estimate panel normals.
    pub fn bbox_points(&self, a: &Arena) -> ([f64; 4], Vec<Vec2>) {
        self.with_linearized_positions(a, None, |verts| {
            let mut mi = verts[0];
            let mut ma = verts[0];
            for v in verts {
                mi = mi.min(*v);
                ma = ma.max(*v);
            }
            let mut b: Vec<Vec2> = verts.iter().copied().filter(|v| v.x == mi.x || v.x == ma.x || v.y == mi.y || v.y == ma.y).collect();
            if b.len() == 2 {
                if !b.contains(&mi) {
                    b = vec![b[0], mi, b[1]];
                } else {
                    b = vec![b[0], Vec2::new(mi.x, ma.y), b[1]];
                }
            }
            ([mi.x, ma.x, mi.y, ma.y], b)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn loops_and_chains_by_identity() {
        let mut a = Arena::new();
        let s = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(1., 0.), v(1., 1.)], true).unwrap();
        assert!(s.is_loop(&a) && s.is_chained(&a));
        assert_eq!(s.verts(&a).len(), 3);
        // Same coordinates, different vertex: not a loop.
        let t = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(1., 0.), v(0., 0.)], false);
        assert!(matches!(t, Ok(ref t) if !t.is_loop(&a)));
    }

    #[test]
    fn reverse_twice_is_identity() {
        let mut a = Arena::new();
        let mut s = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(1., 0.), v(2., 3.)], false).unwrap();
        let before: Vec<_> = s.iter().map(|e| a.geom(*e)).collect();
        s.reverse(&mut a);
        assert_eq!(a.pos(a.start(s[0])), v(2., 3.));
        s.reverse(&mut a);
        let after: Vec<_> = s.iter().map(|e| a.geom(*e)).collect();
        assert_eq!(before, after);
    }

    #[test]
    fn rotate_and_reflect() {
        let mut a = Arena::new();
        let s = EdgeSeq::from_points(&mut a, &[v(1., 1.), v(2., 1.)], false).unwrap();
        s.rotate(&mut a, std::f64::consts::FRAC_PI_2);
        assert!((a.pos(a.end(s[0])) - v(1., 2.)).length() < 1e-15);
        s.reflect(&mut a, v(0., 0.), v(0., 1.));
        assert!((a.pos(a.end(s[0])) - v(-1., 2.)).length() < 1e-15);
    }

    #[test]
    fn stretch_along_opening() {
        let mut a = Arena::new();
        let s = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(1., 1.), v(2., 0.)], false).unwrap();
        s.stretch(&mut a, 2.0);
        assert_eq!(a.pos(a.end(s[1])), v(4., 0.));
        assert_eq!(a.pos(a.end(s[0])), v(2., 1.));
    }

    #[test]
    fn copy_preserves_sharing() {
        let mut a = Arena::new();
        let s = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(1., 0.), v(1., 1.)], true).unwrap();
        let c = s.copy(&mut a);
        assert!(c.is_loop(&a) && c.is_chained(&a));
        assert_ne!(c[0], s[0]);
        c.translate_by(&mut a, v(5., 0.));
        assert_eq!(a.pos(a.start(s[0])), v(0., 0.));
        assert_eq!(a.pos(a.start(c[0])), v(5., 0.));
    }
}
