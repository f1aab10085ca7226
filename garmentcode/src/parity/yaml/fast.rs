//! Fast path: a line-oriented reader for the plain block YAML that design and
//! body files consist of (`key: value`, `- item`, comments, blank lines,
//! single-line quoted scalars and `[a, b]` lists).
//!
//! It gives up (returns `None`) on anything it is not sure about: tabs,
//! multi-line scalars, flow mappings, nested flow, escapes, document markers,
//! odd indentation, duplicate keys, unsupported scalars... The caller then runs
//! the full PyYAML-faithful scanner/parser, which also produces the error
//! message. So the fast path never decides an error and never needs to be
//! complete; it only must agree with the full parser (values and positions)
//! whenever it succeeds, which the fuzz tests check on every input.
//!
//! For speed, every node is written once, straight into its slot on a stack
//! (`items` for sequence items; `pairs` for mapping entries, whose value slot
//! is filled in place), and a finished collection is moved with one copy
//! (`split_off`) into an exactly-sized `Vec`. Building nodes in temporaries
//! and returning them by value made the CPU stall on store-to-load forwarding,
//! which cost more than the parsing itself.

use crate::parity::yaml::node::{Node, Value, keys_equal};
use crate::parity::yaml::resolve::{Resolved, resolve_plain};
use crate::parity::yaml::scanner::MAX_DEPTH;

/// One non-blank, non-comment line (or, for `- key: v`, the part from the key on).
#[derive(Clone, Copy)]
struct Line {
    /// Column (characters) of the content; equals the indentation for whole lines.
    indent: u32,
    /// Byte offsets of the content start and of the line end (before `\r\n`).
    start: usize,
    end: usize,
    line_start: usize,
    /// 0-based line number.
    line: u32,
    ascii: bool,
}

struct Fast<'a> {
    /// Only printable ASCII and `\n` in the whole text.
    clean: bool,
    text: &'a str,
    src: &'a [u8],
    /// Byte offset of the next unread line.
    pos: usize,
    line_no: u32,
    cur: Option<Line>,
    /// Items of the open sequences, and pairs of the open mappings (a pair's
    /// value is written in place once parsed). Index 0 holds a dummy so that
    /// `split_off` never starts at 0 (which would hand over the whole buffer).
    items: Vec<Node>,
    pairs: Vec<(Node, Node)>,
    depth: usize,
}

/// Where a finished node goes: onto the item stack, or into a pair's value slot.
#[derive(Clone, Copy)]
enum Dest {
    Item,
    Pair(usize),
}

const NULL_NODE: Node = Node { value: Value::Null, line: 0, col: 0 };

/// Characters that cannot start a plain scalar (PyYAML `check_plain`; `-`, `?`,
/// `:` are refused here too, even where PyYAML allows them, to stay simple).
#[inline]
fn is_indicator(b: u8) -> bool {
    matches!(
        b,
        b'-' | b'?'
            | b':'
            | b','
            | b'['
            | b']'
            | b'{'
            | b'}'
            | b'#'
            | b'&'
            | b'*'
            | b'!'
            | b'|'
            | b'>'
            | b'\''
            | b'"'
            | b'%'
            | b'@'
            | b'`'
            | b' '
    )
}

/// `clean`: the text is only printable ASCII and `\n` (see `check_characters`).
pub(crate) fn parse_fast(text: &str, clean: bool) -> Option<Node> {
    let mut items = Vec::with_capacity(64);
    items.push(NULL_NODE);
    let mut pairs = Vec::with_capacity(32);
    pairs.push((NULL_NODE, NULL_NODE));
    let mut f = Fast { clean, text, src: text.as_bytes(), pos: 0, line_no: 0, cur: None, items, pairs, depth: 0 };
    f.run()
}

