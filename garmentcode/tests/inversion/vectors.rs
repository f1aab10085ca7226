//! Checks against the logged reference calls (data/all_vectors.json: all 574 unique calls,
//! 28 from the reference case designs and 546 from random designs with sleeves or hoods on
//! the five bodies; collected by tools/collect_inversion_calls.py).

use garmentcode::curves::inversion::*;

fn vectors() -> Vec<super::common::Vector> {
    super::common::load("tests/inversion/data/all_vectors.json")
}

/// Our evaluation of the reference objective reproduces scipy's final `fun` at scipy's `x`.
#[test]
fn objective_matches_reference_values() {
    let mut worst = 0.0f64;
    for v in vectors() {
        let f = objective(v.cps, v.t0, v.t1, v.target_len, v.ref_shift);
        worst = worst.max((f - v.ref_fun).abs() / v.ref_fun);
    }
    println!("worst relative difference to scipy's fun: {worst:.2e}");
    assert!(worst < 1e-9, "objective differs from the reference by {worst:e}");
}

/// The default mode is never worse than the reference on its own objective, and sane.
#[test]
fn not_worse_than_reference() {
    let mut ratios = Vec::new();
    let (mut worst_len_sleeve, mut worst_len, mut worst_tan) = (0.0f64, 0.0f64, 0.0f64);
    for v in vectors() {
        let (fin, st) = match_tangents_with_stats(v.cps, v.t0, v.t1, v.target_len, Mode::Proximal);
        assert_eq!(fin[0], v.cps[0], "start point must not move");
        assert_eq!(st.qp_failures, 0);
        let t = terms(v.cps, v.t0, v.t1, v.target_len, shift_of(&v.cps, &fin));
        let ratio = t.value / v.ref_fun;
        assert!(ratio <= 1.0, "{} {}: objective ratio {ratio}", v.source, v.caller);
        ratios.push(ratio);
        let le = (t.length - v.target_len).abs();
        worst_len = worst_len.max(le);
        worst_tan = worst_tan.max(t.tan0_err.max(t.tan1_err));
        if v.caller == "sleeve" {
            worst_len_sleeve = worst_len_sleeve.max(le);
        }
    }
    ratios.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "objective ratio ours/reference: median {:.6}, worst {:.12}; worst |length - target|: sleeves {worst_len_sleeve:.2e} cm, all {worst_len:.2e} cm; worst tangent error {worst_tan:.3}",
        ratios[ratios.len() / 2],
        ratios[ratios.len() - 1]
    );
    // The objective trades length and tangents against curvature: sleeves keep the length
    // within 0.01 cm; tight hoods (high curvature) do not, in the reference either.
    assert!(worst_len_sleeve <= 0.01);
    assert!(worst_len <= 0.03);
    assert!(worst_tan <= 0.2);
}

/// The converged reference-objective mode is never worse either.
#[test]
fn reference_mode_not_worse_than_reference() {
    for v in vectors() {
        let fin = match_tangents_reference(v.cps, v.t0, v.t1, v.target_len);
        let ratio = objective_of(v.cps, v.t0, v.t1, v.target_len, fin) / v.ref_fun;
        assert!(ratio <= 1.0 + 1e-12, "{} {}: objective ratio {ratio}", v.source, v.caller);
    }
}

/// The ripple-free variant stays close to the reference objective.
#[test]
fn ripple_free_objective_close_to_reference() {
    let mut worst = 0.0f64;
    for v in vectors() {
        let fin = match_tangents_smooth(v.cps, v.t0, v.t1, v.target_len);
        worst = worst.max(objective_of(v.cps, v.t0, v.t1, v.target_len, fin) / v.ref_fun);
    }
    println!("ripple-free mode: worst objective ratio to the reference {worst:.6}");
    assert!(worst < 1.005);
}

/// Same inputs, same bits, in every mode.
#[test]
fn deterministic() {
    for v in vectors().iter().step_by(5) {
        for mode in [Mode::Proximal, Mode::Reference, Mode::RippleFree] {
            let a = match_tangents_with_stats(v.cps, v.t0, v.t1, v.target_len, mode).0;
            let b = match_tangents_with_stats(v.cps, v.t0, v.t1, v.target_len, mode).0;
            for i in 0..4 {
                for c in 0..2 {
                    assert_eq!(a[i][c].to_bits(), b[i][c].to_bits());
                }
            }
        }
    }
}
