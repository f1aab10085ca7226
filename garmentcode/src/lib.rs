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

#![warn(missing_docs)]

// Lets the derive macros' generated code name this crate as `::garmentcode` inside
// the crate's own tests and examples too.
extern crate self as garmentcode;

pub mod arc;
pub mod arena;
pub mod bezier;
pub mod body;
pub mod compare;
pub mod component;
pub mod curves;
pub mod draw;
pub mod edge;
pub mod error;
pub mod interface;
pub mod intersect;
pub mod math;
#[cfg(feature = "mesh")]
pub mod mesh;
mod memo;
pub mod ops;
pub mod panel;
pub mod params;
pub mod pattern;
mod remap;
pub mod rotation;
pub mod seq;
pub mod slots;
pub mod stitch;
pub mod svgpath;
pub mod yaml;

pub use arena::{Arena, EdgeId, InterfaceId, PanelId, VertexId};
pub use body::Body;
pub use component::{Align, Component, Interfaces, Node, PanelPart, Part, PartExt, Parts, Slot, SlotExt};
pub use edge::{Curve, Edge};
pub use error::{Error, Result};
pub use interface::{Gather, Ruffle};
pub use math::{Vec2, Vec3};
pub use params::{Choice, DesignSpace, Params};
pub use pattern::Pattern;
pub use remap::{IdMap, Remap};
pub use rotation::Rotation;
pub use seq::EdgeSeq;
pub use stitch::StitchRule;

/// Derive macros: `#[derive(Params)]`, `#[derive(Choice)]`, `#[derive(Component)]`
/// and `#[component]`.
#[cfg(feature = "derive")]
pub use garmentcode_derive::{Choice, Component, Params, component};

/// Paths used by the derive macros' generated code. Not a public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::arena::{Arena, InterfaceId, PanelId};
    pub use crate::component::{Component, Interfaces, Node, PanelPart, Part, Parts, Slot};
    pub use crate::params::{Choice, Kind, ParamSpec, ParamValue, Params, Range, Value, join_path};
    pub use crate::remap::{IdMap, Remap};
    pub use crate::stitch::StitchRule;
}
