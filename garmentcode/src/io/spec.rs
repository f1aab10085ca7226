//! Reading and writing `specification.json`.
//!
//! Writing reproduces the reference's layout (`json.dump(indent=2)`, the same key
//! order) with floats in Python's shortest round-trip form; `-0.0` is written `0.0`
//! and non-finite numbers are refused, so the same pattern always gives the same
//! bytes. Reading accepts the reference's files and its legacy variants (list-form
//! curvature, absolute curvature coordinates, other units) and reports malformed
//! input with the JSON path of the offending value.

use crate::error::{Error, Result};
use crate::math::{Vec2, abs_to_rel};
use crate::parity::float_repr::write_python_float;
use crate::pattern::{
    Curvature, EXTENSION_VERSION, EdgePlace, EdgeSpec, Hole, HoleKind, InnerLine, InnerSide, InnerStitch, Layer, LineKind, PanelSpec,
    Pattern, Properties, StitchSide, StitchSpec,
};
use serde_json::Value;
use std::fmt::Write;

/// Largest coordinate, translation or arc radius a specification may hold, in cm.
pub const MAX_EXTENT_CM: f64 = 10_000.0;
/// Largest relative control-point coordinate (in edge lengths).
pub const MAX_CONTROL: f64 = 1_000.0;
/// Most panels a specification may hold (the garments of the reference cases have
/// at most 31).
pub const MAX_PANELS: usize = 200;
/// Most edges one panel may have (at most 59 in the reference cases).
pub const MAX_EDGES_PER_PANEL: usize = 500;
/// Most edges all panels together may have (at most 208 in the reference cases):
/// keeps the pairwise self-intersection test of every outline well under a second.
pub const MAX_EDGES: usize = 5_000;
/// Longest name (of a pattern or panel) or label (garment and size on a print), in
/// characters: the reference's are under 40, and every output repeats them.
pub const MAX_NAME_CHARS: usize = 100;
/// Most holes and inner lines one panel may hold together (format extension; a
/// garment has a few darts, pockets and folds per panel). Their edges count in
/// [`MAX_EDGES_PER_PANEL`] and [`MAX_EDGES`] with the outline's.
pub const MAX_INNER_LOOPS_PER_PANEL: usize = 100;
/// Most stitches on holes and inner lines (`pattern.inner_stitches`) a
/// specification may hold.
pub const MAX_INNER_STITCHES: usize = 1_000;

/// Refuse a name or label longer than [`MAX_NAME_CHARS`] or holding control
/// characters; `what` says where it is (for the error).
pub fn check_name(what: &str, name: &str) -> Result<()> {
    if name.chars().count() > MAX_NAME_CHARS {
        return Err(Error::Input(format!("{what}: {} is longer than {MAX_NAME_CHARS} characters", crate::message::quote(name))));
    }
    if name.chars().any(char::is_control) {
        return Err(Error::Input(format!("{what}: {} holds a control character (a line break, a tab, ...)", crate::message::quote(name))));
    }
    Ok(())
}

/// What a file that is not JSON looks like, as a hint after the parse error: one
/// of this tool's YAML files, or other text.
fn looks_like(text: &str) -> &'static str {
    let first = text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with('#')).unwrap_or("");
    if first.starts_with("design:") {
        "; this is a YAML design file, not a pattern: `garmentcode build --design FILE` builds it into one"
    } else if first.starts_with("body:") {
        "; this is a YAML body file, not a pattern: it goes with `garmentcode build --body FILE`"
    } else if first.starts_with('{') || first.starts_with('[') {
        ""
    } else if first.contains(": ") || first.ends_with(':') {
        "; this looks like YAML, not the JSON of a pattern (specification.json)"
    } else {
        "; a pattern is the JSON file specification.json that `garmentcode build` writes"
    }
}

impl Curvature {
    /// Whether this is an arc under 180° of a radius beyond [`MAX_EXTENT_CM`]
    /// (100 m), or an infinite one: a straight line to within `chord² / 8r`
    /// (under 0.03 cm for a 50 cm edge), written straight.
    pub fn is_flat_arc(&self) -> bool {
        matches!(*self, Curvature::Circle { radius, large_arc: false, .. } if radius.abs() > MAX_EXTENT_CM)
    }
}

impl Pattern {
    /// Parse a specification file's text.
    pub fn from_json(text: &str) -> Result<Pattern> {
        let v: Value = serde_json::from_str(text).map_err(|e| Error::Input(format!("malformed JSON: {e}{}", looks_like(text))))?;
        let mut p = read_pattern(&v)?;
        p.normalize_units()?;
        p.straighten_flat_arcs();
        p.check_limits()?;
        Ok(p)
    }

    /// Write every flat arc ([`Curvature::is_flat_arc`]: radius beyond 100 m,
    /// under 180°) as the straight edge it is, so that a nearly straight neckline
    /// (a body with level shoulders) reads and writes within the limits.
    pub fn straighten_flat_arcs(&mut self) {
        for e in self.panels.iter_mut().flat_map(PanelSpec::all_edges_mut) {
            if e.curvature.as_ref().is_some_and(Curvature::is_flat_arc) {
                e.curvature = None;
            }
        }
    }

