//! Panels: one closed loop of edges (a piece of fabric) placed in 3D.
//!
//! Every placement call re-orients the loop so that the panel's normal points away
//! from the world origin ("autonorm"): the right side of the fabric faces outward
//! without the author thinking about loop directions. Pivot changes truncate to whole
//! centimetres as the reference does, so written vertices match its files.

use crate::arena::EdgeSeq;
use crate::arena::StitchRule;
use crate::arena::{Arena, EdgeId, InterfaceId, PanelData, PanelId};
use crate::error::Result;
use crate::math::{Vec2, Vec3, trunc};
use crate::ops::{Cut, EdgeSide};
use crate::pattern::{EdgePlace, EdgeSpec, Layer};
use crate::rotation::Rotation;

impl Arena {
    /// A new empty panel at the origin.
    pub fn new_panel(&mut self, name: &str) -> PanelId {
        self.panels.push(PanelData {
            name: name.to_string(),
            label: String::new(),
            translation: Vec3::ZERO,
            rotation: Rotation::IDENTITY,
            edges: EdgeSeq::new(),
            interfaces: Vec::new(),
            stitches: Vec::new(),
            length_interface: None,
            holes: Vec::new(),
            lines: Vec::new(),
            layer: Layer::Outer,
        });
        PanelId((self.panels.len() - 1) as u32)
    }

    /// A new panel with the given edge loop.
    pub fn panel_with_edges(&mut self, name: &str, edges: EdgeSeq) -> PanelId {
        let p = self.new_panel(name);
        self.panels[p.0 as usize].edges = edges;
        p
    }

    pub(crate) fn pd(&self, p: PanelId) -> &PanelData {
        &self.panels[p.0 as usize]
    }

    pub(crate) fn pd_mut(&mut self, p: PanelId) -> &mut PanelData {
        &mut self.panels[p.0 as usize]
    }
}

impl PanelId {
    /// Name of the panel.
    pub fn name(self, a: &Arena) -> &str {
        &a.pd(self).name
    }

    /// Rename the panel.
    pub fn set_name(self, a: &mut Arena, name: &str) {
        a.pd_mut(self).name = name.to_string();
    }

    /// Semantic label ("" when none).
    pub fn label(self, a: &Arena) -> &str {
        &a.pd(self).label
    }

    /// Set the label; with `overwrite = false` only an empty label is replaced.
    pub fn set_label(self, a: &mut Arena, label: &str, overwrite: bool) {
        let d = a.pd_mut(self);
        if d.label.is_empty() || overwrite {
            d.label = label.to_string();
        }
    }

    /// The edge loop.
    pub fn edges(self, a: &Arena) -> &EdgeSeq {
        &a.pd(self).edges
    }

    /// Mutable edge loop.
    pub fn edges_mut(self, a: &mut Arena) -> &mut EdgeSeq {
        &mut a.pd_mut(self).edges
    }

    /// Replace the edge loop.
    pub fn set_edges(self, a: &mut Arena, edges: EdgeSeq) {
        a.pd_mut(self).edges = edges;
    }

    /// Translation (world position of the local origin).
    pub fn translation(self, a: &Arena) -> Vec3 {
        a.pd(self).translation
    }

    /// Rotation.
    pub fn rotation(self, a: &Arena) -> Rotation {
        a.pd(self).rotation
    }

    /// The interfaces made over this panel's edges, in creation order.
    pub fn interfaces(self, a: &Arena) -> &[InterfaceId] {
        &a.pd(self).interfaces
    }

    /// Use this interface's length as the panel's length.
    pub fn set_length_interface(self, a: &mut Arena, i: InterfaceId) {
        a.pd_mut(self).length_interface = Some(i);
    }

    /// Stitches inside the panel (darts).
    pub fn stitches(self, a: &Arena) -> &[StitchRule] {
        &a.pd(self).stitches
    }

    /// Add a stitch inside the panel.
    pub fn add_stitch(self, a: &mut Arena, rule: StitchRule) {
        a.pd_mut(self).stitches.push(rule);
    }

    /// World position of a panel-local point.
    pub fn point_to_3d(self, a: &Arena, p: Vec2) -> Vec3 {
        let d = a.pd(self);
        d.rotation.apply(Vec3::new(p.x, p.y, 0.0)) + d.translation
    }

    /// Set the translation without re-orienting the loop (the reference assigns it
    /// directly in a few places).
    pub fn set_translation(self, a: &mut Arena, t: Vec3) {
        a.pd_mut(self).translation = t;
    }

