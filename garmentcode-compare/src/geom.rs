//! Panel geometry as the comparator sees it (`EdgeGeom`, `make_arc`, `PanelGeom`,
//! `load_spec` of compare_spec.py). Sampling densities, the arc construction and the
//! rotation conventions are the script's, deliberately not the runtime crate's.

use super::py::{self, PyErr};
use super::{Euler, Fail};
use serde_json::Value;
use std::cell::OnceCell;

pub type P2 = [f64; 2];
pub type P3 = [f64; 3];

pub const CURVE_MIN_SEGMENTS: usize = 64;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Line,
    Quadratic,
    Cubic,
    Circle,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Line => "line",
            Kind::Quadratic => "quadratic",
            Kind::Cubic => "cubic",
            Kind::Circle => "circle",
        }
    }
}

/// One edge in panel-local 2D coordinates; `point(t)` for t in [0, 1].
#[derive(Debug)]
pub struct EdgeGeom {
    pub kind: Kind,
    pub s: P2,
    pub e: P2,
    /// absolute control points
    pub ctrl: Vec<P2>,
    /// (cx, cy, r, a0, sweep)
    pub arc: Option<[f64; 5]>,
    len: OnceCell<f64>,
    mid: OnceCell<P2>,
}

impl EdgeGeom {
    fn new(kind: Kind, s: P2, e: P2, ctrl: Vec<P2>, arc: Option<[f64; 5]>) -> EdgeGeom {
        EdgeGeom { kind, s, e, ctrl, arc, len: OnceCell::new(), mid: OnceCell::new() }
    }

    pub fn point(&self, t: f64) -> P2 {
        let (s, e) = (self.s, self.e);
        match self.kind {
            Kind::Line => [s[0] + (e[0] - s[0]) * t, s[1] + (e[1] - s[1]) * t],
            Kind::Quadratic => {
                let c = self.ctrl[0];
                let u = 1.0 - t;
                [u * u * s[0] + 2.0 * u * t * c[0] + t * t * e[0], u * u * s[1] + 2.0 * u * t * c[1] + t * t * e[1]]
            }
            Kind::Cubic => {
                let (c1, c2) = (self.ctrl[0], self.ctrl[1]);
                let u = 1.0 - t;
                let (a, b, c, d) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
                [a * s[0] + b * c1[0] + c * c2[0] + d * e[0], a * s[1] + b * c1[1] + c * c2[1] + d * e[1]]
            }
            Kind::Circle => {
                if t <= 0.0 {
                    return s;
                }
                if t >= 1.0 {
                    return e;
                }
                let [cx, cy, r, a0, sweep] = self.arc.expect("circle edge without arc");
                let a = a0 + sweep * t;
                [cx + r * a.cos(), cy + r * a.sin()]
            }
        }
    }

    /// Exact for lines and arcs; a 1024-segment polyline for Beziers.
    pub fn length(&self) -> f64 {
        *self.len.get_or_init(|| match self.kind {
            Kind::Line => dist2(self.s, self.e),
            Kind::Circle => {
                let a = self.arc.unwrap();
                (a[2] * a[4]).abs()
            }
            _ => {
                let n = 1024;
                let pts: Vec<P2> = (0..=n).map(|i| self.point(i as f64 / n as f64)).collect();
                (0..n).map(|i| dist2(pts[i], pts[i + 1])).fold(0.0, |acc, d| acc + d)
            }
        })
    }

    /// Point halfway along the edge by arc length (independent of the parametrisation).
    pub fn arc_midpoint(&self) -> P2 {
        *self.mid.get_or_init(|| match self.kind {
            Kind::Line | Kind::Circle => self.point(0.5),
            _ => {
                let n = 256;
                let pts: Vec<P2> = (0..=n).map(|i| self.point(i as f64 / n as f64)).collect();
                let mut cum = vec![0.0f64];
                for i in 0..n {
                    let c = cum[cum.len() - 1] + dist2(pts[i], pts[i + 1]);
                    cum.push(c);
                }
                let half = cum[n] / 2.0;
                for i in 0..n {
                    if cum[i + 1] >= half {
                        let f = if cum[i + 1] == cum[i] { 0.0 } else { (half - cum[i]) / (cum[i + 1] - cum[i]) };
                        return [pts[i][0] + f * (pts[i + 1][0] - pts[i][0]), pts[i][1] + f * (pts[i + 1][1] - pts[i][1])];
                    }
                }
                pts[n]
            }
        })
    }

