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
mod stitch;

// Function namespaces.
pub mod curves;
pub mod intersect;
pub mod math;
#[cfg(feature = "mesh")]
pub mod mesh;
pub mod ops;
pub mod slots;

// Input/output and drawings, apart from geometry.
pub mod draw;
pub mod io;

// Code that exists only to reproduce the reference bit for bit.
pub mod parity;

pub use arc::SvgArc;
pub use arena::{Arena, EdgeId, EdgeSeq, InterfaceId, PanelId, Ruffle, StitchRule, VertexId};
pub use bezier::Bezier;
pub use body::{Body, BodyError, DERIVED_VALUES, Derived, DerivedValue, MEASUREMENTS, Measurement};
pub use component::{Align, Component, Interfaces, Node, PanelPart, Part, PartExt, Parts, Slot, SlotExt, assemble};
pub use edge::{Curve, Edge, Segment};
pub use error::{Error, Result};
pub use interface::Gather;
pub use params::sample::{Sampler, below, sample_rng};
pub use params::space::DesignSpace;
pub use params::spec::{Kind, ParamSpec, Range, Value};
pub use params::{Choice, ParamValue, Params, join_path};
pub use pattern::order::panel_order;
pub use pattern::validate::{Problem, ProblemKind, Severity, validate};
pub use pattern::{Curvature, EdgeSpec, PanelSpec, Pattern, Properties, StitchSide, StitchSpec};
pub use remap::{IdMap, Remap};
pub use rotation::Rotation;
pub use stitch::StitchRecord;

/// 2D point or vector (panel-local coordinates, centimetres).
pub type Vec2 = glam::DVec2;
/// 3D point or vector (world coordinates, centimetres).
pub type Vec3 = glam::DVec3;

/// Derive macros: `#[derive(Params)]`, `#[derive(Choice)]`, `#[derive(Component)]`
/// and `#[component]`.
#[cfg(feature = "derive")]
pub use garmentcode_derive::{Choice, Component, Params, component};

/// Paths used by the derive macros' generated code. Not a public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::arena::{Arena, InterfaceId, PanelId, StitchRule};
    pub use crate::component::{Component, Interfaces, Node, PanelPart, Part, Parts, Slot};
    pub use crate::params::overrides::{Override, OverrideNumber, OverrideProblem, apply_overrides, override_number, override_problem};
    pub use crate::params::spec::{FieldInfo, FieldShape};
    pub use crate::params::spec::{Kind, ParamSpec, Range, Value};
    pub use crate::params::{Choice, ParamValue, Params, join_path};
    pub use crate::remap::{IdMap, Remap};
}
