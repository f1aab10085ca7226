//! The design space: every parameter's path, type, range, default and sampling
//! probability, in document order.

use super::fast::Skeleton;
use super::{Kind, ParamSpec, Range, Value};
use crate::yaml::{self, Node, Value as Y};
use std::collections::HashMap;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The flattened schema of a design.
///
/// ```
/// use garmentcode::Params;
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Skirt {
///     /// Number of panels.
///     #[param(range = 3..=12, default = 6, prob = 0.4)]
///     n_panels: i64,
/// }
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Design {
///     skirt: Skirt,
/// }
///
/// let space = Design::design_space();
/// assert!(space.problems().is_empty());
/// let spec = space.get("skirt.n_panels").unwrap();
/// assert_eq!((spec.range.to_string(), spec.default.to_string()), ("[3.0, 12.0]".to_string(), "6".to_string()));
/// assert!(space.is_group("skirt"));
/// assert!(space.to_yaml().starts_with("design:\n  skirt:\n    n_panels:\n"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct DesignSpace {
    params: Vec<ParamSpec>,
    /// Every parameter's path and every group's path (a proper prefix of some
    /// parameter's path, at a dot), for lookups while reading design files.
    index: HashMap<String, Entry>,
    /// Every parameter's path split at its dots (the keys `Params::set_value`
    /// takes), so that reading a design does not split them again.
    keys: Vec<Vec<String>>,
    /// The space's file layout, for reading the files written for it quickly.
    skeleton: SkeletonSlot,
}

/// Lazily built [`Skeleton`], derived from the parameters (so it is not cloned
/// and does not take part in comparisons).
#[derive(Default)]
struct SkeletonSlot {
    /// Files read so far; the layout is built on the second (a single read
    /// would not repay building it).
    reads: AtomicUsize,
    cell: OnceLock<Option<Skeleton>>,
}

impl Clone for SkeletonSlot {
    fn clone(&self) -> Self {
        SkeletonSlot::default()
    }
}

impl PartialEq for SkeletonSlot {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for SkeletonSlot {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SkeletonSlot")
    }
}

/// What a dotted path names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Entry {
    /// The parameter at this index.
    Param(usize),
    /// A group: some parameter lies below it.
    Group,
}

impl DesignSpace {
    /// A space from parameter specs (in document order).
    pub fn new(params: Vec<ParamSpec>) -> DesignSpace {
        let mut index = HashMap::with_capacity(params.len() * 2);
        for (i, p) in params.iter().enumerate() {
            index.insert(p.path.clone(), Entry::Param(i));
        }
        for p in &params {
            for (dot, _) in p.path.match_indices('.') {
                index.entry(p.path[..dot].to_string()).or_insert(Entry::Group);
            }
        }
        let keys = params.iter().map(|p| p.path.split('.').map(str::to_string).collect()).collect();
        DesignSpace { params, index, keys, skeleton: SkeletonSlot::default() }
    }

    /// The space's file layout with holes for the values, from the second read on.
    pub(super) fn skeleton(&self) -> Option<&Skeleton> {
        if self.skeleton.reads.fetch_add(1, Ordering::Relaxed) == 0 {
            return None;
        }
        self.built_skeleton()
    }

    /// The space's file layout with holes for the values, built now if not yet.
    pub(super) fn built_skeleton(&self) -> Option<&Skeleton> {
        self.skeleton.cell.get_or_init(|| Skeleton::new(self)).as_ref()
    }

    /// Every parameter, in document order.
    pub fn params(&self) -> &[ParamSpec] {
        &self.params
    }

    /// A parameter by dotted path.
    pub fn get(&self, path: &str) -> Option<&ParamSpec> {
        self.index_of(path).map(|i| &self.params[i])
    }

    /// The keys of parameter `i`'s path.
    pub(crate) fn keys(&self, i: usize) -> &[String] {
        &self.keys[i]
    }

    /// Index of the parameter at `path` in [`DesignSpace::params`].
    pub(crate) fn index_of(&self, path: &str) -> Option<usize> {
        match self.index.get(path) {
            Some(Entry::Param(i)) => Some(*i),
            _ => None,
        }
    }

