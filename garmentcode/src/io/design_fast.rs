//! Fast path of [`super::read_design`]: design files in the layout the reference
//! and [`super::write_design`] write, read straight into the design without
//! building a YAML tree.
//!
//! Why: a design file holds ~900 lines of which only the ~120 `v:` values matter;
//! building the generic YAML tree (a `String` per key and name, a `Vec` per
//! mapping and list) and then walking it cost more than building the garment.
//!
//! The accepted text is a strict subset of YAML: printable ASCII lines (blank
//! and comment lines are skipped) that are either `key:`, `key: scalar` or
//! `- scalar` (optionally followed by a ` # comment`), with keys and scalars made
//! of letters, digits and `_ . + -` only,
//! and block indentation as in [`crate::yaml`]'s line-oriented reader (nested
//! mappings deeper than their key, lists deeper or at the key's column). Scalars
//! are resolved with the same YAML 1.1 rules as the full reader. Anything else, and
//! every problem of the design itself (unknown parameter, value out of range,
//! missing `v`, duplicate key...), makes this path give up (`None`); the caller then
//! runs the full reader, which also produces the error messages. So this path never
//! decides an error; whenever it succeeds, the design equals the full reader's
//! (checked by the tests on the project's design files and on mutated ones).

use crate::params::Params;
use crate::params::space::{DesignSpace, Entry, Skeleton};
use crate::params::spec::Value;
use crate::parity::yaml::{Resolved, resolve_plain, resolves_to_value};
use std::sync::atomic::Ordering;

/// Deepest nesting accepted (design files are about six levels deep).
const MAX_DEPTH: usize = 64;

/// The design in `text`, or `None` when the full reader must decide.
pub(crate) fn read_design_fast<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
    let values = match space.skeleton() {
        Some(skeleton) => skeleton.read_values(text, space).or_else(|| read_values_lines(text, space))?,
        None => read_values_lines(text, space)?,
    };
    design_from_values(&values, space)
}

/// Only the line reader (for tests).
pub(crate) fn read_design_lines<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
    design_from_values(&read_values_lines(text, space)?, space)
}

/// Only the space's layout (for tests; built even on a first read).
pub(crate) fn read_design_skeleton<D: Params>(text: &str, space: &DesignSpace) -> Option<D> {
    design_from_values(&space.built_skeleton()?.read_values(text, space)?, space)
}

/// The design with these checked values (`None`: the space's default).
fn design_from_values<D: Params>(values: &[Option<Value>], space: &DesignSpace) -> Option<D> {
    // As `from_values`: every parameter is set, to its value or the space's default.
    let mut d = D::defaults();
    let mut keys: Vec<&str> = Vec::with_capacity(8);
    for (i, (spec, v)) in space.params().iter().zip(values).enumerate() {
        keys.clear();
        keys.extend(space.keys(i).iter().map(String::as_str));
        d.set_value(&keys, v.as_ref().unwrap_or(&spec.default)).ok()?;
    }
    Some(d)
}

/// The checked value of every parameter the file sets, read line by line.
fn read_values_lines(text: &str, space: &DesignSpace) -> Option<Vec<Option<Value>>> {
    if !printable_ascii(text.as_bytes()) {
        return None;
    }
    let mut r = Reader {
        text,
        pos: 0,
        cur: None,
        keys: Vec::with_capacity(64),
        path: String::with_capacity(64),
        space,
        values: vec![None; space.params().len()],
        depth: 0,
    };
    r.advance()?;
    let first = r.cur?;
    if first.indent != 0 {
        return None;
    }
    let mut top = Top { design_seen: false };
    r.mapping(0, &mut Role::Top(&mut top))?;
    if r.cur.is_some() || !top.design_seen {
        return None;
    }
    Some(r.values)
}

impl DesignSpace {
    /// The space's file layout with holes for the values, from the second read on.
    pub(crate) fn skeleton(&self) -> Option<&Skeleton> {
        if self.skeleton.reads.fetch_add(1, Ordering::Relaxed) == 0 {
            return None;
        }
        self.built_skeleton()
    }

    /// The space's file layout with holes for the values, built now if not yet.
    pub(crate) fn built_skeleton(&self) -> Option<&Skeleton> {
        self.skeleton.cell.get_or_init(|| Skeleton::new(self)).as_ref()
    }
}

