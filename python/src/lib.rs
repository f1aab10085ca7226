//! `garmentcode._native`: the compiled part of the Python package `garmentcode`.
//!
//! Every operation calls the library crates or the command-line tool's own code
//! (`garmentcode_cli`): designs and bodies are loaded as `garmentcode build` loads
//! them, files are prepared by the same functions, and `sample_dataset` is
//! `garmentcode sample`, so what Python writes is what the CLI writes, byte for
//! byte, and errors carry the CLI's messages. The Python side (`garmentcode/*.py`)
//! re-exports these names and adds the pure-Python parts (the pygarment
//! compatibility layer, the shard reader).

use garmentcode::io::{read_design, read_design_pairs, write_design};
use garmentcode::mesh::{BoxMesh, VertexLabel};
use garmentcode::{Kind, Params, Range, Value};
use garmentcode_cli::cli::{BackgroundArg, BuildFormat, PngArgs, SampleArgs};
use garmentcode_cli::commands::{self, CliError, build as build_cmd, sample as sample_cmd};
use garments::Design;
use garments::sample::{DatasetSampler, Outcome};
use pyo3::IntoPyObjectExt;
use pyo3::create_exception;
use pyo3::exceptions::{PyKeyError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyString, PyTuple};
use std::path::PathBuf;

/// mimalloc, as in the command-line tool: building a garment makes and frees
/// thousands of small vectors.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

create_exception!(
    garmentcode,
    DesignError,
    PyValueError,
    "A design that is not valid: unknown parameters, values of the wrong type or out of range."
);
create_exception!(garmentcode, BodyError, PyValueError, "A body that is not valid: unknown or missing measurements, implausible values.");
create_exception!(garmentcode, BuildError, PyValueError, "A valid design whose garment cannot be built on the body (or is empty).");
create_exception!(
    garmentcode,
    PatternError,
    PyValueError,
    "A specification (pattern JSON) that cannot be read, or a pattern that cannot be drawn or meshed."
);
create_exception!(garmentcode, InputError, PyValueError, "Other invalid input: bad options, unreadable or unwritable files and folders.");
create_exception!(garmentcode, DatasetError, PyRuntimeError, "Dataset generation stopped: a sample failed, or it was interrupted.");

/// A CLI error as a Python exception: bad input as `InputError` (a `ValueError`),
/// a stopped or failed run as `DatasetError`.
fn cli_err(e: CliError) -> PyErr {
    match e {
        CliError::Usage(m) | CliError::Input(m) => InputError::new_err(m),
        CliError::Rejected(m) | CliError::Failed(m) => DatasetError::new_err(m),
    }
}

/// The message of a CLI error.
fn cli_message(e: CliError) -> String {
    match e {
        CliError::Usage(m) | CliError::Input(m) | CliError::Rejected(m) | CliError::Failed(m) => m,
    }
}

/// A parameter value as a Python object.
fn value_to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    match v {
        Value::Null => Ok(py.None().into_bound(py)),
        Value::Bool(b) => b.into_bound_py_any(py),
        Value::Int(i) => i.into_bound_py_any(py),
        Value::Float(x) => x.into_bound_py_any(py),
        Value::Str(s) => s.into_bound_py_any(py),
    }
}

/// A Python object as a parameter value (`None`, bool, int, float or str).
fn value_from_py(path: &str, o: &Bound<'_, PyAny>) -> PyResult<Value> {
    if o.is_none() {
        return Ok(Value::Null);
    }
    // bool before int: Python's bool is an int.
    if let Ok(b) = o.cast::<pyo3::types::PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if let Ok(i) = o.extract::<i64>() {
        return Ok(Value::Int(i));
    }
    if let Ok(x) = o.extract::<f64>() {
        return Ok(Value::Float(x));
    }
    if let Ok(s) = o.extract::<String>() {
        return Ok(Value::Str(s));
    }
    let type_name = o.get_type().name().map(|n| n.to_string()).unwrap_or_default();
    Err(DesignError::new_err(format!("<dict>: design.{path}: expected a single value (number, bool, string or None), got a {type_name}")))
}

/// How many dicts a design may nest: the design space's paths are a few levels
/// deep (a `design` key and `v` leaves add two), so anything deeper is a mistake,
/// and the limit keeps a deep or self-containing dict from overflowing the stack.
const MAX_DESIGN_DEPTH: usize = 32;

/// Walk a design mapping into `(path, value)` pairs. A mapping with a `v` key is a
/// parameter (the reference's layout, other keys such as `range` ignored); another
/// mapping is a group; anything else is a value. Keys may be dotted paths, and a
/// top-level `design` key is the design itself (a loaded design file). `open`
/// holds the dicts being walked (the path from the top), to refuse a dict that
/// contains itself and one nested deeper than [`MAX_DESIGN_DEPTH`].
fn flatten(prefix: &str, d: &Bound<'_, PyDict>, open: &mut Vec<usize>, out: &mut Vec<(String, Value)>) -> PyResult<()> {
    let id = d.as_ptr() as usize;
    let at = || if prefix.is_empty() { "design".to_string() } else { format!("design.{}", prefix.chars().take(200).collect::<String>()) };
    if open.contains(&id) {
        return Err(DesignError::new_err(format!("<dict>: {}: the dict contains itself", at())));
    }
    if open.len() >= MAX_DESIGN_DEPTH {
        return Err(DesignError::new_err(format!(
            "<dict>: {}...: nested more than {MAX_DESIGN_DEPTH} dicts deep (a design's parameter paths are a few levels deep)",
            at()
        )));
    }
    open.push(id);
    for (k, v) in d.iter() {
        let Ok(key) = k.extract::<String>() else {
            return Err(DesignError::new_err(format!("<dict>: design.{prefix}: keys must be strings, got {}", k.repr()?)));
        };
        let path = garmentcode::join_path(prefix, &key);
        if prefix.is_empty() && key == "design" && v.is_instance_of::<PyDict>() {
            flatten("", v.cast::<PyDict>()?, open, out)?;
        } else if let Ok(group) = v.cast::<PyDict>() {
            match group.get_item("v")? {
                Some(leaf) => out.push((path.clone(), value_from_py(&path, &leaf)?)),
                None => flatten(&path, group, open, out)?,
            }
        } else {
            out.push((path.clone(), value_from_py(&path, &v)?));
        }
    }
    open.pop();
    Ok(())
}

/// A design dict's `(path, value)` pairs (see [`flatten`]).
fn design_pairs(d: &Bound<'_, PyDict>) -> PyResult<Vec<(String, Value)>> {
    let mut pairs = Vec::new();
    flatten("", d, &mut Vec::new(), &mut pairs)?;
    Ok(pairs)
}

/// A design from Python: a mapping (nested as the reference's design files, or
/// flat `{path: value}`), YAML text, or a built-in name or design file path. Also
/// the label the CLI would name it by.
fn load_design(o: &Bound<'_, PyAny>, space: &garmentcode::DesignSpace) -> PyResult<(Design, String)> {
    if let Ok(d) = o.cast::<PyDict>() {
        let pairs = design_pairs(d)?;
        let design = read_design_pairs(&pairs, "<dict>", space).map_err(|e| DesignError::new_err(e.to_string()))?;
        return Ok((design, "design".into()));
    }
    let text = path_or_str(o)
        .map_err(|_| DesignError::new_err("a design is a dict, YAML text, a built-in design name or a design file path".to_string()))?;
    if text.contains('\n') {
        let design = read_design(&text, "<text>", space).map_err(|e| DesignError::new_err(e.to_string()))?;
        return Ok((design, "design".into()));
    }
    commands::load_design(&text).map_err(|e| DesignError::new_err(cli_message(e)))
}