    /// Number of segments for dense sampling: about one per `step` cm, at least 64 on curves.
    pub fn n_segments(&self, step: f64) -> usize {
        let raw = (self.length() / step).ceil();
        let mut n = if raw >= 1.0 { raw.min(1e9) as usize } else { 1 };
        if self.kind != Kind::Line {
            n = n.max(CURVE_MIN_SEGMENTS);
        }
        n.min(20000)
    }
}

/// `_dist` in 2D: sqrt of the plain sum of `(a - b) ** 2`.
#[inline]
pub fn dist2(a: P2, b: P2) -> f64 {
    (py::sq(a[0] - b[0]) + py::sq(a[1] - b[1])).sqrt()
}

/// `_dist` in 3D.
#[inline]
pub fn dist3(a: P3, b: P3) -> f64 {
    (py::sq(a[0] - b[0]) + py::sq(a[1] - b[1]) + py::sq(a[2] - b[2])).sqrt()
}

fn rel_to_abs(s: P2, e: P2, rel: P2) -> P2 {
    let (dx, dy) = (e[0] - s[0], e[1] - s[1]);
    [s[0] + rel[0] * dx - rel[1] * dy, s[1] + rel[0] * dy + rel[1] * dx]
}

/// Circular arc of `radius` from s to e, SVG-like: a too small radius is scaled up to half
/// the chord; `large` picks the longer arc; `right` bulges to the right of s -> e.
/// Returns (cx, cy, r, a0, sweep).
pub fn make_arc(s: P2, e: P2, radius: f64, large: bool, right: bool) -> Result<[f64; 5], String> {
    let (dx, dy) = (e[0] - s[0], e[1] - s[1]);
    let l = py::hypot(dx, dy);
    if l == 0.0 {
        return Err("circle edge with coincident endpoints".into());
    }
    let h = l / 2.0;
    let r = py::max(radius.abs(), h);
    let d = py::max(r * r - h * h, 0.0).sqrt();
    let side = if right { -1.0 } else { 1.0 };
    let (nx, ny) = (side * -dy / l, side * dx / l);
    let (mx, my) = ((s[0] + e[0]) / 2.0, (s[1] + e[1]) / 2.0);
    let k = if large { d } else { -d };
    let (cx, cy) = (mx + nx * k, my + ny * k);
    let a0 = (s[1] - cy).atan2(s[0] - cx);
    let a1 = (e[1] - cy).atan2(e[0] - cx);
    let ab = ny.atan2(nx);
    let two_pi = 2.0 * std::f64::consts::PI;
    let ccw = py::fmod(a1 - a0, two_pi);
    let off = py::fmod(ab - a0, two_pi);
    let sweep = if off <= ccw { ccw } else { ccw - two_pi };
    Ok([cx, cy, r, a0, sweep])
}

/// Failure of `make_edge`: the script's SpecError (reported with panel and edge) or
/// another Python exception (a comparator error).
enum EdgeFail {
    Spec(String),
    Py(PyErr),
}

impl From<PyErr> for EdgeFail {
    fn from(e: PyErr) -> Self {
        EdgeFail::Py(e)
    }
}

/// Python list indexing `list[i]` for a list of length n: the position it reads
/// (negative indices count from the end; bools are ints).
fn py_index(n: usize, idx: &Value) -> Result<usize, PyErr> {
    let i = match idx {
        Value::Number(n) if n.is_i64() || n.is_u64() => {
            n.as_i64().ok_or_else(|| PyErr::new("IndexError", "cannot fit 'int' into an index-sized integer"))?
        }
        Value::Bool(b) => *b as i64,
        other => {
            return Err(PyErr::new("TypeError", format!("list indices must be integers or slices, not {}", py::type_name(other))));
        }
    };
    let n = n as i64;
    let j = if i < 0 { i + n } else { i };
    if j < 0 || j >= n {
        return Err(PyErr::new("IndexError", "list index out of range"));
    }
    Ok(j as usize)
}

/// `float(v[0]), float(v[1])` of a JSON point.
fn xy(v: &Value) -> Result<P2, PyErr> {
    match v {
        Value::Array(a) => {
            if a.len() < 2 {
                return Err(PyErr::new("IndexError", "list index out of range"));
            }
            Ok([py::float(&a[0])?, py::float(&a[1])?])
        }
        Value::String(st) if !st.starts_with('\0') => {
            // a string indexes to its characters
            let ch: Vec<char> = st.chars().collect();
            if ch.len() < 2 {
                return Err(PyErr::new("IndexError", "string index out of range"));
            }
            let f = |c: char| py::float(&Value::String(c.to_string()));
            Ok([f(ch[0])?, f(ch[1])?])
        }
        other => Err(PyErr::new("TypeError", format!("'{}' object is not subscriptable", py::type_name(other)))),
    }
}

