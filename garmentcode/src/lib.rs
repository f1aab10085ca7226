//! # garmentcode
//!
//! The runtime of GarmentCode in Rust: sewing patterns as programs. Edges (lines,
//! circular arcs, quadratic and cubic Béziers with control points relative to the
//! edge), edge sequences, panels placed in 3D, components, interfaces and stitches,
//! the operators of the GarmentCode paper (darts, projecting shapes into edges and
//! onto corners, distributing copies, curve fitting), and the reference's flat
//! pattern format (`specification.json`) with validation and drawings.
//!
//! All geometry of one garment lives in an [`Arena`]; panels, edges and interfaces
//! are small copyable ids into it, so sharing and in-place edits behave as in the
//! reference implementation (pygarment), whose numbers this crate reproduces.
//!
//! ## Layout
//!
//! - The paper's concepts are types at the crate root: [`Edge`]/[`Curve`], [`Bezier`],
//!   [`SvgArc`], [`EdgeSeq`], panels ([`PanelId`]), [`Component`] and its [`slots`],
//!   interfaces ([`InterfaceId`], [`Gather`]), [`StitchRule`], [`Params`] and
//!   [`DesignSpace`], [`Body`], [`Pattern`], all stored in the [`Arena`].
//! - Function namespaces: [`ops`] (the paper's operators), [`curves`] (curve
//!   helpers), [`intersect`] (outline checks), [`math`].
//! - [`mesh`] (feature `mesh`, on by default): the reference's simulation box mesh
//!   of a pattern and its files.
//! - Apart from geometry: [`io`] (design files and design spaces, JSON Schema) and
//!   [`draw`] (SVG; PNG behind the `png` feature, on by default).
//! - [`parity`]: code that exists only to match the reference bit for bit (scipy's
//!   BFGS, svgpathtools with numpy/LAPACK roots, CPython's float `repr`, PyYAML),
//!   called from the concept modules through a function or two.
//!
//! Modules do not import each other in cycles (checked by the workspace's
//! `tests/layering.rs`). The pattern comparator is the separate `garmentcode-compare`
//! crate.

#![warn(missing_docs)]
// Doc examples compile without warnings (no unused imports or variables).
#![doc(test(attr(deny(warnings))))]

// Lets the derive macros' generated code name this crate as `::garmentcode` inside
// the crate's own tests and examples too.
extern crate self as garmentcode;

// The paper's concepts. Modules are private: their public items are re-exported
// below, each under one path.
mod arc;
mod arena;
mod bezier;
mod body;
mod component;
mod edge;
mod error;
mod interface;
mod memo;
mod panel;
mod params;
mod pattern;
mod remap;
mod rotation;
mod seq;
mod size_chart;
mod stitch;
#[cfg(test)]
mod test_data;

// Function namespaces.
pub mod curves;
pub mod guide;
pub mod inner;
pub mod intersect;
pub mod math;
#[cfg(feature = "mesh")]
pub mod mesh;
pub mod message;
pub mod ops;
pub mod slots;

// Input/output and drawings, apart from geometry.
pub mod draw;
#[cfg(feature = "print")]
pub mod fabricate;
pub mod io;

// Code that exists only to reproduce the reference bit for bit.
pub mod parity;

pub use arc::SvgArc;
pub use arena::{Arena, EdgeId, EdgeSeq, InterfaceId, PanelId, Ruffle, StitchRule, VertexId};
pub use bezier::Bezier;
pub use body::{Body, BodyError, BodyValue, DERIVED_VALUES, Derived, DerivedValue, MEASUREMENTS, Measurement, PROPORTIONS, RATIOS};
pub use component::{Align, Component, Interfaces, Node, PanelPart, Part, PartExt, Parts, Slot, SlotExt, assemble};
pub use edge::{Curve, Edge, Segment};
pub use error::{Error, Result};
pub use interface::Gather;
pub use params::sample::{Sampler, below, sample_rng};
pub use params::space::DesignSpace;
pub use params::spec::{Kind, ParamSpec, Range, Value};
pub use params::{Choice, ParamValue, Params, join_path};
pub use pattern::order::panel_order;
pub use pattern::validate::{Problem, ProblemKind, Severity, structural_errors, validate};
pub use pattern::{
    Curvature, EXTENSION_VERSION, EdgePlace, EdgeSpec, Hole, HoleKind, InnerLine, InnerSide, InnerStitch, Layer, LineKind, PanelSpec,
    Pattern, Properties, StitchSide, StitchSpec,
};
pub use remap::{IdMap, Remap};
pub use rotation::Rotation;
pub use size_chart::{MAX_SIZES, SizeChart};
pub use stitch::StitchRecord;

/// 2D point or vector (panel-local coordinates, centimetres).
pub type Vec2 = glam::DVec2;
/// 3D point or vector (world coordinates, centimetres).
pub type Vec3 = glam::DVec3;