/// A `str` or an `os.PathLike` as a string.
fn path_or_str(o: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = o.extract::<String>() {
        return Ok(s);
    }
    let p: PathBuf = o.extract()?;
    Ok(p.to_string_lossy().into_owned())
}

/// A design's values as a flat `{path: value}` dict, in the space's order.
fn design_dict<'py>(py: Python<'py>, design: &Design, space: &garmentcode::DesignSpace) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for p in space.params() {
        let keys: Vec<&str> = p.path.split('.').collect();
        let v = design.get_value(&keys).unwrap_or_else(|| p.default.clone());
        d.set_item(&p.path, value_to_py(py, &v)?)?;
    }
    Ok(d)
}

/// Body measurements: a built-in body (`Body("mean_all")`), a body file
/// (`Body("path/to/body.yaml")`), or `Body.from_yaml` / `Body.from_dict`.
#[pyclass(module = "garmentcode", name = "Body", frozen)]
#[derive(Clone)]
struct PyBody {
    body: garmentcode::Body,
    name: String,
}

#[pymethods]
impl PyBody {
    /// A built-in body by name, or a body file (YAML with a `body:` mapping).
    #[new]
    #[pyo3(signature = (source = None))]
    fn new(source: Option<&Bound<'_, PyAny>>) -> PyResult<PyBody> {
        let arg = match source {
            None => garments::builtin::DEFAULT_BODY.to_string(),
            Some(o) => {
                if let Ok(d) = o.cast::<PyDict>() {
                    return PyBody::from_dict(d);
                }
                path_or_str(o).map_err(|_| BodyError::new_err("a body is a built-in body name, a body file path or a dict"))?
            }
        };
        let (body, label) = commands::load_body(&arg).map_err(|e| BodyError::new_err(cli_message(e)))?;
        let name = if garments::builtin::body(&label).is_some() { label } else { stem(&label) };
        Ok(PyBody { body, name })
    }

    /// Names of the built-in bodies.
    #[staticmethod]
    fn builtin() -> Vec<&'static str> {
        garments::builtin::BODIES.iter().map(|(n, _)| *n).collect()
    }

    /// A body from the text of a body file.
    #[staticmethod]
    #[pyo3(signature = (text, name = "body".to_string()))]
    fn from_yaml(text: &str, name: String) -> PyResult<PyBody> {
        let body = garments::builtin::body_from_yaml(text, "<text>").map_err(|e| BodyError::new_err(e.to_string()))?;
        Ok(PyBody { body, name })
    }

    /// A body from a `{measurement: value}` dict: the `body:` mapping of a body
    /// file (also inside `{"body": {...}}`), which may start from a built-in body
    /// (`{"base": "mean_female", "waist": 70.0}`; the web API's `{"base": ...,
    /// "measurements": {...}}` reads too). Derived `_` values are ignored and
    /// recomputed.
    #[staticmethod]
    fn from_dict(d: &Bound<'_, PyDict>) -> PyResult<PyBody> {
        let mut d = match d.get_item("body")? {
            Some(inner) => {
                inner.cast_into::<PyDict>().map_err(|_| BodyError::new_err("<dict>: `body` must be a mapping of measurements"))?
            }
            None => d.clone(),
        };
        if let Some(m) = d.get_item("measurements")? {
            let m = m.cast_into::<PyDict>().map_err(|_| BodyError::new_err("<dict>: `measurements` must be a mapping of measurements"))?;
            let merged = m.copy()?;
            if let Some(base) = d.get_item("base")? {
                merged.set_item("base", base)?;
            }
            d = merged;
        }
        let items: Vec<(String, Bound<'_, PyAny>)> = d
            .iter()
            .map(|(k, v)| Ok((k.extract::<String>().map_err(|_| BodyError::new_err("<dict>: measurement names must be strings"))?, v)))
            .collect::<PyResult<_>>()?;
        let texts: Vec<Option<String>> = items.iter().map(|(_, v)| v.extract::<String>().ok()).collect();
        let entries: Vec<(String, &str, garmentcode::BodyValue<'_>)> = items
            .iter()
            .zip(&texts)
            .map(|((name, v), text)| {
                let value = if let Some(t) = text {
                    garmentcode::BodyValue::Text(t)
                } else if v.is_none() {
                    garmentcode::BodyValue::Null
                } else if let (false, Ok(x)) = (v.is_instance_of::<pyo3::types::PyBool>(), v.extract::<f64>()) {
                    garmentcode::BodyValue::Number(x)
                } else {
                    garmentcode::BodyValue::Other(format!("a {}", v.get_type().name().map(|n| n.to_string()).unwrap_or_default()))
                };
                (String::new(), name.as_str(), value)
            })
            .collect();
        let body = garmentcode::Body::from_entries(&entries, garments::builtin::BODIES)
            .map_err(|problems| BodyError::new_err(garmentcode::BodyError { file: "<dict>".into(), problems }.to_string()))?;
        Ok(PyBody { body, name: "body".into() })
    }

    /// The body's name: its built-in name or file stem.
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// The raw measurements, `{name: value}` (cm, angles in degrees).
    #[getter]
    fn measurements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for name in garmentcode::Body::measurement_names() {
            if let Some(v) = self.body.get(name) {
                d.set_item(name, v)?;
            }
        }
        Ok(d)
    }

    /// The derived values, `{"_name": value}`, as the reference computes them.
    #[getter]
    fn derived<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in self.body.entries() {
            if k.starts_with('_') {
                d.set_item(k, v)?;
            }
        }
        Ok(d)
    }

    /// What a measurement (raw or `_`-derived) is.
    #[staticmethod]
    fn describe(name: &str) -> PyResult<&'static str> {
        garmentcode::Body::describe_measurement(name).ok_or_else(|| PyKeyError::new_err(name.to_string()))
    }

    /// The body file (`body_measurements.yaml` layout).
    fn to_yaml(&self) -> String {
        self.body.to_yaml()
    }

    /// Every value, raw and derived, `{name: value}`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in self.body.entries() {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    fn __getitem__(&self, name: &str) -> PyResult<f64> {
        self.body.entries().into_iter().find(|(k, _)| *k == name).map(|(_, v)| v).ok_or_else(|| PyKeyError::new_err(name.to_string()))
    }

    fn __repr__(&self) -> String {
        format!("Body({:?})", self.name)
    }
}

/// A file path's stem.
fn stem(path: &str) -> String {
    std::path::Path::new(path).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| path.to_string())
}

/// A body from Python: `None` (the default body), a `Body`, a dict, a built-in
/// name or a body file path.
fn load_body(o: Option<&Bound<'_, PyAny>>) -> PyResult<PyBody> {
    match o {
        Some(o) => match o.cast::<PyBody>() {
            Ok(b) => Ok(b.get().clone()),
            Err(_) => PyBody::new(Some(o)),
        },
        None => PyBody::new(None),
    }
}

