//! The JSON API of the configurator, as plain functions from a request (method,
//! path, body bytes) to a response, so that they are tested and benchmarked
//! without sockets.
//!
//! Everything a page or a tool needs goes through here: the design space (the
//! page builds its controls from it), built-in designs and bodies, the pattern of a
//! design on a body (drawing, `specification.json`, the reference's checks), its
//! simulation box mesh for the 3D view, its drape on the body ([`super::drape`]), random designs from the project's sampler,
//! and the files of a design for download.
//!
//! Errors follow one rule: a request the server cannot read (malformed JSON, an
//! unknown parameter, a value outside its range, an unknown body) is a 4xx answer
//! whose `error` names the parameter path and what is allowed; a well-formed
//! design that the garment library refuses (an empty garment, a neckline that does
//! not fit) is a 200 answer with `"ok": false` and the library's reason, because
//! the request itself was fine. Validation is the params module's
//! ([`ParamSpec::check`], [`read_design_values`]) and the body module's
//! ([`Body::from_entries`], [`Body::check_measurement`]), never a copy of it.

use std::borrow::Cow;
use std::cell::RefCell;
use std::sync::OnceLock;

use garmentcode::io::{DesignError, from_values, read_design_values, write_design};
use garmentcode::{Arena, Body, BodyValue, DesignSpace, Kind, ParamSpec, Params, Range, Value as PValue, message};
use garments::Design;
use garments::sample::{DatasetSampler, NamedBody, Outcome};
use serde_json::{Map, Value as Json, json};

use super::http::{Request, Response};
use super::zip;

/// Longest accepted pattern name.
const MAX_NAME: usize = 64;
/// Problems an error lists; the rest are counted in a last line.
const MAX_PROBLEMS: usize = 20;

/// A request the API refuses: the HTTP status, a message, and for designs and
/// bodies with several problems one line per problem.
#[derive(Clone, Debug, PartialEq)]
pub struct ApiError {
    /// 4xx status (500 only for an internal failure).
    pub status: u16,
    /// One-line summary naming what is wrong and what is allowed.
    pub message: String,
    /// Every problem found (a design file can have several).
    pub problems: Vec<String>,
}

impl ApiError {
    /// An error with this status and message.
    pub fn new(status: u16, message: impl Into<String>) -> ApiError {
        let message = message.into();
        ApiError { status, problems: vec![message.clone()], message }
    }

    /// A 400 Bad Request with this message.
    pub fn bad(message: impl Into<String>) -> ApiError {
        ApiError::new(400, message)
    }

    fn from_problems(mut problems: Vec<String>) -> ApiError {
        let n = problems.len();
        if n > MAX_PROBLEMS {
            problems.truncate(MAX_PROBLEMS);
            problems.push(format!("... and {} more", n - MAX_PROBLEMS));
        }
        let message = match n {
            1 => problems[0].clone(),
            n => format!("{n} problems: {}", problems.join("; ")),
        };
        ApiError { status: 400, message, problems }
    }

    /// The JSON body of the error.
    pub fn to_json(&self) -> Json {
        json!({ "ok": false, "error": self.message, "problems": self.problems })
    }
}

type ApiResult<T> = Result<T, ApiError>;

/// The design space, computed once: the reference's followed by
/// `design.extension` (the page's controls and the designs it reads; "random"
/// draws from the reference's alone, as `garmentcode sample` does).
pub fn space() -> &'static DesignSpace {
    static SPACE: OnceLock<DesignSpace> = OnceLock::new();
    SPACE.get_or_init(garments::design::extended_design_space)
}

/// The built-in bodies, parsed once.
fn builtin_bodies() -> &'static [(&'static str, Body)] {
    static BODIES: OnceLock<Vec<(&'static str, Body)>> = OnceLock::new();
    BODIES.get_or_init(|| garments::builtin::BODIES.iter().filter_map(|(n, _)| garments::builtin::body(n).map(|b| (*n, b))).collect())
}

fn builtin_body(name: &str) -> ApiResult<Body> {
    builtin_bodies().iter().find(|(n, _)| *n == name).map(|(_, b)| b.clone()).ok_or_else(|| {
        let known: Vec<&str> = builtin_bodies().iter().map(|(n, _)| *n).collect();
        ApiError::new(404, format!("no built-in body '{}' (built-in: {})", shown(name), known.join(", ")))
    })
}

// ---------------------------------------------------------------------------
// Routing

/// Answer one request. Never panics: a panic inside the garment library is caught
/// and answered with 500, so the server keeps serving.
pub fn route(req: &Request) -> Response {
    let run = || route_inner(req);
    match std::panic::catch_unwind(run) {
        Ok(r) => r,
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            error_response(&ApiError::new(
                500,
                format!("internal error while answering {} {}: {what}", shown(&req.method), shown(&req.path)),
            ))
        }
    }
}

