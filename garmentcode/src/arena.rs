//! The arena: where the vertices, edges, panels and interfaces of one garment live.
//!
//! Garment programs share vertices between edges and edges between panel loops and
//! interfaces, and mutate them in place (moving a vertex moves every edge that holds
//! it; reversing an edge is seen by every interface that lists it). The arena gives
//! each object an identity (a small copyable id) so these sharing semantics are
//! explicit and cheap: components and interfaces hold ids, all geometry is here.
//!
//! One arena holds one garment; reuse it with [`Arena::clear`] to build many garments
//! without reallocating.

use crate::edge::{Curve, Edge};
use crate::error::{Error, Result};
use crate::math::{Vec2, Vec3, close_enough};
use crate::pattern::{EdgePlace, HoleKind, Layer, LineKind};
use crate::rotation::Rotation;
use std::ops::{Deref, DerefMut};

/// Identity of a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VertexId(pub(crate) u32);

/// Identity of an edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EdgeId(pub(crate) u32);

/// Identity of a panel.
///
/// Panels are made by the [`Arena`] and read and placed through their id:
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, Vec2, Vec3};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges);
/// panel.translate_to(&mut a, Vec3::new(0.0, 100.0, 15.0));
/// assert_eq!(panel.name(&a), "front");
/// assert_eq!(panel.translation(&a), Vec3::new(0.0, 100.0, 15.0));
/// assert_eq!(panel.bbox(&a), (Vec2::ZERO, Vec2::new(20.0, 30.0)));
/// // The panel as the pattern format writes it.
/// let written = panel.assemble(&mut a)?;
/// assert_eq!((written.name.as_str(), written.edges.len()), ("front", 4));
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PanelId(pub(crate) u32);

/// Identity of an interface.
///
/// An interface is a list of panel edges that can be stitched, made by the [`Arena`]:
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges.clone());
/// let side = a.interface(panel, edges[0]);
/// let top = a.interface(panel, edges.slice(1, 3));
/// assert_eq!((side.len(&a), side.length(&a)), (1, 30.0));
/// assert_eq!((top.len(&a), top.length(&a)), (2, 50.0));
/// // Interfaces concatenate, and the panel knows those made over its edges.
/// let both = a.interface_from(&[side, top]);
/// assert_eq!(both.panels(&a), [panel; 3]);
/// assert_eq!(panel.interfaces(&a), [side, top]);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct InterfaceId(pub(crate) u32);

/// Stored edge: end-point vertices, relative curvature, label.
#[derive(Clone, Debug)]
pub(crate) struct EdgeData {
    pub start: VertexId,
    pub end: VertexId,
    pub curve: Curve,
    /// Index into [`Arena::labels`]; 0 is "no label".
    pub label: u32,
    /// Index of the edge in its panel's written loop, set on assembly.
    pub geometric_id: u32,
    /// Where the edge was written (outline, hole or inner line), set on assembly.
    pub place: EdgePlace,
}

/// An ordered list of edges.
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 10.0), Vec2::new(20.0, 10.0), Vec2::new(20.0, 0.0)];
/// let outline = EdgeSeq::from_points(&mut a, &corners, true)?;
/// assert!(outline.is_loop(&a));
/// assert_eq!((outline.len(), outline.length(&a)), (4, 60.0));
/// // A slice is a new list over the same edges; `copy` copies the geometry.
/// let top = outline.slice(1, 2);
/// let moved = top.copy(&mut a);
/// moved.translate_by(&mut a, Vec2::new(0.0, 5.0));
/// assert_eq!(top.shortcut(&a), (Vec2::new(0.0, 10.0), Vec2::new(20.0, 10.0)));
/// assert_eq!(moved.shortcut(&a), (Vec2::new(0.0, 15.0), Vec2::new(20.0, 15.0)));
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeSeq(pub Vec<EdgeId>);

