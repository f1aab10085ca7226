//! The whole `garmentcode mesh` process per garment: start, read the specification,
//! mesh at 1 cm, write the folder of files (into a fresh folder under
//! `$GARMENTCODE_BENCH_DIR`, default the temporary directory), exit. For every reference
//! case with a specification (`tests/data/cases`), 11 runs: their mean CPU time (user and
//! system, from the kernel's account of this process's children in `/proc/self/stat`,
//! in 10 ms ticks summed over the 11 runs) and their median wall-clock time; then the
//! distribution over the cases beside the reference's median of 3.68 s of CPU to
//! generate and serialise a box mesh (`BoxMesh(...).load()` and `serialize()`, shared
//! reference FORMAT.md §11). First, the floor: the mean CPU time of `garmentcode
//! --version` (start, parse the command line, exit) over 101 processes.
//!
//! With `GARMENTCODE_BENCH_BASELINE=PATH` (an earlier build of `garmentcode`), every case
//! is also run by that binary, case by case in alternating order, so that both see the
//! same load, and the two are reported side by side.
//!
//! `cargo bench --bench mesh_command`

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The reference's median CPU time per garment to generate and serialise the box mesh, s.
const REFERENCE_S: f64 = 3.68;

/// Runs per case and binary.
const RUNS: usize = 11;

fn main() {
    let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases");
    let mut specs: Vec<PathBuf> = std::fs::read_dir(&cases)
        .expect("reference cases")
        .map(|e| e.expect("entry").path().join("specification.json"))
        .filter(|p| p.exists())
        .collect();
    specs.sort();
    let root = std::env::var_os("GARMENTCODE_BENCH_DIR")
        .map_or_else(std::env::temp_dir, PathBuf::from)
        .join(format!("garmentcode-bench-mesh-command-{}", std::process::id()));
    let mut binaries = vec![("this build", PathBuf::from(env!("CARGO_BIN_EXE_garmentcode")))];
    if let Some(baseline) = std::env::var_os("GARMENTCODE_BENCH_BASELINE") {
        binaries.push(("baseline", PathBuf::from(baseline)));
    }
    for (label, binary) in &binaries {
        let ticks = children_ticks();
        for _ in 0..101 {
            let status = Command::new(binary).arg("--version").stdout(Stdio::null()).status();
            assert!(status.expect("garmentcode runs").success());
        }
        let floor = (children_ticks() - ticks) as f64 / 100.0 / 101.0;
        println!("{label}: garmentcode --version: {:.3} ms CPU (mean of 101 processes)", floor * 1e3);
    }
    // Per binary: each case's mean CPU time and median wall-clock time (s).
    let mut cpu = vec![Vec::new(); binaries.len()];
    let mut wall = vec![Vec::new(); binaries.len()];
    for (c, spec) in specs.iter().enumerate() {
        let name = spec.parent().and_then(|d| d.file_name()).expect("case folder").to_string_lossy().into_owned();
        let mut line = format!("{name}:");
        for k in 0..binaries.len() {
            // Alternate which binary goes first.
            let b = (k + c) % binaries.len();
            let (label, binary) = &binaries[b];
            let ticks = children_ticks();
            let mut times: Vec<f64> = (0..RUNS)
                .map(|run| {
                    let out = root.join(format!("{name}-{b}-{run}"));
                    let t = Instant::now();
                    let status = Command::new(binary)
                        .arg("mesh")
                        .arg(spec)
                        .arg("--out")
                        .arg(&out)
                        .stderr(Stdio::null())
                        .status()
                        .expect("garmentcode runs");
                    let elapsed = t.elapsed().as_secs_f64();
                    assert!(status.success(), "{label} meshes {name}");
                    elapsed
                })
                .collect();
            let mean_cpu = (children_ticks() - ticks) as f64 / 100.0 / RUNS as f64;
            let _ = std::fs::remove_dir_all(&root);
            times.sort_by(f64::total_cmp);
            let median_wall = times[times.len() / 2];
            line += &format!(" {label} {:.3} ms CPU (mean), {:.3} ms wall (median);", mean_cpu * 1e3, median_wall * 1e3);
            cpu[b].push(mean_cpu);
            wall[b].push(median_wall);
        }
        println!("{}", line.trim_end_matches(';'));
    }
    let quantiles = |v: &[f64]| {
        let mut v = v.to_vec();
        v.sort_by(f64::total_cmp);
        let q = |f: f64| v[((v.len() - 1) as f64 * f).round() as usize];
        (q(0.5), format!("median {:.3} ms, p99 {:.3} ms, worst {:.3} ms", q(0.5) * 1e3, q(0.99) * 1e3, q(1.0) * 1e3))
    };
    let mut medians = Vec::new();
    for (b, (label, _)) in binaries.iter().enumerate() {
        let ((cpu_median, cpu_text), (_, wall_text)) = (quantiles(&cpu[b]), quantiles(&wall[b]));
        println!("{label}: garmentcode mesh, whole process, per garment over {} cases: CPU {cpu_text}; wall {wall_text}", specs.len());
        println!(
            "{label}: the reference takes {REFERENCE_S} s of CPU per garment (median): x{:.0} at the median",
            REFERENCE_S / cpu_median
        );
        medians.push(cpu_median);
    }
    if binaries.len() == 2 {
        // Per case, this build's CPU time over the baseline's.
        let ratios: Vec<f64> = cpu[0].iter().zip(&cpu[1]).map(|(new, old)| new / old).collect();
        let (ratio, _) = quantiles(&ratios);
        println!(
            "this build against the baseline: median CPU {:.3} ms against {:.3} ms (x{:.2}); per case, median ratio x{ratio:.2}",
            medians[0] * 1e3,
            medians[1] * 1e3,
            medians[0] / medians[1]
        );
    }
}

/// CPU time (user and system) of this process's waited-for children, in ticks of 10 ms
/// (`/proc/self/stat` fields 16 and 17; 0 where there is no `/proc`).
fn children_ticks() -> u64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    // Fields after the command name, which is in parentheses and may hold spaces.
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // rest starts at field 3 (state): cutime is field 16, cstime 17.
    [13, 14].iter().filter_map(|&i| fields.get(i)?.parse::<u64>().ok()).sum()
}