fn route_inner(req: &Request) -> Response {
    let path = req.path.as_str();
    let get = req.method == "GET" || req.method == "HEAD";
    let post = req.method == "POST";
    let allow = |methods: &'static str| {
        let mut r =
            error_response(&ApiError::new(405, format!("{} is not allowed on {} (allowed: {methods})", shown(&req.method), shown(path))));
        r.headers.push(("Allow", methods.to_string()));
        r
    };
    // Static page.
    if let Some(asset) = super::assets::get(path) {
        return if get {
            Response { status: 200, content_type: asset.content_type, headers: Vec::new(), body: asset.body.as_bytes().to_vec() }
        } else {
            allow("GET, HEAD")
        };
    }
    let Some(api) = path.strip_prefix("/api") else {
        return error_response(&ApiError::new(404, format!("no such page: {} (the configurator is at /, the API at /api)", shown(path))));
    };
    match api {
        "" | "/" => return if get { json_response(200, &index()) } else { allow("GET, HEAD") },
        "/schema" => return if get { json_text_response(200, schema_text().to_string()) } else { allow("GET, HEAD") },
        "/json-schema" => return if get { json_response(200, &space().json_schema()) } else { allow("GET, HEAD") },
        _ => {}
    }
    if let Some(name) = api.strip_prefix("/design/") {
        return if get { reply(builtin_design(name)) } else { allow("GET, HEAD") };
    }
    if let Some(name) = api.strip_prefix("/guide/") {
        return if get { guide_figure(name).unwrap_or_else(|e| error_response(&e)) } else { allow("GET, HEAD") };
    }
    if let Some(name) = api.strip_prefix("/body/") {
        return if get { reply(builtin_body(name).map(|b| body_json(name, &b))) } else { allow("GET, HEAD") };
    }
    if let Some(job) = api.strip_prefix("/drape/").filter(|j| *j != "cancel") {
        return if get {
            super::drape::status(job).map_or_else(|e| error_response(&e), |t| json_text_response(200, t))
        } else {
            allow("GET, HEAD")
        };
    }
    const POSTS: [&str; 9] = ["/pattern", "/mesh", "/drape", "/drape/cancel", "/design", "/body", "/random", "/files", "/zip"];
    if !POSTS.contains(&api) {
        return error_response(&ApiError::new(404, format!("no such API endpoint: {} (see GET /api)", shown(path))));
    }
    if !post {
        return allow("POST");
    }
    let input = match parse_json(req) {
        Ok(v) => v,
        Err(e) => return error_response(&e),
    };
    let result = match api {
        "/pattern" => pattern_text(&input).map(|text| json_text_response(200, text)),
        "/mesh" => mesh_text(&input).map(|text| json_text_response(200, text)),
        "/drape" => super::drape::start(&input).map(|text| json_text_response(200, text)),
        "/drape/cancel" => super::drape::cancel(&input).map(|v| json_response(200, &v)),
        "/zip" => zip_archive(&input).map(|(name, bytes)| Response {
            status: 200,
            content_type: "application/zip",
            headers: vec![("Content-Disposition", format!("attachment; filename=\"{name}.zip\""))],
            body: bytes,
        }),
        "/design" => design(&input).map(|v| json_response(200, &v)),
        "/body" => body(&input).map(|v| json_response(200, &v)),
        "/random" => random(&input).map(|v| json_response(200, &v)),
        _ => files(&input).map(|v| json_response(200, &v)),
    };
    result.unwrap_or_else(|e| error_response(&e))
}

/// The request body as a JSON object (an empty body is `{}`).
fn parse_json(req: &Request) -> ApiResult<Json> {
    // Only `application/json`: a web page can send `text/plain` or a form to any
    // address without asking, but not JSON.
    let mime = req.header("content-type").map(|ct| ct.split(';').next().unwrap_or("").trim().to_ascii_lowercase());
    if mime.as_deref() != Some("application/json") {
        return Err(ApiError::new(
            415,
            format!(
                "the body must be JSON sent with Content-Type: application/json (got {})",
                mime.as_deref().map_or("none".into(), shown)
            ),
        ));
    }
    if req.body.iter().all(u8::is_ascii_whitespace) {
        return Ok(Json::Object(Map::new()));
    }
    let v: Json = serde_json::from_slice(&req.body).map_err(|e| ApiError::bad(format!("malformed JSON body: {e}")))?;
    if !v.is_object() {
        return Err(ApiError::bad("the body must be a JSON object"));
    }
    Ok(v)
}

fn json_response(status: u16, v: &Json) -> Response {
    json_text_response(status, v.to_string())
}

fn json_text_response(status: u16, text: String) -> Response {
    Response { status, content_type: "application/json; charset=utf-8", headers: Vec::new(), body: text.into_bytes() }
}

/// The response of an [`ApiError`].
pub fn error_response(e: &ApiError) -> Response {
    json_response(e.status, &e.to_json())
}

fn reply(r: ApiResult<Json>) -> Response {
    match r {
        Ok(v) => json_response(200, &v),
        Err(e) => error_response(&e),
    }
}

fn index() -> Json {
    json!({
        "endpoints": [
            "GET /api/schema", "GET /api/json-schema", "GET /api/design/NAME", "GET /api/body/NAME", "GET /api/guide/NAME.svg",
            "POST /api/design", "POST /api/body", "POST /api/pattern", "POST /api/mesh", "POST /api/drape", "GET /api/drape/JOB",
            "POST /api/drape/cancel", "POST /api/random", "POST /api/files",
            "POST /api/zip"
        ],
        "documentation": "README.md, section 'Web configurator and its API'",
    })
}

