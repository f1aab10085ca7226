//! Tokenizer: a port of PyYAML's `scanner.py`, restricted to the supported subset.
//!
//! Following PyYAML token by token (simple keys, indentation stack, "allow simple
//! key" flag, tab handling, plain-scalar folding) is what makes every accepted
//! document read exactly as PyYAML reads it. Tokens PyYAML would produce for
//! unsupported features (anchors, aliases, tags, directives, block scalars,
//! explicit `?` keys) become errors here.
//!
//! Works on bytes: every delimiter is ASCII, so slicing at them never splits a
//! UTF-8 character. Positions are byte offsets; columns are counted in
//! characters (as PyYAML does) only when a mark is taken.

use crate::parity::yaml::node::YamlError;
use std::collections::VecDeque;

/// Nesting deeper than this is refused (PyYAML itself fails with a
/// `RecursionError` somewhere around 300-500 levels).
pub(crate) const MAX_DEPTH: usize = 256;

/// A position: byte offset plus 0-based line and character column.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Mark {
    pub pos: usize,
    pub line: u32,
    pub col: u32,
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Kind {
    StreamEnd,
    DocStart,
    DocEnd,
    BlockSeqStart,
    BlockMapStart,
    BlockEnd,
    FlowSeqStart,
    FlowSeqEnd,
    FlowMapStart,
    FlowMapEnd,
    BlockEntry,
    FlowEntry,
    Key,
    Value,
    Scalar,
}

/// Scalar style, as written in the source.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Style {
    Plain,
    Single,
    Double,
}

/// Scalar text: a slice of the source when it can be (the common case, no
/// allocation), otherwise an owned string (escapes, folded lines).
#[derive(Debug)]
pub(crate) enum Text {
    None,
    Span(usize, usize),
    Owned(String),
}

#[derive(Debug)]
pub(crate) struct Token {
    pub kind: Kind,
    pub start: Mark,
    pub end: Mark,
    pub style: Style,
    pub text: Text,
}

impl Token {
    fn simple(kind: Kind, start: Mark, end: Mark) -> Token {
        Token { kind, start, end, style: Style::Plain, text: Text::None }
    }
}

/// A place where a simple key (`key: value` without `?`) may have started.
#[derive(Clone, Copy, Debug)]
struct SimpleKey {
    token_number: usize,
    required: bool,
    mark: Mark,
}

/// Builds scalar text, staying a borrowed span while the pieces are contiguous
/// in the source (e.g. `Fitted Shirt` is scanned as three pieces).
struct TextBuf {
    span: Option<(usize, usize)>,
    owned: Option<String>,
}

impl TextBuf {
    fn new() -> TextBuf {
        TextBuf { span: None, owned: None }
    }

    fn push_span(&mut self, src: &str, a: usize, b: usize) {
        if a == b {
            return;
        }
        if let Some(s) = &mut self.owned {
            s.push_str(src.get(a..b).unwrap_or(""));
            return;
        }
        match self.span {
            None => self.span = Some((a, b)),
            Some((x, y)) if y == a => self.span = Some((x, b)),
            Some((x, y)) => {
                let mut s = String::with_capacity(y - x + b - a + 8);
                s.push_str(src.get(x..y).unwrap_or(""));
                s.push_str(src.get(a..b).unwrap_or(""));
                self.owned = Some(s);
            }
        }
    }

    fn to_owned_mut(&mut self, src: &str) -> &mut String {
        if self.owned.is_none() {
            let mut s = String::new();
            if let Some((x, y)) = self.span {
                s.push_str(src.get(x..y).unwrap_or(""));
            }
            self.owned = Some(s);
        }
        self.owned.get_or_insert_with(String::new)
    }

    fn push_char(&mut self, src: &str, c: char) {
        self.to_owned_mut(src).push(c);
    }

    fn push_newlines(&mut self, src: &str, n: usize) {
        let s = self.to_owned_mut(src);
        for _ in 0..n {
            s.push('\n');
        }
    }

    fn finish(self) -> Text {
        match (self.owned, self.span) {
            (Some(s), _) => Text::Owned(s),
            (None, Some((a, b))) => Text::Span(a, b),
            (None, None) => Text::Span(0, 0),
        }
    }
}

/// Whitespace found after a piece of a plain scalar (PyYAML `scan_plain_spaces`).
enum Spaces {
    /// Nothing usable: the scalar ends here.
    End,
    /// Spaces on the same line (kept verbatim if another piece follows).
    Inline(usize, usize),
    /// A line break folded into one space.
    Fold,
    /// `n` empty lines, kept as `n` newlines.
    Breaks(usize),
}

