//! Parser: tokens to a [`Node`] tree, following PyYAML's `parser.py` states
//! (implicit/explicit document, indentless sequences as mapping values, empty
//! values, single-pair mappings inside flow sequences) and `composer.py`
//! (exactly one document), with YAML 1.1 resolution of plain scalars.
//!
//! Also turns PyYAML's terse parser errors (`expected <block end>, but found
//! '<block mapping start>'`) into messages about what is wrong in the file.

use crate::parity::yaml::node::{Node, Value, YamlError, keys_equal};
use crate::parity::yaml::resolve::{Resolved, resolve_plain};
use crate::parity::yaml::scanner::{Kind, MAX_DEPTH, Mark, Scanner, Style, Text, Token, check_characters, short_quote};

pub(crate) fn parse(text: &str) -> Result<Node, YamlError> {
    let clean = check_characters(text)?;
    if let Some(node) = crate::parity::yaml::fast::parse_fast(text, clean) {
        return Ok(node);
    }
    parse_full(text)
}

/// The PyYAML-faithful parser alone (no fast path); also used by tests to
/// check that both paths agree.
pub(crate) fn parse_full(text: &str) -> Result<Node, YamlError> {
    check_characters(text)?;
    let mut p = Parser { s: Scanner::new(text), depth: 0, block_cols: Vec::new(), last_closed_col: None };
    p.parse_stream()
}

struct Parser<'a> {
    s: Scanner<'a>,
    depth: usize,
    /// Columns (0-based) and kinds of the open block collections, for indentation messages.
    block_cols: Vec<(u32, bool)>,
    /// Column of the block collection that ended last (the "nested block above").
    last_closed_col: Option<u32>,
}

fn node_at(value: Value, m: Mark) -> Node {
    Node { value, line: m.line + 1, col: m.col + 1 }
}

impl<'a> Parser<'a> {
    fn error(&self, m: Mark, message: String) -> YamlError {
        self.s.error_at(m, message)
    }

    fn parse_stream(&mut self) -> Result<Node, YamlError> {
        let first = self.s.peek_kind()?;
        let mut doc: Option<Node> = None;
        if first != Kind::DocStart && first != Kind::StreamEnd {
            // Implicit document.
            doc = Some(self.parse_node(true, false)?);
            self.parse_document_end()?;
        }
        loop {
            while self.s.peek_kind()? == Kind::DocEnd {
                self.s.next_token()?;
            }
            let t = self.s.peek_token()?;
            match t.kind {
                Kind::StreamEnd => break,
                Kind::DocStart => {
                    let m = t.start;
                    if doc.is_some() {
                        return Err(
                            self.error(m, "a second document ('---') is not supported: a file must hold exactly one document".into())
                        );
                    }
                    self.s.next_token()?;
                    let k = self.s.peek_kind()?;
                    let node = if matches!(k, Kind::DocStart | Kind::DocEnd | Kind::StreamEnd) {
                        let m = self.s.peek_token()?.start;
                        node_at(Value::Null, m)
                    } else {
                        self.parse_node(true, false)?
                    };
                    doc = Some(node);
                    self.parse_document_end()?;
                }
                _ => {
                    let m = t.start;
                    let what = self.describe_next();
                    return Err(self.error(m, format!("expected the end of the input after the document end marker '...', found {}", what)));
                }
            }
        }
        Ok(doc.unwrap_or(Node { value: Value::Null, line: 1, col: 1 }))
    }

    fn parse_document_end(&mut self) -> Result<(), YamlError> {
        if self.s.peek_kind()? == Kind::DocEnd {
            self.s.next_token()?;
        }
        Ok(())
    }

    /// PyYAML `parse_node`: a scalar, a flow collection, or (in block context) a
    /// block collection; `indentless` allows a `- ` sequence at the key's indentation.
    fn parse_node(&mut self, block: bool, indentless: bool) -> Result<Node, YamlError> {
        let t = self.s.peek_token()?;
        let kind = t.kind;
        let start = t.start;
        if indentless && kind == Kind::BlockEntry {
            return self.nested(|p| p.parse_indentless_sequence(start));
        }
        match kind {
            Kind::Scalar => {
                let tok = self.s.next_token()?;
                self.scalar(tok, false)
            }
            Kind::FlowSeqStart => self.nested(|p| p.parse_flow_sequence()),
            Kind::FlowMapStart => self.nested(|p| p.parse_flow_mapping()),
            Kind::BlockSeqStart if block => self.nested(|p| p.parse_block_sequence()),
            Kind::BlockMapStart if block => self.nested(|p| p.parse_block_mapping()),
            _ => Err(self.unexpected_in_node()),
        }
    }

