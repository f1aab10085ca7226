//! Speed of the whole pipeline for random designs: design file (YAML text) →
//! typed design → garment → flat pattern → `specification.json` text, on one
//! thread, for a fixed set of designs sampled from the default design space
//! (seed 2026, the five built-in bodies in turn; designs the library rejects, such
//! as empty garments, are left out of the set).
//!
//! `cargo bench -p garments --bench build` prints divan's figures for the whole set
//! (time per design = time per iteration / set size) and then, per design, the
//! median of several runs summarised over the set (median, mean, 90th percentile,
//! worst; designs with sleeves or hoods separately), with the speed-up against the
//! reference's figures on this machine kind (median 0.10 s, mean 0.48 s; with
//! sleeves median 1.4 s).

use std::sync::OnceLock;
use std::time::Instant;

use garmentcode::io::{read_design, write_design};
use garmentcode::{Arena, Body, DesignSpace, Params, Sampler, sample_rng};
use garments::Design;

/// Designs in the fixed set.
const SET_SIZE: usize = 300;
const SEED: u64 = 2026;

struct Case {
    yaml: String,
    body: Body,
    with_sleeves: bool,
}

fn space() -> &'static DesignSpace {
    static SPACE: OnceLock<DesignSpace> = OnceLock::new();
    SPACE.get_or_init(Design::design_space)
}

/// The fixed set of design files, each with its body.
fn cases() -> &'static [Case] {
    static CASES: OnceLock<Vec<Case>> = OnceLock::new();
    CASES.get_or_init(|| {
        let sampler = Sampler::new(space().clone());
        let bodies: Vec<Body> = garments::builtin::BODIES.iter().map(|(n, _)| garments::builtin::body(n).expect("built-in body")).collect();
        let mut out = Vec::with_capacity(SET_SIZE);
        let mut arena = Arena::new();
        for index in 0.. {
            if out.len() == SET_SIZE {
                break;
            }
            let design: Design = sampler.sample(&mut sample_rng(SEED, index));
            let body = bodies[index as usize % bodies.len()].clone();
            if let Ok(built) = garments::build::build_in(&mut arena, &design, &body, "design") {
                let with_sleeves = built.pattern.panels.iter().any(|p| p.name.contains("sleeve") || p.name.contains("hood"));
                out.push(Case { yaml: write_design(&design, space()), body, with_sleeves });
            }
        }
        out
    })
}

/// Design file text to pattern JSON text; returns the JSON's length.
fn run(arena: &mut Arena, case: &Case) -> usize {
    let design: Design = read_design(&case.yaml, "design.yaml", space()).expect("valid design file");
    let built = garments::build::build_in(arena, &design, &case.body, "design").expect("the set holds buildable designs");
    built.pattern.to_json().expect("pattern serialises").len()
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn design_file_to_json(bencher: divan::Bencher) {
    let set = cases();
    let mut arena = Arena::new();
    bencher.counter(divan::counter::ItemsCount::new(set.len())).bench_local(|| set.iter().map(|c| run(&mut arena, c)).sum::<usize>());
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    let i = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[i]
}

fn summary(label: &str, mut times: Vec<f64>, reference_median: f64, reference_mean: Option<f64>) {
    times.sort_by(f64::total_cmp);
    let mean = times.iter().sum::<f64>() / times.len() as f64;
    let median = percentile(&times, 0.5);
    let ms = |s: f64| s * 1e3;
    println!(
        "{label:<22} {:>4} designs  median {:>7.4} ms  mean {:>7.4} ms  p90 {:>7.4} ms  worst {:>7.3} ms",
        times.len(),
        ms(median),
        ms(mean),
        ms(percentile(&times, 0.9)),
        ms(*times.last().expect("non-empty"))
    );
    let mut ratios = format!("{:<22} speed-up vs the reference: median ×{:.0}", "", reference_median / median);
    if let Some(m) = reference_mean {
        ratios += &format!(", mean ×{:.0}", m / mean);
    }
    println!("{ratios}");
}

fn main() {
    divan::main();
    // Under `cargo test` the harness runs every benchmark once; the per-design
    // summary is for `cargo bench` only.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let set = cases();
    let mut arena = Arena::new();
    const RUNS: usize = 7;
    let mut per_design = Vec::with_capacity(set.len());
    for case in set {
        let mut t: Vec<f64> = (0..RUNS)
            .map(|_| {
                let start = Instant::now();
                std::hint::black_box(run(&mut arena, case));
                start.elapsed().as_secs_f64()
            })
            .collect();
        t.sort_by(f64::total_cmp);
        per_design.push((t[RUNS / 2], case.with_sleeves));
    }
    println!();
    println!("Per design (median of {RUNS} runs each), design file to JSON text, one thread:");
    summary("all designs", per_design.iter().map(|d| d.0).collect(), 0.10, Some(0.48));
    summary("with sleeves or hoods", per_design.iter().filter(|d| d.1).map(|d| d.0).collect(), 1.4, None);
}