pub(crate) struct Scanner<'a> {
    text: &'a str,
    src: &'a [u8],
    pos: usize,
    line: u32,
    line_start: usize,
    /// Cache for character-column computation: (byte position, column there).
    col_cache: (usize, u32),
    flow_level: usize,
    tokens: VecDeque<Token>,
    tokens_taken: usize,
    indent: i64,
    indents: Vec<i64>,
    /// For each open block collection (parallel to `indents`): true = mapping.
    indent_is_map: Vec<bool>,
    cur_is_map: bool,
    allow_simple_key: bool,
    /// Possible simple key per flow level (index = flow level).
    possible_keys: Vec<Option<SimpleKey>>,
    active_keys: usize,
    done: bool,
    /// Marks of the currently open `[` / `{`, for "unclosed" messages.
    open_flows: Vec<(u8, Mark)>,
    /// Start and end byte of the plain scalar fetched last, if it was the last
    /// token fetched (to explain a following ':' error).
    prev_plain: Option<(Mark, usize)>,
}

/// `\0` (end of input), space, tab or line break: what may follow an indicator.
#[inline]
fn is_blankz(b: u8) -> bool {
    matches!(b, 0 | b' ' | b'\t' | b'\r' | b'\n')
}

#[inline]
fn is_break(b: u8) -> bool {
    b == b'\n' || b == b'\r'
}

/// Byte classes for the plain-scalar inner loop: bit 1 = always ends a piece
/// (`\0`, space, tab, break), bit 2 = `:`, bit 4 = flow indicator `,?[]{}`.
static CLASS: [u8; 256] = {
    let mut t = [0u8; 256];
    t[0] = 1;
    t[b' ' as usize] = 1;
    t[b'\t' as usize] = 1;
    t[b'\r' as usize] = 1;
    t[b'\n' as usize] = 1;
    t[b':' as usize] = 2;
    t[b',' as usize] = 4;
    t[b'?' as usize] = 4;
    t[b'[' as usize] = 4;
    t[b']' as usize] = 4;
    t[b'{' as usize] = 4;
    t[b'}' as usize] = 4;
    t
};

impl<'a> Scanner<'a> {
    pub fn new(text: &'a str) -> Scanner<'a> {
        Scanner {
            text,
            src: text.as_bytes(),
            pos: 0,
            line: 0,
            line_start: 0,
            col_cache: (0, 0),
            flow_level: 0,
            tokens: VecDeque::with_capacity(16),
            tokens_taken: 0,
            indent: -1,
            indents: Vec::new(),
            indent_is_map: Vec::new(),
            cur_is_map: false,
            allow_simple_key: true,
            possible_keys: vec![None],
            active_keys: 0,
            done: false,
            open_flows: Vec::new(),
            prev_plain: None,
        }
    }

    pub fn source(&self) -> &'a str {
        self.text
    }

    // ----- reader primitives -------------------------------------------------

    #[inline]
    fn peek(&self, k: usize) -> u8 {
        // The input never contains NUL (checked up front), so 0 means "end".
        self.src.get(self.pos + k).copied().unwrap_or(0)
    }

    /// Character column of byte position `pos` on the current line. U+FEFF
    /// does not advance the column, as in PyYAML's reader.
    fn column_of(&mut self, pos: usize) -> u32 {
        let (mut p, mut c) = self.col_cache;
        if p < self.line_start || p > pos {
            p = self.line_start;
            c = 0;
        }
        let bytes = &self.src[p.min(self.src.len())..pos.min(self.src.len())];
        for (i, &b) in bytes.iter().enumerate() {
            if b & 0xC0 != 0x80 {
                c += 1;
                if b == 0xEF && bytes.get(i + 1) == Some(&0xBB) && bytes.get(i + 2) == Some(&0xBF) {
                    c -= 1;
                }
            }
        }
        self.col_cache = (pos, c);
        c
    }

    #[inline]
    fn column(&mut self) -> u32 {
        if self.pos == self.line_start {
            return 0;
        }
        self.column_of(self.pos)
    }

    fn mark(&mut self) -> Mark {
        let col = self.column();
        Mark { pos: self.pos, line: self.line, col }
    }

    /// Number of characters between two byte positions.
    fn chars_between(&self, a: usize, b: usize) -> usize {
        self.src[a..b].iter().filter(|&&x| x & 0xC0 != 0x80).count()
    }

    /// Consumes one line break (`\r\n`, `\r` or `\n`) if there is one.
    #[inline]
    fn scan_line_break(&mut self) -> bool {
        match self.peek(0) {
            b'\r' => {
                self.pos += if self.peek(1) == b'\n' { 2 } else { 1 };
            }
            b'\n' => self.pos += 1,
            _ => return false,
        }
        self.line += 1;
        self.line_start = self.pos;
        true
    }

    /// `---` or `...` followed by a blank at the current position.
    fn at_document_separator(&self) -> bool {
        let a = self.peek(0);
        (a == b'-' || a == b'.') && self.peek(1) == a && self.peek(2) == a && is_blankz(self.peek(3))
    }

