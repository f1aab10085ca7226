//! Robustness: random mutations of real files never panic, and whatever is
//! accepted survives a write/read round trip. An ignored test compares the
//! same kind of mutated inputs against PyYAML itself (needs a Python with PyYAML
//! 6.0 in `PYYAML_PYTHON`; ignored by default).

use super::common::*;
use garmentcode::parity::yaml::{parse, to_string};
use std::io::Write;
use std::process::{Command, Stdio};

/// Small hand-written documents covering the syntax the real files do not use.
const EXTRA_SAMPLES: &[&str] = &[
    "a: [1, 2.5, 'x', \"y\\n\", {b: c, d: [e, f]}]\nz: {p: 1.,\n  q: [true, null, ~]}\n",
    "---\n# comment\nkey: 'it''s'   # trailing comment\nother: \"tab\\there \\u00e9\"\nlist:\n  - a\n  - - b\n    - c\n  - k: v\n    k2: v2\n...\n",
    "\u{FEFF}body:\r\n  height: 165  \r\n  waist:  80  # cm\r\n  note: multi word value\r\n",
    "x: 0x1F\ny: 0777\nz: 1_000.5\nw: -.inf\nv: .nan\nu: 1:30\nt: yes\ns: 1e3\nr: -.5\nq: ''\n",
    "plain: folded\n  continuation line\n\n  after blank\nq: 'single\n  folded'\nd: \"double \\\n  escaped break\"\n",
    "- [a, b]\n- {c: d}\n- [a: 1, b]\n- {e, f: }\n-\n- - - deep\n",
    "a: [1, # comment\n  2, 'x\n\n  y',\n  {k: v, \"q\": [z]}\n ]\nb: {x: 1,\n    y: [2, 3]}  # done\n",
    "--- {a: 1}\n...\n",
    "\u{FEFF}---\r\nkey  : 'multi\r\n   line'\r\nk2 : \"esc \\x41\\u00E9\\U0001F600 \\\r\n  tail\"\r\n",
    "? a\n: b\n",
    "-   a: 1\n    b:\n    - x\n    -   y: 2\n        z: 3\n",
    "a:\n  - 1\n  -\n  - - 2\n    - 3\nb: !!str 5\nc: &x [1]\nd: *x\n",
    "x: 'a''b'\ny: \"a\\\"b\"\nz: '  lead and trail  '\nw: \"\\t\\n\"\n",
    "1: one\n2.5: two\ntrue: t\nnull: n\n~: m\n0x10: hex\n",
    "top:\n    deep: 1\n    other:\n        - a\n        - b\n    last: [x, y]\n",
];

fn samples() -> Vec<String> {
    let mut out: Vec<String> = EXTRA_SAMPLES.iter().map(|s| s.to_string()).collect();
    let files = reference_files();
    for (i, (name, p)) in files.iter().enumerate() {
        // All hand-written files, plus a few generated designs.
        if !name.starts_with("cases/") || i % 20 == 0 {
            out.push(std::fs::read_to_string(p).unwrap());
        }
    }
    out
}

const INTERESTING: &[&str] = &[
    ":",
    ": ",
    "-",
    "- ",
    " ",
    "  ",
    "\n",
    "\r\n",
    "\r",
    "\t",
    "#",
    " #",
    "'",
    "\"",
    "\\",
    "[",
    "]",
    "{",
    "}",
    ",",
    "?",
    "? ",
    "!",
    "&a ",
    "*a",
    "|",
    ">",
    "%",
    "@",
    "`",
    "---",
    "...",
    "~",
    "=",
    "<<",
    "0x",
    "0b",
    "0o",
    "1e3",
    ".5",
    "-.inf",
    ".nan",
    "1:30",
    "2001-12-14",
    "yes",
    "null",
    "\u{FEFF}",
    "é",
    "\u{2028}",
    "\u{0}",
    "\\u",
    "\\x4",
    "_",
    "+",
    "1.",
    "\n  ",
    "\n- ",
    "\nkey: ",
];

