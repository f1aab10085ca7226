//! Input and output apart from geometry: the reference's `specification.json`,
//! design files (typed designs and design spaces in the reference's YAML layout,
//! and the JSON Schema of design files).
//!
//! Body measurement files are read and written by [`Body::from_yaml`](crate::Body::from_yaml)
//! and [`Body::to_yaml`](crate::Body::to_yaml); patterns by
//! [`Pattern::from_json`](crate::Pattern::from_json) and [`Pattern::to_json`](crate::Pattern::to_json).

mod design;
mod design_error;
mod design_fast;
mod design_space;
mod design_writer;
mod spec;

pub use design::{from_values, read_design, read_design_pairs, read_design_values, write_design, write_values};
pub use design_error::DesignError;
pub use design_writer::DesignWriter;
pub use spec::{MAX_CONTROL, MAX_EDGES, MAX_EDGES_PER_PANEL, MAX_EXTENT_CM, MAX_NAME_CHARS, MAX_PANELS, check_name};

/// Testing aids; not part of the stable API.
#[doc(hidden)]
pub mod testing {
    use super::design_error::DesignError;
    use crate::params::Params;
    use crate::params::space::DesignSpace;

    /// Only the fast paths of [`read_design`](crate::io::read_design); `None` when they defer to the full reader.
    pub fn read_design_fast<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::design_fast::read_design_fast(text, space)
    }

    /// Only the line reader of the fast path.
    pub fn read_design_lines<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::design_fast::read_design_lines(text, space)
    }

    /// Only the space-layout reader of the fast path (the layout built for this call).
    pub fn read_design_skeleton<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::design_fast::read_design_skeleton(text, space)
    }

    /// Only the full reader behind [`read_design`](crate::io::read_design).
    pub fn read_design_full<D: Params>(text: &str, file: &str, space: &DesignSpace) -> Result<D, DesignError> {
        super::design::read_design_full(text, file, space)
    }
}