    /// Refuse geometry no garment has, before any algorithm whose work grows with
    /// it runs: coordinates beyond [`MAX_EXTENT_CM`], control points far outside
    /// their edge, and more panels or edges than [`MAX_PANELS`],
    /// [`MAX_EDGES_PER_PANEL`] and [`MAX_EDGES`]. Reading a specification checks
    /// this; a pattern built in memory that fails it would not read back.
    pub fn check_limits(&self) -> Result<()> {
        let far = |x: f64| x.abs() > MAX_EXTENT_CM;
        if self.panels.len() > MAX_PANELS {
            return Err(Error::Input(format!("{} panels: at most {MAX_PANELS} are accepted", self.panels.len())));
        }
        let edges: usize = self.panels.iter().map(|p| p.all_edges().count()).sum();
        if edges > MAX_EDGES {
            return Err(Error::Input(format!("{edges} edges in all: at most {MAX_EDGES} are accepted")));
        }
        if self.inner_stitches.len() > MAX_INNER_STITCHES {
            return Err(Error::Input(format!(
                "pattern.inner_stitches: {} stitches, at most {MAX_INNER_STITCHES} are accepted",
                self.inner_stitches.len()
            )));
        }
        check_name("name", &self.name)?;
        for p in &self.panels {
            check_name("pattern.panels", &p.name)?;
            let at = format!("pattern.panels.{}", p.name);
            let n_edges = p.all_edges().count();
            if n_edges > MAX_EDGES_PER_PANEL {
                return Err(Error::Input(format!("{at}: {n_edges} edges, at most {MAX_EDGES_PER_PANEL} are accepted")));
            }
            if p.holes.len() + p.lines.len() > MAX_INNER_LOOPS_PER_PANEL {
                return Err(Error::Input(format!(
                    "{at}: {} holes and inner lines, at most {MAX_INNER_LOOPS_PER_PANEL} are accepted",
                    p.holes.len() + p.lines.len()
                )));
            }
            for (what, name) in p.holes.iter().map(|h| ("holes", &h.name)).chain(p.lines.iter().map(|l| ("lines", &l.name))) {
                check_name(&format!("{at}.{what}"), name)?;
            }
            let inner_vertices = p.holes.iter().flat_map(|h| &h.vertices).chain(p.lines.iter().flat_map(|l| &l.vertices));
            let coords = p.vertices.iter().chain(inner_vertices).flatten().chain(&p.translation);
            if let Some(x) = coords.copied().find(|x| far(*x)) {
                return Err(Error::Input(format!(
                    "{at}: coordinate {} cm is beyond ±{MAX_EXTENT_CM} cm (100 m); no garment is that large",
                    crate::message::short(x)
                )));
            }
            for (i, e) in p.all_edges().enumerate() {
                let bad = match &e.curvature {
                    Some(Curvature::Quadratic(c)) => c.iter().any(|x| x.abs() > MAX_CONTROL),
                    Some(Curvature::Cubic(c1, c2)) => c1.iter().chain(c2).any(|x| x.abs() > MAX_CONTROL),
                    Some(Curvature::Circle { radius, .. }) => far(*radius),
                    None => false,
                };
                if bad {
                    return Err(Error::Input(format!(
                        "{at}.{}.curvature: a control point more than {MAX_CONTROL} edge lengths away or a radius beyond {MAX_EXTENT_CM} cm",
                        p.edge_path(i)
                    )));
                }
            }
        }
        Ok(())
    }

    /// The specification file's text.
    pub fn to_json(&self) -> Result<String> {
        let mut w = Writer { out: String::with_capacity(64 * 1024), depth: 0 };
        w.open('{');
        w.field("pattern");
        w.open('{');
        w.field("panels");
        if self.panels.is_empty() {
            w.out.push_str("{}");
        } else {
            w.open('{');
            for (i, p) in self.panels.iter().enumerate() {
                w.sep(i);
                w.key(&p.name);
                write_panel(&mut w, p)?;
            }
            w.close('}');
        }
        w.sep(1);
        w.field("stitches");
        if self.stitches.is_empty() {
            w.out.push_str("[]");
        } else {
            w.open('[');
            for (i, s) in self.stitches.iter().enumerate() {
                w.sep(i);
                let [a, b] = &s.sides;
                write_stitch(&mut w, [(&a.panel, EdgePlace::Outline, a.edge), (&b.panel, EdgePlace::Outline, b.edge)], s.right_wrong);
            }
            w.close(']');
        }
        if !self.inner_stitches.is_empty() {
            w.sep(2);
            w.field("inner_stitches");
            w.open('[');
            for (i, s) in self.inner_stitches.iter().enumerate() {
                w.sep(i);
                let [a, b] = &s.sides;
                write_stitch(&mut w, [(&a.panel, a.place, a.edge), (&b.panel, b.place, b.edge)], s.right_wrong);
            }
            w.close(']');
        }
        if let Some(order) = &self.panel_order {
            w.sep(2);
            w.field("panel_order");
            w.string_list(order);
        }
        w.close('}');
        w.sep(1);
        w.field("parameters");
        w.value(&self.parameters)?;
        w.sep(2);
        w.field("parameter_order");
        w.value(&self.parameter_order)?;
        w.sep(3);
        w.field("properties");
        w.open('{');
        let pr = &self.properties;
        w.field("curvature_coords");
        w.string(&pr.curvature_coords);
        w.sep(1);
        w.field("normalize_panel_translation");
        w.out.push_str(if pr.normalize_panel_translation { "true" } else { "false" });
        w.sep(2);
        w.field("normalized_edge_loops");
        w.out.push_str(if pr.normalized_edge_loops { "true" } else { "false" });
        w.sep(3);
        w.field("units_in_meter");
        if pr.units_in_meter.fract() == 0.0 && pr.units_in_meter.abs() < 1e15 {
            let _ = write!(w.out, "{}", pr.units_in_meter as i64);
        } else {
            w.float(pr.units_in_meter)?;
        }
        for (k, v) in &pr.extra {
            w.sep(4);
            w.key(k);
            w.value(v)?;
        }
        if self.uses_extension() {
            w.sep(4);
            w.field("extension_version");
            w.index(EXTENSION_VERSION as usize);
        }
        w.close('}');
        w.close('}');
        w.out.push('\n');
        Ok(w.out)
    }

