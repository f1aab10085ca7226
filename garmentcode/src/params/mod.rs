//! Design parameters: typed parameter structs, their schema (the design space), design
//! files in the reference's YAML format, JSON Schema, and reproducible sampling.
//!
//! A garment's design is a tree of plain Rust structs deriving [`Params`] (see the
//! `garmentcode-derive` crate): leaves are numbers, booleans, enums deriving
//! [`Choice`] and optional enums; groups nest. The derive generates the schema,
//! typed access by path and defaults; everything else here works on any such tree:
//!
//! - [`DesignSpace`]: the flattened schema (path, type, range or options, default,
//!   probability of keeping the default, description), loadable from and writable
//!   to the reference's design-file format;
//! - [`read_design`] / [`write_design`]: design files ↔ typed structs, with errors
//!   naming the file, parameter path, bad value and allowed range;
//! - [`Sampler`]: the reference's sampling semantics on a named, seeded generator.

mod fast;
mod io;
mod overrides;
mod sample;
mod space;
mod writer;

pub use io::{DesignError, from_values, read_design, read_design_values, write_design, write_values};
pub use sample::{Sampler, below, sample_rng};

/// Support of the derive's per-instance overrides; not part of the stable API.
#[doc(hidden)]
pub use overrides::{FieldInfo, FieldShape, Override, OverrideNumber, OverrideProblem, apply_overrides, override_number, override_problem};

/// Testing aids; not part of the stable API.
#[doc(hidden)]
pub mod testing {
    use super::{DesignError, DesignSpace, Params};

    /// Only the fast paths of [`super::read_design`]; `None` when they defer to the full reader.
    pub fn read_design_fast<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::fast::read_design_fast(text, space)
    }

    /// Only the line reader of the fast path.
    pub fn read_design_lines<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::fast::read_design_lines(text, space)
    }

    /// Only the space-layout reader of the fast path (the layout built for this call).
    pub fn read_design_skeleton<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
        super::fast::read_design_skeleton(text, space)
    }

    /// Only the full reader behind [`super::read_design`].
    pub fn read_design_full<D: Params>(text: &str, file: &str, space: &DesignSpace) -> Result<D, DesignError> {
        super::io::read_design_full(text, file, space)
    }
}
pub use space::DesignSpace;
pub use writer::DesignWriter;

use std::fmt;

/// Type of a parameter, named as in the reference's design files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Real number in a range.
    Float,
    /// Integer in an inclusive range.
    Int,
    /// `true` or `false`.
    Bool,
    /// One of a list of options (names or numbers).
    Select,
    /// One of a list of options, or null (absent).
    SelectNull,
}

impl Kind {
    /// The `type` string of the design file.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Float => "float",
            Kind::Int => "int",
            Kind::Bool => "bool",
            Kind::Select => "select",
            Kind::SelectNull => "select_null",
        }
    }

    /// Parse a `type` string.
    pub fn parse(s: &str) -> Option<Kind> {
        Some(match s {
            "float" => Kind::Float,
            "int" => Kind::Int,
            "bool" => Kind::Bool,
            "select" => Kind::Select,
            "select_null" => Kind::SelectNull,
            _ => return None,
        })
    }

    /// Discrete kinds sample from an option list.
    pub fn is_discrete(self) -> bool {
        matches!(self, Kind::Bool | Kind::Select | Kind::SelectNull)
    }
}

/// A parameter value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// Null (an absent component).
    Null,
    /// Boolean.
    Bool(bool),
    /// Integer.
    Int(i64),
    /// Real number.
    Float(f64),
    /// Option name.
    Str(String),
}