    /// Move by `delta` (then re-orient the loop).
    pub fn translate_by(self, a: &mut Arena, delta: Vec3) -> Self {
        let d = a.pd_mut(self);
        d.translation += delta;
        self.autonorm(a);
        self
    }

    /// Place the local origin at `t` (then re-orient the loop).
    pub fn translate_to(self, a: &mut Arena, t: Vec3) -> Self {
        a.pd_mut(self).translation = t;
        self.autonorm(a);
        self
    }

    /// Rotate by `q` about the local origin, in world frame (then re-orient).
    pub fn rotate_by(self, a: &mut Arena, q: Rotation) -> Self {
        let d = a.pd_mut(self);
        d.rotation = q.compose(&d.rotation);
        self.autonorm(a);
        self
    }

    /// Set the rotation (then re-orient the loop).
    pub fn rotate_to(self, a: &mut Arena, q: Rotation) -> Self {
        a.pd_mut(self).rotation = q;
        self.autonorm(a);
        self
    }

    /// Rotate so that the panel normal points along `v`.
    pub fn rotate_align(self, a: &mut Arena, v: Vec3) -> Self {
        let v = v / v.length();
        let n = self.norm(a);
        self.rotate_by(a, Rotation::align(n, v))
    }

    /// Normal of the panel, estimated from the points on its bounding box (which
    /// works for non-convex outlines).
    pub fn norm(self, a: &Arena) -> Vec3 {
        let (_, b2) = self.edges(a).bbox_points(a);
        // The box points in 3D (a handful: on the stack).
        let m = b2.len();
        let mut stack = [Vec3::ZERO; 16];
        let heap: Vec<Vec3>;
        let b3: &[Vec3] = if m <= stack.len() {
            for (slot, p) in stack.iter_mut().zip(&b2) {
                *slot = self.point_to_3d(a, *p);
            }
            &stack[..m]
        } else {
            heap = b2.iter().map(|p| self.point_to_3d(a, *p)).collect();
            &heap
        };
        let mut sum = Vec3::ZERO;
        for p in b3 {
            sum += *p;
        }
        let c = sum / m as f64;
        let normal = |i: usize| {
            let n = (b3[i] - c).cross(b3[(i + 1) % m] - c);
            n / n.length()
        };
        let mut avg = Vec3::ZERO;
        for i in 0..m {
            avg += normal(i);
        }
        avg /= m as f64;
        if avg.length() < 1e-4 {
            avg = normal(0);
        }
        let mut n = avg / avg.length();
        for k in 0..3 {
            if n[k].abs() <= 1e-8 {
                n[k] = 0.0;
            }
        }
        n
    }

    /// Reverse the loop if the normal points toward the world origin.
    pub fn autonorm(self, a: &mut Arena) {
        let n = self.norm(a);
        if n.dot(a.pd(self).translation) < 0.0 {
            let mut edges = std::mem::take(&mut a.pd_mut(self).edges);
            edges.reverse(a);
            a.pd_mut(self).edges = edges;
            // Holes keep their turn relative to the outline.
            for k in 0..a.pd(self).holes.len() {
                let mut hole = std::mem::take(&mut a.pd_mut(self).holes[k].edges);
                hole.reverse(a);
                a.pd_mut(self).holes[k].edges = hole;
            }
        }
    }

    /// Move the local origin to `p`, shifting vertices by the *truncated* `p`
    /// (reference quirk); with `keep_placement` the translation becomes the world
    /// position of `p` so the panel stays where it was (up to the fractional part).
    pub fn set_pivot(self, a: &mut Arena, p: Vec2, keep_placement: bool) {
        if keep_placement {
            let t = self.point_to_3d(a, p);
            a.pd_mut(self).translation = t;
        }
        let shift = Vec2::new(trunc(p.x), trunc(p.y));
        let mut verts = self.edges(a).verts(a);
        for seq in self.inner_edges(a) {
            verts.extend(seq.verts(a));
        }
        for v in verts {
            let q = a.pos(v);
            a.set_pos(v, Vec2::new(q.x - shift.x, q.y - shift.y));
        }
    }