    /// What `path` names: a parameter (its index), a group, or nothing.
    pub(crate) fn lookup(&self, path: &str) -> Option<Entry> {
        self.index.get(path).copied()
    }

    /// Whether `prefix` is a group (some parameter lies below it).
    pub fn is_group(&self, prefix: &str) -> bool {
        self.params.iter().any(|s| s.path.len() > prefix.len() && s.path.starts_with(prefix) && s.path.as_bytes()[prefix.len()] == b'.')
    }

    /// Problems that make the space unusable for sampling (empty or reversed ranges,
    /// defaults outside their range, probabilities outside [0, 1], a default that is
    /// the only option while it must be avoided).
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for p in &self.params {
            let here = &p.path;
            if let Some(prob) = p.default_prob
                && !(0.0..=1.0).contains(&prob)
            {
                out.push(format!("{here}: default_prob {prob} is outside [0, 1]"));
            }
            match (&p.kind, &p.range) {
                (Kind::Float | Kind::Int, Range::Numeric { lo, hi }) => {
                    if !(lo.is_finite() && hi.is_finite()) || lo >= hi {
                        out.push(format!("{here}: range [{lo}, {hi}] is empty or reversed"));
                    }
                }
                (Kind::Float | Kind::Int, Range::Options(_)) => {
                    out.push(format!("{here}: a {} parameter needs a [min, max] range", p.kind.as_str()))
                }
                (_, Range::Options(opts)) => {
                    if opts.is_empty() {
                        out.push(format!("{here}: no options"));
                    }
                    let others = opts.iter().filter(|o| !o.loosely_eq(&p.default)).count()
                        + usize::from(p.kind == Kind::SelectNull && p.default != Value::Null && !opts.contains(&Value::Null));
                    if p.default_prob.is_some_and(|x| x < 1.0) && others == 0 {
                        out.push(format!("{here}: the default is the only option, so it cannot be avoided when sampling"));
                    }
                }
                (_, Range::Numeric { .. }) => out.push(format!("{here}: a {} parameter needs a list of options", p.kind.as_str())),
            }
            if let Err(e) = p.check(&p.default) {
                out.push(format!("{here}: default: {e}"));
            }
        }
        out
    }

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
    pub fn from_yaml(text: &str, file: &str, base: &DesignSpace) -> Result<DesignSpace, super::DesignError> {
        let mut problems = Vec::new();
        let doc = yaml::parse(text).map_err(|e| super::DesignError::single(file, format!("{e}")))?;
        let Some(design) = doc.get("design") else {
            return Err(super::DesignError::single(file, "expected a top-level `design:` mapping".into()));
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
                let path = super::join_path(&prefix, &name);
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
        if problems.is_empty() { Ok(space) } else { Err(super::DesignError { file: file.to_string(), problems }) }
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
                    if kind == Kind::SelectNull && !opts.contains(&Value::Null) {
                        opts.push(Value::Null);
                    }
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

pub(super) fn from_node(n: &Node) -> Option<Value> {
    Some(match &n.value {
        Y::Null => Value::Null,
        Y::Bool(b) => Value::Bool(*b),
        Y::Int(i) => Value::Int(*i),
        Y::Float(f) => Value::Float(*f),
        Y::Str(s) => Value::Str(s.clone()),
        _ => return None,
    })
}

pub(super) fn to_node(v: &Value) -> Node {
    Node::new(match v {
        Value::Null => Y::Null,
        Value::Bool(b) => Y::Bool(*b),
        Value::Int(i) => Y::Int(*i),
        Value::Float(f) => Y::Float(*f),
        Value::Str(s) => Y::Str(s.clone()),
    })
}

pub(super) fn key(k: &str) -> Node {
    Node::new(Y::Str(k.to_string()))
}

pub(super) fn insert(map: &mut Vec<(Node, Node)>, keys: &[&str], leaf: Node) {
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

pub(super) fn at(n: &Node) -> String {
    format!("line {}, column {}", n.line, n.col)
}

fn show(prefix: &str) -> String {
    if prefix.is_empty() { "design".into() } else { format!("design.{prefix}") }
}