/// The design space: every parameter's path, type, range, default, sampling
/// probability and description. `DesignSpace()` is the built-in one;
/// `DesignSpace(path)` takes a design file's ranges and probabilities, as
/// `garmentcode sample --design-space` does.
#[pyclass(module = "garmentcode", name = "DesignSpace", frozen)]
struct PyDesignSpace {
    space: garmentcode::DesignSpace,
    /// The design file, or `None` for the built-in space.
    source: Option<String>,
    /// With the parameters past the reference (`design.extension`).
    extended: bool,
}

/// One slot of the vector encoding.
enum Slot<'a> {
    /// `(x - lo) / (hi - lo)` of a number.
    Number { lo: f64, hi: f64, int: bool },
    /// 0 or 1.
    Flag,
    /// One-hot slot of an option.
    Option(&'a Value),
}

impl PyDesignSpace {
    /// The encoding's slots, each with its parameter index.
    fn slots(&self) -> Vec<(usize, Slot<'_>)> {
        let mut out = Vec::new();
        for (i, p) in self.space.params().iter().enumerate() {
            match (&p.kind, &p.range) {
                (Kind::Float | Kind::Int, Range::Numeric { lo, hi }) => {
                    out.push((i, Slot::Number { lo: *lo, hi: *hi, int: p.kind == Kind::Int }))
                }
                (Kind::Bool, _) => out.push((i, Slot::Flag)),
                (_, Range::Options(opts)) => {
                    out.extend(opts.iter().map(|o| (i, Slot::Option(o))));
                    if p.kind == Kind::SelectNull && !opts.contains(&Value::Null) {
                        out.push((i, Slot::Option(&Value::Null)));
                    }
                }
                (_, Range::Numeric { .. }) => {}
            }
        }
        out
    }
}

/// The slot value of a number `x` of a `[lo, hi]` parameter: `(x - lo) / (hi - lo)`.
fn encode_number(x: f64, lo: f64, hi: f64) -> f64 {
    if hi > lo { (x - lo) / (hi - lo) } else { 0.0 }
}

/// The number of a slot value `t` (clamped to [0, 1]) of a `[lo, hi]`
/// parameter: `lo + t (hi - lo)` rounded to the parameter's precision, the
/// shortest decimal number (1 to 17 significant digits) in the range that
/// [`encode_number`] turns into `t` again, or failing that the closest float
/// that does (a few units in the last place away). So `decode(encode(d))` gives
/// back `d`'s values (0.1 stays 0.1, not 0.09999999999999998), whenever the
/// encoding tells the value from its neighbours. Without any such number (a
/// vector not made by `encode`), `lo + t (hi - lo)` itself.
fn decode_number(t: f64, lo: f64, hi: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    let y = (lo + t * (hi - lo)).clamp(lo, hi);
    let encodes = |x: &f64| (lo..=hi).contains(x) && encode_number(*x, lo, hi) == t;
    let shortest = (0..17).map(|digits| format!("{y:.digits$e}").parse::<f64>().unwrap_or(y));
    let (mut up, mut down) = (y, y);
    let closest = (0..8).flat_map(|_| {
        (up, down) = (up.next_up(), down.next_down());
        [down, up]
    });
    shortest.chain(closest).find(encodes).unwrap_or(y)
}

#[pymethods]
impl PyDesignSpace {
    /// The built-in design space, or the one of a design file (its ranges and
    /// probabilities replace the built-in ones). `extended=True` adds the
    /// parameters past the reference (`design.extension`: pockets, pleats, diamond
    /// darts, one-piece sleeves, folded cuffs and collars) after the reference's, as
    /// `garmentcode sample --extended` does.
    #[new]
    #[pyo3(signature = (path = None, *, extended = false))]
    fn new(path: Option<&Bound<'_, PyAny>>, extended: bool) -> PyResult<PyDesignSpace> {
        let source = path.map(path_or_str).transpose()?;
        let (space, _) = sample_cmd::load_space(source.as_deref(), extended).map_err(|e| DesignError::new_err(cli_message(e)))?;
        Ok(PyDesignSpace { space, source, extended })
    }

    /// Whether the space has the parameters past the reference (`design.extension`).
    #[getter]
    fn extended(&self) -> bool {
        self.extended
    }

    /// The design file this space comes from (`None`: built-in).
    #[getter]
    fn source(&self) -> Option<&str> {
        self.source.as_deref()
    }

