//! Comparisons with PyYAML results recorded by `tools/pyyaml_oracle.py`
//! (see `tools/README.md` for how to regenerate `tests/yaml/data/*.json`).

use super::common::*;
use garmentcode::parity::yaml::{Node, Value, parse, to_string};

/// Every YAML file under the reference directory reads exactly as PyYAML `safe_load`.
#[test]
fn reference_files_match_pyyaml() {
    let expected = parse_json(&std::fs::read_to_string(data_path("reference_expected.json")).unwrap());
    let files = reference_files();
    let mut checked = 0;
    for (rel, path) in &files {
        let exp = expected.get(rel).unwrap_or_else(|| panic!("no PyYAML result recorded for {}", rel));
        let text = std::fs::read_to_string(path).unwrap();
        let ours = parse(&text).unwrap_or_else(|e| panic!("{}: {}", rel, e));
        let theirs = untag(exp.get("ok").unwrap_or_else(|| panic!("PyYAML failed on {}", rel))).unwrap();
        assert!(same(&ours.value, &theirs), "{} differs from PyYAML", rel);
        checked += 1;
    }
    assert_eq!(checked, expected.arr_len_or_obj());
    eprintln!("{} reference files identical to PyYAML safe_load", checked);
}

trait ObjLen {
    fn arr_len_or_obj(&self) -> usize;
}
impl ObjLen for Json {
    fn arr_len_or_obj(&self) -> usize {
        match self {
            Json::Obj(p) => p.len(),
            Json::Arr(a) => a.len(),
            _ => 0,
        }
    }
}

/// Result of our parser against a recorded PyYAML load result. Returns a
/// description of a mismatch, or None when acceptable.
fn check_load(doc: &str, exp: &Json) -> Option<String> {
    let ours = parse(doc);
    match (exp.get("ok"), &ours) {
        (Some(t), Ok(n)) => match untag(t) {
            Ok(v) if same(&n.value, &v) => None,
            Ok(v) => Some(format!("value differs: ours {:?}, PyYAML {:?}", n.value, v)),
            Err(why) => Some(format!("we accepted, PyYAML gave an unrepresentable value ({})", why)),
        },
        (Some(t), Err(e)) => {
            if is_unsupported(&e.message) || untag(t).is_err() {
                None
            } else {
                Some(format!("we rejected ({}), PyYAML accepted {:?}", e, untag(t)))
            }
        }
        (None, Ok(n)) => Some(format!("we accepted {:?}, PyYAML failed: {}", n.value, exp.get("err").unwrap().str())),
        (None, Err(_)) => None,
    }
}

/// The table of tricky scalars: resolution (`x: <s>`) and quoting on output.
#[test]
fn scalar_table_matches_pyyaml() {
    let table = parse_json(&std::fs::read_to_string(data_path("scalars.json")).unwrap());
    let mut failures = Vec::new();
    let mut ok = 0;
    for e in table.arr() {
        let s = e.get("s").unwrap().str();
        let doc = format!("x: {}", s);
        if let Some(why) = check_load(&doc, e.get("load").unwrap()) {
            failures.push(format!("load {:?}: {}", doc, why));
        }
        let v = Value::Map(vec![(Node::new(Value::Str("x".into())), Node::new(Value::Str(s.to_string())))]);
        let out = to_string(&v);
        let dump = e.get("dump").unwrap().str();
        if out != dump {
            failures.push(format!("dump {:?}: ours {:?}, PyYAML {:?}", s, out, dump));
        }
        // And what we write reads back as the same string.
        match parse(&out) {
            Ok(n) if same(&n.value, &v) => {}
            other => failures.push(format!("round trip of {:?} via {:?}: {:?}", s, out, other)),
        }
        ok += 1;
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
    eprintln!("{} scalars agree with PyYAML (resolution, quoting, round trip)", ok);
}

fn has_explicit_key_in_pyyaml(v: &Value) -> bool {
    match v {
        Value::Seq(items) => items.iter().any(|n| has_explicit_key_in_pyyaml(&n.value)),
        Value::Map(pairs) => pairs.iter().any(|(k, v)| {
            let long = match &k.value {
                Value::Str(s) => s.is_empty() || s.contains(['\n', '\u{85}', '\u{2028}', '\u{2029}']) || s.chars().count() >= 123,
                _ => false,
            };
            long || has_explicit_key_in_pyyaml(&v.value)
        }),
        _ => false,
    }
}

/// Random values: our writer produces PyYAML's `dump` text byte for byte
/// (except the documented explicit-key difference), and our reader reads
/// PyYAML's output as PyYAML does.
#[test]
fn emitter_table_matches_pyyaml() {
    let table = parse_json(&std::fs::read_to_string(data_path("emit.json")).unwrap());
    let mut failures = Vec::new();
    let (mut exact, mut skipped) = (0, 0);
    for e in table.arr() {
        let value = untag(e.get("value").unwrap()).expect("representable");
        let dump = e.get("dump").unwrap().str();
        if let Some(why) = check_load(dump, e.get("load").unwrap()) {
            failures.push(format!("reading PyYAML's dump {:?}: {}", dump, why));
        }
        let out = to_string(&value);
        if has_explicit_key_in_pyyaml(&value) {
            skipped += 1;
        } else if out != dump {
            failures.push(format!("dump of {:?}:\n ours   {:?}\n PyYAML {:?}", value, out, dump));
        } else {
            exact += 1;
        }
        match parse(&out) {
            Ok(n) if same(&n.value, &value) => {}
            other => failures.push(format!("round trip of {:?} via {:?}: {:?}", value, out, other)),
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n\n"));
    eprintln!("{} dumps byte-identical to PyYAML, {} with PyYAML '? key' forms (round trip only)", exact, skipped);
}
