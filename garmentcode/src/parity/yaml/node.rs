//! The YAML document tree ([`Node`], [`Value`]), parse errors, and Python's key
//! equality for mapping keys.

use std::fmt;

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

/// Anything [`to_string`](super::to_string) can write: a [`Value`] or a [`Node`].
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

/// Python dict key equality for scalars: numbers compare by value across
/// bool/int/float, NaN keys are all the same object in PyYAML (so equal).
pub(crate) fn keys_equal(a: &Value, b: &Value) -> bool {
    fn num(v: &Value) -> Option<Num> {
        match *v {
            Value::Bool(b) => Some(Num::I(b as i64)),
            Value::Int(i) => Some(Num::I(i)),
            Value::Float(f) => Some(Num::F(f)),
            _ => None,
        }
    }
    enum Num {
        I(i64),
        F(f64),
    }
    match (a, b) {
        (Value::Str(x), Value::Str(y)) => x == y,
        (Value::Null, Value::Null) => true,
        _ => match (num(a), num(b)) {
            (Some(Num::I(x)), Some(Num::I(y))) => x == y,
            (Some(Num::F(x)), Some(Num::F(y))) => x == y || (x.is_nan() && y.is_nan()),
            (Some(Num::I(i)), Some(Num::F(f))) | (Some(Num::F(f)), Some(Num::I(i))) => {
                // Exact comparison, as Python does (no rounding of large ints):
                // only integral floats in i64's range [-2^63, 2^63) can be equal.
                const TWO_63: f64 = 9_223_372_036_854_775_808.0;
                f.fract() == 0.0 && (-TWO_63..TWO_63).contains(&f) && f as i64 == i
            }
            _ => false,
        },
    }
}