// ---------------------------------------------------------------------------
// Values

fn value_json(v: &PValue) -> Json {
    match v {
        PValue::Null => Json::Null,
        PValue::Bool(b) => json!(b),
        PValue::Int(i) => json!(i),
        PValue::Float(f) => serde_json::Number::from_f64(*f).map(Json::Number).unwrap_or(Json::Null),
        PValue::Str(s) => json!(s),
    }
}

fn json_value(v: &Json) -> Option<PValue> {
    Some(match v {
        Json::Null => PValue::Null,
        Json::Bool(b) => PValue::Bool(*b),
        Json::Number(n) => match n.as_i64() {
            Some(i) => PValue::Int(i),
            None => PValue::Float(n.as_f64()?),
        },
        Json::String(s) => PValue::Str(s.clone()),
        Json::Array(_) | Json::Object(_) => return None,
    })
}

fn values_json(values: &[(String, PValue)]) -> Json {
    Json::Object(values.iter().map(|(p, v)| (p.clone(), value_json(v))).collect())
}

/// The design of a request: absent or `null` for the defaults, an object of
/// parameter paths and values (the others take their defaults), or the text of a
/// design file. Every value is checked against its range; all problems are
/// reported at once.
pub fn design_values(v: Option<&Json>) -> ApiResult<Vec<(String, PValue)>> {
    let space = space();
    let mut values: Vec<(String, PValue)> = space.params().iter().map(|p| (p.path.clone(), p.default.clone())).collect();
    match v {
        None | Some(Json::Null) => Ok(values),
        Some(Json::String(text)) => read_design_values(text, "design", space).map_err(design_error),
        Some(Json::Object(map)) => {
            let mut problems = Vec::new();
            for (path, jv) in map {
                let Some(i) = space.params().iter().position(|p| p.path == *path) else {
                    problems.push(format!("design.{}: unknown parameter{}", shown(path), hint(path)));
                    continue;
                };
                let spec: &ParamSpec = &space.params()[i];
                let Some(value) = json_value(jv) else {
                    problems.push(format!("design.{path}: expected a single value in {}, got a JSON {}", spec.range, json_type(jv)));
                    continue;
                };
                match spec.check(&value) {
                    Ok(checked) => values[i].1 = checked,
                    Err(e) => problems.push(format!("design.{path}: {e}")),
                }
            }
            if problems.is_empty() { Ok(values) } else { Err(ApiError::from_problems(problems)) }
        }
        Some(other) => Err(ApiError::bad(format!(
            "\"design\" must be an object of parameter paths and values or the text of a design file, not a JSON {}",
            json_type(other)
        ))),
    }
}

fn design_error(e: DesignError) -> ApiError {
    ApiError::from_problems(e.problems.iter().map(|p| format!("{}: {p}", e.file)).collect())
}

/// A close parameter path for a typo, as design files get.
fn hint(path: &str) -> String {
    let last = path.rsplit('.').next().unwrap_or(path);
    let close: Vec<&str> = space()
        .params()
        .iter()
        .map(|p| p.path.as_str())
        .filter(|p| *p == last || p.strip_suffix(last).is_some_and(|head| head.ends_with('.')))
        .take(3)
        .collect();
    if close.is_empty() { String::new() } else { format!(" (did you mean {}?)", close.join(", ")) }
}

fn json_type(v: &Json) -> &'static str {
    match v {
        Json::Null => "null",
        Json::Bool(_) => "boolean",
        Json::Number(_) => "number",
        Json::String(_) => "string",
        Json::Array(_) => "array",
        Json::Object(_) => "object",
    }
}

/// A key, path or name of a request as an error message shows it: as it is when
/// short, else cut and quoted by [`message::quote`] (the start and the length).
pub fn shown(text: &str) -> Cow<'_, str> {
    if text.chars().count() > message::QUOTE_CHARS { Cow::Owned(message::quote(text)) } else { Cow::Borrowed(text) }
}

/// A JSON value as an error message shows it: a string quoted and shortened
/// ([`message::quote`]), a number in a short form, an array or object by its type.
pub(super) fn json_shown(v: &Json) -> String {
    match v {
        Json::String(s) => message::quote(s),
        Json::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() => message::short(x).to_string(),
            _ => n.to_string(), // an integer: at most 20 digits
        },
        Json::Array(_) | Json::Object(_) => format!("a JSON {}", json_type(v)),
        Json::Null | Json::Bool(_) => v.to_string(),
    }
}

fn typed_design(values: &[(String, PValue)]) -> ApiResult<Design> {
    from_values(values, "design").map_err(design_error)
}

/// Warnings in words (see [`crate::explain_warning`]).
fn explained(warnings: Vec<String>) -> Vec<String> {
    warnings.iter().map(|w| crate::explain_warning(w)).collect()
}

