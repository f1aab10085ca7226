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

pub mod arc;
pub mod arena;
pub mod bezier;
pub mod component;
pub mod curves;
pub mod draw;
pub mod edge;
pub mod error;
pub mod interface;
pub mod intersect;
pub mod math;
pub mod ops;
pub mod panel;
pub mod pattern;
pub mod rotation;
pub mod seq;
pub mod stitch;

pub use arena::{Arena, EdgeId, InterfaceId, PanelId, VertexId};
pub use component::{Align, Component, Node, Part, PartExt, Parts};
pub use edge::{Curve, Edge};
pub use error::{Error, Result};
pub use interface::{Gather, Ruffle};
pub use math::{Vec2, Vec3};
pub use pattern::Pattern;
pub use rotation::Rotation;
pub use seq::EdgeSeq;
pub use stitch::StitchRule;
