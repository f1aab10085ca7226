//! Per-instance overrides of a reused parameter group.
//!
//! A nested group field may change some parameters of its instance of the group
//! (`#[param(cuff(top_ruffle(range = 1..=2)))]`, see `#[derive(Params)]`). The derive
//! checks the overrides while compiling ([`override_problem`], against the group's
//! [`Params::FIELDS`]) and applies them to the group's schema ([`apply_overrides`]) and
//! defaults (plain field assignments).

use super::spec::{FieldInfo, FieldShape, Kind, ParamSpec, Range};
use super::{Params, join_path};

/// One override of a nested group field, as applied to the schema (the default is
/// applied to the group's value by the derive, and read back from it here).
#[derive(Debug)]
pub struct Override {
    /// Rust field path inside the group.
    pub path: &'static [&'static str],
    /// New range.
    pub range: Option<(f64, f64)>,
    /// New sampling probability (`Some(None)`: none).
    pub prob: Option<Option<f64>>,
    /// New description.
    pub doc: Option<&'static str>,
    /// The default changed.
    pub default: bool,
    /// Left out of the schema.
    pub skip: bool,
}

const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

const fn find(fields: &'static [FieldInfo], name: &str) -> Option<&'static FieldInfo> {
    let mut i = 0;
    while i < fields.len() {
        if str_eq(fields[i].field, name) {
            return Some(&fields[i]);
        }
        i += 1;
    }
    None
}

/// The field at a Rust field path.
const fn lookup(fields: &'static [FieldInfo], path: &[&str]) -> Option<&'static FieldInfo> {
    let mut fields = fields;
    let mut i = 0;
    loop {
        let Some(f) = find(fields, path[i]) else { return None };
        if i + 1 == path.len() {
            return Some(f);
        }
        match &f.shape {
            FieldShape::Group(inner) => fields = inner,
            FieldShape::Leaf { .. } => return None,
        }
        i += 1;
    }
}

/// What is wrong with an override, found by [`override_problem`].
#[derive(Debug, PartialEq, Eq)]
pub enum OverrideProblem {
    /// Nothing (or an unknown field name, which the compiler reports itself).
    None,
    /// The override sets a default, range or probability on a nested group.
    NotAParameter,
    /// `range` on a parameter that is not a number.
    NotNumeric,
    /// A fractional default for an integer parameter.
    NotAnInteger,
    /// The numeric default lies outside the (possibly overridden) range.
    OutOfRange,
}

/// Check an override that sets a default, range or probability against the group's
/// fields at compile time: the derive matches the answer in a `const` and panics
/// there, at the override, with a message naming it.
pub const fn override_problem(
    fields: &'static [FieldInfo],
    path: &[&str],
    default: Option<f64>,
    range: Option<(f64, f64)>,
) -> OverrideProblem {
    let Some(f) = lookup(fields, path) else { return OverrideProblem::None };
    let FieldShape::Leaf { kind, range: own } = &f.shape else {
        return OverrideProblem::NotAParameter;
    };
    let numeric = matches!(kind, Kind::Float | Kind::Int);
    if range.is_some() && !numeric {
        return OverrideProblem::NotNumeric;
    }
    let Some(d) = default else { return OverrideProblem::None };
    if matches!(kind, Kind::Int) && d % 1.0 != 0.0 {
        return OverrideProblem::NotAnInteger;
    }
    let bounds = match range {
        Some(r) => Some(r),
        None => *own,
    };
    if let Some((lo, hi)) = bounds
        && (d < lo || d > hi)
    {
        return OverrideProblem::OutOfRange;
    }
    OverrideProblem::None
}

/// The design-file keys of a Rust field path.
fn keys(fields: &'static [FieldInfo], path: &[&str]) -> Vec<&'static str> {
    let mut fields = fields;
    let mut out = Vec::new();
    for name in path {
        let f = fields.iter().find(|f| f.field == *name).unwrap_or_else(|| panic!("no parameter field `{name}` (checked by the derive)"));
        out.push(f.name);
        if let FieldShape::Group(inner) = &f.shape {
            fields = inner;
        }
    }
    out
}

/// Apply the overrides of the group instance at `prefix` to its specs, `out[start..]`;
/// `group` is the instance's defaults (with the overridden defaults set).
pub fn apply_overrides<G: Params>(out: &mut Vec<ParamSpec>, start: usize, prefix: &str, group: &G, overrides: &[Override]) {
    for o in overrides {
        let keys = keys(G::FIELDS, o.path);
        let path = join_path(prefix, &keys.join("."));
        if o.skip {
            let below = format!("{path}.");
            let tail = out.split_off(start);
            out.extend(tail.into_iter().filter(|p| p.path != path && !p.path.starts_with(&below)));
            continue;
        }
        let spec = out[start..].iter_mut().find(|p| p.path == path).unwrap_or_else(|| panic!("override of `{path}`: no such parameter"));
        if let Some((lo, hi)) = o.range {
            spec.range = Range::Numeric { lo, hi };
        }
        if let Some(p) = o.prob {
            spec.default_prob = p;
        }
        if let Some(d) = o.doc {
            spec.description = d.to_string();
        }
        if o.default {
            spec.default = group.get_value(&keys).unwrap_or_else(|| panic!("override of `{path}`: no value"));
        }
    }
}

/// A number literal as the default of an `f64` or `i64` parameter.
#[diagnostic::on_unimplemented(
    message = "a number cannot be the default of a `{Self}` parameter",
    label = "this override sets a number",
    note = "numeric defaults apply to f64 and i64 parameters; write `true`/`false`, `Enum::Variant`, `Some(..)` or `None` for the others"
)]
pub trait OverrideNumber {
    /// The literal's value.
    fn from_literal(x: f64) -> Self;
}

impl OverrideNumber for f64 {
    fn from_literal(x: f64) -> Self {
        x
    }
}

impl OverrideNumber for i64 {
    fn from_literal(x: f64) -> Self {
        x as i64
    }
}

/// A number literal written in an override, as the field's type.
pub fn override_number<T: OverrideNumber>(x: f64) -> T {
    T::from_literal(x)
}