impl Deref for EdgeSeq {
    type Target = Vec<EdgeId>;
    fn deref(&self) -> &Vec<EdgeId> {
        &self.0
    }
}

impl DerefMut for EdgeSeq {
    fn deref_mut(&mut self) -> &mut Vec<EdgeId> {
        &mut self.0
    }
}

impl From<Vec<EdgeId>> for EdgeSeq {
    fn from(v: Vec<EdgeId>) -> Self {
        EdgeSeq(v)
    }
}

impl From<EdgeId> for EdgeSeq {
    fn from(e: EdgeId) -> Self {
        EdgeSeq(vec![e])
    }
}

impl<'a> IntoIterator for &'a EdgeSeq {
    type Item = &'a EdgeId;
    type IntoIter = std::slice::Iter<'a, EdgeId>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

/// A stitch between two interfaces, matched edge for edge.
///
/// Making the rule splits edges so that both sides have matching edges:
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, StitchRule, Vec2};
///
/// let mut a = Arena::new();
/// let square = |a: &mut Arena, name: &str| -> garmentcode::Result<_> {
///     let corners = [Vec2::ZERO, Vec2::new(0.0, 20.0), Vec2::new(20.0, 20.0), Vec2::new(20.0, 0.0)];
///     let edges = EdgeSeq::from_points(a, &corners, true)?;
///     Ok((a.panel_with_edges(name, edges.clone()), edges))
/// };
/// let (front, f) = square(&mut a, "front")?;
/// let (back, b) = square(&mut a, "back")?;
/// let one_edge = a.interface(front, f[0]);
/// let two_edges = a.interface(back, b.slice(0, 2));
/// let rule = StitchRule::new(&mut a, one_edge, two_edges)?;
/// assert!(rule.is_matching(&a));
/// assert_eq!((one_edge.len(&a), two_edges.len(&a)), (2, 2));
/// assert_eq!(front.edges(&a).len(), 5);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StitchRule {
    /// First side.
    pub a: InterfaceId,
    /// Second side.
    pub b: InterfaceId,
}

/// A run of consecutive interface edges `[start, end)` gathered by `coeff`: the
/// fabric of these edges is `coeff` times longer than the seam it is sewn to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ruffle {
    /// Gather factor (1 = flat).
    pub coeff: f64,
    /// First edge of the section.
    pub start: usize,
    /// One past the last edge of the section.
    pub end: usize,
}

/// Stored interface.
#[derive(Clone, Debug, Default)]
pub(crate) struct InterfaceData {
    pub edges: EdgeSeq,
    pub panels: Vec<PanelId>,
    pub right_wrong: Vec<bool>,
    /// "Treat this edge as reversed" flags used by stitch matching.
    pub flipping: Vec<bool>,
    pub ruffle: Vec<Ruffle>,
}

impl InterfaceData {
    /// Make this record equal to `other`, in its own buffers.
    pub fn copy_from(&mut self, other: &InterfaceData) {
        self.edges.0.clone_from(&other.edges.0);
        self.panels.clone_from(&other.panels);
        self.right_wrong.clone_from(&other.right_wrong);
        self.flipping.clone_from(&other.flipping);
        self.ruffle.clone_from(&other.ruffle);
    }
}

/// Stored panel.
#[derive(Clone, Debug)]
pub(crate) struct PanelData {
    pub name: String,
    pub label: String,
    pub translation: Vec3,
    pub rotation: Rotation,
    pub edges: EdgeSeq,
    /// The interfaces made over this panel's edges, in creation order (every
    /// [`Arena::interface`] over the panel adds one; a corner cut updates all of
    /// them and adds the one over the inserted shape).
    pub interfaces: Vec<InterfaceId>,
    /// Stitches inside the panel (darts).
    pub stitches: Vec<StitchRule>,
    /// When set, the panel's "length" is this interface's length instead of its
    /// bounding-box height.
    pub length_interface: Option<InterfaceId>,
    /// Closed loops inside the outline (format extension), each over its own vertices.
    pub holes: Vec<InnerPath<HoleKind>>,
    /// Open lines inside the panel (format extension), each over its own vertices.
    pub lines: Vec<InnerPath<LineKind>>,
    /// Layer of a double-layer component.
    pub layer: Layer,
}

