//! Dataset sampling speed, in samples per second (divan's `item/s`), for a fixed
//! seed with JSON written and drawings off:
//!
//! - `library_one_thread`: `DatasetSampler::draw_in` and `Pattern::to_json` per
//!   sample, on one thread (what one core does, without file I/O);
//! - `cli`: the whole `garmentcode sample` command (threads, files, summary) into a
//!   fresh folder, with `--jobs` 1 and 2.
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
}

/// Samples per iteration of the library benchmark.
const LIB_SAMPLES: u64 = 1000;

#[divan::bench(sample_count = 5, sample_size = 1)]
fn library_one_thread(bencher: divan::Bencher) {
    let sampler = DatasetSampler::with_defaults(SEED);
    let mut arena = garmentcode::Arena::new();
    bencher.counter(divan::counter::ItemsCount::new(LIB_SAMPLES)).bench_local(|| {
        let mut bytes = 0;
        for i in 0..LIB_SAMPLES {
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
    static RUN: AtomicUsize = AtomicUsize::new(0);
    let base = std::env::var_os("GARMENTCODE_BENCH_DIR").map_or_else(std::env::temp_dir, PathBuf::from);
    let root = base.join(format!("garmentcode-bench-{}", std::process::id()));
    bencher
        .counter(divan::counter::ItemsCount::new(CLI_SAMPLES))
        .with_inputs(|| -> PathBuf {
            let dir = root.join(RUN.fetch_add(1, Ordering::Relaxed).to_string());
            let _ = std::fs::remove_dir_all(&dir);
            dir
        })
        .bench_local_values(|dir: PathBuf| {
            let status = Command::new(env!("CARGO_BIN_EXE_garmentcode"))
                .args([
                    "sample",
                    "--n",
                    &CLI_SAMPLES.to_string(),
                    "--seed",
                    &SEED.to_string(),
                    "--jobs",
                    &jobs.to_string(),
                    "--formats",
                    "json",
                ])
                .arg("--out")
                .arg(&dir)
                .stderr(std::process::Stdio::null())
                .status()
                .expect("garmentcode runs");
            assert!(status.success());
            dir
        });
    let _ = std::fs::remove_dir_all(&root);
}