fn make_edge(verts: &[P2], edge: &Value, absolute: bool, radius_scale: f64) -> Result<EdgeGeom, EdgeFail> {
    // i, j = edge['endpoints']; s, e = float(verts[i][0..2])
    let ends = (|| -> Result<(P2, P2), PyErr> {
        let obj = edge.as_object().ok_or_else(|| PyErr::new("TypeError", format!("{} indices must be integers", py::type_name(edge))))?;
        let ep = obj.get("endpoints").ok_or_else(|| PyErr::new("KeyError", "'endpoints'"))?;
        let pair = match ep {
            Value::Array(a) if a.len() == 2 => a,
            Value::Array(a) => {
                return Err(PyErr::new(
                    "ValueError",
                    if a.len() < 2 {
                        format!("not enough values to unpack (expected 2, got {})", a.len())
                    } else {
                        "too many values to unpack (expected 2)".to_string()
                    },
                ));
            }
            other => {
                return Err(PyErr::new("TypeError", format!("cannot unpack non-iterable {} object", py::type_name(other))));
            }
        };
        Ok((verts[py_index(verts.len(), &pair[0])?], verts[py_index(verts.len(), &pair[1])?]))
    })();
    let (s, e) = match ends {
        Ok(x) => x,
        Err(ex) => {
            let Some(obj) = edge.as_object() else {
                // the script's error message calls edge.get(), which a non-dict lacks
                return Err(EdgeFail::Py(PyErr::new("AttributeError", format!("'{}' object has no attribute 'get'", py::type_name(edge)))));
            };
            let ep = obj.get("endpoints").map(py::repr).unwrap_or_else(|| "None".into());
            return Err(EdgeFail::Spec(format!("bad edge endpoints {ep}: {}", ex.msg)));
        }
    };
    let obj = edge.as_object().unwrap();
    let curv = match obj.get("curvature") {
        None | Some(Value::Null) => return Ok(EdgeGeom::new(Kind::Line, s, e, vec![], None)),
        Some(c) => c,
    };
    let cp = |p: &Value| -> Result<P2, PyErr> {
        let q = xy(p)?;
        Ok(if absolute { q } else { rel_to_abs(s, e, q) })
    };
    if let Value::Array(_) = curv {
        // legacy: "curvature": [x, y] is a relative quadratic control point
        return Ok(EdgeGeom::new(Kind::Quadratic, s, e, vec![cp(curv)?], None));
    }
    let Value::Object(c) = curv else {
        return Err(EdgeFail::Py(PyErr::new("AttributeError", format!("'{}' object has no attribute 'get'", py::type_name(curv)))));
    };
    let ctype = c.get("type").cloned().unwrap_or(Value::Null);
    let params = c.get("params").cloned().unwrap_or(Value::Null);
    let item = |k: usize| -> Result<Value, PyErr> {
        match &params {
            Value::Array(a) => a.get(k).cloned().ok_or_else(|| PyErr::new("IndexError", "list index out of range")),
            Value::Object(_) => Err(PyErr::new("KeyError", k.to_string())),
            other => Err(PyErr::new("TypeError", format!("'{}' object is not subscriptable", py::type_name(other)))),
        }
    };
    match ctype.as_str() {
        Some("quadratic") => Ok(EdgeGeom::new(Kind::Quadratic, s, e, vec![cp(&item(0)?)?], None)),
        Some("cubic") => {
            let n = match &params {
                Value::Array(a) => a.len(),
                Value::Object(o) => o.len(),
                Value::String(st) => st.chars().count(),
                other => {
                    return Err(EdgeFail::Py(PyErr::new("TypeError", format!("object of type '{}' has no len()", py::type_name(other)))));
                }
            };
            if n != 2 {
                return Err(EdgeFail::Spec(format!("cubic edge with {n} control points")));
            }
            Ok(EdgeGeom::new(Kind::Cubic, s, e, vec![cp(&item(0)?)?, cp(&item(1)?)?], None))
        }
        Some("circle") => {
            let Value::Array(a) = &params else {
                return Err(EdgeFail::Py(PyErr::new("TypeError", format!("cannot unpack non-iterable {} object", py::type_name(&params)))));
            };
            if a.len() != 3 {
                return Err(EdgeFail::Py(PyErr::new(
                    "ValueError",
                    if a.len() < 3 {
                        format!("not enough values to unpack (expected 3, got {})", a.len())
                    } else {
                        "too many values to unpack (expected 3)".to_string()
                    },
                )));
            }
            let radius = py::float(&a[0])? * radius_scale;
            let arc = make_arc(s, e, radius, py::truthy(&a[1]), py::truthy(&a[2])).map_err(EdgeFail::Spec)?;
            Ok(EdgeGeom::new(Kind::Circle, s, e, vec![], Some(arc)))
        }
        _ => Err(EdgeFail::Spec(format!("unknown curvature type {}", py::repr(&ctype)))),
    }
}

