//! Writer: a port of PyYAML's `emitter.py` (with `representer.py` for the
//! scalar text), configured as `yaml.dump(data, default_flow_style=False,
//! sort_keys=False)`: block collections, 2-space indentation, sequences that are
//! mapping values written at the key's indentation, empty collections as `[]` /
//! `{}`, plain style unless the text would read back as something else (then
//! single quotes, or double quotes with escapes for control/non-ASCII
//! characters), long scalars folded at column 80.
//!
//! One deliberate difference: PyYAML writes scalar keys that are empty,
//! multi-line or 123+ characters long (128 counting the implicit `!!str` tag) as explicit `? key` entries, which our
//! reader does not support; we write them as ordinary (quoted) keys instead,
//! which PyYAML reads identically. Only keys whose written form exceeds YAML's
//! 1024-character simple-key limit still use `? key`.

use crate::parity::yaml::node::{AsValue, Node, Value};
use crate::parity::yaml::resolve::plain_is_str;

const BEST_INDENT: i64 = 2;
const BEST_WIDTH: usize = 80;

/// Writes a value as PyYAML `dump(v, default_flow_style=False, sort_keys=False)`
/// would (floats at full precision, in Python `repr` form: `1.0`, `0.1`, `1.0e+20`).
///
/// For values made of the supported types, `parse(&to_string(v))` gives back `v`.
pub fn to_string<T: AsValue + ?Sized>(v: &T) -> String {
    let mut e = Emitter::new();
    e.expect_node(v.as_value(), Ctx { root: true, ..Ctx::default() });
    // Document end (implicit) and stream end.
    e.write_indent();
    if e.open_ended {
        e.write_indicator("...", true, false, false);
        e.write_indent();
    }
    e.out
}

#[derive(Clone, Copy, Default)]
struct Ctx {
    root: bool,
    mapping: bool,
    simple_key: bool,
}

struct Emitter {
    out: String,
    indents: Vec<Option<i64>>,
    indent: Option<i64>,
    flow_level: usize,
    column: usize,
    whitespace: bool,
    indention: bool,
    open_ended: bool,
}

#[derive(Clone, Copy, PartialEq)]
enum ScalarStyle {
    Plain,
    Single,
    Double,
}

struct Analysis {
    empty: bool,
    multiline: bool,
    allow_flow_plain: bool,
    allow_block_plain: bool,
    allow_single_quoted: bool,
}

impl Emitter {
    fn new() -> Emitter {
        Emitter {
            out: String::new(),
            indents: Vec::new(),
            indent: None,
            flow_level: 0,
            column: 0,
            whitespace: true,
            indention: true,
            open_ended: false,
        }
    }

    fn increase_indent(&mut self, flow: bool, indentless: bool) {
        self.indents.push(self.indent);
        match self.indent {
            None => self.indent = Some(if flow { BEST_INDENT } else { 0 }),
            Some(i) if !indentless => self.indent = Some(i + BEST_INDENT),
            Some(_) => {}
        }
    }

    fn pop_indent(&mut self) {
        self.indent = self.indents.pop().unwrap_or(None);
    }

    fn expect_node(&mut self, v: &Value, ctx: Ctx) {
        match v {
            Value::Seq(items) => {
                if self.flow_level > 0 || items.is_empty() {
                    self.flow_sequence(items);
                } else {
                    self.block_sequence(items, ctx);
                }
            }
            Value::Map(pairs) => {
                if self.flow_level > 0 || pairs.is_empty() {
                    self.flow_mapping(pairs);
                } else {
                    self.block_mapping(pairs);
                }
            }
            _ => {
                self.increase_indent(true, false);
                self.process_scalar(v, ctx);
                self.pop_indent();
            }
        }
    }