    /// Every parameter as a dict: `path`, `type` (float, int, bool, select,
    /// select_null), `range` (`(lo, hi)` or a list of options), `default`,
    /// `default_prob` and `description`.
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        for p in self.space.params() {
            let d = PyDict::new(py);
            d.set_item("path", &p.path)?;
            d.set_item("type", p.kind.as_str())?;
            match &p.range {
                Range::Numeric { lo, hi } => d.set_item("range", (lo, hi))?,
                Range::Options(opts) => {
                    let opts: Vec<Bound<'py, PyAny>> = opts.iter().map(|o| value_to_py(py, o)).collect::<PyResult<_>>()?;
                    d.set_item("range", opts)?
                }
            }
            d.set_item("default", value_to_py(py, &p.default)?)?;
            d.set_item("default_prob", p.default_prob)?;
            d.set_item("description", &p.description)?;
            list.append(d)?;
        }
        Ok(list)
    }

    /// The parameter paths, in order.
    #[getter]
    fn paths(&self) -> Vec<String> {
        self.space.params().iter().map(|p| p.path.clone()).collect()
    }

    /// The default design: every parameter at its default, `{path: value}`.
    fn default<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for p in self.space.params() {
            d.set_item(&p.path, value_to_py(py, &p.default)?)?;
        }
        Ok(d)
    }

    /// Check a design (any form `build` accepts) against this space: its complete
    /// values `{path: value}`, or `DesignError` listing every problem.
    fn validate<'py>(&self, py: Python<'py>, design: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let (d, _) = load_design(design, &self.space)?;
        design_dict(py, &d, &self.space)
    }

    /// The design of sample `index` of a dataset with this `seed`, as
    /// `garmentcode sample` draws it (the first design the filters accept) on
    /// `bodies` (as `sample_dataset`'s; default the neutral body). With
    /// `with_body=True`, `(design, body)`: also the body the sampler drew it
    /// for, as the sample's `body_measurements.yaml` has it.
    #[pyo3(signature = (seed, index, bodies = None, *, with_body = false))]
    fn sample<'py>(
        &self,
        py: Python<'py>,
        seed: u64,
        index: u64,
        bodies: Option<&Bound<'py, PyAny>>,
        with_body: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let bodies = bodies_arg(bodies)?;
        let bodies = sample_cmd::load_bodies(bodies.as_deref()).map_err(|e| BodyError::new_err(cli_message(e)))?;
        let sampler = DatasetSampler::new(seed, self.space.clone(), bodies).map_err(|e| DesignError::new_err(e.to_string()))?;
        let s = match py.detach(|| sampler.draw(index)) {
            Outcome::Accepted(s) => s,
            Outcome::Exhausted { .. } => {
                return Err(DatasetError::new_err(format!(
                    "{}: every one of {} designs was rejected",
                    garments::sample::sample_name(index),
                    garments::sample::MAX_ATTEMPTS
                )));
            }
        };
        let design = design_dict(py, &s.design, &self.space)?;
        if !with_body {
            return Ok(design.into_any());
        }
        let body = PyBody { body: sampler.body_for(s.body, &s.design), name: sampler.bodies()[s.body].name.clone() };
        (design, body).into_bound_py_any(py)
    }

    /// The JSON Schema of a design file's values.
    fn json_schema<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = serde_json::to_string(&self.space.json_schema()).expect("the schema serialises");
        py.import("json")?.call_method1("loads", (text,))
    }

    /// A design in the reference's design-file layout (values with ranges,
    /// types and probabilities); the space's defaults without a design.
    #[pyo3(signature = (design = None))]
    fn to_yaml(&self, design: Option<&Bound<'_, PyAny>>) -> PyResult<String> {
        let d = match design {
            Some(o) => load_design(o, &self.space)?.0,
            None => Design::defaults(),
        };
        Ok(write_design(&d, &self.space))
    }

    /// Names of the slots of the vector encoding: `path` for numbers and flags,
    /// `path=option` for the one-hot slots of choices.
    fn vector_labels(&self) -> Vec<String> {
        let params = self.space.params();
        self.slots()
            .into_iter()
            .map(|(i, s)| match s {
                Slot::Option(o) => format!("{}={o}", params[i].path),
                _ => params[i].path.clone(),
            })
            .collect()
    }

    /// A design as a flat vector of floats: numbers normalised by their range to
    /// [0, 1], flags 0 or 1, choices one-hot (a `select_null` choice has a slot
    /// for `None`). `decode` inverts it.
    fn encode<'py>(&self, py: Python<'py>, design: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (d, _) = load_design(design, &self.space)?;
        let params = self.space.params();
        let values: Vec<Value> = params
            .iter()
            .map(|p| {
                let keys: Vec<&str> = p.path.split('.').collect();
                d.get_value(&keys).unwrap_or_else(|| p.default.clone())
            })
            .collect();
        let v: Vec<f64> = self
            .slots()
            .into_iter()
            .map(|(i, s)| match s {
                Slot::Number { lo, hi, .. } => encode_number(values[i].as_f64().unwrap_or(lo), lo, hi),
                Slot::Flag => f64::from(u8::from(values[i] == Value::Bool(true))),
                Slot::Option(o) => f64::from(u8::from(o.loosely_eq(&values[i]))),
            })
            .collect();
        py.import("numpy")?.call_method1("asarray", (v, "float64"))
    }

    /// The design of a vector (`encode`'s inverse; any vector of the right length
    /// decodes: numbers are clamped to their range and rounded to the parameter's
    /// precision (see [`decode_number`]), integers rounded, flags are true from
    /// 0.5, choices take the largest slot).
    fn decode<'py>(&self, py: Python<'py>, vector: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let v: Vec<f64> = py.import("numpy")?.call_method1("asarray", (vector, "float64"))?.call_method0("tolist")?.extract()?;
        let slots = self.slots();
        if v.len() != slots.len() {
            return Err(PyValueError::new_err(format!(
                "expected a vector of {} values (see vector_labels()), got {}",
                slots.len(),
                v.len()
            )));
        }
        let params = self.space.params();
        let mut values: Vec<Value> = params.iter().map(|p| p.default.clone()).collect();
        let mut best: Vec<f64> = vec![f64::NEG_INFINITY; params.len()];
        for ((i, s), x) in slots.into_iter().zip(v) {
            match s {
                Slot::Number { lo, hi, int: true } => values[i] = Value::Int(decode_number(x, lo, hi).round() as i64),
                Slot::Number { lo, hi, int: false } => values[i] = Value::Float(decode_number(x, lo, hi)),
                Slot::Flag => values[i] = Value::Bool(x >= 0.5),
                Slot::Option(o) => {
                    if x > best[i] {
                        best[i] = x;
                        values[i] = o.clone();
                    }
                }
            }
        }
        let d = PyDict::new(py);
        for (p, v) in params.iter().zip(&values) {
            d.set_item(&p.path, value_to_py(py, v)?)?;
        }
        Ok(d)
    }

    fn __len__(&self) -> usize {
        self.space.params().len()
    }

    fn __repr__(&self) -> String {
        let n = self.space.params().len();
        let extended = if self.extended { ", extended" } else { "" };
        match &self.source {
            Some(s) => format!("DesignSpace({s:?}{extended}, {n} parameters)"),
            None => format!("DesignSpace(built-in{extended}, {n} parameters)"),
        }
    }
}

/// `bodies=` as the CLI's `--bodies`: a string, or a list of names and files.
fn bodies_arg(o: Option<&Bound<'_, PyAny>>) -> PyResult<Option<String>> {
    let Some(o) = o else { return Ok(None) };
    if let Ok(s) = path_or_str(o) {
        return Ok(Some(s));
    }
    let mut items = Vec::new();
    for item in o.try_iter()? {
        let item = item?;
        let s = match item.cast::<PyBody>() {
            Ok(_) => return Err(InputError::new_err("bodies: give built-in body names or body files (Body objects are not files)")),
            Err(_) => path_or_str(&item)?,
        };
        items.push(s);
    }
    Ok(Some(items.join(",")))
}

/// What a built pattern was made of.
#[derive(Clone)]
struct Origin {
    design: Design,
    body: PyBody,
    checks: garments::build::Checks,
}

/// A sewing pattern: built by `garmentcode.build`, or read by `Pattern.from_json`.
#[pyclass(module = "garmentcode", name = "Pattern", frozen)]
struct PyPattern {
    pattern: garmentcode::Pattern,
    origin: Option<Origin>,
}

/// The drawing options of `build` and `render` for a layout (`"placed"` or
/// `"flat"`), a PNG resolution (`None`: the reference's 3 px per cm) and a PNG
/// background (`"white"` or `"none"`, transparent as the reference's).
fn draw_options(layout: &str, dpi: Option<f64>, background: &str) -> PyResult<garmentcode::draw::DrawOptions> {
    let background = match background {
        "white" => BackgroundArg::White,
        "none" => BackgroundArg::None,
        _ => return Err(PyValueError::new_err(format!("background: expected 'white' or 'none', got '{background}'"))),
    };
    if dpi.is_some_and(|d| !(d.is_finite() && d > 0.0 && d <= 1200.0)) {
        return Err(PyValueError::new_err("dpi: expected a resolution in dots per inch, above 0 and at most 1200"));
    }
    Ok(PngArgs { dpi, background }.draw_options(self::layout(layout)?))
}

/// `"placed"` or `"flat"`.
fn layout(s: &str) -> PyResult<garmentcode::draw::Layout> {
    match s {
        "placed" => Ok(garmentcode::draw::Layout::Placed),
        "flat" => Ok(garmentcode::draw::Layout::Flat),
        _ => Err(PyValueError::new_err(format!("layout: expected 'placed' or 'flat', got '{s}'"))),
    }
}

