//! The pattern comparator, a tool apart from the runtime (`garmentcode`): geometric
//! comparison of two sewing patterns, with the judgement the project's
//! parity checks use (`compare_spec.py`, written for the reference cases): two
//! patterns are the same garment when every outline and stitch matches to a
//! tolerance (0.05 cm), whatever the vertex order or the JSON text.
//!
//! A pattern is judged by its geometry, not its text: panels are matched by name; each
//! outline is sampled densely and compared with a symmetric Hausdorff-like distance in
//! panel-local 2D and in world 3D (start vertex, edge order and loop direction do not
//! matter); perimeters are compared; stitches are an unordered set of unordered pairs of
//! sides identified by panel name and edge geometry, plus their flags. Sleeve, sleeve-cuff
//! and hood panels ("chaotic" panels, built in the reference from a numerically chaotic
//! fit) and the stitches touching them are judged by the chaotic rule (see `chaos.rs`).
//!
//! The port follows the script statement by statement, including its early exits (which
//! make reported deviations lower bounds), its iteration orders, and CPython's float
//! arithmetic where it could change a verdict ([`py`]). Messages for malformed input are
//! close to, but not always the same text as, Python's exception messages.

#![warn(missing_docs)]

mod chaos;
mod dist;
mod geom;
/// CPython's float arithmetic where it can change a verdict (tested bit for bit).
#[doc(hidden)]
pub mod py;
mod pyjson;
mod stitch;

use geom::PanelGeom;
use py::PyErr;
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use stitch::{Panels, Stitch};

/// Largest deviation (cm) of an outline, vertex or perimeter judged equal.
pub const DEFAULT_TOL: f64 = 0.05;
/// Spacing (cm) of the points sampled along outlines.
pub const SAMPLE_STEP: f64 = 0.5;

/// Rotation convention of the panels' Euler angles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Euler {
    /// scipy intrinsic 'XYZ': R = Rx @ Ry @ Rz (what pygarment writes; the default)
    #[default]
    Xyz,
    /// extrinsic 'xyz': R = Rz @ Ry @ Rx (pygarment's simulator code)
    ExtrinsicXyz,
}

/// The chaotic rule's constants (the script's module globals; calibration in its source).
#[derive(Clone, Debug, PartialEq)]
pub struct ChaosParams {
    /// a chaotic group may deviate by tol + fit_gain * fit_dev ...
    pub fit_gain: f64,
    /// ... but at most this much (cm): 2D/3D outline, perimeter of a panel
    pub outline_tol: f64,
    /// ... and at most this much (cm): position of a stitch side on it
    pub stitch_tol: f64,
    /// relative: |ratio_actual / ratio_expected - 1| of a stitch's side lengths
    pub ratio_tol: f64,
    /// relative: the same for a chaotic group's total seam length with non-chaotic panels
    pub seam_ratio_tol: f64,
    /// cm: edges / stitches this short may exist on one side only; also the tolerance for
    /// a non-chaotic side's position and per-pair length
    pub sliver_len: f64,
}

impl Default for ChaosParams {
    fn default() -> Self {
        ChaosParams { fit_gain: 3.5, outline_tol: 2.8, stitch_tol: 3.3, ratio_tol: 0.065, seam_ratio_tol: 0.0025, sliver_len: 1.0 }
    }
}

/// The script's command-line knobs, with its defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareOptions {
    /// tolerance in cm (`--tol`, 0.05)
    pub tol: f64,
    /// Hausdorff sampling step in cm (hidden `--step`, 0.5)
    pub step: f64,
    /// `--euler XYZ|xyz`
    pub euler: Euler,
    /// `--strict`: also fail on panel label or loop orientation differences
    pub strict: bool,
    /// `--no-chaotic-rule` clears it
    pub chaotic_rule: bool,
    /// `--chaos-*`, `--sliver` overrides
    pub chaos: ChaosParams,
    /// Exact Hausdorff distances for chaotic panels: what `--chaos-stats` switches on in the
    /// script (it also changes the wording "at least" of their reasons).
    pub exact_chaos: bool,
}