impl Value {
    /// Numeric value of an int or float.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Float(f) => Some(*f),
            _ => None,
        }
    }

    /// Equality as the reference compares values (`1 == 1.0`).
    pub fn loosely_eq(&self, other: &Value) -> bool {
        match (self.as_f64(), other.as_f64()) {
            (Some(a), Some(b)) => a == b,
            _ => self == other,
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Null => f.write_str("null"),
            Value::Bool(b) => write!(f, "{b}"),
            Value::Int(i) => write!(f, "{i}"),
            Value::Float(x) => f.write_str(&crate::pattern::python_float_repr(*x)),
            Value::Str(s) => f.write_str(s),
        }
    }
}

/// Allowed values of a parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum Range {
    /// Numbers from `lo` to `hi`, both included.
    Numeric {
        /// Lower bound.
        lo: f64,
        /// Upper bound.
        hi: f64,
    },
    /// A list of options.
    Options(Vec<Value>),
}

impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Range::Numeric { lo, hi } => write!(f, "[{}, {}]", Value::Float(*lo), Value::Float(*hi)),
            Range::Options(opts) => {
                let names: Vec<String> = opts.iter().map(|o| o.to_string()).collect();
                write!(f, "one of [{}]", names.join(", "))
            }
        }
    }
}

/// One parameter of a design space.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamSpec {
    /// Dotted path below `design`, e.g. `sleeve.cuff.type` (keys as in the file).
    pub path: String,
    /// Parameter type.
    pub kind: Kind,
    /// Allowed values.
    pub range: Range,
    /// Default value.
    pub default: Value,
    /// Probability that sampling keeps the default (the reference's `default_prob`).
    pub default_prob: Option<f64>,
    /// What the parameter does (from the field's doc comment).
    pub description: String,
}

impl ParamSpec {
    /// Check a value against the type and range; the error says what is allowed.
    pub fn check(&self, v: &Value) -> Result<Value, String> {
        match self.kind {
            Kind::Float | Kind::Int => {
                let Some(x) = v.as_f64() else {
                    return Err(format!("expected a number in {}, got {}", self.range, describe(v)));
                };
                if !x.is_finite() {
                    return Err(format!("expected a finite number in {}, got {v}", self.range));
                }
                if self.kind == Kind::Int && x.fract() != 0.0 {
                    return Err(format!("expected an integer in {}, got {v}", self.range));
                }
                if let Range::Numeric { lo, hi } = self.range
                    && (x < lo || x > hi)
                {
                    return Err(format!("{v} is outside the allowed range {}", self.range));
                }
                Ok(if self.kind == Kind::Int { Value::Int(x as i64) } else { Value::Float(x) })
            }
            Kind::Bool | Kind::Select | Kind::SelectNull => {
                let Range::Options(opts) = &self.range else {
                    return Err("parameter has no options".into());
                };
                if self.kind == Kind::SelectNull && *v == Value::Null {
                    return Ok(Value::Null);
                }
                match opts.iter().find(|o| o.loosely_eq(v)) {
                    Some(o) => Ok(o.clone()),
                    None => Err(format!("{} is not allowed: expected {}", describe(v), self.range)),
                }
            }
        }
    }
}

fn describe(v: &Value) -> String {
    match v {
        Value::Str(s) => format!("\"{s}\""),
        other => other.to_string(),
    }
}

/// A leaf parameter type: how values of a Rust type map to design-file values.
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a parameter type",
    label = "not a parameter type",
    note = "a parameter is an `f64`, `i64`, `bool`, an enum with `#[derive(Choice)]` or an `Option` of such an enum",
    note = "a nested group of parameters is a struct with `#[derive(Params)]` (and no `default`/`range`/`options`/`prob` on its field)"
)]
pub trait ParamValue: Sized + Clone {
    /// Parameter type.
    const KIND: Kind;
    /// The value as written in a design file.
    fn to_value(&self) -> Value;
    /// From a design-file value (already checked against the range).
    fn from_value(v: &Value) -> Option<Self>;
    /// Options of discrete types (booleans, enums).
    fn options() -> Vec<Value> {
        Vec::new()
    }
}

