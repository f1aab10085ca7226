//! Derive macros for garmentcode (see the `garmentcode` crate).