/// Rotation matrix from Euler angles in degrees: intrinsic 'XYZ' (scipy, as pygarment
/// writes panels) is Rx @ Ry @ Rz; extrinsic 'xyz' is Rz @ Ry @ Rx.
/// Python's math.cos / math.sin raise on an infinite angle.
pub fn rot_matrix(deg: [f64; 3], euler: Euler) -> Result<[[f64; 3]; 3], PyErr> {
    let [ax, ay, az] = deg.map(f64::to_radians);
    if [ax, ay, az].iter().any(|a| a.is_infinite()) {
        return Err(PyErr::new("ValueError", "math domain error"));
    }
    let (cx, sx) = (ax.cos(), ax.sin());
    let (cy, sy) = (ay.cos(), ay.sin());
    let (cz, sz) = (az.cos(), az.sin());
    let rx = [[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]];
    let ry = [[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]];
    let rz = [[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]];
    // plain left-to-right sums (Python 3.11 sum); at most two non-zero terms per entry
    let mm = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| {
        let mut m = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
            }
        }
        m
    };
    Ok(match euler {
        Euler::Xyz => mm(mm(rx, ry), rz),
        Euler::ExtrinsicXyz => mm(mm(rz, ry), rx),
    })
}

pub struct PanelGeom {
    pub translation: P3,
    /// rotation rows; only the first two columns are ever used (panels are flat)
    pub r: [[f64; 2]; 3],
    pub label: Option<Value>,
    pub n_vertices: usize,
    pub edges: Vec<EdgeGeom>,
    dense: OnceCell<Vec<Vec<P2>>>,
}