    pub fn error_at(&self, mark: Mark, message: String) -> YamlError {
        YamlError { line: mark.line + 1, col: mark.col + 1, message }
    }

    fn err<T>(&mut self, message: String) -> Result<T, YamlError> {
        let m = self.mark();
        Err(self.error_at(m, message))
    }

    // ----- token queue -------------------------------------------------------

    /// The next token without consuming it.
    pub fn peek_token(&mut self) -> Result<&Token, YamlError> {
        while self.need_more_tokens()? {
            self.fetch_more_tokens()?;
        }
        match self.tokens.front() {
            Some(t) => Ok(t),
            None => Err(YamlError { line: self.line + 1, col: 1, message: "internal error: no token".into() }),
        }
    }

    pub fn peek_kind(&mut self) -> Result<Kind, YamlError> {
        Ok(self.peek_token()?.kind)
    }

    /// Tokens already queued behind the next one (no scanning; for messages).
    pub fn queued(&self, i: usize) -> Option<&Token> {
        self.tokens.get(i)
    }

    /// Consumes and returns the next token.
    pub fn next_token(&mut self) -> Result<Token, YamlError> {
        while self.need_more_tokens()? {
            self.fetch_more_tokens()?;
        }
        match self.tokens.pop_front() {
            Some(t) => {
                self.tokens_taken += 1;
                Ok(t)
            }
            None => Err(YamlError { line: self.line + 1, col: 1, message: "internal error: no token".into() }),
        }
    }

    fn need_more_tokens(&mut self) -> Result<bool, YamlError> {
        if self.done {
            return Ok(false);
        }
        if self.tokens.is_empty() {
            return Ok(true);
        }
        if self.active_keys == 0 {
            return Ok(false);
        }
        self.stale_possible_simple_keys()?;
        Ok(self.next_possible_simple_key() == Some(self.tokens_taken))
    }

    fn fetch_more_tokens(&mut self) -> Result<(), YamlError> {
        let prev_plain = self.prev_plain.take();
        self.scan_to_next_token();
        self.stale_possible_simple_keys()?;
        let col = self.column();
        self.unwind_indent(col as i64);
        let ch = self.peek(0);
        match ch {
            0 => return self.fetch_stream_end(),
            b'%' if col == 0 => {
                return self.err("directives ('%YAML', '%TAG') are not supported".into());
            }
            b'-' if col == 0 && self.at_document_separator() => return self.fetch_document_indicator(Kind::DocStart),
            b'.' if col == 0 && self.at_document_separator() => return self.fetch_document_indicator(Kind::DocEnd),
            b'[' => return self.fetch_flow_collection_start(Kind::FlowSeqStart),
            b'{' => return self.fetch_flow_collection_start(Kind::FlowMapStart),
            b']' => return self.fetch_flow_collection_end(Kind::FlowSeqEnd),
            b'}' => return self.fetch_flow_collection_end(Kind::FlowMapEnd),
            b',' => return self.fetch_flow_entry(),
            b'-' if is_blankz(self.peek(1)) => return self.fetch_block_entry(),
            b'?' if self.flow_level > 0 || is_blankz(self.peek(1)) => {
                return self.err("explicit mapping keys ('? key') are not supported; write 'key: value'".into());
            }
            b':' if self.flow_level > 0 || is_blankz(self.peek(1)) => return self.fetch_value(prev_plain),
            b'*' => return self.err("aliases ('*name') are not supported".into()),
            b'&' => return self.err("anchors ('&name') are not supported".into()),
            b'!' => return self.err("tags ('!tag', '!!type') are not supported; quote the value to make it a string".into()),
            b'|' | b'>' if self.flow_level == 0 => {
                return self.err(format!("block scalars ('{}') are not supported; use a quoted string", ch as char));
            }
            b'\'' => return self.fetch_flow_scalar(Style::Single),
            b'"' => return self.fetch_flow_scalar(Style::Double),
            _ => {}
        }
        if self.check_plain() {
            return self.fetch_plain();
        }
        let msg = match ch {
            b'\t' => "found a tab character where a token was expected; YAML (as PyYAML reads it) allows tabs only inside quoted strings and comments: use spaces".to_string(),
            b'@' | b'`' => format!("'{}' is reserved and cannot start a plain value; quote the value", ch as char),
            b'#' => "'#' cannot start a value here; quote the value".to_string(),
            b'-' | b':' => format!("'{}' cannot start a value here; quote the value", ch as char),
            _ => {
                let c = self.text.get(self.pos..).and_then(|s| s.chars().next()).unwrap_or('?');
                format!("found character {:?} that cannot start any token", c)
            }
        };
        self.err(msg)
    }

    // ----- simple keys -------------------------------------------------------