    fn nested<F: FnOnce(&mut Self) -> Result<Node, YamlError>>(&mut self, f: F) -> Result<Node, YamlError> {
        if self.depth >= MAX_DEPTH {
            let m = self.s.peek_token()?.start;
            return Err(self.error(m, format!("nesting deeper than {} levels is not supported", MAX_DEPTH)));
        }
        self.depth += 1;
        let r = f(self);
        self.depth -= 1;
        r
    }

    fn scalar(&mut self, tok: Token, is_key: bool) -> Result<Node, YamlError> {
        let src = self.s.source();
        let m = tok.start;
        let value = match (tok.style, tok.text) {
            (Style::Plain, Text::Owned(s)) => match self.resolve(&s, m, is_key)? {
                Some(v) => v,
                None => Value::Str(s),
            },
            (Style::Plain, Text::Span(a, b)) => {
                let s = src.get(a..b).unwrap_or("");
                match self.resolve(s, m, is_key)? {
                    Some(v) => v,
                    None => Value::Str(s.to_string()),
                }
            }
            (_, Text::Owned(s)) => Value::Str(s),
            (_, Text::Span(a, b)) => Value::Str(src.get(a..b).unwrap_or("").to_string()),
            (_, Text::None) => Value::Null,
        };
        Ok(node_at(value, m))
    }

    /// YAML 1.1 implicit typing of a plain scalar; `None` means "a string".
    fn resolve(&self, s: &str, m: Mark, is_key: bool) -> Result<Option<Value>, YamlError> {
        Ok(Some(match resolve_plain(s) {
            Resolved::Null => Value::Null,
            Resolved::Bool(b) => Value::Bool(b),
            Resolved::Int(i) => Value::Int(i),
            Resolved::Float(f) => Value::Float(f),
            Resolved::Str => return Ok(None),
            // PyYAML turns a plain `=` key into the string "=" but rejects it as a value.
            Resolved::ValueKey if is_key => return Ok(None),
            Resolved::ValueKey => {
                return Err(self.error(m, "a plain '=' value is not allowed (PyYAML rejects it); quote it: '='".into()));
            }
            Resolved::Merge => {
                return Err(self.error(m, "merge keys ('<<') are not supported; quote it ('<<') for a plain string".into()));
            }
            Resolved::Timestamp => {
                return Err(self.error(
                    m,
                    format!("timestamps are not supported: {} would be read as a date; quote it to make it a string", short_quote(s)),
                ));
            }
            Resolved::IntOutOfRange => {
                return Err(self.error(m, format!("integer {} is out of the supported range (64-bit)", short_quote(s))));
            }
            Resolved::BadInt => {
                return Err(self.error(m, format!("invalid integer {} (no digits)", short_quote(s))));
            }
        }))
    }

    fn empty(&self, m: Mark) -> Node {
        node_at(Value::Null, m)
    }

    // ----- block collections -------------------------------------------------

    fn parse_block_sequence(&mut self) -> Result<Node, YamlError> {
        let open = self.s.next_token()?.start; // BLOCK-SEQUENCE-START
        self.block_cols.push((open.col, false));
        let mut items = Vec::new();
        loop {
            let t = self.s.peek_token()?;
            if t.kind != Kind::BlockEntry {
                break;
            }
            let entry = self.s.next_token()?;
            let k = self.s.peek_kind()?;
            if k == Kind::BlockEntry || k == Kind::BlockEnd {
                items.push(self.empty(entry.end));
            } else {
                items.push(self.parse_node(true, false)?);
            }
        }
        if self.s.peek_kind()? != Kind::BlockEnd {
            return Err(self.unexpected_in_block(open, false));
        }
        self.s.next_token()?;
        self.block_cols.pop();
        self.last_closed_col = Some(open.col);
        Ok(node_at(Value::Seq(items), open))
    }

    /// A `- item` sequence used as a mapping value at the key's indentation.
    fn parse_indentless_sequence(&mut self, open: Mark) -> Result<Node, YamlError> {
        let mut items = Vec::new();
        while self.s.peek_kind()? == Kind::BlockEntry {
            let entry = self.s.next_token()?;
            let k = self.s.peek_kind()?;
            if matches!(k, Kind::BlockEntry | Kind::Key | Kind::Value | Kind::BlockEnd) {
                items.push(self.empty(entry.end));
            } else {
                items.push(self.parse_node(true, false)?);
            }
        }
        Ok(node_at(Value::Seq(items), open))
    }

