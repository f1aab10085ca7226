//! The drape's cost: `cargo bench -p garmentcode-drape`.
//!
//! Prints, for garments of growing size (the waistband, then reference cases of 6,000 to
//! 11,000 vertices, on the built-in `mean_all` body), the CPU time (all threads) and the
//! peak resident memory of a process doing only that drape (built-in body included), over
//! the first 60 frames, and per vertex and frame, to show how both grow with the number of
//! particles; then the whole t-shirt drape (the target: at most 5 s) with its wall
//! and CPU seconds, its frames and the reference's 276 CPU s beside it. Drapes run on all
//! the machine's threads (`DRAPE_BENCH_THREADS=N` for N).

use std::time::Instant;

use cpu_time::ProcessTime;

use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION};
use garmentcode_drape::{BodyMesh, Settings, drape};

fn garment(case: &str) -> (garmentcode::Pattern, BoxMesh) {
    let path = format!("{}/../tests/data/cases/{case}/specification.json", env!("CARGO_MANIFEST_DIR"));
    let pattern = garmentcode::Pattern::from_json(&std::fs::read_to_string(&path).expect("specification")).expect("pattern");
    let mesh = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("box mesh");
    (pattern, mesh)
}

/// Peak resident memory of this process (kB, `VmHWM`), if the system tells it.
fn peak_kb() -> Option<usize> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    status.lines().find_map(|l| l.strip_prefix("VmHWM:"))?.trim().trim_end_matches("kB").trim().parse().ok()
}

/// Drapes `case` for `frames` frames (0: to the end) in this process and prints
/// `vertices frames cpu_seconds wall_seconds peak_kB self_crossings converged`.
fn child(case: &str, frames: usize) {
    let body = BodyMesh::builtin("mean_all").expect("built-in body");
    let measurements = garmentcode::Body::from_yaml(include_str!("../tests/data/mean_all.yaml"), "mean_all.yaml").expect("body");
    let (pattern, mesh) = garment(case);
    let mut settings = Settings::for_body(&measurements).with_panel_labels(&pattern);
    if frames > 0 {
        settings.max_frames = frames;
    }
    settings.threads = std::env::var("DRAPE_BENCH_THREADS").ok().and_then(|t| t.parse().ok()).unwrap_or(0);
    let (cpu, wall) = (ProcessTime::now(), Instant::now());
    let result = drape(&mesh, &body, &settings).expect("drape");
    let (seconds, wall) = (cpu.elapsed().as_secs_f64(), wall.elapsed().as_secs_f64());
    let s = result.stats;
    println!("{} {} {seconds} {wall} {} {} {}", mesh.vertices.len(), s.frames, peak_kb().unwrap_or(0), s.self_intersections, s.converged);
}

/// Runs [`child`] in a new process of this benchmark (so that the peak memory is this
/// drape's alone) and returns its figures.
fn run(case: &str, frames: usize) -> (usize, usize, f64, f64, usize, usize, bool) {
    let out = std::process::Command::new(std::env::current_exe().expect("benchmark path"))
        .env("DRAPE_BENCH_CASE", format!("{case}:{frames}"))
        .output()
        .expect("benchmark child");
    let text = String::from_utf8_lossy(&out.stdout);
    let w: Vec<&str> = text.split_whitespace().collect();
    assert!(out.status.success() && w.len() == 7, "drape of {case} failed: {text} {}", String::from_utf8_lossy(&out.stderr));
    let number = |k: usize| w[k].parse::<f64>().unwrap();
    (number(0) as usize, number(1) as usize, number(2), number(3), number(4) as usize, number(5) as usize, w[6] == "true")
}

fn main() {
    if let Ok(job) = std::env::var("DRAPE_BENCH_CASE") {
        let (case, frames) = job.split_once(':').expect("case:frames");
        child(case, frames.parse().expect("frames"));
        return;
    }
    if std::env::args().any(|a| a == "--list") {
        // `cargo bench` asks harness-less benchmarks for their list of tests.
        return;
    }
    println!("growth with the number of particles (first 60 frames, one process per garment):");
    println!("{:<18} {:>9} {:>8} {:>13} {:>16} {:>13}", "garment", "vertices", "CPU s", "peak RSS MB", "µs/vertex/frame", "kB/vertex");
    for case in ["case-001", "case-021", "t-shirt-mean_all", "case-036", "case-026", "case-031"] {
        let (n, frames, seconds, _, peak, _, _) = run(case, 60);
        println!(
            "{case:<18} {n:>9} {seconds:>8.2} {:>13.1} {:>16.2} {:>13.1}",
            peak as f64 / 1e3,
            seconds * 1e6 / (n * frames) as f64,
            peak as f64 / n as f64
        );
    }
    let (n, frames, seconds, wall, peak, crossings, converged) = run("t-shirt-mean_all", 0);
    println!(
        "t-shirt drape: {n} vertices, {frames} frames, {wall:.1} s wall, {seconds:.1} CPU s (target 5 s; the reference's simulator: 276 CPU s), peak RSS {:.1} MB, {crossings} self-crossing edges, converged: {converged}",
        peak as f64 / 1e3
    );
}