impl Default for CompareOptions {
    fn default() -> Self {
        CompareOptions {
            tol: DEFAULT_TOL,
            step: SAMPLE_STEP,
            euler: Euler::Xyz,
            strict: false,
            chaotic_rule: true,
            chaos: ChaosParams::default(),
            exact_chaos: false,
        }
    }
}

/// The judgement of one comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// The patterns are judged the same garment.
    pub pass: bool,
    /// passed only thanks to the chaotic rule (the script's "PASS*")
    pub chaotic: bool,
    /// the strict rule alone would have failed on chaotic panels / stitches
    pub rule_needed: bool,
    /// largest deviation judged strictly (cm; inf for structural failures)
    pub max_dev: f64,
    /// Why the comparison failed, most important first.
    pub reasons: Vec<String>,
    /// Remarks that did not fail the comparison.
    pub notes: Vec<String>,
    /// how many panels were judged by the chaotic rule
    pub chaotic_panels: usize,
    /// largest chaotic outline / perimeter deviation (cm)
    pub chaos_dev: f64,
}

impl Verdict {
    fn fail(reason: String) -> Verdict {
        Verdict {
            pass: false,
            chaotic: false,
            rule_needed: false,
            max_dev: f64::INFINITY,
            reasons: vec![reason],
            notes: Vec::new(),
            chaotic_panels: 0,
            chaos_dev: 0.0,
        }
    }

    fn ok() -> Verdict {
        Verdict { pass: true, max_dev: 0.0, reasons: Vec::new(), ..Verdict::fail(String::new()) }
    }

    /// The script's result line: `PASS|PASS*|FAIL <name> max_dev=... [(chaotic rule: ...)]: reasons`.
    pub fn report_line(&self, name: &str, max_reasons: i64) -> String {
        let dtxt = if self.max_dev == f64::INFINITY { "inf".to_string() } else { py::fixed(self.max_dev, 4) };
        let tag = if self.chaotic {
            "PASS*"
        } else if self.pass {
            "PASS"
        } else {
            "FAIL"
        };
        let mut line = format!("{tag} {name} max_dev={dtxt}");
        if self.chaotic {
            line += &format!(" (chaotic rule: {} panels, chaotic max_dev={})", self.chaotic_panels, py::fixed(self.chaos_dev, 4));
        }
        if !self.reasons.is_empty() {
            // reasons[:max_reasons] with Python's slice semantics
            let n = self.reasons.len() as i64;
            let end = if max_reasons < 0 { (n + max_reasons).max(0) } else { max_reasons.min(n) } as usize;
            let shown = &self.reasons[..end];
            let more = self.reasons.len() - shown.len();
            line += ": ";
            line += &shown.join("; ");
            if more > 0 {
                line += &format!("; (+{more} more)");
            }
        }
        line
    }
}

/// Why loading or comparing stopped: the script's `SpecError` (a reason), or any other
/// Python exception (reported as a comparator error).
#[derive(Clone, Debug)]
pub enum Fail {
    /// A judged difference or malformed input (the reason).
    Spec(String),
    /// Any other error while comparing.
    Py(PyErr),
}

impl From<PyErr> for Fail {
    fn from(e: PyErr) -> Self {
        Fail::Py(e)
    }
}

/// A specification to compare: its parsed JSON (or why it could not be read) and the path
/// the script would name in its messages.
struct Source {
    path: String,
    json: Result<Value, String>,
}

/// Parse like Python's `json.loads`: NaN / Infinity literals accepted, errors worded as
/// Python's `JSONDecodeError` (serde_json's own text where Python would have accepted it).
fn parse_json(text: &str) -> Result<Value, String> {
    let first = match serde_json::from_str(text) {
        Ok(v) => return Ok(v),
        Err(e) => e,
    };
    if let Some(t) = py::rewrite_nonstandard_literals(text) {
        if let Ok(v) = serde_json::from_str(&t) {
            return Ok(v);
        }
    }
    Err(pyjson::decode_error(text).unwrap_or_else(|| first.to_string()))
}