    fn flow_sequence(&mut self, items: &[Node]) {
        self.write_indicator("[", true, true, false);
        self.flow_level += 1;
        self.increase_indent(true, false);
        for (i, item) in items.iter().enumerate() {
            if i > 0 {
                self.write_indicator(",", false, false, false);
            }
            if self.column > BEST_WIDTH {
                self.write_indent();
            }
            self.expect_node(&item.value, Ctx::default());
        }
        self.pop_indent();
        self.flow_level -= 1;
        self.write_indicator("]", false, false, false);
    }

    fn flow_mapping(&mut self, pairs: &[(Node, Node)]) {
        self.write_indicator("{", true, true, false);
        self.flow_level += 1;
        self.increase_indent(true, false);
        for (i, (k, v)) in pairs.iter().enumerate() {
            if i > 0 {
                self.write_indicator(",", false, false, false);
            }
            if self.column > BEST_WIDTH {
                self.write_indent();
            }
            let key_ctx = Ctx { mapping: true, simple_key: true, ..Ctx::default() };
            if self.check_simple_key(&k.value) {
                self.expect_node(&k.value, key_ctx);
                self.write_indicator(":", false, false, false);
            } else {
                self.write_indicator("?", true, false, false);
                self.expect_node(&k.value, Ctx { mapping: true, ..Ctx::default() });
                if self.column > BEST_WIDTH {
                    self.write_indent();
                }
                self.write_indicator(":", true, false, false);
            }
            self.expect_node(&v.value, Ctx { mapping: true, ..Ctx::default() });
        }
        self.pop_indent();
        self.flow_level -= 1;
        self.write_indicator("}", false, false, false);
    }

    fn block_sequence(&mut self, items: &[Node], ctx: Ctx) {
        let indentless = ctx.mapping && !self.indention;
        self.increase_indent(false, indentless);
        for item in items {
            self.write_indent();
            self.write_indicator("-", true, false, true);
            self.expect_node(&item.value, Ctx::default());
        }
        self.pop_indent();
    }

    fn block_mapping(&mut self, pairs: &[(Node, Node)]) {
        self.increase_indent(false, false);
        for (k, v) in pairs {
            self.write_indent();
            if self.check_simple_key(&k.value) {
                self.expect_node(&k.value, Ctx { mapping: true, simple_key: true, ..Ctx::default() });
                self.write_indicator(":", false, false, false);
            } else {
                self.write_indicator("?", true, false, true);
                self.expect_node(&k.value, Ctx { mapping: true, ..Ctx::default() });
                self.write_indent();
                self.write_indicator(":", true, false, true);
            }
            self.expect_node(&v.value, Ctx { mapping: true, ..Ctx::default() });
        }
        self.pop_indent();
    }

    /// PyYAML `check_simple_key`, extended to every scalar whose written form
    /// fits YAML's 1024-character simple-key limit (see the module docs).
    fn check_simple_key(&self, k: &Value) -> bool {
        match k {
            Value::Seq(items) => items.is_empty(),
            Value::Map(pairs) => pairs.is_empty(),
            Value::Str(s) if s.len() < 100 && is_simple_plain(s) => true,
            Value::Null | Value::Bool(_) | Value::Int(_) | Value::Float(_) => true,
            _ => {
                let text = scalar_text(k);
                let a = analyze(&text);
                if text.chars().count() < 128 && !a.empty && !a.multiline {
                    return true;
                }
                let mut e = Emitter::new();
                e.flow_level = self.flow_level;
                e.expect_node(k, Ctx { mapping: true, simple_key: true, ..Ctx::default() });
                e.out.chars().count() <= 1000
            }
        }
    }

