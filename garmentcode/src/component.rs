//! Components: hierarchies of panels and sub-components, placed as rigid blocks and
//! assembled into the flat pattern.
//!
//! A garment program's types implement [`Part`] (usually through the
//! `#[derive(Component)]` macro): a part is either a panel ([`Node::Panel`]) or a
//! component ([`Node::Component`]) that lists its sub-parts in a fixed order and owns
//! stitches. Placement (translate, rotate about the block's top centre, mirror),
//! bounding boxes, lengths, labels and assembly are defined once here on [`Node`].

use crate::arena::StitchRule;
use crate::arena::{Arena, InterfaceId, PanelId};
use crate::error::{Error, Result};
use crate::math::Vec3;
use crate::pattern::Pattern;
use crate::remap::{IdMap, Remap};
use crate::rotation::Rotation;
use crate::stitch::StitchRecord;

/// What a part is: a single panel or a component with sub-parts.
#[derive(Clone, Copy)]
pub enum Node<'a> {
    /// A panel (or a panel class wrapping one).
    Panel(PanelId),
    /// A component.
    Component(&'a dyn Component),
}

/// Something placeable and assemblable: a panel, a panel class or a component.
///
/// Implemented by `#[derive(Component)]`; [`PartExt`] adds the methods:
///
/// ```
/// use garmentcode::{Node, Part};
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
/// assert!(matches!(band.node(), Node::Panel(p) if p == band.panel));
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a garment part",
    label = "not a panel, panel class or component",
    note = "add `#[derive(Component)]` (or `#[component]`) to the type: a struct with a `#[panel]` field is a panel class, one with `#[part]` fields a component, an enum of parts a choice between them"
)]
pub trait Part {
    /// This part as a panel or a component.
    fn node(&self) -> Node<'_>;
}

impl Part for PanelId {
    fn node(&self) -> Node<'_> {
        Node::Panel(*self)
    }
}

impl<T: Part + ?Sized> Part for &T {
    fn node(&self) -> Node<'_> {
        (**self).node()
    }
}

impl<T: Part + ?Sized> Part for Box<T> {
    fn node(&self) -> Node<'_> {
        (**self).node()
    }
}

/// A part that is one panel: a [`PanelId`], or a panel class (a struct with a
/// `#[panel]` field, for which `#[derive(Component)]` implements this trait).
///
/// ```
/// use garmentcode::PanelPart;
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
/// fn panel_name<P: PanelPart>(part: &P, a: &Arena) -> String {
///     part.panel_id().name(a).to_string()
/// }
///
/// let mut a = Arena::new();
/// let band = Band::new(&mut a, "band", 20.0)?;
/// assert_eq!(panel_name(&band, &a), "band");
/// assert_eq!(panel_name(&band.panel, &a), "band");
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a panel",
    label = "a panel or panel class is needed here: something with one panel surface",
    note = "pass a `PanelId` or a struct with `#[derive(Component)]` and a `#[panel]` field; a component of several panels or an edge sequence has no single surface to cut, fold or sew onto"
)]
pub trait PanelPart: Part {
    /// The panel.
    fn panel_id(&self) -> PanelId;
}

impl PanelPart for PanelId {
    fn panel_id(&self) -> PanelId {
        *self
    }
}

/// A garment component: an ordered set of sub-parts plus the stitches between them.
///
/// Implemented by `#[derive(Component)]` on a struct with `#[part]` fields:
///
/// ```
/// use garmentcode::{Component, PartExt, StitchRule};
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
/// #[derive(Component)]
/// #[component(name = "belt")]
/// struct Belt {
///     #[part]
///     front: Band,
///     #[part]
///     back: Band,
///     #[stitches]
///     seams: Vec<StitchRule>,
/// }
///
/// let mut a = Arena::new();
/// let (front, back) = (Band::new(&mut a, "front", 40.0)?, Band::new(&mut a, "back", 40.0)?);
/// let seams = vec![StitchRule::new(&mut a, front.side, back.side)?];
/// let belt = Belt { front, back, seams };
/// assert_eq!((belt.name(), belt.stitches().len()), ("belt".to_string(), 1));
/// let mut parts = 0;
/// belt.for_each_part(&mut |_| parts += 1);
/// assert_eq!(parts, 2);
/// assert_eq!(belt.panel_ids(), [belt.front.panel, belt.back.panel]);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a component",
    label = "no `#[derive(Component)]` with `#[part]` fields",
    note = "add `#[derive(Component)]` to a struct whose `#[part]` fields hold its panels and sub-components"
)]
pub trait Component {
    /// Name of the component (informational; panel names are what is written).
    fn name(&self) -> String;

