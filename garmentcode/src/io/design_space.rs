//! Design spaces in the reference's design-file format (reading and writing the
//! `design:` tree) and as JSON Schema.

use super::design_error::DesignError;
use crate::params::join_path;
use crate::params::space::DesignSpace;
use crate::params::spec::{Kind, ParamSpec, Range, Value};
use crate::parity::yaml::{self, Node, Value as Y};

impl DesignSpace {
    /// The space written in the reference's design-file format (`design:` tree of
    /// `v`, `range`, `type`, `default_prob`).
    pub fn to_yaml(&self) -> String {
        self.to_yaml_with(|p| p.default.clone())
    }

    /// As [`DesignSpace::to_yaml`] with the given values as `v`.
    pub fn to_yaml_with(&self, mut value: impl FnMut(&ParamSpec) -> Value) -> String {
        let mut root: Vec<(Node, Node)> = Vec::new();
        for p in &self.params {
            let keys: Vec<&str> = p.path.split('.').collect();
            let mut leaf = vec![(key("v"), to_node(&value(p)))];
            let range = match &p.range {
                Range::Numeric { lo, hi } => {
                    if p.kind == Kind::Int {
                        vec![Node::new(Y::Int(*lo as i64)), Node::new(Y::Int(*hi as i64))]
                    } else {
                        vec![Node::new(Y::Float(*lo)), Node::new(Y::Float(*hi))]
                    }
                }
                Range::Options(o) => o.iter().map(to_node).collect(),
            };
            leaf.push((key("range"), Node::new(Y::Seq(range))));
            leaf.push((key("type"), Node::new(Y::Str(p.kind.as_str().into()))));
            if let Some(prob) = p.default_prob {
                leaf.push((key("default_prob"), Node::new(Y::Float(prob))));
            }
            insert(&mut root, &keys, Node::new(Y::Map(leaf)));
        }
        let doc = Node::new(Y::Map(vec![(key("design"), Node::new(Y::Map(root)))]));
        yaml::to_string(&doc)
    }

    /// Load a design space from a reference-format design file: its `v` become the
    /// defaults and its ranges, types and probabilities replace the built-in ones.
    /// Every parameter must be one of `base` (same path and compatible type);
    /// parameters the file omits keep their built-in definition.
    pub fn from_yaml(text: &str, file: &str, base: &DesignSpace) -> Result<DesignSpace, DesignError> {
        let mut problems = Vec::new();
        let doc = yaml::parse(text).map_err(|e| DesignError::single(file, format!("{e}")))?;
        let Some(design) = doc.get("design") else {
            return Err(DesignError::single(file, "expected a top-level `design:` mapping".into()));
        };
        let mut params = base.params.clone();
        let mut walk_stack: Vec<(String, &Node)> = vec![(String::new(), design)];
        while let Some((prefix, node)) = walk_stack.pop() {
            let Some(pairs) = node.as_map() else {
                problems.push(format!("{}: {}: expected a mapping", at(node), show(&prefix)));
                continue;
            };
            for (k, v) in pairs.iter().rev() {
                let name = k.as_str().map(str::to_string).unwrap_or_else(|| format!("{:?}", k.value));
                let path = join_path(&prefix, &name);
                if v.get("v").is_some() {
                    match base.index_of(&path) {
                        None => problems.push(format!("{}: design.{path}: unknown parameter", at(k))),
                        Some(i) => match read_spec(&path, v, &base.params[i]) {
                            Ok(spec) => params[i] = spec,
                            Err(e) => problems.push(format!("{}: design.{path}: {e}", at(v))),
                        },
                    }
                } else if base.is_group(&path) {
                    walk_stack.push((path, v));
                } else {
                    problems.push(format!("{}: design.{path}: unknown parameter or group", at(k)));
                }
            }
        }
        let space = DesignSpace::new(params);
        problems.extend(space.problems().into_iter().map(|p| format!("design.{p}")));
        if problems.is_empty() { Ok(space) } else { Err(DesignError { file: file.to_string(), problems }) }
    }

    /// JSON Schema (draft 2020-12) of design files of this space, for tools and
    /// pipelines that emit designs.
    pub fn json_schema(&self) -> serde_json::Value {
        use serde_json::json;
        let mut root = serde_json::Map::new();
        for p in &self.params {
            let keys: Vec<&str> = p.path.split('.').collect();
            let mut v = serde_json::Map::new();
            match &p.range {
                Range::Numeric { lo, hi } => {
                    v.insert("type".into(), json!(if p.kind == Kind::Int { "integer" } else { "number" }));
                    v.insert("minimum".into(), json!(lo));
                    v.insert("maximum".into(), json!(hi));
                }
                Range::Options(o) => {
                    v.insert("enum".into(), serde_json::Value::Array(o.iter().map(value_json).collect()));
                }
            }
            v.insert("default".into(), value_json(&p.default));
            if !p.description.is_empty() {
                v.insert("description".into(), json!(p.description));
            }
            let mut leaf = json!({
                "type": "object",
                "properties": { "v": serde_json::Value::Object(v) },
                "required": ["v"],
                "x-type": p.kind.as_str(),
            });
            if let Some(prob) = p.default_prob {
                leaf["x-default-prob"] = json!(prob);
            }
            insert_json(&mut root, &keys, leaf);
        }
        json!({
            "$schema": "https://json-schema.org/draft/2020-12/schema",
            "title": "GarmentCode design",
            "description": "A design file: every parameter is an object whose `v` holds the value; missing parameters take their defaults.",
            "type": "object",
            "properties": { "design": group_json(root) },
            "required": ["design"],
        })
    }
}