    fn process_scalar(&mut self, v: &Value, ctx: Ctx) {
        // Fast path for what design files are made of (numbers, `null`,
        // booleans, identifier-like strings on short lines): PyYAML's analysis
        // would choose plain style and its writer would not fold the line.
        if self.flow_level == 0 {
            let simple = match v {
                Value::Str(s) => is_simple_plain(s) && self.column + 1 + s.len() <= BEST_WIDTH && plain_is_str(s),
                Value::Seq(_) | Value::Map(_) => false,
                _ => true,
            };
            if simple {
                let text: std::borrow::Cow<str> = match v {
                    Value::Str(s) => std::borrow::Cow::Borrowed(s.as_str()),
                    other => std::borrow::Cow::Owned(scalar_text(other)),
                };
                if ctx.root {
                    self.open_ended = true;
                }
                if !self.whitespace {
                    self.out.push(' ');
                    self.column += 1;
                }
                self.out.push_str(&text);
                self.column += text.len();
                self.whitespace = false;
                self.indention = false;
                return;
            }
        }
        let text = scalar_text(v);
        let implicit = match v {
            Value::Str(s) => plain_is_str(s),
            _ => true,
        };
        let a = analyze(&text);
        let style = self.choose_style(&a, implicit, ctx);
        let split = !ctx.simple_key;
        let chars: Vec<char> = text.chars().collect();
        match style {
            ScalarStyle::Plain => self.write_plain(&chars, split, ctx.root),
            ScalarStyle::Single => self.write_single_quoted(&chars, split),
            ScalarStyle::Double => self.write_double_quoted(&chars, split),
        }
    }

    fn choose_style(&self, a: &Analysis, implicit: bool, ctx: Ctx) -> ScalarStyle {
        if implicit
            && !(ctx.simple_key && (a.empty || a.multiline))
            && ((self.flow_level > 0 && a.allow_flow_plain) || (self.flow_level == 0 && a.allow_block_plain))
        {
            return ScalarStyle::Plain;
        }
        if a.allow_single_quoted && !(ctx.simple_key && a.multiline) {
            return ScalarStyle::Single;
        }
        ScalarStyle::Double
    }

    // ----- low-level writers (PyYAML write_indicator / write_indent / ...) ----

    fn write(&mut self, s: &str) {
        self.out.push_str(s);
    }

    fn write_indicator(&mut self, indicator: &str, need_whitespace: bool, whitespace: bool, indention: bool) {
        if !self.whitespace && need_whitespace {
            self.out.push(' ');
            self.column += 1;
        }
        self.out.push_str(indicator);
        self.column += indicator.len();
        self.whitespace = whitespace;
        self.indention = self.indention && indention;
        self.open_ended = false;
    }

    fn write_indent(&mut self) {
        let indent = self.indent.unwrap_or(0).max(0) as usize;
        if !self.indention || self.column > indent || (self.column == indent && !self.whitespace) {
            self.write_line_break();
        }
        if self.column < indent {
            self.whitespace = true;
            for _ in self.column..indent {
                self.out.push(' ');
            }
            self.column = indent;
        }
    }

    fn write_line_break(&mut self) {
        self.whitespace = true;
        self.indention = true;
        self.column = 0;
        self.out.push('\n');
    }

    fn write_chars(&mut self, chars: &[char]) {
        for &c in chars {
            self.out.push(c);
        }
        self.column += chars.len();
    }

    fn write_plain(&mut self, text: &[char], split: bool, root: bool) {
        if root {
            self.open_ended = true;
        }
        if text.is_empty() {
            return;
        }
        if !self.whitespace {
            self.write(" ");
            self.column += 1;
        }
        self.whitespace = false;
        self.indention = false;
        let mut spaces = false;
        let mut breaks = false;
        let (mut start, mut end) = (0usize, 0usize);
        while end <= text.len() {
            let ch = text.get(end).copied();
            if spaces {
                if ch != Some(' ') {
                    if start + 1 == end && self.column > BEST_WIDTH && split {
                        self.write_indent();
                        self.whitespace = false;
                        self.indention = false;
                    } else {
                        self.write_chars(&text[start..end]);
                    }
                    start = end;
                }
            } else if breaks {
                if !matches!(ch, Some('\n' | '\u{85}' | '\u{2028}' | '\u{2029}')) {
                    self.write_breaks(&text[start..end]);
                    self.write_indent();
                    self.whitespace = false;
                    self.indention = false;
                    start = end;
                }
            } else if ch.is_none() || matches!(ch, Some(' ' | '\n' | '\u{85}' | '\u{2028}' | '\u{2029}')) {
                self.write_chars(&text[start..end]);
                start = end;
            }
            if let Some(c) = ch {
                spaces = c == ' ';
                breaks = matches!(c, '\n' | '\u{85}' | '\u{2028}' | '\u{2029}');
            }
            end += 1;
        }
    }