#[pymethods]
impl PyPattern {
    /// Read a specification: JSON text, or the path of a `specification.json`
    /// (any the reference writes). `name` names the pattern (default: from the
    /// file's name; none for text).
    #[staticmethod]
    #[pyo3(signature = (source, name = None))]
    fn from_json(source: &Bound<'_, PyAny>, name: Option<String>) -> PyResult<PyPattern> {
        let s = path_or_str(source)?;
        let pattern = if s.trim_start().starts_with('{') {
            garmentcode::Pattern::from_json(&s).map_err(|e| PatternError::new_err(format!("<text>: {e}")))?
        } else {
            let mut p = commands::read_pattern(&s).map_err(|e| PatternError::new_err(cli_message(e)))?;
            p.name = spec_name(&s);
            p
        };
        let mut pattern = pattern;
        if let Some(name) = name {
            pattern.name = name;
        }
        Ok(PyPattern { pattern, origin: None })
    }

    /// The pattern's name (the garment's name; a file's folder or prefix).
    #[getter]
    fn name(&self) -> &str {
        &self.pattern.name
    }

    /// The specification as a dict (`json.loads(pattern.to_json())`).
    #[getter]
    fn spec<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("json")?.call_method1("loads", (self.to_json()?,))
    }

    /// The specification file's text (`specification.json`, as the CLI writes it).
    fn to_json(&self) -> PyResult<String> {
        self.pattern.to_json().map_err(|e| PatternError::new_err(e.to_string()))
    }

    /// The drawing as SVG text (`pattern.svg`); layout `"placed"` or `"flat"`.
    #[pyo3(signature = (layout = "placed"))]
    fn svg(&self, py: Python<'_>, layout: &str) -> PyResult<String> {
        let opts = draw_options(layout, None, "white")?;
        py.detach(|| garmentcode::draw::to_svg(&self.pattern, &opts)).map_err(|e| PatternError::new_err(e.to_string()))
    }

    /// The drawing as PNG bytes (`pattern.png`), as `garmentcode build` draws it:
    /// layout `"placed"` or `"flat"`, `dpi` (default: the reference's 3 px per cm),
    /// background `"white"` or `"none"` (transparent, as the reference's).
    #[pyo3(signature = (layout = "placed", dpi = None, background = "white"))]
    fn png<'py>(&self, py: Python<'py>, layout: &str, dpi: Option<f64>, background: &str) -> PyResult<Bound<'py, PyBytes>> {
        let opts = draw_options(layout, dpi, background)?;
        let bytes = py.detach(|| garmentcode::draw::to_png(&self.pattern, &opts)).map_err(|e| PatternError::new_err(e.to_string()))?;
        Ok(PyBytes::new(py, &bytes))
    }

    /// The reference's validity checks of a built garment (`checks.json` plus
    /// `passed` and readable `warnings`); `None` for a pattern read from a file.
    #[getter]
    fn checks<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(o) = &self.origin else { return Ok(None) };
        let d = py.import("json")?.call_method1("loads", (o.checks.to_json(),))?;
        d.set_item("passed", o.checks.passed())?;
        d.set_item("warnings", o.checks.warnings())?;
        Ok(Some(d))
    }

    /// Structural problems of the pattern, as `garmentcode check --format json`
    /// lists them (`kind`, `severity`, `panel`, `edge`, `stitch`, `ratio`,
    /// `message`).
    fn problems<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let list: Vec<serde_json::Value> = garmentcode::validate(&self.pattern).iter().map(commands::check::problem_json).collect();
        py.import("json")?.call_method1("loads", (serde_json::to_string(&list).expect("problems serialise"),))
    }

    /// Panel names, in file order.
    #[getter]
    fn panels(&self) -> Vec<String> {
        self.pattern.panels.iter().map(|p| p.name.clone()).collect()
    }

    /// A panel as the specification writes it (a dict: `vertices`, `edges`,
    /// `translation`, `rotation`, ...), with the format extension's keys always there:
    /// `holes` and `lines` (lists, empty when the panel has none) and `layer`
    /// (`"outer"`, `"facing"` or `"lining"`). Raises `KeyError` for an unknown name.
    fn panel<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let Some(panel) = self.pattern.panel(name) else {
            let known: Vec<&str> = self.pattern.panels.iter().map(|p| p.name.as_str()).collect();
            return Err(PyKeyError::new_err(format!("no panel '{name}' (panels: {})", known.join(", "))));
        };
        let text = panel.to_json().map_err(|e| PatternError::new_err(e.to_string()))?;
        let mut v: serde_json::Value = serde_json::from_str(&text).map_err(|e| PatternError::new_err(e.to_string()))?;
        if let Some(m) = v.as_object_mut() {
            m.entry("holes").or_insert_with(|| serde_json::json!([]));
            m.entry("lines").or_insert_with(|| serde_json::json!([]));
            m.entry("layer").or_insert_with(|| serde_json::json!("outer"));
        }
        py.import("json")?.call_method1("loads", (v.to_string(),))
    }

    /// Stitches as `((panel, edge), (panel, edge))`.
    #[getter]
    fn stitches(&self) -> Vec<((String, usize), (String, usize))> {
        self.pattern
            .stitches
            .iter()
            .map(|s| ((s.sides[0].panel.clone(), s.sides[0].edge), (s.sides[1].panel.clone(), s.sides[1].edge)))
            .collect()
    }

    /// Stitches with a side on a hole or an inner line (the format extension,
    /// `docs/pattern-extension.md`), as `(side, side)` dicts the way the file writes
    /// them: `{"panel": "front", "hole": 0, "edge": 2}`, `"line"` for an inner line,
    /// neither for the outline.
    #[getter]
    fn inner_stitches<'py>(&self, py: Python<'py>) -> PyResult<Vec<(Bound<'py, PyDict>, Bound<'py, PyDict>)>> {
        let side = |s: &garmentcode::InnerSide| -> PyResult<Bound<'py, PyDict>> {
            let d = PyDict::new(py);
            d.set_item("panel", &s.panel)?;
            match s.place {
                garmentcode::EdgePlace::Outline => {}
                garmentcode::EdgePlace::Hole(k) => d.set_item("hole", k)?,
                garmentcode::EdgePlace::Line(k) => d.set_item("line", k)?,
            }
            d.set_item("edge", s.edge)?;
            Ok(d)
        };
        self.pattern.inner_stitches.iter().map(|s| Ok((side(&s.sides[0])?, side(&s.sides[1])?))).collect()
    }

    /// The design it was built from, `{path: value}` (`None` if read from a file).
    #[getter]
    fn design<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.origin.as_ref().map(|o| design_dict(py, &o.design, &garments::design::space_of(&o.design))).transpose()
    }

    /// The body it was built on (`None` if read from a file).
    #[getter]
    fn body(&self) -> Option<PyBody> {
        self.origin.as_ref().map(|o| o.body.clone())
    }

    /// The simulation box mesh at `resolution` cm (as `garmentcode mesh`).
    #[pyo3(signature = (resolution = 1.0))]
    fn mesh(&self, py: Python<'_>, resolution: f64) -> PyResult<PyMesh> {
        let mesh = py
            .detach(|| BoxMesh::new(&self.pattern, resolution))
            .map_err(|e| PatternError::new_err(format!("{}: cannot mesh the pattern: {e}", self.pattern.name)))?;
        Ok(PyMesh { mesh })
    }

    /// Drape the garment on a body: the box mesh at `resolution` cm simulated as cloth
    /// falling onto the body mesh (`garmentcode_drape`, the reference's scheme), for at
    /// most `max_frames` frames (it stops earlier once the garment is at rest).
    /// `body`: measurements as `build` takes them (default: the body the pattern was
    /// built on, else the neutral body); they place the waist and collar attachments.
    /// `body_mesh`: the path of a closed body OBJ in metres, y up (default: the body's
    /// built-in mesh). The GIL is released while it runs. Raises `BodyError` (no mesh
    /// for the body, a bad body mesh), `PatternError` (a pattern that cannot be
    /// meshed), `InputError` (a setting out of range).
    #[pyo3(signature = (body = None, body_mesh = None, max_frames = 2400, resolution = 1.0, self_collision = true))]
    fn drape(
        &self,
        py: Python<'_>,
        body: Option<&Bound<'_, PyAny>>,
        body_mesh: Option<&Bound<'_, PyAny>>,
        max_frames: i64,
        resolution: f64,
        self_collision: bool,
    ) -> PyResult<PyDrape> {
        let limit = garmentcode_drape::solver::MAX_FRAMES;
        if !(1..=limit as i64).contains(&max_frames) {
            return Err(InputError::new_err(format!("max_frames: expected a number of frames from 1 to {limit}, got {max_frames}")));
        }
        let body = match (body, &self.origin) {
            (None, Some(o)) => o.body.clone(),
            (b, _) => load_body(b)?,
        };
        let mesh_file = body_mesh.map(path_or_str).transpose()?;
        let pattern = &self.pattern;
        let (mesh, result) = py.detach(|| {
            let mesh = BoxMesh::new(pattern, resolution)
                .map_err(|e| PatternError::new_err(format!("{}: cannot mesh the pattern: {e}", pattern.name)))?;
            let collider = match &mesh_file {
                Some(f) => garmentcode_drape::BodyMesh::load(f.as_ref()),
                None => garmentcode_drape::BodyMesh::for_body(&body.name, &body.body),
            }
            .map_err(|e| BodyError::new_err(e.to_string()))?;
            let mut settings = garmentcode_drape::Settings::for_body(&body.body).with_panel_labels(pattern);
            settings.max_frames = max_frames as usize;
            settings.self_collision = self_collision;
            let result = garmentcode_drape::drape(&mesh, &collider, &settings).map_err(|e| match e {
                garmentcode_drape::DrapeError::Mesh { .. } => PatternError::new_err(e.to_string()),
                garmentcode_drape::DrapeError::Setting { .. } => InputError::new_err(e.to_string()),
            })?;
            Ok::<_, PyErr>((mesh, result))
        })?;
        Ok(PyDrape { mesh: PyMesh { mesh }, result })
    }

    /// Write the pattern's files into the folder `out`, as `garmentcode build`
    /// does: `specification.json` (always), `pattern.svg`, `pattern.png`, the mesh
    /// files and the printable pattern (PDF, SVG sheet, DXF, cutting layout) for the formats `svg`, `png`,
    /// `mesh`, `print`, and for a built pattern `design_params.yaml`,
    /// `body_measurements.yaml`, `checks.json`. `layout`, `dpi` and `background`
    /// as for `png`. The folder is replaced whole; one holding other files needs
    /// `force=True`. Returns the names of the files written.
    #[pyo3(signature = (out, formats = vec!["json".to_string(), "svg".to_string(), "png".to_string()], layout = "placed", mesh_resolution = 1.0, force = false, dpi = None, background = "white"))]
    fn write(
        &self,
        py: Python<'_>,
        out: &Bound<'_, PyAny>,
        formats: Vec<String>,
        layout: &str,
        mesh_resolution: f64,
        force: bool,
        dpi: Option<f64>,
        background: &str,
    ) -> PyResult<Vec<String>> {
        let out = PathBuf::from(path_or_str(out)?);
        let mut wanted = Vec::new();
        for f in &formats {
            wanted.push(match f.as_str() {
                "json" => BuildFormat::Json,
                "svg" => BuildFormat::Svg,
                "png" => BuildFormat::Png,
                "mesh" => BuildFormat::Mesh,
                "print" => BuildFormat::Print,
                _ => {
                    return Err(PyValueError::new_err(format!(
                        "formats: unknown format '{f}' (expected a list of json, svg, png, mesh, print)"
                    )));
                }
            });
        }
        let draw = draw_options(layout, dpi, background)?;
        let origin = self.origin.as_ref().map(|o| build_cmd::Origin { design: &o.design, body: &o.body.body, checks: &o.checks });
        let mut print = garmentcode::fabricate::PrintOptions { garment: self.pattern.name.clone(), ..Default::default() };
        if let Some(o) = &self.origin {
            print.size = o.body.name.clone();
        }
        py.detach(|| {
            let set = build_cmd::files(&self.pattern, origin, &wanted, &draw, mesh_resolution, &print)
                .map_err(|e| PatternError::new_err(format!("{}: {e}", self.pattern.name)))?;
            commands::write_folder(&set, &out, force).map_err(cli_err)?;
            Ok(set.names())
        })
    }

    fn __repr__(&self) -> String {
        format!("Pattern({:?}, {} panels, {} stitches)", self.pattern.name, self.pattern.panels.len(), self.pattern.stitches.len())
    }
}