fn read_source(path: &Path) -> Source {
    let json = match std::fs::read(path) {
        Err(e) => Err(match e.kind() {
            // Python's OSError text
            std::io::ErrorKind::NotFound => {
                format!("[Errno 2] No such file or directory: {}", py::repr_str(&path.display().to_string()))
            }
            std::io::ErrorKind::IsADirectory => {
                format!("[Errno 21] Is a directory: {}", py::repr_str(&path.display().to_string()))
            }
            _ => e.to_string(),
        }),
        Ok(bytes) => match String::from_utf8(bytes) {
            Err(e) => Err(e.to_string()),
            Ok(text) => parse_json(&text),
        },
    };
    Source { path: path.display().to_string(), json }
}

/// `load_spec`: the spec and its panels (scaled to cm).
fn load_spec<'v>(src: &'v Source, which: &str, euler: Euler) -> Result<(&'v Value, Panels), Fail> {
    let spec = match &src.json {
        Ok(v) => v,
        Err(e) => return Err(Fail::Spec(format!("{which}: cannot read {}: {e}", src.path))),
    };
    let no_panels = || Fail::Spec(format!("{which}: no pattern.panels in {}", src.path));
    let Value::Object(top) = spec else { return Err(no_panels()) };
    let pattern = top.get("pattern").ok_or_else(no_panels)?;
    // `'panels' in spec['pattern']`, then `spec['pattern']['panels']`
    let panels_v = match pattern {
        Value::Object(o) => o.get("panels").ok_or_else(no_panels)?,
        Value::String(s) if s.contains("panels") => {
            return Err(Fail::Py(PyErr::new("TypeError", "string indices must be integers")));
        }
        Value::Array(a) if a.contains(&Value::String("panels".into())) => {
            return Err(Fail::Py(PyErr::new("TypeError", "list indices must be integers or slices, not str")));
        }
        _ => return Err(no_panels()),
    };
    let props = match top.get("properties") {
        Some(p) if py::truthy(p) => p.clone(),
        _ => Value::Object(Default::default()),
    };
    let Value::Object(props) = props else {
        return Err(Fail::Py(PyErr::new("AttributeError", format!("'{}' object has no attribute 'get'", py::type_name(&props)))));
    };
    let units = match props.get("units_in_meter") {
        Some(u) => py::float(u)?,
        None => 100.0,
    };
    let scale = py::div(100.0, units)?;
    let absolute = props.get("curvature_coords").is_some_and(|c| c.as_str() == Some("absolute"));
    let Value::Object(pm) = panels_v else {
        return Err(Fail::Py(PyErr::new("AttributeError", format!("'{}' object has no attribute 'items'", py::type_name(panels_v)))));
    };
    let mut panels = BTreeMap::new();
    for (name, pdata) in pm {
        match PanelGeom::new(name, pdata, scale, absolute, euler) {
            Ok(p) => {
                panels.insert(name.clone(), p);
            }
            Err(Fail::Spec(m)) => return Err(Fail::Spec(format!("{which}: {m}"))),
            Err(e) => return Err(e),
        }
    }
    Ok((spec, panels))
}

/// Loop orientation and label checks, shared by the strict and the chaotic panel rules:
/// failures with `strict`, notes otherwise.
pub(crate) fn orientation_and_label(
    name: &str,
    pe: &PanelGeom,
    pa: &PanelGeom,
    strict: bool,
    reasons: &mut Vec<String>,
    notes: &mut Vec<String>,
) {
    let sink = if strict { reasons } else { notes };
    if (pe.signed_area() > 0.0) != (pa.signed_area() > 0.0) {
        sink.push(format!("panel {name}: edge loop orientation reversed"));
    }
    // (label or None) != (label or None)
    let norm = |l: &Option<Value>| l.clone().filter(py::truthy).unwrap_or(Value::Null);
    if !py::eq(&norm(&pe.label), &norm(&pa.label)) {
        let r = |l: &Option<Value>| l.as_ref().map(py::repr).unwrap_or_else(|| "None".into());
        sink.push(format!("panel {name}: label {} vs expected {}", r(&pa.label), r(&pe.label)));
    }
}