impl ParamValue for f64 {
    const KIND: Kind = Kind::Float;
    fn to_value(&self) -> Value {
        Value::Float(*self)
    }
    fn from_value(v: &Value) -> Option<Self> {
        v.as_f64()
    }
}

impl ParamValue for i64 {
    const KIND: Kind = Kind::Int;
    fn to_value(&self) -> Value {
        Value::Int(*self)
    }
    fn from_value(v: &Value) -> Option<Self> {
        v.as_f64().filter(|x| x.fract() == 0.0).map(|x| x as i64)
    }
}

impl ParamValue for bool {
    const KIND: Kind = Kind::Bool;
    fn to_value(&self) -> Value {
        Value::Bool(*self)
    }
    fn from_value(v: &Value) -> Option<Self> {
        match v {
            Value::Bool(b) => Some(*b),
            _ => None,
        }
    }
    fn options() -> Vec<Value> {
        vec![Value::Bool(true), Value::Bool(false)]
    }
}

/// An enum whose variants are the options of a categorical parameter
/// (`#[derive(Choice)]`).
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a choice of options",
    label = "no `#[derive(Choice)]` on this type",
    note = "add `#[derive(Choice)]` to the enum `{Self}`: its unit variants are the options"
)]
pub trait Choice: Sized + Copy + 'static {
    /// Option names, in declaration order.
    const NAMES: &'static [&'static str];
    /// The option's name.
    fn name(&self) -> &'static str;
    /// The option with this name.
    fn from_name(name: &str) -> Option<Self>;
}

impl<T: Choice> ParamValue for T {
    const KIND: Kind = Kind::Select;
    fn to_value(&self) -> Value {
        Value::Str(self.name().to_string())
    }
    fn from_value(v: &Value) -> Option<Self> {
        match v {
            Value::Str(s) => T::from_name(s),
            _ => None,
        }
    }
    fn options() -> Vec<Value> {
        T::NAMES.iter().map(|n| Value::Str(n.to_string())).collect()
    }
}

impl<T: Choice> ParamValue for Option<T> {
    const KIND: Kind = Kind::SelectNull;
    fn to_value(&self) -> Value {
        match self {
            Some(x) => x.to_value(),
            None => Value::Null,
        }
    }
    fn from_value(v: &Value) -> Option<Self> {
        match v {
            Value::Null => Some(None),
            other => T::from_value(other).map(Some),
        }
    }
    fn options() -> Vec<Value> {
        let mut o = <T as ParamValue>::options();
        o.push(Value::Null);
        o
    }
}

/// A group of design parameters (`#[derive(Params)]`).
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a group of design parameters",
    label = "no `#[derive(Params)]` on this type",
    note = "add `#[derive(Params)]` to the struct `{Self}`",
    note = "a field that is a single parameter needs `#[param(default = ..)]` (with `range`/`options` for numbers)"
)]
pub trait Params: Sized + Clone {
    /// The group's fields, for checking overrides at compile time (generated).
    #[doc(hidden)]
    const FIELDS: &'static [FieldInfo] = &[];
    /// Append the specs of every leaf below this group, paths prefixed by `prefix`.
    fn describe(prefix: &str, out: &mut Vec<ParamSpec>);
    /// The design with every parameter at its default.
    fn defaults() -> Self;
    /// Value of the leaf at `path` (relative to this group).
    fn get_value(&self, path: &[&str]) -> Option<Value>;
    /// Set the leaf at `path`; the value must already be checked against its spec.
    fn set_value(&mut self, path: &[&str], v: &Value) -> Result<(), String>;

    /// The design space of this parameter tree.
    fn design_space() -> DesignSpace {
        let mut out = Vec::new();
        Self::describe("", &mut out);
        DesignSpace::new(out)
    }
}

/// Join a group prefix and a key into a dotted path.
pub fn join_path(prefix: &str, key: &str) -> String {
    if prefix.is_empty() { key.to_string() } else { format!("{prefix}.{key}") }
}
