//! Stitches identified by geometry (`_side`, `stitch_list`, `compare_stitches`): a side is
//! a panel name plus its edge's endpoints and parameter midpoint, never an edge index.

use super::Fail;
use super::geom::{EdgeGeom, P2, PanelGeom, dist2};
use super::py::{self, PyErr};
use serde_json::Value;
use std::collections::BTreeMap;

/// One stitch side (the script's tuple `(panel, s, e, point(0.5), length, edge)`).
#[derive(Clone, Copy)]
pub struct Side<'a> {
    pub panel: &'a str,
    pub s: P2,
    pub e: P2,
    pub mid: P2,
    pub len: f64,
    pub edge: &'a EdgeGeom,
}

pub struct Stitch<'a> {
    pub sides: [Side<'a>; 2],
    /// `sorted(str(x) for x in st[2:])`, e.g. ["right_wrong"]
    pub flags: Vec<String>,
}

impl Stitch<'_> {
    /// Panel-pair key: the two panel names, sorted.
    pub fn key(&self) -> (String, String) {
        pair_key(self.sides[0].panel, self.sides[1].panel)
    }
}

pub fn pair_key(a: &str, b: &str) -> (String, String) {
    if a <= b { (a.to_string(), b.to_string()) } else { (b.to_string(), a.to_string()) }
}

pub type Panels = BTreeMap<String, PanelGeom>;

fn side<'a>(panels: &'a Panels, side: &Value, which: &str) -> Result<Side<'a>, Fail> {
    let obj = match side {
        Value::Object(o) if o.contains_key("panel") && o.contains_key("edge") => o,
        _ => return Err(Fail::Spec(format!("{which}: malformed stitch side {}", py::repr(side)))),
    };
    let pn_v = &obj["panel"];
    let (name, p) = match pn_v {
        Value::String(s) if panels.contains_key(s.as_str()) => {
            let (k, p) = panels.get_key_value(s.as_str()).unwrap();
            (k.as_str(), p)
        }
        Value::Array(_) | Value::Object(_) => {
            return Err(Fail::Py(PyErr::new("TypeError", format!("unhashable type: '{}'", py::type_name(pn_v)))));
        }
        _ => return Err(Fail::Spec(format!("{which}: stitch refers to unknown panel {}", py::repr(pn_v)))),
    };
    let ev = &obj["edge"];
    let missing = || Fail::Spec(format!("{which}: stitch refers to missing edge {} of panel {name}", py::repr(ev)));
    let idx = match py::int(ev) {
        Ok(i) => i,
        Err(e) if matches!(e.kind, "ValueError" | "TypeError" | "IndexError") => return Err(missing()),
        Err(e) => return Err(Fail::Py(e)),
    };
    // p.edges[i] (negative indices read from the end), then `if i < 0: raise IndexError`
    let n = p.edges.len() as i64;
    if idx < 0 || idx >= n {
        return Err(missing());
    }
    let e = &p.edges[idx as usize];
    Ok(Side { panel: name, s: e.s, e: e.e, mid: e.point(0.5), len: e.length(), edge: e })
}

/// The stitches of a spec, sides resolved against its panels.
pub fn stitch_list<'a>(spec: &Value, panels: &'a Panels, which: &str) -> Result<Vec<Stitch<'a>>, Fail> {
    let empty = Value::Array(vec![]);
    let sts = spec["pattern"].get("stitches").unwrap_or(&empty);
    let list: Vec<Value> = match sts {
        Value::Array(a) => a.clone(),
        Value::Object(o) => o.keys().map(|k| Value::String(k.clone())).collect(),
        Value::String(s) => s.chars().map(|c| Value::String(c.to_string())).collect(),
        other => {
            return Err(Fail::Py(PyErr::new("TypeError", format!("'{}' object is not iterable", py::type_name(other)))));
        }
    };
    let mut out = Vec::with_capacity(list.len());
    for (k, st) in list.iter().enumerate() {
        let Value::Array(items) = st else {
            return Err(Fail::Spec(format!("{which}: malformed stitch #{k}: {}", py::repr(st))));
        };
        if items.len() < 2 {
            return Err(Fail::Spec(format!("{which}: malformed stitch #{k}: {}", py::repr(st))));
        }
        let mut flags: Vec<String> = items[2..].iter().map(py::str_of).collect();
        flags.sort();
        let a = side(panels, &items[0], which)?;
        let b = side(panels, &items[1], which)?;
        out.push(Stitch { sides: [a, b], flags });
    }
    Ok(out)
}