    /// Convert legacy unit scales to centimetres.
    fn normalize_units(&mut self) -> Result<()> {
        let u = self.properties.units_in_meter;
        if !(u.is_finite() && (1.0..=1000.0).contains(&u)) {
            return Err(Error::Input(format!(
                "properties.units_in_meter: expected 1 (metres) to 1000 (millimetres), usually 100 (centimetres), got {}",
                crate::message::short(u)
            )));
        }
        if u != 100.0 {
            let k = 100.0 / u;
            for p in &mut self.panels {
                let inner = p.holes.iter_mut().flat_map(|h| &mut h.vertices).chain(p.lines.iter_mut().flat_map(|l| &mut l.vertices));
                p.vertices.iter_mut().chain(inner).for_each(|v| *v = [v[0] * k, v[1] * k]);
                p.translation = p.translation.map(|t| t * k);
                for e in p.all_edges_mut() {
                    if let Some(Curvature::Circle { radius, .. }) = &mut e.curvature {
                        *radius *= k;
                    }
                }
            }
            self.properties.extra.push(("original_units_in_meter".into(), serde_json::json!(u)));
            self.properties.units_in_meter = 100.0;
        }
        Ok(())
    }
}

impl PanelSpec {
    /// The panel as the specification file writes it under `pattern.panels.NAME`
    /// (the same keys and numbers as [`Pattern::to_json`], without the name).
    ///
    /// ```
    /// let text = r#"{"pattern": {"panels": {"square": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
    ///   "vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
    ///   "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}},
    ///   "stitches": []},
    ///   "properties": {"curvature_coords": "relative", "normalize_panel_translation": false,
    ///   "normalized_edge_loops": true, "units_in_meter": 100}}"#;
    /// let pattern = garmentcode::Pattern::from_json(text).unwrap();
    /// let panel: serde_json::Value = serde_json::from_str(&pattern.panel("square").unwrap().to_json().unwrap()).unwrap();
    /// assert_eq!(panel["vertices"][2], serde_json::json!([10.0, 10.0]));
    /// ```
    pub fn to_json(&self) -> Result<String> {
        let mut w = Writer { out: String::with_capacity(4096), depth: 0 };
        write_panel(&mut w, self)?;
        Ok(w.out)
    }
}

fn write_panel(w: &mut Writer, p: &PanelSpec) -> Result<()> {
    w.open('{');
    w.field("translation");
    w.float_list(&p.translation)?;
    w.sep(1);
    w.field("rotation");
    w.float_list(&p.rotation)?;
    w.sep(2);
    write_geometry(w, &p.vertices, &p.edges)?;
    if let Some(l) = &p.label {
        w.sep(4);
        w.field("label");
        w.string(l);
    }
    if !p.holes.is_empty() {
        w.sep(4);
        w.field("holes");
        w.open('[');
        for (i, h) in p.holes.iter().enumerate() {
            w.sep(i);
            w.open('{');
            w.field("name");
            w.string(&h.name);
            w.sep(1);
            w.field("kind");
            w.literal(match h.kind {
                HoleKind::Cut => "cut",
                HoleKind::Dart => "dart",
            });
            w.sep(2);
            write_geometry(w, &h.vertices, &h.edges)?;
            w.close('}');
        }
        w.close(']');
    }
    if !p.lines.is_empty() {
        w.sep(4);
        w.field("lines");
        w.open('[');
        for (i, l) in p.lines.iter().enumerate() {
            w.sep(i);
            w.open('{');
            w.field("name");
            w.string(&l.name);
            w.sep(1);
            w.field("kind");
            w.literal(line_kind_name(l.kind));
            if let LineKind::Fold { angle } = l.kind {
                w.sep(2);
                w.field("angle");
                w.float(angle)?;
            }
            w.sep(2);
            write_geometry(w, &l.vertices, &l.edges)?;
            w.close('}');
        }
        w.close(']');
    }
    if p.layer != Layer::Outer {
        w.sep(4);
        w.field("layer");
        w.literal(layer_name(p.layer));
    }
    w.close('}');
    Ok(())
}