    /// A run of line breaks inside a scalar, as PyYAML writes it: a leading `\n`
    /// is doubled (folding would eat one), other breaks are copied.
    fn write_breaks(&mut self, breaks: &[char]) {
        if breaks[0] == '\n' {
            self.write_line_break();
        }
        for &br in breaks {
            if br == '\n' {
                self.write_line_break();
            } else {
                self.out.push(br);
                self.whitespace = true;
                self.indention = true;
                self.column = 0;
            }
        }
    }

    fn write_single_quoted(&mut self, text: &[char], split: bool) {
        self.write_indicator("'", true, false, false);
        let mut spaces = false;
        let mut breaks = false;
        let (mut start, mut end) = (0usize, 0usize);
        while end <= text.len() {
            let ch = text.get(end).copied();
            if spaces {
                if ch != Some(' ') {
                    if start + 1 == end && self.column > BEST_WIDTH && split && start != 0 && end != text.len() {
                        self.write_indent();
                    } else {
                        self.write_chars(&text[start..end]);
                    }
                    start = end;
                }
            } else if breaks {
                if !matches!(ch, Some('\n' | '\u{85}' | '\u{2028}' | '\u{2029}')) {
                    self.write_breaks(&text[start..end]);
                    self.write_indent();
                    start = end;
                }
            } else if (ch.is_none() || matches!(ch, Some(' ' | '\n' | '\u{85}' | '\u{2028}' | '\u{2029}' | '\''))) && start < end {
                self.write_chars(&text[start..end]);
                start = end;
            }
            if ch == Some('\'') {
                self.write("''");
                self.column += 2;
                start = end + 1;
            }
            if let Some(c) = ch {
                spaces = c == ' ';
                breaks = matches!(c, '\n' | '\u{85}' | '\u{2028}' | '\u{2029}');
            }
            end += 1;
        }
        self.write_indicator("'", false, false, false);
    }

    fn write_double_quoted(&mut self, text: &[char], split: bool) {
        self.write_indicator("\"", true, false, false);
        let (mut start, mut end) = (0usize, 0usize);
        while end <= text.len() {
            let ch = text.get(end).copied();
            let needs_escape = match ch {
                None => true,
                Some(c) => matches!(c, '"' | '\\' | '\u{85}' | '\u{2028}' | '\u{2029}' | '\u{FEFF}') || !(' '..='~').contains(&c),
            };
            if needs_escape {
                if start < end {
                    self.write_chars(&text[start..end]);
                    start = end;
                }
                if let Some(c) = ch {
                    let data = match c {
                        '\0' => "\\0".to_string(),
                        '\x07' => "\\a".to_string(),
                        '\x08' => "\\b".to_string(),
                        '\t' => "\\t".to_string(),
                        '\n' => "\\n".to_string(),
                        '\x0B' => "\\v".to_string(),
                        '\x0C' => "\\f".to_string(),
                        '\r' => "\\r".to_string(),
                        '\x1B' => "\\e".to_string(),
                        '"' => "\\\"".to_string(),
                        '\\' => "\\\\".to_string(),
                        '\u{85}' => "\\N".to_string(),
                        '\u{A0}' => "\\_".to_string(),
                        '\u{2028}' => "\\L".to_string(),
                        '\u{2029}' => "\\P".to_string(),
                        c if (c as u32) <= 0xFF => format!("\\x{:02X}", c as u32),
                        c if (c as u32) <= 0xFFFF => format!("\\u{:04X}", c as u32),
                        c => format!("\\U{:08X}", c as u32),
                    };
                    self.column += data.len();
                    self.write(&data);
                    start = end + 1;
                }
            }
            if 0 < end
                && end + 1 < text.len()
                && (ch == Some(' ') || start >= end)
                && self.column as i64 + end as i64 - start as i64 > BEST_WIDTH as i64
                && split
            {
                let piece: String = text[start.min(end)..end].iter().collect();
                let data = format!("{}\\", if start < end { piece.as_str() } else { "" });
                if start < end {
                    start = end;
                }
                self.column += data.chars().count();
                self.write(&data);
                self.write_indent();
                self.whitespace = false;
                self.indention = false;
                if text.get(start) == Some(&' ') {
                    self.write("\\");
                    self.column += 1;
                }
            }
            end += 1;
        }
        self.write_indicator("\"", false, false, false);
    }
}

