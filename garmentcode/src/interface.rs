//! Interfaces: the ordered edges of one or several panels that a component exposes for
//! stitching, with gather (ruffle) factors.
//!
//! An interface is an object with identity (an [`InterfaceId`] into the arena): a
//! stitch that splits edges updates the interface it was given, and every component
//! holding that interface sees the split, as in the reference.

use crate::arena::EdgeSeq;
use crate::arena::{Arena, EdgeId, InterfaceData, InterfaceId, PanelId, Ruffle};
use crate::error::{Error, Result};
use crate::math::{Vec3, close_enough};

/// Gather factors of a new interface: one for all edges, or one per edge (runs of
/// equal values become sections).
#[derive(Clone, Debug, PartialEq)]
pub enum Gather {
    /// The same factor for every edge.
    Uniform(f64),
    /// One factor per edge.
    PerEdge(Vec<f64>),
}

impl From<f64> for Gather {
    fn from(v: f64) -> Self {
        Gather::Uniform(v)
    }
}

impl Arena {
    pub(crate) fn iface(&self, i: InterfaceId) -> &InterfaceData {
        &self.interfaces[i.0 as usize]
    }

    pub(crate) fn iface_mut(&mut self, i: InterfaceId) -> &mut InterfaceData {
        &mut self.interfaces[i.0 as usize]
    }

    /// An empty interface record, with the buffers of one of a previous garment
    /// when there is one.
    pub(crate) fn blank_interface(&mut self) -> InterfaceData {
        let Some(mut d) = self.spare_interfaces.pop() else { return InterfaceData::default() };
        d.edges.0.clear();
        d.panels.clear();
        d.right_wrong.clear();
        d.flipping.clear();
        d.ruffle.clear();
        d
    }

    /// A new interface over `edges` of `panel`, flat (no gathers). The panel keeps a
    /// list of the interfaces made over it ([`PanelId::interfaces`]): a corner cut
    /// updates them and a copy of the panel copies them.
    pub fn interface(&mut self, panel: PanelId, edges: impl Into<EdgeSeq>) -> InterfaceId {
        self.interface_gathered(panel, edges, Gather::Uniform(1.0)).expect("uniform gathers always fit")
    }

    /// A new interface over `edges` of `panel` with gather factors.
    pub fn interface_gathered(&mut self, panel: PanelId, edges: impl Into<EdgeSeq>, gather: impl Into<Gather>) -> Result<InterfaceId> {
        let edges = edges.into();
        let n = edges.len();
        let gather = gather.into();
        if let Gather::PerEdge(coeffs) = &gather
            && coeffs.len() != n
        {
            return Err(Error::Interface(format!("{} gather factors for {n} edges", coeffs.len())));
        }
        let mut d = self.blank_interface();
        match gather {
            Gather::Uniform(c) => d.ruffle.push(Ruffle { coeff: c, start: 0, end: n }),
            Gather::PerEdge(coeffs) => {
                let mut start = 0;
                for i in 1..=n {
                    if i == n || coeffs[i] != coeffs[start] {
                        d.ruffle.push(Ruffle { coeff: coeffs[start], start, end: i });
                        start = i;
                    }
                }
            }
        }
        d.edges = edges;
        d.panels.resize(n, panel);
        d.right_wrong.resize(n, false);
        d.flipping.resize(n, false);
        self.interfaces.push(d);
        let id = InterfaceId((self.interfaces.len() - 1) as u32);
        // The panel knows its interfaces: a corner cut updates them, a copy copies them.
        self.pd_mut(panel).interfaces.push(id);
        Ok(id)
    }

    /// A new interface concatenating others (their edges, panels, flags and gather
    /// sections, in order). Later splits in the new interface do not reach the sources.
    pub fn interface_from(&mut self, parts: &[InterfaceId]) -> InterfaceId {
        // Copied from the sources in place (no clone of each source).
        let mut d = self.blank_interface();
        for &p in parts {
            let src = self.iface(p);
            let shift = d.edges.len();
            d.ruffle.extend(src.ruffle.iter().map(|r| Ruffle { coeff: r.coeff, start: r.start + shift, end: r.end + shift }));
            d.edges.extend_from_slice(&src.edges);
            d.panels.extend_from_slice(&src.panels);
            d.right_wrong.extend_from_slice(&src.right_wrong);
            d.flipping.extend_from_slice(&src.flipping);
        }
        self.interfaces.push(d);
        InterfaceId((self.interfaces.len() - 1) as u32)
    }
}

impl InterfaceId {
    /// The interface's edges, in order.
    pub fn edges(self, a: &Arena) -> &EdgeSeq {
        &a.iface(self).edges
    }

    /// The panel of every edge.
    pub fn panels(self, a: &Arena) -> &[PanelId] {
        &a.iface(self).panels
    }

    /// Number of edges.
    pub fn len(self, a: &Arena) -> usize {
        a.iface(self).edges.len()
    }

    /// No edges.
    pub fn is_empty(self, a: &Arena) -> bool {
        self.len(a) == 0
    }

    /// Gather sections.
    pub fn ruffle(self, a: &Arena) -> &[Ruffle] {
        &a.iface(self).ruffle
    }

    /// Per-edge right/wrong flags.
    pub fn right_wrong(self, a: &Arena) -> &[bool] {
        &a.iface(self).right_wrong
    }

    /// Per-edge "treat as reversed" flags.
    pub fn flipping(self, a: &Arena) -> &[bool] {
        &a.iface(self).flipping
    }

    /// Total length of the edges.
    pub fn length(self, a: &Arena) -> f64 {
        a.iface(self).edges.length(a)
    }

