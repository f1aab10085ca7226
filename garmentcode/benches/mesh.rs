//! Box-mesh generation (`garmentcode::mesh::BoxMesh::new`) at the default resolution on
//! the patterns of the reference cases (`../tests/data/cases`, every case with a
//! specification); the reference's BoxMesh needs a median 1.15 s of CPU per garment for
//! the same step.
//!
//! `cargo bench -p garmentcode --bench mesh` prints divan's figures per garment, then the
//! per-garment distribution over all cases (median of 11 runs each): median, 99th
//! percentile, worst, in CPU time of the meshing thread (so that other processes on a shared
//! machine do not count) and in wall-clock time.

use std::time::Instant;

use cpu_time::ThreadTime;

use garmentcode::Pattern;
use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION};

fn cases() -> Vec<(String, Pattern)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/cases");
    let mut names: Vec<String> =
        std::fs::read_dir(dir).expect("mesh cases").map(|e| e.expect("entry").file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
        .into_iter()
        .filter(|n| std::path::Path::new(&format!("{dir}/{n}/specification.json")).exists())
        .map(|n| {
            let text = std::fs::read_to_string(format!("{dir}/{n}/specification.json")).expect("specification");
            let mut p = Pattern::from_json(&text).expect("pattern");
            p.name = n.clone();
            (n, p)
        })
        .collect()
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn all_cases(bencher: divan::Bencher) {
    let set = cases();
    bencher.bench(|| set.iter().map(|(_, p)| BoxMesh::new(p, DEFAULT_RESOLUTION).map_or(0, |m| m.vertices.len())).sum::<usize>());
}

fn main() {
    divan::main();
    // Per case: median CPU and wall time of 11 runs.
    let mut per: Vec<(f64, f64, String, usize)> = cases()
        .into_iter()
        .map(|(n, p)| {
            let (mut cpu, mut wall): (Vec<f64>, Vec<f64>) = (0..11)
                .map(|_| {
                    let (c, t) = (ThreadTime::now(), Instant::now());
                    let m = BoxMesh::new(&p, DEFAULT_RESOLUTION);
                    let (cpu, wall) = (c.elapsed().as_secs_f64(), t.elapsed().as_secs_f64());
                    std::hint::black_box(m.is_ok());
                    (cpu, wall)
                })
                .unzip();
            cpu.sort_by(f64::total_cmp);
            wall.sort_by(f64::total_cmp);
            let nv = BoxMesh::new(&p, DEFAULT_RESOLUTION).map_or(0, |m| m.vertices.len());
            (cpu[cpu.len() / 2], wall[wall.len() / 2], n, nv)
        })
        .collect();
    per.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (c, w, n, nv) in &per {
        println!("{n}: {:.3} ms CPU, {:.3} ms wall ({nv} vertices)", c * 1e3, w * 1e3);
    }
    let quantiles = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        let q = |f: f64| v[((v.len() - 1) as f64 * f).round() as usize] * 1e3;
        format!("median {:.3} ms, p99 {:.3} ms, worst {:.3} ms", q(0.5), q(0.99), q(1.0))
    };
    println!("per garment over {} cases, CPU time: {}", per.len(), quantiles(per.iter().map(|p| p.0).collect()));
    println!("per garment over {} cases, wall time: {}", per.len(), quantiles(per.iter().map(|p| p.1).collect()));
}