    /// Visit the direct sub-parts in order (the assembly order).
    fn for_each_part(&self, f: &mut dyn FnMut(&dyn Part));

    /// The component's own stitches, in creation order.
    fn stitches(&self) -> Vec<StitchRule>;

    /// Vertical length of the component, by default the sum of its parts' lengths.
    fn length(&self, a: &Arena) -> f64 {
        let mut total = 0.0;
        self.for_each_part(&mut |p| total += p.node().length(a));
        total
    }
}

/// The interfaces a component or panel class exposes (its `#[interface]` fields)
/// with their names, in declaration order: for tools that list or inspect parts.
/// Garment code uses the fields themselves (or [`Slot`]), never names.
pub trait Interfaces {
    /// `(name, interface)` of every exposed interface (an absent optional one is
    /// left out).
    fn interfaces(&self) -> Vec<(&'static str, InterfaceId)>;
}

/// A bare panel exposes no named interfaces (its interfaces are
/// [`PanelId::interfaces`]).
impl Interfaces for PanelId {
    fn interfaces(&self) -> Vec<(&'static str, InterfaceId)> {
        Vec::new()
    }
}

/// A component that fills slot `S` (a marker type from [`crate::slots`] or your
/// own): it exposes the interface that slot connects through. Requiring
/// `Slot<Top>` of a bottom garment makes plugging in a component without a `top`
/// interface a compile error.
///
/// `#[derive(Component)]` implements it for every `#[interface]` field named like a
/// slot marker (`top` fills [`slots::Top`](crate::slots::Top)):
///
/// ```
/// use garmentcode::slots::Top;
/// use garmentcode::{Slot, SlotExt};
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
/// /// Anything with a `top` interface.
/// fn waistline<B: Slot<Top>>(bottom: &B, a: &Arena) -> f64 {
///     bottom.iface::<Top>().length(a)
/// }
///
/// let mut a = Arena::new();
/// let band = Band::new(&mut a, "band", 20.0)?;
/// assert_eq!(waistline(&band, &a), 20.0);
/// assert_eq!(Slot::<Top>::slot(&band), band.top);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` does not expose the interface slot `{S}` needs",
    label = "no `#[interface]` for slot `{S}`",
    note = "declare the interface on the component with `#[interface]` on an `InterfaceId` field named after the slot (e.g. `top`)"
)]
pub trait Slot<S> {
    /// The interface filling the slot.
    fn slot(&self) -> InterfaceId;
}

impl<S, T: Slot<S> + ?Sized> Slot<S> for Box<T> {
    fn slot(&self) -> InterfaceId {
        (**self).slot()
    }
}

impl<S, T: Slot<S> + ?Sized> Slot<S> for &T {
    fn slot(&self) -> InterfaceId {
        (**self).slot()
    }
}

/// `x.iface::<Top>()` instead of `Slot::<Top>::slot(&x)`.
pub trait SlotExt {
    /// The interface filling slot `S`.
    fn iface<S>(&self) -> InterfaceId
    where
        Self: Slot<S>,
    {
        Slot::<S>::slot(self)
    }
}

impl<T: ?Sized> SlotExt for T {}

/// Collects `&dyn Part`s from component fields of various shapes (a part, an
/// optional part, a list of parts); used by the derive macro.
#[diagnostic::on_unimplemented(
    message = "a `#[part]` field of type `{Self}` holds no garment parts",
    label = "expected a part, `Option` of a part or `Vec` of parts",
    note = "a `#[part]` field holds a `PanelId`, a type with `#[derive(Component)]`, or an `Option`/`Vec`/`Box` of those"
)]
pub trait Parts {
    /// Visit every part held by this field.
    fn visit_parts(&self, f: &mut dyn FnMut(&dyn Part));
}

impl<T: Part> Parts for T {
    fn visit_parts(&self, f: &mut dyn FnMut(&dyn Part)) {
        f(self)
    }
}

impl<T: Part> Parts for Option<T> {
    fn visit_parts(&self, f: &mut dyn FnMut(&dyn Part)) {
        if let Some(p) = self {
            f(p)
        }
    }
}

impl<T: Part> Parts for Vec<T> {
    fn visit_parts(&self, f: &mut dyn FnMut(&dyn Part)) {
        for p in self {
            f(p)
        }
    }
}

