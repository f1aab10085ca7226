//! Dataset sampling speed, in samples per second (divan's `item/s`), for a fixed
//! seed with JSON written and drawings off:
//!
//! - `library_one_thread`: `DatasetSampler::draw_in` and `Pattern::to_json` per
//!   sample, on one thread (what one core does, without file I/O), new samples in
//!   every run;
//! - `cli`: the whole `garmentcode sample` command (threads, files, summary) into a
//!   fresh folder, with `--jobs` 1 and 2;
//! - `cli_mesh`: the command with `--formats json,mesh --layout shards` (every sample's
//!   simulation box mesh too), with `--jobs` 2;
//! - after divan's table: where one thread's time goes per sample with meshes (drawing
//!   and building the design, the mesh, the mesh's files), the share of meshing;
//! - then `sample --layout shards --formats json --jobs 2` into a folder on disk
//!   against the same run with `--out /dev/null` (every file made, then discarded:
//!   the CPU floor), in alternating rounds: the median samples/s of each and their
//!   ratio.
//!
//! `cargo bench --bench sample`; the command writes under `$GARMENTCODE_BENCH_DIR`
//! (default: the temporary directory), so the disk can be chosen.

use garments::sample::{DatasetSampler, Outcome};
use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

const SEED: u64 = 1;

/// The allocator of the `garmentcode` binary, so that the library figure is
/// what the command's threads do.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
    // On a new thread: the geometry's memo tables of this one hold what the
    // library benchmark drew, the same first samples.
    std::thread::spawn(mesh_share).join().expect("the mesh figures are measured");
    shards_against_sink();
}

/// Samples per run of the disk-against-sink comparison, and its rounds.
const SINK_SAMPLES: u64 = 50_000;
const SINK_ROUNDS: usize = 5;

/// Prints the speed of writing shards to disk against discarding them.
fn shards_against_sink() {
    let args = ["--layout", "shards", "--formats", "json"];
    let speed = |out: &std::path::Path| {
        let start = std::time::Instant::now();
        let status = sample_command(SINK_SAMPLES, 2, &args, out).status().expect("garmentcode runs");
        assert!(status.success());
        SINK_SAMPLES as f64 / start.elapsed().as_secs_f64()
    };
    let (mut disk, mut sink) = (Vec::new(), Vec::new());
    let root = bench_dir().join(format!("garmentcode-bench-sink-{}", std::process::id()));
    for round in 0..SINK_ROUNDS {
        let dir = root.join(round.to_string());
        disk.push(speed(&dir));
        let _ = std::fs::remove_dir_all(&root);
        sink.push(speed(std::path::Path::new("/dev/null")));
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (disk, sink) = (median(&mut disk), median(&mut sink));
    println!(
        "sample --layout shards --formats json --jobs 2, {SINK_SAMPLES} samples, median of {SINK_ROUNDS} alternating rounds: \
         {disk:.0} samples/s into {}, {sink:.0} samples/s into /dev/null; the disk costs {:.2}x the floor",
        bench_dir().display(),
        sink / disk
    );
}

/// Where the command benchmarks write.
fn bench_dir() -> PathBuf {
    std::env::var_os("GARMENTCODE_BENCH_DIR").map_or_else(std::env::temp_dir, PathBuf::from)
}

/// `garmentcode sample --n n --seed SEED --jobs jobs ARGS --out out`, quiet.
fn sample_command(n: u64, jobs: usize, args: &[&str], out: &std::path::Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_garmentcode"));
    command
        .args(["sample", "--n", &n.to_string(), "--seed", &SEED.to_string(), "--jobs", &jobs.to_string()])
        .args(args)
        .arg("--out")
        .arg(out)
        .stderr(std::process::Stdio::null());
    command
}

/// Prints the time per sample of one thread in the design (draw, build, JSON), the
/// box mesh and its files, over the first 300 samples of the seed.
fn mesh_share() {
    use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION};
    use std::time::{Duration, Instant};
    let sampler = DatasetSampler::with_defaults(SEED);
    let mut arena = garmentcode::Arena::new();
    let (mut design, mut mesh, mut files, mut n) = (Duration::ZERO, Duration::ZERO, Duration::ZERO, 0u32);
    for i in 0..300 {
        let t = Instant::now();
        let Outcome::Accepted(s) = sampler.draw_in(&mut arena, i) else { continue };
        let json = s.built.pattern.to_json().expect("pattern serialises");
        let t1 = Instant::now();
        let m = BoxMesh::new(&s.built.pattern, DEFAULT_RESOLUTION).expect("every sample meshes");
        let t2 = Instant::now();
        let bytes: usize = m.files().iter().map(|f| f.1.len()).sum::<usize>() + json.len();
        std::hint::black_box(bytes);
        let t3 = Instant::now();
        design += t1 - t;
        mesh += t2 - t1;
        files += t3 - t2;
        n += 1;
    }
    let total = design + mesh + files;
    let ms = |d: Duration| d.as_secs_f64() * 1e3 / f64::from(n);
    println!(
        "one thread, per sample with a mesh ({n} samples): design {:.3} ms, mesh {:.3} ms, mesh files {:.3} ms; meshing {:.0}% of the time, {:.0} samples/s",
        ms(design),
        ms(mesh),
        ms(files),
        100.0 * (mesh + files).as_secs_f64() / total.as_secs_f64(),
        f64::from(n) / total.as_secs_f64()
    );
}

