//! YAML 1.1 implicit typing of plain scalars, exactly as PyYAML's `Resolver`
//! and `SafeConstructor` do it. Each regular expression of `resolver.py` is
//! hand-coded as a small matcher (no regex engine, no allocation on the common
//! path); the construction step mirrors `construct_yaml_int/float/bool/null`.
//!
//! Reminders of the YAML 1.1 rules (all checked against PyYAML in tests):
//! `yes/no/on/off` are booleans; a float needs a `.` (`1e3` is a string, `1.0e+3`
//! a float, `1.0e3` a string: the exponent needs a sign); `.5` is a float but
//! `-.5` a string; `0777` is octal, `0o17` and `08` are strings; `1:30` is 90
//! (base 60); `_` is ignored inside numbers.

/// What a plain scalar means.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Resolved {
    Null,
    Bool(bool),
    Int(i64),
    Float(f64),
    Str,
    /// `=`: PyYAML's "value" tag; a string as a mapping key, an error as a value.
    ValueKey,
    /// `<<`: a merge key (unsupported).
    Merge,
    /// A date or date-time (unsupported).
    Timestamp,
    /// An int PyYAML would accept but that does not fit in `i64`.
    IntOutOfRange,
    /// `0x_` / `0b_`: matches PyYAML's int pattern but has no digits (PyYAML crashes).
    BadInt,
}

/// Resolves a plain (unquoted) scalar.
pub(crate) fn resolve_plain(s: &str) -> Resolved {
    let b = s.as_bytes();
    let first = match b.first() {
        None => return Resolved::Null,
        Some(&c) => c,
    };
    match first {
        b'~' if b.len() == 1 => Resolved::Null,
        b'n' | b'N' => match s {
            "null" | "Null" | "NULL" => Resolved::Null,
            "no" | "No" | "NO" => Resolved::Bool(false),
            _ => Resolved::Str,
        },
        b'y' | b'Y' | b't' | b'T' | b'f' | b'F' | b'o' | b'O' => match s {
            "yes" | "Yes" | "YES" | "true" | "True" | "TRUE" | "on" | "On" | "ON" => Resolved::Bool(true),
            "false" | "False" | "FALSE" | "off" | "Off" | "OFF" => Resolved::Bool(false),
            _ => Resolved::Str,
        },
        b'<' if s == "<<" => Resolved::Merge,
        b'=' if s == "=" => Resolved::ValueKey,
        b'-' | b'+' | b'.' | b'0'..=b'9' => resolve_number(s),
        _ => Resolved::Str,
    }
}

/// Whether [`resolve_plain`] gives a value (null, boolean, number or string)
/// rather than one of its error kinds, without converting decimal floats (the
/// common case of a design file's ranges, which are only validated).
pub(crate) fn resolves_to_value(s: &str) -> bool {
    let b = s.as_bytes();
    // A non-sexagesimal float always constructs (as a float, or as a string in
    // theory), which is what `resolve_number` would find first.
    if matches!(b.first(), Some(b'-' | b'+' | b'.' | b'0'..=b'9')) && match_float(b) == Some(false) {
        return true;
    }
    matches!(resolve_plain(s), Resolved::Null | Resolved::Bool(_) | Resolved::Int(_) | Resolved::Float(_) | Resolved::Str)
}

/// True if PyYAML would read `s`, written plain, back as the same string
/// (used by the writer to decide whether a string needs quotes).
pub(crate) fn plain_is_str(s: &str) -> bool {
    resolve_plain(s) == Resolved::Str
}

fn resolve_number(s: &str) -> Resolved {
    let b = s.as_bytes();
    if let Some(sexa) = match_float(b) {
        return construct_float(s, sexa);
    }
    if let Some(kind) = match_int(b) {
        return construct_int(s, kind);
    }
    if match_timestamp(b) {
        return Resolved::Timestamp;
    }
    Resolved::Str
}

#[inline]
fn is_digit(c: u8) -> bool {
    c.is_ascii_digit()
}

/// Skips `[0-9_]*` from `i`.
fn skip_digits_(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && (is_digit(b[i]) || b[i] == b'_') {
        i += 1;
    }
    i
}

