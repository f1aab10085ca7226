//! The fast paths of `read_design` agree with the full reader: they take the
//! project's design files and freshly written ones, and on mutated files they
//! either defer (`None`) or return exactly the full reader's design.

use garmentcode::io::testing::{read_design_fast, read_design_full, read_design_lines, read_design_skeleton};
use garmentcode::io::write_design;
use garmentcode::{DesignSpace, Params, Sampler, sample_rng};
use garments::Design;
use std::path::Path;
use std::sync::OnceLock;

/// One space for all reads, so that its file layout is built and used.
fn space() -> &'static DesignSpace {
    static SPACE: OnceLock<DesignSpace> = OnceLock::new();
    SPACE.get_or_init(Design::design_space)
}

/// Design files of the project: the reference cases, the built-in designs and
/// written samples.
fn corpus() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases");
    let mut dirs: Vec<_> = std::fs::read_dir(&root).expect("cases").map(|d| d.expect("entry").path()).collect();
    dirs.sort();
    for d in dirs {
        let f = d.join("design.yaml");
        if let Ok(text) = std::fs::read_to_string(&f) {
            out.push((f.display().to_string(), text));
        }
    }
    // The designs past the reference set `design.extension`, which this space (the
    // reference's, the sampler's) does not have.
    for (name, text) in garments::builtin::DESIGNS.iter().filter(|(_, text)| !text.contains("extension:")) {
        out.push((format!("built-in {name}"), text.to_string()));
    }
    let space = Design::design_space();
    let sampler = Sampler::new(space.clone());
    for i in 0..20 {
        let d: Design = sampler.sample(&mut sample_rng(7, i));
        out.push((format!("sample {i}"), write_design(&d, &space)));
    }
    out
}

/// Which fast paths took a file.
#[derive(Clone, Copy, Default)]
struct Taken {
    lines: bool,
    skeleton: bool,
}

/// Every fast path either defers or agrees with the full reader.
fn agree(text: &str, what: &str) -> Taken {
    let space = space();
    let full = read_design_full::<Design>(text, "f.yaml", space);
    let mut taken = Taken::default();
    for (path, fast) in [
        ("line", read_design_lines::<Design>(text, space)),
        ("layout", read_design_skeleton::<Design>(text, space)),
        ("combined", read_design_fast::<Design>(text, space)),
    ] {
        if let Some(fast) = fast {
            assert_eq!(full.as_ref(), Ok(&fast), "{path} fast path disagrees on {what}:\n{text}");
            match path {
                "line" => taken.lines = true,
                "layout" => taken.skeleton = true,
                _ => {}
            }
        }
    }
    taken
}