    fn next_possible_simple_key(&self) -> Option<usize> {
        self.possible_keys.iter().flatten().map(|k| k.token_number).min()
    }

    fn stale_possible_simple_keys(&mut self) -> Result<(), YamlError> {
        if self.active_keys == 0 {
            return Ok(());
        }
        for level in 0..self.possible_keys.len() {
            if let Some(key) = self.possible_keys[level] {
                let stale =
                    key.mark.line != self.line || (self.pos - key.mark.pos > 1024 && self.chars_between(key.mark.pos, self.pos) > 1024);
                if stale {
                    if key.required {
                        return Err(self.missing_colon_error(key));
                    }
                    self.possible_keys[level] = None;
                    self.active_keys -= 1;
                }
            }
        }
        Ok(())
    }

    fn save_possible_simple_key(&mut self) -> Result<(), YamlError> {
        let mark = self.mark();
        let required = self.flow_level == 0 && self.indent == mark.col as i64;
        if self.allow_simple_key {
            self.remove_possible_simple_key()?;
            let token_number = self.tokens_taken + self.tokens.len();
            self.possible_keys[self.flow_level] = Some(SimpleKey { token_number, required, mark });
            self.active_keys += 1;
        }
        Ok(())
    }

    fn remove_possible_simple_key(&mut self) -> Result<(), YamlError> {
        if let Some(key) = self.possible_keys[self.flow_level] {
            if key.required {
                return Err(self.missing_colon_error(key));
            }
            self.possible_keys[self.flow_level] = None;
            self.active_keys -= 1;
        }
        Ok(())
    }

    /// PyYAML's "could not find expected ':'", phrased for people: a line at the
    /// indentation of a block collection that is neither `key: value` nor `- item`.
    fn missing_colon_error(&self, key: SimpleKey) -> YamlError {
        let idx = key.token_number.wrapping_sub(self.tokens_taken);
        let tok = self.tokens.get(idx);
        let (what, at) = match tok {
            Some(t) if t.kind == Kind::Scalar => {
                let s = match &t.text {
                    Text::Owned(s) => s.as_str(),
                    Text::Span(a, b) => self.text.get(*a..*b).unwrap_or(""),
                    Text::None => "",
                };
                (Some(s.to_string()), t.end)
            }
            Some(t) => (None, t.end),
            None => (None, key.mark),
        };
        let shown = what.as_deref().map(short_quote);
        let message = if self.cur_is_map || self.indent < 0 {
            match shown {
                Some(s) => {
                    let mut m = format!("expected ':' after mapping key {}", s);
                    if let Some(w) = &what {
                        if w.contains(':') {
                            m.push_str(" (a ':' only separates key and value when followed by a space)");
                        }
                    }
                    m
                }
                None => "expected ':' after this mapping key".to_string(),
            }
        } else {
            match shown {
                Some(s) => format!(
                    "expected a sequence entry ('- ') at this indentation, found {}; indent it further to continue the previous item",
                    s
                ),
                None => "expected a sequence entry ('- ') at this indentation".to_string(),
            }
        };
        self.error_at(at, message)
    }

    /// Explains a ':' that has no key before it. The usual causes: a plain value
    /// containing ': ', a line indented so deep that it continues the previous
    /// value, or a missing closing bracket.
    fn no_key_error(&mut self, prev_plain: Option<(Mark, usize)>) -> YamlError {
        let m = self.mark();
        if let Some((b, om)) = self.innermost_open_flow() {
            return self.error_at(
                m,
                format!(
                    "unexpected ':' inside the '{}' opened at line {}, column {}; is the closing '{}' missing?",
                    b as char,
                    om.line + 1,
                    om.col + 1,
                    if b == b'[' { ']' } else { '}' }
                ),
            );
        }
        if let Some((start, end)) = prev_plain.filter(|(st, _)| st.line < self.line) {
            // Show the value's first line only.
            let raw = self.text.get(start.pos..end).unwrap_or("");
            let first = raw.split(['\n', '\r']).next().unwrap_or("");
            return self.error_at(
                m,
                format!(
                    "mapping values are not allowed here: this line continues the plain value {} started at line {}, column {} (a line indented deeper than its mapping's keys continues the value above); check the indentation, or whether line {} is missing a ':'",
                    short_quote(first),
                    start.line + 1,
                    start.col + 1,
                    start.line + 1
                ),
            );
        }
        if self.flow_level == 0 && !self.allow_simple_key {
            return self.error_at(
                m,
                "mapping values are not allowed here (a plain value cannot contain ': '; quote the value, or put the nested mapping on its own line)".into(),
            );
        }
        self.error_at(m, "found ':' without a mapping key before it".into())
    }

    // ----- indentation -------------------------------------------------------

