//! Agreement with compare_spec.py on the validation corpus (data/corpus.json, made by
//! tools/gen_compare_corpus.py): each pair is a reference case plus a compact patch on either side,
//! with the Python verdict. The pairs are laid out as case directories again here and
//! judged by `compare_case`; verdict, PASS* flag, max_dev, every reason and note must agree.
//!
//! The cases are the project's copy of the reference cases, `tests/data/cases`.

use garmentcode_compare::{CompareOptions, Euler, Verdict, compare_case};
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn ref_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases")
}

/// Apply ['set', path, value] / ['del', path] ops (the generator's `apply`).
fn apply(base: &Value, ops: &[Value]) -> Value {
    let mut spec = base.clone();
    for op in ops {
        let op = op.as_array().unwrap();
        let path = op[1].as_array().unwrap();
        if path.is_empty() {
            spec = op[2].clone();
            continue;
        }
        let mut node = &mut spec;
        for k in &path[..path.len() - 1] {
            node = match k {
                Value::String(s) => node.get_mut(s.as_str()).unwrap(),
                Value::Number(n) => node.get_mut(n.as_u64().unwrap() as usize).unwrap(),
                _ => panic!("bad path"),
            };
        }
        let last = &path[path.len() - 1];
        match (op[0].as_str().unwrap(), last) {
            ("set", Value::String(s)) => {
                node.as_object_mut().unwrap().insert(s.clone(), op[2].clone());
            }
            ("set", Value::Number(n)) => node[n.as_u64().unwrap() as usize] = op[2].clone(),
            ("del", Value::String(s)) => {
                node.as_object_mut().unwrap().shift_remove(s.as_str());
            }
            ("del", Value::Number(n)) => {
                node.as_array_mut().unwrap().remove(n.as_u64().unwrap() as usize);
            }
            _ => panic!("bad op"),
        }
    }
    spec
}

fn options(o: &Value) -> CompareOptions {
    let mut opts = CompareOptions::default();
    let f = |k: &str| o.get(k).and_then(Value::as_f64);
    if let Some(x) = f("tol") {
        opts.tol = x;
    }
    if o.get("euler").and_then(Value::as_str) == Some("xyz") {
        opts.euler = Euler::ExtrinsicXyz;
    }
    opts.strict = o.get("strict").and_then(Value::as_bool).unwrap_or(false);
    opts.chaotic_rule = o.get("chaotic_rule").and_then(Value::as_bool).unwrap_or(true);
    let c = &mut opts.chaos;
    for (k, slot) in [
        ("outline", &mut c.outline_tol),
        ("ratio", &mut c.ratio_tol),
        ("sliver", &mut c.sliver_len),
        ("stitch", &mut c.stitch_tol),
        ("seam_ratio", &mut c.seam_ratio_tol),
        ("gain", &mut c.fit_gain),
    ] {
        if let Some(x) = f(k) {
            *slot = x;
        }
    }
    opts
}

struct Base {
    specs: BTreeMap<String, Value>,
}

fn write_side(dir: &Path, src: &Value, base: &Base) {
    if src.get("missing").is_some() {
        return;
    }
    std::fs::create_dir_all(dir).unwrap();
    if let Some(case) = src.get("case").and_then(Value::as_str) {
        let ops = src.get("patch").and_then(Value::as_array).cloned().unwrap_or_default();
        let spec = apply(&base.specs[case], &ops);
        std::fs::write(dir.join("specification.json"), serde_json::to_string(&spec).unwrap()).unwrap();
        if let Some(e) = src.get("also_error").and_then(Value::as_str) {
            std::fs::write(dir.join("error.txt"), e).unwrap();
        }
    } else if let Some(e) = src.get("error").and_then(Value::as_str) {
        std::fs::write(dir.join("error.txt"), e).unwrap();
    } else if let Some(r) = src.get("raw").and_then(Value::as_str) {
        std::fs::write(dir.join("specification.json"), r).unwrap();
    }
}

/// 64-bit FNV-1a of the UTF-8 text, hex (the generator stores it instead of every reason).
fn fnv1a(text: &str) -> String {
    let mut h: u64 = 0xcbf29ce484222325;
    for b in text.bytes() {
        h = (h ^ b as u64).wrapping_mul(0x100000001b3);
    }
    format!("{h:016x}")
}

#[derive(Default)]
struct Tally {
    pairs: usize,
    py_pass: usize,
    py_star: usize,
    verdict: usize,
    first_reason: usize,
    all_text: usize,
    max_dev: usize,
}

