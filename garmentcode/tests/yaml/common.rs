//! Shared test helpers: a minimal JSON reader/writer (the crate has no
//! dependencies), conversion of the oracle's tagged JSON to `Value`, exact value
//! comparison, and a tiny deterministic random generator.
#![allow(dead_code)]

use garmentcode::parity::yaml::{Node, Value};

// ----- JSON ------------------------------------------------------------------

#[derive(Debug, Clone, PartialEq)]
pub enum Json {
    Null,
    Bool(bool),
    Num(f64),
    Str(String),
    Arr(Vec<Json>),
    Obj(Vec<(String, Json)>),
}

impl Json {
    pub fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Obj(p) => p.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }
    pub fn str(&self) -> &str {
        match self {
            Json::Str(s) => s,
            _ => panic!("not a JSON string: {:?}", self),
        }
    }
    pub fn arr(&self) -> &[Json] {
        match self {
            Json::Arr(a) => a,
            _ => panic!("not a JSON array: {:?}", self),
        }
    }
}

pub fn parse_json(text: &str) -> Json {
    let mut p = JsonParser { b: text.as_bytes(), i: 0 };
    let v = p.value();
    p.ws();
    assert_eq!(p.i, p.b.len(), "trailing JSON data");
    v
}

struct JsonParser<'a> {
    b: &'a [u8],
    i: usize,
}

impl JsonParser<'_> {
    fn ws(&mut self) {
        while self.i < self.b.len() && matches!(self.b[self.i], b' ' | b'\n' | b'\r' | b'\t') {
            self.i += 1;
        }
    }
    fn value(&mut self) -> Json {
        self.ws();
        match self.b[self.i] {
            b'n' => {
                self.i += 4;
                Json::Null
            }
            b't' => {
                self.i += 4;
                Json::Bool(true)
            }
            b'f' => {
                self.i += 5;
                Json::Bool(false)
            }
            b'"' => Json::Str(self.string()),
            b'[' => {
                self.i += 1;
                let mut out = Vec::new();
                self.ws();
                if self.b[self.i] == b']' {
                    self.i += 1;
                    return Json::Arr(out);
                }
                loop {
                    out.push(self.value());
                    self.ws();
                    let c = self.b[self.i];
                    self.i += 1;
                    if c == b']' {
                        return Json::Arr(out);
                    }
                    assert_eq!(c, b',');
                }
            }
            b'{' => {
                self.i += 1;
                let mut out = Vec::new();
                self.ws();
                if self.b[self.i] == b'}' {
                    self.i += 1;
                    return Json::Obj(out);
                }
                loop {
                    self.ws();
                    let k = self.string();
                    self.ws();
                    assert_eq!(self.b[self.i], b':');
                    self.i += 1;
                    let v = self.value();
                    out.push((k, v));
                    self.ws();
                    let c = self.b[self.i];
                    self.i += 1;
                    if c == b'}' {
                        return Json::Obj(out);
                    }
                    assert_eq!(c, b',');
                }
            }
            _ => {
                let s = self.i;
                while self.i < self.b.len() && matches!(self.b[self.i], b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9') {
                    self.i += 1;
                }
                Json::Num(std::str::from_utf8(&self.b[s..self.i]).unwrap().parse().unwrap())
            }
        }
    }
    fn hex4(&mut self) -> u32 {
        let s = std::str::from_utf8(&self.b[self.i..self.i + 4]).unwrap();
        self.i += 4;
        u32::from_str_radix(s, 16).unwrap()
    }
    fn string(&mut self) -> String {
        assert_eq!(self.b[self.i], b'"');
        self.i += 1;
        let mut out: Vec<u8> = Vec::new();
        loop {
            let c = self.b[self.i];
            self.i += 1;
            match c {
                b'"' => return String::from_utf8(out).unwrap(),
                b'\\' => {
                    let e = self.b[self.i];
                    self.i += 1;
                    let ch = match e {
                        b'"' => '"',
                        b'\\' => '\\',
                        b'/' => '/',
                        b'b' => '\x08',
                        b'f' => '\x0C',
                        b'n' => '\n',
                        b'r' => '\r',
                        b't' => '\t',
                        b'u' => {
                            let u = self.hex4();
                            if (0xD800..0xDC00).contains(&u) && self.b.get(self.i..self.i + 2) == Some(b"\\u") {
                                let save = self.i;
                                self.i += 2;
                                let lo = self.hex4();
                                if (0xDC00..0xE000).contains(&lo) {
                                    char::from_u32(0x10000 + ((u - 0xD800) << 10) + (lo - 0xDC00)).unwrap()
                                } else {
                                    self.i = save;
                                    LONE_SURROGATE
                                }
                            } else {
                                char::from_u32(u).unwrap_or(LONE_SURROGATE)
                            }
                        }
                        _ => panic!("bad JSON escape"),
                    };
                    let mut buf = [0u8; 4];
                    out.extend_from_slice(ch.encode_utf8(&mut buf).as_bytes());
                }
                _ => out.push(c),
            }
        }
    }
}

