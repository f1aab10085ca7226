//! Code generation for each derive.

pub mod choice;
pub mod component;
pub mod params;