    fn unwind_indent(&mut self, col: i64) {
        if self.flow_level > 0 {
            return;
        }
        while self.indent > col {
            let m = Mark { pos: self.pos, line: self.line, col: col.max(0) as u32 };
            self.indent = self.indents.pop().unwrap_or(-1);
            self.cur_is_map = self.indent_is_map.pop().unwrap_or(false);
            self.tokens.push_back(Token::simple(Kind::BlockEnd, m, m));
        }
    }

    fn add_indent(&mut self, col: i64, is_map: bool) -> bool {
        if self.indent < col {
            self.indents.push(self.indent);
            self.indent_is_map.push(self.cur_is_map);
            self.indent = col;
            self.cur_is_map = is_map;
            true
        } else {
            false
        }
    }

    // ----- fetchers ----------------------------------------------------------

    fn fetch_stream_end(&mut self) -> Result<(), YamlError> {
        self.unwind_indent(-1);
        self.remove_possible_simple_key()?;
        self.allow_simple_key = false;
        for k in self.possible_keys.iter_mut() {
            *k = None;
        }
        self.active_keys = 0;
        let m = self.mark();
        self.tokens.push_back(Token::simple(Kind::StreamEnd, m, m));
        self.done = true;
        Ok(())
    }

    fn fetch_document_indicator(&mut self, kind: Kind) -> Result<(), YamlError> {
        self.unwind_indent(-1);
        self.remove_possible_simple_key()?;
        self.allow_simple_key = false;
        let start = self.mark();
        self.pos += 3;
        let end = self.mark();
        self.tokens.push_back(Token::simple(kind, start, end));
        Ok(())
    }

    fn fetch_flow_collection_start(&mut self, kind: Kind) -> Result<(), YamlError> {
        self.save_possible_simple_key()?;
        if self.flow_level >= MAX_DEPTH {
            return self.err(format!("nesting deeper than {} levels is not supported", MAX_DEPTH));
        }
        self.flow_level += 1;
        self.possible_keys.push(None);
        self.allow_simple_key = true;
        let start = self.mark();
        self.open_flows.push((self.peek(0), start));
        self.pos += 1;
        let end = self.mark();
        self.tokens.push_back(Token::simple(kind, start, end));
        Ok(())
    }

    fn fetch_flow_collection_end(&mut self, kind: Kind) -> Result<(), YamlError> {
        let ch = self.peek(0) as char;
        if self.flow_level == 0 {
            // PyYAML's parser rejects a stray closing bracket wherever it is.
            return self.err(format!("unexpected '{}' without a matching '{}'", ch, if ch == ']' { '[' } else { '{' }));
        }
        self.remove_possible_simple_key()?;
        self.possible_keys.pop();
        self.flow_level -= 1;
        self.open_flows.pop();
        self.allow_simple_key = false;
        let start = self.mark();
        self.pos += 1;
        let end = self.mark();
        self.tokens.push_back(Token::simple(kind, start, end));
        Ok(())
    }

    fn fetch_flow_entry(&mut self) -> Result<(), YamlError> {
        self.allow_simple_key = true;
        self.remove_possible_simple_key()?;
        let start = self.mark();
        self.pos += 1;
        let end = self.mark();
        self.tokens.push_back(Token::simple(Kind::FlowEntry, start, end));
        Ok(())
    }

    fn fetch_block_entry(&mut self) -> Result<(), YamlError> {
        if self.flow_level == 0 {
            if !self.allow_simple_key {
                return self.err(
                    "a sequence entry ('- ') is not allowed here; it must start its own line (or follow '- ' or 'key:' on a new line)"
                        .into(),
                );
            }
            let m = self.mark();
            if self.add_indent(m.col as i64, false) {
                self.tokens.push_back(Token::simple(Kind::BlockSeqStart, m, m));
            }
        } else {
            // PyYAML's parser rejects block entries inside flow collections.
            return self.err("'- ' sequence entries are not allowed inside '[...]' or '{...}'; separate items with ','".into());
        }
        self.allow_simple_key = true;
        self.remove_possible_simple_key()?;
        let start = self.mark();
        self.pos += 1;
        let end = self.mark();
        self.tokens.push_back(Token::simple(Kind::BlockEntry, start, end));
        Ok(())
    }

    fn fetch_value(&mut self, prev_plain: Option<(Mark, usize)>) -> Result<(), YamlError> {
        if let Some(key) = self.possible_keys[self.flow_level].take() {
            self.active_keys -= 1;
            let idx = key.token_number - self.tokens_taken;
            self.tokens.insert(idx, Token::simple(Kind::Key, key.mark, key.mark));
            if self.flow_level == 0 && self.add_indent(key.mark.col as i64, true) {
                self.tokens.insert(idx, Token::simple(Kind::BlockMapStart, key.mark, key.mark));
            }
            self.allow_simple_key = false;
        } else {
            // A ':' with no key before it on the same line. PyYAML either fails
            // here or (without '?' keys, which we do not support) in its parser.
            return Err(self.no_key_error(prev_plain));
        }
        let start = self.mark();
        self.pos += 1;
        let end = self.mark();
        self.tokens.push_back(Token::simple(Kind::Value, start, end));
        Ok(())
    }

