//! A small mutational fuzzer on stable Rust, for the four kinds of input users
//! and web pages give: design YAML, body YAML, specification JSON and API
//! requests. Seeds are the reference cases, the built-in designs and bodies and
//! the reproducers of issue 16 (tests/data/hardening); each execution mutates one
//! seed (bit flips, byte and token insertions, deletions, duplicated ranges,
//! interesting numbers in place of numbers) and runs it through what the tool
//! does with it: parse, check, build, draw. A finding is a panic or an execution
//! slower than [`SLOW`]; findings are written to `target/tmp/fuzz-findings/` and
//! fail the test.
//!
//! The CI-sized run (`cargo test --test fuzz`) does [`DEFAULT_EXECS`] executions
//! per target within a few seconds. A long run (see the README):
//! `GARMENTCODE_FUZZ_EXECS=200000 GARMENTCODE_FUZZ_SEED=7 cargo test --release --test fuzz -- --nocapture`.

use garmentcode::{Body, Pattern};
use garmentcode_cli::web::{api::route, http::Request};
use std::panic::AssertUnwindSafe;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Executions per target in the CI-sized run.
const DEFAULT_EXECS: usize = 2_000;
/// Slower than this is a finding: a second (the issue's bound) times a margin of 3
/// for an unoptimised test build on a loaded, shared machine.
const SLOW: Duration = Duration::from_secs(3);

/// xorshift64*: small, fast, deterministic.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

const TOKENS: &[&str] = &[
    "1e308",
    "-1e308",
    "1e-300",
    "0",
    "-0.0",
    "-1",
    "0.3",
    "0.000001",
    "1000000.0",
    "NaN",
    ".nan",
    ".inf",
    "-.inf",
    "null",
    "~",
    "true",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    ": ",
    "\n",
    "\n  ",
    "\n    v: ",
    "- ",
    "&a ",
    "*a",
    "!!python/object ",
    "'",
    "\"",
    "#",
    "\t",
    "\u{0}",
    "\u{feff}",
    "é",
    "v: ",
    "range: [",
    "type: float",
    "9999999999999999999999",
    "1.7976931348623157e308",
];

const NUMBERS: &[&str] = &["0", "-1", "1e308", "1e-300", "0.606592", "0.3", "1e6", "-0.0", "123456789", "0.5", "2", "1e-6"];

fn mutate(rng: &mut Rng, seed: &[u8]) -> Vec<u8> {
    let mut d = seed.to_vec();
    for _ in 0..1 + rng.below(4) {
        let n = d.len();
        match rng.below(7) {
            0 if n > 0 => {
                let i = rng.below(n);
                d[i] ^= 1 << rng.below(8);
            }
            1 => {
                let t = TOKENS[rng.below(TOKENS.len())].as_bytes();
                let i = rng.below(n + 1);
                d.splice(i..i, t.iter().copied());
            }
            2 if n > 0 => {
                let i = rng.below(n);
                let len = 1 + rng.below(64.min(n - i));
                d.drain(i..i + len);
            }
            3 if n > 0 => {
                // Duplicate a range (repeated keys, long lists).
                let i = rng.below(n);
                let len = 1 + rng.below(256.min(n - i));
                let piece: Vec<u8> = d[i..i + len].to_vec();
                for _ in 0..1 + rng.below(8) {
                    let at = rng.below(d.len() + 1);
                    d.splice(at..at, piece.iter().copied());
                }
            }
            _ => {
                // Replace a number with an interesting one.
                let starts: Vec<usize> =
                    (0..n).filter(|&i| d[i].is_ascii_digit() && (i == 0 || !d[i - 1].is_ascii_alphanumeric())).collect();
                if let Some(&i) = starts.get(rng.below(starts.len())) {
                    let mut j = i;
                    while j < n && (d[j].is_ascii_digit() || b".eE-+".contains(&d[j])) {
                        j += 1;
                    }
                    d.splice(i..j, NUMBERS[rng.below(NUMBERS.len())].bytes());
                }
            }
        }
    }
    d
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read_all(dir: &Path, name: &str) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            if let Ok(b) = std::fs::read(p.join(name)) {
                out.push(b);
            }
        }
    }
    out
}

