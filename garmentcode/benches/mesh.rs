//! Box-mesh generation (`garmentcode::mesh::BoxMesh::new`) at the default resolution on
//! the patterns of the reference cases (`../tests/data/cases`, every case with a
//! specification); the reference's BoxMesh needs a median 1.15 s of CPU per garment for
//! the same step.
//!
//! `cargo bench -p garmentcode --bench mesh` prints divan's figures per garment, then the
//! per-garment distribution over all cases (median of 11 runs each): median, 99th
//! percentile, worst, in CPU time of the meshing thread (so that other processes on a shared
//! machine do not count) and in wall-clock time; then the same for its files, made in
//! memory (`BoxMesh::files`) and made and written into a folder (`BoxMesh::write_files`,
//! CPU time of the thread, system calls included), and the files' time over the mesh's.

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

/// Median CPU time (s) of the meshing thread over 11 runs of `f`.
fn median_cpu<T>(mut f: impl FnMut() -> T) -> f64 {
    let mut times: Vec<f64> = (0..11)
        .map(|_| {
            let c = ThreadTime::now();
            std::hint::black_box(f());
            c.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    divan::main();
    // Per case, medians of 11 runs: the mesh (CPU and wall time), its files made in
    // memory, and its files made and written into a folder (CPU time).
    let dir = std::env::temp_dir().join(format!("garmentcode-bench-mesh-{}", std::process::id()));
    let mut per: Vec<(f64, f64, f64, f64, String, usize)> = cases()
        .into_iter()
        .filter_map(|(n, p)| {
            let mesh = BoxMesh::new(&p, DEFAULT_RESOLUTION).ok()?;
            let cpu = median_cpu(|| BoxMesh::new(&p, DEFAULT_RESOLUTION).is_ok());
            let mut wall: Vec<f64> = (0..11)
                .map(|_| {
                    let t = Instant::now();
                    std::hint::black_box(BoxMesh::new(&p, DEFAULT_RESOLUTION).is_ok());
                    t.elapsed().as_secs_f64()
                })
                .collect();
            wall.sort_by(f64::total_cmp);
            let files = median_cpu(|| mesh.files().len());
            let written = median_cpu(|| mesh.write_files(&dir).expect("files written").len());
            Some((cpu, wall[wall.len() / 2], files, written, n, mesh.vertices.len()))
        })
        .collect();
    let _ = std::fs::remove_dir_all(&dir);
    per.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (c, w, f, fw, n, nv) in &per {
        println!(
            "{n}: mesh {:.3} ms CPU, {:.3} ms wall; files {:.3} ms, written {:.3} ms CPU ({nv} vertices)",
            c * 1e3,
            w * 1e3,
            f * 1e3,
            fw * 1e3
        );
    }
    let quantiles = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        let q = |f: f64| v[((v.len() - 1) as f64 * f).round() as usize] * 1e3;
        format!("median {:.3} ms, p99 {:.3} ms, worst {:.3} ms", q(0.5), q(0.99), q(1.0))
    };
    let n = per.len();
    println!("per garment over {n} meshed cases, mesh, CPU time: {}", quantiles(per.iter().map(|p| p.0).collect()));
    println!("per garment over {n} meshed cases, mesh, wall time: {}", quantiles(per.iter().map(|p| p.1).collect()));
    println!("per garment over {n} meshed cases, files made (BoxMesh::files), CPU time: {}", quantiles(per.iter().map(|p| p.2).collect()));
    println!(
        "per garment over {n} meshed cases, files made and written (BoxMesh::write_files), CPU time: {}",
        quantiles(per.iter().map(|p| p.3).collect())
    );
    // The files against the mesh, garment by garment (issue 23's target: no more time).
    let mut ratios: Vec<f64> = per.iter().map(|p| p.3 / p.0).collect();
    ratios.sort_by(f64::total_cmp);
    let q = |f: f64| ratios[((ratios.len() - 1) as f64 * f).round() as usize];
    println!(
        "per garment over {n} meshed cases, files made and written over the mesh, CPU time: median x{:.2}, p90 x{:.2}, worst x{:.2}",
        q(0.5),
        q(0.9),
        q(1.0)
    );
}