fn group_json(children: serde_json::Map<String, serde_json::Value>) -> serde_json::Value {
    serde_json::json!({ "type": "object", "properties": serde_json::Value::Object(children), "additionalProperties": false })
}

fn insert_json(map: &mut serde_json::Map<String, serde_json::Value>, keys: &[&str], leaf: serde_json::Value) {
    if keys.len() == 1 {
        map.insert(keys[0].to_string(), leaf);
        return;
    }
    let entry = map.entry(keys[0].to_string()).or_insert_with(|| group_json(serde_json::Map::new()));
    if let Some(serde_json::Value::Object(children)) = entry.get_mut("properties") {
        insert_json(children, &keys[1..], leaf);
    }
}

fn value_json(v: &Value) -> serde_json::Value {
    match v {
        Value::Null => serde_json::Value::Null,
        Value::Bool(b) => serde_json::json!(b),
        Value::Int(i) => serde_json::json!(i),
        Value::Float(f) => serde_json::json!(f),
        Value::Str(s) => serde_json::json!(s),
    }
}

fn read_spec(path: &str, node: &Node, base: &ParamSpec) -> Result<ParamSpec, String> {
    let kind = match node.get("type") {
        None => base.kind,
        Some(t) => {
            let s = t.as_str().ok_or("`type` must be a string")?;
            let k = Kind::parse(s).ok_or_else(|| format!("unknown type `{s}` (expected float, int, bool, select or select_null)"))?;
            if k != base.kind {
                return Err(format!("type `{s}` does not match the parameter's type `{}`", base.kind.as_str()));
            }
            k
        }
    };
    let range = match node.get("range") {
        None => base.range.clone(),
        Some(r) => {
            let items = r.as_seq().ok_or("`range` must be a list")?;
            match kind {
                Kind::Float | Kind::Int => {
                    if items.len() != 2 {
                        return Err(format!("`range` of a {} parameter must be [min, max]", kind.as_str()));
                    }
                    let lo = items[0].as_f64().ok_or("`range` bounds must be numbers")?;
                    let hi = items[1].as_f64().ok_or("`range` bounds must be numbers")?;
                    Range::Numeric { lo, hi }
                }
                _ => {
                    let Range::Options(allowed) = &base.range else { return Err("parameter has no options".into()) };
                    let mut opts = Vec::new();
                    for it in items {
                        let v = from_node(it).ok_or("options must be names, numbers, booleans or null")?;
                        if !allowed.iter().any(|a| a.loosely_eq(&v)) && (v != Value::Null || kind != Kind::SelectNull) {
                            return Err(format!("option {v} is not supported (known options: {})", base.range));
                        }
                        opts.push(v);
                    }
                    // A `select_null` whose list leaves null out keeps it so (the
                    // reference's `style_side_cut`): null stays a valid value, and
                    // the sampler draws it all the same.
                    Range::Options(opts)
                }
            }
        }
    };
    let default_prob = match node.get("default_prob") {
        None => None,
        Some(n) if n.is_null() => None,
        Some(n) => Some(n.as_f64().ok_or("`default_prob` must be a number")?),
    };
    let default = from_node(node.get("v").expect("leaf has v")).ok_or("`v` must be a name, number, boolean or null")?;
    let spec = ParamSpec { path: path.to_string(), kind, range, default, default_prob, description: base.description.clone() };
    let checked = spec.check(&spec.default).map_err(|e| format!("v: {e}"))?;
    Ok(ParamSpec { default: checked, ..spec })
}

pub(crate) fn from_node(n: &Node) -> Option<Value> {
    Some(match &n.value {
        Y::Null => Value::Null,
        Y::Bool(b) => Value::Bool(*b),
        Y::Int(i) => Value::Int(*i),
        Y::Float(f) => Value::Float(*f),
        Y::Str(s) => Value::Str(s.clone()),
        _ => return None,
    })
}

pub(crate) fn to_node(v: &Value) -> Node {
    Node::new(match v {
        Value::Null => Y::Null,
        Value::Bool(b) => Y::Bool(*b),
        Value::Int(i) => Y::Int(*i),
        Value::Float(f) => Y::Float(*f),
        Value::Str(s) => Y::Str(s.clone()),
    })
}

pub(crate) fn key(k: &str) -> Node {
    Node::new(Y::Str(k.to_string()))
}

pub(crate) fn insert(map: &mut Vec<(Node, Node)>, keys: &[&str], leaf: Node) {
    if keys.len() == 1 {
        map.push((key(keys[0]), leaf));
        return;
    }
    let pos = map.iter().position(|(k, _)| k.as_str() == Some(keys[0]));
    let i = match pos {
        Some(i) => i,
        None => {
            map.push((key(keys[0]), Node::new(Y::Map(Vec::new()))));
            map.len() - 1
        }
    };
    if let Y::Map(children) = &mut map[i].1.value {
        insert(children, &keys[1..], leaf);
    }
}

pub(crate) fn at(n: &Node) -> String {
    format!("line {}, column {}", n.line, n.col)
}

fn show(prefix: &str) -> String {
    if prefix.is_empty() { "design".into() } else { format!("design.{prefix}") }
}