    /// Pivot at the middle of whichever side of the (vertex) bounding box is highest
    /// in 3D.
    pub fn top_center_pivot(self, a: &mut Arena) -> Self {
        let pts = self.edges(a).vert_positions(a);
        let (mut lo, mut hi) = (pts[0], pts[0]);
        for p in &pts {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let mid = Vec2::new((hi.x + lo.x) / 2.0, (hi.y + lo.y) / 2.0);
        let candidates = [Vec2::new(mid.x, hi.y), Vec2::new(mid.x, lo.y), Vec2::new(hi.x, mid.y), Vec2::new(lo.x, mid.y)];
        let mut best = 0;
        let mut best_y = f64::NEG_INFINITY;
        for (i, c) in candidates.iter().enumerate() {
            let y = self.point_to_3d(a, *c).y;
            if y > best_y {
                best_y = y;
                best = i;
            }
        }
        self.set_pivot(a, candidates[best], false);
        self
    }

    /// Approximate centre: mean of the loop vertices with three extra points per edge.
    pub fn center_2d(self, a: &Arena) -> Vec2 {
        let pts = self.edges(a).linearized_positions_n(a, Some(3));
        let mut s = Vec2::ZERO;
        for p in &pts {
            s += *p;
        }
        s / pts.len() as f64
    }

    /// Shift along x so the panel's centre sits on the body's centre line.
    pub fn center_x(self, a: &mut Arena) -> Self {
        let c = self.point_to_3d(a, self.center_2d(a));
        a.pd_mut(self).translation.x += -c.x;
        self
    }

    /// 2D bounding box of the linearised loop.
    pub fn bbox(self, a: &Arena) -> (Vec2, Vec2) {
        self.edges(a).with_linearized_positions(a, None, |pts| {
            let (mut lo, mut hi) = (pts[0], pts[0]);
            for p in pts {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
            (lo, hi)
        })
    }

    /// 3D bounding box of the linearised loop.
    pub fn bbox3d(self, a: &Arena) -> (Vec3, Vec3) {
        self.edges(a).with_linearized_positions(a, None, |pts| {
            let mut lo = Vec3::splat(f64::INFINITY);
            let mut hi = Vec3::splat(f64::NEG_INFINITY);
            for &p in pts {
                let w = self.point_to_3d(a, p);
                lo = lo.min(w);
                hi = hi.max(w);
            }
            (lo, hi)
        })
    }

    /// Length of the panel: its bounding-box height, or the length of its length
    /// interface when one was set.
    pub fn length(self, a: &Arena) -> f64 {
        if let Some(i) = a.pd(self).length_interface {
            return i.length(a);
        }
        let (lo, hi) = self.bbox(a);
        (hi.y - lo.y).abs()
    }

    /// Mirror across the world plane x = 0 (local y axis), keeping the fabric's right
    /// side outward.
    pub fn mirror(self, a: &mut Arena) -> Self {
        let edges = a.pd(self).edges.clone();
        edges.reflect(a, Vec2::ZERO, Vec2::Y);
        for seq in self.inner_edges(a).cloned().collect::<Vec<_>>() {
            seq.reflect(a, Vec2::ZERO, Vec2::Y);
        }
        a.pd_mut(self).translation.x *= -1.0;
        let mut e = a.pd(self).rotation.as_euler_xyz();
        e[1] *= -1.0;
        e[2] *= -1.0;
        self.rotate_to(a, Rotation::from_euler_xyz(e));
        self.autonorm(a);
        self
    }

    /// Insert a dart shape into `edge` centred at arc length `offset` on `side`, and
    /// stitch its two legs together. Returns the cut: the edges replacing `edge`,
    /// the dart's legs and the leftover pieces of the original edge. The panel loop
    /// is not modified (callers substitute).
    pub fn add_dart(self, a: &mut Arena, shape: &EdgeSeq, edge: EdgeId, offset: f64, side: EdgeSide) -> Result<Cut> {
        let cut = crate::ops::cut_into_edge(a, shape, edge, offset, side)?;
        if cut.shape.len() < 2 {
            // A dart narrower than the closeness tolerance collapses to one edge.
            return Err(crate::Error::Dart(format!(
                "the dart in panel '{}' is too narrow to cut ({} edge(s) left of its two legs)",
                self.name(a),
                cut.shape.len()
            )));
        }
        let l0 = a.interface(self, cut.shape[0]);
        let l1 = a.interface(self, cut.shape[1]);
        let rule = StitchRule::new(a, l0, l1)?;
        self.add_stitch(a, rule);
        Ok(cut)
    }

    /// Whether the outline crosses itself (the reference's check: arcs replaced by 11
    /// straight pieces, every pair of pieces intersected, shared vertices ignored).
    pub fn is_self_intersecting(self, a: &Arena) -> bool {
        crate::intersect::has_self_intersection(&crate::intersect::panel_segments(a, self))
    }

    /// With [`Arena::stop_at_self_intersection`] on, fail if the outline crosses
    /// itself; otherwise do nothing. Garment programs call it where an outline is
    /// complete but for the splits that later stitches make (splitting an edge keeps
    /// its points, so a crossing stays one).
    pub fn check_outline(self, a: &Arena) -> Result<()> {
        if a.stop_at_self_intersection && self.is_self_intersecting(a) {
            return Err(crate::error::Error::SelfIntersecting { panel: self.name(a).to_string() });
        }
        Ok(())
    }
}

impl PanelId {
    /// Flatten into the written panel: reset the pivot to the first vertex (with the
    /// reference's truncation), write vertices once each (consecutive equal
    /// coordinates merged) and record every edge's index for stitches. Holes and
    /// inner lines are written the same way, each over its own vertices.
    pub fn assemble(self, a: &mut Arena) -> Result<crate::pattern::PanelSpec> {
        use crate::pattern::{Hole, InnerLine, PanelSpec};
        let name = self.name(a).to_string();
        if self.edges(a).is_empty() {
            return Err(crate::error::Error::Design(format!("panel '{name}' has no edges")));
        }
        let first = a.pos(a.start(self.edges(a)[0]));
        self.set_pivot(a, first, true);
        let (vertices, specs) = write_edges(a, &self.edges(a).clone(), EdgePlace::Outline, true);
        let d = a.pd(self);
        let mut spec = PanelSpec::new(
            &name,
            d.translation.into(),
            d.rotation.as_euler_xyz_degrees(),
            vertices,
            specs,
            (!d.label.is_empty()).then(|| d.label.clone()),
        );
        spec.layer = d.layer;
        let (holes, lines) = (d.holes.clone(), d.lines.clone());
        for (k, h) in holes.into_iter().enumerate() {
            let (vertices, edges) = write_edges(a, &h.edges, EdgePlace::Hole(k), true);
            spec.holes.push(Hole { name: h.name, kind: h.kind, vertices, edges });
        }
        for (k, l) in lines.into_iter().enumerate() {
            let (vertices, edges) = write_edges(a, &l.edges, EdgePlace::Line(k), false);
            spec.lines.push(InnerLine { name: l.name, kind: l.kind, vertices, edges });
        }
        Ok(spec)
    }
}

/// Vertices and edge records of a chain of edges as written (consecutive equal
/// vertices merged; a `closed` chain's last edge ends at vertex 0), each edge's
/// index and place recorded for stitches.
fn write_edges(a: &mut Arena, edges: &EdgeSeq, place: EdgePlace, closed: bool) -> (Vec<[f64; 2]>, Vec<EdgeSpec>) {
    use crate::pattern::Curvature;
    let mut vertices: Vec<Vec2> = vec![a.pos(a.start(edges[0]))];
    let mut specs = Vec::with_capacity(edges.len());
    for (i, &e) in edges.iter().enumerate() {
        let g = a.geom(e);
        let shift = if *vertices.last().expect("non-empty") == g.start {
            vertices.push(g.end);
            vertices.len() - 2
        } else {
            vertices.push(g.start);
            vertices.push(g.end);
            vertices.len() - 2
        };
        let d = &mut a.edges[e.0 as usize];
        d.geometric_id = i as u32;
        d.place = place;
        let curvature = match g.curve {
            crate::edge::Curve::Line => None,
            crate::edge::Curve::Arc { .. } => {
                let (r, large, right) = g.arc_radius_flags().expect("arc");
                Some(Curvature::Circle { radius: r, large_arc: large, right })
            }
            crate::edge::Curve::Quadratic(c) => Some(Curvature::Quadratic(c.into())),
            crate::edge::Curve::Cubic(c1, c2) => Some(Curvature::Cubic(c1.into(), c2.into())),
        };
        let label = a.edge_label(e);
        specs.push(EdgeSpec { endpoints: [shift, shift + 1], label: (!label.is_empty()).then(|| label.to_string()), curvature });
    }
    if closed && vertices.len() > 1 && vertices.last() == vertices.first() {
        vertices.pop();
        specs.last_mut().expect("non-empty").endpoints[1] = 0;
    }
    (vertices.into_iter().map(|v| v.into()).collect(), specs)
}