#[test]
fn agrees_with_python_on_corpus() {
    let refdir = ref_dir();
    let t_load = std::time::Instant::now();
    let corpus: Value =
        serde_json::from_str(&std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/compare/data/corpus.json")).unwrap())
            .unwrap();
    let mut base = Base { specs: BTreeMap::new() };
    for d in std::fs::read_dir(&refdir).unwrap() {
        let d = d.unwrap().path();
        let sp = d.join("specification.json");
        if sp.is_file() {
            let v: Value = serde_json::from_str(&std::fs::read_to_string(sp).unwrap()).unwrap();
            base.specs.insert(d.file_name().unwrap().to_string_lossy().into_owned(), v);
        }
    }
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("corpus-rs");
    let _ = std::fs::remove_dir_all(&tmp);
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    let mut problems = Vec::new();
    println!("loading + cleanup: {:.3} s", t_load.elapsed().as_secs_f64());
    let t0 = std::time::Instant::now();
    let mut compare_time = std::time::Duration::ZERO;
    let mut slowest = Vec::new();
    for p in corpus["pairs"].as_array().unwrap() {
        let id = p["id"].as_str().unwrap();
        let opts = options(&p["opts"]);
        let root = tmp.join(id);
        write_side(&root.join("exp").join(id), &p["exp"], &base);
        write_side(&root.join("act").join(id), &p["act"], &base);
        let t = std::time::Instant::now();
        let v: Verdict = compare_case(&root.join("exp").join(id), &root.join("act").join(id), &opts);
        compare_time += t.elapsed();
        slowest.push((t.elapsed(), format!("{id} ({})", p["desc"].as_str().unwrap())));
        let roots = root.display().to_string();
        let norm = |s: &String| s.replace(&roots, "{ROOT}");
        let reasons: Vec<String> = v.reasons.iter().map(norm).collect();
        let notes: Vec<String> = v.notes.iter().map(norm).collect();
        let py = &p["python"];
        let py_first: Vec<String> = py["reasons"].as_array().unwrap().iter().map(|r| r.as_str().unwrap().to_string()).collect();
        let py_dev = py["max_dev"].as_f64().unwrap_or(f64::INFINITY);
        let t = tallies.entry(p["cat"].as_str().unwrap().to_string()).or_default();
        t.pairs += 1;
        t.py_pass += py["ok"].as_bool().unwrap() as usize;
        t.py_star += py["star"].as_bool().unwrap() as usize;
        let verdict_ok = v.pass == py["ok"].as_bool().unwrap() && v.chaotic == py["star"].as_bool().unwrap();
        let first_ok = reasons.first() == py_first.first();
        let text = format!("{}\u{1e}{}", reasons.join("\u{1f}"), notes.join("\u{1f}"));
        let all_ok = reasons.len() as u64 == py["n_reasons"].as_u64().unwrap()
            && notes.len() as u64 == py["n_notes"].as_u64().unwrap()
            && reasons.iter().take(3).eq(py_first.iter())
            && fnv1a(&text) == py["text_hash"].as_str().unwrap();
        let dev_ok = v.max_dev.to_bits() == py_dev.to_bits();
        t.verdict += verdict_ok as usize;
        t.first_reason += first_ok as usize;
        t.all_text += all_ok as usize;
        t.max_dev += dev_ok as usize;
        if !(verdict_ok && all_ok && dev_ok) {
            problems.push(format!(
                "{id} [{}] {}: rust pass={} star={} dev={} reasons={:?} notes={:?}\n    python pass={} star={} dev={} reasons[:3]={:?} ({} reasons, {} notes)",
                p["cat"].as_str().unwrap(),
                p["desc"].as_str().unwrap(),
                v.pass,
                v.chaotic,
                v.max_dev,
                reasons,
                notes,
                py["ok"],
                py["star"],
                py_dev,
                py_first,
                py["n_reasons"],
                py["n_notes"]
            ));
        }
    }
    println!(
        "| category | pairs | Python pass (PASS*) | verdict agrees | first reason agrees | all reasons+notes agree (count, first 3, hash) | max_dev bit-equal |"
    );
    println!("|---|---|---|---|---|---|---|");
    let mut total = Tally::default();
    for (c, t) in &tallies {
        println!(
            "| {c} | {} | {} ({}) | {} | {} | {} | {} |",
            t.pairs, t.py_pass, t.py_star, t.verdict, t.first_reason, t.all_text, t.max_dev
        );
        total.pairs += t.pairs;
        total.py_pass += t.py_pass;
        total.py_star += t.py_star;
        total.verdict += t.verdict;
        total.first_reason += t.first_reason;
        total.all_text += t.all_text;
        total.max_dev += t.max_dev;
    }
    println!(
        "| total | {} | {} ({}) | {} | {} | {} | {} |",
        total.pairs, total.py_pass, total.py_star, total.verdict, total.first_reason, total.all_text, total.max_dev
    );
    println!(
        "comparisons: {:.3} s for {} pairs (total with layout {:.3} s)",
        compare_time.as_secs_f64(),
        total.pairs,
        t0.elapsed().as_secs_f64()
    );
    slowest.sort();
    slowest.reverse();
    let mut times: Vec<_> = slowest.iter().map(|(d, _)| d.as_secs_f64()).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "per pair: median {:.1} ms, 90th percentile {:.1} ms; slowest: {}",
        times[times.len() / 2] * 1e3,
        times[times.len() * 9 / 10] * 1e3,
        slowest.iter().take(3).map(|(d, n)| format!("{n} {:.0} ms", d.as_secs_f64() * 1e3)).collect::<Vec<_>>().join(", ")
    );
    for p in &problems {
        println!("DISAGREE {p}");
    }
    assert!(problems.is_empty(), "{} disagreements", problems.len());
}