fn hardening(ext: &str, contains: &str) -> Vec<Vec<u8>> {
    let dir = root().join("tests/data/hardening");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    files
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == ext) && p.to_string_lossy().contains(contains))
        .map(|p| std::fs::read(p).unwrap())
        .collect()
}

fn design_seeds() -> Vec<Vec<u8>> {
    let mut s: Vec<Vec<u8>> = read_all(&root().join("tests/data/cases"), "design.yaml").into_iter().step_by(6).collect();
    s.extend(garments::builtin::DESIGNS.iter().map(|(_, t)| t.as_bytes().to_vec()));
    s.extend(hardening("yaml", "design"));
    s
}

fn body_seeds() -> Vec<Vec<u8>> {
    let mut s: Vec<Vec<u8>> = garments::builtin::BODIES
        .iter()
        .map(|(n, _)| std::fs::read(root().join(format!("garments/data/bodies/{n}.yaml"))).unwrap())
        .collect();
    s.extend(hardening("yaml", "mean_female"));
    s
}

fn spec_seeds() -> Vec<Vec<u8>> {
    let mut s: Vec<Vec<u8>> = read_all(&root().join("tests/data/cases"), "specification.json").into_iter().step_by(8).collect();
    s.extend(hardening("json", ""));
    s
}

fn design_of(text: &str) -> Option<garments::Design> {
    use garmentcode::Params;
    garmentcode::io::read_design(text, "fuzz.yaml", &garments::Design::design_space()).ok()
}

/// What the tool does with each kind of input.
/// Each returns whether the input got past parsing (how deep the run went).
fn run_design(input: &[u8]) -> bool {
    let text = String::from_utf8_lossy(input);
    let Some(d) = design_of(&text) else { return false };
    let body = garments::builtin::body("mean_all").unwrap();
    let _ = garments::build::build(&d, &body, "fuzz");
    true
}

fn run_body(input: &[u8]) -> bool {
    let text = String::from_utf8_lossy(input);
    let Ok(b) = Body::from_yaml(&text, "fuzz.yaml") else { return false };
    let d = garments::builtin::design("sundress").unwrap();
    let _ = garments::build::build(&d, &b, "fuzz");
    let _ = b.to_yaml();
    true
}

fn run_spec(input: &[u8]) -> bool {
    let text = String::from_utf8_lossy(input);
    let Ok(p) = Pattern::from_json(&text) else { return false };
    let _ = garmentcode::validate(&p);
    let _ = p.to_json();
    let _ = garmentcode::draw::to_svg(&p, &Default::default());
    true
}

fn run_request(rng: &mut Rng, input: &[u8]) -> bool {
    const PATHS: &[&str] =
        &["/api/pattern", "/api/design", "/api/body", "/api/random", "/api/files", "/api/zip", "/api/schema", "/api/%zz", "/"];
    let method = if rng.below(8) == 0 { "GET" } else { "POST" };
    let req = Request {
        method: method.into(),
        path: PATHS[rng.below(PATHS.len())].into(),
        headers: vec![("content-type".into(), "application/json".into())],
        body: input.to_vec(),
    };
    let r = route(&req);
    assert!((200..600).contains(&r.status));
    r.status == 200
}

