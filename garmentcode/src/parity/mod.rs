//! Reference parity: code that exists only to reproduce the reference
//! implementation (pygarment on CPython 3.11, numpy, scipy, svgpathtools, PyYAML)
//! bit for bit, so that every written file is byte-identical to the reference's.
//!
//! Each module is a hand-written port of one library's behaviour, down to evaluation
//! order and rounding, because a general-purpose equivalent gives different bits:
//!
//! - [`bfgs`]: scipy's BFGS with its line searches (the tangent fit of quadratic
//!   curves, [`curves::quadratic_from_tangents`](crate::curves::quadratic_from_tangents));
//! - [`svgpath`]: svgpathtools' segment intersections (with numpy/LAPACK roots) and
//!   SVG outlines (panel self-intersection checks, decorative cuts);
//! - [`float_repr`]: CPython's `repr` of floats (every number written);
//! - [`yaml`]: a PyYAML-compatible YAML reader and writer (design and body files).
//!
//! The concept modules call these through a function or two each; nothing here
//! defines a concept of its own.

pub mod bfgs;
pub mod float_repr;
pub mod svgpath;
pub mod yaml;