/// The body of a request: absent for the neutral body, a built-in name, or an
/// object with a body file's text (`yaml`) or measurements over a built-in body
/// (`base`, default the neutral body; `measurements`: name → number, derived
/// `_` values ignored as body files do).
pub fn body_from(v: Option<&Json>) -> ApiResult<(String, Body)> {
    let default = garments::builtin::DEFAULT_BODY;
    match v {
        None | Some(Json::Null) => Ok((default.to_string(), builtin_body(default)?)),
        Some(Json::String(name)) => builtin_body(name).map(|b| (name.clone(), b)).map_err(|e| ApiError { status: 400, ..e }),
        Some(Json::Object(map)) => {
            for k in map.keys() {
                if !["yaml", "base", "name", "measurements"].contains(&k.as_str()) {
                    return Err(ApiError::bad(format!(
                        "body: unknown key {} (expected yaml, name, or base and measurements)",
                        message::quote(k)
                    )));
                }
            }
            let label = checked_name("body.name", map.get("name"), "custom")?;
            if let Some(y) = map.get("yaml") {
                let Some(text) = y.as_str() else { return Err(ApiError::bad("body.yaml must be the text of a body file")) };
                if map.contains_key("measurements") || map.contains_key("base") {
                    return Err(ApiError::bad("body: give either yaml or base and measurements, not both"));
                }
                let b = garments::builtin::body_from_yaml(text, "body")
                    .map_err(|e| ApiError::from_problems(e.problems.iter().map(|p| format!("body: {p}")).collect()))?;
                return Ok((label, b));
            }
            let base = match map.get("base") {
                None | Some(Json::Null) => default,
                Some(Json::String(s)) => s.as_str(),
                Some(_) => return Err(ApiError::bad("body.base must be the name of a built-in body")),
            };
            let mut entries = vec![(String::new(), "base", BodyValue::Text(base))];
            match map.get("measurements") {
                None | Some(Json::Null) => {}
                Some(Json::Object(m)) => entries.extend(m.iter().map(|(name, jv)| {
                    let value = match jv {
                        Json::Number(_) => BodyValue::Number(jv.as_f64().unwrap_or(f64::NAN)),
                        Json::String(s) => BodyValue::Text(s),
                        Json::Null => BodyValue::Null,
                        other => BodyValue::Other(format!("a JSON {}", json_type(other))),
                    };
                    (String::new(), name.as_str(), value)
                })),
                Some(other) => {
                    return Err(ApiError::bad(format!(
                        "body.measurements must be an object of measurement names and numbers, not a JSON {}",
                        json_type(other)
                    )));
                }
            }
            // Problems name their measurement (`body.waist: ...`); the others
            // (derived values that make no sense) are about the whole body.
            let b = Body::from_entries(&entries, garments::builtin::BODIES).map_err(|problems| {
                ApiError::from_problems(
                    problems.into_iter().map(|p| if p.starts_with("body.") { p } else { format!("body: {p}") }).collect(),
                )
            })?;
            let label = if map.contains_key("measurements") { label } else { base.to_string() };
            Ok((label, b))
        }
        Some(other) => Err(ApiError::bad(format!("\"body\" must be a built-in body name or an object, not a JSON {}", json_type(other)))),
    }
}

/// A body's measurements and derived values.
pub fn body_json(name: &str, b: &Body) -> Json {
    let mut measurements = Map::new();
    for n in Body::measurement_names() {
        measurements.insert(n.to_string(), b.get(n).and_then(serde_json::Number::from_f64).map(Json::Number).unwrap_or(Json::Null));
    }
    let derived: Map<String, Json> =
        b.entries().into_iter().filter(|(n, _)| n.starts_with('_')).map(|(n, v)| (n.to_string(), json!(v))).collect();
    json!({ "name": name, "measurements": measurements, "derived": derived })
}

/// The pattern name of a request: letters, digits, `-`, `_`, `.` (it names files).
fn pattern_name(input: &Json) -> ApiResult<String> {
    checked_name("name", input.get("name"), "garment")
}

/// A name a request gives (the pattern's, `name`; the body's, `body.name`): 1 to
/// [`MAX_NAME`] letters, digits, `-`, `_` or `.`, not starting with `.` (it names
/// files and folders); `default` when absent or null.
fn checked_name(field: &str, v: Option<&Json>, default: &str) -> ApiResult<String> {
    match v {
        None | Some(Json::Null) => Ok(default.into()),
        Some(Json::String(s)) => {
            let ok = !s.is_empty()
                && s.len() <= MAX_NAME
                && !s.starts_with('.')
                && s.chars().all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
            if ok {
                Ok(s.clone())
            } else {
                Err(ApiError::bad(format!(
                    "{field}: expected 1 to {MAX_NAME} letters, digits, '-', '_' or '.' (not first), got {}",
                    message::quote(s)
                )))
            }
        }
        Some(other) => Err(ApiError::bad(format!("{field} must be a string, not a JSON {}", json_type(other)))),
    }
}

// ---------------------------------------------------------------------------
// Handlers