impl<'a> Fast<'a> {
    fn run(&mut self) -> Option<Node> {
        if self.src.starts_with(&[0xEF, 0xBB, 0xBF]) {
            self.pos = 3;
            self.clean = false;
        }
        self.advance()?;
        self.cur?; // empty document: let the full parser produce `null`
        self.block_node(-1, Dest::Item)?;
        if self.cur.is_some() || self.items.len() != 2 {
            return None;
        }
        self.items.pop()
    }

    /// Moves to the next content line, skipping blank and comment lines.
    fn advance(&mut self) -> Option<()> {
        let src = self.src;
        loop {
            if self.pos >= src.len() {
                self.cur = None;
                return Some(());
            }
            let line_start = self.pos;
            let mut i = line_start;
            let mut ascii = true;
            if self.clean {
                i = find_newline(src, i);
            } else {
                // Find the end of the line; give up on tabs, lone CRs and BOMs.
                while i < src.len() {
                    let b = src[i];
                    if b == b'\n' {
                        break;
                    }
                    if !(0x20..0x80).contains(&b) {
                        match b {
                            b'\r' if src.get(i + 1) == Some(&b'\n') => {}
                            0xEF if src.get(i + 1) == Some(&0xBB) && src.get(i + 2) == Some(&0xBF) => return None,
                            b if b >= 0x80 => ascii = false,
                            _ => return None,
                        }
                    }
                    i += 1;
                }
            }
            let mut end = i;
            if end > line_start && src[end - 1] == b'\r' {
                end -= 1;
            }
            self.pos = if i < src.len() { i + 1 } else { i };
            let line = self.line_no;
            self.line_no += 1;
            let mut s = line_start;
            while s < end && src[s] == b' ' {
                s += 1;
            }
            if s == end || src[s] == b'#' {
                continue;
            }
            if s == line_start {
                // Document markers and directives: leave them to the full parser.
                let b = src[s];
                if b == b'%' || ((b == b'-' || b == b'.') && src.get(s + 1) == Some(&b) && src.get(s + 2) == Some(&b)) {
                    return None;
                }
            }
            self.cur = Some(Line { indent: (s - line_start) as u32, start: s, end, line_start, line, ascii });
            return Some(());
        }
    }

    /// Character column of byte `pos` on `l`'s line.
    #[inline(always)]
    fn col(&self, l: &Line, pos: usize) -> u32 {
        if l.ascii { (pos - l.line_start) as u32 } else { self.src[l.line_start..pos].iter().filter(|&&b| b & 0xC0 != 0x80).count() as u32 }
    }

    #[inline(always)]
    fn put(&mut self, dest: Dest, value: Value, l: &Line, pos: usize) {
        let col = self.col(l, pos) + 1;
        let line = l.line + 1;
        match dest {
            Dest::Item => self.items.push(Node { value, line, col }),
            Dest::Pair(i) => {
                let slot = &mut self.pairs[i].1;
                slot.value = value;
                slot.line = line;
                slot.col = col;
            }
        }
    }

    fn is_entry(&self, l: &Line) -> bool {
        self.src[l.start] == b'-' && (l.start + 1 == l.end || self.src[l.start + 1] == b' ')
    }

    /// A block collection starting at the current line, deeper than `parent`.
    fn block_node(&mut self, parent: i64, dest: Dest) -> Option<()> {
        let l = self.cur?;
        if (l.indent as i64) <= parent || self.depth >= MAX_DEPTH {
            return None;
        }
        self.depth += 1;
        let r = if self.is_entry(&l) { self.sequence(l.indent, false, dest) } else { self.mapping(l.indent, dest) };
        self.depth -= 1;
        r
    }