impl Node<'_> {
    /// Pivot: a panel's origin; a component's top centre (centre x and z, top y of its
    /// bounding box).
    pub fn pivot_3d(&self, a: &Arena) -> Vec3 {
        match self {
            Node::Panel(p) => PanelId::translation(*p, a),
            Node::Component(_) => {
                let (lo, hi) = self.bbox3d(a);
                Vec3::new((lo.x + hi.x) / 2.0, hi.y, (lo.z + hi.z) / 2.0)
            }
        }
    }

    /// 3D bounding box of the linearised outlines (infinite and inverted when empty).
    pub fn bbox3d(&self, a: &Arena) -> (Vec3, Vec3) {
        match self {
            Node::Panel(p) => PanelId::bbox3d(*p, a),
            Node::Component(c) => {
                let mut lo = Vec3::splat(f64::INFINITY);
                let mut hi = Vec3::splat(f64::NEG_INFINITY);
                c.for_each_part(&mut |p| {
                    let (l, h) = p.node().bbox3d(a);
                    lo = lo.min(l);
                    hi = hi.max(h);
                });
                (lo, hi)
            }
        }
    }

    /// Move by `d`.
    pub fn translate_by(&self, a: &mut Arena, d: Vec3) {
        match self {
            Node::Panel(p) => {
                PanelId::translate_by(*p, a, d);
            }
            Node::Component(c) => c.for_each_part(&mut |p| p.node().translate_by(a, d)),
        }
    }

    /// Place the pivot at `t`, keeping the relative placement of sub-parts.
    pub fn translate_to(&self, a: &mut Arena, t: Vec3) {
        match self {
            Node::Panel(p) => {
                PanelId::translate_to(*p, a, t);
            }
            Node::Component(c) => {
                let pivot = self.pivot_3d(a);
                c.for_each_part(&mut |p| {
                    let n = p.node();
                    let sub = n.pivot_3d(a);
                    n.translate_to(a, t + (sub - pivot));
                });
            }
        }
    }

    /// Rotate by `q` about the pivot as a rigid block.
    pub fn rotate_by(&self, a: &mut Arena, q: Rotation) {
        match self {
            Node::Panel(p) => {
                PanelId::rotate_by(*p, a, q);
            }
            Node::Component(c) => {
                let pivot = self.pivot_3d(a);
                c.for_each_part(&mut |p| {
                    let n = p.node();
                    let rel = n.pivot_3d(a) - pivot;
                    let rotated = q.apply(rel);
                    n.rotate_by(a, q);
                    n.translate_by(a, rotated - rel);
                });
            }
        }
    }

    /// Mirror across the world plane x = 0.
    pub fn mirror(&self, a: &mut Arena) {
        match self {
            Node::Panel(p) => {
                PanelId::mirror(*p, a);
            }
            Node::Component(c) => c.for_each_part(&mut |p| p.node().mirror(a)),
        }
    }

    /// Length: a panel's length, or the component's own notion of length.
    pub fn length(&self, a: &Arena) -> f64 {
        match self {
            Node::Panel(p) => PanelId::length(*p, a),
            Node::Component(c) => c.length(a),
        }
    }

    /// Set the label of every panel (with `overwrite = false`, only empty labels).
    pub fn set_panel_label(&self, a: &mut Arena, label: &str, overwrite: bool) {
        match self {
            Node::Panel(p) => PanelId::set_label(*p, a, label, overwrite),
            Node::Component(c) => c.for_each_part(&mut |p| p.node().set_panel_label(a, label, overwrite)),
        }
    }

    /// Whether any panel's outline crosses itself.
    pub fn is_self_intersecting(&self, a: &Arena) -> bool {
        match self {
            Node::Panel(p) => PanelId::is_self_intersecting(*p, a),
            Node::Component(c) => {
                let mut any = false;
                c.for_each_part(&mut |p| any = any || p.node().is_self_intersecting(a));
                any
            }
        }
    }

    /// Every panel, in assembly order.
    pub fn panels(&self, out: &mut Vec<PanelId>) {
        match self {
            Node::Panel(p) => out.push(*p),
            Node::Component(c) => c.for_each_part(&mut |p| p.node().panels(out)),
        }
    }

    /// Every stitch, in assembly order: a panel's darts; a component's parts' stitches
    /// then its own.
    pub fn stitches(&self, a: &Arena, out: &mut Vec<StitchRule>) {
        match self {
            Node::Panel(p) => out.extend_from_slice(p.stitches(a)),
            Node::Component(c) => {
                c.for_each_part(&mut |p| p.node().stitches(a, out));
                out.extend(c.stitches());
            }
        }
    }
}