/// `GET /api/schema`: the design space (every parameter with its group, type,
/// range or options, default, sampling probability and description), the
/// built-in designs and bodies, and the body measurements.
pub fn schema() -> Json {
    let space = space();
    let mut groups: Vec<String> = Vec::new();
    let params: Vec<Json> = space
        .params()
        .iter()
        .map(|p| {
            let (group, name) = p.path.rsplit_once('.').unwrap_or(("", &p.path));
            // Every enclosing group, outermost first, in document order.
            let mut prefix = String::new();
            for part in group.split('.').filter(|s| !s.is_empty()) {
                if !prefix.is_empty() {
                    prefix.push('.');
                }
                prefix.push_str(part);
                if !groups.contains(&prefix) {
                    groups.push(prefix.clone());
                }
            }
            let mut o = Map::new();
            o.insert("path".into(), json!(p.path));
            o.insert("group".into(), json!(group));
            o.insert("name".into(), json!(name));
            o.insert("type".into(), json!(p.kind.as_str()));
            match &p.range {
                Range::Numeric { lo, hi } if p.kind == Kind::Int => {
                    o.insert("range".into(), json!([*lo as i64, *hi as i64]));
                }
                Range::Numeric { lo, hi } => {
                    o.insert("range".into(), json!([lo, hi]));
                }
                Range::Options(opts) => {
                    let mut opts: Vec<Json> = opts.iter().map(value_json).collect();
                    if p.kind == Kind::SelectNull && !opts.contains(&Json::Null) {
                        opts.push(Json::Null);
                    }
                    o.insert("options".into(), Json::Array(opts));
                }
            }
            o.insert("default".into(), value_json(&p.default));
            o.insert("default_prob".into(), p.default_prob.map(|x| json!(x)).unwrap_or(Json::Null));
            o.insert("description".into(), json!(p.description));
            Json::Object(o)
        })
        .collect();
    let designs: Vec<Json> = garments::builtin::DESIGNS
        .iter()
        .map(|(n, text)| {
            let description = text.lines().next().and_then(|l| l.strip_prefix("# ")).unwrap_or("");
            json!({ "name": n, "description": description })
        })
        .collect();
    let measurements: Vec<Json> = garmentcode::MEASUREMENTS
        .iter()
        .map(|m| {
            json!({
                "name": m.name,
                "unit": m.unit,
                "optional": m.optional,
                "description": m.description,
                "min": m.min,
                "max": m.max,
                "how": garmentcode::guide::how_to_measure(m.name),
            })
        })
        .collect();
    let derived: Vec<Json> = garmentcode::DERIVED_VALUES.iter().map(|d| json!({ "name": d.name, "description": d.description })).collect();
    json!({
        "groups": groups,
        "params": params,
        "designs": designs,
        "default_design": garments::builtin::DEFAULT_DESIGN,
        "bodies": builtin_bodies().iter().map(|(n, _)| *n).collect::<Vec<_>>(),
        "default_body": garments::builtin::DEFAULT_BODY,
        "measurements": measurements,
        "derived": derived,
        "random_attempts": garments::sample::MAX_ATTEMPTS,
    })
}

/// `GET /api/guide/NAME.svg`: where the tape goes for measurement NAME (the
/// measuring guide's figure, drawn on the neutral body).
fn guide_figure(file: &str) -> ApiResult<Response> {
    let name = file.strip_suffix(".svg").unwrap_or(file);
    let body = builtin_body(garments::builtin::DEFAULT_BODY)?;
    let svg = garmentcode::guide::figure_svg(&body, name).ok_or_else(|| {
        ApiError::new(404, format!("no measurement {} (see GET /api/schema, measurements)", garmentcode::message::quote_name(name)))
    })?;
    Ok(Response { status: 200, content_type: "image/svg+xml", headers: Vec::new(), body: svg.into_bytes() })
}

fn schema_text() -> &'static str {
    static TEXT: OnceLock<String> = OnceLock::new();
    TEXT.get_or_init(|| schema().to_string())
}

/// `GET /api/design/NAME`: a built-in design's values (every parameter).
pub fn builtin_design(name: &str) -> ApiResult<Json> {
    let Some((_, text)) = garments::builtin::DESIGNS.iter().find(|(n, _)| *n == name) else {
        let known: Vec<&str> = garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect();
        return Err(ApiError::new(404, format!("no built-in design '{}' (built-in: {})", shown(name), known.join(", "))));
    };
    let values = read_design_values(text, name, space()).map_err(design_error)?;
    Ok(json!({ "name": name, "design": values_json(&values) }))
}

/// `POST /api/design` `{"design": ...}`: the design's every value, checked (for
/// reading a design file into the page's controls).
pub fn design(input: &Json) -> ApiResult<Json> {
    let values = design_values(input.get("design"))?;
    Ok(json!({ "ok": true, "design": values_json(&values) }))
}

/// `POST /api/body` `{"body": ...}`: the body's measurements and derived values.
pub fn body(input: &Json) -> ApiResult<Json> {
    let (name, b) = body_from(input.get("body"))?;
    let mut out = body_json(&name, &b);
    out["ok"] = json!(true);
    Ok(out)
}