    /// `- item` lines at column `n` (`indentless`: a mapping value at the key's column).
    fn sequence(&mut self, n: u32, indentless: bool, dest: Dest) -> Option<()> {
        let first = self.cur?;
        let base = self.items.len();
        while let Some(l) = self.cur {
            if l.indent < n {
                break;
            }
            if l.indent > n {
                return None;
            }
            if !self.is_entry(&l) {
                if indentless {
                    break;
                }
                return None;
            }
            let dash = l.start;
            let mut p = dash + 1;
            while p < l.end && self.src[p] == b' ' {
                p += 1;
            }
            if p >= l.end || self.src[p] == b'#' {
                // Value on the following lines, or null.
                self.advance()?;
                match self.cur {
                    Some(next) if next.indent > n => self.block_node(n as i64, Dest::Item)?,
                    _ => self.put(Dest::Item, Value::Null, &l, dash + 1),
                }
            } else if self.src[p] == b'-' && (p + 1 == l.end || self.src[p + 1] == b' ') {
                return None; // `- - x`
            } else if self.key_colon(p, l.end).is_some() {
                // `- key: value`: a mapping whose column is the key's.
                let c = self.col(&l, p);
                self.cur = Some(Line { indent: c, start: p, ..l });
                if self.depth >= MAX_DEPTH {
                    return None;
                }
                self.depth += 1;
                let m = self.mapping(c, Dest::Item);
                self.depth -= 1;
                m?;
            } else {
                self.inline_value(&l, p, Dest::Item)?;
                self.advance()?;
                if matches!(self.cur, Some(next) if next.indent > n) {
                    return None; // continuation line or bad indentation
                }
            }
        }
        let items = self.items.split_off(base);
        self.put(dest, Value::Seq(items), &first, first.start);
        Some(())
    }

    /// `key: value` lines at column `n`.
    fn mapping(&mut self, n: u32, dest: Dest) -> Option<()> {
        let first = self.cur?;
        let base = self.pairs.len();
        while let Some(l) = self.cur {
            if l.indent < n {
                break;
            }
            // Many keys: the full parser (linear in keys) handles them.
            if l.indent > n || self.is_entry(&l) || self.pairs.len() - base >= 256 {
                return None;
            }
            let colon = self.key_colon(l.start, l.end)?;
            if colon - l.start > 1000 {
                return None; // PyYAML's simple keys are limited to 1024 characters
            }
            let mut key_end = colon;
            while self.src[key_end - 1] == b' ' {
                key_end -= 1;
            }
            let key_text = self.text.get(l.start..key_end)?;
            let key_res = resolve_plain(key_text);
            // Duplicate keys: the full parser reports them.
            for (k, _) in &self.pairs[base..] {
                let same = match (&k.value, key_res) {
                    (Value::Str(a), Resolved::Str | Resolved::ValueKey) => a == key_text,
                    (Value::Str(_), _) | (_, Resolved::Str | Resolved::ValueKey) => false,
                    (a, r) => keys_equal(a, &scalar_value(r)?),
                };
                if same {
                    return None;
                }
            }
            // The key is written straight into its slot (no temporary Value).
            let idx = self.pairs.len();
            self.pairs.push((NULL_NODE, NULL_NODE));
            let col = self.col(&l, l.start) + 1;
            let key = &mut self.pairs[idx].0;
            key.line = l.line + 1;
            key.col = col;
            match key_res {
                Resolved::Str | Resolved::ValueKey => key.value = Value::Str(key_text.to_string()),
                Resolved::Null => {}
                Resolved::Bool(b) => key.value = Value::Bool(b),
                Resolved::Int(i) => key.value = Value::Int(i),
                Resolved::Float(f) => key.value = Value::Float(f),
                _ => return None,
            }
            let vdest = Dest::Pair(idx);
            let mut p = colon + 1;
            while p < l.end && self.src[p] == b' ' {
                p += 1;
            }
            if p >= l.end || self.src[p] == b'#' {
                self.advance()?;
                match self.cur {
                    Some(next) if next.indent > n => self.block_node(n as i64, vdest)?,
                    Some(next) if next.indent == n && self.is_entry(&next) => self.sequence(n, true, vdest)?,
                    _ => self.put(vdest, Value::Null, &l, colon + 1),
                }
            } else {
                self.inline_value(&l, p, vdest)?;
                self.advance()?;
                if matches!(self.cur, Some(next) if next.indent > n) {
                    return None; // continuation line or bad indentation
                }
            }
        }
        let pairs = self.pairs.split_off(base);
        self.put(dest, Value::Map(pairs), &first, first.start);
        Some(())
    }