/// A string PyYAML writes plain without any analysis subtleties: starts with
/// a letter, digit or `_`, then letters, digits and `_-./+` or single spaces,
/// not ending with a space. (Whether it would read back as a string is checked
/// separately.)
fn is_simple_plain(s: &str) -> bool {
    let b = s.as_bytes();
    match b.first() {
        Some(c) if c.is_ascii_alphanumeric() || *c == b'_' => {}
        _ => return false,
    }
    if b[b.len() - 1] == b' ' {
        return false;
    }
    let mut prev_space = false;
    for &c in &b[1..] {
        let ok = c.is_ascii_alphanumeric() || matches!(c, b'_' | b'-' | b'.' | b'/' | b'+');
        if c == b' ' {
            if prev_space {
                return false;
            }
            prev_space = true;
        } else if ok {
            prev_space = false;
        } else {
            return false;
        }
    }
    true
}

/// The scalar's text as PyYAML's representer writes it.
fn scalar_text(v: &Value) -> String {
    match v {
        Value::Null => "null".to_string(),
        Value::Bool(true) => "true".to_string(),
        Value::Bool(false) => "false".to_string(),
        Value::Int(i) => i.to_string(),
        Value::Float(f) => float_repr(*f),
        Value::Str(s) => s.clone(),
        Value::Seq(_) | Value::Map(_) => String::new(),
    }
}

/// A float as PyYAML writes it: Python's `repr`, with `.0` added to a mantissa
/// without a point (`1e+16` → `1.0e+16`), and `.nan`, `.inf`, `-.inf`.
pub(crate) fn float_repr(f: f64) -> String {
    let mut out = String::with_capacity(24);
    push_float_repr(&mut out, f);
    out
}

/// [`float_repr`] appended to `out`, without allocating.
pub(crate) fn push_float_repr(out: &mut String, f: f64) {
    if f.is_nan() {
        out.push_str(".nan");
        return;
    }
    if f.is_infinite() {
        out.push_str(if f > 0.0 { ".inf" } else { "-.inf" });
        return;
    }
    if f == 0.0 {
        out.push_str(if f.is_sign_negative() { "-0.0" } else { "0.0" });
        return;
    }
    let start = out.len();
    crate::parity::float_repr::write_python_float(out, f);
    if let Some(e) = out[start..].find('e')
        && !out[start..start + e].contains('.')
    {
        out.insert_str(start + e, ".0");
    }
}

