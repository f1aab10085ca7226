//! Property test: parse(to_string(v)) == v for random values, plus the fast
//! path agreeing with the full parser on everything the writer produces
//! (and on hand-formatted variants of it).

use super::common::*;
use garmentcode::parity::yaml::{Node, Value, parse, testing, to_string};

/// Words typical of design files (what the fast path handles).
const SIMPLE: &[&str] = &[
    "FittedShirt",
    "Shirt",
    "SkirtCircle",
    "null",
    "true",
    "false",
    "select_null",
    "float",
    "0.5",
    "1.",
    "-0.35",
    "12",
    "a b",
    "x-y",
    "CircleNeckHalf",
    "1e3",
    "yes",
    "0x1F",
    "é-word",
    "~",
    "1_000",
    ".inf",
    "'quoted'",
    "it's",
];

fn random_string(rng: &mut Rng) -> String {
    if SIMPLE_MODE.with(|m| m.get()) {
        return SIMPLE[rng.below(SIMPLE.len())].to_string();
    }
    const PIECES: &[&str] = &[
        "a",
        "b",
        "FittedShirt",
        " ",
        "  ",
        ":",
        ": ",
        " #",
        "#",
        "-",
        "- ",
        "'",
        "\"",
        "\\",
        "\n",
        "\n\n",
        "\t",
        "é",
        "日本",
        "\u{2028}",
        "\u{85}",
        "\u{0}",
        "\u{7}",
        "\u{FEFF}",
        "\u{A0}",
        "\u{1F600}",
        "1",
        "1.0",
        "1e3",
        "0x1F",
        "0777",
        "1:30",
        "true",
        "yes",
        "no",
        "off",
        "null",
        "~",
        "[",
        "]",
        "{",
        "}",
        ",",
        "?",
        "!",
        "&",
        "*",
        "|",
        ">",
        "%",
        "@",
        "`",
        "---",
        "...",
        "=",
        "<<",
        "2001-12-14",
        ".inf",
        "-.5",
        ".nan",
        "\r",
        "\r\n",
    ];
    match rng.below(10) {
        0 => {
            // Long text with spaces (folded at 80 columns on output).
            let n = 10 + rng.below(30);
            (0..n).map(|_| ["alpha", "beta", "x", "yyyyyyyyyyyyyyyyyyyyyyyy", "d"][rng.below(5)]).collect::<Vec<_>>().join(" ")
        }
        1 => {
            // Long text with escapes and breaks (double-quoted, folded).
            (0..(20 + rng.below(40))).map(|_| ["ab", " ", "\n", "é", "\\", "\"", "cd "][rng.below(7)]).collect()
        }
        _ => (0..rng.below(6)).map(|_| PIECES[rng.below(PIECES.len())]).collect(),
    }
}