    fn fetch_flow_scalar(&mut self, style: Style) -> Result<(), YamlError> {
        self.save_possible_simple_key()?;
        self.allow_simple_key = false;
        let tok = self.scan_flow_scalar(style)?;
        self.tokens.push_back(tok);
        Ok(())
    }

    fn fetch_plain(&mut self) -> Result<(), YamlError> {
        self.save_possible_simple_key()?;
        self.allow_simple_key = false;
        let tok = self.scan_plain();
        self.prev_plain = Some((tok.start, tok.end.pos));
        self.tokens.push_back(tok);
        Ok(())
    }

    /// PyYAML `check_plain`: may a plain scalar start here?
    fn check_plain(&self) -> bool {
        let ch = self.peek(0);
        let indicator = matches!(
            ch,
            0 | b' '
                | b'\t'
                | b'\r'
                | b'\n'
                | b'-'
                | b'?'
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
        );
        !indicator || (!is_blankz(self.peek(1)) && (ch == b'-' || (self.flow_level == 0 && (ch == b'?' || ch == b':'))))
    }

    // ----- scanners ----------------------------------------------------------

    /// Skips spaces, comments and line breaks (not tabs, exactly like PyYAML).
    fn scan_to_next_token(&mut self) {
        if self.pos == 0 && self.src.starts_with(&[0xEF, 0xBB, 0xBF]) {
            self.pos = 3;
            self.line_start = 3;
        }
        loop {
            while self.peek(0) == b' ' {
                self.pos += 1;
            }
            if self.peek(0) == b'#' {
                while !matches!(self.peek(0), 0 | b'\r' | b'\n') {
                    self.pos += 1;
                }
            }
            if self.scan_line_break() {
                if self.flow_level == 0 {
                    self.allow_simple_key = true;
                }
            } else {
                break;
            }
        }
    }

    fn scan_plain(&mut self) -> Token {
        let start = self.mark();
        let mut end = start;
        let indent = self.indent + 1;
        let flow = self.flow_level > 0;
        let mut buf = TextBuf::new();
        let mut spaces = Spaces::End;
        loop {
            if self.peek(0) == b'#' {
                break;
            }
            let mut len = 0;
            loop {
                let ch = self.peek(len);
                let c = CLASS[ch as usize];
                if c != 0 {
                    if c & 1 != 0 {
                        break;
                    }
                    if c & 2 != 0 {
                        let n = self.peek(len + 1);
                        if is_blankz(n) || (flow && matches!(n, b',' | b'[' | b']' | b'{' | b'}')) {
                            break;
                        }
                    } else if flow {
                        break;
                    }
                }
                len += 1;
            }
            if len == 0 {
                break;
            }
            self.allow_simple_key = false;
            match spaces {
                Spaces::End => {}
                Spaces::Inline(a, b) => buf.push_span(self.text, a, b),
                Spaces::Fold => buf.push_char(self.text, ' '),
                Spaces::Breaks(n) => buf.push_newlines(self.text, n),
            }
            buf.push_span(self.text, self.pos, self.pos + len);
            self.pos += len;
            end = self.mark();
            spaces = self.scan_plain_spaces();
            if matches!(spaces, Spaces::End) || self.peek(0) == b'#' {
                break;
            }
            if !flow && (self.column() as i64) < indent {
                break;
            }
        }
        Token { kind: Kind::Scalar, start, end, style: Style::Plain, text: buf.finish() }
    }

    fn scan_plain_spaces(&mut self) -> Spaces {
        let a = self.pos;
        while self.peek(0) == b' ' {
            self.pos += 1;
        }
        let b = self.pos;
        if is_break(self.peek(0)) {
            self.scan_line_break();
            self.allow_simple_key = true;
            if self.at_document_separator() {
                return Spaces::End;
            }
            let mut breaks = 0;
            loop {
                match self.peek(0) {
                    b' ' => self.pos += 1,
                    b'\r' | b'\n' => {
                        self.scan_line_break();
                        breaks += 1;
                        if self.at_document_separator() {
                            return Spaces::End;
                        }
                    }
                    _ => break,
                }
            }
            if breaks == 0 { Spaces::Fold } else { Spaces::Breaks(breaks) }
        } else if b > a {
            Spaces::Inline(a, b)
        } else {
            Spaces::End
        }
    }

