//! CPython 3.11 semantics that the comparator's verdicts depend on.
//!
//! The Python tool decides pass / fail by comparing floats with tolerances, so the port
//! reproduces its arithmetic to the bit where that is cheap: `math.hypot` (CPython's own
//! `vector_norm`, not libm's), `x ** 2` (libm `pow`), `%` on floats (sign of the divisor),
//! `sum()` (plain left-to-right in 3.11; 3.12 switched to compensated summation), `max` /
//! `min` (first argument wins ties and NaN), `float()` / `int()` / truthiness / `repr()` of
//! JSON values, and `f'{x:.Nf}'` formatting.

use serde_json::Value;
use std::hint::black_box;

/// Stand-ins for the non-standard JSON literals Python's `json` accepts (`NaN`,
/// `Infinity`, `-Infinity`); serde_json rejects them, so they are rewritten as these
/// strings before parsing and read back by [`float`].
pub const NAN_TOKEN: &str = "\u{0}py:NaN";
pub const INF_TOKEN: &str = "\u{0}py:Infinity";
pub const NEG_INF_TOKEN: &str = "\u{0}py:-Infinity";

/// A Python exception that is not the comparator's own `SpecError`: the script lets it
/// escape to its `run_one`, which reports `comparator error: <Type>: <message>`.
#[derive(Clone, Debug, PartialEq)]
pub struct PyErr {
    pub kind: &'static str,
    pub msg: String,
}

impl PyErr {
    pub fn new(kind: &'static str, msg: impl Into<String>) -> PyErr {
        PyErr { kind, msg: msg.into() }
    }
    pub fn zero_division() -> PyErr {
        PyErr::new("ZeroDivisionError", "float division by zero")
    }
}

impl std::fmt::Display for PyErr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.msg)
    }
}

/// Python's `a / b` on floats (raises on a zero divisor instead of giving inf / NaN).
pub fn div(a: f64, b: f64) -> Result<f64, PyErr> {
    if b == 0.0 { Err(PyErr::zero_division()) } else { Ok(a / b) }
}

/// `max(a, b)`: returns `a` unless `b > a`.
#[inline]
pub fn max(a: f64, b: f64) -> f64 {
    if b > a { b } else { a }
}

/// `min(a, b)`: returns `a` unless `b < a`.
#[inline]
pub fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// `x ** 2` on a float: CPython calls libm `pow`, which is not always bit-equal to `x * x`
/// (glibc's pow is not correctly rounded); `black_box` keeps LLVM from folding it to a multiply.
#[inline]
pub fn sq(x: f64) -> f64 {
    x.powf(black_box(2.0))
}

/// `a % b` on floats: the result takes the sign of the divisor.
pub fn fmod(a: f64, b: f64) -> f64 {
    let m = a % b;
    if m != 0.0 { if (b < 0.0) != (m < 0.0) { m + b } else { m } } else { 0.0f64.copysign(b) }
}

/// `math.hypot(x, y)` of CPython 3.10/3.11 (`vector_norm` in Modules/mathmodule.c):
/// an extended-precision sum of squares with a differential correction.
pub fn hypot(x: f64, y: f64) -> f64 {
    let v = [x.abs(), y.abs()];
    let mut mx = 0.0f64;
    let mut found_nan = false;
    for &a in &v {
        found_nan |= a.is_nan();
        if a > mx {
            mx = a;
        }
    }
    vector_norm(&v, mx, found_nan)
}

