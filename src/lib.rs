//! Library part of the `garmentcode` tool: the web configurator, shared by the
//! binary, its integration tests and its benchmark.

pub mod web;

/// A build warning as users read it: the reference's internal error strings
/// (`ERROR::IncorrectParams::...`, kept verbatim in `checks.json`) explained.
pub fn explain_warning(w: &str) -> String {
    match w.split_once("ERROR::IncorrectParams::") {
        Some((before, what)) => {
            format!("{before}the reference refuses this combination of parameters ({what}); change one of them to get a valid garment")
        }
        None => w.to_string(),
    }
}

/// The README's code blocks, compiled and run by `cargo test` as doc tests (blocks
/// tagged `sh`, `text` and the like are not Rust and are skipped).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