/// The JSON name of a line kind.
fn line_kind_name(k: LineKind) -> &'static str {
    match k {
        LineKind::Fold { .. } => "fold",
        LineKind::Placement => "placement",
        LineKind::PleatFold => "pleat_fold",
        LineKind::PleatPlacement => "pleat_placement",
    }
}

/// The JSON name of a layer.
fn layer_name(l: Layer) -> &'static str {
    match l {
        Layer::Outer => "outer",
        Layer::Facing => "facing",
        Layer::Lining => "lining",
    }
}

/// One stitch: two sides `{"panel", ["hole" | "line"], "edge"}` and the optional
/// `"right_wrong"`.
fn write_stitch(w: &mut Writer, sides: [(&str, EdgePlace, usize); 2], right_wrong: bool) {
    w.open('[');
    for (k, (panel, place, edge)) in sides.into_iter().enumerate() {
        w.sep(k);
        w.open('{');
        w.field("panel");
        w.string(panel);
        match place {
            EdgePlace::Outline => {}
            EdgePlace::Hole(h) => {
                w.sep(1);
                w.field("hole");
                w.index(h);
            }
            EdgePlace::Line(l) => {
                w.sep(1);
                w.field("line");
                w.index(l);
            }
        }
        w.sep(1);
        w.field("edge");
        w.index(edge);
        w.close('}');
    }
    if right_wrong {
        w.sep(2);
        w.literal("right_wrong");
    }
    w.close(']');
}

/// `"vertices": [...], "edges": [...]` (of an outline, a hole or a line).
fn write_geometry(w: &mut Writer, vertices: &[[f64; 2]], edges: &[EdgeSpec]) -> Result<()> {
    w.field("vertices");
    if vertices.is_empty() {
        w.out.push_str("[]");
    } else {
        w.open('[');
        for (i, v) in vertices.iter().enumerate() {
            w.sep(i);
            w.float_list(v)?;
        }
        w.close(']');
    }
    w.sep(1);
    w.field("edges");
    if edges.is_empty() {
        w.out.push_str("[]");
    } else {
        w.open('[');
        for (i, e) in edges.iter().enumerate() {
            w.sep(i);
            write_edge(w, e)?;
        }
        w.close(']');
    }
    Ok(())
}

fn write_edge(w: &mut Writer, e: &EdgeSpec) -> Result<()> {
    w.open('{');
    w.field("endpoints");
    w.open('[');
    w.index(e.endpoints[0]);
    w.sep(1);
    w.index(e.endpoints[1]);
    w.close(']');
    if let Some(l) = &e.label {
        w.sep(1);
        w.field("label");
        w.string(l);
    }
    if let Some(c) = &e.curvature {
        w.sep(1);
        w.field("curvature");
        w.open('{');
        w.field("type");
        match c {
            Curvature::Quadratic(cp) => {
                w.literal("quadratic");
                w.sep(1);
                w.field("params");
                w.open('[');
                w.float_list(cp)?;
                w.close(']');
            }
            Curvature::Cubic(c1, c2) => {
                w.literal("cubic");
                w.sep(1);
                w.field("params");
                w.open('[');
                w.float_list(c1)?;
                w.sep(1);
                w.float_list(c2)?;
                w.close(']');
            }
            Curvature::Circle { radius, large_arc, right } => {
                w.literal("circle");
                w.sep(1);
                w.field("params");
                w.open('[');
                w.float(*radius)?;
                w.sep(1);
                w.out.push(if *large_arc { '1' } else { '0' });
                w.sep(2);
                w.out.push(if *right { '1' } else { '0' });
                w.close(']');
            }
        }
        w.close('}');
    }
    w.close('}');
    Ok(())
}

/// Indented JSON writer in the layout of Python's `json.dump(indent=2)`.
struct Writer {
    out: String,
    depth: usize,
}