fn vector_norm(vec: &[f64], max: f64, found_nan: bool) -> f64 {
    const T27: f64 = 134217729.0; // 2**27 + 1
    if max.is_infinite() {
        return max;
    }
    if found_nan {
        return f64::NAN;
    }
    if max == 0.0 || vec.len() <= 1 {
        return max;
    }
    let max_e = frexp_exp(max);
    if max_e < -1023 {
        let scaled: Vec<f64> = vec.iter().map(|x| x / f64::MIN_POSITIVE).collect();
        return f64::MIN_POSITIVE * vector_norm(&scaled, max / f64::MIN_POSITIVE, found_nan);
    }
    let scale = ldexp1(-max_e);
    let (mut csum, mut frac1, mut frac2, mut frac3) = (1.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &x0 in vec {
        let x = x0 * scale;
        let t = x * T27;
        let hi = t - (t - x);
        let lo = x - hi;
        let x = hi * hi;
        let old = csum;
        csum += x;
        frac1 += (old - csum) + x;
        let x = 2.0 * hi * lo;
        let old = csum;
        csum += x;
        frac2 += (old - csum) + x;
        frac3 += lo * lo;
    }
    let h = (csum - 1.0 + (frac1 + frac2 + frac3)).sqrt();
    let t = h * T27;
    let hi = t - (t - h);
    let lo = h - hi;
    let x = -hi * hi;
    let old = csum;
    csum += x;
    frac1 += (old - csum) + x;
    let x = -2.0 * hi * lo;
    let old = csum;
    csum += x;
    frac2 += (old - csum) + x;
    let x = -lo * lo;
    let old = csum;
    csum += x;
    frac3 += (old - csum) + x;
    let x = csum - 1.0 + (frac1 + frac2 + frac3);
    (h + x / (2.0 * h)) / scale
}

/// The exponent `e` of C's `frexp(x)` (x = m * 2**e, 0.5 <= |m| < 1), x finite and non-zero.
fn frexp_exp(x: f64) -> i32 {
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32;
    if e == 0 {
        // subnormal: normalise first
        frexp_exp(x * 2f64.powi(64)) - 64
    } else {
        e - 1022
    }
}

/// `ldexp(1.0, e)` for the exponents vector_norm needs.
fn ldexp1(e: i32) -> f64 {
    if e > 1023 {
        2f64.powi(1023) * 2f64.powi(e - 1023)
    } else if e < -1022 {
        2f64.powi(-1022) * 2f64.powi(e + 1022)
    } else {
        f64::from_bits(((e + 1023) as u64) << 52)
    }
}

// ------------------------------------------------------------------ JSON values

/// Python's `float(value)` for a JSON value: numbers, booleans and numeric strings.
pub fn float(v: &Value) -> Result<f64, PyErr> {
    match v {
        Value::Number(n) => Ok(n.as_f64().unwrap_or(f64::NAN)),
        Value::Bool(b) => Ok(if *b { 1.0 } else { 0.0 }),
        Value::String(s) => match s.as_str() {
            NAN_TOKEN => Ok(f64::NAN),
            INF_TOKEN => Ok(f64::INFINITY),
            NEG_INF_TOKEN => Ok(f64::NEG_INFINITY),
            _ => parse_float_str(s).ok_or_else(|| PyErr::new("ValueError", format!("could not convert string to float: {}", repr_str(s)))),
        },
        other => Err(PyErr::new("TypeError", format!("float() argument must be a string or a real number, not '{}'", type_name(other)))),
    }
}

fn parse_float_str(s: &str) -> Option<f64> {
    let t = s.trim();
    let body = t.strip_prefix(['+', '-']).unwrap_or(t);
    let lower = body.to_ascii_lowercase();
    if matches!(lower.as_str(), "nan" | "inf" | "infinity") {
        return t.parse::<f64>().ok();
    }
    // digits with single underscores between digits, as float() allows
    if body.is_empty() || !body.chars().all(|c| c.is_ascii_digit() || "._eE+-".contains(c)) {
        return None;
    }
    let b = body.as_bytes();
    for (i, &c) in b.iter().enumerate() {
        if c == b'_' && !(i > 0 && b[i - 1].is_ascii_digit() && i + 1 < b.len() && b[i + 1].is_ascii_digit()) {
            return None;
        }
    }
    t.replace('_', "").parse::<f64>().ok()
}

/// Python's `int(value)`: ints, booleans, floats (truncated), integer strings.
pub fn int(v: &Value) -> Result<i64, PyErr> {
    match v {
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                Ok(i)
            } else if n.as_u64().is_some() {
                Err(PyErr::new("IndexError", "cannot fit 'int' into an index-sized integer"))
            } else {
                float_to_int(n.as_f64().unwrap_or(f64::NAN))
            }
        }
        Value::Bool(b) => Ok(*b as i64),
        Value::String(s) => match s.as_str() {
            NAN_TOKEN => float_to_int(f64::NAN),
            INF_TOKEN => float_to_int(f64::INFINITY),
            NEG_INF_TOKEN => float_to_int(f64::NEG_INFINITY),
            _ => {
                let t = s.trim();
                let ok = !t.is_empty() && t.strip_prefix(['+', '-']).unwrap_or(t).chars().all(|c| c.is_ascii_digit() || c == '_');
                t.replace('_', "")
                    .parse::<i64>()
                    .ok()
                    .filter(|_| ok)
                    .ok_or_else(|| PyErr::new("ValueError", format!("invalid literal for int() with base 10: {}", repr_str(s))))
            }
        },
        other => Err(PyErr::new(
            "TypeError",
            format!("int() argument must be a string, a bytes-like object or a real number, not '{}'", type_name(other)),
        )),
    }
}