    fn scan_flow_scalar(&mut self, style: Style) -> Result<Token, YamlError> {
        let double = style == Style::Double;
        let start = self.mark();
        let quote = self.peek(0);
        self.pos += 1;
        let mut buf = TextBuf::new();
        self.scan_flow_scalar_non_spaces(double, &mut buf, start)?;
        while self.peek(0) != quote {
            self.scan_flow_scalar_spaces(double, &mut buf, start)?;
            self.scan_flow_scalar_non_spaces(double, &mut buf, start)?;
        }
        self.pos += 1;
        let end = self.mark();
        Ok(Token { kind: Kind::Scalar, start, end, style, text: buf.finish() })
    }

    fn scan_flow_scalar_non_spaces(&mut self, double: bool, buf: &mut TextBuf, start: Mark) -> Result<(), YamlError> {
        loop {
            let mut len = 0;
            while !matches!(self.peek(len), b'\'' | b'"' | b'\\' | 0 | b' ' | b'\t' | b'\r' | b'\n') {
                len += 1;
            }
            if len > 0 {
                buf.push_span(self.text, self.pos, self.pos + len);
                self.pos += len;
            }
            let ch = self.peek(0);
            if !double && ch == b'\'' && self.peek(1) == b'\'' {
                buf.push_span(self.text, self.pos, self.pos + 1);
                self.pos += 2;
            } else if (double && ch == b'\'') || (!double && (ch == b'"' || ch == b'\\')) {
                buf.push_span(self.text, self.pos, self.pos + 1);
                self.pos += 1;
            } else if double && ch == b'\\' {
                self.pos += 1;
                let e = self.peek(0);
                let rep = match e {
                    b'0' => Some('\0'),
                    b'a' => Some('\x07'),
                    b'b' => Some('\x08'),
                    b't' | b'\t' => Some('\t'),
                    b'n' => Some('\n'),
                    b'v' => Some('\x0B'),
                    b'f' => Some('\x0C'),
                    b'r' => Some('\r'),
                    b'e' => Some('\x1B'),
                    b' ' => Some(' '),
                    b'"' => Some('"'),
                    b'\\' => Some('\\'),
                    b'/' => Some('/'),
                    b'N' => Some('\u{85}'),
                    b'_' => Some('\u{A0}'),
                    b'L' => Some('\u{2028}'),
                    b'P' => Some('\u{2029}'),
                    _ => None,
                };
                if let Some(c) = rep {
                    buf.push_char(self.text, c);
                    self.pos += 1;
                } else if matches!(e, b'x' | b'u' | b'U') {
                    let n = match e {
                        b'x' => 2,
                        b'u' => 4,
                        _ => 8,
                    };
                    self.pos += 1;
                    let mut code: u32 = 0;
                    for k in 0..n {
                        let h = self.peek(k);
                        let d = match h {
                            b'0'..=b'9' => h - b'0',
                            b'a'..=b'f' => h - b'a' + 10,
                            b'A'..=b'F' => h - b'A' + 10,
                            _ => {
                                self.pos += k;
                                return self.err(format!(
                                    "invalid escape in double-quoted string (started at line {}, column {}): expected {} hexadecimal digits after '\\{}'",
                                    start.line + 1,
                                    start.col + 1,
                                    n,
                                    e as char
                                ));
                            }
                        };
                        code = code.wrapping_mul(16).wrapping_add(d as u32);
                    }
                    match char::from_u32(code) {
                        Some(c) => buf.push_char(self.text, c),
                        None => {
                            return self.err(format!(
                                "escape '\\{}{}' is not a valid Unicode character (surrogates and values above 10FFFF are not supported)",
                                e as char,
                                self.text.get(self.pos..self.pos + n).unwrap_or("")
                            ));
                        }
                    }
                    self.pos += n;
                } else if is_break(e) {
                    self.scan_line_break();
                    let n = self.scan_flow_scalar_breaks(start)?;
                    buf.push_newlines(self.text, n);
                } else {
                    let c = self.text.get(self.pos..).and_then(|s| s.chars().next());
                    return match c {
                        None => self.unterminated(double, start),
                        Some(c) => self.err(format!(
                            "unknown escape '\\{}' in double-quoted string (started at line {}, column {}); write '\\\\' for a backslash",
                            c,
                            start.line + 1,
                            start.col + 1
                        )),
                    };
                }
            } else {
                return Ok(());
            }
        }
    }

    fn unterminated<T>(&mut self, double: bool, start: Mark) -> Result<T, YamlError> {
        Err(self.error_at(
            start,
            format!(
                "unterminated {} string: no closing {} before the end of the input",
                if double { "double-quoted" } else { "single-quoted" },
                if double { "'\"'" } else { "\"'\"" }
            ),
        ))
    }