/// Placement and assembly methods for every [`Part`].
///
/// ```
/// use garmentcode::{PartExt, Vec3};
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
/// band.translate_by(&mut a, Vec3::new(0.0, 100.0, 5.0));
/// let (lo, hi) = band.bbox3d(&a);
/// assert_eq!((lo.y, hi.y, lo.z), (100.0, 110.0, 5.0));
/// // A deep copy is a `Band` with its own panel and interfaces.
/// let copy = band.deep_copy(&mut a);
/// assert!(copy.panel != band.panel && copy.top != band.top);
/// let pattern = band.assemble(&mut a, "one band")?;
/// assert_eq!(pattern.panels.len(), 1);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub trait PartExt: Part {
    /// See [`Node::translate_by`].
    fn translate_by(&self, a: &mut Arena, d: Vec3) -> &Self {
        self.node().translate_by(a, d);
        self
    }
    /// See [`Node::translate_to`].
    fn translate_to(&self, a: &mut Arena, t: Vec3) -> &Self {
        self.node().translate_to(a, t);
        self
    }
    /// See [`Node::rotate_by`].
    fn rotate_by(&self, a: &mut Arena, q: Rotation) -> &Self {
        self.node().rotate_by(a, q);
        self
    }
    /// See [`Node::mirror`].
    fn mirror(&self, a: &mut Arena) -> &Self {
        self.node().mirror(a);
        self
    }
    /// See [`Node::bbox3d`].
    fn bbox3d(&self, a: &Arena) -> (Vec3, Vec3) {
        self.node().bbox3d(a)
    }
    /// See [`Node::pivot_3d`].
    fn pivot_3d(&self, a: &Arena) -> Vec3 {
        self.node().pivot_3d(a)
    }
    /// See [`Node::length`].
    fn part_length(&self, a: &Arena) -> f64 {
        self.node().length(a)
    }
    /// See [`Node::set_panel_label`].
    fn set_panel_label(&self, a: &mut Arena, label: &str, overwrite: bool) {
        self.node().set_panel_label(a, label, overwrite)
    }
    /// See [`Node::is_self_intersecting`].
    fn is_self_intersecting(&self, a: &Arena) -> bool {
        self.node().is_self_intersecting(a)
    }
    /// Every panel in assembly order.
    fn panel_ids(&self) -> Vec<PanelId> {
        let mut out = Vec::new();
        self.node().panels(&mut out);
        out
    }

    /// A deep copy: the same type over new panels, edges and interfaces (see
    /// [`Arena::copy_part`]).
    fn deep_copy(&self, a: &mut Arena) -> Self
    where
        Self: Remap + Sized,
    {
        a.copy_part(self)
    }

    /// Move down so that this part's top sits `gap` below `other`'s bottom.
    fn place_below(&self, a: &mut Arena, other: &dyn Part, gap: f64) -> &Self {
        let (olo, _) = other.node().bbox3d(a);
        let (_, shi) = self.node().bbox3d(a);
        self.node().translate_by(a, Vec3::new(0.0, olo.y - shi.y - gap, 0.0));
        self
    }

    /// Move so that interface `own` meets interface `target`, aligned as asked and
    /// `gap` outside along the interface's outward direction.
    fn place_by_interface(&self, a: &mut Arena, own: InterfaceId, target: InterfaceId, gap: f64, align: Align) -> &Self {
        let (slo, shi) = own.bbox3d(a);
        let (olo, ohi) = target.bbox3d(a);
        let mut p_out = (ohi + olo) / 2.0;
        let mut p_self = (shi + slo) / 2.0;
        match align {
            Align::Center => {}
            Align::Top => {
                p_out.y = ohi.y;
                p_self.y = shi.y;
            }
            Align::Bottom => {
                p_out.y = olo.y;
                p_self.y = slo.y;
            }
            Align::Right => {
                p_out.x = olo.x;
                p_self.x = slo.x;
            }
            Align::Left => {
                p_out.x = ohi.x;
                p_self.x = shi.x;
            }
        }
        let (flo, fhi) = self.node().bbox3d(a);
        let center = (flo + fhi) / 2.0;
        let mid_self = (shi + slo) / 2.0;
        let dir = mid_self - center;
        let g = gap * dir / dir.length();
        self.node().translate_by(a, p_out - (p_self + g));
        self
    }

    /// Assemble into the flat sewing pattern named `name`. Panel pivots are reset as
    /// the reference does (this moves vertices), so assemble a garment once.
    fn assemble(&self, a: &mut Arena, name: &str) -> Result<Pattern> {
        assemble(a, &self.node(), name)
    }
}

impl<T: Part + ?Sized> PartExt for T {}

/// Alignment for [`PartExt::place_by_interface`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// Centre to centre.
    Center,
    /// Tops (max y) aligned.
    Top,
    /// Bottoms (min y) aligned.
    Bottom,
    /// Min x aligned (the wearer's right).
    Right,
    /// Max x aligned.
    Left,
}