/// Stand-in for a lone UTF-16 surrogate (a Python string Rust cannot hold).
pub const LONE_SURROGATE: char = '\u{10FFFE}';

pub fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 || (c as u32) > 0x7E => {
                let mut buf = [0u16; 2];
                for u in c.encode_utf16(&mut buf) {
                    out.push_str(&format!("\\u{:04x}", u));
                }
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

// ----- tagged values ---------------------------------------------------------

/// The oracle's tagged JSON as a `Value`, or Err(reason) if it cannot be one
/// (big int, lone surrogate, date ...).
pub fn untag(j: &Json) -> Result<Value, String> {
    let a = j.arr();
    let kind = a[0].str();
    Ok(match kind {
        "null" => Value::Null,
        "bool" => Value::Bool(a[1] == Json::Bool(true)),
        "int" => Value::Int(a[1].str().parse::<i64>().map_err(|_| format!("big int {}", a[1].str()))?),
        "float" => Value::Float(a[1].str().parse::<f64>().unwrap()),
        "str" => {
            let s = a[1].str();
            if s.contains(LONE_SURROGATE) {
                return Err("lone surrogate".into());
            }
            Value::Str(s.to_string())
        }
        "seq" => Value::Seq(a[1].arr().iter().map(|x| untag(x).map(Node::new)).collect::<Result<_, _>>()?),
        "map" => Value::Map(
            a[1].arr()
                .iter()
                .map(|p| Ok((Node::new(untag(&p.arr()[0])?), Node::new(untag(&p.arr()[1])?))))
                .collect::<Result<_, String>>()?,
        ),
        other => return Err(format!("unsupported type {}", other)),
    })
}

pub fn tag(v: &Value) -> String {
    match v {
        Value::Null => "[\"null\"]".into(),
        Value::Bool(b) => format!("[\"bool\", {}]", b),
        Value::Int(i) => format!("[\"int\", \"{}\"]", i),
        Value::Float(f) => {
            let s = if f.is_nan() {
                "nan".to_string()
            } else if f.is_infinite() {
                if *f > 0.0 { "inf".into() } else { "-inf".into() }
            } else {
                format!("{:e}", f)
            };
            format!("[\"float\", \"{}\"]", s)
        }
        Value::Str(s) => format!("[\"str\", {}]", json_string(s)),
        Value::Seq(items) => {
            let parts: Vec<String> = items.iter().map(|n| tag(&n.value)).collect();
            format!("[\"seq\", [{}]]", parts.join(", "))
        }
        Value::Map(pairs) => {
            let parts: Vec<String> = pairs.iter().map(|(k, v)| format!("[{}, {}]", tag(&k.value), tag(&v.value))).collect();
            format!("[\"map\", [{}]]", parts.join(", "))
        }
    }
}

/// Exact equality: floats bit for bit (so -0.0 != 0.0), NaN equal to NaN.
pub fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Float(x), Value::Float(y)) => x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()),
        (Value::Seq(x), Value::Seq(y)) => x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same(&p.value, &q.value)),
        (Value::Map(x), Value::Map(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|((k1, v1), (k2, v2))| same(&k1.value, &k2.value) && same(&v1.value, &v2.value))
        }
        _ => a == b,
    }
}

/// Same values and same source positions everywhere in the tree.
pub fn same_with_positions(a: &Node, b: &Node) -> bool {
    if a.line != b.line || a.col != b.col {
        return false;
    }
    match (&a.value, &b.value) {
        (Value::Seq(x), Value::Seq(y)) => x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same_with_positions(p, q)),
        (Value::Map(x), Value::Map(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|((k1, v1), (k2, v2))| same_with_positions(k1, k2) && same_with_positions(v1, v2))
        }
        (x, y) => same(x, y),
    }
}

/// Our error messages for deliberate limitations all say "supported".
pub fn is_unsupported(msg: &str) -> bool {
    msg.contains("supported")
}

// ----- random ----------------------------------------------------------------

/// xorshift64*: small, deterministic, good enough for test generation.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545F4914F6CDD1D)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    pub fn chance(&mut self, p: f64) -> bool {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 <= p
    }
}

/// Every YAML file the project carries, keyed the way
/// `tools/pyyaml_oracle.py reference` recorded them: `cases/...` for the
/// reference cases' designs, `garments/...` for the built-in bodies and designs.
pub fn reference_files() -> Vec<(String, std::path::PathBuf)> {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        let Ok(rd) = std::fs::read_dir(dir) else { return };
        let mut entries: Vec<_> = rd.flatten().map(|e| e.path()).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "yaml" || e == "yml") {
                out.push(p);
            }
        }
    }
    let workspace = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut out = Vec::new();
    for (key, dir) in [("cases", "tests/data/cases"), ("garments", "garments/data")] {
        let root = workspace.join(dir);
        let mut files = Vec::new();
        walk(&root, &mut files);
        for path in files {
            let rel = path.strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/");
            out.push((format!("{key}/{rel}"), path));
        }
    }
    out
}

pub fn data_path(name: &str) -> String {
    format!("{}/tests/yaml/data/{}", env!("CARGO_MANIFEST_DIR"), name)
}