/// Distance between two stitch sides (same panel required), orientation-insensitive.
pub fn side_dev(a: &Side, b: &Side) -> f64 {
    if a.panel != b.panel {
        return f64::INFINITY;
    }
    let d_same = py::max(dist2(a.s, b.s), dist2(a.e, b.e));
    let d_flip = py::max(dist2(a.s, b.e), dist2(a.e, b.s));
    py::max(py::min(d_same, d_flip), dist2(a.mid, b.mid))
}

pub fn fmt_pt(p: P2) -> String {
    format!("({}, {})", py::fixed(p[0], 2), py::fixed(p[1], 2))
}

pub fn stitch_str(st: &Stitch) -> String {
    let [a, b] = &st.sides;
    format!("{}[{}-{}] <-> {}[{}-{}]", a.panel, fmt_pt(a.s), fmt_pt(a.e), b.panel, fmt_pt(b.s), fmt_pt(b.e))
}

/// `repr(list_of_str)`.
pub fn flags_repr(f: &[String]) -> String {
    format!("[{}]", f.iter().map(|s| py::repr_str(s)).collect::<Vec<_>>().join(", "))
}

/// Strict comparison: each expected stitch greedily takes the closest unused actual
/// stitch of the same panel pair within tol. Returns (reasons, worst deviation).
pub fn compare_stitches(se: &[&Stitch], sa: &[&Stitch], tol: f64) -> (Vec<String>, f64) {
    let mut reasons = Vec::new();
    let mut worst = 0.0f64;
    let mut by_pair: BTreeMap<(String, String), Vec<usize>> = BTreeMap::new();
    for (k, st) in sa.iter().enumerate() {
        by_pair.entry(st.key()).or_default().push(k);
    }
    let mut used = vec![false; sa.len()];
    let mut missing: Vec<(&Stitch, f64)> = Vec::new();
    for st in se {
        let mut best: (Option<usize>, f64) = (None, f64::INFINITY);
        if let Some(ks) = by_pair.get(&st.key()) {
            for &k in ks {
                if used[k] {
                    continue;
                }
                let a = sa[k];
                let d = py::min(
                    py::max(side_dev(&st.sides[0], &a.sides[0]), side_dev(&st.sides[1], &a.sides[1])),
                    py::max(side_dev(&st.sides[0], &a.sides[1]), side_dev(&st.sides[1], &a.sides[0])),
                );
                if d < best.1 {
                    best = (Some(k), d);
                }
            }
        }
        match best {
            (Some(k), d) if d <= tol => {
                used[k] = true;
                worst = py::max(worst, d);
                if sa[k].flags != st.flags {
                    reasons.push(format!(
                        "stitch {}<->{}: flags {} vs expected {}",
                        st.sides[0].panel,
                        st.sides[1].panel,
                        flags_repr(&sa[k].flags),
                        flags_repr(&st.flags)
                    ));
                }
            }
            (_, d) => missing.push((st, d)),
        }
    }
    for (st, d) in &missing {
        let dtxt = if *d == f64::INFINITY { String::new() } else { format!(" (closest candidate off by {} cm)", py::fixed(*d, 4)) };
        reasons.push(format!("missing stitch {}{dtxt}", stitch_str(st)));
        if *d != f64::INFINITY {
            worst = py::max(worst, *d);
        }
    }
    for (k, st) in sa.iter().enumerate() {
        if !used[k] {
            reasons.push(format!("extra stitch {}", stitch_str(st)));
        }
    }
    if se.len() != sa.len() {
        reasons.insert(0, format!("stitch count {} vs expected {}", sa.len(), se.len()));
    }
    (reasons, worst)
}
