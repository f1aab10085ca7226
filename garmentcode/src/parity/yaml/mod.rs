//! Reference parity: a small, fast, dependency-free reader and writer for the YAML
//! subset used by GarmentCode's design-parameter and body-measurement files,
//! hand-written because the files must read and write exactly as PyYAML (the
//! reference's library) reads and writes them, which general YAML crates do not do
//! (YAML 1.1 resolution, PyYAML's errors, its emitter's quoting and folding).
//!
//! Reading follows PyYAML `safe_load` (a YAML 1.1 resolver) exactly for every
//! input it accepts: the scanner is a port of PyYAML's scanner (same tokens, same
//! simple-key and indentation rules, same tab strictness), the parser follows
//! PyYAML's parser states, and plain scalars are resolved with PyYAML's YAML 1.1
//! regular expressions (`yes`/`on` are booleans, `1e3` is a string, `0777` is
//! octal, `1:30` is 90 ...). Whatever PyYAML rejects is rejected too. A few
//! features PyYAML does accept are deliberately unsupported and give a clear
//! error instead: anchors/aliases, tags, directives, block scalars (`|`, `>`),
//! explicit keys (`?`), multiple documents, timestamps, merge keys (`<<`),
//! integers outside `i64`, and duplicate mapping keys (PyYAML silently keeps the
//! last one; we name both lines).
//!
//! Typical files take a line-oriented fast path (`fast.rs`) that handles
//! `key: value` / `- item` blocks, comments, single-line quoted scalars and
//! `[a, b]` lists; anything else (and every error) goes through the full
//! PyYAML port. Both paths are checked against each other by the fuzz tests.
//!
//! Writing ([`to_string`]) produces the same text as PyYAML
//! `dump(data, default_flow_style=False, sort_keys=False)` (block style, 2-space
//! indentation, sequences inside mappings not indented, quoting only where needed,
//! lines folded at 80 columns, non-ASCII escaped), with full-precision floats.
//!
//! ```
//! let doc = garmentcode::parity::yaml::parse("design:\n  v: 1.\n  range: [0.5, 2]\n").unwrap();
//! let v = doc.get("design").and_then(|d| d.get("v")).unwrap();
//! assert_eq!(v.value, garmentcode::parity::yaml::Value::Float(1.0));
//! assert_eq!((v.line, v.col), (2, 6));
//! assert_eq!(garmentcode::parity::yaml::to_string(&doc), "design:\n  v: 1.0\n  range:\n  - 0.5\n  - 2\n");
//! ```

mod emitter;
mod fast;
mod parser;
mod resolve;
mod scanner;

mod node;

pub(crate) use emitter::push_float_repr;
pub use emitter::to_string;
pub use node::{AsValue, Node, Value, YamlError};
pub(crate) use resolve::{Resolved, resolve_plain, resolves_to_value};

/// Parses one YAML document (as PyYAML `safe_load` would) into a [`Node`] tree.
///
/// An empty document (only comments, blank lines or `---`) gives a `Null` node.
/// Errors name the line and column of the problem; unsupported YAML features
/// are reported as such rather than misread.
pub fn parse(text: &str) -> Result<Node, YamlError> {
    parser::parse(text)
}

/// Testing aids; not part of the stable API.
#[doc(hidden)]
pub mod testing {
    use crate::parity::yaml::{Node, YamlError};

    /// Only the line-oriented fast path; `None` when it defers to the full parser.
    pub fn parse_fast(text: &str) -> Option<Node> {
        let clean = crate::parity::yaml::scanner::check_characters(text).ok()?;
        crate::parity::yaml::fast::parse_fast(text, clean)
    }

    /// Only the full PyYAML-faithful parser.
    pub fn parse_full(text: &str) -> Result<Node, YamlError> {
        crate::parity::yaml::parser::parse_full(text)
    }
}
