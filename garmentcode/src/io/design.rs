//! Design files in the reference's format: reading into typed parameter structs and
//! writing them back.

use super::design_error::{DesignError, MAX_SHOWN};
use super::design_space::{at, from_node, insert, key, to_node};
use crate::params::space::DesignSpace;
use crate::params::spec::Value;
use crate::params::{Params, join_path};
use crate::parity::yaml::{self, Node, Value as Y};

/// Read a design file: the `v` of every parameter, checked against `space`;
/// parameters the file omits take their default. Unknown keys, values of the wrong
/// type and values out of range are errors (all of them are reported at once).
pub fn read_design_values(text: &str, file: &str, space: &DesignSpace) -> Result<Vec<(String, Value)>, DesignError> {
    let doc = yaml::parse(text).map_err(|e| DesignError::single(file, e.to_string()))?;
    let Some(design) = doc.get("design") else {
        return Err(DesignError::single(file, "expected a top-level `design:` mapping".into()));
    };
    let mut values: Vec<(String, Value)> = space.params().iter().map(|p| (p.path.clone(), p.default.clone())).collect();
    let mut problems = Vec::new();
    walk(design, "", space, &mut values, &mut problems);
    if problems.is_empty() { Ok(values) } else { Err(DesignError { file: file.to_string(), problems }) }
}

fn walk(node: &Node, prefix: &str, space: &DesignSpace, values: &mut [(String, Value)], problems: &mut Vec<String>) {
    let Some(pairs) = node.as_map() else {
        let what = if prefix.is_empty() { "design".to_string() } else { format!("design.{prefix}") };
        problems.push(format!("{}: {what}: expected a mapping of parameters, got {}", at(node), node.value.type_name()));
        return;
    };
    for (k, v) in pairs {
        let Some(name) = k.as_str() else {
            problems.push(format!("{}: design.{prefix}: keys must be names", at(k)));
            continue;
        };
        let path = join_path(prefix, name);
        match (space.get(&path), v.get("v")) {
            (Some(spec), Some(val)) => {
                let Some(value) = from_node(val) else {
                    problems.push(format!("{}: design.{path}: expected a single value, got a {}", at(val), val.value.type_name()));
                    continue;
                };
                match spec.check(&value) {
                    Ok(checked) => {
                        // `values` lists the space's parameters in order.
                        if let Some(i) = space.index_of(&path) {
                            values[i].1 = checked;
                        }
                    }
                    Err(e) => problems.push(format!("{}: design.{path}: {e}", at(val))),
                }
            }
            (Some(_), None) => problems.push(format!("{}: design.{path}: a parameter needs a `v:` value", at(v))),
            (None, _) if space.is_group(&path) => walk(v, &path, space, values, problems),
            (None, _) => {
                // Suggestions only for the problems shown (they cost a pass over the space).
                let hint = (problems.len() < MAX_SHOWN)
                    .then(|| suggestion(&path, space))
                    .flatten()
                    .map(|s| format!(" (did you mean design.{s}?)"))
                    .unwrap_or_default();
                problems.push(format!("{}: design.{path}: unknown parameter{hint}", at(k)));
            }
        }
    }
}

/// Read a design given as `(path, value)` pairs (a program's flat mapping rather
/// than a file), checked as [`read_design_values`] checks a file's values: unknown
/// paths (with a suggestion), types and ranges, all problems at once; parameters
/// not given take their default. `source` names the design in errors.
pub fn read_design_pairs<D: Params>(pairs: &[(String, Value)], source: &str, space: &DesignSpace) -> Result<D, DesignError> {
    let mut values: Vec<(String, Value)> = space.params().iter().map(|p| (p.path.clone(), p.default.clone())).collect();
    let mut problems = Vec::new();
    for (path, value) in pairs {
        match (space.get(path), space.index_of(path)) {
            (Some(spec), Some(i)) => match spec.check(value) {
                Ok(checked) => values[i].1 = checked,
                Err(e) => problems.push(format!("design.{path}: {e}")),
            },
            _ => {
                let hint = (problems.len() < MAX_SHOWN)
                    .then(|| suggestion(path, space))
                    .flatten()
                    .map(|s| format!(" (did you mean design.{s}?)"))
                    .unwrap_or_default();
                let what = if space.is_group(path) { "a group of parameters, not a parameter" } else { "unknown parameter" };
                problems.push(format!("design.{path}: {what}{hint}"));
            }
        }
    }
    if !problems.is_empty() {
        return Err(DesignError { file: source.to_string(), problems });
    }
    from_values(&values, source)
}

/// The closest known path, for typos.
fn suggestion(path: &str, space: &DesignSpace) -> Option<String> {
    let mut best: Option<(usize, &str)> = None;
    for p in space.params() {
        let d = edit_distance(path, &p.path);
        if d <= 3 && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, &p.path));
        }
    }
    best.map(|(_, p)| p.to_string())
}

fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Read a design file into the typed parameter tree `D`.
///
/// Files in the usual layout take a fast path that reads the values straight into
/// the design; every other file, and every file with a problem, goes through the
/// full YAML reader and [`read_design_values`] (same result, and the errors).
pub fn read_design<D: Params>(text: &str, file: &str, space: &DesignSpace) -> Result<D, DesignError> {
    if let Some(d) = super::design_fast::read_design_fast(text, space) {
        return Ok(d);
    }
    read_design_full(text, file, space)
}

/// [`read_design`] without the fast path.
pub(super) fn read_design_full<D: Params>(text: &str, file: &str, space: &DesignSpace) -> Result<D, DesignError> {
    let values = read_design_values(text, file, space)?;
    from_values(&values, file)
}

/// Build a typed design from checked values.
pub fn from_values<D: Params>(values: &[(String, Value)], file: &str) -> Result<D, DesignError> {
    let mut d = D::defaults();
    let mut problems = Vec::new();
    for (path, v) in values {
        let keys: Vec<&str> = path.split('.').collect();
        if let Err(e) = d.set_value(&keys, v) {
            problems.push(format!("design.{path}: {e}"));
        }
    }
    if problems.is_empty() { Ok(d) } else { Err(DesignError { file: file.to_string(), problems }) }
}

/// Write a design in the reference's format: for every parameter of `space` its
/// value (`v`), range, type and default probability.
pub fn write_design<D: Params>(design: &D, space: &DesignSpace) -> String {
    space.to_yaml_with(|p| {
        let keys: Vec<&str> = p.path.split('.').collect();
        design.get_value(&keys).unwrap_or_else(|| p.default.clone())
    })
}

/// Values as a `design:` tree of `{v: ...}` leaves only (a compact design file).
pub fn write_values(values: &[(String, Value)]) -> String {
    let mut root: Vec<(Node, Node)> = Vec::new();
    for (path, v) in values {
        let keys: Vec<&str> = path.split('.').collect();
        insert(&mut root, &keys, Node::new(Y::Map(vec![(key("v"), to_node(v))])));
    }
    yaml::to_string(&Node::new(Y::Map(vec![(key("design"), Node::new(Y::Map(root)))])))
}