/// A design built on a body, or the library's reason for refusing it.
struct Evaluation {
    name: String,
    body_name: String,
    body: Body,
    design: Design,
    result: Result<Output, String>,
}

struct Output {
    svg: String,
    spec: String,
    checks: garments::build::Checks,
    panels: Vec<String>,
    stitches: usize,
}

thread_local! {
    /// One arena per thread, reused across its requests.
    static ARENA: RefCell<Arena> = RefCell::new(Arena::new());
}

/// Refuses a request with a key outside `allowed`.
fn check_keys(input: &Json, allowed: &[&str]) -> ApiResult<()> {
    for k in input.as_object().map(|m| m.keys().collect::<Vec<_>>()).unwrap_or_default() {
        if !allowed.contains(&k.as_str()) {
            let (last, first) = allowed.split_last().unwrap_or((&"", &[]));
            return Err(ApiError::bad(format!("unknown key {} (expected {} and {last})", message::quote(k), first.join(", "))));
        }
    }
    Ok(())
}

fn evaluate(input: &Json) -> ApiResult<Evaluation> {
    check_keys(input, &["design", "body", "name", "layout"])?;
    let name = pattern_name(input)?;
    let values = design_values(input.get("design"))?;
    let (body_name, body) = body_from(input.get("body"))?;
    let layout = match input.get("layout") {
        None | Some(Json::Null) => garmentcode::draw::Layout::Placed,
        Some(Json::String(s)) => s.parse().map_err(|e: String| ApiError::bad(format!("layout: {e}")))?,
        Some(other) => return Err(ApiError::bad(format!("layout must be \"placed\" or \"flat\", got {}", json_shown(other)))),
    };
    let design = typed_design(&values)?;
    let result = build(&design, &body, &name, layout);
    Ok(Evaluation { name, body_name, body, design, result })
}

fn build(design: &Design, body: &Body, name: &str, layout: garmentcode::draw::Layout) -> Result<Output, String> {
    let built = ARENA.with(|a| garments::build::build_in(&mut a.borrow_mut(), design, body, name)).map_err(|e| e.to_string())?;
    let svg = garmentcode::draw::to_svg(&built.pattern, &garmentcode::draw::DrawOptions { layout, ..Default::default() })
        .map_err(|e| format!("the pattern cannot be drawn: {e}"))?;
    let spec = built.pattern.to_json().map_err(|e| format!("the pattern cannot be written: {e}"))?;
    Ok(Output {
        svg,
        spec,
        panels: built.pattern.panels.iter().map(|p| p.name.clone()).collect(),
        stitches: built.pattern.stitches.len(),
        checks: built.checks,
    })
}

fn checks_json(c: &garments::build::Checks) -> Json {
    serde_json::from_str(&c.to_json()).unwrap_or(Json::Null)
}

/// `POST /api/pattern` `{"design", "body", "name"}`: the pattern as JSON text:
/// `ok`, `name`, `panels`, `stitches`, `warnings`, `checks`, `svg`, `body` and
/// `specification` (the `specification.json` object), or `ok: false` and `error`
/// when the library refuses the design.
pub fn pattern_text(input: &Json) -> ApiResult<String> {
    let ev = evaluate(input)?;
    let body = body_json(&ev.body_name, &ev.body);
    match ev.result {
        Err(reason) => Ok(json!({ "ok": false, "name": ev.name, "error": reason, "problems": [reason], "body": body }).to_string()),
        Ok(out) => {
            let head = json!({
                "ok": true,
                "name": ev.name,
                "panels": out.panels,
                "stitches": out.stitches,
                "warnings": explained(out.checks.warnings()),
                "checks": checks_json(&out.checks),
                "svg": out.svg,
                "body": body,
            });
            // The specification is spliced in as written, not re-parsed and re-printed.
            let mut text = head.to_string();
            text.pop(); // the closing brace
            text.push_str(",\"specification\":");
            text.push_str(&out.spec);
            text.push('}');
            Ok(text)
        }
    }
}

/// [`pattern_text`] as a JSON value.
pub fn pattern(input: &Json) -> ApiResult<Json> {
    let text = pattern_text(input)?;
    serde_json::from_str(&text).map_err(|e| ApiError::new(500, format!("internal error: {e}")))
}

/// Finest and coarsest mesh resolution `POST /api/mesh` accepts (cm): the finest is
/// the reference simulator's default, which bounds a garment's mesh to some tens of
/// thousands of vertices.
pub const MESH_RESOLUTION: [f64; 2] = [garmentcode::mesh::DEFAULT_RESOLUTION, 10.0];