/// Strict judgement of one panel. With `verdict_only` the deviations may be lower bounds
/// (enough to know whether they exceed tol). Returns (reasons, notes, max deviation).
fn compare_panel(
    name: &str,
    pe: &PanelGeom,
    pa: &PanelGeom,
    tol: f64,
    step: f64,
    strict: bool,
    verdict_only: bool,
) -> (Vec<String>, Vec<String>, f64) {
    let stop = if verdict_only { Some(tol) } else { None };
    let (mut reasons, mut notes) = (Vec::new(), Vec::new());
    let fast = dist::fast_pointwise(pe, pa);
    let (mut d2, mut d3) = (None, None);
    let (mut need2, mut need3) = (true, true);
    if let Some((f2, f3)) = fast {
        d2 = Some(f2);
        d3 = Some(f3);
        need2 = f2 > tol;
        need3 = f3 > tol;
    }
    let cell = py::max(2.0 * step, 1.0);
    if need2 {
        d2 = Some(dist::hausdorff(&dist::lift(pe.dense(step)), &dist::lift(pa.dense(step)), cell, false, stop));
    }
    let d2 = d2.unwrap();
    if need3 && !(verdict_only && d2 > tol) {
        d3 = Some(dist::hausdorff(&pe.dense3d(step), &pa.dense3d(step), cell, false, stop));
    }
    let d3 = d3.unwrap_or(0.0); // not evaluated: the verdict is already known
    let per = (pe.perimeter() - pa.perimeter()).abs();
    if d2 > tol {
        reasons.push(format!("panel {name}: 2D outline deviates by {} cm", py::fixed(d2, 4)));
    }
    if d3 > tol {
        reasons.push(format!("panel {name}: 3D outline deviates by {} cm", py::fixed(d3, 4)));
    }
    if per > tol {
        reasons.push(format!("panel {name}: perimeter {} vs expected {}", py::fixed(pa.perimeter(), 4), py::fixed(pe.perimeter(), 4)));
    }
    orientation_and_label(name, pe, pa, strict, &mut reasons, &mut notes);
    (reasons, notes, py::max(py::max(d2, d3), per))
}