/// One random edit: replace/insert/delete characters, truncate, or shuffle lines.
pub fn mutate(rng: &mut Rng, s: &str) -> String {
    let mut chars: Vec<char> = s.chars().collect();
    let edits = 1 + rng.below(4);
    for _ in 0..edits {
        let n = chars.len();
        match rng.below(9) {
            0 if n > 0 => {
                // Flip one byte of a character's encoding (may create U+FFFD).
                let i = rng.below(n);
                let mut buf = [0u8; 4];
                let bytes = chars[i].encode_utf8(&mut buf).as_bytes().to_vec();
                let mut b = bytes.clone();
                let j = rng.below(b.len());
                b[j] ^= 1 << rng.below(8);
                let repl: Vec<char> = String::from_utf8_lossy(&b).chars().collect();
                chars.splice(i..i + 1, repl);
            }
            1 | 2 => {
                let i = rng.below(n + 1);
                let ins: Vec<char> = INTERESTING[rng.below(INTERESTING.len())].chars().collect();
                chars.splice(i..i, ins);
            }
            3 if n > 0 => {
                let i = rng.below(n);
                let len = 1 + rng.below(4.min(n - i));
                chars.drain(i..i + len);
            }
            4 if n > 0 => {
                chars.truncate(rng.below(n));
            }
            5 if n > 0 => {
                let i = rng.below(n);
                chars[i] = (rng.below(0x80) as u8) as char;
            }
            6 => {
                // Change the indentation of a random line.
                let text: String = chars.iter().collect();
                let mut lines: Vec<String> = text.split('\n').map(|l| l.to_string()).collect();
                let k = rng.below(lines.len());
                if rng.chance(0.5) {
                    lines[k].insert(0, ' ');
                } else if lines[k].starts_with(' ') {
                    lines[k].remove(0);
                }
                chars = lines.join("\n").chars().collect();
            }
            7 => {
                // Duplicate or swap lines.
                let text: String = chars.iter().collect();
                let mut lines: Vec<String> = text.split('\n').map(|l| l.to_string()).collect();
                let a = rng.below(lines.len());
                let b = rng.below(lines.len());
                if rng.chance(0.5) {
                    lines.swap(a, b);
                } else {
                    let l = lines[a].clone();
                    lines.insert(b, l);
                }
                chars = lines.join("\n").chars().collect();
            }
            _ => {
                let i = rng.below(n + 1);
                let c = char::from_u32(rng.below(0x3000) as u32).unwrap_or('x');
                chars.insert(i, c);
            }
        }
    }
    chars.into_iter().collect()
}

/// A random window of lines (short inputs reach more parser states per run).
fn window(rng: &mut Rng, s: &str) -> String {
    let lines: Vec<&str> = s.split_inclusive('\n').collect();
    if lines.len() <= 12 {
        return s.to_string();
    }
    let a = rng.below(lines.len());
    let len = 1 + rng.below(12);
    lines[a..(a + len).min(lines.len())].concat()
}

#[test]
fn mutations_never_panic_and_accepted_inputs_round_trip() {
    let samples = samples();
    let mut rng = Rng(0x9E3779B97F4A7C15);
    let iterations = std::env::var("FUZZ_ITERS").ok().and_then(|v| v.parse().ok()).unwrap_or(30_000);
    let (mut ok, mut err, mut fast_used) = (0usize, 0usize, 0usize);
    for it in 0..iterations {
        let base = &samples[rng.below(samples.len())];
        let input = if rng.chance(0.7) { window(&mut rng, base) } else { base.clone() };
        let input = mutate(&mut rng, &input);
        let result = std::panic::catch_unwind(|| parse(&input));
        let parsed = match result {
            Ok(r) => r,
            Err(_) => panic!("iteration {}: parse panicked on {:?}", it, input),
        };
        // The fast path must agree with the full parser whenever it answers.
        let full = std::panic::catch_unwind(|| garmentcode::parity::yaml::testing::parse_full(&input))
            .unwrap_or_else(|_| panic!("iteration {}: full parser panicked on {:?}", it, input));
        if let Some(fast) = garmentcode::parity::yaml::testing::parse_fast(&input) {
            fast_used += 1;
            match &full {
                Ok(f) => assert!(
                    same_with_positions(&fast, f),
                    "iteration {}: fast path differs from the full parser on {:?}\nfast {:?}\nfull {:?}",
                    it,
                    input,
                    fast,
                    f
                ),
                Err(e) => panic!("iteration {}: fast path accepted {:?} but the full parser says {}", it, input, e),
            }
        }
        match (&parsed, &full) {
            (Ok(a), Ok(b)) => assert!(same_with_positions(a, b)),
            (Err(a), Err(b)) => assert_eq!(a, b),
            _ => panic!("iteration {}: parse and parse_full disagree on {:?}", it, input),
        }
        match parsed {
            Ok(node) => {
                ok += 1;
                let out = std::panic::catch_unwind(|| to_string(&node))
                    .unwrap_or_else(|_| panic!("iteration {}: to_string panicked for {:?}", it, input));
                match parse(&out) {
                    Ok(back) => assert!(
                        same(&back.value, &node.value),
                        "iteration {}: round trip changed the value\ninput {:?}\nwritten {:?}",
                        it,
                        input,
                        out
                    ),
                    Err(e) => panic!("iteration {}: cannot re-read our output ({})\ninput {:?}\nwritten {:?}", it, e, input, out),
                }
            }
            Err(e) => {
                err += 1;
                assert!(e.line >= 1 && e.col >= 1 && !e.message.is_empty());
            }
        }
    }
    eprintln!(
        "fuzz: {} iterations, {} accepted (all round-tripped), {} rejected, 0 panics; fast path answered {} times, always like the full parser",
        iterations, ok, err, fast_used
    );
}