/// A hole or an inner line of a panel: its name, kind and edges (a closed loop for
/// a hole, an open chain for a line).
#[derive(Clone, Debug)]
pub(crate) struct InnerPath<K> {
    pub name: String,
    pub kind: K,
    pub edges: EdgeSeq,
}

/// Storage of one garment's geometry.
///
/// Edges hold vertex ids, so moving a vertex moves every edge that holds it:
///
/// ```
/// use garmentcode::{Arena, Curve, Vec2};
///
/// let mut a = Arena::new();
/// let (p, q, r) = (a.vertex(Vec2::ZERO), a.vertex(Vec2::new(3.0, 0.0)), a.vertex(Vec2::new(3.0, 4.0)));
/// let e1 = a.edge(p, q, Curve::Line)?;
/// let e2 = a.edge(q, r, Curve::Line)?;
/// assert_eq!((a.edge_length(e1), a.edge_length(e2)), (3.0, 4.0));
/// a.set_pos(q, Vec2::new(0.0, 4.0));
/// assert_eq!((a.edge_length(e1), a.edge_length(e2)), (4.0, 3.0));
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Arena {
    pub(crate) verts: Vec<Vec2>,
    pub(crate) edges: Vec<EdgeData>,
    pub(crate) panels: Vec<PanelData>,
    pub(crate) interfaces: Vec<InterfaceData>,
    labels: Vec<String>,
    /// Interfaces of previous garments, kept for their buffers (see
    /// [`Arena::clear`]); never read as interfaces.
    pub(crate) spare_interfaces: Vec<InterfaceData>,
    /// See [`Arena::stop_at_self_intersection`].
    pub(crate) stop_at_self_intersection: bool,
    /// Where a linearisation first made a piece whose ends coincide (see
    /// [`Arena::take_degenerate_linearization`]).
    degenerate_linearization: std::cell::Cell<Option<Vec2>>,
}

/// Interface records kept for reuse by [`Arena::clear`] at most (a garment of the
/// library makes up to a few hundred).
const MAX_SPARE_INTERFACES: usize = 4096;

impl Default for Arena {
    fn default() -> Self {
        Arena::new()
    }
}

impl Arena {
    /// An empty arena.
    pub fn new() -> Arena {
        Arena {
            verts: Vec::new(),
            edges: Vec::new(),
            panels: Vec::new(),
            interfaces: Vec::new(),
            labels: vec![String::new()],
            spare_interfaces: Vec::new(),
            stop_at_self_intersection: false,
            degenerate_linearization: std::cell::Cell::new(None),
        }
    }

    /// The reference refuses a garment whenever one of the straight pieces it makes
    /// while linearising an edge (for a bounding box, a centre, a self-intersection
    /// check) has coinciding ends, as it refuses any such edge. Linearising through
    /// the arena records the first such piece; builders call this after each step
    /// that linearises and fail with the returned error. Taking it clears it.
    pub fn take_degenerate_linearization(&mut self) -> Option<Error> {
        self.degenerate_linearization.take().map(|p| Error::DegenerateEdge { x: p.x, y: p.y })
    }

    /// Record the first piece with coinciding ends among `start`, `interior...`,
    /// `end` (an edge split at its linearisation points).
    pub(crate) fn note_linearization(&self, start: Vec2, interior: &[Vec2], end: Vec2) {
        if interior.is_empty() || self.degenerate_linearization.get().is_some() {
            return;
        }
        let pts = std::iter::once(start).chain(interior.iter().copied()).chain(std::iter::once(end));
        let mut prev: Option<Vec2> = None;
        for p in pts {
            if let Some(q) = prev {
                if check_distinct(q, p).is_err() {
                    self.degenerate_linearization.set(Some(q));
                    return;
                }
            }
            prev = Some(p);
        }
    }

