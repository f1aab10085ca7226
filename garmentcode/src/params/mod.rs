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

pub(crate) mod overrides;
pub(crate) mod sample;
pub(crate) mod space;
pub(crate) mod spec;

use space::DesignSpace;
use spec::{FieldInfo, Kind, ParamSpec, Value};

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
///
/// A parameter is a choice, or with `Option` a choice that may be none:
///
/// ```
/// use garmentcode::{Choice, Params};
///
/// #[derive(Clone, Copy, Debug, PartialEq, Choice)]
/// enum Cuff {
///     Band,
///     Flared,
/// }
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Sleeve {
///     /// Cuff at the wrist, if any.
///     #[param(default = None)]
///     cuff: Option<Cuff>,
/// }
///
/// assert_eq!(Cuff::NAMES, ["Band", "Flared"]);
/// assert_eq!(Cuff::from_name("Flared").map(|c| c.name()), Some("Flared"));
/// assert_eq!(Sleeve::defaults().cuff, None);
/// assert_eq!(Sleeve::design_space().get("cuff").unwrap().range.to_string(), "one of [Band, Flared, null]");
/// ```
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
///
/// Design files are read into and written from such a tree:
///
/// ```
/// use garmentcode::Params;
/// use garmentcode::io::{read_design, write_design};
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Skirt {
///     /// Fullness of the hem in full circles.
///     #[param(range = 0.05..=1.5, default = 0.3)]
///     suns: f64,
/// }
///
/// let space = Skirt::design_space();
/// let mut skirt = Skirt::defaults();
/// skirt.suns = 1.0;
/// let file = write_design(&skirt, &space);
/// assert_eq!(read_design::<Skirt>(&file, "skirt.yaml", &space).unwrap(), skirt);
/// let too_full = file.replace("v: 1.0", "v: 2.0");
/// let err = read_design::<Skirt>(&too_full, "skirt.yaml", &space).unwrap_err();
/// assert!(err.to_string().contains("suns"));
/// ```
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