    fn parse_block_mapping(&mut self) -> Result<Node, YamlError> {
        let open = self.s.next_token()?.start; // BLOCK-MAPPING-START
        self.block_cols.push((open.col, true));
        let mut pairs: Vec<(Node, Node)> = Vec::new();
        let mut index = KeyIndex::default();
        loop {
            if self.s.peek_kind()? != Kind::Key {
                break;
            }
            let key_tok = self.s.next_token()?;
            let k = self.s.peek_kind()?;
            let key = if matches!(k, Kind::Key | Kind::Value | Kind::BlockEnd) { self.empty(key_tok.end) } else { self.parse_key(true)? };
            let value = if self.s.peek_kind()? == Kind::Value {
                let v = self.s.next_token()?;
                let k = self.s.peek_kind()?;
                if matches!(k, Kind::Key | Kind::Value | Kind::BlockEnd) { self.empty(v.end) } else { self.parse_node(true, true)? }
            } else {
                let m = self.s.peek_token()?.start;
                self.empty(m)
            };
            self.push_pair(&mut pairs, &mut index, key, value)?;
        }
        if self.s.peek_kind()? != Kind::BlockEnd {
            return Err(self.unexpected_in_block(open, true));
        }
        self.s.next_token()?;
        self.block_cols.pop();
        self.last_closed_col = Some(open.col);
        Ok(node_at(Value::Map(pairs), open))
    }

    /// A mapping key: must be a scalar (PyYAML fails on unhashable keys).
    fn parse_key(&mut self, block: bool) -> Result<Node, YamlError> {
        let t = self.s.peek_token()?;
        if t.kind == Kind::Scalar {
            let tok = self.s.next_token()?;
            return self.scalar(tok, true);
        }
        let m = t.start;
        let node = self.parse_node(block, block)?;
        Err(self.error(m, format!("a {} cannot be a mapping key (keys must be scalars)", node.value.type_name())))
    }

    /// Appends a pair, refusing duplicate keys (PyYAML would silently keep the
    /// last value). Keys compare like Python dict keys: `1`, `1.0` and `true` are equal.
    fn push_pair(&self, pairs: &mut Vec<(Node, Node)>, index: &mut KeyIndex, key: Node, value: Node) -> Result<(), YamlError> {
        if let Some((first, _)) = index.find(pairs, &key) {
            let shown = match &key.value {
                Value::Str(s) => short_quote(s),
                Value::Null => "null".to_string(),
                Value::Bool(b) => b.to_string(),
                Value::Int(i) => i.to_string(),
                Value::Float(f) => format!("{:?}", f),
                _ => "?".to_string(),
            };
            let m = Mark { pos: 0, line: key.line.saturating_sub(1), col: key.col.saturating_sub(1) };
            return Err(
                self.error(m, format!("duplicate mapping key {} (first defined on line {}, column {})", shown, first.line, first.col))
            );
        }
        index.add(pairs.len(), &key);
        pairs.push((key, value));
        Ok(())
    }

    // ----- flow collections --------------------------------------------------

    fn parse_flow_sequence(&mut self) -> Result<Node, YamlError> {
        let open = self.s.next_token()?.start; // '['
        let mut items = Vec::new();
        let mut first = true;
        while self.next_flow_entry(open, Kind::FlowSeqEnd, b']', &mut first)? {
            let t = self.s.peek_token()?;
            match t.kind {
                Kind::Key => {
                    // `[a: 1]`: a single-pair mapping as an item.
                    let (start, key, value) = self.flow_pair(Kind::FlowSeqEnd)?;
                    items.push(node_at(Value::Map(vec![(key, value)]), start));
                }
                Kind::FlowSeqEnd => break,
                _ => items.push(self.parse_node(false, false)?),
            }
        }
        self.s.next_token()?;
        Ok(node_at(Value::Seq(items), open))
    }

    /// Before an entry of a flow collection opened at `open`: false at its end
    /// token `end`; else consumes the `,` every entry but the first needs.
    fn next_flow_entry(&mut self, open: Mark, end: Kind, closer: u8, first: &mut bool) -> Result<bool, YamlError> {
        let t = self.s.peek_token()?;
        if t.kind == end {
            return Ok(false);
        }
        if !*first {
            if t.kind != Kind::FlowEntry {
                return Err(self.unexpected_in_flow(open, closer));
            }
            self.s.next_token()?;
        }
        *first = false;
        Ok(true)
    }