/// `(?::[0-5]?[0-9])+` from `i` (which must be at a ':'); returns the end or None.
fn match_sexagesimal_tail(b: &[u8], mut i: usize) -> Option<usize> {
    let mut groups = 0;
    while i < b.len() && b[i] == b':' {
        let d1 = *b.get(i + 1)?;
        if !is_digit(d1) {
            return None;
        }
        // Greedy two digits when the first is 0-5; backtracking to one digit
        // could never help since a digit cannot follow the group.
        if d1 <= b'5' && b.get(i + 2).is_some_and(|&c| is_digit(c)) {
            i += 3;
        } else {
            i += 2;
        }
        groups += 1;
    }
    if groups == 0 { None } else { Some(i) }
}

/// `[eE][-+][0-9]+$` from `i`, or end of input.
fn match_exponent_end(b: &[u8], i: usize) -> bool {
    if i == b.len() {
        return true;
    }
    if !(b[i] == b'e' || b[i] == b'E') {
        return false;
    }
    if !matches!(b.get(i + 1), Some(b'-') | Some(b'+')) {
        return false;
    }
    let mut j = i + 2;
    let start = j;
    while j < b.len() && is_digit(b[j]) {
        j += 1;
    }
    j > start && j == b.len()
}

/// PyYAML's float pattern. Returns Some(is_sexagesimal) on a match.
fn match_float(b: &[u8]) -> Option<bool> {
    let n = b.len();
    // \.(?:nan|NaN|NAN)
    if matches!(b, b".nan" | b".NaN" | b".NAN") {
        return Some(false);
    }
    let j = if b[0] == b'-' || b[0] == b'+' { 1 } else { 0 };
    // [-+]?\.(?:inf|Inf|INF)
    if matches!(&b[j..], b".inf" | b".Inf" | b".INF") {
        return Some(false);
    }
    // \.[0-9][0-9_]*(?:[eE][-+][0-9]+)?   (no sign allowed)
    if b[0] == b'.' {
        if n < 2 || !is_digit(b[1]) {
            return None;
        }
        let i = skip_digits_(b, 2);
        return if match_exponent_end(b, i) { Some(false) } else { None };
    }
    // [-+]?[0-9][0-9_]* then `\.[0-9_]*(exp)?` or `(:[0-5]?[0-9])+\.[0-9_]*`
    if j >= n || !is_digit(b[j]) {
        return None;
    }
    let i = skip_digits_(b, j + 1);
    if i < n && b[i] == b'.' {
        let k = skip_digits_(b, i + 1);
        return if match_exponent_end(b, k) { Some(false) } else { None };
    }
    if i < n && b[i] == b':' {
        let k = match_sexagesimal_tail(b, i)?;
        if k < n && b[k] == b'.' && skip_digits_(b, k + 1) == n {
            return Some(true);
        }
    }
    None
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum IntKind {
    Bin,
    Oct,
    Dec,
    Hex,
    Sexa,
}

/// PyYAML's int pattern.
fn match_int(b: &[u8]) -> Option<IntKind> {
    let n = b.len();
    let j = if b[0] == b'-' || b[0] == b'+' { 1 } else { 0 };
    let r = &b[j..];
    if r.is_empty() {
        return None;
    }
    if r[0] == b'0' {
        if r.len() == 1 {
            return Some(IntKind::Dec);
        }
        let rest = &r[1..];
        let all = |f: fn(u8) -> bool, s: &[u8]| !s.is_empty() && s.iter().all(|&c| f(c) || c == b'_');
        if rest[0] == b'b' && all(|c| c == b'0' || c == b'1', &rest[1..]) {
            return Some(IntKind::Bin);
        }
        if rest[0] == b'x' && all(|c| c.is_ascii_hexdigit(), &rest[1..]) {
            return Some(IntKind::Hex);
        }
        if all(|c| (b'0'..=b'7').contains(&c), rest) {
            return Some(IntKind::Oct);
        }
        return None;
    }
    if !(b'1'..=b'9').contains(&r[0]) {
        return None;
    }
    let i = skip_digits_(b, j + 1);
    if i == n {
        return Some(IntKind::Dec);
    }
    if b[i] == b':' && match_sexagesimal_tail(b, i) == Some(n) {
        return Some(IntKind::Sexa);
    }
    None
}

/// `construct_yaml_int`.
fn construct_int(s: &str, kind: IntKind) -> Resolved {
    let mut digits: Vec<u8> = Vec::with_capacity(s.len());
    digits.extend(s.bytes().filter(|&c| c != b'_'));
    let neg = digits[0] == b'-';
    let v: &[u8] = if digits[0] == b'-' || digits[0] == b'+' { &digits[1..] } else { &digits[..] };
    let magnitude: Option<u128> = if v == b"0" {
        Some(0)
    } else {
        match kind {
            IntKind::Bin => radix(&v[2..], 2),
            IntKind::Hex => radix(&v[2..], 16),
            IntKind::Oct => radix(v, 8),
            IntKind::Dec => radix(v, 10),
            IntKind::Sexa => {
                let mut total: u128 = 0;
                let mut ok = true;
                for part in v.split(|&c| c == b':') {
                    match radix(part, 10).and_then(|p| total.checked_mul(60).and_then(|t| t.checked_add(p))) {
                        Some(t) => total = t,
                        None => {
                            ok = false;
                            break;
                        }
                    }
                }
                if ok { Some(total) } else { None }
            }
        }
    };
    let m = match magnitude {
        Some(m) => m,
        None => {
            // Either no digits at all (`0x_`) or too large.
            let no_digits = matches!(kind, IntKind::Bin | IntKind::Hex) && v.len() <= 2;
            return if no_digits { Resolved::BadInt } else { Resolved::IntOutOfRange };
        }
    };
    if neg {
        if m <= 1u128 << 63 { Resolved::Int((m as i128).wrapping_neg() as i64) } else { Resolved::IntOutOfRange }
    } else if m <= i64::MAX as u128 {
        Resolved::Int(m as i64)
    } else {
        Resolved::IntOutOfRange
    }
}

/// Parses digits in `base`; None if empty, invalid or beyond u128.
fn radix(d: &[u8], base: u32) -> Option<u128> {
    if d.is_empty() {
        return None;
    }
    let mut acc: u128 = 0;
    for &c in d {
        let x = (c as char).to_digit(base)? as u128;
        acc = acc.checked_mul(base as u128)?.checked_add(x)?;
    }
    Some(acc)
}

/// `construct_yaml_float`.
fn construct_float(s: &str, sexagesimal: bool) -> Resolved {
    // Common case (`0.5`, `-1.25e+3`): Rust's parser reads exactly what
    // Python's `float()` reads once `_` is gone; `.inf`/`.nan` need the slow path.
    if !sexagesimal && !s.contains(['_', 'i', 'I', 'n', 'N']) {
        if let Ok(f) = s.parse::<f64>() {
            return Resolved::Float(f);
        }
    }
    let mut buf = [0u8; 64];
    let mut owned: Vec<u8> = Vec::new();
    let cleaned: &[u8] = if s.len() <= buf.len() {
        let mut n = 0;
        for c in s.bytes() {
            if c != b'_' {
                buf[n] = c.to_ascii_lowercase();
                n += 1;
            }
        }
        &buf[..n]
    } else {
        owned.extend(s.bytes().filter(|&c| c != b'_').map(|c| c.to_ascii_lowercase()));
        &owned
    };
    let neg = cleaned[0] == b'-';
    let v = if cleaned[0] == b'-' || cleaned[0] == b'+' { &cleaned[1..] } else { cleaned };
    let sign = |x: f64| if neg { -x } else { x };
    if v == b".inf" {
        return Resolved::Float(sign(f64::INFINITY));
    }
    if v == b".nan" {
        return Resolved::Float(f64::NAN);
    }
    if sexagesimal {
        // value = sum(part_i * 60^i), parts read right to left, as PyYAML does.
        let parts: Vec<&[u8]> = v.split(|&c| c == b':').collect();
        let mut value = 0.0f64;
        let mut base: u128 = 1;
        for part in parts.iter().rev() {
            let d = match parse_f64(part) {
                Some(d) => d,
                None => return Resolved::Str,
            };
            value += d * (base as f64);
            base = match base.checked_mul(60) {
                Some(b) => b,
                None => return Resolved::IntOutOfRange,
            };
        }
        return Resolved::Float(sign(value));
    }
    match parse_f64(v) {
        Some(f) => Resolved::Float(sign(f)),
        None => Resolved::Str,
    }
}

fn parse_f64(v: &[u8]) -> Option<f64> {
    std::str::from_utf8(v).ok()?.parse::<f64>().ok()
}

/// PyYAML's timestamp pattern (`2001-12-14`, `2001-12-14t21:59:43.10-05:00`, ...).
fn match_timestamp(b: &[u8]) -> bool {
    let n = b.len();
    let digit = |i: usize| i < n && is_digit(b[i]);
    if n < 10 || !(digit(0) && digit(1) && digit(2) && digit(3)) || b[4] != b'-' {
        return false;
    }
    // [0-9]{4}-[0-9]{2}-[0-9]{2}$
    if n == 10 && digit(5) && digit(6) && b[7] == b'-' && digit(8) && digit(9) {
        return true;
    }
    // 1-2 digits helper: returns the index after them.
    let one_two = |i: usize| -> Option<usize> {
        if !digit(i) {
            return None;
        }
        Some(if digit(i + 1) { i + 2 } else { i + 1 })
    };
    let Some(mut i) = one_two(5) else { return false };
    if i >= n || b[i] != b'-' {
        return false;
    }
    let Some(j) = one_two(i + 1) else { return false };
    i = j;
    // (?:[Tt]|[ \t]+)
    if i < n && (b[i] == b'T' || b[i] == b't') {
        i += 1;
    } else {
        let s = i;
        while i < n && (b[i] == b' ' || b[i] == b'\t') {
            i += 1;
        }
        if i == s {
            return false;
        }
    }
    let Some(j) = one_two(i) else { return false };
    i = j;
    if !(i < n && b[i] == b':' && digit(i + 1) && digit(i + 2)) {
        return false;
    }
    i += 3;
    if !(i < n && b[i] == b':' && digit(i + 1) && digit(i + 2)) {
        return false;
    }
    i += 3;
    if i < n && b[i] == b'.' {
        i += 1;
        while digit(i) {
            i += 1;
        }
    }
    if i == n {
        return true;
    }
    while i < n && (b[i] == b' ' || b[i] == b'\t') {
        i += 1;
    }
    if i < n && b[i] == b'Z' {
        return i + 1 == n;
    }
    if i < n && (b[i] == b'-' || b[i] == b'+') {
        let Some(j) = one_two(i + 1) else { return false };
        i = j;
        if i == n {
            return true;
        }
        return b[i] == b':' && digit(i + 1) && digit(i + 2) && i + 3 == n;
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn basics() {
        assert_eq!(resolve_plain("1."), Resolved::Float(1.0));
        assert_eq!(resolve_plain("1e3"), Resolved::Str);
        assert_eq!(resolve_plain("1.0e+3"), Resolved::Float(1000.0));
        assert_eq!(resolve_plain("-.5"), Resolved::Str);
        assert_eq!(resolve_plain("0777"), Resolved::Int(511));
        assert_eq!(resolve_plain("1:30"), Resolved::Int(90));
        assert_eq!(resolve_plain("1:30.5"), Resolved::Float(90.5));
        assert_eq!(resolve_plain("0x_"), Resolved::BadInt);
        assert_eq!(resolve_plain("-9223372036854775808"), Resolved::Int(i64::MIN));
        assert_eq!(resolve_plain("9223372036854775808"), Resolved::IntOutOfRange);
        assert_eq!(resolve_plain("2001-12-14"), Resolved::Timestamp);
        assert_eq!(resolve_plain("2001-12-14 21:59:43.10 -5"), Resolved::Timestamp);
        assert_eq!(resolve_plain("yes"), Resolved::Bool(true));
        assert_eq!(resolve_plain("Off"), Resolved::Bool(false));
    }

    #[test]
    fn resolves_to_value_matches_resolve_plain() {
        let words = [
            "",
            "~",
            "null",
            "x",
            "1",
            "-1",
            "+1",
            "1.",
            ".5",
            "-.5",
            "+.5",
            "1.0e+3",
            "1.0e3",
            "1e3",
            "1_0.5",
            "1:30",
            "1:30.5",
            "99999999999999999999:0.5",
            "9223372036854775808",
            "0x_",
            "0b_",
            "0x1F",
            "0777",
            "08",
            "2001-12-14",
            "<<",
            "=",
            ".inf",
            "-.inf",
            ".nan",
            ".NaN",
            "yes",
            "Off",
            "0.5",
            "-0.25",
            "1__",
            "._5",
            "1:60.5",
            "0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0:0.5",
        ];
        for w in words {
            let expected =
                matches!(resolve_plain(w), Resolved::Null | Resolved::Bool(_) | Resolved::Int(_) | Resolved::Float(_) | Resolved::Str);
            assert_eq!(resolves_to_value(w), expected, "{w:?}");
        }
    }
}
