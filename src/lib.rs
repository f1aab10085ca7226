//! Library part of the `garmentcode` tool: the web configurator, shared by the
//! binary, its integration tests and its benchmark.

pub mod web;

/// The README's code blocks, compiled and run by `cargo test` as doc tests (blocks
/// tagged `sh`, `text` and the like are not Rust and are skipped).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
