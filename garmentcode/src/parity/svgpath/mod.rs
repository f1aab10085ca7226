//! Reference parity: the parts of svgpathtools 1.8.0 (MIT licence,
//! <https://github.com/mathandy/svgpathtools>) that pygarment calls, ported so that
//! results agree bit for bit: segment intersections (with numpy's `roots`, a port of
//! LAPACK's eigenvalue routines, and CPython's `set` iteration order),
//! and outlines (`Path`) with their crossings, crops and pygarment's split of SVG
//! outlines into halves.
//!
//! Why hand-written: panel self-intersection verdicts near tangencies and shared
//! vertices, and the shape of decorative cuts drawn from an SVG picture, depend on
//! the exact floating-point results and their order, which no general-purpose
//! geometry library reproduces. Concept code reaches this through
//! [`intersect`](crate::intersect) (panel checks) only.

mod path;
mod segment;

pub use path::{Crossing, SvgPath, bbox_paths, edge_seq_from_path, halves_from_outlines, seg_length, split_halves};
pub use segment::{
    IntersectError, MAX_PAIRS, Num, P, Seg, lapack, np_roots, polyroots_real, polyroots01, py_float_hash, py_set_order, quad_length,
    try_has_self_intersection, try_intersect, try_intersect_as,
};