#[test]
fn fast_path_reads_the_project_design_files() {
    let corpus = corpus();
    let mut taken = 0;
    for (name, text) in &corpus {
        let t = agree(text, name);
        if t.lines {
            taken += 1;
        } else {
            // Only hand-edited files (trailing spaces...) may defer, and they must read.
            read_design_full::<Design>(text, name, space()).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
        if name.starts_with("sample") || name.starts_with("built-in") {
            assert!(t.lines, "{name} should take the line reader");
        }
        if name.starts_with("sample") {
            assert!(t.skeleton, "{name} should take the space's layout");
        }
    }
    assert!(taken * 10 >= corpus.len() * 9, "only {taken} of {} files took the fast path", corpus.len());
}

/// Small deterministic generator (xorshift).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

const SCALARS: &[&str] = &[
    "yes",
    "no",
    "on",
    "Off",
    "~",
    "null",
    "Null",
    "",
    " ",
    "1e3",
    "1.0e+3",
    "0x1F",
    "0777",
    "08",
    "1:30",
    "1_000",
    ".5",
    "-.5",
    "+.5",
    ".inf",
    "-.inf",
    ".nan",
    "2001-12-14",
    "0x_",
    "99999999999999999999",
    "'FittedShirt'",
    "\"Shirt\"",
    "[1, 2]",
    "[]",
    "{a: 1}",
    "Shirt",
    "FittedShirt",
    "Pants",
    "true",
    "True",
    "0",
    "1",
    "-1",
    "+1",
    "0.5",
    "1.0",
    "1.",
    "=",
    "<<",
    "- x",
    "a: b",
    "x # c",
    "x#c",
    "-",
    "--",
    "|",
    ">",
    "&a",
    "*a",
    "!!str x",
    "%x",
    "@x",
    "`x",
    "?x",
    "x,",
    "0.3000000000000000444",
    "1e-3",
    "1.5e-05",
    "-0.0",
    "CircleNeckHalf",
    "null # c",
    "'a''b'",
    "x\ty",
    "é",
];

const KEYS: &[&str] = &[
    "v",
    "range",
    "type",
    "default_prob",
    "design",
    "meta",
    "upper",
    "bottom",
    "shirt",
    "length",
    "sleeve",
    "sleeveless",
    "collar",
    "component",
    "style",
    "wb",
    "x",
    "V",
    "v ",
    " v",
    "'v'",
    "\"v\"",
    "v.v",
    "shirt.length",
    "meta.upper",
    "-v",
    "1",
    "true",
    "null",
    "~",
    "?",
    "v:",
    "skirt-many-panels",
    "design.meta",
];

const CHARS: &[&str] = &[
    " ", "  ", "\t", ":", ": ", "-", "- ", "#", " #", "'", "\"", "x", "1", ".", "\n", "\r", "\r\n", "[", "]", "{", "}", "&", "*", "!", "|",
    ">", "%", "@", "`", "?", ",", "é", "\u{feff}", "\u{7}",
];

fn mutate(rng: &mut Rng, text: &str) -> String {
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    let n = lines.len();
    let times = 1 + rng.below(3);
    for _ in 0..times {
        let i = rng.below(lines.len().max(1));
        match rng.below(11) {
            0 => {
                // Delete a character.
                let l = &mut lines[i];
                if !l.is_empty() {
                    let at = rng.below(l.len());
                    if l.is_char_boundary(at) && l.is_char_boundary(at + 1) {
                        l.remove(at);
                    }
                }
            }
            1 => {
                // Insert characters.
                let l = &mut lines[i];
                let at = rng.below(l.len() + 1);
                if l.is_char_boundary(at) {
                    l.insert_str(at, rng.pick(CHARS));
                }
            }
            2 => {
                let l = lines[i].clone();
                lines.insert(i, l);
            }
            3 => {
                lines.remove(i);
                if lines.is_empty() {
                    lines.push(String::new());
                }
            }
            4 => {
                // Re-indent a line.
                let l = &mut lines[i];
                match rng.below(4) {
                    0 => l.insert(0, ' '),
                    1 => l.insert_str(0, "  "),
                    _ => {
                        let k = l.len() - l.trim_start_matches(' ').len();
                        l.drain(..k.min(1 + rng.below(2)));
                    }
                }
            }
            5 | 6 => {
                // Replace the value after a colon or a dash.
                let l = &mut lines[i];
                if let Some(c) = l.find(": ").or_else(|| l.find("- ")) {
                    l.truncate(c + 2);
                    l.push_str(rng.pick(SCALARS));
                }
            }
            7 => {
                // Replace a key.
                let l = &mut lines[i];
                let k = l.len() - l.trim_start_matches(' ').len();
                if let Some(c) = l.find(':') {
                    if c >= k {
                        l.replace_range(k..c, rng.pick(KEYS));
                    }
                }
            }
            8 => {
                let j = rng.below(n.min(lines.len()).max(1));
                lines.swap(i, j);
            }
            9 => {
                let comment = ["# c", "", "   ", "  # c", "#", "---", "...", "%YAML 1.1"][rng.below(8)];
                lines.insert(i, comment.to_string());
            }
            _ => {
                // A trailing space or comment.
                let l = &mut lines[i];
                l.push_str([" ", "  ", " # c", "#c", "\t"][rng.below(5)]);
            }
        }
    }
    lines.join("\n")
}

#[test]
fn fast_path_agrees_with_the_full_reader_on_mutated_files() {
    let corpus = corpus();
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let (mut lines, mut skeleton, mut total) = (0, 0, 0);
    let rounds = if cfg!(debug_assertions) { 1500 } else { 6000 };
    for round in 0..rounds {
        let (name, base) = &corpus[round % corpus.len()];
        let text = mutate(&mut rng, base);
        total += 1;
        let t = agree(&text, &format!("{name}, mutation {round}"));
        lines += usize::from(t.lines);
        skeleton += usize::from(t.skeleton);
    }
    // Many mutations keep the file valid (a changed value, a comment); they must
    // still be read by the fast paths often enough for this test to mean something.
    assert!(lines * 10 >= total, "only {lines} of {total} mutated files took the line reader");
    assert!(skeleton * 200 >= total, "only {skeleton} of {total} mutated files took the space's layout");
}

/// Written designs with other values (valid or not, plain or not) in their `v:`
/// lines: the space's layout reader takes many and agrees on all.
#[test]
fn layout_reader_agrees_on_changed_values() {
    let space = space();
    let sampler = Sampler::new(space.clone());
    let names: Vec<String> = space
        .params()
        .iter()
        .filter_map(|p| match &p.range {
            garmentcode::Range::Options(o) => Some(o.iter().map(|v| v.to_string()).collect::<Vec<_>>()),
            _ => None,
        })
        .flatten()
        .collect();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut skeleton, mut total) = (0, 0);
    let rounds = if cfg!(debug_assertions) { 300 } else { 2000 };
    for round in 0..rounds {
        let d: Design = sampler.sample(&mut sample_rng(11, round as u64));
        let text = write_design(&d, space);
        let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
        let v_lines: Vec<usize> = (0..lines.len()).filter(|&i| lines[i].trim_start().starts_with("v: ")).collect();
        for _ in 0..1 + rng.below(3) {
            let i = v_lines[rng.below(v_lines.len())];
            let value = match rng.below(4) {
                0 => rng.pick(SCALARS).to_string(),
                1 => names[rng.below(names.len())].clone(),
                2 => format!("{}", (rng.next() % 4000) as f64 / 1000.0 - 1.0),
                _ => ["1", "0", "2", "7", "95", "1.0", "1.", "0.5e+0", "+0.5", "-0.0", "true", "false", "null"][rng.below(13)].to_string(),
            };
            let l = &mut lines[i];
            let c = l.find("v: ").expect("v line");
            l.truncate(c + 3);
            l.push_str(&value);
        }
        let text = lines.join("\n");
        total += 1;
        skeleton += usize::from(agree(&text, &format!("changed values, round {round}")).skeleton);
    }
    assert!(skeleton * 40 >= total, "only {skeleton} of {total} files took the space's layout");
}