/// A pattern's name from its file: `NAME_specification.json` gives `NAME`, a
/// plain `specification.json` its folder's name.
fn spec_name(path: &str) -> String {
    let p = std::path::Path::new(path);
    let stem = stem(path);
    if let Some(n) = stem.strip_suffix("_specification").filter(|n| !n.is_empty()) {
        return n.to_string();
    }
    let folder =
        std::fs::canonicalize(p).ok().and_then(|p| p.parent().and_then(|d| d.file_name()).map(|n| n.to_string_lossy().into_owned()));
    folder.unwrap_or(stem)
}

/// The simulation box mesh of a pattern, with its arrays as numpy arrays.
#[pyclass(module = "garmentcode", name = "Mesh", frozen)]
struct PyMesh {
    mesh: BoxMesh,
}

/// A numpy array of `values`: one-dimensional for `columns == 1`, else rows of
/// `columns` values.
fn array<'py, T: Copy + IntoPyObjectExt<'py>>(py: Python<'py>, values: Vec<T>, dtype: &str, columns: usize) -> PyResult<Bound<'py, PyAny>> {
    let rows = values.len() / columns;
    let a = py.import("numpy")?.call_method1("asarray", (values, dtype))?;
    if columns == 1 { Ok(a) } else { a.call_method1("reshape", ((rows, columns),)) }
}

#[pymethods]
impl PyMesh {
    /// Vertex positions, `(V, 3)` float64, cm: the merged stitch vertices first.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = self.mesh.vertices.iter().flat_map(|p| [p.x, p.y, p.z]).collect();
        array(py, v, "float64", 3)
    }

    /// Triangles, `(F, 3)` int64 vertex ids.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let f: Vec<i64> = self.mesh.faces.iter().flat_map(|f| f.vertices.map(|i| i as i64)).collect();
        array(py, f, "int64", 3)
    }

    /// Texture coordinates, `(T, 2)` float64 (cm from each panel's corner).
    #[getter]
    fn uvs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let t = self.mesh.texture_coordinates();
        let v: Vec<f64> = t.iter().flat_map(|p| [p.x, p.y]).collect();
        array(py, v, "float64", 2)
    }

    /// Texture coordinate ids of each triangle's corners, `(F, 3)` int64.
    #[getter]
    fn face_uvs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let f: Vec<i64> = self.mesh.faces.iter().flat_map(|f| f.uvs.map(|i| i as i64)).collect();
        array(py, f, "int64", 3)
    }

    /// Panel of each triangle, `(F,)` int64 (index into `panel_names`).
    #[getter]
    fn face_panels<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let f: Vec<i64> = self.mesh.faces.iter().map(|f| f.panel as i64).collect();
        array(py, f, "int64", 1)
    }

    /// Panel of each vertex, `(V,)` int64; -1 for merged stitch vertices.
    #[getter]
    fn vertex_panels<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<i64> = self
            .mesh
            .labels
            .iter()
            .map(|l| match l {
                VertexLabel::Panel(p) => *p as i64,
                VertexLabel::Stitch(_) => -1,
            })
            .collect();
        array(py, v, "int64", 1)
    }

    /// Segmentation label of each vertex (a panel name, or `stitch_k,...`), as
    /// in `_sim_segmentation.txt`.
    #[getter]
    fn vertex_labels(&self) -> Vec<String> {
        self.mesh.segmentation().lines().map(str::to_string).collect()
    }

    /// Panel names, in mesh order.
    #[getter]
    fn panel_names(&self) -> Vec<String> {
        self.mesh.panels.iter().map(|p| p.name.clone()).collect()
    }

    /// For each stitch, the vertex ids of its two sides paired point by point,
    /// `(n, 2)` int64 each (merged stitches pair a vertex with itself).
    #[getter]
    fn stitch_pairs<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyAny>>> {
        let m = &self.mesh;
        m.stitches
            .iter()
            .map(|s| {
                let side = |k: usize| -> Vec<usize> {
                    let (p, e) = s.sides[k];
                    let panel = &m.panels[p];
                    panel.edges[e].local.iter().map(|&l| panel.global[l]).collect()
                };
                let (mut a, b) = (side(0), side(1));
                if !s.right_wrong {
                    a.reverse();
                }
                let pairs: Vec<i64> = a.iter().zip(&b).flat_map(|(x, y)| [*x as i64, *y as i64]).collect();
                array(py, pairs, "int64", 2)
            })
            .collect()
    }

    /// Rest lengths of the edges near stitches: `(E, 2)` int64 vertex pairs and
    /// `(E,)` float64 lengths (cm), as in `_orig_lens.pickle`.
    #[getter]
    fn rest_lengths<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let r = &self.mesh.rest_lengths;
        let pairs: Vec<i64> = r.iter().flat_map(|(e, _)| e.map(|i| i as i64)).collect();
        let lens: Vec<f64> = r.iter().map(|(_, l)| *l).collect();
        PyTuple::new(py, [array(py, pairs, "int64", 2)?, array(py, lens, "float64", 1)?])
    }

    /// The mesh files as `{file name: bytes}` (as `garmentcode mesh` writes them).
    fn files<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, bytes) in self.mesh.files() {
            d.set_item(name, PyBytes::new(py, &bytes))?;
        }
        Ok(d)
    }

    fn __repr__(&self) -> String {
        format!("Mesh({:?}, {} vertices, {} triangles)", self.mesh.name, self.mesh.vertices.len(), self.mesh.faces.len())
    }
}