    fn scan_flow_scalar_spaces(&mut self, double: bool, buf: &mut TextBuf, start: Mark) -> Result<(), YamlError> {
        let a = self.pos;
        while matches!(self.peek(0), b' ' | b'\t') {
            self.pos += 1;
        }
        let b = self.pos;
        let ch = self.peek(0);
        if ch == 0 {
            return self.unterminated(double, start);
        } else if is_break(ch) {
            self.scan_line_break();
            let n = self.scan_flow_scalar_breaks(start)?;
            if n == 0 {
                buf.push_char(self.text, ' ');
            } else {
                buf.push_newlines(self.text, n);
            }
        } else {
            buf.push_span(self.text, a, b);
        }
        Ok(())
    }

    fn scan_flow_scalar_breaks(&mut self, start: Mark) -> Result<usize, YamlError> {
        let mut n = 0;
        loop {
            if self.at_document_separator() {
                return self.err(format!(
                    "found a document separator ('---' or '...') inside the quoted string started at line {}, column {}",
                    start.line + 1,
                    start.col + 1
                ));
            }
            while matches!(self.peek(0), b' ' | b'\t') {
                self.pos += 1;
            }
            if self.scan_line_break() {
                n += 1;
            } else {
                return Ok(n);
            }
        }
    }

    /// The innermost unclosed `[` or `{`, if any (for end-of-input messages).
    pub fn innermost_open_flow(&self) -> Option<(u8, Mark)> {
        self.open_flows.last().copied()
    }
}

/// A scalar shown in a message: double-quoted, shortened if long.
pub(crate) fn short_quote(s: &str) -> String {
    let mut out = String::from("\"");
    for (i, c) in s.chars().enumerate() {
        if i >= 40 {
            out.push_str("...");
            break;
        }
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\x{:02X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Checks the characters PyYAML's reader accepts (printable ones, tab and line
/// breaks). The Unicode line breaks NEL/LS/PS, which PyYAML treats as line
/// breaks, are refused as unsupported.
///
/// Returns `true` when the text is "clean": only printable ASCII and `\n`
/// (no tabs, no `\r`, no non-ASCII), which lets the fast path skip per-line
/// checks. The clean test is written so that the compiler vectorizes it.
pub(crate) fn check_characters(text: &str) -> Result<bool, YamlError> {
    let bytes = text.as_bytes();
    // A plain reduction over contiguous bytes, which LLVM turns into SIMD.
    let mut bad = 0u8;
    for &b in bytes {
        bad |= (((b < 0x20) & (b != b'\n')) | (b >= 0x7F)) as u8;
    }
    let clean = bad == 0;
    if clean {
        return Ok(true);
    }
    check_slow(text, 0, bytes.len())?;
    Ok(false)
}

fn check_slow(text: &str, from: usize, to: usize) -> Result<(), YamlError> {
    let bytes = text.as_bytes();
    let mut i = from;
    while i < to {
        let b = bytes[i];
        if b < 0x80 {
            if !(b.wrapping_sub(0x20) < 0x5F || b == b'\n' || b == b'\r' || b == b'\t') {
                return Err(char_error(text, i, b as char));
            }
            i += 1;
            continue;
        }
        if b & 0xC0 == 0x80 {
            // Continuation byte of a character that started in the previous chunk.
            i += 1;
            continue;
        }
        let c = match text.get(i..).and_then(|s| s.chars().next()) {
            Some(c) => c,
            None => return Err(char_error(text, i, '\u{FFFD}')),
        };
        let u = c as u32;
        let ok = (0xA0..=0xD7FF).contains(&u) || (0xE000..=0xFFFD).contains(&u) || u >= 0x10000;
        if u == 0x85 || u == 0x2028 || u == 0x2029 {
            let (line, col) = line_col(text, i);
            return Err(YamlError {
                line,
                col,
                message: format!("the Unicode line break U+{:04X} is not supported; use '\\n' line breaks", u),
            });
        }
        if !ok {
            return Err(char_error(text, i, c));
        }
        i += c.len_utf8();
    }
    Ok(())
}

fn char_error(text: &str, pos: usize, c: char) -> YamlError {
    let (line, col) = line_col(text, pos);
    YamlError {
        line,
        col,
        message: format!("special character U+{:04X} is not allowed in YAML (only printable characters, tabs and line breaks)", c as u32),
    }
}

/// 1-based line and character column of a byte position (slow; errors only).
pub(crate) fn line_col(text: &str, pos: usize) -> (u32, u32) {
    let bytes = &text.as_bytes()[..pos.min(text.len())];
    let mut line = 1u32;
    let mut start = 0usize;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'\n' => {
                line += 1;
                start = i + 1;
            }
            b'\r' if bytes.get(i + 1) != Some(&b'\n') => {
                line += 1;
                start = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    let col = bytes[start..].iter().filter(|&&b| b & 0xC0 != 0x80).count() as u32 + 1;
    (line, col)
}
