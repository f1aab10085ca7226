//! What the flat pattern says past the reference's format (the GarmentCode paper's
//! limitations): closed loops inside a panel ([`Hole`]: a diamond dart, a keyhole, a
//! welt-pocket opening), lines inside a panel ([`InnerLine`]: fold lines, placement
//! lines for pieces sewn on top, pleat folds), the layer a panel belongs to
//! ([`Layer`]: an outer layer and its facing or lining) and stitches on any of those
//! edges ([`InnerStitch`]).
//!
//! A pattern that uses none of them is exactly the reference's pattern: the fields are
//! empty and nothing of them is written (see `docs/pattern-extension.md` for the file
//! layout and what the reference's loader does with it).
//!
//! Hole and line geometry is held like an outline's: panel-local vertices and edges
//! between them with the outline's relative curvature ([`EdgeSpec`]); a hole's edges
//! form one closed loop over its own vertices, a line's edges an open chain over its
//! own vertices.
//!
//! ```
//! use garmentcode::{EdgePlace, EdgeSpec, Hole, HoleKind, InnerSide, InnerStitch};
//!
//! // A diamond dart: a closed loop of four edges, its sides sewn together in pairs.
//! let dart = Hole {
//!     name: "waist_dart".into(),
//!     kind: HoleKind::Dart,
//!     vertices: vec![[10.0, 20.0], [11.5, 35.0], [10.0, 50.0], [8.5, 35.0]],
//!     edges: (0..4).map(|i| EdgeSpec { endpoints: [i, (i + 1) % 4], label: None, curvature: None }).collect(),
//! };
//! let side = |edge| InnerSide { panel: "front".into(), place: EdgePlace::Hole(0), edge };
//! let seam = InnerStitch { sides: [side(0), side(3)], right_wrong: false };
//! assert_eq!(dart.edges.len(), 4);
//! assert_eq!(seam.sides[1].place, EdgePlace::Hole(0));
//! ```

use super::{EdgePlace, EdgeSpec, Hole, InnerLine, PanelSpec, edge_geometry};
use crate::edge::{Curve, Edge};
use crate::math::Vec2;

impl PanelSpec {
    /// Every edge of the panel: the outline's, then each hole's, then each inner
    /// line's (the order of [`edge_path`](Self::edge_path)).
    pub fn all_edges(&self) -> impl Iterator<Item = &EdgeSpec> {
        self.edges.iter().chain(self.holes.iter().flat_map(|h| &h.edges)).chain(self.lines.iter().flat_map(|l| &l.edges))
    }

    /// [`all_edges`](Self::all_edges), mutable.
    pub fn all_edges_mut(&mut self) -> impl Iterator<Item = &mut EdgeSpec> {
        self.edges
            .iter_mut()
            .chain(self.holes.iter_mut().flat_map(|h| &mut h.edges))
            .chain(self.lines.iter_mut().flat_map(|l| &mut l.edges))
    }

    /// The index in [`all_edges`](Self::all_edges) of edge `edge` of the outline, hole
    /// or line `place`, if it exists.
    pub fn edge_index(&self, place: EdgePlace, edge: usize) -> Option<usize> {
        let count = |edges: &[EdgeSpec]| edges.len();
        let hole_edges = |n: usize| self.holes[..n].iter().map(|h| count(&h.edges)).sum::<usize>();
        let (before, len) = match place {
            EdgePlace::Outline => (0, self.edges.len()),
            EdgePlace::Hole(h) => {
                let len = count(&self.holes.get(h)?.edges);
                (self.edges.len() + hole_edges(h), len)
            }
            EdgePlace::Line(l) => {
                let len = count(&self.lines.get(l)?.edges);
                (self.edges.len() + hole_edges(self.holes.len()) + self.lines[..l].iter().map(|x| count(&x.edges)).sum::<usize>(), len)
            }
        };
        (edge < len).then_some(before + edge)
    }

    /// Where edge `i` of [`all_edges`](Self::all_edges) is in the panel's JSON
    /// (`edges[3]`, `holes[0].edges[1]`, `lines[2].edges[0]`).
    pub fn edge_path(&self, i: usize) -> String {
        let mut rest = i;
        if rest < self.edges.len() {
            return format!("edges[{rest}]");
        }
        rest -= self.edges.len();
        for (h, hole) in self.holes.iter().enumerate() {
            if rest < hole.edges.len() {
                return format!("holes[{h}].edges[{rest}]");
            }
            rest -= hole.edges.len();
        }
        for (l, line) in self.lines.iter().enumerate() {
            if rest < line.edges.len() {
                return format!("lines[{l}].edges[{rest}]");
            }
            rest -= line.edges.len();
        }
        format!("edge {i}")
    }
}

impl Hole {
    /// Geometry of edge `i` (indices must be valid: see [`validate`](crate::validate)).
    pub fn edge_geom(&self, i: usize) -> Edge {
        edge_geometry(&self.vertices, &self.edges[i])
    }

    /// The loop as a closed polygon (panel-local): each edge's start and, on curves,
    /// `steps − 1` points between.
    pub fn polygon(&self, steps: usize) -> Vec<Vec2> {
        sample(&self.vertices, &self.edges, steps)
    }
}

impl InnerLine {
    /// Geometry of edge `i` (indices must be valid: see [`validate`](crate::validate)).
    pub fn edge_geom(&self, i: usize) -> Edge {
        edge_geometry(&self.vertices, &self.edges[i])
    }

    /// The line as a polyline (panel-local): each edge's start and, on curves,
    /// `steps − 1` points between, then the last edge's end.
    pub fn polyline(&self, steps: usize) -> Vec<Vec2> {
        let mut out = sample(&self.vertices, &self.edges, steps);
        if let Some(last) = self.edges.last() {
            out.push(Vec2::from(self.vertices[last.endpoints[1]]));
        }
        out
    }
}

/// Each edge's start and, on curves, `steps − 1` points between.
pub(crate) fn sample(vertices: &[[f64; 2]], edges: &[EdgeSpec], steps: usize) -> Vec<Vec2> {
    let mut out = Vec::new();
    for e in edges {
        let g = edge_geometry(vertices, e);
        let n = if matches!(g.curve, Curve::Line) { 1 } else { steps.max(1) };
        out.extend((0..n).map(|k| g.point(k as f64 / n as f64)));
    }
    out
}