impl Writer {
    fn newline(&mut self) {
        /// A newline and the indentation of the deepest level written (one copy).
        const INDENT: &str = "\n                                        ";
        match INDENT.get(..1 + 2 * self.depth) {
            Some(s) => self.out.push_str(s),
            None => {
                self.out.push('\n');
                for _ in 0..self.depth {
                    self.out.push_str("  ");
                }
            }
        }
    }
    fn open(&mut self, c: char) {
        self.out.push(c);
        self.depth += 1;
        self.newline();
    }
    fn close(&mut self, c: char) {
        self.depth -= 1;
        self.newline();
        self.out.push(c);
    }
    /// Separator before item `i` of a container (nothing before the first).
    fn sep(&mut self, i: usize) {
        if i > 0 {
            /// A comma, a newline and the indentation (one copy).
            const SEP: &str = ",\n                                        ";
            match SEP.get(..2 + 2 * self.depth) {
                Some(s) => self.out.push_str(s),
                None => {
                    self.out.push(',');
                    self.newline();
                }
            }
        }
    }
    fn key(&mut self, k: &str) {
        self.string(k);
        self.out.push_str(": ");
    }
    /// A key that is one of this writer's own names (plain ASCII: no escapes).
    fn field(&mut self, k: &'static str) {
        self.out.push('"');
        self.out.push_str(k);
        self.out.push_str("\": ");
    }
    /// A string value that is one of this writer's own names.
    fn literal(&mut self, s: &'static str) {
        self.out.push('"');
        self.out.push_str(s);
        self.out.push('"');
    }
    fn string(&mut self, s: &str) {
        // Names and labels are plain ASCII and need no escapes; anything else goes
        // through serde_json, which escapes like Python's json with ensure_ascii=False.
        if s.bytes().all(|b| (0x20..0x7f).contains(&b) && b != b'"' && b != b'\\') {
            self.out.push('"');
            self.out.push_str(s);
            self.out.push('"');
        } else {
            self.out.push_str(&serde_json::to_string(s).expect("strings serialise"));
        }
    }
    /// A non-negative integer (vertex and edge indices), without `fmt`.
    fn index(&mut self, i: usize) {
        let mut digits = [0u8; 20];
        let mut n = 0;
        let mut rest = i;
        loop {
            digits[n] = b'0' + (rest % 10) as u8;
            n += 1;
            rest /= 10;
            if rest == 0 {
                break;
            }
        }
        for &d in digits[..n].iter().rev() {
            self.out.push(char::from(d));
        }
    }
    fn string_list(&mut self, items: &[String]) {
        if items.is_empty() {
            self.out.push_str("[]");
            return;
        }
        self.open('[');
        for (i, s) in items.iter().enumerate() {
            self.sep(i);
            self.string(s);
        }
        self.close(']');
    }
    fn float(&mut self, x: f64) -> Result<()> {
        if !x.is_finite() {
            return Err(Error::Geometry(format!("cannot write the non-finite number {x}")));
        }
        write_python_float(&mut self.out, x);
        Ok(())
    }
    fn float_list(&mut self, xs: &[f64]) -> Result<()> {
        self.open('[');
        for (i, x) in xs.iter().enumerate() {
            self.sep(i);
            self.float(*x)?;
        }
        self.close(']');
        Ok(())
    }
    fn value(&mut self, v: &Value) -> Result<()> {
        match v {
            Value::Null => self.out.push_str("null"),
            Value::Bool(b) => self.out.push_str(if *b { "true" } else { "false" }),
            Value::Number(n) => {
                if let Some(i) = n.as_i64() {
                    let _ = write!(self.out, "{i}");
                } else {
                    self.float(n.as_f64().unwrap_or(f64::NAN))?;
                }
            }
            Value::String(s) => self.string(s),
            Value::Array(items) => {
                if items.is_empty() {
                    self.out.push_str("[]");
                } else {
                    self.open('[');
                    for (i, x) in items.iter().enumerate() {
                        self.sep(i);
                        self.value(x)?;
                    }
                    self.close(']');
                }
            }
            Value::Object(map) => {
                if map.is_empty() {
                    self.out.push_str("{}");
                } else {
                    self.open('{');
                    for (i, (k, x)) in map.iter().enumerate() {
                        self.sep(i);
                        self.key(k);
                        self.value(x)?;
                    }
                    self.close('}');
                }
            }
        }
        Ok(())
    }
}

// ---------------------------------------------------------------- reading

fn read_pattern(v: &Value) -> Result<Pattern> {
    let root = obj(v, "")?;
    let pat = obj(get(root, "pattern", "")?, "pattern")?;
    let mut p = Pattern::new("pattern");
    if let Some(props) = root.get("properties") {
        p.properties = read_properties(props)?;
    }
    let absolute = p.properties.curvature_coords == "absolute";
    let panels = obj(get(pat, "panels", "pattern")?, "pattern.panels")?;
    for (name, pv) in panels {
        p.panels.push(read_panel(name, pv, absolute)?);
    }
    if let Some(st) = pat.get("stitches") {
        let list = arr(st, "pattern.stitches")?;
        for (i, s) in list.iter().enumerate() {
            p.stitches.push(read_stitch(s, &format!("pattern.stitches[{i}]"))?);
        }
    }
    if let Some(st) = pat.get("inner_stitches") {
        let list = arr(st, "pattern.inner_stitches")?;
        if list.len() > MAX_INNER_STITCHES {
            return Err(Error::Input(format!(
                "pattern.inner_stitches: {} stitches, at most {MAX_INNER_STITCHES} are accepted",
                list.len()
            )));
        }
        for (i, s) in list.iter().enumerate() {
            p.inner_stitches.push(read_inner_stitch(s, &format!("pattern.inner_stitches[{i}]"))?);
        }
    }
    if let Some(order) = pat.get("panel_order") {
        let list = arr(order, "pattern.panel_order")?;
        let mut names = Vec::new();
        for (i, n) in list.iter().enumerate() {
            names.push(string(n, &format!("pattern.panel_order[{i}]"))?.to_string());
        }
        p.panel_order = Some(names);
    }
    if let Some(params) = root.get("parameters") {
        p.parameters = params.clone();
    }
    if let Some(order) = root.get("parameter_order") {
        p.parameter_order = order.clone();
    }
    if absolute {
        p.properties.curvature_coords = "relative".into();
    }
    Ok(p)
}

