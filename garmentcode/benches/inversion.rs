//! Speed of the sleeve-opening / hood inversion (`curves::match_tangents`, the
//! paper's Appendix A) on the 574 calls logged from the reference
//! (`tests/inversion/data/all_vectors.json`). The reference needs about 0.1 to 1 s
//! per call (scipy L-BFGS-B with numeric gradients); the target here is under 1 ms.
//!
//! `cargo bench -p garmentcode --bench inversion` prints divan's figures for the whole
//! set (time per call = time per iteration / 574), then the per-call distribution
//! (median of 5 runs of each call): median, 99th percentile, worst.

use std::time::Instant;

use garmentcode::Vec2;
use garmentcode::curves::inversion::{Mode, match_tangents_with_stats};

type Call = ([Vec2; 4], Vec2, Vec2, f64);

/// One inversion, computed afresh: `curves::match_tangents` memoises its results
/// per thread, so timing it on repeated inputs would time the memo.
fn match_tangents(cps: [Vec2; 4], t0: Vec2, t1: Vec2, len: f64) -> [Vec2; 4] {
    let p = cps.map(|v| [v.x, v.y]);
    match_tangents_with_stats(p, [t0.x, t0.y], [t1.x, t1.y], len, Mode::Proximal).0.map(|q| Vec2::new(q[0], q[1]))
}

fn calls() -> Vec<Call> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/inversion/data/all_vectors.json");
    let data: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).expect("logged calls")).expect("JSON");
    let v2 = |x: &serde_json::Value| Vec2::new(x[0].as_f64().expect("x"), x[1].as_f64().expect("y"));
    data.as_array()
        .expect("a list of calls")
        .iter()
        .map(|c| {
            let cps = c["cps"].as_array().expect("4 control points");
            ([v2(&cps[0]), v2(&cps[1]), v2(&cps[2]), v2(&cps[3])], v2(&c["t0"]), v2(&c["t1"]), c["target_len"].as_f64().expect("length"))
        })
        .collect()
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn all_logged_calls(bencher: divan::Bencher) {
    let set = calls();
    bencher
        .counter(divan::counter::ItemsCount::new(set.len()))
        .bench_local(|| set.iter().map(|&(cps, t0, t1, len)| match_tangents(cps, t0, t1, len)[3].x).sum::<f64>());
}

fn main() {
    divan::main();
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let set = calls();
    let mut per_call: Vec<f64> = set
        .iter()
        .map(|&(cps, t0, t1, len)| {
            let mut t: Vec<f64> = (0..5)
                .map(|_| {
                    let start = Instant::now();
                    std::hint::black_box(match_tangents(cps, t0, t1, len));
                    start.elapsed().as_secs_f64()
                })
                .collect();
            t.sort_by(f64::total_cmp);
            t[2]
        })
        .collect();
    per_call.sort_by(f64::total_cmp);
    let at = |q: f64| per_call[((per_call.len() - 1) as f64 * q).round() as usize] * 1e6;
    println!();
    println!(
        "Per call ({} logged calls, median of 5 runs each): median {:.0} µs, p99 {:.0} µs, worst {:.0} µs (target < 1000 µs)",
        per_call.len(),
        at(0.5),
        at(0.99),
        at(1.0)
    );
}