impl Skeleton {
    /// The layout of `space`, or `None` if it is not one the line reader reads.
    ///
    /// Self-check: the space's own file of defaults, read through the holes, must
    /// give a value for every parameter, the same values the line reader finds.
    /// The lines around the holes are then lines the line reader accepts, and a
    /// file that differs only by other plain scalars in the holes takes the same
    /// path through it.
    pub(crate) fn new(space: &DesignSpace) -> Option<Skeleton> {
        const MARK: &str = "zqvaluehole";
        let n = space.params().len();
        let holes = space.to_yaml_with(|p| Value::Str(format!("{MARK}{}{MARK}", space.index_of(&p.path).unwrap_or(usize::MAX))));
        let mut parts = Vec::with_capacity(n);
        let mut seen = vec![false; n];
        let mut rest = holes.as_str();
        while let Some(k) = rest.find(MARK) {
            let after = &rest[k + MARK.len()..];
            let digits = after.find(MARK)?;
            let index: usize = after[..digits].parse().ok()?;
            if index >= n || std::mem::replace(&mut seen[index], true) {
                return None;
            }
            parts.push((rest[..k].to_string(), index));
            rest = &after[digits + MARK.len()..];
        }
        if parts.len() != n {
            return None;
        }
        let skeleton = Skeleton { parts, tail: rest.to_string() };
        let defaults = space.to_yaml();
        let through_holes = skeleton.read_values(&defaults, space)?;
        (through_holes.iter().all(Option::is_some) && read_values_lines(&defaults, space)? == through_holes).then_some(skeleton)
    }

    /// The checked values of a file that is this layout with plain scalars in the
    /// holes; `None` for any other text or any value its parameter refuses.
    fn read_values(&self, text: &str, space: &DesignSpace) -> Option<Vec<Option<Value>>> {
        let src = text.as_bytes();
        let mut values = vec![None; space.params().len()];
        let mut pos = 0;
        for (literal, index) in &self.parts {
            if !src[pos..].starts_with(literal.as_bytes()) {
                return None;
            }
            pos += literal.len();
            let end = plain_run(src, pos);
            if src.get(end).is_some_and(|&b| b != b'\n') {
                return None; // anything but a plain scalar up to the end of the line
            }
            let s = &text[pos..end];
            if !scalar_ok(s) {
                return None;
            }
            values[*index] = Some(space.params()[*index].check(&value_of(s, resolve_plain(s))).ok()?);
            pos = end;
        }
        (src[pos..] == *self.tail.as_bytes()).then_some(values)
    }
}

/// One content line.
#[derive(Clone, Copy)]
struct Line<'a> {
    indent: usize,
    kind: Kind<'a>,
}

#[derive(Clone, Copy)]
enum Kind<'a> {
    /// `key:` (no inline value) or `key: scalar`.
    Key(&'a str, Option<&'a str>),
    /// `- scalar`.
    Item(&'a str),
}

struct Top {
    design_seen: bool,
}

/// What a node means for the design, which decides what it may be.
enum Role<'r> {
    /// The document: a mapping whose `design` key holds the parameters.
    Top(&'r mut Top),
    /// A group of parameters (`design` itself or below); `prefix_len` is the
    /// length of its dotted path in `Reader::path`.
    Group { prefix_len: usize },
    /// A parameter's mapping: must hold `v`.
    Param { index: usize, v_seen: bool },
    /// The `v` of a parameter: a scalar or null.
    Value { index: usize },
    /// Anything else (`range`, `type`, other top-level keys): only validated.
    Skip,
}

struct Reader<'a, 's> {
    text: &'a str,
    /// Byte offset of the next unread line.
    pos: usize,
    cur: Option<Line<'a>>,
    /// Keys of the open mappings (duplicates are left to the full reader).
    keys: Vec<&'a str>,
    /// Dotted path of the current group.
    path: String,
    space: &'s DesignSpace,
    /// Checked value of every parameter the file sets.
    values: Vec<Option<Value>>,
    depth: usize,
}

/// Characters allowed in keys and scalars.
const PLAIN: [bool; 256] = {
    let mut t = [false; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        t[b] = c.is_ascii_alphanumeric() || matches!(c, b'_' | b'.' | b'+' | b'-');
        b += 1;
    }
    t
};