fn read_properties(v: &Value) -> Result<Properties> {
    let m = obj(v, "properties")?;
    let mut pr = Properties::default();
    for (k, x) in m {
        let path = format!("properties.{k}");
        match k.as_str() {
            "curvature_coords" => {
                let s = string(x, &path)?;
                if s != "relative" && s != "absolute" {
                    return Err(Error::Input(format!("{path}: expected \"relative\" or \"absolute\", got {}", crate::message::quote(s))));
                }
                pr.curvature_coords = s.to_string();
            }
            "normalize_panel_translation" => pr.normalize_panel_translation = boolean(x, &path)?,
            "normalized_edge_loops" => pr.normalized_edge_loops = boolean(x, &path)?,
            "units_in_meter" => pr.units_in_meter = number(x, &path)?,
            // Written again from what the pattern holds (see `Pattern::uses_extension`).
            "extension_version" => match x.as_u64() {
                Some(v) if (1..=u64::from(EXTENSION_VERSION)).contains(&v) => {}
                _ => {
                    return Err(Error::Input(format!(
                        "{path}: expected a format extension version from 1 to {EXTENSION_VERSION}, got {} (a newer garmentcode wrote this file?)",
                        kind(x)
                    )));
                }
            },
            _ => pr.extra.push((k.clone(), x.clone())),
        }
    }
    Ok(pr)
}

fn read_panel(name: &str, v: &Value, absolute: bool) -> Result<PanelSpec> {
    check_name("pattern.panels", name)?;
    let path = format!("pattern.panels.{name}");
    let m = obj(v, &path)?;
    let translation = vec_n::<3>(get(m, "translation", &path)?, &format!("{path}.translation"))?;
    let rotation = vec_n::<3>(get(m, "rotation", &path)?, &format!("{path}.rotation"))?;
    let (vertices, edges) = read_geometry(m, &path, absolute)?;
    let label = match m.get("label") {
        None | Some(Value::Null) => None,
        Some(l) => Some(string(l, &format!("{path}.label"))?.to_string()).filter(|s| !s.is_empty()),
    };
    let mut panel = PanelSpec::new(name, translation, rotation, vertices, edges, label);
    let inner_list = |key: &str| -> Result<&[Value]> {
        let Some(v) = m.get(key) else { return Ok(&[]) };
        let list = arr(v, &format!("{path}.{key}"))?;
        if list.len() > MAX_INNER_LOOPS_PER_PANEL {
            return Err(Error::Input(format!("{path}.{key}: {} items, at most {MAX_INNER_LOOPS_PER_PANEL} are accepted", list.len())));
        }
        Ok(list)
    };
    for (i, h) in inner_list("holes")?.iter().enumerate() {
        let hp = format!("{path}.holes[{i}]");
        let hm = obj(h, &hp)?;
        let name = inner_name(hm, &hp)?;
        let kind = match string(get(hm, "kind", &hp)?, &format!("{hp}.kind"))? {
            "cut" => HoleKind::Cut,
            "dart" => HoleKind::Dart,
            other => {
                return Err(Error::Input(format!("{hp}.kind: expected \"cut\" or \"dart\", got {}", crate::message::quote(other))));
            }
        };
        let (vertices, edges) = read_geometry(hm, &hp, absolute)?;
        panel.holes.push(Hole { name, kind, vertices, edges });
    }
    for (i, l) in inner_list("lines")?.iter().enumerate() {
        let lp = format!("{path}.lines[{i}]");
        let lm = obj(l, &lp)?;
        let name = inner_name(lm, &lp)?;
        let kind = match string(get(lm, "kind", &lp)?, &format!("{lp}.kind"))? {
            "fold" => LineKind::Fold { angle: number(get(lm, "angle", &lp)?, &format!("{lp}.angle"))? },
            "placement" => LineKind::Placement,
            "pleat_fold" => LineKind::PleatFold,
            "pleat_placement" => LineKind::PleatPlacement,
            other => {
                return Err(Error::Input(format!(
                    "{lp}.kind: expected \"fold\", \"placement\", \"pleat_fold\" or \"pleat_placement\", got {}",
                    crate::message::quote(other)
                )));
            }
        };
        let (vertices, edges) = read_geometry(lm, &lp, absolute)?;
        panel.lines.push(InnerLine { name, kind, vertices, edges });
    }
    if let Some(l) = m.get("layer") {
        panel.layer = match string(l, &format!("{path}.layer"))? {
            "outer" => Layer::Outer,
            "facing" => Layer::Facing,
            "lining" => Layer::Lining,
            other => {
                return Err(Error::Input(format!(
                    "{path}.layer: expected \"outer\", \"facing\" or \"lining\", got {}",
                    crate::message::quote(other)
                )));
            }
        };
    }
    Ok(panel)
}

