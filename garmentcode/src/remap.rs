//! Copies of parts: a panel, a panel class or a whole component copied with every id
//! it holds remapped to the copy's own, so a copy of a `ThinSkirtPanel` is a
//! `ThinSkirtPanel` with its own panel, edges and interfaces (the reference copies
//! components with Python's `deepcopy`).
//!
//! `#[derive(Component)]` implements [`Remap`] for components and panel classes;
//! [`Arena::copy_part`] (behind [`PartExt::deep_copy`](crate::PartExt::deep_copy) and
//! the distributing operators) uses it.

use crate::arena::EdgeSeq;
use crate::arena::PanelData;
use crate::arena::StitchRule;
use crate::arena::{Arena, EdgeId, InterfaceId, PanelId};

/// Old and new ids of one copy: the copied panels, their edges and the interfaces
/// copied with them.
#[derive(Debug, Default)]
pub struct IdMap {
    panels: Vec<(PanelId, PanelId)>,
    edges: Vec<(EdgeId, EdgeId)>,
    interfaces: Vec<(InterfaceId, InterfaceId)>,
}

impl IdMap {
    /// The copy of panel `p`, if it was copied.
    pub fn panel(&self, p: PanelId) -> Option<PanelId> {
        find(&self.panels, p)
    }

    /// The copy of edge `e`, if it was copied.
    pub fn edge(&self, e: EdgeId) -> Option<EdgeId> {
        find(&self.edges, e)
    }

    /// The copy of interface `i`, if it was copied.
    pub fn interface(&self, i: InterfaceId) -> Option<InterfaceId> {
        find(&self.interfaces, i)
    }
}

fn find<T: PartialEq + Copy>(pairs: &[(T, T)], old: T) -> Option<T> {
    pairs.iter().find(|(o, _)| *o == old).map(|(_, n)| *n)
}

/// A value that can follow a copy: the same value with the ids of copied panels,
/// edges and interfaces replaced by those of the copy. Ids outside the copy stay as
/// they are.
///
/// Implemented for the ids, edge sequences, stitches and their `Vec`, `Option` and
/// `Box`; `#[derive(Component)]` implements it for components and panel classes.
///
/// ```
/// use garmentcode::{Part, PartExt, Remap};
/// # use garmentcode::{Arena, EdgeSeq, InterfaceId, PanelId, Vec2};
/// # /// A rectangle `width` wide and 10 high, with `top` and `side` interfaces.
/// # #[derive(garmentcode::Component)]
/// # struct Band {
/// #     #[panel]
/// #     panel: PanelId,
/// #     #[interface]
/// #     top: InterfaceId,
/// #     #[interface]
/// #     side: InterfaceId,
/// # }
/// # impl Band {
/// #     fn new(a: &mut Arena, name: &str, width: f64) -> garmentcode::Result<Band> {
/// #         let corners = [Vec2::ZERO, Vec2::new(0.0, 10.0), Vec2::new(width, 10.0), Vec2::new(width, 0.0)];
/// #         let edges = EdgeSeq::from_points(a, &corners, true)?;
/// #         let panel = a.panel_with_edges(name, edges.clone());
/// #         Ok(Band { panel, side: a.interface(panel, edges[0]), top: a.interface(panel, edges[1]) })
/// #     }
/// # }
///
/// let mut a = Arena::new();
/// let band = Band::new(&mut a, "band", 20.0)?;
/// fn twin<T: Part + Remap>(part: &T, a: &mut Arena) -> T {
///     part.deep_copy(a)
/// }
/// let copy = twin(&band, &mut a);
/// // The copy's interfaces lie on the copy's panel, at the same places.
/// assert_eq!(copy.top.panels(&a), [copy.panel]);
/// assert_eq!(copy.top.length(&a), band.top.length(&a));
/// assert_eq!(copy.panel.interfaces(&a), [copy.side, copy.top]);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` cannot be copied with its ids remapped",
    label = "a component field of this type cannot follow a copy",
    note = "derive `Component` for parts; fields that hold ids (`InterfaceId`, `PanelId`, `EdgeSeq`, `StitchRule`) are remapped, other fields must be `Clone`"
)]
pub trait Remap: Sized {
    /// This value in the copy described by `map`.
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self;
}