/// `POST /api/mesh` `{"design", "body", "name", "resolution"}`: the simulation box
/// mesh of the pattern ([`garmentcode::mesh::BoxMesh`], at `resolution` cm, default
/// 1), for the page's 3D view, as JSON text:
///
/// - `ok`, `name`, `resolution`, `vertices` and `faces` (counts);
/// - `positions`: `x, y, z` of every vertex in cm (to 0.01 cm), flat;
/// - `triangles`: three vertex indices per face, flat, wound like the panel outline;
/// - `panels`: `{"name", "first_face", "faces"}` in panel order (the faces of a
///   panel are consecutive; a vertex on a stitch belongs to two panels, a face to one);
/// - `stitches`: per stitch, the indices of its merged vertices from one end to the
///   other (the seam, to draw as a line);
/// - `bounds`: `{"min": [x, y, z], "max": [x, y, z]}` of the positions.
///
/// A design the library refuses, or a pattern that cannot be meshed, is
/// `ok: false` with the reason, as for [`pattern_text`].
pub fn mesh_text(input: &Json) -> ApiResult<String> {
    let m = meshed(input, &[])?;
    Ok(match m.result {
        Err(reason) => json!({ "ok": false, "name": m.name, "error": reason, "problems": [reason] }).to_string(),
        Ok((_, mesh)) => mesh_json(&mesh),
    })
}

/// A request's box mesh ([`mesh_text`], [`super::drape`]): the pattern name, the body, and
/// the pattern with its mesh or the library's reason for refusing the design.
pub(super) struct Meshed {
    pub name: String,
    pub body_name: String,
    pub body: Body,
    pub result: Result<(garmentcode::Pattern, garmentcode::mesh::BoxMesh), String>,
}

/// Reads `design`, `body`, `name` and `resolution` (cm, [`MESH_RESOLUTION`], default 1) of
/// a request that may also have the keys `extra`, builds the pattern and meshes it.
pub(super) fn meshed(input: &Json, extra: &[&str]) -> ApiResult<Meshed> {
    let mut keys = vec!["design", "body", "name", "resolution"];
    keys.extend_from_slice(extra);
    check_keys(input, &keys)?;
    let [lo, hi] = MESH_RESOLUTION;
    let resolution = match input.get("resolution") {
        None | Some(Json::Null) => garmentcode::mesh::DEFAULT_RESOLUTION,
        Some(v) => v
            .as_f64()
            .filter(|r| (lo..=hi).contains(r))
            .ok_or_else(|| ApiError::bad(format!("resolution: expected a number of cm from {lo} to {hi}, got {}", json_shown(v))))?,
    };
    let name = pattern_name(input)?;
    let values = design_values(input.get("design"))?;
    let (body_name, body) = body_from(input.get("body"))?;
    let design = typed_design(&values)?;
    let built = ARENA.with(|a| garments::build::build_in(&mut a.borrow_mut(), &design, &body, &name)).map_err(|e| e.to_string());
    let result = built.and_then(|b| match garmentcode::mesh::BoxMesh::new(&b.pattern, resolution) {
        Ok(mesh) => Ok((b.pattern, mesh)),
        Err(e) => Err(format!("cannot mesh the pattern: {e}")),
    });
    Ok(Meshed { name, body_name, body, result })
}

/// A length in cm as the API sends it: to 0.01 cm, without a negative zero (a rounded
/// value prints as its shortest decimal).
fn cm(x: f64) -> f64 {
    (x * 100.0).round() / 100.0 + 0.0
}

/// `[x, y, z, x, y, z, ...]` of `positions` in cm (to 0.01 cm), appended to `text`.
pub(super) fn write_positions(text: &mut String, positions: &[garmentcode::Vec3]) {
    use std::fmt::Write;
    text.reserve(positions.len() * 24);
    text.push('[');
    for (i, v) in positions.iter().enumerate() {
        let sep = if i == 0 { "" } else { "," };
        let _ = write!(text, "{sep}{},{},{}", cm(v.x), cm(v.y), cm(v.z));
    }
    text.push(']');
}

/// The JSON text of [`mesh_text`] for a mesh, written directly (a mesh has some
/// hundred thousand numbers).
pub(super) fn mesh_json(m: &garmentcode::mesh::BoxMesh) -> String {
    use std::fmt::Write;
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in &m.vertices {
        for (k, x) in v.to_array().into_iter().enumerate() {
            lo[k] = lo[k].min(cm(x));
            hi[k] = hi[k].max(cm(x));
        }
    }
    let mut panels = Vec::with_capacity(m.panels.len());
    let mut first = 0;
    for (i, p) in m.panels.iter().enumerate() {
        let n = m.faces[first..].iter().take_while(|f| f.panel == i).count();
        panels.push(json!({ "name": p.name, "first_face": first, "faces": n }));
        first += n;
    }
    let stitches: Vec<Vec<usize>> = m
        .stitches
        .iter()
        .map(|s| {
            let (p, e) = s.sides[1];
            let panel = &m.panels[p];
            panel.edges[e].local.iter().map(|&l| panel.global[l]).collect()
        })
        .collect();
    let head = json!({
        "ok": true,
        "name": m.name,
        "resolution": m.resolution,
        "vertices": m.vertices.len(),
        "faces": m.faces.len(),
        "panels": panels,
        "stitches": stitches,
        "bounds": { "min": lo, "max": hi },
    });
    let mut text = head.to_string();
    text.pop(); // the closing brace
    text.reserve(m.vertices.len() * 24 + m.faces.len() * 18);
    text.push_str(",\"positions\":");
    write_positions(&mut text, &m.vertices);
    text.push_str(",\"triangles\":[");
    for (i, f) in m.faces.iter().enumerate() {
        let sep = if i == 0 { "" } else { "," };
        let [a, b, c] = f.vertices;
        let _ = write!(text, "{sep}{a},{b},{c}");
    }
    text.push_str("]}");
    text
}

