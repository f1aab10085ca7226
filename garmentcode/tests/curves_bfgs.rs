//! `curve_from_tangents` parity: every distinct call the reference made while
//! building the 62 reference cases and 400 sampled designs (start, end, absolute
//! tangents, initial guess) gives scipy's control point bit for bit.

use garmentcode::curves::quadratic_from_tangents;
use garmentcode::{Curve, Vec2};

#[test]
fn tangent_fits_match_scipy_bit_for_bit() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/bfgs_real.json")).unwrap();
    let data: serde_json::Value = serde_json::from_str(&text).unwrap();
    let v2 = |x: &serde_json::Value| x.as_array().map(|a| Vec2::new(a[0].as_f64().unwrap(), a[1].as_f64().unwrap()));
    let vectors = data["vectors"].as_array().unwrap();
    assert!(vectors.len() > 400);
    let mut worst = 0.0f64;
    for v in vectors {
        let Curve::Quadratic(cp) = quadratic_from_tangents(
            v2(&v["start"]).unwrap(),
            v2(&v["end"]).unwrap(),
            v2(&v["tan0_abs"]),
            v2(&v["tan1_abs"]),
            v2(&v["x0"]).unwrap(),
        ) else {
            panic!("a quadratic")
        };
        let want = v2(&v["x"]).unwrap();
        worst = worst.max((cp - want).length());
    }
    assert!(worst < 1e-12, "max deviation {worst:e}");
}