thread_local! {
    static SIMPLE_MODE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

fn random_float(rng: &mut Rng) -> f64 {
    match rng.below(5) {
        0 => f64::from_bits(rng.next()),
        1 => (rng.next() % 2_000_000) as f64 / 1000.0 - 1000.0,
        2 => [0.0, -0.0, 1.0, 0.1, 1e16, 1e15, 1e-4, 1e-5, 5e-324, f64::MAX, f64::INFINITY, f64::NEG_INFINITY, f64::NAN][rng.below(13)],
        _ => (rng.next() as f64 / u64::MAX as f64) * 10f64.powi(rng.below(60) as i32 - 30),
    }
}

fn random_scalar(rng: &mut Rng) -> Value {
    match rng.below(10) {
        0 => Value::Null,
        1 => Value::Bool(rng.chance(0.5)),
        2 => Value::Int(match rng.below(4) {
            0 => rng.next() as i64,
            1 => i64::MIN,
            2 => i64::MAX,
            _ => (rng.below(2000) as i64) - 1000,
        }),
        3 | 4 => Value::Float(random_float(rng)),
        _ => Value::Str(random_string(rng)),
    }
}

fn random_key(rng: &mut Rng) -> Value {
    if rng.chance(0.2) && !SIMPLE_MODE.with(|m| m.get()) {
        // Non-string keys, and keys near the 128-character explicit-key limit.
        return match rng.below(4) {
            0 => random_scalar(rng),
            1 => Value::Str("k".repeat(100 + rng.below(60))),
            _ => Value::Str(random_string(rng)),
        };
    }
    let base = ["v", "range", "type", "default_prob", "flare-skirt", "a b", "1", "null", "", "x"][rng.below(10)];
    let mut s = base.to_string();
    if rng.chance(0.3) {
        s.push_str(&random_string(rng));
    }
    Value::Str(s)
}

fn random_value(rng: &mut Rng, depth: usize) -> Value {
    if depth < 5 && rng.chance(0.35) {
        if rng.chance(0.5) {
            let n = rng.below(5);
            return Value::Seq((0..n).map(|_| Node::new(random_value(rng, depth + 1))).collect());
        }
        let n = rng.below(5);
        let mut pairs: Vec<(Node, Node)> = Vec::new();
        for _ in 0..n {
            let k = random_key(rng);
            // Keys must be unique (as Python dict keys).
            if pairs.iter().any(|(x, _)| key_eq(&x.value, &k)) {
                continue;
            }
            pairs.push((Node::new(k), Node::new(random_value(rng, depth + 1))));
        }
        return Value::Map(pairs);
    }
    random_scalar(rng)
}

/// Python dict key equality (1 == 1.0 == true).
fn key_eq(a: &Value, b: &Value) -> bool {
    let num = |v: &Value| match *v {
        Value::Bool(b) => Some(b as i64 as f64),
        Value::Int(i) => Some(i as f64),
        Value::Float(f) => Some(f),
        _ => None,
    };
    match (num(a), num(b)) {
        (Some(x), Some(y)) => x == y || (x.is_nan() && y.is_nan()),
        _ => a == b,
    }
}

#[test]
fn parse_of_to_string_is_identity() {
    let mut rng = Rng(0x1234_5678_9ABC_DEF1);
    let n = std::env::var("ROUNDTRIP_ITERS").ok().and_then(|v| v.parse().ok()).unwrap_or(20_000);
    let mut fast_used = 0;
    for i in 0..n {
        let v = random_value(&mut rng, 0);
        let text = to_string(&v);
        let back = parse(&text).unwrap_or_else(|e| panic!("case {}: cannot read back {:?}: {}\nvalue {:?}", i, text, e, v));
        assert!(same(&back.value, &v), "case {}: round trip changed the value\nvalue {:?}\ntext {:?}\nback {:?}", i, v, text, back.value);
        // Writing is deterministic and stable.
        assert_eq!(to_string(&back), text);
        if let Some(f) = testing::parse_fast(&text) {
            fast_used += 1;
            assert!(same_with_positions(&f, &testing::parse_full(&text).unwrap()), "case {}: fast path differs on {:?}", i, text);
        }
    }
    eprintln!("{} random values round-tripped ({} via the fast path)", n, fast_used);
}

/// Hand-written style variations of written documents (extra spaces, comments,
/// flow lists, quotes, CRLF) read the same through the fast and the full path.
#[test]
fn fast_path_agrees_on_reformatted_documents() {
    let mut rng = Rng(77);
    let mut fast_used = 0;
    for i in 0..20_000 {
        SIMPLE_MODE.with(|m| m.set(i % 4 != 0));
        let v = random_value(&mut rng, 0);
        let text = to_string(&v);
        let mut out = String::new();
        for line in text.lines() {
            let mut l = line.to_string();
            if rng.chance(0.2) {
                l = l.replacen(": ", ":   ", 1);
            }
            if rng.chance(0.2) {
                l.push_str("   ");
            }
            if rng.chance(0.2) {
                l.push_str(" # comment: - [x]");
            }
            out.push_str(&l);
            out.push_str(if rng.chance(0.1) { "\r\n" } else { "\n" });
            if rng.chance(0.1) {
                out.push_str(["\n", "# note\n", "   \n", "  # indented note\n"][rng.below(4)]);
            }
        }
        if rng.chance(0.3) {
            out = out.replace("- a\n", "- [a, 'b c', -1.5, \"d\"]\n");
        }
        let full = testing::parse_full(&out);
        if let Some(f) = testing::parse_fast(&out) {
            fast_used += 1;
            let full = full.unwrap_or_else(|e| panic!("case {}: fast accepted, full rejected ({}) {:?}", i, e, out));
            assert!(same_with_positions(&f, &full), "case {}: fast path differs on {:?}", i, out);
        }
    }
    eprintln!("fast path answered {} of 20000 reformatted documents, always like the full parser", fast_used);
}
