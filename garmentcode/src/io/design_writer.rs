//! Writing many designs of one space fast: every design file of a space is the same
//! text except for the `v` values, so the text around them is rendered once (by
//! [`write_design`](super::write_design) itself) and only the values are formatted
//! per design. The output is the same as `write_design`'s, byte for byte; where
//! that cannot be made sure of (a value whose text could depend on where it
//! stands), the writer falls back to `write_design`.

use super::design::write_design;
use crate::params::Params;
use crate::params::space::DesignSpace;
use crate::params::spec::{Range, Value};
use crate::parity::yaml::{self, Node, Value as Y};
use std::collections::HashMap;

/// A design-file writer for one design space.
#[derive(Clone, Debug)]
pub struct DesignWriter {
    space: DesignSpace,
    /// Per parameter, its path split into keys.
    keys: Vec<Vec<String>>,
    /// Per parameter, the text since the previous value up to its own (`...v: `);
    /// empty when the writer falls back to `write_design`.
    before: Vec<String>,
    /// The text after the last value.
    after: String,
    /// Text of every option (strings only), per parameter.
    options: Vec<HashMap<String, String>>,
}

/// A stand-in value that renders as itself and occurs nowhere else.
fn marker(i: usize) -> String {
    format!("zq{i}qz")
}

/// The text of `v` as the emitter writes it as a mapping value, if it is one line.
fn value_text(v: &Value) -> Option<String> {
    let doc = Node::new(Y::Map(vec![(Node::new(Y::Str("v".into())), super::design_space::to_node(v))]));
    let text = yaml::to_string(&doc);
    let inner = text.strip_prefix("v: ")?.strip_suffix('\n')?;
    (!inner.contains('\n')).then(|| inner.to_string())
}

impl DesignWriter {
    /// A writer for designs of `space`.
    pub fn new(space: &DesignSpace) -> DesignWriter {
        let params = space.params();
        let keys = params.iter().map(|p| p.path.split('.').map(str::to_string).collect()).collect();
        let mut w = DesignWriter { space: space.clone(), keys, before: Vec::new(), after: String::new(), options: Vec::new() };
        let mut i = 0;
        let text = space.to_yaml_with(|_| {
            i += 1;
            Value::Str(marker(i - 1))
        });
        let mut rest = text.as_str();
        let mut before = Vec::with_capacity(params.len());
        for i in 0..params.len() {
            let m = marker(i);
            let Some((head, tail)) = rest.split_once(&m) else { return w };
            if head.contains("zq") || !head.ends_with("v: ") {
                return w;
            }
            before.push(head.to_string());
            rest = tail;
        }
        if rest.contains("zq") {
            return w;
        }
        let mut options = Vec::with_capacity(params.len());
        for p in params {
            let mut texts = HashMap::new();
            if let Range::Options(opts) = &p.range {
                for o in opts.iter().chain([&p.default]) {
                    if let Value::Str(s) = o {
                        let Some(t) = value_text(o) else { return w };
                        texts.insert(s.clone(), t);
                    }
                }
            }
            options.push(texts);
        }
        // Numbers, booleans and null are plain one-line scalars wherever they stand;
        // strings are written as looked up above.
        w.before = before;
        w.after = rest.to_string();
        w.options = options;
        w
    }

    /// Whether designs are written from the template (else by `write_design`).
    pub fn templated(&self) -> bool {
        !self.before.is_empty() || self.space.params().is_empty()
    }

    /// The design file of `design`: the same text as
    /// [`write_design`](super::write_design)`(design, space)`.
    pub fn write<D: Params>(&self, design: &D) -> String {
        if !self.templated() {
            return write_design(design, &self.space);
        }
        let mut out = String::with_capacity(self.after.len() + self.before.iter().map(|b| b.len() + 24).sum::<usize>());
        let mut path: Vec<&str> = Vec::new();
        for (i, p) in self.space.params().iter().enumerate() {
            path.clear();
            path.extend(self.keys[i].iter().map(String::as_str));
            let v = design.get_value(&path).unwrap_or_else(|| p.default.clone());
            out.push_str(&self.before[i]);
            match &v {
                Value::Null => out.push_str("null"),
                Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
                Value::Int(x) => {
                    use std::fmt::Write as _;
                    let _ = write!(out, "{x}");
                }
                Value::Float(x) => yaml::push_float_repr(&mut out, *x),
                Value::Str(s) => match self.options[i].get(s) {
                    Some(t) => out.push_str(t),
                    None => return write_design(design, &self.space),
                },
            }
        }
        out.push_str(&self.after);
        out
    }
}
