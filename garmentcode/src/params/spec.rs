//! One parameter: its type, value, range and spec.

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
            Value::Float(x) => f.write_str(&crate::parity::float_repr::python_float_repr(*x)),
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
        Value::Str(s) => crate::message::quote(s),
        other => other.to_string(),
    }
}

/// One field of a parameter group: its Rust name, its name in design files and its shape.
#[derive(Debug)]
pub struct FieldInfo {
    /// Rust field name (without `r#`).
    pub field: &'static str,
    /// Name in design files.
    pub name: &'static str,
    /// A parameter or a nested group.
    pub shape: FieldShape,
}

/// What a field of a parameter group is.
#[derive(Debug)]
pub enum FieldShape {
    /// A parameter of this type, with its numeric range if it has one.
    Leaf {
        /// Parameter type.
        kind: Kind,
        /// `range = lo..=hi` of numeric parameters.
        range: Option<(f64, f64)>,
    },
    /// A nested group with these fields.
    Group(&'static [FieldInfo]),
}