fn float_to_int(x: f64) -> Result<i64, PyErr> {
    if x.is_nan() {
        Err(PyErr::new("ValueError", "cannot convert float NaN to integer"))
    } else if x.is_infinite() {
        Err(PyErr::new("OverflowError", "cannot convert float infinity to integer"))
    } else {
        Ok(x.trunc() as i64)
    }
}

/// Python truthiness of a JSON value (`bool(x)`, `x or None`).
pub fn truthy(v: &Value) -> bool {
    match v {
        Value::Null => false,
        Value::Bool(b) => *b,
        Value::Number(n) => n.as_f64().is_some_and(|x| x != 0.0),
        Value::String(s) => !s.is_empty(),
        Value::Array(a) => !a.is_empty(),
        Value::Object(o) => !o.is_empty(),
    }
}

/// Python `==` between JSON-loaded values (1 == 1.0 == True).
pub fn eq(a: &Value, b: &Value) -> bool {
    let num = |v: &Value| match v {
        Value::Number(n) => n.as_f64(),
        Value::Bool(b) => Some(*b as i64 as f64),
        Value::String(s) if s == NAN_TOKEN => Some(f64::NAN),
        Value::String(s) if s == INF_TOKEN => Some(f64::INFINITY),
        Value::String(s) if s == NEG_INF_TOKEN => Some(f64::NEG_INFINITY),
        _ => None,
    };
    match (a, b) {
        (Value::Null, Value::Null) => true,
        (Value::String(x), Value::String(y)) if !x.starts_with('\0') && !y.starts_with('\0') => x == y,
        (Value::Array(x), Value::Array(y)) => x.len() == y.len() && x.iter().zip(y).all(|(p, q)| eq(p, q)),
        (Value::Object(x), Value::Object(y)) => x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| eq(v, w))),
        _ => match (num(a), num(b)) {
            (Some(x), Some(y)) => x == y,
            _ => false,
        },
    }
}

pub fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "NoneType",
        Value::Bool(_) => "bool",
        Value::Number(n) if n.is_f64() => "float",
        Value::Number(_) => "int",
        Value::String(s) if [NAN_TOKEN, INF_TOKEN, NEG_INF_TOKEN].contains(&s.as_str()) => "float",
        Value::String(_) => "str",
        Value::Array(_) => "list",
        Value::Object(_) => "dict",
    }
}

/// `repr(value)` of a JSON-loaded value.
pub fn repr(v: &Value) -> String {
    match v {
        Value::Null => "None".into(),
        Value::Bool(b) => (if *b { "True" } else { "False" }).into(),
        Value::Number(n) => {
            if n.is_f64() {
                float_repr(n.as_f64().unwrap_or(f64::NAN))
            } else {
                n.to_string()
            }
        }
        Value::String(s) => match s.as_str() {
            NAN_TOKEN => "nan".into(),
            INF_TOKEN => "inf".into(),
            NEG_INF_TOKEN => "-inf".into(),
            _ => repr_str(s),
        },
        Value::Array(a) => format!("[{}]", a.iter().map(repr).collect::<Vec<_>>().join(", ")),
        Value::Object(o) => {
            format!("{{{}}}", o.iter().map(|(k, v)| format!("{}: {}", repr_str(k), repr(v))).collect::<Vec<_>>().join(", "))
        }
    }
}