    /// If `start..end` begins with a plain key followed by `: ` (or `:` at the
    /// end), the byte index of that colon.
    fn key_colon(&self, start: usize, end: usize) -> Option<usize> {
        let src = self.src;
        if is_indicator(src[start]) {
            return None;
        }
        let mut i = start + 1;
        while i < end {
            match src[i] {
                b':' if i + 1 == end || src[i + 1] == b' ' => return Some(i),
                b'#' if src[i - 1] == b' ' => return None,
                _ => {}
            }
            i += 1;
        }
        None
    }

    /// A value written on the key's (or dash's) line, from `p` to the end of
    /// the line: a plain scalar, a single-line quoted scalar or a `[...]` list.
    fn inline_value(&mut self, l: &Line, p: usize, dest: Dest) -> Option<()> {
        let src = self.src;
        match src[p] {
            b'[' => self.flow_sequence(l, p, dest),
            b'\'' | b'"' => {
                let (s, after) = self.quoted(l, p)?;
                self.rest_is_blank(l, after)?;
                self.put(dest, Value::Str(s), l, p);
                Some(())
            }
            // `-5`, `-x` are plain scalars; `- ` would be a (misplaced) entry.
            b'-' if p + 1 < l.end && src[p + 1] != b' ' => self.plain_value(l, p, dest),
            b if is_indicator(b) => None,
            _ => self.plain_value(l, p, dest),
        }
    }

    /// A plain scalar from `p` to the end of the line or a ` #` comment.
    fn plain_value(&mut self, l: &Line, p: usize, dest: Dest) -> Option<()> {
        let src = self.src;
        let mut i = p + 1;
        let mut end = l.end;
        while i < l.end {
            match src[i] {
                // PyYAML: "mapping values are not allowed here".
                b':' if i + 1 == l.end || src[i + 1] == b' ' => return None,
                b'#' if src[i - 1] == b' ' => {
                    end = i;
                    break;
                }
                _ => {}
            }
            i += 1;
        }
        while src[end - 1] == b' ' {
            end -= 1;
        }
        let s = self.text.get(p..end)?;
        self.put_scalar(dest, s, l, p)
    }

    /// Resolves a plain scalar and stores it.
    #[inline(always)]
    fn put_scalar(&mut self, dest: Dest, s: &str, l: &Line, p: usize) -> Option<()> {
        match resolve_plain(s) {
            Resolved::Str => self.put(dest, Value::Str(s.to_string()), l, p),
            Resolved::Null => self.put(dest, Value::Null, l, p),
            Resolved::Bool(b) => self.put(dest, Value::Bool(b), l, p),
            Resolved::Int(i) => self.put(dest, Value::Int(i), l, p),
            Resolved::Float(f) => self.put(dest, Value::Float(f), l, p),
            _ => return None,
        }
        Some(())
    }

    /// A quoted scalar closed on the same line, without escapes; returns the
    /// text and the index after the closing quote.
    fn quoted(&self, l: &Line, p: usize) -> Option<(String, usize)> {
        let src = self.src;
        let q = src[p];
        let mut i = p + 1;
        let mut out: Option<String> = None;
        let mut chunk = i;
        loop {
            if i >= l.end {
                return None; // continues on the next line
            }
            let b = src[i];
            if b == b'\\' && q == b'"' {
                return None; // escapes: full parser
            }
            if b == q {
                if q == b'\'' && i + 1 < l.end && src[i + 1] == b'\'' {
                    let o = out.get_or_insert_with(String::new);
                    o.push_str(self.text.get(chunk..i + 1)?);
                    i += 2;
                    chunk = i;
                    continue;
                }
                let last = self.text.get(chunk..i)?;
                let s = match out {
                    Some(mut o) => {
                        o.push_str(last);
                        o
                    }
                    None => last.to_string(),
                };
                return Some((s, i + 1));
            }
            i += 1;
        }
    }