/// Pathological inputs: deep nesting, long lines, many keys.
#[test]
fn pathological_inputs() {
    let deep = "[".repeat(100_000);
    assert!(parse(&deep).is_err());
    let deep_ok = format!("{}{}", "[".repeat(200), "]".repeat(200));
    assert!(parse(&deep_ok).is_ok());
    let deep_block: String = (0..2000).map(|i| format!("{}k:\n", " ".repeat(i))).collect();
    let e = parse(&deep_block).unwrap_err();
    assert!(e.message.contains("nesting"), "{}", e);
    let dashes = "- ".repeat(50_000);
    assert!(parse(&dashes).is_err());
    let long_key = format!("{}: 1", "k".repeat(2000));
    assert!(parse(&long_key).is_err());
    let many: String = (0..20_000).map(|i| format!("key{}: {}\n", i, i)).collect();
    let t = std::time::Instant::now();
    let n = parse(&many).unwrap();
    assert_eq!(n.as_map().unwrap().len(), 20_000);
    assert!(t.elapsed().as_secs_f64() < 5.0);
    let mut dup = many.clone();
    dup.push_str("key7: 1\n");
    assert!(parse(&dup).unwrap_err().message.contains("duplicate"));
}

fn run_oracle(mode: &str, input: &str) -> Option<String> {
    let python = std::env::var("PYYAML_PYTHON").unwrap_or_else(|_| "python3".into());
    let script = format!("{}/../tools/pyyaml_oracle.py", env!("CARGO_MANIFEST_DIR"));
    let mut child = Command::new(python).arg(script).arg(mode).stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().ok()?;
    child.stdin.take()?.write_all(input.as_bytes()).ok()?;
    let out = child.wait_with_output().ok()?;
    assert!(out.status.success(), "oracle failed");
    Some(String::from_utf8(out.stdout).unwrap())
}

