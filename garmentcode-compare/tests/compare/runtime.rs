//! The runtime's own reading + writing of every reference spec
//! must be judged equal to the file (exercises `compare_runtime_patterns`).

use garmentcode::Pattern;
use garmentcode_compare::{CompareOptions, compare_patterns, compare_runtime_patterns};

#[test]
fn runtime_round_trip_passes() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases");
    let entries = std::fs::read_dir(&dir).expect("the project's reference cases");
    let opts = CompareOptions::default();
    let mut n = 0;
    for e in entries {
        let path = e.unwrap().path().join("specification.json");
        let Ok(text) = std::fs::read_to_string(&path) else { continue };
        let p = Pattern::from_json(&text).unwrap();
        let v = compare_runtime_patterns(&p, &p, &opts);
        assert!(v.pass, "{}: {:?}", path.display(), v.reasons);
        let written: serde_json::Value = serde_json::from_str(&p.to_json().unwrap()).unwrap();
        let original: serde_json::Value = serde_json::from_str(&text).unwrap();
        let v = compare_patterns(&original, &written, &opts);
        assert!(v.pass && !v.chaotic, "{}: {:?}", path.display(), v.reasons);
        n += 1;
    }
    println!("{n} reference specs round-trip through the runtime's Pattern");
}