    /// An explicit `? key : value` pair in a flow collection ending with `end`
    /// (either side may be empty), with the position of its `?`.
    fn flow_pair(&mut self, end: Kind) -> Result<(Mark, Node, Node), YamlError> {
        let key_tok = self.s.next_token()?;
        let k = self.s.peek_kind()?;
        let key = if k == Kind::Value || k == Kind::FlowEntry || k == end { self.empty(key_tok.end) } else { self.parse_key(false)? };
        let value = self.flow_value(end)?;
        Ok((key_tok.start, key, value))
    }

    /// The value after a flow key: `: value`, `:` (null) or nothing (null).
    fn flow_value(&mut self, end: Kind) -> Result<Node, YamlError> {
        let t = self.s.peek_token()?;
        if t.kind == Kind::Value {
            let v = self.s.next_token()?;
            let k = self.s.peek_kind()?;
            if k == Kind::FlowEntry || k == end { Ok(self.empty(v.end)) } else { self.parse_node(false, false) }
        } else {
            let m = t.start;
            Ok(self.empty(m))
        }
    }

    fn parse_flow_mapping(&mut self) -> Result<Node, YamlError> {
        let open = self.s.next_token()?.start; // '{'
        let mut pairs: Vec<(Node, Node)> = Vec::new();
        let mut index = KeyIndex::default();
        let mut first = true;
        while self.next_flow_entry(open, Kind::FlowMapEnd, b'}', &mut first)? {
            let t = self.s.peek_token()?;
            match t.kind {
                Kind::Key => {
                    let (_, key, value) = self.flow_pair(Kind::FlowMapEnd)?;
                    self.push_pair(&mut pairs, &mut index, key, value)?;
                }
                Kind::FlowMapEnd => break,
                _ => {
                    // `{a, b}`: a key without a value.
                    let key = if t.kind == Kind::Scalar {
                        let tok = self.s.next_token()?;
                        self.scalar(tok, true)?
                    } else {
                        self.parse_key(false)?
                    };
                    let m = self.s.peek_token()?.start;
                    let value = self.empty(m);
                    self.push_pair(&mut pairs, &mut index, key, value)?;
                }
            }
        }
        self.s.next_token()?;
        Ok(node_at(Value::Map(pairs), open))
    }

    // ----- error messages ----------------------------------------------------

    /// Describes the next token for a message, e.g. `mapping key "range"`.
    fn describe_next(&mut self) -> String {
        let src = self.s.source();
        let text_of = |t: &Token| -> Option<String> {
            match &t.text {
                Text::Owned(s) => Some(short_quote(s)),
                Text::Span(a, b) => Some(short_quote(src.get(*a..*b).unwrap_or(""))),
                Text::None => None,
            }
        };
        let kind = match self.s.peek_token() {
            Ok(t) => t.kind,
            Err(_) => return "an invalid token".into(),
        };
        let key_text = || -> String {
            for i in 0..3 {
                match self.s.queued(i) {
                    Some(t) if t.kind == Kind::Scalar => {
                        return format!("mapping key {}", text_of(t).unwrap_or_default());
                    }
                    Some(t) if matches!(t.kind, Kind::Key | Kind::BlockMapStart) => continue,
                    _ => break,
                }
            }
            "a mapping key".to_string()
        };
        match kind {
            Kind::StreamEnd => "the end of the input".into(),
            Kind::DocStart => "a document start marker '---'".into(),
            Kind::DocEnd => "a document end marker '...'".into(),
            Kind::BlockMapStart | Kind::Key => key_text(),
            Kind::BlockSeqStart | Kind::BlockEntry => "a sequence entry '- '".into(),
            Kind::BlockEnd => "a less indented line".into(),
            Kind::FlowSeqStart => "'['".into(),
            Kind::FlowSeqEnd => "']'".into(),
            Kind::FlowMapStart => "'{'".into(),
            Kind::FlowMapEnd => "'}'".into(),
            Kind::FlowEntry => "','".into(),
            Kind::Value => "':'".into(),
            Kind::Scalar => match self.s.queued(0).and_then(text_of) {
                Some(s) => format!("the value {}", s),
                None => "a value".into(),
            },
        }
    }