fn request_seeds() -> Vec<Vec<u8>> {
    let design = String::from_utf8(hardening("yaml", "case-021").remove(0)).unwrap();
    let metres = String::from_utf8(hardening("yaml", "metres").remove(0)).unwrap();
    vec![
        br#"{"design": {"meta.upper": "Shirt", "shirt.length": 1.2}, "body": "mean_female"}"#.to_vec(),
        br#"{"design": "t-shirt", "body": {"base": "mean_all", "measurements": {"waist": 70.0, "leg_circ": 0.606592}}}"#.to_vec(),
        serde_json::json!({ "design": design, "body": { "yaml": metres } }).to_string().into_bytes(),
        br#"{"seed": 3, "body": "mean_male", "layout": "flat"}"#.to_vec(),
        br#"{"design": {"meta.bottom": "Pants"}, "name": "trousers"}"#.to_vec(),
    ]
}

/// Run `execs` mutated inputs through `target`; returns the findings.
fn fuzz(name: &str, seeds: &[Vec<u8>], execs: usize, rng: &mut Rng, mut target: impl FnMut(&mut Rng, &[u8]) -> bool) -> Vec<String> {
    assert!(!seeds.is_empty(), "{name}: no seeds");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-findings");
    let mut findings = Vec::new();
    let mut slowest = Duration::ZERO;
    let mut deep = 0usize;
    let start = Instant::now();
    for i in 0..execs {
        let seed = &seeds[rng.below(seeds.len())];
        // Every tenth input is a seed as it is (the reproducers must stay fixed).
        let input = if i % 10 == 0 { seed.clone() } else { mutate(rng, seed) };
        let t = Instant::now();
        let mut sub = Rng(rng.next() | 1);
        let result = std::panic::catch_unwind(AssertUnwindSafe(|| target(&mut sub, &input)));
        let took = t.elapsed();
        slowest = slowest.max(took);
        deep += usize::from(matches!(result, Ok(true)));
        let problem = match result {
            Err(_) => Some("panic"),
            Ok(_) if took > SLOW => Some("slow"),
            Ok(_) => None,
        };
        if let Some(kind) = problem {
            std::fs::create_dir_all(&dir).unwrap();
            let file = dir.join(format!("{name}-{kind}-{i}"));
            std::fs::write(&file, &input).unwrap();
            findings.push(format!("{name}: {kind} ({took:?}), input in {}", file.display()));
        }
    }
    eprintln!(
        "fuzz {name}: {execs} executions ({deep} past parsing) in {:.1} s, slowest {:.0} ms, {} finding(s)",
        start.elapsed().as_secs_f64(),
        slowest.as_secs_f64() * 1e3,
        findings.len()
    );
    findings
}

#[test]
fn fuzz_every_kind_of_input() {
    let execs: usize = std::env::var("GARMENTCODE_FUZZ_EXECS").ok().and_then(|v| v.parse().ok()).unwrap_or(DEFAULT_EXECS);
    let seed: u64 = std::env::var("GARMENTCODE_FUZZ_SEED").ok().and_then(|v| v.parse().ok()).unwrap_or(16);
    let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
    // Panics are findings, not noise: keep the output readable.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut findings = Vec::new();
    findings.extend(fuzz("design", &design_seeds(), execs, &mut rng, |_, i| run_design(i)));
    findings.extend(fuzz("body", &body_seeds(), execs, &mut rng, |_, i| run_body(i)));
    findings.extend(fuzz("spec", &spec_seeds(), execs, &mut rng, |_, i| run_spec(i)));
    findings.extend(fuzz("request", &request_seeds(), execs, &mut rng, run_request));
    std::panic::set_hook(hook);
    assert!(findings.is_empty(), "{} finding(s):\n{}", findings.len(), findings.join("\n"));
}

#[test]
fn mutations_are_deterministic_and_change_the_input() {
    let seed = b"design:\n  shirt:\n    length:\n      v: 1.2\n".to_vec();
    let (mut a, mut b) = (Rng(5), Rng(5));
    let (x, y): (Vec<Vec<u8>>, Vec<Vec<u8>>) =
        ((0..50).map(|_| mutate(&mut a, &seed)).collect(), (0..50).map(|_| mutate(&mut b, &seed)).collect());
    assert_eq!(x, y);
    assert!(x.iter().filter(|m| **m != seed).count() > 40);
}