/// A draped garment (`Pattern.drape`): its box mesh's vertices moved onto the body.
#[pyclass(module = "garmentcode", name = "Drape", frozen)]
struct PyDrape {
    mesh: PyMesh,
    result: garmentcode_drape::Drape,
}

#[pymethods]
impl PyDrape {
    /// Draped vertex positions, `(V, 3)` float64, cm, y up, in the box mesh's order.
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = self.result.positions.iter().flat_map(|p| [p.x, p.y, p.z]).collect();
        array(py, v, "float64", 3)
    }

    /// Triangles, `(F, 3)` int64 vertex ids (the box mesh's).
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.mesh.faces(py)
    }

    /// Segmentation label of each vertex, as `Mesh.vertex_labels`.
    #[getter]
    fn vertex_labels(&self) -> Vec<String> {
        self.mesh.vertex_labels()
    }

    /// The box mesh that was draped (its rest positions, texture coordinates, panels).
    #[getter]
    fn mesh(&self) -> PyMesh {
        PyMesh { mesh: self.mesh.mesh.clone() }
    }

    /// Figures of the run: `frames`, `seconds`, `converged` (came to rest before the
    /// frame limit), `non_static_vertices`, `body_penetrations`, `self_intersections`.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let s = &self.result.stats;
        let d = PyDict::new(py);
        d.set_item("frames", s.frames)?;
        d.set_item("seconds", s.seconds)?;
        d.set_item("converged", s.converged)?;
        d.set_item("non_static_vertices", s.non_static_vertices)?;
        d.set_item("body_penetrations", s.body_penetrations)?;
        d.set_item("self_intersections", s.self_intersections)?;
        Ok(d)
    }

    /// `<name>_sim.obj`'s text: the box mesh's OBJ with the draped positions (cm).
    fn obj(&self) -> String {
        garmentcode_drape::sim_obj(&self.mesh.mesh, &self.result.positions)
    }

    fn __repr__(&self) -> String {
        let s = &self.result.stats;
        format!(
            "Drape({:?}, {} vertices, {} frames, {})",
            self.mesh.mesh.name,
            self.result.positions.len(),
            s.frames,
            if s.converged { "converged" } else { "not converged" }
        )
    }
}

/// Build a garment: `design` (a dict, nested as the reference's design files or
/// flat `{path: value}`; YAML text; a built-in design name or a design file
/// path) on `body` (a `Body`, a built-in name, a body file path, or a dict;
/// default the neutral body), named `name` (default: the design's name).
/// Raises `DesignError`, `BodyError` or `BuildError` with the CLI's messages.
#[pyfunction]
#[pyo3(signature = (design, body = None, name = None))]
fn build(py: Python<'_>, design: &Bound<'_, PyAny>, body: Option<&Bound<'_, PyAny>>, name: Option<String>) -> PyResult<PyPattern> {
    let space = garments::design::extended_design_space();
    let (design, design_label) = load_design(design, &space)?;
    let body = load_body(body)?;
    let name = name.unwrap_or_else(|| design_label.clone());
    let built = py
        .detach(|| garments::build::build(&design, &body.body, &name))
        .map_err(|e| BuildError::new_err(format!("{design_label} on {}: {e}", body.name)))?;
    Ok(PyPattern { pattern: built.pattern, origin: Some(Origin { design, body, checks: built.checks }) })
}

/// A design dict (nested as design files, or partly flat) as flat
/// `{path: value}`, in its own order and unchecked: for reading the designs of
/// samples, whose design space may be a file's (`iter_shards`).
#[pyfunction]
#[pyo3(name = "_flat_design")]
fn flat_design<'py>(py: Python<'py>, design: &Bound<'py, PyDict>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (path, v) in design_pairs(design)? {
        d.set_item(path, value_to_py(py, &v)?)?;
    }
    Ok(d)
}

/// Names of the built-in designs.
#[pyfunction]
fn builtin_designs() -> Vec<&'static str> {
    garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect()
}