/// End of the run of plain characters from `i`.
#[inline]
fn plain_run(src: &[u8], mut i: usize) -> usize {
    while i < src.len() && PLAIN[src[i] as usize] {
        i += 1;
    }
    i
}

/// Index of the newline ending the line at `i` (or the length).
#[inline]
fn line_end(src: &[u8], mut i: usize) -> usize {
    while i < src.len() && src[i] != b'\n' {
        i += 1;
    }
    i
}

/// Only printable ASCII and newlines (no tabs, CRs, BOMs or control characters,
/// which the full reader handles), checked in blocks the compiler vectorises.
fn printable_ascii(src: &[u8]) -> bool {
    src.chunks(64).all(|c| c.iter().fold(true, |ok, &b| ok & ((0x20..0x7f).contains(&b) | (b == b'\n'))))
}

/// A plain scalar the full reader reads the same way: not empty, not a lone `-`
/// (an entry), and resolving to a null, boolean, number or string.
fn scalar_ok(s: &str) -> bool {
    !s.is_empty() && s != "-" && resolves_to_value(s)
}

fn value_of(s: &str, r: Resolved) -> Value {
    match r {
        Resolved::Null => Value::Null,
        Resolved::Bool(b) => Value::Bool(b),
        Resolved::Int(i) => Value::Int(i),
        Resolved::Float(f) => Value::Float(f),
        _ => Value::Str(s.to_string()),
    }
}