impl Remap for PanelId {
    fn remap(&self, _: &mut Arena, map: &mut IdMap) -> Self {
        map.panel(*self).unwrap_or(*self)
    }
}

impl Remap for EdgeId {
    fn remap(&self, _: &mut Arena, map: &mut IdMap) -> Self {
        map.edge(*self).unwrap_or(*self)
    }
}

impl Remap for EdgeSeq {
    fn remap(&self, _: &mut Arena, map: &mut IdMap) -> Self {
        EdgeSeq(self.iter().map(|e| map.edge(*e).unwrap_or(*e)).collect())
    }
}

/// An interface over a copied panel is copied (once: every holder of the original
/// gets the same copy); one over other panels only is kept.
impl Remap for InterfaceId {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        if let Some(copy) = map.interface(*self) {
            return copy;
        }
        let src = a.iface(*self);
        if !src.panels.iter().any(|p| map.panel(*p).is_some()) {
            return *self;
        }
        // Into the buffers of a spare record, as `Arena::interface` does: a clone
        // would add a record to the spares at every `Arena::clear`.
        let mut d = a.blank_interface();
        d.copy_from(a.iface(*self));
        for e in d.edges.iter_mut() {
            *e = map.edge(*e).unwrap_or(*e);
        }
        for p in d.panels.iter_mut() {
            *p = map.panel(*p).unwrap_or(*p);
        }
        a.interfaces.push(d);
        let copy = InterfaceId((a.interfaces.len() - 1) as u32);
        map.interfaces.push((*self, copy));
        copy
    }
}

impl Remap for StitchRule {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        StitchRule { a: self.a.remap(a, map), b: self.b.remap(a, map) }
    }
}

impl<T: Remap> Remap for Vec<T> {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        self.iter().map(|x| x.remap(a, map)).collect()
    }
}

impl<T: Remap> Remap for Option<T> {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        self.as_ref().map(|x| x.remap(a, map))
    }
}

impl<T: Remap> Remap for Box<T> {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        Box::new((**self).remap(a, map))
    }
}

impl Arena {
    /// A new panel with copies of `p`'s edges (vertex sharing kept).
    pub(crate) fn copy_panel_geometry(&mut self, p: PanelId, map: &mut IdMap) {
        if map.panel(p).is_some() {
            return;
        }
        let src = self.pd(p);
        let (name, label, translation, rotation) = (src.name.clone(), src.label.clone(), src.translation, src.rotation);
        let (mut holes, mut lines, layer) = (src.holes.clone(), src.lines.clone(), src.layer);
        let old_edges = src.edges.clone();
        let new_edges = self.copy_edges(&old_edges);
        map.edges.extend(old_edges.iter().copied().zip(new_edges.iter().copied()));
        let inner = holes.iter_mut().map(|h| &mut h.edges).chain(lines.iter_mut().map(|l| &mut l.edges));
        for seq in inner {
            let copy = self.copy_edges(seq);
            map.edges.extend(seq.iter().copied().zip(copy.iter().copied()));
            *seq = EdgeSeq(copy);
        }
        self.panels.push(PanelData {
            name,
            label,
            translation,
            rotation,
            edges: EdgeSeq(new_edges),
            interfaces: Vec::new(),
            stitches: Vec::new(),
            length_interface: None,
            holes,
            lines,
            layer,
        });
        map.panels.push((p, PanelId((self.panels.len() - 1) as u32)));
    }

    /// The copy of `p` gets copies of its interfaces, darts and length interface.
    pub(crate) fn copy_panel_links(&mut self, p: PanelId, map: &mut IdMap) {
        let Some(new) = map.panel(p) else { return };
        let src = self.pd(p);
        let (interfaces, stitches, length) = (src.interfaces.clone(), src.stitches.clone(), src.length_interface);
        let interfaces = interfaces.remap(self, map);
        let stitches = stitches.remap(self, map);
        let length = length.remap(self, map);
        let d = self.pd_mut(new);
        d.interfaces = interfaces;
        d.stitches = stitches;
        d.length_interface = length;
    }
}
