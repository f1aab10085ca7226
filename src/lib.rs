//! Library part of the `garmentcode` tool: the web configurator, shared by the
//! binary, its integration tests and its benchmark.

pub mod web;