    /// Length every edge should project to on the other side of a seam: its length
    /// divided by its gather factor.
    pub fn projecting_lengths(self, a: &Arena) -> Vec<f64> {
        let d = a.iface(self);
        let n = d.edges.len();
        let mut out = Vec::with_capacity(n);
        for r in &d.ruffle {
            let (s, e) = (r.start.min(n), r.end.min(n));
            if s >= e {
                continue;
            }
            for &edge in &d.edges[s..e] {
                let l = a.edge_length(edge);
                out.push(if close_enough(r.coeff, 1.0, 1e-3) { l } else { l / r.coeff });
            }
        }
        out
    }

    /// [`InterfaceId::projecting_lengths`] normalised to sum to one.
    pub fn projecting_fractions(self, a: &Arena) -> Vec<f64> {
        let mut l = self.projecting_lengths(a);
        let total: f64 = l.iter().sum();
        l.iter_mut().for_each(|x| *x /= total);
        l
    }

    /// Reverse the order of the edges (not the edges themselves); with
    /// `flip_edges` also toggle every edge's "treat as reversed" flag.
    ///
    /// Reference quirk kept: the right/wrong flags keep their old order.
    pub fn reverse(self, a: &mut Arena, flip_edges: bool) -> Self {
        let d = a.iface_mut(self);
        d.edges.0.reverse();
        d.panels.reverse();
        d.flipping.reverse();
        if flip_edges {
            d.flipping.iter_mut().for_each(|f| *f = !*f);
        }
        let n = d.edges.len();
        for r in d.ruffle.iter_mut() {
            let (s, e) = (n - r.start.min(n), n - r.end.min(n));
            r.start = e;
            r.end = s;
        }
        self
    }

    /// Toggle every edge's "treat as reversed" flag.
    pub fn flip_edges(self, a: &mut Arena) -> Self {
        a.iface_mut(self).flipping.iter_mut().for_each(|f| *f = !*f);
        self
    }

    /// Set one edge's "treat as reversed" flag (stitch matching measures its split
    /// fractions from the other end).
    pub fn set_flip(self, a: &mut Arena, edge: usize, flag: bool) -> Self {
        a.iface_mut(self).flipping[edge] = flag;
        self
    }

    /// Mark every edge as sewn right side to wrong side.
    pub fn set_right_wrong(self, a: &mut Arena, flag: bool) -> Self {
        let d = a.iface_mut(self);
        d.right_wrong.iter_mut().for_each(|f| *f = flag);
        self
    }

    /// Set the label of every edge.
    pub fn propagate_label(self, a: &mut Arena, label: &str) {
        let edges = a.iface(self).edges.clone();
        edges.propagate_label(a, label);
    }

    /// Replace edge `orig` by `new_edges` (all of panel `panel`), repeating its flags
    /// and widening its gather section.
    pub fn substitute(self, a: &mut Arena, orig: EdgeId, new_edges: &[EdgeId], panel: PanelId) -> Result<()> {
        let d = a.iface_mut(self);
        let i = d.edges.index_of(orig).ok_or_else(|| Error::Interface("substitute: edge not in interface".into()))?;
        d.edges.substitute_at(i, new_edges);
        d.panels.remove(i);
        let flip = d.flipping.remove(i);
        let rw = d.right_wrong.remove(i);
        for j in 0..new_edges.len() {
            d.panels.insert(i + j, panel);
            d.flipping.insert(i + j, flip);
            d.right_wrong.insert(i + j, rw);
        }
        if new_edges.len() > 1 {
            let extra = new_edges.len() - 1;
            for r in d.ruffle.iter_mut() {
                if r.start > i {
                    r.start += extra;
                }
                if r.end > i {
                    r.end += extra;
                }
            }
        }
        Ok(())
    }

    /// Replace, in the edge list only, the edge `orig` by `new` (one for one; flags
    /// keep their positions). Used when a corner cut shortens an edge.
    pub(crate) fn replace_edge(self, a: &mut Arena, orig: EdgeId, new: EdgeId) {
        let d = a.iface_mut(self);
        if let Some(i) = d.edges.index_of(orig) {
            d.edges[i] = new;
        }
    }

    /// World-space bounding box of the linearised edges.
    pub fn bbox3d(self, a: &Arena) -> (Vec3, Vec3) {
        let d = a.iface(self);
        let mut lo = Vec3::splat(f64::INFINITY);
        let mut hi = Vec3::splat(f64::NEG_INFINITY);
        let mut seq = EdgeSeq(Vec::with_capacity(1));
        for (&e, &p) in d.edges.iter().zip(d.panels.iter()) {
            seq.clear();
            seq.push(e);
            seq.with_linearized_positions(a, None, |pts| {
                for &v in pts {
                    let w = p.point_to_3d(a, v);
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
            });
        }
        (lo, hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec2;

    #[test]
    fn per_edge_gathers_become_sections() {
        let mut a = Arena::new();
        let p = a.new_panel("p");
        let s = EdgeSeq::from_points(&mut a, &[Vec2::ZERO, Vec2::X, Vec2::new(2., 0.), Vec2::new(3., 0.)], false).unwrap();
        let i = a.interface_gathered(p, s, Gather::PerEdge(vec![1.0, 1.0, 2.0])).unwrap();
        assert_eq!(i.ruffle(&a), &[Ruffle { coeff: 1.0, start: 0, end: 2 }, Ruffle { coeff: 2.0, start: 2, end: 3 }]);
        assert_eq!(i.projecting_lengths(&a), vec![1.0, 1.0, 0.5]);
        i.reverse(&mut a, true);
        assert_eq!(i.ruffle(&a), &[Ruffle { coeff: 1.0, start: 1, end: 3 }, Ruffle { coeff: 2.0, start: 0, end: 1 }]);
        assert!(i.flipping(&a).iter().all(|f| *f));
    }
}