    /// After a value: only spaces, then the end of the line or a ` #` comment.
    fn rest_is_blank(&self, l: &Line, mut i: usize) -> Option<()> {
        let start = i;
        while i < l.end && self.src[i] == b' ' {
            i += 1;
        }
        if i == l.end || (self.src[i] == b'#' && i > start) { Some(()) } else { None }
    }

    /// `[a, b, c]` on one line, with plain or quoted scalar items.
    fn flow_sequence(&mut self, l: &Line, p: usize, dest: Dest) -> Option<()> {
        let src = self.src;
        let base = self.items.len();
        let mut i = p + 1;
        while i < l.end && src[i] == b' ' {
            i += 1;
        }
        if i < l.end && src[i] == b']' {
            i += 1;
        } else {
            loop {
                if i >= l.end {
                    return None;
                }
                let q = i;
                match src[q] {
                    b'\'' | b'"' => {
                        let (s, after) = self.quoted(l, q)?;
                        i = after;
                        while i < l.end && src[i] == b' ' {
                            i += 1;
                        }
                        self.put(Dest::Item, Value::Str(s), l, q);
                    }
                    b'-' if q + 1 < l.end && !matches!(src[q + 1], b' ' | b',' | b']') => self.flow_plain(l, &mut i)?,
                    b if is_indicator(b) => return None,
                    _ => self.flow_plain(l, &mut i)?,
                }
                if i >= l.end {
                    return None;
                }
                match src[i] {
                    b',' => {
                        i += 1;
                        while i < l.end && src[i] == b' ' {
                            i += 1;
                        }
                        if i < l.end && src[i] == b']' {
                            return None; // trailing comma: full parser
                        }
                    }
                    b']' => {
                        i += 1;
                        break;
                    }
                    _ => return None,
                }
            }
        }
        self.rest_is_blank(l, i)?;
        let items = self.items.split_off(base);
        self.put(dest, Value::Seq(items), l, p);
        Some(())
    }

    /// A plain scalar inside `[...]`, stopping at `,` or `]` (anything
    /// unusual gives up); leaves `i` at the delimiter.
    fn flow_plain(&mut self, l: &Line, i: &mut usize) -> Option<()> {
        let src = self.src;
        let q = *i;
        let mut j = q;
        while j < l.end {
            match src[j] {
                b',' | b']' => break,
                b':' | b'?' | b'[' | b'{' | b'}' | b'#' | b'\'' | b'"' => return None,
                _ => j += 1,
            }
        }
        let mut end = j;
        while src[end - 1] == b' ' {
            end -= 1;
        }
        *i = j;
        let s = self.text.get(q..end)?;
        self.put_scalar(Dest::Item, s, l, q)
    }
}

/// Index of the next `\n` at or after `i` (or the length), 8 bytes at a time.
#[inline]
fn find_newline(src: &[u8], mut i: usize) -> usize {
    const LO: u64 = 0x0101_0101_0101_0101;
    const HI: u64 = 0x8080_8080_8080_8080;
    while i + 8 <= src.len() {
        let mut w = [0u8; 8];
        w.copy_from_slice(&src[i..i + 8]);
        let x = u64::from_le_bytes(w) ^ (LO * b'\n' as u64);
        let found = x.wrapping_sub(LO) & !x & HI;
        if found != 0 {
            return i + (found.trailing_zeros() / 8) as usize;
        }
        i += 8;
    }
    while i < src.len() && src[i] != b'\n' {
        i += 1;
    }
    i
}

/// The value of a resolved non-string scalar; None for the error kinds.
fn scalar_value(r: Resolved) -> Option<Value> {
    match r {
        Resolved::Null => Some(Value::Null),
        Resolved::Bool(b) => Some(Value::Bool(b)),
        Resolved::Int(i) => Some(Value::Int(i)),
        Resolved::Float(f) => Some(Value::Float(f)),
        _ => None,
    }
}
