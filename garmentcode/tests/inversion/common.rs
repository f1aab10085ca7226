//! Shared test helpers: a minimal JSON reader (std only) and the logged test vectors.
#![allow(dead_code)]

use std::collections::BTreeMap;

/// A parsed JSON value.
#[derive(Clone, Debug)]
pub enum Json {
    Null,
    Bool(bool),
    Num(f64),
    Str(String),
    Arr(Vec<Json>),
    Obj(BTreeMap<String, Json>),
}

impl Json {
    pub fn get(&self, key: &str) -> &Json {
        match self {
            Json::Obj(m) => m.get(key).unwrap_or_else(|| panic!("missing key {key}")),
            _ => panic!("not an object"),
        }
    }
    pub fn num(&self) -> f64 {
        match self {
            Json::Num(v) => *v,
            _ => panic!("not a number"),
        }
    }
    pub fn str(&self) -> &str {
        match self {
            Json::Str(s) => s,
            _ => panic!("not a string"),
        }
    }
    pub fn arr(&self) -> &[Json] {
        match self {
            Json::Arr(v) => v,
            _ => panic!("not an array"),
        }
    }
    pub fn v2(&self) -> [f64; 2] {
        let a = self.arr();
        [a[0].num(), a[1].num()]
    }
}

/// Parse a JSON document (numbers via Rust's correctly rounded `f64::from_str`).
pub fn parse(text: &str) -> Json {
    let b = text.as_bytes();
    let mut i = 0;
    let v = value(b, &mut i);
    skip(b, &mut i);
    assert_eq!(i, b.len(), "trailing characters");
    v
}

fn skip(b: &[u8], i: &mut usize) {
    while *i < b.len() && (b[*i] as char).is_ascii_whitespace() {
        *i += 1;
    }
}

fn value(b: &[u8], i: &mut usize) -> Json {
    skip(b, i);
    match b[*i] {
        b'{' => {
            *i += 1;
            let mut m = BTreeMap::new();
            loop {
                skip(b, i);
                if b[*i] == b'}' {
                    *i += 1;
                    break;
                }
                let k = match value(b, i) {
                    Json::Str(s) => s,
                    _ => panic!("bad key"),
                };
                skip(b, i);
                assert_eq!(b[*i], b':');
                *i += 1;
                let v = value(b, i);
                m.insert(k, v);
                skip(b, i);
                if b[*i] == b',' {
                    *i += 1;
                }
            }
            Json::Obj(m)
        }
        b'[' => {
            *i += 1;
            let mut v = Vec::new();
            loop {
                skip(b, i);
                if b[*i] == b']' {
                    *i += 1;
                    break;
                }
                v.push(value(b, i));
                skip(b, i);
                if b[*i] == b',' {
                    *i += 1;
                }
            }
            Json::Arr(v)
        }
        b'"' => {
            *i += 1;
            let start = *i;
            while b[*i] != b'"' {
                if b[*i] == b'\\' {
                    *i += 1;
                }
                *i += 1;
            }
            let s = String::from_utf8(b[start..*i].to_vec()).unwrap();
            *i += 1;
            Json::Str(s)
        }
        b't' => {
            *i += 4;
            Json::Bool(true)
        }
        b'f' => {
            *i += 5;
            Json::Bool(false)
        }
        b'n' => {
            *i += 4;
            Json::Null
        }
        _ => {
            let start = *i;
            while *i < b.len() && matches!(b[*i], b'0'..=b'9' | b'-' | b'+' | b'.' | b'e' | b'E') {
                *i += 1;
            }
            let s = std::str::from_utf8(&b[start..*i]).unwrap();
            Json::Num(s.parse().unwrap_or_else(|_| panic!("bad number {s}")))
        }
    }
}

/// One logged call of the reference's curve_match_tangents and its scipy result.
#[derive(Clone, Debug)]
pub struct Vector {
    pub source: String,
    pub caller: String,
    pub cps: [[f64; 2]; 4],
    pub t0: [f64; 2],
    pub t1: [f64; 2],
    pub target_len: f64,
    pub ref_shift: [f64; 5],
    pub ref_cps: [[f64; 2]; 4],
    pub ref_fun: f64,
}

/// Load test vectors from a JSON file (path relative to the crate root).
pub fn load(rel: &str) -> Vec<Vector> {
    let path = if rel.starts_with('/') { rel.to_string() } else { format!("{}/{}", env!("CARGO_MANIFEST_DIR"), rel) };
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    parse(&text)
        .arr()
        .iter()
        .map(|r| {
            let cps = r.get("cps").arr();
            let rc = r.get("ref_cps").arr();
            let sh = r.get("ref_shift").arr();
            Vector {
                source: r.get("source").str().to_string(),
                caller: r.get("caller").str().to_string(),
                cps: [cps[0].v2(), cps[1].v2(), cps[2].v2(), cps[3].v2()],
                t0: r.get("t0").v2(),
                t1: r.get("t1").v2(),
                target_len: r.get("target_len").num(),
                ref_shift: [sh[0].num(), sh[1].num(), sh[2].num(), sh[3].num(), sh[4].num()],
                ref_cps: [rc[0].v2(), rc[1].v2(), rc[2].v2(), rc[3].v2()],
                ref_fun: r.get("ref_fun").num(),
            }
        })
        .collect()
}
