//! The built-in named designs on the neutral body: each builds, passes the
//! reference's checks, matches the reference implementation's pattern for the same
//! design (`tests/data/named`), and emits a pinned `specification.json` (insta
//! snapshots guard against regressions anywhere in the library).

use garments::builtin;

#[test]
fn named_designs_are_pinned() {
    let body = builtin::body(builtin::DEFAULT_BODY).unwrap();
    assert!(builtin::DESIGNS.len() >= 5);
    for (name, _) in builtin::DESIGNS {
        let design = builtin::design(name).unwrap();
        if design.extension != <garments::design::Extension as garmentcode::Params>::defaults() {
            // Past the reference (no reference pattern): `tests/extension_designs.rs`.
            continue;
        }
        let built = garments::build::build(&design, &body, name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(built.checks.passed(), "{name}: {:?}", built.checks.warnings());
        let problems = garmentcode::validate(&built.pattern);
        assert!(problems.iter().all(|p| p.severity != garmentcode::Severity::Error), "{name}: {problems:?}");
        let reference = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../tests/data/named/{name}/specification.json"));
        let reference = std::fs::read_to_string(&reference).unwrap_or_else(|e| panic!("{}: {e}", reference.display()));
        let json = built.pattern.to_json().unwrap();
        let verdict = garmentcode_compare::compare_spec_texts(&reference, &json, &Default::default());
        assert!(verdict.pass, "{name} differs from the reference: {:?}", verdict.reasons);
        insta::assert_snapshot!(format!("{name}-{}", builtin::DEFAULT_BODY), json);
    }
}