/// Short synthetic files around the subset's borders.
#[test]
fn fast_path_borders() {
    let space = space();
    let default = write_design(&Design::defaults(), space);
    // The plain layout is taken.
    assert!(read_design_lines::<Design>(&default, space).is_some());
    assert!(read_design_skeleton::<Design>(&default, space).is_some());
    for text in [
        "design:\n  meta:\n    upper:\n      v: Shirt\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n  shirt:\n    length:\n      v: 1.5\n      range:\n      - 0.5\n      - 3.5\n",
        "design:\n  meta.upper:\n    v: Shirt\n",
        "other: 1\ndesign:\n  meta:\n    upper:\n      v: null\n",
        "design:\n  meta:\n    upper:\n      v:\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n      range:\n        - Shirt\n",
        "# comment\ndesign:\n\n  meta:   \n    upper:\n      v: Shirt # c\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n    upper:\n      v: Shirt\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n  meta:\n    wb:\n      v: null\n",
        "design:\n  meta:\n    upper:\n      range: [1]\n",
        "design:\n  meta:\n    upper:\n      v: Dress\n",
        "design:\n  meta:\n    uper:\n      v: Shirt\n",
        "design:\n  meta:\n    upper: Shirt\n",
        "design:\n  meta:\n    upper:\n      v:\n        x: 1\n",
        "design:\n  meta:\n    upper:\n      v:\n      - Shirt\n",
        "design:\n  meta:\n    upper:\n    v: Shirt\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n     x: 1\n",
        "design:\n  meta:\n  - x\n",
        "design:\n",
        "design: 1\n",
        "- design\n",
        "",
        "  design:\n    meta:\n      upper:\n        v: Shirt\n",
        "design:\n  meta:\n    upper:\n      v: Shirt\n      v: Shirt\n",
        "design:\n  shirt:\n    length:\n      v: 9.5\n",
        "design:\n  shirt:\n    length:\n      v: yes\n",
        "design:\n  collar:\n    fc_angle:\n      v: 90.0\n",
        "design:\n  collar:\n    fc_angle:\n      v: 90.5\n",
        "design:\n  collar:\n    fc_angle:\n      v: 1:30\n",
        "design:\n  collar:\n    fc_angle:\n      v: 0b1011010\n",
    ] {
        agree(text, text);
    }
    // Files the full reader accepts take the fast path when in the subset.
    assert!(read_design_lines::<Design>("design:\n  meta:\n    upper:\n      v: Shirt\n", space).is_some());
    assert!(read_design_lines::<Design>("# c\ndesign:\n\n  meta:   \n    upper:\n      v: Shirt\n", space).is_some());
    assert!(read_design_lines::<Design>("design:\n  meta:  # c\n    upper:\n      v: Shirt # c\n", space).is_some());
    assert!(read_design_lines::<Design>("design:\n  meta:\n    upper:\n      v: Shirt# c\n", space).is_none());
}