/// `str(value)`: like repr, except that a string is itself.
pub fn str_of(v: &Value) -> String {
    match v {
        Value::String(s) if !s.starts_with('\0') => s.clone(),
        other => repr(other),
    }
}

/// `repr(str)`: single quotes unless the text has a single quote and no double quote.
pub fn repr_str(s: &str) -> String {
    let q = if s.contains('\'') && !s.contains('"') { '"' } else { '\'' };
    let mut out = String::with_capacity(s.len() + 2);
    out.push(q);
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c == q => {
                out.push('\\');
                out.push(c);
            }
            c if (c as u32) < 0x20 || c as u32 == 0x7f => out.push_str(&format!("\\x{:02x}", c as u32)),
            c if (0x80..0xa0).contains(&(c as u32)) => out.push_str(&format!("\\x{:02x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push(q);
    out
}

/// `repr(float)`: shortest round-trip digits, positional for 1e-4 <= |x| < 1e16.
pub fn float_repr(x: f64) -> String {
    if x == 0.0 && x.is_sign_negative() {
        return "-0.0".into();
    }
    garmentcode::parity::float_repr::python_float_repr(x)
}

/// `f'{x:.Nf}'`. Rust's fixed formatting rounds the exact binary value half-to-even like
/// Python's; only the spelling of the non-finite values differs.
pub fn fixed(x: f64, prec: usize) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{x:.prec$}")
    }
}

/// `f'{x:.N%}'`.
pub fn percent(x: f64, prec: usize) -> String {
    format!("{}%", fixed(x * 100.0, prec))
}

/// Rewrite the bare `NaN`, `Infinity` and `-Infinity` literals Python's `json` accepts into
/// the token strings above (outside of strings only), so that serde_json can read the text.
pub fn rewrite_nonstandard_literals(text: &str) -> Option<String> {
    if !(text.contains("NaN") || text.contains("Infinity")) {
        return None;
    }
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut last = 0;
    let mut changed = false;
    while i < b.len() {
        match b[i] {
            b'"' => {
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    if b[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
                i += 1;
            }
            b'N' if text[i..].starts_with("NaN") => {
                out.push_str(&text[last..i]);
                out.push_str(&serde_json::to_string(NAN_TOKEN).unwrap());
                i += 3;
                last = i;
                changed = true;
            }
            b'I' if text[i..].starts_with("Infinity") => {
                out.push_str(&text[last..i]);
                out.push_str(&serde_json::to_string(INF_TOKEN).unwrap());
                i += 8;
                last = i;
                changed = true;
            }
            b'-' if text[i..].starts_with("-Infinity") => {
                out.push_str(&text[last..i]);
                out.push_str(&serde_json::to_string(NEG_INF_TOKEN).unwrap());
                i += 9;
                last = i;
                changed = true;
            }
            _ => i += 1,
        }
    }
    if !changed {
        return None;
    }
    out.push_str(&text[last.min(text.len())..]);
    Some(out)
}

/// `str.strip().splitlines()[0]` of an error file's text (None when empty).
pub fn first_line(text: &str) -> Option<String> {
    let is_break = |c: char| matches!(c, '\n' | '\r' | '\x0b' | '\x0c' | '\x1c' | '\x1d' | '\x1e' | '\u{85}' | '\u{2028}' | '\u{2029}');
    let t = text.trim_matches(|c: char| c.is_whitespace() || ('\x1c'..='\x1f').contains(&c));
    if t.is_empty() {
        return None;
    }
    Some(t.split(is_break).next().unwrap_or("").to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reprs() {
        assert_eq!(float_repr(0.1), "0.1");
        assert_eq!(float_repr(1e-5), "1e-05");
        assert_eq!(float_repr(1e16), "1e+16");
        assert_eq!(float_repr(123.0), "123.0");
        assert_eq!(float_repr(-2.5e-7), "-2.5e-07");
        assert_eq!(repr_str("it's"), "\"it's\"");
        assert_eq!(fmod(-1.0, 6.0), 5.0);
        assert_eq!(hypot(3.0, 4.0), 5.0);
    }
}
