//! Speed of the whole pipeline for random designs: design file (YAML text) →
//! typed design → garment → flat pattern → `specification.json` text, on one
//! thread, for a fixed set of designs sampled from the default design space
//! (seed 2026, the five built-in bodies in turn; designs the library rejects, such
//! as empty garments, are left out of the set).
//!
//! `cargo bench -p garments --bench build` prints divan's figures for the whole set
//! (time per design = time per iteration / set size) and then, per design,
//! summarised over the set (median, mean, 90th percentile, worst; designs with
//! sleeves or hoods separately), side by side:
//!
//! - warm: the median of repeated builds of the same design;
//! - cold stream: the first build of each design, the set built in order on a
//!   thread that built nothing before (as a dataset run meets new designs);
//! - cold process: the first build in a fresh process (the benchmark runs its own
//!   executable for a few dozen designs of the set, each building one design), by
//!   step (read, build, JSON), and the same design built again in that process with
//!   the geometry memo emptied: the build and JSON steps then do the same work as the
//!   first time (the read uses the space's file layout from the second file on), so
//!   the difference is the processor's cold caches and predictors;
//!
//! with the medians' ratios, and the speed-up against the reference's figures on
//! this machine kind (median 0.10 s, mean 0.48 s; with sleeves median 1.4 s).

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
    /// Index of the design in the seed's stream.
    index: u64,
    with_sleeves: bool,
}

fn space() -> &'static DesignSpace {
    static SPACE: OnceLock<DesignSpace> = OnceLock::new();
    SPACE.get_or_init(Design::design_space)
}

/// The fixed set of design files, each with its body. Made on a thread of its own:
/// the per-thread memo tables of the geometry (see `garmentcode::memo`) of the
/// measuring thread then hold nothing of the set.
fn cases() -> &'static [Case] {
    static CASES: OnceLock<Vec<Case>> = OnceLock::new();
    CASES.get_or_init(|| std::thread::spawn(make_cases).join().expect("the set is made"))
}

fn make_cases() -> Vec<Case> {
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
            out.push(Case { yaml: write_design(&design, space()), body, index, with_sleeves });
        }
    }
    out
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

/// Environment variable that makes the benchmark's executable a child process
/// building one design of the set (`INDEX:BODY`, the design's sample index in the
/// seed's stream and its body's index) and printing its times in nanoseconds.
const COLD_PROCESS_VAR: &str = "GARMENTCODE_BENCH_COLD_DESIGN";

/// Times of one design file to JSON text, by step, in seconds.
#[derive(Clone, Copy)]
struct Steps {
    read: f64,
    build: f64,
    json: f64,
}

impl Steps {
    fn total(&self) -> f64 {
        self.read + self.build + self.json
    }
}

/// Design file text to pattern JSON text on a new arena, timed by step.
fn run_steps(case: &Case) -> Steps {
    let start = Instant::now();
    let design: Design = read_design(&case.yaml, "design.yaml", space()).expect("valid design file");
    let read = start.elapsed().as_secs_f64();
    let built = garments::build::build_in(&mut Arena::new(), &design, &case.body, "design").expect("the set holds buildable designs");
    let build = start.elapsed().as_secs_f64() - read;
    std::hint::black_box(built.pattern.to_json().expect("pattern serialises").len());
    let json = start.elapsed().as_secs_f64() - read - build;
    Steps { read, build, json }
}

/// The child of the cold-process measurement: the design is drawn and written to
/// YAML text (untimed), then read, built and written to JSON as the first build of
/// the process; then twice more, the geometry memo emptied before each, so that
/// these repeat the first build's work (the same instructions; the read, though,
/// uses the space's file layout from the second file on) with the processor's
/// caches and predictors warm. Prints six numbers: the first run's steps (read,
/// build, JSON) and the third run's.
fn cold_process_child(spec: &str) {
    let (index, body) = spec.split_once(':').expect("INDEX:BODY");
    let (index, body): (u64, usize) = (index.parse().expect("sample index"), body.parse().expect("body index"));
    let design: Design = Sampler::new(space().clone()).sample(&mut sample_rng(SEED, index));
    let name = garments::builtin::BODIES[body].0;
    let case = Case {
        yaml: write_design(&design, space()),
        body: garments::builtin::body(name).expect("built-in body"),
        index,
        with_sleeves: false,
    };
    let first = run_steps(&case);
    let mut again = first;
    for _ in 0..2 {
        garmentcode::__private::clear_memo();
        again = run_steps(&case);
    }
    let ns = |s: f64| (s * 1e9).round() as u64;
    println!("{} {} {} {} {} {}", ns(first.read), ns(first.build), ns(first.json), ns(again.read), ns(again.build), ns(again.json));
}