/// Samples per iteration of the library benchmark.
const LIB_SAMPLES: u64 = 1000;

/// Each run draws the next `LIB_SAMPLES` samples: no sample is drawn twice, so the
/// geometry's memo tables (kept from garment to garment on a thread) help only as
/// much as a dataset run's new samples share with the earlier ones.
#[divan::bench(sample_count = 5, sample_size = 1)]
fn library_one_thread(bencher: divan::Bencher) {
    let sampler = DatasetSampler::with_defaults(SEED);
    let mut arena = garmentcode::Arena::new();
    let mut next = 0;
    bencher.counter(divan::counter::ItemsCount::new(LIB_SAMPLES)).bench_local(|| {
        let mut bytes = 0;
        let first = next;
        next += LIB_SAMPLES;
        for i in first..first + LIB_SAMPLES {
            if let Outcome::Accepted(s) = sampler.draw_in(&mut arena, i) {
                bytes += s.built.pattern.to_json().expect("pattern serialises").len();
            }
        }
        bytes
    });
}

/// Samples per run of the command benchmark.
const CLI_SAMPLES: u64 = 5000;

#[divan::bench(args = [1, 2], sample_count = 3, sample_size = 1)]
fn cli(bencher: divan::Bencher, jobs: usize) {
    run_command(bencher, "json", CLI_SAMPLES, jobs, &["--formats", "json"]);
}

/// Samples per run of the command benchmark with meshes.
const MESH_CLI_SAMPLES: u64 = 500;

#[divan::bench(args = [2], sample_count = 3, sample_size = 1)]
fn cli_mesh(bencher: divan::Bencher, jobs: usize) {
    run_command(bencher, "mesh", MESH_CLI_SAMPLES, jobs, &["--formats", "json,mesh", "--layout", "shards"]);
}

/// `garmentcode sample --n n --seed SEED --jobs jobs ARGS` into a fresh folder per run
/// under `$GARMENTCODE_BENCH_DIR` (named after `tag`), removed after the run (untimed).
fn run_command(bencher: divan::Bencher, tag: &str, n: u64, jobs: usize, args: &[&str]) {
    static RUN: AtomicUsize = AtomicUsize::new(0);
    let root = bench_dir().join(format!("garmentcode-bench-{tag}-{}", std::process::id()));
    bencher
        .counter(divan::counter::ItemsCount::new(n))
        .with_inputs(|| -> PathBuf {
            let dir = root.join(RUN.fetch_add(1, Ordering::Relaxed).to_string());
            let _ = std::fs::remove_dir_all(&dir);
            dir
        })
        .bench_local_values(|dir: PathBuf| {
            let status = sample_command(n, jobs, args, &dir).status().expect("garmentcode runs");
            assert!(status.success());
            // Removed when divan drops it, after the timing.
            Removed(dir)
        });
    let _ = std::fs::remove_dir_all(&root);
}

/// A folder removed when dropped.
struct Removed(PathBuf);

impl Drop for Removed {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