/// `compare_specs` after reading: Ok(verdict) or the exception that the script's `run_one`
/// turns into a comparator error.
fn compare_sources(es: &Source, as_: &Source, opts: &CompareOptions) -> Result<Verdict, PyErr> {
    let mut v = Verdict::ok();
    let (spec_e, pan_e) = match load_spec(es, "expected", opts.euler) {
        Ok(x) => x,
        Err(Fail::Spec(m)) => return Ok(Verdict::fail(format!("cannot use expected spec: {m}"))),
        Err(Fail::Py(e)) => return Err(e),
    };
    let (spec_a, pan_a) = match load_spec(as_, "actual", opts.euler) {
        Ok(x) => x,
        Err(Fail::Spec(m)) => return Ok(Verdict::fail(m)),
        Err(Fail::Py(e)) => return Err(e),
    };
    let (tol, step, cp) = (opts.tol, opts.step, &opts.chaos);
    let mut reasons: Vec<String> = Vec::new();
    let mut notes: Vec<String> = Vec::new();
    let mut strict_only: Vec<String> = Vec::new(); // strict-rule failures on chaotic parts
    let mut worst = 0.0f64;
    let chaotic: BTreeSet<String> =
        if opts.chaotic_rule { pan_e.keys().filter(|n| chaos::is_chaotic(n)).cloned().collect() } else { BTreeSet::new() };
    let missing: Vec<&str> = pan_e.keys().filter(|n| !pan_a.contains_key(*n)).map(|s| s.as_str()).collect();
    let extra: Vec<&str> = pan_a.keys().filter(|n| !pan_e.contains_key(*n)).map(|s| s.as_str()).collect();
    if !missing.is_empty() {
        reasons.push(format!("missing panels: {}", missing.join(", ")));
        worst = f64::INFINITY;
    }
    if !extra.is_empty() {
        reasons.push(format!("unexpected panels: {}", extra.join(", ")));
        worst = f64::INFINITY;
    }
    // Stitches first: the chaotic-rule stitch comparison measures how far each chaotic
    // group's fitted curves moved (fit_dev), which bounds how far its panels may move.
    let panel_reasons = std::mem::take(&mut reasons);
    let mut fit_dev: BTreeMap<String, Option<f64>> = BTreeMap::new();
    match stitch::stitch_list(spec_e, &pan_e, "expected") {
        Err(Fail::Spec(m)) => reasons.push(format!("cannot use expected stitches: {m}")),
        Err(Fail::Py(e)) => return Err(e),
        Ok(st_e) => match stitch::stitch_list(spec_a, &pan_a, "actual") {
            Err(Fail::Spec(m)) => {
                reasons.push(m);
                worst = f64::INFINITY;
            }
            Err(Fail::Py(e)) => return Err(e),
            Ok(st_a) => {
                let touches = |st: &Stitch| chaotic.contains(st.sides[0].panel) || chaotic.contains(st.sides[1].panel);
                let (ce, ne): (Vec<&Stitch>, Vec<&Stitch>) = st_e.iter().partition(|st| touches(st));
                let (ca, na): (Vec<&Stitch>, Vec<&Stitch>) = st_a.iter().partition(|st| touches(st));
                let (r, d) = stitch::compare_stitches(&ne, &na, tol);
                reasons.extend(r);
                worst = py::max(worst, d);
                if !chaotic.is_empty() {
                    let groups = chaos::chaotic_groups(&st_e, &chaotic);
                    strict_only.extend(stitch::compare_stitches(&ce, &ca, tol).0);
                    let (r, fd) = chaos::compare_chaotic_stitches(&ce, &ca, &groups, tol, cp)?;
                    reasons.extend(r);
                    fit_dev = groups.iter().map(|(n, g)| (n.clone(), fd.get(g).copied())).collect();
                }
            }
        },
    }
    let stitch_reasons = std::mem::replace(&mut reasons, panel_reasons);
    for (name, pe) in &pan_e {
        let Some(pa) = pan_a.get(name) else { continue };
        let is_ch = chaotic.contains(name);
        let (r, n, d) = compare_panel(name, pe, pa, tol, step, opts.strict, is_ch);
        if is_ch {
            v.chaotic_panels += 1;
            strict_only.extend(r);
            let limit = chaos::chaos_limit(tol, fit_dev.get(name).copied().flatten(), cp.outline_tol, cp.fit_gain);
            let res = chaos::compare_chaotic_panel(name, pe, pa, step, opts.strict, limit, opts.exact_chaos, cp);
            let m = py::max(py::max(res.devs[0], res.devs[1]), res.devs[2]);
            v.chaos_dev = py::max(v.chaos_dev, m);
            reasons.extend(res.reasons);
            notes.extend(res.notes);
            continue;
        }
        reasons.extend(r);
        notes.extend(n);
        worst = py::max(worst, d);
    }
    reasons.extend(stitch_reasons);
    v.rule_needed = !strict_only.is_empty();
    v.pass = reasons.is_empty();
    v.chaotic = v.pass && v.rule_needed;
    v.max_dev = worst;
    v.reasons = reasons;
    v.notes = notes;
    Ok(v)
}

fn run(es: &Source, as_: &Source, opts: &CompareOptions) -> Verdict {
    compare_sources(es, as_, opts).unwrap_or_else(|e| Verdict::fail(format!("comparator error: {e}")))
}

/// Compare two parsed `specification.json` documents.
pub fn compare_patterns(expected: &Value, actual: &Value, opts: &CompareOptions) -> Verdict {
    let es = Source { path: "<expected>".into(), json: Ok(expected.clone()) };
    let as_ = Source { path: "<actual>".into(), json: Ok(actual.clone()) };
    run(&es, &as_, opts)
}

/// Compare two specification texts.
pub fn compare_spec_texts(expected: &str, actual: &str, opts: &CompareOptions) -> Verdict {
    let es = Source { path: "<expected>".into(), json: parse_json(expected) };
    let as_ = Source { path: "<actual>".into(), json: parse_json(actual) };
    run(&es, &as_, opts)
}

/// Compare two specification files (the script's single-file mode).
pub fn compare_spec_files(expected: &Path, actual: &Path, opts: &CompareOptions) -> Verdict {
    run(&read_source(expected), &read_source(actual), opts)
}