    /// Make [`PanelId::check_outline`] fail on a panel outline that crosses itself
    /// (off by default; kept by [`Arena::clear`]). A filter that turns such garments
    /// down (the dataset sampler) then stops building one as soon as the outline is
    /// known, before the costly parts that follow.
    pub fn stop_at_self_intersection(&mut self, on: bool) {
        self.stop_at_self_intersection = on;
    }

    /// Forget everything (keeping the allocations) to build another garment.
    pub fn clear(&mut self) {
        self.verts.clear();
        self.edges.clear();
        self.panels.clear();
        // A garment makes dozens of interfaces of four or five small vectors each:
        // the next garment reuses their buffers. Every record is made from a spare
        // when there is one, so the spares stay as many as the largest garment's;
        // the cap keeps a flat memory whatever a garment program does.
        self.spare_interfaces.append(&mut self.interfaces);
        self.spare_interfaces.truncate(MAX_SPARE_INTERFACES);
        self.labels.truncate(1);
        self.degenerate_linearization.set(None);
    }

    // ---- vertices ----

    /// A new vertex at `p`.
    pub fn vertex(&mut self, p: Vec2) -> VertexId {
        self.verts.push(p);
        VertexId((self.verts.len() - 1) as u32)
    }

    /// Position of a vertex.
    #[inline]
    pub fn pos(&self, v: VertexId) -> Vec2 {
        self.verts[v.0 as usize]
    }

    /// Move a vertex (every edge holding it follows).
    #[inline]
    pub fn set_pos(&mut self, v: VertexId, p: Vec2) {
        self.verts[v.0 as usize] = p;
    }

    // ---- edges ----

    /// A new edge between two existing vertices. Like the reference, an edge whose
    /// ends coincide (each coordinate within 1e-4) is refused.
    pub fn edge(&mut self, start: VertexId, end: VertexId, curve: Curve) -> Result<EdgeId> {
        check_distinct(self.pos(start), self.pos(end))?;
        Ok(self.push_edge(start, end, curve))
    }

    pub(crate) fn push_edge(&mut self, start: VertexId, end: VertexId, curve: Curve) -> EdgeId {
        self.edges.push(EdgeData { start, end, curve, label: 0, geometric_id: 0, place: EdgePlace::Outline });
        EdgeId((self.edges.len() - 1) as u32)
    }

    /// A new straight edge between two new vertices.
    pub fn line(&mut self, start: Vec2, end: Vec2) -> Result<EdgeId> {
        check_distinct(start, end)?;
        let s = self.vertex(start);
        let e = self.vertex(end);
        Ok(self.push_edge(s, e, Curve::Line))
    }

    /// A new edge with the given geometry between two new vertices.
    pub fn add_edge(&mut self, edge: Edge) -> Result<EdgeId> {
        check_distinct(edge.start, edge.end)?;
        let s = self.vertex(edge.start);
        let e = self.vertex(edge.end);
        Ok(self.push_edge(s, e, edge.curve))
    }

    /// Geometry of an edge.
    #[inline]
    pub fn geom(&self, e: EdgeId) -> Edge {
        let d = &self.edges[e.0 as usize];
        Edge { start: self.pos(d.start), end: self.pos(d.end), curve: d.curve }
    }

    /// Start vertex of an edge.
    #[inline]
    pub fn start(&self, e: EdgeId) -> VertexId {
        self.edges[e.0 as usize].start
    }

    /// End vertex of an edge.
    #[inline]
    pub fn end(&self, e: EdgeId) -> VertexId {
        self.edges[e.0 as usize].end
    }