/// PyYAML `analyze_scalar` (with `allow_unicode=False`).
fn analyze(scalar: &str) -> Analysis {
    if scalar.is_empty() {
        return Analysis { empty: true, multiline: false, allow_flow_plain: false, allow_block_plain: true, allow_single_quoted: true };
    }
    let chars: Vec<char> = scalar.chars().collect();
    let n = chars.len();
    let is_ws = |c: char| matches!(c, '\0' | ' ' | '\t' | '\r' | '\n' | '\u{85}' | '\u{2028}' | '\u{2029}');
    let is_br = |c: char| matches!(c, '\n' | '\u{85}' | '\u{2028}' | '\u{2029}');
    let mut block_indicators = false;
    let mut flow_indicators = false;
    let mut line_breaks = false;
    let mut special_characters = false;
    let mut leading_space = false;
    let mut leading_break = false;
    let mut trailing_space = false;
    let mut trailing_break = false;
    let mut break_space = false;
    let mut space_break = false;
    if scalar.starts_with("---") || scalar.starts_with("...") {
        block_indicators = true;
        flow_indicators = true;
    }
    let mut preceded_by_whitespace = true;
    let mut followed_by_whitespace = n == 1 || is_ws(chars[1]);
    let mut previous_space = false;
    let mut previous_break = false;
    for index in 0..n {
        let ch = chars[index];
        if index == 0 {
            if "#,[]{}&*!|>'\"%@`".contains(ch) {
                flow_indicators = true;
                block_indicators = true;
            }
            if ch == '?' || ch == ':' {
                flow_indicators = true;
                if followed_by_whitespace {
                    block_indicators = true;
                }
            }
            if ch == '-' && followed_by_whitespace {
                flow_indicators = true;
                block_indicators = true;
            }
        } else {
            if ",?[]{}".contains(ch) {
                flow_indicators = true;
            }
            if ch == ':' {
                flow_indicators = true;
                if followed_by_whitespace {
                    block_indicators = true;
                }
            }
            if ch == '#' && preceded_by_whitespace {
                flow_indicators = true;
                block_indicators = true;
            }
        }
        if is_br(ch) {
            line_breaks = true;
        }
        if !(ch == '\n' || (' '..='~').contains(&ch)) {
            // allow_unicode=False: every other character must be escaped.
            special_characters = true;
        }
        if ch == ' ' {
            if index == 0 {
                leading_space = true;
            }
            if index == n - 1 {
                trailing_space = true;
            }
            if previous_break {
                break_space = true;
            }
            previous_space = true;
            previous_break = false;
        } else if is_br(ch) {
            if index == 0 {
                leading_break = true;
            }
            if index == n - 1 {
                trailing_break = true;
            }
            if previous_space {
                space_break = true;
            }
            previous_space = false;
            previous_break = true;
        } else {
            previous_space = false;
            previous_break = false;
        }
        preceded_by_whitespace = is_ws(ch);
        followed_by_whitespace = index + 2 >= n || is_ws(chars[index + 2]);
    }
    let mut allow_flow_plain = true;
    let mut allow_block_plain = true;
    let mut allow_single_quoted = true;
    if leading_space || leading_break || trailing_space || trailing_break {
        allow_flow_plain = false;
        allow_block_plain = false;
    }
    if break_space {
        allow_flow_plain = false;
        allow_block_plain = false;
        allow_single_quoted = false;
    }
    if space_break || special_characters {
        allow_flow_plain = false;
        allow_block_plain = false;
        allow_single_quoted = false;
    }
    if line_breaks {
        allow_flow_plain = false;
        allow_block_plain = false;
    }
    if flow_indicators {
        allow_flow_plain = false;
    }
    if block_indicators {
        allow_block_plain = false;
    }
    Analysis { empty: false, multiline: line_breaks, allow_flow_plain, allow_block_plain, allow_single_quoted }
}

#[cfg(test)]
mod tests {
    use super::float_repr;

    #[test]
    fn python_float_repr() {
        let cases: &[(f64, &str)] = &[
            (0.0, "0.0"),
            (-0.0, "-0.0"),
            (1.0, "1.0"),
            (0.1, "0.1"),
            (1e16, "1.0e+16"),
            (1e15, "1000000000000000.0"),
            (1234567890123456.0, "1234567890123456.0"),
            (0.0001, "0.0001"),
            (0.00001, "1.0e-05"),
            (1.5e-7, "1.5e-07"),
            (1e100, "1.0e+100"),
            (0.7815787603227047, "0.7815787603227047"),
            (5e-324, "5.0e-324"),
            (f64::MAX, "1.7976931348623157e+308"),
        ];
        for &(f, s) in cases {
            assert_eq!(float_repr(f), s, "{:?}", f);
        }
    }
}