/// A typed group of design parameters: the [`Params`](trait@Params) trait, with the
/// schema, defaults and typed access generated from the fields.
///
/// ```
/// use garmentcode::{Choice, Params};
///
/// /// How the hem is finished.
/// #[derive(Clone, Copy, Debug, PartialEq, Choice)]
/// enum Hem {
///     Plain,
///     Rolled,
/// }
///
/// /// A skirt's design.
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Skirt {
///     /// Length as a fraction of the leg.
///     #[param(range = 0.1..=0.95, default = 0.45)]
///     length: f64,
///     /// Number of panels.
///     #[param(range = 3..=12, default = 6, prob = 0.4)]
///     n_panels: i64,
///     /// Hem finish.
///     #[param(default = Plain)]
///     hem: Hem,
/// }
///
/// let skirt = Skirt::defaults();
/// assert_eq!((skirt.length, skirt.n_panels, skirt.hem), (0.45, 6, Hem::Plain));
/// let space = Skirt::design_space();
/// assert_eq!(space.params().len(), 3);
/// assert_eq!(space.get("n_panels").unwrap().default_prob, Some(0.4));
/// assert_eq!(space.get("length").unwrap().description, "Length as a fraction of the leg.");
/// ```
#[cfg(feature = "derive")]
pub use garmentcode_derive::Params;

/// A categorical parameter: the [`Choice`](trait@Choice) trait for an enum of unit
/// variants, each an option.
///
/// ```
/// use garmentcode::Choice;
///
/// #[derive(Clone, Copy, Debug, PartialEq, Choice)]
/// enum Collar {
///     Turtle,
///     #[param(rename = "lapel-collar")]
///     Lapel,
/// }
///
/// assert_eq!(Collar::NAMES, ["Turtle", "lapel-collar"]);
/// assert_eq!(Collar::from_name("lapel-collar"), Some(Collar::Lapel));
/// assert_eq!(Collar::Turtle.name(), "Turtle");
/// ```
#[cfg(feature = "derive")]
pub use garmentcode_derive::Choice;

/// A garment part: a panel class (a struct with a `#[panel]` field), a
/// component (`#[part]` fields, in assembly order) or an enum of parts, with
/// `#[interface]` and `#[stitches]` fields. Implements [`Part`], [`Remap`],
/// [`Interfaces`], [`Slot`] for interfaces named after a [`slots`] marker, and
/// [`PanelPart`] or [`Component`](trait@Component).
///
/// ```
/// use garmentcode::slots::Top;
/// use garmentcode::{Arena, Component, EdgeSeq, InterfaceId, PanelId, PartExt, SlotExt, StitchRule, Vec2};
///
/// /// A panel class: one rectangle with its top edge as an interface.
/// #[derive(Component)]
/// struct Band {
///     #[panel]
///     panel: PanelId,
///     #[interface]
///     top: InterfaceId,
///     #[interface]
///     side: InterfaceId,
/// }
///
/// impl Band {
///     fn new(a: &mut Arena, name: &str, width: f64) -> garmentcode::Result<Band> {
///         let corners = [Vec2::ZERO, Vec2::new(0.0, 10.0), Vec2::new(width, 10.0), Vec2::new(width, 0.0)];
///         let edges = EdgeSeq::from_points(a, &corners, true)?;
///         let panel = a.panel_with_edges(name, edges.clone());
///         Ok(Band { panel, side: a.interface(panel, edges[0]), top: a.interface(panel, edges[1]) })
///     }
/// }
///
/// /// A component: two bands sewn side to side.
/// #[derive(Component)]
/// #[component(name = "skirt")]
/// struct Skirt {
///     #[part]
///     bands: Vec<Band>,
///     #[interface]
///     top: InterfaceId,
///     #[stitches]
///     seams: Vec<StitchRule>,
/// }
///
/// /// One of several parts that all have a `top`.
/// #[derive(Component)]
/// #[component(slots(Top))]
/// enum Bottom {
///     Band(Band),
///     Skirt(Skirt),
/// }
///
/// let mut a = Arena::new();
/// let (front, back) = (Band::new(&mut a, "front", 40.0)?, Band::new(&mut a, "back", 40.0)?);
/// let seams = vec![StitchRule::new(&mut a, front.side, back.side)?];
/// let top = a.interface_from(&[front.top, back.top]);
/// let skirt = Skirt { bands: vec![front, back], top, seams };
/// assert_eq!(skirt.name(), "skirt");
/// assert_eq!(skirt.panel_ids().len(), 2);
///
/// let bottom = Bottom::from(skirt);
/// assert_eq!(bottom.iface::<Top>().length(&a), 80.0);
/// let pattern = bottom.assemble(&mut a, "demo")?;
/// assert_eq!((pattern.panels.len(), pattern.stitches.len()), (2, 1));
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[cfg(feature = "derive")]
pub use garmentcode_derive::Component;

/// `#[component]` on a struct: shorthand for `#[derive(Component)]`, its arguments
/// (`name = "..."`, `length = path::to_fn`) those of `#[component(..)]`.
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, InterfaceId, PanelId, PanelPart, Vec2, component};
///
/// #[component]
/// struct Square {
///     #[panel]
///     panel: PanelId,
///     #[interface]
///     top: InterfaceId,
/// }
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 5.0), Vec2::new(5.0, 5.0), Vec2::new(5.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("square", edges.clone());
/// let square = Square { panel, top: a.interface(panel, edges[1]) };
/// assert_eq!(square.panel_id(), panel);
/// assert_eq!(square.top.length(&a), 5.0);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[cfg(feature = "derive")]
pub use garmentcode_derive::component;

/// Paths used by the derive macros' generated code. Not a public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::arena::{Arena, InterfaceId, PanelId, StitchRule};
    pub use crate::component::{Component, Interfaces, Node, PanelPart, Part, Parts, Slot};
    pub use crate::memo::clear as clear_memo;
    pub use crate::params::overrides::{Override, OverrideNumber, OverrideProblem, apply_overrides, override_number, override_problem};
    pub use crate::params::spec::{FieldInfo, FieldShape};
    pub use crate::params::spec::{Kind, ParamSpec, Range, Value};
    pub use crate::params::{Choice, ParamValue, Params, join_path};
    pub use crate::remap::{IdMap, Remap};
}
