//! Layering: no import cycles between the modules of the `garmentcode` and `garments`
//! crates.
//!
//! The module graph is built at file granularity (a folder's `mod.rs` is a node of its
//! own) from the source text: `use` declarations (including `pub use` re-exports) and
//! `crate::`/`super::`/`self::` paths, each resolved to the deepest module file it
//! names. Declaring a child module (`mod child;`) is not a dependency; naming its
//! items is. `tools/modgraph.py` prints the same graph.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The source with comments, string and character literals blanked (line breaks kept).
fn strip(src: &str) -> String {
    let b: Vec<char> = src.chars().collect();
    let n = b.len();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    let newlines = |from: usize, to: usize| b[from..to.min(n)].iter().filter(|&&c| c == '\n').count();
    let is_ident = |c: char| c.is_alphanumeric() || c == '_';
    while i < n {
        let c = b[i];
        let next = b.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < n && b[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let (mut depth, mut j) = (1, i + 2);
            while j < n && depth > 0 {
                if b[j] == '/' && b.get(j + 1) == Some(&'*') {
                    depth += 1;
                    j += 2;
                } else if b[j] == '*' && b.get(j + 1) == Some(&'/') {
                    depth -= 1;
                    j += 2;
                } else {
                    j += 1;
                }
            }
            out.push_str(&"\n".repeat(newlines(i, j)));
            i = j;
        } else if c == 'r'
            && (i == 0 || !is_ident(b[i - 1]))
            && matches!(next, Some('"') | Some('#'))
            && raw_string_start(&b[i + 1..]).is_some()
        {
            let hashes = raw_string_start(&b[i + 1..]).unwrap_or(0);
            let mut j = i + 2 + hashes;
            while j < n && !(b[j] == '"' && b[j + 1..].iter().take(hashes).filter(|&&h| h == '#').count() == hashes) {
                j += 1;
            }
            let end = (j + 1 + hashes).min(n);
            out.push_str("\"\"");
            out.push_str(&"\n".repeat(newlines(i, end)));
            i = end;
        } else if c == '"' {
            let mut j = i + 1;
            while j < n && b[j] != '"' {
                j += if b[j] == '\\' { 2 } else { 1 };
            }
            out.push_str("\"\"");
            out.push_str(&"\n".repeat(newlines(i, j)));
            i = j + 1;
        } else if c == '\'' {
            // A character literal, or else a lifetime.
            let len = char_literal_len(&b[i..]);
            if len > 0 {
                out.push_str("' '");
                i += len;
            } else {
                out.push(c);
                i += 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// Number of `#` of a raw string starting after its `r`, if it is one.
fn raw_string_start(b: &[char]) -> Option<usize> {
    let hashes = b.iter().take_while(|&&c| c == '#').count();
    (b.get(hashes) == Some(&'"')).then_some(hashes)
}

/// Length of the character literal at the start of `b` (0 if it is a lifetime).
fn char_literal_len(b: &[char]) -> usize {
    match (b.get(1), b.get(2)) {
        (Some('\\'), _) => {
            let end = b.iter().skip(2).position(|&c| c == '\'').map_or(0, |p| p + 3);
            if end > 0 && end <= 12 { end } else { 0 }
        }
        (Some(_), Some('\'')) => 3,
        _ => 0,
    }
}

/// Module path of a file relative to the crate's `src` (`a/mod.rs` and `a.rs` are `a`).
fn module_of(rel: &str) -> Vec<String> {
    let mut parts: Vec<String> = rel.trim_end_matches(".rs").split('/').map(String::from).collect();
    if matches!(parts.last().map(String::as_str), Some("lib" | "mod")) {
        parts.pop();
    }
    parts
}

/// Every path of a use tree such as `a::{b, c::{d as e, self}}`.
fn expand_use(tree: &str) -> Vec<Vec<String>> {
    let mut cleaned = String::new();
    let words: Vec<&str> = tree.split_whitespace().collect();
    let mut k = 0;
    while k < words.len() {
        if words[k] == "as" {
            k += 2; // drop `as alias`; a trailing `,`/`}` glued to the alias is kept
            if let Some(w) = words.get(k - 1) {
                cleaned.push_str(&w.chars().skip_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>());
            }
            continue;
        }
        cleaned.push_str(words[k]);
        k += 1;
    }
    let mut out = Vec::new();
    walk(&[], &cleaned, &mut out);
    out
}

fn walk(prefix: &[String], tree: &str, out: &mut Vec<Vec<String>>) {
    let mut items = Vec::new();
    let (mut depth, mut cur) = (0, String::new());
    for c in tree.chars() {
        if c == ',' && depth == 0 {
            items.push(std::mem::take(&mut cur));
            continue;
        }
        depth += i32::from(c == '{') - i32::from(c == '}');
        cur.push(c);
    }
    items.push(cur);
    for item in items.iter().filter(|i| !i.is_empty()) {
        if let Some(open) = item.find('{') {
            let head = item[..open].trim_end_matches(':');
            let mut p = prefix.to_vec();
            p.extend(head.split("::").filter(|s| !s.is_empty()).map(String::from));
            walk(&p, &item[open + 1..item.rfind('}').unwrap_or(item.len())], out);
        } else {
            let mut p = prefix.to_vec();
            p.extend(item.split("::").filter(|s| !s.is_empty()).map(String::from));
            if p.last().map(String::as_str) == Some("self") {
                p.pop();
            }
            out.push(p);
        }
    }
}

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// Offsets of the word `w` (not part of a longer identifier).
fn word_at(text: &[u8], w: &str) -> Vec<usize> {
    let w = w.as_bytes();
    (0..text.len().saturating_sub(w.len() - 1))
        .filter(|&i| {
            &text[i..i + w.len()] == w && (i == 0 || !is_ident(text[i - 1])) && text.get(i + w.len()).is_none_or(|&c| !is_ident(c))
        })
        .collect()
}

/// `mod name;` / `mod name {` declarations: (offset of the `{` or `;`, name, is inline).
fn mod_decls(text: &[u8]) -> Vec<(usize, String, bool)> {
    let mut out = Vec::new();
    for i in word_at(text, "mod") {
        let mut j = i + 3;
        while j < text.len() && text[j].is_ascii_whitespace() {
            j += 1;
        }
        let start = j;
        while j < text.len() && is_ident(text[j]) {
            j += 1;
        }
        let name = String::from_utf8_lossy(&text[start..j]).to_string();
        while j < text.len() && text[j].is_ascii_whitespace() {
            j += 1;
        }
        if !name.is_empty() && j < text.len() && (text[j] == b';' || text[j] == b'{') {
            out.push((j, name, text[j] == b'{'));
        }
    }
    out
}

/// For each offset, how many inline `mod x { ... }` blocks enclose it.
fn inline_depths(text: &[u8], decls: &[(usize, String, bool)]) -> Vec<usize> {
    let opens: BTreeSet<usize> = decls.iter().filter(|d| d.2).map(|d| d.0).collect();
    let (mut stack, mut mods, mut out) = (Vec::new(), 0, vec![0; text.len() + 1]);
    for (i, &c) in text.iter().enumerate() {
        if c == b'{' {
            let m = opens.contains(&i);
            stack.push(m);
            mods += usize::from(m);
        } else if c == b'}' {
            mods -= usize::from(stack.pop().unwrap_or(false));
        }
        out[i] = mods;
    }
    out
}

/// The module graph of one crate: line counts and dependencies per file (relative paths).
fn crate_graph(src: &Path) -> (BTreeMap<String, usize>, BTreeMap<String, BTreeSet<String>>) {
    let mut files = Vec::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p: PathBuf = e.unwrap().path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                files.push(p);
            }
        }
    }
    let rel_of = |p: &Path| p.strip_prefix(src).unwrap().to_string_lossy().replace('\\', "/");
    let by_module: BTreeMap<Vec<String>, String> = files.iter().map(|p| (module_of(&rel_of(p)), rel_of(p))).collect();
    let (mut lines, mut edges) = (BTreeMap::new(), BTreeMap::new());
    for p in &files {
        let rel = rel_of(p);
        let raw = std::fs::read_to_string(p).unwrap();
        lines.insert(rel.clone(), raw.matches('\n').count());
        let text = strip(&raw);
        let t = text.as_bytes();
        let here = module_of(&rel);
        let decls = mod_decls(t);
        let depth = inline_depths(t, &decls);
        let children: BTreeSet<&str> = decls.iter().filter(|d| !d.2).map(|d| d.1.as_str()).collect();
        let mut refs: Vec<(Vec<String>, usize)> = Vec::new();
        for i in word_at(t, "use") {
            if let Some(end) = text[i..].find(';') {
                refs.extend(expand_use(&text[i + 3..i + end]).into_iter().map(|p| (p, i)));
            }
        }
        for w in ["crate", "super", "self"] {
            for i in word_at(t, w) {
                if i >= 2 && &t[i - 2..i] == b"::" {
                    continue; // inside a longer path (`super::super`), or a use tree
                }
                let mut segs = vec![w.to_string()];
                let mut j = i + w.len();
                loop {
                    let mut k = j;
                    while k < t.len() && t[k].is_ascii_whitespace() {
                        k += 1;
                    }
                    if !t[k..].starts_with(b"::") {
                        break;
                    }
                    k += 2;
                    while k < t.len() && t[k].is_ascii_whitespace() {
                        k += 1;
                    }
                    let s = k;
                    while k < t.len() && is_ident(t[k]) {
                        k += 1;
                    }
                    if s == k {
                        break;
                    }
                    segs.push(text[s..k].to_string());
                    j = k;
                }
                if segs.len() > 1 {
                    refs.push((segs, i));
                }
            }
        }
        let deps: &mut BTreeSet<String> = edges.entry(rel.clone()).or_default();
        for (segs, at) in refs {
            let inner = depth[at];
            let target: Vec<String> = match segs.first().map(String::as_str) {
                None => continue,
                Some("crate") => segs[1..].to_vec(),
                Some("super" | "self") => {
                    let (mut cur, mut extra, mut i) = (here.clone(), inner, 0);
                    while i < segs.len() && (segs[i] == "super" || segs[i] == "self") {
                        if segs[i] == "super" {
                            if extra > 0 {
                                extra -= 1;
                            } else {
                                cur.pop();
                            }
                        }
                        i += 1;
                    }
                    cur.extend(segs[i..].iter().cloned());
                    cur
                }
                Some(first) if children.contains(first) && inner == 0 => here.iter().chain(&segs).cloned().collect(),
                _ => continue,
            };
            let found = (0..=target.len()).rev().find_map(|k| by_module.get(&target[..k]));
            if let Some(dep) = found.filter(|d| **d != rel) {
                deps.insert(dep.clone());
            }
        }
    }
    (lines, edges)
}

/// One cycle of the graph (its files in order, the first repeated at the end), if any.
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        Open,
        Done,
    }
    let mut mark: BTreeMap<&str, Mark> = BTreeMap::new();
    for start in edges.keys() {
        if mark.contains_key(start.as_str()) {
            continue;
        }
        let mut stack: Vec<(&str, Vec<&str>)> = vec![(start, edges[start].iter().rev().map(String::as_str).collect())];
        mark.insert(start, Mark::Open);
        while let Some((node, todo)) = stack.last_mut() {
            match todo.pop() {
                None => {
                    mark.insert(node, Mark::Done);
                    stack.pop();
                }
                Some(next) => match mark.get(next) {
                    Some(Mark::Open) => {
                        let from = stack.iter().position(|(n, _)| *n == next).unwrap();
                        let mut cycle: Vec<String> = stack[from..].iter().map(|(n, _)| n.to_string()).collect();
                        cycle.push(next.to_string());
                        return Some(cycle);
                    }
                    Some(Mark::Done) => {}
                    None => {
                        mark.insert(next, Mark::Open);
                        let deps = edges.get(next).map(|d| d.iter().rev().map(String::as_str).collect()).unwrap_or_default();
                        stack.push((next, deps));
                    }
                },
            }
        }
    }
    None
}