/// Make a dataset, as `garmentcode sample` does (same files, byte for byte):
/// `n` samples of `seed` into the folder `out`. Keywords as the CLI's flags:
/// `jobs` (threads, default all cores), `bodies` (built-in names or body files,
/// a list or a comma-separated string, or a folder), `formats` (`json`, `svg`,
/// `png`, `mesh`), `layout` (`"folders"`, `"shards"` or `"shards:N"`), `design_space` (a
/// design file or a `DesignSpace` read from one), `extended` (also draw the
/// parameters past the reference, as `--extended`; implied by a `DesignSpace` made
/// with `extended=True`), `shard` (`(i, k)`: only the
/// samples `i % k == i`). `progress(done, total)` is called a few times a second
/// from the calling thread. `quiet` (the default) keeps the CLI's messages
/// (resuming, the closing summary line) off stderr; `quiet=False` prints them.
/// Builds run without the GIL. Returns the summary's path. Raises `InputError` for bad arguments and `DatasetError` when samples
/// fail or the run is interrupted (Ctrl-C, or an exception from `progress`).
#[pyfunction]
#[pyo3(signature = (n, seed, out, *, jobs = None, bodies = None, formats = None, layout = None, design_space = None, extended = false, shard = None, progress = None, quiet = true))]
fn sample_dataset(
    py: Python<'_>,
    n: u64,
    seed: u64,
    out: &Bound<'_, PyAny>,
    jobs: Option<u64>,
    bodies: Option<&Bound<'_, PyAny>>,
    formats: Option<&Bound<'_, PyAny>>,
    layout: Option<String>,
    design_space: Option<&Bound<'_, PyAny>>,
    extended: bool,
    shard: Option<(u64, u64)>,
    progress: Option<Py<PyAny>>,
    quiet: bool,
) -> PyResult<String> {
    if n == 0 {
        return Err(InputError::new_err("sample_dataset: n must be at least 1"));
    }
    if jobs == Some(0) {
        return Err(InputError::new_err("sample_dataset: jobs must be at least 1"));
    }
    let formats = match formats {
        None => None,
        Some(f) => match f.extract::<String>() {
            Ok(s) => Some(s),
            Err(_) => Some(f.extract::<Vec<String>>()?.join(",")),
        },
    };
    let (design_space, extended) = match design_space {
        None => (None, extended),
        Some(o) => match o.cast::<PyDesignSpace>() {
            Ok(s) => (s.get().source.clone(), extended || s.get().extended),
            Err(_) => (Some(path_or_str(o)?), extended),
        },
    };
    let out = PathBuf::from(path_or_str(out)?);
    let args = SampleArgs {
        n: Some(n),
        seed: Some(seed),
        out: out.clone(),
        design_space,
        extended,
        bodies: bodies_arg(bodies)?,
        jobs,
        shard: shard.map(|(i, k)| format!("{i}/{k}")),
        formats,
        replay: None,
        layout,
        unpack: Vec::new(),
        sim: Default::default(),
    };
    let shard_of = shard;
    let mut callback_error: Option<PyErr> = None;
    let result = py.detach(|| {
        let mut report = |done: u64, total: u64| -> Result<(), String> {
            Python::attach(|py| {
                let r = py.check_signals().and_then(|()| match &progress {
                    Some(f) => f.call1(py, (done, total)).map(|_| ()),
                    None => Ok(()),
                });
                r.map_err(|e| {
                    let m = format!("interrupted: {e}");
                    callback_error.get_or_insert(e);
                    m
                })
            })
        };
        sample_cmd::run_reporting(args, Some(&mut report), quiet)
    });
    if let Some(e) = callback_error {
        return Err(e);
    }
    result.map_err(cli_err)?;
    let name = match shard_of {
        None => "dataset_properties.yaml".to_string(),
        Some((i, k)) => format!("dataset_properties_shard_{i}_of_{k}.yaml"),
    };
    Ok(out.join(name).to_string_lossy().into_owned())
}

/// Compare two specifications (JSON texts) as the parity test and
/// `garmentcode compare` do: by geometry within `tol` cm, sleeve, cuff and hood
/// panels by how they sew. Returns `{"pass", "reasons", "chaotic", "max_dev"}`.
#[pyfunction]
#[pyo3(signature = (expected, actual, tol = None))]
fn compare_specs<'py>(py: Python<'py>, expected: &str, actual: &str, tol: Option<f64>) -> PyResult<Bound<'py, PyDict>> {
    let mut opts = garmentcode_compare::CompareOptions::default();
    if let Some(t) = tol {
        opts.tol = t;
    }
    let v = py.detach(|| garmentcode_compare::compare_spec_texts(expected, actual, &opts));
    let d = PyDict::new(py);
    d.set_item("pass", v.pass)?;
    d.set_item("reasons", v.reasons)?;
    d.set_item("chaotic", v.chaotic)?;
    d.set_item("max_dev", v.max_dev)?;
    Ok(d)
}

/// Parse YAML text as the library reads design and body files, into plain Python
/// values (dicts, lists, numbers, strings, `None`): for reading the YAML files of
/// samples without a YAML package.
#[pyfunction]
fn parse_yaml<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    let node = garmentcode::parity::yaml::parse(text).map_err(|e| InputError::new_err(e.to_string()))?;
    yaml_to_py(py, &node)
}

/// A YAML node as Python values.
fn yaml_to_py<'py>(py: Python<'py>, n: &garmentcode::parity::yaml::Node) -> PyResult<Bound<'py, PyAny>> {
    use garmentcode::parity::yaml::Value as Y;
    Ok(match &n.value {
        Y::Map(pairs) => {
            let d = PyDict::new(py);
            for (k, v) in pairs {
                d.set_item(yaml_to_py(py, k)?, yaml_to_py(py, v)?)?;
            }
            d.into_any()
        }
        Y::Seq(items) => PyList::new(py, items.iter().map(|i| yaml_to_py(py, i)).collect::<PyResult<Vec<_>>>()?)?.into_any(),
        Y::Str(s) => PyString::new(py, s).into_any(),
        Y::Float(x) => x.into_bound_py_any(py)?,
        Y::Int(i) => i.into_bound_py_any(py)?,
        Y::Bool(b) => b.into_bound_py_any(py)?,
        Y::Null => py.None().into_bound(py),
    })
}

/// The compiled module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<PyBody>()?;
    m.add_class::<PyDesignSpace>()?;
    m.add_class::<PyPattern>()?;
    m.add_class::<PyMesh>()?;
    m.add_class::<PyDrape>()?;
    m.add_function(wrap_pyfunction!(build, m)?)?;
    m.add_function(wrap_pyfunction!(builtin_designs, m)?)?;
    m.add_function(wrap_pyfunction!(sample_dataset, m)?)?;
    m.add_function(wrap_pyfunction!(compare_specs, m)?)?;
    m.add_function(wrap_pyfunction!(parse_yaml, m)?)?;
    m.add_function(wrap_pyfunction!(flat_design, m)?)?;
    // The suffixes of the mesh files after a pattern's name (`_boxmesh.obj`, ...).
    m.add("_MESH_FILE_SUFFIXES", garmentcode::mesh::write::FILE_SUFFIXES.to_vec())?;
    m.add("DesignError", py.get_type::<DesignError>())?;
    m.add("BodyError", py.get_type::<BodyError>())?;
    m.add("BuildError", py.get_type::<BuildError>())?;
    m.add("PatternError", py.get_type::<PatternError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("DatasetError", py.get_type::<DatasetError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
