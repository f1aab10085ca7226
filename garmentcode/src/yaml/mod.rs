//! A small, fast, dependency-free reader and writer for the YAML subset used by
//! GarmentCode's design-parameter and body-measurement files.
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
//! let doc = garmentcode::yaml::parse("design:\n  v: 1.\n  range: [0.5, 2]\n").unwrap();
//! let v = doc.get("design").and_then(|d| d.get("v")).unwrap();
//! assert_eq!(v.value, garmentcode::yaml::Value::Float(1.0));
//! assert_eq!((v.line, v.col), (2, 6));
//! assert_eq!(garmentcode::yaml::to_string(&doc), "design:\n  v: 1.0\n  range:\n  - 0.5\n  - 2\n");
//! ```

mod emitter;
mod fast;
mod parser;
mod resolve;
mod scanner;

use std::fmt;

pub(crate) use emitter::push_float_repr;
pub use emitter::to_string;
pub(crate) use resolve::{Resolved, resolve_plain, resolves_to_value};

/// A YAML value as PyYAML `safe_load` would build it (restricted to the types
/// the supported subset can produce).
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `null`, `~`, `Null`, `NULL` or an empty value.
    Null,
    /// Any YAML 1.1 boolean spelling (`true`, `False`, `yes`, `OFF`, ...).
    Bool(bool),
    /// Decimal, `0x` hexadecimal, `0b` binary, leading-`0` octal or `a:b` base-60 integers.
    Int(i64),
    /// Numbers with a `.` (`1.`, `.5`, `1.0e+3`), `.inf`, `-.inf`, `.nan`.
    Float(f64),
    /// Everything else, and every quoted scalar.
    Str(String),
    /// A block (`- x`) or flow (`[x, y]`) sequence.
    Seq(Vec<Node>),
    /// A block or flow mapping, in document order. Keys are scalars and unique.
    Map(Vec<(Node, Node)>),
}

/// A value with the position where it starts in the source text.
///
/// `line` and `col` are 1-based (column counted in characters); they are 0 for
/// nodes built in code. Equality (`==`) compares values only, not positions, so
/// parsed trees can be compared with trees built in code.
#[derive(Debug, Clone)]
pub struct Node {
    /// The value.
    pub value: Value,
    /// 1-based line where the value starts (0 when built in code).
    pub line: u32,
    /// 1-based column where the value starts (0 when built in code).
    pub col: u32,
}

impl PartialEq for Node {
    fn eq(&self, other: &Node) -> bool {
        self.value == other.value
    }
}

impl Node {
    /// A node without a source position (line 0, column 0), e.g. for writing.
    pub fn new(value: Value) -> Node {
        Node { value, line: 0, col: 0 }
    }

    /// The value of `key` if this is a mapping with a string key `key`.
    pub fn get(&self, key: &str) -> Option<&Node> {
        match &self.value {
            Value::Map(pairs) => pairs.iter().find(|(k, _)| matches!(&k.value, Value::Str(s) if s == key)).map(|(_, v)| v),
            _ => None,
        }
    }

    /// The string, if this is a string.
    pub fn as_str(&self) -> Option<&str> {
        match &self.value {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }

    /// The number as `f64` if this is an int or a float (design files mix them freely).
    pub fn as_f64(&self) -> Option<f64> {
        match self.value {
            Value::Int(i) => Some(i as f64),
            Value::Float(f) => Some(f),
            _ => None,
        }
    }

    /// The integer, if this is an int.
    pub fn as_i64(&self) -> Option<i64> {
        match self.value {
            Value::Int(i) => Some(i),
            _ => None,
        }
    }

    /// The boolean, if this is a bool.
    pub fn as_bool(&self) -> Option<bool> {
        match self.value {
            Value::Bool(b) => Some(b),
            _ => None,
        }
    }

    /// True for `null`.
    pub fn is_null(&self) -> bool {
        matches!(self.value, Value::Null)
    }

    /// The items, if this is a sequence.
    pub fn as_seq(&self) -> Option<&[Node]> {
        match &self.value {
            Value::Seq(items) => Some(items),
            _ => None,
        }
    }

    /// The key/value pairs in document order, if this is a mapping.
    pub fn as_map(&self) -> Option<&[(Node, Node)]> {
        match &self.value {
            Value::Map(pairs) => Some(pairs),
            _ => None,
        }
    }
}

impl Value {
    /// A short name of the value's type for error messages ("string", "mapping", ...).
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "bool",
            Value::Int(_) => "int",
            Value::Float(_) => "float",
            Value::Str(_) => "string",
            Value::Seq(_) => "sequence",
            Value::Map(_) => "mapping",
        }
    }
}

impl From<Value> for Node {
    fn from(value: Value) -> Node {
        Node::new(value)
    }
}

/// Anything [`to_string`] can write: a [`Value`] or a [`Node`].
pub trait AsValue {
    /// The value to write.
    fn as_value(&self) -> &Value;
}

impl AsValue for Value {
    fn as_value(&self) -> &Value {
        self
    }
}

impl AsValue for Node {
    fn as_value(&self) -> &Value {
        &self.value
    }
}

/// A parse error with a 1-based line and column (in characters).
///
/// Displays as `line 12, column 7: expected ':' after mapping key "range"`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct YamlError {
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub col: u32,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for YamlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}: {}", self.line, self.col, self.message)
    }
}

impl std::error::Error for YamlError {}

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
    use crate::yaml::{Node, YamlError};

    /// Only the line-oriented fast path; `None` when it defers to the full parser.
    pub fn parse_fast(text: &str) -> Option<Node> {
        let clean = crate::yaml::scanner::check_characters(text).ok()?;
        crate::yaml::fast::parse_fast(text, clean)
    }

    /// Only the full PyYAML-faithful parser.
    pub fn parse_full(text: &str) -> Result<Node, YamlError> {
        crate::yaml::parser::parse_full(text)
    }
}