fn assert_acyclic(krate: &str) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join(krate).join("src");
    let (lines, edges) = crate_graph(&src);
    assert!(lines.len() > 10 && edges.values().map(BTreeSet::len).sum::<usize>() > 10, "{krate}: the graph was not found");
    if let Some(cycle) = find_cycle(&edges) {
        panic!("import cycle between the modules of {krate}: {}", cycle.join(" -> "));
    }
}

#[test]
fn runtime_modules_have_no_import_cycles() {
    assert_acyclic("garmentcode");
}

#[test]
fn garment_library_modules_have_no_import_cycles() {
    assert_acyclic("garments");
}

/// The checker itself: it finds what it must.
#[test]
fn the_checker_sees_uses_paths_and_cycles() {
    assert_eq!(
        expand_use(" crate::a::{b::{self, C as D}, e}"),
        [vec!["crate", "a", "b"], vec!["crate", "a", "b", "C"], vec!["crate", "a", "e"]]
    );
    assert_eq!(strip("a // use crate::x;\n\"crate::y\" '\"' 'a"), "a \n\"\" ' ' 'a");
    let dir = std::env::temp_dir().join(format!("layering-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("p")).unwrap();
    let write = |f: &str, s: &str| std::fs::write(dir.join(f), s).unwrap();
    write("lib.rs", "mod a;\nmod p;\npub use a::A;\n");
    write("a.rs", "pub struct A;\nfn f(_: crate::p::q::Q) {}\n#[cfg(test)]\nmod tests {\n    use super::*;\n}\n");
    write("p/mod.rs", "mod q;\npub use q::Q;\n");
    write("p/q.rs", "use super::super::a::A;\npub struct Q(A);\n");
    let (lines, edges) = crate_graph(&dir);
    assert_eq!(lines["a.rs"], 6);
    let deps = |f: &str| edges[f].iter().map(String::as_str).collect::<Vec<_>>();
    assert_eq!(deps("lib.rs"), ["a.rs"]);
    assert_eq!(deps("a.rs"), ["p/q.rs"]);
    assert_eq!(deps("p/mod.rs"), ["p/q.rs"]);
    assert_eq!(deps("p/q.rs"), ["a.rs"]);
    assert_eq!(find_cycle(&edges), Some(vec!["a.rs".to_string(), "p/q.rs".to_string(), "a.rs".to_string()]));
    std::fs::remove_dir_all(&dir).unwrap();
}
