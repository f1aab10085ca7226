//! Compile-time validation of the derive macros: each file under `tests/ui/` must fail
//! to compile with the error recorded next to it (`.stderr`).

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
    t.pass("examples/params_demo.rs");
}