impl<'a> Reader<'a, '_> {
    /// Moves to the next content line (skipping blank and comment lines), or
    /// gives up on a line outside the subset. The text is known to be printable
    /// ASCII and newlines.
    fn advance(&mut self) -> Option<()> {
        let src = self.text.as_bytes();
        let at = |k: usize| src.get(k).copied().unwrap_or(b'\n');
        loop {
            let start = self.pos;
            if start >= src.len() {
                self.cur = None;
                return Some(());
            }
            let mut i = start;
            while at(i) == b' ' {
                i += 1;
            }
            let indent = i - start;
            let kind = match at(i) {
                b'\n' => {
                    self.pos = i + 1;
                    continue;
                }
                b'#' => {
                    self.pos = line_end(src, i) + 1;
                    continue;
                }
                b'-' if at(i + 1) == b' ' => {
                    let mut v = i + 2;
                    while at(v) == b' ' {
                        v += 1;
                    }
                    let e = plain_run(src, v);
                    self.pos = self.after_value(e)?;
                    Kind::Item(&self.text[v..e])
                }
                _ => {
                    let e = plain_run(src, i);
                    if e == i || at(e) != b':' || src[i] == b'-' {
                        return None;
                    }
                    let key = &self.text[i..e];
                    if resolve_plain(key) != Resolved::Str {
                        return None;
                    }
                    match at(e + 1) {
                        b'\n' => {
                            self.pos = e + 2;
                            Kind::Key(key, None)
                        }
                        b' ' => {
                            let mut v = e + 2;
                            while at(v) == b' ' {
                                v += 1;
                            }
                            match at(v) {
                                b'\n' => {
                                    self.pos = v + 1;
                                    Kind::Key(key, None)
                                }
                                b'#' => {
                                    self.pos = line_end(src, v) + 1;
                                    Kind::Key(key, None)
                                }
                                _ => {
                                    let ve = plain_run(src, v);
                                    self.pos = self.after_value(ve)?;
                                    Kind::Key(key, Some(&self.text[v..ve]))
                                }
                            }
                        }
                        _ => return None,
                    }
                }
            };
            self.cur = Some(Line { indent, kind });
            return Some(());
        }
    }

    /// After a plain scalar ending at `e`: spaces, then the end of the line or a
    /// ` #` comment. Returns the start of the next line.
    fn after_value(&self, e: usize) -> Option<usize> {
        let src = self.text.as_bytes();
        let mut k = e;
        while k < src.len() && src[k] == b' ' {
            k += 1;
        }
        match src.get(k) {
            None | Some(b'\n') => Some(k + 1),
            Some(b'#') if k > e => Some(line_end(src, k) + 1),
            _ => None,
        }
    }

    /// `key: ...` lines at column `n`.
    fn mapping(&mut self, n: usize, role: &mut Role) -> Option<()> {
        let base = self.keys.len();
        while let Some(l) = self.cur {
            if l.indent < n {
                break;
            }
            let Kind::Key(key, inline) = l.kind else { return None };
            // Many keys: the full reader (linear in keys) handles them.
            if l.indent > n || self.keys.len() - base >= 256 || self.keys[base..].contains(&key) {
                return None;
            }
            self.keys.push(key);
            let mut child = self.child(role, key)?;
            self.advance()?;
            match inline {
                Some(s) => {
                    if matches!(self.cur, Some(next) if next.indent > n) {
                        return None; // continuation line or bad indentation
                    }
                    self.scalar_node(&mut child, s)?;
                }
                None => match self.cur {
                    Some(next) if next.indent > n => self.block(next, &mut child)?,
                    Some(next) if next.indent == n && matches!(next.kind, Kind::Item(_)) => self.sequence(n, true, &mut child)?,
                    _ => self.null_node(&mut child)?,
                },
            }
            self.end_child(role, child)?;
        }
        self.keys.truncate(base);
        if let Role::Param { v_seen: false, .. } = role {
            return None; // a parameter needs a `v:` value
        }
        Some(())
    }

    /// A nested block collection starting at `first`.
    fn block(&mut self, first: Line<'a>, role: &mut Role) -> Option<()> {
        if self.depth >= MAX_DEPTH {
            return None;
        }
        self.depth += 1;
        let r = match first.kind {
            Kind::Key(..) => self.mapping(first.indent, role),
            Kind::Item(_) => self.sequence(first.indent, false, role),
        };
        self.depth -= 1;
        r
    }

    /// `- scalar` lines at column `n` (`indentless`: a mapping value at the key's column).
    fn sequence(&mut self, n: usize, indentless: bool, role: &mut Role) -> Option<()> {
        if !matches!(role, Role::Skip) {
            return None;
        }
        while let Some(l) = self.cur {
            if l.indent < n {
                break;
            }
            match l.kind {
                Kind::Item(s) if l.indent == n => {
                    if !scalar_ok(s) {
                        return None;
                    }
                    self.advance()?;
                    if matches!(self.cur, Some(next) if next.indent > n) {
                        return None;
                    }
                }
                Kind::Key(..) if indentless && l.indent == n => break,
                _ => return None,
            }
        }
        Some(())
    }

    /// The role of the value of `key` in a node of role `parent`.
    fn child(&mut self, parent: &mut Role, key: &str) -> Option<Role<'static>> {
        Some(match parent {
            Role::Top(top) if key == "design" => {
                top.design_seen = true;
                self.path.clear();
                Role::Group { prefix_len: 0 }
            }
            Role::Top(_) | Role::Skip => Role::Skip,
            Role::Group { prefix_len } => {
                self.path.truncate(*prefix_len);
                if *prefix_len > 0 {
                    self.path.push('.');
                }
                self.path.push_str(key);
                match self.space.lookup(&self.path)? {
                    Entry::Param(index) => Role::Param { index, v_seen: false },
                    Entry::Group => Role::Group { prefix_len: self.path.len() },
                }
            }
            Role::Param { index, v_seen } if key == "v" => {
                *v_seen = true;
                Role::Value { index: *index }
            }
            Role::Param { .. } => Role::Skip,
            Role::Value { .. } => return None,
        })
    }

    /// After a child: restore the group path.
    fn end_child(&mut self, parent: &mut Role, _child: Role) -> Option<()> {
        if let Role::Group { prefix_len } = parent {
            self.path.truncate(*prefix_len);
        }
        Some(())
    }

    fn scalar_node(&mut self, role: &mut Role, s: &str) -> Option<()> {
        if !scalar_ok(s) {
            return None;
        }
        match role {
            Role::Skip => Some(()),
            Role::Value { index } => self.set(*index, value_of(s, resolve_plain(s))),
            _ => None, // groups and parameters must be mappings
        }
    }

    fn null_node(&mut self, role: &mut Role) -> Option<()> {
        match role {
            Role::Skip => Some(()),
            Role::Value { index } => self.set(*index, Value::Null),
            _ => None,
        }
    }

    fn set(&mut self, index: usize, v: Value) -> Option<()> {
        let checked = self.space.params()[index].check(&v).ok()?;
        self.values[index] = Some(checked);
        Some(())
    }
}