    /// A node was expected but something else came (PyYAML "expected the node content").
    fn unexpected_in_node(&mut self) -> YamlError {
        let (kind, m) = match self.s.peek_token() {
            Ok(t) => (t.kind, t.start),
            Err(e) => return e,
        };
        let what = self.describe_next();
        if kind == Kind::StreamEnd {
            if let Some((b, om)) = self.s.innermost_open_flow() {
                return self.error(
                    om,
                    format!("unclosed '{}': the input ends before the matching '{}'", b as char, if b == b'[' { ']' } else { '}' }),
                );
            }
        }
        if matches!(kind, Kind::BlockSeqStart | Kind::BlockMapStart) {
            return self.error(m, format!("{} is not allowed inside '[...]' or '{{...}}'", what));
        }
        self.error(m, format!("expected a value, found {}", what))
    }

    /// Something other than a new entry/key or the end of a block collection.
    fn unexpected_in_block(&mut self, open: Mark, is_map: bool) -> YamlError {
        let (kind, m) = match self.s.peek_token() {
            Ok(t) => (t.kind, t.start),
            Err(e) => return e,
        };
        let what = self.describe_next();
        let coll = if is_map { "mapping" } else { "sequence" };
        let msg = match kind {
            Kind::BlockMapStart | Kind::BlockSeqStart => {
                // A line indented deeper than its siblings but not nested under anything.
                let mut expected = format!("column {}", open.col + 1);
                if let Some(c) = self.last_closed_col.filter(|&c| c > open.col && c != m.col) {
                    expected.push_str(&format!(
                        " (like the {} started at line {}), or column {} (to continue the nested block above)",
                        coll,
                        open.line + 1,
                        c + 1
                    ));
                } else {
                    expected.push_str(&format!(" (like the {} started at line {})", coll, open.line + 1));
                }
                format!("bad indentation: {} is at column {}, expected {}", what, m.col + 1, expected)
            }
            Kind::Key if !is_map => format!(
                "{} at the indentation of the sequence started at line {}, column {}: inside a sequence every line at this column must start with '- '",
                what,
                open.line + 1,
                open.col + 1
            ),
            Kind::BlockEntry if is_map => format!(
                "a sequence entry '- ' at the indentation of the mapping started at line {}, column {}: a mapping cannot also contain sequence entries (was a 'key:' line missing?)",
                open.line + 1,
                open.col + 1
            ),
            _ => format!(
                "expected a new {} at this indentation or the end of the {} started at line {}, column {}, found {}",
                if is_map { "'key: value'" } else { "'- item'" },
                coll,
                open.line + 1,
                open.col + 1,
                what
            ),
        };
        self.error(m, msg)
    }

    fn unexpected_in_flow(&mut self, open: Mark, close: u8) -> YamlError {
        let (kind, m) = match self.s.peek_token() {
            Ok(t) => (t.kind, t.start),
            Err(e) => return e,
        };
        let open_ch = if close == b']' { '[' } else { '{' };
        if kind == Kind::StreamEnd {
            return self.error(open, format!("unclosed '{}': the input ends before the matching '{}'", open_ch, close as char));
        }
        let what = self.describe_next();
        self.error(
            m,
            format!(
                "expected ',' or '{}' in the '{}...{}' started at line {}, column {}, found {}",
                close as char,
                open_ch,
                close as char,
                open.line + 1,
                open.col + 1,
                what
            ),
        )
    }
}

/// The keys of one mapping being read, so that finding a duplicate takes constant
/// time for string keys (a mapping of many keys reads in linear time).
#[derive(Default)]
struct KeyIndex {
    /// String keys → position in the mapping.
    strings: std::collections::HashMap<String, usize>,
    /// Positions of the other (scalar) keys, compared one by one.
    others: Vec<usize>,
}

impl KeyIndex {
    /// The earlier pair whose key equals `key`, if any.
    fn find<'p>(&self, pairs: &'p [(Node, Node)], key: &Node) -> Option<&'p (Node, Node)> {
        match &key.value {
            Value::Str(s) => self.strings.get(s).map(|&i| &pairs[i]),
            v => self.others.iter().map(|&i| &pairs[i]).find(|(k, _)| keys_equal(&k.value, v)),
        }
    }

    /// Record the key of the pair at position `i`.
    fn add(&mut self, i: usize, key: &Node) {
        match &key.value {
            Value::Str(s) => {
                self.strings.entry(s.clone()).or_insert(i);
            }
            _ => self.others.push(i),
        }
    }
}