    /// Re-link the start of an edge to another vertex.
    #[inline]
    pub fn set_start(&mut self, e: EdgeId, v: VertexId) {
        self.edges[e.0 as usize].start = v;
    }

    /// Re-link the end of an edge to another vertex.
    #[inline]
    pub fn set_end(&mut self, e: EdgeId, v: VertexId) {
        self.edges[e.0 as usize].end = v;
    }

    /// Curvature of an edge.
    #[inline]
    pub fn curve(&self, e: EdgeId) -> Curve {
        self.edges[e.0 as usize].curve
    }

    /// Replace the curvature of an edge.
    pub fn set_curve(&mut self, e: EdgeId, c: Curve) {
        self.edges[e.0 as usize].curve = c;
    }

    /// Length of an edge.
    pub fn edge_length(&self, e: EdgeId) -> f64 {
        self.geom(e).length()
    }

    /// Label of an edge ("" when none).
    pub fn edge_label(&self, e: EdgeId) -> &str {
        &self.labels[self.edges[e.0 as usize].label as usize]
    }

    /// Set the label of an edge.
    pub fn set_edge_label(&mut self, e: EdgeId, label: &str) {
        let id = self.intern(label);
        self.edges[e.0 as usize].label = id;
    }

    pub(crate) fn intern(&mut self, label: &str) -> u32 {
        if let Some(i) = self.labels.iter().position(|l| l == label) {
            return i as u32;
        }
        self.labels.push(label.to_string());
        (self.labels.len() - 1) as u32
    }

    /// Index of the edge in its panel's written loop (valid after assembly).
    pub fn geometric_id(&self, e: EdgeId) -> u32 {
        self.edges[e.0 as usize].geometric_id
    }

    /// Reverse an edge in place: swap its ends and mirror its curvature. Every
    /// sequence and interface holding the edge sees the new direction.
    pub fn reverse_edge(&mut self, e: EdgeId) {
        let d = &mut self.edges[e.0 as usize];
        std::mem::swap(&mut d.start, &mut d.end);
        d.curve = d.curve.reversed();
    }

    /// Mirror an edge's curvature across its chord (after its vertices were reflected).
    pub fn reflect_edge_features(&mut self, e: EdgeId) {
        let d = &mut self.edges[e.0 as usize];
        d.curve = d.curve.reflected();
    }

    /// Split an edge at fractions of its length (`by_length`) or of its curve
    /// parameter. The pieces start at the edge's start vertex, end at its end vertex
    /// and share new interior vertices. The original edge is left untouched (callers
    /// substitute the pieces where it was used). Labels are not propagated.
    pub fn subdivide(&mut self, e: EdgeId, fractions: &[f64], by_length: bool) -> Result<Vec<EdgeId>> {
        let sum: f64 = fractions.iter().map(|f| f.abs()).sum();
        if !close_enough(sum, 1.0, 1e-4) {
            return Err(Error::Fractions { sum });
        }
        let geom = self.geom(e);
        let pieces = geom.split(fractions, by_length);
        for p in &pieces {
            check_distinct(p.start, p.end)?;
        }
        let (first, last) = (self.start(e), self.end(e));
        let mut out = Vec::with_capacity(pieces.len());
        let mut prev = first;
        for (i, p) in pieces.iter().enumerate() {
            let end = if i + 1 == pieces.len() { last } else { self.vertex(p.end) };
            out.push(self.push_edge(prev, end, p.curve));
            prev = end;
        }
        Ok(out)
    }

    /// Straight edges through the interior linearisation points of an edge, reusing
    /// its end vertices (used by bounding boxes and centres, as in the reference).
    /// Appends them to `out`.
    pub(crate) fn linearized_points_into(&self, e: EdgeId, n: Option<usize>, out: &mut Vec<Vec2>) {
        let g = self.geom(e);
        let from = out.len();
        g.linearize_into(n.unwrap_or_else(|| g.default_linearization()), out);
        self.note_linearization(g.start, &out[from..], g.end);
    }