/// Compare the runtime's patterns (serialised as the reference writes them).
pub fn compare_runtime_patterns(expected: &garmentcode::Pattern, actual: &garmentcode::Pattern, opts: &CompareOptions) -> Verdict {
    let text = |p: &garmentcode::Pattern, which: &str| match p.to_json() {
        Ok(t) => t,
        Err(e) => format!("{{\"unserialisable {which} pattern\": {}}}", serde_json::Value::String(e.to_string())),
    };
    compare_spec_texts(&text(expected, "expected"), &text(actual, "actual"), opts)
}

fn error_first_line(path: &Path) -> Option<String> {
    let bytes = std::fs::read(path).ok()?;
    py::first_line(&String::from_utf8_lossy(&bytes))
}

/// Compare one case directory (`specification.json` or `error.txt`) with another: an
/// expected error passes iff the actual case has an error.txt and no specification.
pub fn compare_case(exp_dir: &Path, act_dir: &Path, opts: &CompareOptions) -> Verdict {
    let (e_spec, e_err) = (exp_dir.join("specification.json"), exp_dir.join("error.txt"));
    let (a_spec, a_err) = (act_dir.join("specification.json"), act_dir.join("error.txt"));
    if !act_dir.is_dir() {
        return Verdict::fail("actual case directory missing".into());
    }
    let (a_has_spec, a_has_err) = (a_spec.is_file(), a_err.is_file());
    let neither = || Verdict::fail("actual has neither specification.json nor error.txt".into());
    if e_spec.is_file() {
        if a_has_spec {
            return compare_spec_files(&e_spec, &a_spec, opts);
        }
        if a_has_err {
            let msg = error_first_line(&a_err).unwrap_or_else(|| "(empty error.txt)".into());
            return Verdict::fail(format!("expected a pattern, actual reported error: {msg}"));
        }
        return neither();
    }
    if a_has_err && !a_has_spec {
        return Verdict::ok();
    }
    if a_has_spec {
        if !e_err.is_file() {
            // the script opens the expected error.txt regardless
            return Verdict::fail(format!(
                "comparator error: FileNotFoundError: [Errno 2] No such file or directory: {}",
                py::repr_str(&e_err.display().to_string())
            ));
        }
        let msg = error_first_line(&e_err).unwrap_or_default();
        return Verdict::fail(format!("expected an error ({msg}), actual produced a pattern"));
    }
    neither()
}

/// `--cases`: every sub-directory of `expected_dir` holding a specification.json or an
/// error.txt is a case, compared with the directory of the same name in `actual_dir`.
/// Cases are in sorted order.
pub fn compare_case_dirs(expected_dir: &Path, actual_dir: &Path, opts: &CompareOptions) -> Result<Vec<(String, Verdict)>, String> {
    if !expected_dir.is_dir() {
        return Err(format!("expected directory not found: {}", expected_dir.display()));
    }
    let mut names: Vec<String> = std::fs::read_dir(expected_dir)
        .map_err(|e| e.to_string())?
        .filter_map(|d| d.ok())
        .map(|d| d.file_name().to_string_lossy().into_owned())
        .filter(|n| {
            let d = expected_dir.join(n);
            d.join("specification.json").is_file() || d.join("error.txt").is_file()
        })
        .collect();
    names.sort();
    Ok(names
        .into_iter()
        .map(|n| {
            let v = compare_case(&expected_dir.join(&n), &actual_dir.join(&n), opts);
            (n, v)
        })
        .collect())
}

/// The script's closing lines: the PASS* count (or "chaotic rule off") and
/// `N passed, M failed`.
pub fn summary(results: &[(String, Verdict)], opts: &CompareOptions) -> [String; 2] {
    let passed = results.iter().filter(|(_, v)| v.pass).count();
    let failed = results.len() - passed;
    let starred = results.iter().filter(|(_, v)| v.chaotic).count();
    let first = if opts.chaotic_rule {
        format!("PASS*: {starred} of {passed} passed cases needed the chaotic rule")
    } else {
        "chaotic rule off".to_string()
    };
    [first, format!("{passed} passed, {failed} failed")]
}
