//! The YAML reader and writer against PyYAML: recorded results, round trips,
//! error messages and mutation fuzzing (one test binary to keep linking cheap).

mod common;
mod errors;
mod fuzz;
mod pyyaml_compare;
mod roundtrip;