/// `POST /api/random` `{"seed", "body"}`: a random design from the dataset
/// sampler (`garmentcode sample`): sample 0 of `seed` on the request's body, drawn
/// again while it fails the reference's filters, exactly as a dataset does. So
/// "Random" with seed S on a body shows the first garment of
/// `garmentcode sample --seed S --bodies BODY`.
pub fn random(input: &Json) -> ApiResult<Json> {
    let seed = match input.get("seed") {
        None | Some(Json::Null) => 0,
        Some(v) => {
            v.as_u64().ok_or_else(|| ApiError::bad(format!("seed must be an integer from 0 to {}, got {}", u64::MAX, json_shown(v))))?
        }
    };
    let (name, body) = body_from(input.get("body"))?;
    let sampler = DatasetSampler::new(seed, Design::design_space(), vec![NamedBody { name, body }])
        .map_err(|e| ApiError::new(500, format!("internal error: {e}")))?;
    let outcome = ARENA.with(|a| sampler.draw_in(&mut a.borrow_mut(), 0));
    Ok(match outcome {
        Outcome::Accepted(sample) => {
            let values = design_to_values(&sample.design);
            json!({ "ok": true, "seed": seed, "draw": sample.attempt, "design": values_json(&values), "warnings": explained(sample.built.checks.warnings()) })
        }
        Outcome::Exhausted { rejections, .. } => json!({
            "ok": false,
            "seed": seed,
            "error": format!("all {} random designs of seed {seed} failed the filters on this body; try another seed", rejections.len())
        }),
    })
}

/// Every parameter's value in a typed design, in schema order.
fn design_to_values(design: &Design) -> Vec<(String, PValue)> {
    use garmentcode::Params;
    space()
        .params()
        .iter()
        .map(|p| {
            let keys: Vec<&str> = p.path.split('.').collect();
            (p.path.clone(), design.get_value(&keys).unwrap_or_else(|| p.default.clone()))
        })
        .collect()
}

/// The files of a design: `design_params.yaml` and `body_measurements.yaml`
/// always; `specification.json`, `pattern.svg` and `checks.json` when the design
/// builds, else `error.txt` with the reason.
fn file_set(input: &Json) -> ApiResult<(Evaluation, Vec<(&'static str, String)>)> {
    let ev = evaluate(input)?;
    let mut files = vec![
        ("design_params.yaml", write_design(&ev.design, &garments::design::space_of(&ev.design))),
        ("body_measurements.yaml", ev.body.to_yaml()),
    ];
    match &ev.result {
        Ok(out) => {
            files.push(("specification.json", out.spec.clone()));
            files.push(("pattern.svg", out.svg.clone()));
            files.push(("checks.json", out.checks.to_json()));
        }
        Err(reason) => files.push(("error.txt", format!("{reason}\n"))),
    }
    Ok((ev, files))
}

/// `POST /api/files` `{"design", "body", "name"}`: every file of the design as
/// text, by file name.
pub fn files(input: &Json) -> ApiResult<Json> {
    let (ev, files) = file_set(input)?;
    let map: Map<String, Json> = files.into_iter().map(|(n, t)| (n.to_string(), Json::String(t))).collect();
    let mut out = json!({ "ok": ev.result.is_ok(), "name": ev.name, "files": map });
    if let Err(reason) = &ev.result {
        out["error"] = json!(reason);
    }
    Ok(out)
}

/// `POST /api/zip`: the files of [`files`] as one zip archive, in a folder named
/// after the pattern, and when the design builds, the files to print, cut and sew
/// (`garmentcode print`'s, at its defaults: A4, 1 cm seam allowance) in its `print/`.
pub fn zip_archive(input: &Json) -> ApiResult<(String, Vec<u8>)> {
    let (ev, files) = file_set(input)?;
    let mut named: Vec<(String, &[u8])> = files.iter().map(|(n, t)| (format!("{}/{n}", ev.name), t.as_bytes())).collect();
    let printed = match &ev.result {
        Ok(out) => {
            let internal = |e: garmentcode::Error| ApiError::new(500, format!("internal error: {e}"));
            let pattern = garmentcode::Pattern::from_json(&out.spec).map_err(internal)?;
            let opts = garmentcode::fabricate::PrintOptions { garment: ev.name.clone(), size: ev.body_name.clone(), ..Default::default() };
            garmentcode::fabricate::files(&pattern, &opts).map_err(internal)?
        }
        Err(_) => Vec::new(),
    };
    named.extend(printed.iter().map(|(n, b)| (format!("{}/print/{n}", ev.name), b.as_slice())));
    let refs: Vec<(&str, &[u8])> = named.iter().map(|(n, b)| (n.as_str(), *b)).collect();
    let bytes = zip::write(&refs).map_err(|e| ApiError::new(500, format!("internal error: {e}")))?;
    Ok((ev.name, bytes))
}

#[cfg(test)]
mod tests;
