//! A design whose garment program computes a NaN (sample 73732 of seed 7, its
//! attempt 3: a skirt placed at a NaN translation) is refused with the place named,
//! instead of a pattern that cannot be written.

use garmentcode::Params;
use garmentcode::io::read_design;
use garments::{Design, builtin};

#[test]
fn a_nan_in_the_pattern_is_a_build_error_naming_its_place() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/nan_translation_design.yaml");
    let text = std::fs::read_to_string(path).unwrap();
    let design: Design = read_design(&text, "nan_translation_design.yaml", &Design::design_space()).unwrap();
    let body = builtin::body(builtin::DEFAULT_BODY).unwrap();
    let Err(err) = garments::build::build(&design, &body, "nan") else { panic!("a NaN pattern was built") };
    let err = err.to_string();
    assert!(err.contains("not finite at panel 'skirt_front' translation"), "{err}");
    // The sampler's path refuses it the same way.
    let mut arena = garmentcode::Arena::new();
    let Err(refusal) = garments::build::build_valid_in(&mut arena, &design, &body, "nan") else { panic!("a NaN pattern was accepted") };
    assert!(matches!(refusal, garments::build::Refusal::Build(_)), "{refusal:?}");
}