/// The `name` of a hole or an inner line.
fn inner_name(m: &serde_json::Map<String, Value>, path: &str) -> Result<String> {
    let name = string(get(m, "name", path)?, &format!("{path}.name"))?;
    check_name(&format!("{path}.name"), name)?;
    Ok(name.to_string())
}

/// The `vertices` and `edges` of an outline, a hole or an inner line at `path`.
fn read_geometry(m: &serde_json::Map<String, Value>, path: &str, absolute: bool) -> Result<(Vec<[f64; 2]>, Vec<EdgeSpec>)> {
    let vl = arr(get(m, "vertices", path)?, &format!("{path}.vertices"))?;
    let mut vertices = Vec::with_capacity(vl.len());
    for (i, x) in vl.iter().enumerate() {
        vertices.push(vec_n::<2>(x, &format!("{path}.vertices[{i}]"))?);
    }
    let el = arr(get(m, "edges", path)?, &format!("{path}.edges"))?;
    let mut edges = Vec::with_capacity(el.len());
    for (i, x) in el.iter().enumerate() {
        edges.push(read_edge(x, &format!("{path}.edges[{i}]"), &vertices, absolute)?);
    }
    Ok((vertices, edges))
}

fn read_edge(v: &Value, path: &str, vertices: &[[f64; 2]], absolute: bool) -> Result<EdgeSpec> {
    let m = obj(v, path)?;
    let ep = arr(get(m, "endpoints", path)?, &format!("{path}.endpoints"))?;
    if ep.len() != 2 {
        return Err(Error::Input(format!("{path}.endpoints: expected 2 vertex indices, got {}", ep.len())));
    }
    let mut endpoints = [0usize; 2];
    for (k, x) in ep.iter().enumerate() {
        endpoints[k] = index(x, &format!("{path}.endpoints[{k}]"))?;
    }
    let label = match m.get("label") {
        None | Some(Value::Null) => None,
        Some(l) => Some(string(l, &format!("{path}.label"))?.to_string()).filter(|s| !s.is_empty()),
    };
    let curvature = match m.get("curvature") {
        None | Some(Value::Null) => None,
        Some(Value::Array(_)) => {
            // Legacy form: a bare control point of a quadratic.
            let cp = vec_n::<2>(&m["curvature"], &format!("{path}.curvature"))?;
            let cp = if absolute {
                let (s, e) = endpoint_positions(vertices, endpoints, path)?;
                abs_to_rel(s, e, Vec2::from(cp)).into()
            } else {
                cp
            };
            Some(Curvature::Quadratic(cp))
        }
        Some(c) => {
            let cpath = format!("{path}.curvature");
            let cm = obj(c, &cpath)?;
            let ty = string(get(cm, "type", &cpath)?, &format!("{cpath}.type"))?;
            let params = arr(get(cm, "params", &cpath)?, &format!("{cpath}.params"))?;
            let ppath = format!("{cpath}.params");
            let expect = |n: usize| -> Result<()> {
                if params.len() != n {
                    return Err(Error::Input(format!("{ppath}: a {ty} curvature needs {n} parameters, got {}", params.len())));
                }
                Ok(())
            };
            match ty {
                "quadratic" => {
                    expect(1)?;
                    Some(Curvature::Quadratic(vec_n::<2>(&params[0], &format!("{ppath}[0]"))?))
                }
                "cubic" => {
                    expect(2)?;
                    Some(Curvature::Cubic(vec_n::<2>(&params[0], &format!("{ppath}[0]"))?, vec_n::<2>(&params[1], &format!("{ppath}[1]"))?))
                }
                "circle" => {
                    expect(3)?;
                    let radius = number(&params[0], &format!("{ppath}[0]"))?;
                    if radius <= 0.0 {
                        return Err(Error::Input(format!("{ppath}[0]: an arc radius must be positive, got {radius}")));
                    }
                    Some(Curvature::Circle {
                        radius,
                        large_arc: flag(&params[1], &format!("{ppath}[1]"))?,
                        right: flag(&params[2], &format!("{ppath}[2]"))?,
                    })
                }
                other => {
                    return Err(Error::Input(format!(
                        "{cpath}.type: unknown curvature type \"{other}\" (expected quadratic, cubic or circle)"
                    )));
                }
            }
        }
    };
    Ok(EdgeSpec { endpoints, label, curvature })
}

fn endpoint_positions(vertices: &[[f64; 2]], ep: [usize; 2], path: &str) -> Result<(Vec2, Vec2)> {
    let get = |i: usize| {
        vertices.get(i).map(|v| Vec2::from(*v)).ok_or_else(|| Error::Input(format!("{path}.endpoints: vertex {i} does not exist")))
    };
    Ok((get(ep[0])?, get(ep[1])?))
}