    /// Deep copy of edges: new edges and new vertices, with vertex sharing among the
    /// copied edges preserved (consecutive edges stay chained, a loop stays closed).
    pub fn copy_edges(&mut self, edges: &[EdgeId]) -> Vec<EdgeId> {
        let mut map: Vec<(VertexId, VertexId)> = Vec::with_capacity(edges.len() + 1);
        let mut out = Vec::with_capacity(edges.len());
        for &e in edges {
            let d = self.edges[e.0 as usize].clone();
            let s = self.copy_vertex(&mut map, d.start);
            let t = self.copy_vertex(&mut map, d.end);
            self.edges.push(EdgeData { start: s, end: t, ..d });
            out.push(EdgeId((self.edges.len() - 1) as u32));
        }
        out
    }

    fn copy_vertex(&mut self, map: &mut Vec<(VertexId, VertexId)>, v: VertexId) -> VertexId {
        if let Some((_, n)) = map.iter().find(|(o, _)| *o == v) {
            return *n;
        }
        let n = self.vertex(self.pos(v));
        map.push((v, n));
        n
    }

    /// Number of panels created so far.
    pub fn panel_count(&self) -> usize {
        self.panels.len()
    }
}

/// The reference refuses edges whose ends are within 1e-4 in both coordinates.
pub(crate) fn check_distinct(a: Vec2, b: Vec2) -> Result<()> {
    if close_enough(a.x, b.x, 1e-4) && close_enough(a.y, b.y, 1e-4) {
        return Err(Error::DegenerateEdge { x: a.x, y: a.y });
    }
    if !(a.is_finite() && b.is_finite()) {
        return Err(Error::Geometry(format!("edge with non-finite end points ({a}, {b})")));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arena::EdgeSeq;
    use crate::edge::Curve;

    #[test]
    fn garments_built_one_after_another_in_an_arena_keep_its_memory_flat() {
        let mut a = Arena::new();
        let mut spares = Vec::new();
        for _ in 0..20 {
            a.clear();
            let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
            let edges = EdgeSeq::from_points(&mut a, &corners, true).unwrap();
            let panel = a.panel_with_edges("front", edges.clone());
            a.interface(panel, edges[0]);
            a.interface(panel, edges.slice(1, 3));
            // A copy of the panel copies its interfaces.
            let copy = a.copy_part(&panel);
            assert_eq!(copy.interfaces(&a).len(), 2);
            spares.push(a.spare_interfaces.len() + a.interfaces.len());
        }
        assert!(spares.iter().all(|&n| n == 4), "interface records kept: {spares:?}");
    }

    #[test]
    fn a_linearisation_piece_with_coinciding_ends_is_refused_as_the_reference_does() {
        let mut a = Arena::new();
        // A curve 5e-4 long: valid as an edge, but its ten linearisation pieces are
        // each shorter than the closeness tolerance.
        let s = a.vertex(Vec2::new(0.0, 0.0));
        let e = a.vertex(Vec2::new(5e-4, 0.0));
        let tiny = a.edge(s, e, Curve::Quadratic(Vec2::new(0.5, 0.2))).unwrap();
        let seq = EdgeSeq::from(vec![tiny]);
        let _ = seq.linearized_positions_n(&a, None);
        let err = a.take_degenerate_linearization().expect("refused");
        assert!(err.to_string().contains("start and end of an edge should differ"), "{err}");
        assert!(a.take_degenerate_linearization().is_none(), "taken once");
        // A normal curve passes.
        let far = a.vertex(Vec2::new(30.0, 0.0));
        let normal = a.edge(s, far, Curve::Quadratic(Vec2::new(0.5, 0.2))).unwrap();
        let _ = EdgeSeq::from(vec![normal]).linearized_positions_n(&a, None);
        assert!(a.take_degenerate_linearization().is_none());
    }
}