impl PanelGeom {
    pub fn new(name: &str, pdata: &Value, scale: f64, absolute: bool, euler: Euler) -> Result<PanelGeom, Fail> {
        let malformed = |m: String| Fail::Spec(format!("panel {name}: malformed ({m})"));
        let Value::Object(pd) = pdata else {
            return Err(malformed(format!("{} indices must be integers", py::type_name(pdata))));
        };
        let verts_v = pd.get("vertices").ok_or_else(|| malformed("'vertices'".into()))?;
        let verts_list: &[Value] = match verts_v {
            Value::Array(a) => a,
            other => return Err(malformed(format!("'{}' object is not iterable", py::type_name(other)))),
        };
        let mut verts = Vec::with_capacity(verts_list.len());
        for v in verts_list {
            let p = xy(v).map_err(|e| malformed(e.msg))?;
            verts.push([p[0] * scale, p[1] * scale]);
        }
        let default_t = Value::Array(vec![0.into(), 0.into(), 0.into()]);
        let tv = pd.get("translation").unwrap_or(&default_t);
        let translation: Vec<f64> = match tv {
            Value::Array(a) => a.iter().map(|x| py::float(x).map(|f| f * scale)).collect::<Result<_, _>>().map_err(|e| malformed(e.msg))?,
            other => return Err(malformed(format!("'{}' object is not iterable", py::type_name(other)))),
        };
        let default_r = Value::Array(vec![0.into(), 0.into(), 0.into()]);
        let rotation = pd.get("rotation").unwrap_or(&default_r);
        let edges_v = pd.get("edges").ok_or_else(|| malformed("'edges'".into()))?;
        if translation.len() != 3 {
            return Err(Fail::Spec(format!("panel {name}: translation must have 3 components")));
        }
        if !translation.iter().chain(verts.iter().flatten()).all(|x| x.is_finite()) {
            return Err(Fail::Spec(format!("panel {name}: non-finite vertex or translation value")));
        }
        let r: [[f64; 2]; 3] = match rotation {
            Value::Array(a) if a.len() == 3 && !a[0].is_array() => {
                let mut deg = [0.0; 3];
                for k in 0..3 {
                    deg[k] = py::float(&a[k]).map_err(Fail::Py)?;
                }
                let m = rot_matrix(deg, euler).map_err(Fail::Py)?;
                [[m[0][0], m[0][1]], [m[1][0], m[1][1]], [m[2][0], m[2][1]]]
            }
            Value::Array(a) if a.len() == 3 => {
                // a 3x3 matrix
                let mut m = [[0.0; 2]; 3];
                let mut finite = true;
                for (i, row) in a.iter().enumerate() {
                    let Value::Array(row) = row else {
                        return Err(Fail::Py(PyErr::new("TypeError", format!("'{}' object is not iterable", py::type_name(row)))));
                    };
                    let vals: Vec<f64> = row.iter().map(py::float).collect::<Result<_, _>>().map_err(Fail::Py)?;
                    finite &= vals.iter().all(|x| x.is_finite());
                    if vals.len() < 2 {
                        // the script fails later, when to3d reads R[i][1]
                        return Err(Fail::Py(PyErr::new("IndexError", "list index out of range")));
                    }
                    m[i] = [vals[0], vals[1]];
                }
                if !finite {
                    return Err(Fail::Spec(format!("panel {name}: non-finite rotation")));
                }
                m
            }
            _ => return Err(Fail::Spec(format!("panel {name}: rotation must be 3 Euler angles or a 3x3 matrix"))),
        };
        if !r.iter().flatten().all(|x| x.is_finite()) {
            return Err(Fail::Spec(format!("panel {name}: non-finite rotation")));
        }
        let label = pd.get("label").cloned();
        let edges_list: Vec<Value> = match edges_v {
            Value::Array(a) => a.clone(),
            Value::Object(o) => o.keys().map(|k| Value::String(k.clone())).collect(),
            other => return Err(Fail::Py(PyErr::new("TypeError", format!("'{}' object is not iterable", py::type_name(other))))),
        };
        let mut edges = Vec::with_capacity(edges_list.len());
        for (k, ed) in edges_list.iter().enumerate() {
            let eg = match make_edge(&verts, ed, absolute, scale) {
                Ok(eg) => eg,
                Err(EdgeFail::Spec(m)) => return Err(Fail::Spec(format!("panel {name} edge {k}: {m}"))),
                Err(EdgeFail::Py(e)) => return Err(Fail::Py(e)),
            };
            let ctrl_ok = eg.ctrl.iter().flatten().all(|x| x.is_finite());
            let arc_ok = eg.arc.is_none_or(|a| a.iter().all(|x| x.is_finite()));
            if !ctrl_ok || !arc_ok {
                return Err(Fail::Spec(format!("panel {name} edge {k}: non-finite curvature")));
            }
            edges.push(eg);
        }
        if edges.is_empty() {
            return Err(Fail::Spec(format!("panel {name}: no edges")));
        }
        Ok(PanelGeom {
            translation: [translation[0], translation[1], translation[2]],
            r,
            label,
            n_vertices: verts.len(),
            edges,
            dense: OnceCell::new(),
        })
    }

    pub fn to3d(&self, p: P2) -> P3 {
        let (r, t) = (&self.r, &self.translation);
        [r[0][0] * p[0] + r[0][1] * p[1] + t[0], r[1][0] * p[0] + r[1][1] * p[1] + t[1], r[2][0] * p[0] + r[2][1] * p[1] + t[2]]
    }

    pub fn perimeter(&self) -> f64 {
        self.edges.iter().fold(0.0, |acc, e| acc + e.length())
    }

    /// Shoelace area of a coarse sampling (16 points per curve): only its sign is used.
    pub fn signed_area(&self) -> f64 {
        let mut pts = Vec::new();
        for e in &self.edges {
            let n = if e.kind == Kind::Line { 1 } else { 16 };
            pts.extend((0..n).map(|i| e.point(i as f64 / n as f64)));
        }
        let m = pts.len();
        let s = (0..m).fold(0.0, |acc, i| {
            let (p, q) = (pts[i], pts[(i + 1) % m]);
            acc + (p[0] * q[1] - q[0] * p[1])
        });
        0.5 * s
    }

    /// Per-edge dense polylines (2D), cached (the step is fixed per run).
    pub fn dense(&self, step: f64) -> &Vec<Vec<P2>> {
        self.dense.get_or_init(|| {
            self.edges
                .iter()
                .map(|e| {
                    let n = e.n_segments(step);
                    (0..=n).map(|i| e.point(i as f64 / n as f64)).collect()
                })
                .collect()
        })
    }

    pub fn dense3d(&self, step: f64) -> Vec<Vec<P3>> {
        self.dense(step).iter().map(|pl| pl.iter().map(|&p| self.to3d(p)).collect()).collect()
    }
}