/// Differential fuzzing against PyYAML: for every mutated input, if we accept
/// it PyYAML must give the same value; if PyYAML rejects it we must reject it.
/// Run with `cargo test --release --test fuzz -- --ignored --nocapture`.
#[test]
#[ignore]
fn differential_against_pyyaml() {
    let samples = samples();
    let mut rng = Rng(0xDEADBEEF12345);
    let total: usize = std::env::var("DIFF_ITERS").ok().and_then(|v| v.parse().ok()).unwrap_or(20_000);
    let mut docs = Vec::with_capacity(total);
    for _ in 0..total {
        let base = &samples[rng.below(samples.len())];
        let w = window(&mut rng, base);
        let w = if w.len() > 600 { w[..w.char_indices().nth(600).map(|(i, _)| i).unwrap_or(w.len())].to_string() } else { w };
        let m = if rng.chance(0.1) { w } else { mutate(&mut rng, &w) };
        docs.push(m);
    }
    let json = format!("[{}]", docs.iter().map(|d| json_string(d)).collect::<Vec<_>>().join(","));
    let Some(out) = run_oracle("load", &json) else {
        eprintln!("PyYAML oracle not available; skipping");
        return;
    };
    let results = parse_json(&out);
    let mut stats = [0usize; 5]; // both ok, both err, ours unsupported, dup, mismatch
    let mut mismatches = Vec::new();
    let mut unsupported: std::collections::BTreeMap<String, usize> = Default::default();
    for (doc, exp) in docs.iter().zip(results.arr()) {
        let ours = parse(doc);
        match (exp.get("ok"), ours) {
            (Some(t), Ok(n)) => match untag(t) {
                Ok(v) if same(&n.value, &v) => stats[0] += 1,
                other => {
                    stats[4] += 1;
                    mismatches.push(format!("{:?}\n  ours {:?}\n  PyYAML {:?}", doc, n.value, other));
                }
            },
            (Some(t), Err(e)) => {
                if is_unsupported(&e.message) || untag(t).is_err() {
                    stats[2] += 1;
                    let key: String = e.message.split([':', '(', ';']).next().unwrap_or("").to_string();
                    *unsupported.entry(key).or_default() += 1;
                } else {
                    stats[4] += 1;
                    mismatches.push(format!("{:?}\n  we rejected: {}\n  PyYAML accepted {:?}", doc, e, untag(t)));
                }
            }
            (None, Ok(n)) => {
                stats[4] += 1;
                mismatches.push(format!("{:?}\n  we accepted {:?}\n  PyYAML: {}", doc, n.value, exp.get("err").unwrap().str()));
            }
            (None, Err(_)) => {
                if exp.get("err").unwrap().str().starts_with("duplicate") {
                    stats[3] += 1;
                } else {
                    stats[1] += 1;
                }
            }
        }
    }
    eprintln!(
        "differential: {} inputs: {} same value, {} both rejected, {} duplicate keys rejected, {} unsupported by us but accepted by PyYAML, {} mismatches",
        total, stats[0], stats[1], stats[3], stats[2], stats[4]
    );
    for (k, v) in &unsupported {
        eprintln!("  unsupported {:5}  {}", v, k);
    }
    assert!(
        mismatches.is_empty(),
        "{} mismatches, first ones:\n{}",
        mismatches.len(),
        mismatches.iter().take(15).cloned().collect::<Vec<_>>().join("\n")
    );
}

/// Our writer's output, read by PyYAML, gives back the value we wrote.
#[test]
#[ignore]
fn pyyaml_reads_our_output() {
    let samples = samples();
    let mut rng = Rng(42);
    let mut values = Vec::new();
    for _ in 0..3000 {
        let base = &samples[rng.below(samples.len())];
        let w = window(&mut rng, base);
        let m = mutate(&mut rng, &w);
        if let Ok(n) = parse(&m) {
            values.push(n);
        }
    }
    // Plus the random values of the emitter table (long/multi-line/empty keys
    // that PyYAML would write as `? key` and we write as plain keys).
    let table = parse_json(&std::fs::read_to_string(data_path("emit.json")).unwrap());
    for e in table.arr() {
        values.push(garmentcode::parity::yaml::Node::new(untag(e.get("value").unwrap()).unwrap()));
    }
    let docs: Vec<String> = values.iter().map(to_string).collect();
    let json = format!("[{}]", docs.iter().map(|d| json_string(d)).collect::<Vec<_>>().join(","));
    let Some(out) = run_oracle("load", &json) else {
        eprintln!("PyYAML oracle not available; skipping");
        return;
    };
    let results = parse_json(&out);
    let mut bad = Vec::new();
    for ((v, d), exp) in values.iter().zip(&docs).zip(results.arr()) {
        match exp.get("ok").map(untag) {
            Some(Ok(back)) if same(&back, &v.value) => {}
            other => bad.push(format!("{:?}\n  PyYAML read {:?}", d, other)),
        }
    }
    eprintln!("PyYAML read {} of our documents, {} differences", values.len(), bad.len());
    assert!(bad.is_empty(), "{}", bad.iter().take(10).cloned().collect::<Vec<_>>().join("\n"));
}