/// The first build in a fresh process of `count` designs spread over the set, one
/// child process each: per design, the first build's steps and the same build's
/// when repeated in that process without the memo.
fn cold_process(set: &[Case], count: usize) -> Vec<(Steps, Steps)> {
    let exe = std::env::current_exe().expect("the benchmark's executable");
    let bodies = garments::builtin::BODIES.len();
    (0..count)
        .map(|k| {
            let case = &set[k * set.len() / count];
            let out = std::process::Command::new(&exe)
                .env(COLD_PROCESS_VAR, format!("{}:{}", case.index, case.index as usize % bodies))
                .output()
                .expect("the benchmark runs itself");
            assert!(out.status.success(), "child failed: {}", String::from_utf8_lossy(&out.stderr));
            let t: Vec<f64> = String::from_utf8_lossy(&out.stdout)
                .split_whitespace()
                .map(|w| w.parse::<f64>().expect("the child prints nanoseconds") * 1e-9)
                .collect();
            assert_eq!(t.len(), 6, "the child prints six times");
            (Steps { read: t[0], build: t[1], json: t[2] }, Steps { read: t[3], build: t[4], json: t[5] })
        })
        .collect()
}

fn median(mut t: Vec<f64>) -> f64 {
    t.sort_by(f64::total_cmp);
    percentile(&t, 0.5)
}

fn main() {
    if let Ok(spec) = std::env::var(COLD_PROCESS_VAR) {
        cold_process_child(&spec);
        return;
    }
    divan::main();
    // Under `cargo test` the harness runs every benchmark once; the per-design
    // summary is for `cargo bench` only.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let set = cases();
    // On a new thread, whose memo tables are empty: each design's first build there
    // follows the other designs' (cold stream: no design built before, but what it
    // shares with earlier designs is memoised, as in a dataset run); the builds
    // repeated right after it are warm.
    const WARM_RUNS: usize = 7;
    let (cold, warm): (Vec<f64>, Vec<f64>) = std::thread::spawn(move || {
        let mut arena = Arena::new();
        let time = |arena: &mut Arena, case: &Case| {
            let start = Instant::now();
            std::hint::black_box(run(arena, case));
            start.elapsed().as_secs_f64()
        };
        set.iter().map(|case| (time(&mut arena, case), median((0..WARM_RUNS).map(|_| time(&mut arena, case)).collect()))).unzip()
    })
    .join()
    .expect("the measuring thread runs");
    const CHILDREN: usize = 40;
    let process = cold_process(set, CHILDREN);
    println!();
    println!("Per design, design file to JSON text, one thread:");
    println!("warm: median of {WARM_RUNS} builds of the design repeated after its first");
    summary("all designs", warm.clone(), 0.10, Some(0.48));
    let sleeved = |t: &[f64]| set.iter().zip(t).filter(|(c, _)| c.with_sleeves).map(|(_, t)| *t).collect::<Vec<f64>>();
    summary("with sleeves or hoods", sleeved(&warm), 1.4, None);
    println!("cold stream: the first build of each design, one after the other (the set in order)");
    summary("all designs", cold.clone(), 0.10, Some(0.48));
    summary("with sleeves or hoods", sleeved(&cold), 1.4, None);
    println!("cold process: the first build in a fresh process, {CHILDREN} designs");
    let first: Vec<Steps> = process.iter().map(|p| p.0).collect();
    let repeated: Vec<Steps> = process.iter().map(|p| p.1).collect();
    summary("all designs", first.iter().map(Steps::total).collect(), 0.10, Some(0.48));
    let steps = |s: &[Steps]| {
        let m = |f: fn(&Steps) -> f64| median(s.iter().map(f).collect()) * 1e3;
        format!("read {:.4} ms, build {:.4} ms, JSON {:.4} ms", m(|s| s.read), m(|s| s.build), m(|s| s.json))
    };
    println!("{:<22} medians by step: {}", "", steps(&first));
    println!("the same designs built again in their process, the memo emptied (the same build work, warm processor)");
    summary("all designs", repeated.iter().map(Steps::total).collect(), 0.10, Some(0.48));
    println!("{:<22} medians by step: {}", "", steps(&repeated));
    let (w, c, p, r) =
        (median(warm), median(cold), median(first.iter().map(Steps::total).collect()), median(repeated.iter().map(Steps::total).collect()));
    println!(
        "medians: warm {:.4} ms, cold stream {:.4} ms (×{:.2} warm), cold process {:.4} ms (×{:.2} warm), its repeat without the memo {:.4} ms (×{:.2} warm)",
        w * 1e3,
        c * 1e3,
        c / w,
        p * 1e3,
        p / w,
        r * 1e3,
        r / w
    );
}