fn read_stitch(v: &Value, path: &str) -> Result<StitchSpec> {
    let s = read_inner_stitch(v, path)?;
    let mut sides = s.sides.into_iter().enumerate().map(|(k, side)| match side.place {
        EdgePlace::Outline => Ok(StitchSide { panel: side.panel, edge: side.edge }),
        _ => Err(Error::Input(format!("{path}[{k}]: a side on a hole or an inner line belongs in pattern.inner_stitches"))),
    });
    let (a, b) = (sides.next().expect("two sides")?, sides.next().expect("two sides")?);
    Ok(StitchSpec { sides: [a, b], right_wrong: s.right_wrong })
}

fn read_inner_stitch(v: &Value, path: &str) -> Result<InnerStitch> {
    let list = arr(v, path)?;
    if list.len() < 2 || list.len() > 3 {
        return Err(Error::Input(format!("{path}: a stitch has two sides and an optional \"right_wrong\", got {} items", list.len())));
    }
    let mut sides = Vec::with_capacity(2);
    for (k, s) in list.iter().take(2).enumerate() {
        let sp = format!("{path}[{k}]");
        let m = obj(s, &sp)?;
        let panel = string(get(m, "panel", &sp)?, &format!("{sp}.panel"))?.to_string();
        check_name(&format!("{sp}.panel"), &panel)?;
        let place = match (m.get("hole"), m.get("line")) {
            (None, None) => EdgePlace::Outline,
            (Some(h), None) => EdgePlace::Hole(index(h, &format!("{sp}.hole"))?),
            (None, Some(l)) => EdgePlace::Line(index(l, &format!("{sp}.line"))?),
            (Some(_), Some(_)) => {
                return Err(Error::Input(format!(
                    "{sp}: a side is on a \"hole\" or on a \"line\" (or on the outline, with neither), not both"
                )));
            }
        };
        let edge = index(get(m, "edge", &sp)?, &format!("{sp}.edge"))?;
        sides.push(InnerSide { panel, place, edge });
    }
    let right_wrong = match list.get(2) {
        None => false,
        Some(Value::String(s)) if s == "right_wrong" => true,
        Some(other) => return Err(Error::Input(format!("{path}[2]: expected \"right_wrong\", got {}", kind(other)))),
    };
    let b = sides.pop().expect("two sides");
    let a = sides.pop().expect("two sides");
    Ok(InnerStitch { sides: [a, b], right_wrong })
}

fn obj<'a>(v: &'a Value, path: &str) -> Result<&'a serde_json::Map<String, Value>> {
    v.as_object().ok_or_else(|| Error::Input(format!("{}: expected an object, got {}", name(path), kind(v))))
}

fn arr<'a>(v: &'a Value, path: &str) -> Result<&'a Vec<Value>> {
    v.as_array().ok_or_else(|| Error::Input(format!("{}: expected a list, got {}", name(path), kind(v))))
}

fn get<'a>(m: &'a serde_json::Map<String, Value>, key: &str, path: &str) -> Result<&'a Value> {
    m.get(key).ok_or_else(|| {
        let p = if path.is_empty() { key.to_string() } else { format!("{path}.{key}") };
        Error::Input(format!("{p}: missing"))
    })
}

fn string<'a>(v: &'a Value, path: &str) -> Result<&'a str> {
    v.as_str().ok_or_else(|| Error::Input(format!("{path}: expected a string, got {}", kind(v))))
}

fn boolean(v: &Value, path: &str) -> Result<bool> {
    v.as_bool().ok_or_else(|| Error::Input(format!("{path}: expected true or false, got {}", kind(v))))
}

fn number(v: &Value, path: &str) -> Result<f64> {
    let x = v.as_f64().ok_or_else(|| Error::Input(format!("{path}: expected a number, got {}", kind(v))))?;
    if !x.is_finite() {
        return Err(Error::Input(format!("{path}: expected a finite number, got {}", crate::message::short(x))));
    }
    Ok(x)
}

fn index(v: &Value, path: &str) -> Result<usize> {
    v.as_u64().map(|x| x as usize).ok_or_else(|| Error::Input(format!("{path}: expected a non-negative integer index, got {}", kind(v))))
}

fn flag(v: &Value, path: &str) -> Result<bool> {
    match v {
        Value::Bool(b) => Ok(*b),
        Value::Number(n) if n.as_f64() == Some(0.0) => Ok(false),
        Value::Number(n) if n.as_f64() == Some(1.0) => Ok(true),
        _ => Err(Error::Input(format!("{path}: expected 0 or 1, got {}", kind(v)))),
    }
}

fn vec_n<const N: usize>(v: &Value, path: &str) -> Result<[f64; N]> {
    let list = arr(v, path)?;
    if list.len() != N {
        return Err(Error::Input(format!("{path}: expected {N} numbers, got {}", list.len())));
    }
    let mut out = [0.0; N];
    for (i, x) in list.iter().enumerate() {
        out[i] = number(x, &format!("{path}[{i}]"))?;
    }
    Ok(out)
}

fn name(path: &str) -> &str {
    if path.is_empty() { "the file" } else { path }
}

fn kind(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("{b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {}", crate::message::quote(s)),
        Value::Array(_) => "a list".into(),
        Value::Object(_) => "an object".into(),
    }
}