/// Assemble a part tree into a flat pattern.
pub fn assemble(a: &mut Arena, root: &Node<'_>, name: &str) -> Result<Pattern> {
    let mut panels = Vec::new();
    root.panels(&mut panels);
    let mut seen: Vec<PanelId> = Vec::with_capacity(panels.len());
    let mut specs = Vec::with_capacity(panels.len());
    for p in panels {
        if seen.contains(&p) {
            continue;
        }
        seen.push(p);
        let spec = p.assemble(a)?;
        if specs.iter().any(|s: &crate::pattern::PanelSpec| s.name == spec.name) {
            return Err(Error::Design(format!("two panels are named '{}'", spec.name)));
        }
        specs.push(spec);
    }
    let mut rules = Vec::new();
    root.stitches(a, &mut rules);
    let mut records: Vec<StitchRecord> = Vec::new();
    for r in &rules {
        r.records(a, &mut records);
    }
    Ok(Pattern::from_parts(name, specs, records))
}

impl Arena {
    /// A deep copy of `part`: new panels (same names, placement and labels), edges
    /// and vertices, the interfaces over them and the darts, and `part` rebuilt over
    /// them ([`Remap`]). Rename the copy's panels before assembling both.
    pub fn copy_part<T: Part + Remap>(&mut self, part: &T) -> T {
        let mut map = IdMap::default();
        let panels = part.panel_ids();
        for &p in &panels {
            self.copy_panel_geometry(p, &mut map);
        }
        // Interfaces may span several panels: link them once every panel is copied.
        for &p in &panels {
            self.copy_panel_links(p, &mut map);
        }
        part.remap(self, &mut map)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arena::{EdgeSeq, StitchRule};
    use crate::math::Vec2;

    fn square(a: &mut Arena, name: &str) -> (PanelId, InterfaceId, InterfaceId) {
        let pts = [Vec2::new(0.0, 0.0), Vec2::new(10.0, 0.0), Vec2::new(10.0, 10.0), Vec2::new(0.0, 10.0)];
        let edges = EdgeSeq::from_points(a, &pts, true).unwrap();
        let p = a.panel_with_edges(name, edges.clone());
        let bottom = a.interface(p, edges[0]);
        let top = a.interface(p, edges[2]);
        (p, bottom, top)
    }

    #[test]
    fn a_copied_panel_has_its_own_edges_and_interfaces() {
        let mut a = Arena::new();
        let (p, bottom, top) = square(&mut a, "p");
        let q = p.deep_copy(&mut a);
        assert_ne!(p, q);
        assert_eq!(q.name(&a), "p");
        assert_eq!(q.interfaces(&a).len(), 2);
        for (orig, copy) in p.interfaces(&a).to_vec().into_iter().zip(q.interfaces(&a).to_vec()) {
            assert_ne!(orig, copy);
            assert_eq!(copy.panels(&a), &[q]);
            assert!(copy.edges(&a).iter().all(|e| q.edges(&a).index_of(*e).is_some()));
            assert_eq!(a.geom(orig.edges(&a)[0]), a.geom(copy.edges(&a)[0]));
        }
        // Moving the copy's vertices leaves the original alone.
        let v = a.start(q.edges(&a)[0]);
        a.set_pos(v, Vec2::new(-5.0, -5.0));
        assert_eq!(a.pos(a.start(p.edges(&a)[0])), Vec2::new(0.0, 0.0));
        assert_eq!(bottom.panels(&a), &[p]);
        assert_eq!(top.panels(&a), &[p]);
    }

    #[test]
    fn shared_interfaces_stay_shared_and_outside_ids_stay() {
        let mut a = Arena::new();
        let (p, bottom, _) = square(&mut a, "p");
        let (other, other_top, _) = square(&mut a, "other");
        let seam = StitchRule { a: bottom, b: other_top };
        let held = vec![bottom, bottom];
        let mut map = IdMap::default();
        a.copy_panel_geometry(p, &mut map);
        a.copy_panel_links(p, &mut map);
        let held_copy = held.remap(&mut a, &mut map);
        let seam_copy = seam.remap(&mut a, &mut map);
        assert_eq!(held_copy[0], held_copy[1]);
        assert_eq!(Some(held_copy[0]), map.interface(bottom));
        assert_eq!(seam_copy.a, held_copy[0]);
        assert_eq!(seam_copy.b, other_top, "an interface of a panel outside the copy is kept");
        assert_eq!(other.remap(&mut a, &mut map), other);
    }
}
