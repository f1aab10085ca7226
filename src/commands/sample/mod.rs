//! `garmentcode sample --n N --seed S --out DIR [--design-space FILE.yaml]
//! [--bodies NAME,NAME|DIR] [--jobs J] [--shard I/K] [--formats json,svg,png,mesh]
//! [--layout folders|shards[:N]]`: a dataset of random garments, as a folder per
//! sample or as tar shards (see `shards`); `--unpack SHARD.tar... --out DIR` turns
//! shards back into folders.
//!
//! The sampling itself is `garments::sample` (sample `i` depends on `(S, i)` alone);
//! this command validates the input before doing any work, spreads the samples of
//! its share over threads, writes each sample folder atomically, skips samples a
//! previous run finished, shows progress and writes the summary.
//!
//! Shards: shard `I` of `K` makes the samples whose index `i` has `i % K == I`.
//! Round-robin rather than blocks, so that a sample's shard does not depend on `N`
//! (a dataset extended with a larger `N` keeps its samples in their shards) and
//! every shard gets a similar mix of cheap and expensive designs. With
//! `--layout shards` a task takes whole archives instead: shard `k` of the archives
//! (samples `k·N .. (k+1)·N`) is made by the task with `k % K == I`, so an archive
//! is the same whatever `--shard` and `--jobs`.

mod progress;
mod shards;
mod store;
mod summary;

use crate::cli::SampleArgs;
use crate::commands::CliError;
use crate::output::OutputSet;
use garmentcode::io::write_design;
use garmentcode::{Arena, Params};
use garments::Design;
use garments::sample::{DatasetSampler, MAX_ATTEMPTS, NamedBody, Outcome, sample_name};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};
use store::{Formats, Record, Settings};

/// The command line, checked.
struct Options {
    n: Option<u64>,
    seed: u64,
    out: PathBuf,
    design_space: Option<String>,
    extended: bool,
    bodies: Option<String>,
    jobs: usize,
    shard: Option<(u64, u64)>,
    formats: Formats,
    replay: Option<(u64, Option<u32>)>,
    layout: Layout,
    sim: crate::cli::SimArgs,
}

/// `--layout`: a folder per sample, or tar shards of so many samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Layout {
    Folders,
    Shards(u64),
}

/// `folders`, `shards` or `shards:N` with `N >= 1`.
fn parse_layout(s: &str) -> Result<Layout, CliError> {
    let bad = || usage(format!("sample --layout: expected folders, shards or shards:N with N >= 1 samples per shard, got '{s}'"));
    match s.split_once(':') {
        None if s == "folders" => Ok(Layout::Folders),
        None if s == "shards" => Ok(Layout::Shards(shards::DEFAULT_SIZE)),
        Some(("shards", size)) => match size.trim().parse::<u64>() {
            Ok(size) if size >= 1 => Ok(Layout::Shards(size)),
            _ => Err(bad()),
        },
        _ => Err(bad()),
    }
}

fn usage(m: String) -> CliError {
    CliError::Usage(m)
}

impl Options {
    /// Check what clap cannot: shards, replays and format lists.
    fn from_args(args: SampleArgs) -> Result<Options, CliError> {
        let replay = args.replay.as_deref().map(parse_replay).transpose()?;
        let jobs = match args.jobs {
            Some(j) => usize::try_from(j).unwrap_or(usize::MAX),
            None => std::thread::available_parallelism().map(|p| p.get()).unwrap_or(1),
        };
        let shard = args.shard.as_deref().map(parse_shard).transpose()?;
        // A replay writes its sample as `build` does: with both drawings.
        let default_formats = if replay.is_some() { "json,svg,png" } else { "json" };
        let formats = parse_formats(args.formats.as_deref().unwrap_or(default_formats))?;
        let layout = args.layout.as_deref().map(parse_layout).transpose()?.unwrap_or(Layout::Folders);
        Ok(Options {
            n: args.n,
            seed: args.seed.expect("--seed is required without --unpack"),
            out: args.out,
            design_space: args.design_space,
            extended: args.extended,
            bodies: args.bodies,
            jobs,
            shard,
            formats,
            replay,
            layout,
            sim: args.sim,
        })
    }
}

/// `I/K` with `0 ≤ I < K`.
fn parse_shard(s: &str) -> Result<(u64, u64), CliError> {
    let bad = || usage(format!("sample --shard: expected I/K with 0 <= I < K (shard I of K, e.g. 0/4), got '{s}'"));
    let (i, k) = s.split_once('/').ok_or_else(bad)?;
    let (i, k): (u64, u64) = (i.trim().parse().map_err(|_| bad())?, k.trim().parse().map_err(|_| bad())?);
    if k == 0 || i >= k {
        return Err(bad());
    }
    Ok((i, k))
}

/// `INDEX` or `INDEX:ATTEMPT`.
fn parse_replay(s: &str) -> Result<(u64, Option<u32>), CliError> {
    let bad = || usage(format!("sample --replay: expected INDEX or INDEX:ATTEMPT (e.g. 42:3), got '{s}'"));
    let (i, a) = match s.split_once(':') {
        Some((i, a)) => (i, Some(a)),
        None => (s, None),
    };
    let index = i.trim().parse().map_err(|_| bad())?;
    let attempt = a.map(|a| a.trim().parse::<u32>().map_err(|_| bad())).transpose()?;
    if attempt.is_some_and(|a| a >= MAX_ATTEMPTS) {
        return Err(usage(format!("sample --replay: attempts are numbered 0 to {}", MAX_ATTEMPTS - 1)));
    }
    Ok((index, attempt))
}

fn parse_formats(s: &str) -> Result<Formats, CliError> {
    let mut f = Formats::default();
    for name in s.split(',').map(str::trim) {
        match name {
            "json" => f.json = true,
            "svg" => f.svg = true,
            "png" => f.png = true,
            "mesh" => f.mesh = true,
            "drape" => f.drape = true,
            other => {
                return Err(usage(format!("sample --formats: unknown format '{other}' (expected a list of json, svg, png, mesh, drape)")));
            }
        }
    }
    Ok(f)
}

/// The design space: the built-in one (the reference's, or with `extended` the
/// reference's followed by `design.extension`), or a design file's ranges and
/// probabilities over it.
pub fn load_space(file: Option<&str>, extended: bool) -> Result<(garmentcode::DesignSpace, String), CliError> {
    let (base, label) =
        if extended { (garments::design::extended_design_space(), "built-in, extended") } else { (Design::design_space(), "built-in") };
    let Some(file) = file else { return Ok((base, label.into())) };
    let text = super::read_text(file).map_err(|e| CliError::Input(format!("{file}: cannot read the design space: {e}")))?;
    let space =
        garmentcode::DesignSpace::from_yaml(&text, file, &base).map_err(|e| CliError::Input(format!("invalid design space: {e}")))?;
    Ok((space, file.to_string()))
}

/// Bodies: built-in names or body files separated by commas, or a folder of body
/// files (`*.yaml`, or those in its `measurements/` folder as in GarmentCodeData's
/// body samples), sorted by name. A body's name is its built-in name or file stem.
pub fn load_bodies(arg: Option<&str>) -> Result<Vec<NamedBody>, CliError> {
    let arg = arg.unwrap_or(garments::builtin::DEFAULT_BODY);
    let mut files: Vec<String> = Vec::new();
    let dir = Path::new(arg);
    if dir.is_dir() {
        let dir = if dir.join("measurements").is_dir() { dir.join("measurements") } else { dir.to_path_buf() };
        let entries = std::fs::read_dir(&dir).map_err(|e| CliError::Input(format!("{}: cannot list bodies: {e}", dir.display())))?;
        for e in entries {
            let path = e.map_err(|e| CliError::Input(format!("{}: cannot list bodies: {e}", dir.display())))?.path();
            if path.extension().is_some_and(|x| x == "yaml" || x == "yml") {
                files.push(path.to_string_lossy().into_owned());
            }
        }
        files.sort();
        if files.is_empty() {
            return Err(CliError::Input(format!("{}: no body files (*.yaml) in this folder", dir.display())));
        }
    } else {
        files = arg.split(',').map(|s| s.trim().to_string()).collect();
    }
    let mut out: Vec<NamedBody> = Vec::new();
    for item in files {
        if item.is_empty() {
            return Err(usage(format!("sample --bodies: empty body name in '{arg}'")));
        }
        let builtin = if Path::new(&item).is_file() { None } else { garments::builtin::body(item.strip_suffix(".yaml").unwrap_or(&item)) };
        let (body, name) = match builtin {
            Some(b) => (b, item.strip_suffix(".yaml").unwrap_or(&item).to_string()),
            None if Path::new(&item).is_file() => {
                let text = super::read_text(&item).map_err(|e| CliError::Input(format!("{item}: cannot read: {e}")))?;
                let b = garments::builtin::body_from_yaml(&text, &item).map_err(|e| CliError::Input(e.to_string()))?;
                let stem = Path::new(&item).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| item.clone());
                (b, stem)
            }
            None => {
                let known: Vec<&str> = garments::builtin::BODIES.iter().map(|(n, _)| *n).collect();
                return Err(CliError::Input(format!(
                    "unknown body '{item}'{}: not a built-in body ({}), a body file or a folder of body files",
                    crate::commands::did_you_mean(&item, &known),
                    known.join(", ")
                )));
            }
        };
        if out.iter().any(|b| b.name == name) {
            return Err(CliError::Input(format!("body '{name}' is given twice")));
        }
        out.push(NamedBody { name, body });
    }
    Ok(out)
}

/// Create the output folder and check that files can be written into it.
fn prepare_out(dir: &Path) -> Result<(), CliError> {
    let fail = |e: std::io::Error| CliError::Input(format!("{}: cannot write the output folder: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(fail)?;
    let probe = dir.join(format!(".write-test-{}", std::process::id()));
    std::fs::write(&probe, b"").map_err(fail)?;
    std::fs::remove_file(&probe).map_err(fail)
}

/// How a run reports its progress to a caller: called on the calling thread with
/// the samples made so far and the samples to make, a few times a second and once
/// at the end; an error stops the run (after the samples in progress) with that
/// message.
pub type Report<'a> = &'a mut dyn FnMut(u64, u64) -> Result<(), String>;

/// `garmentcode sample`, with progress drawn on stderr.
pub fn run(args: SampleArgs) -> Result<i32, CliError> {
    run_reporting(args, None, false)
}

/// `garmentcode sample`, with progress given to `report` (instead of drawn on
/// stderr) when there is one, and without its messages on stderr when `quiet`:
/// the Python package's `sample_dataset`.
pub fn run_reporting(args: SampleArgs, mut report: Option<Report>, quiet: bool) -> Result<i32, CliError> {
    // What the run did (resumed, removed temporaries, the closing summary line), on
    // stderr unless `quiet`.
    let note = |m: std::fmt::Arguments| {
        if !quiet {
            eprintln!("{m}");
        }
    };
    if !args.unpack.is_empty() {
        return unpack(&args.unpack, &args.out);
    }
    let opts = Options::from_args(args)?;
    let (space, space_label) = load_space(opts.design_space.as_deref(), opts.extended)?;
    let bodies = load_bodies(opts.bodies.as_deref())?;
    let body_names: Vec<String> = bodies.iter().map(|b| b.name.clone()).collect();
    let sampler = DatasetSampler::new(opts.seed, space, bodies).map_err(|e| CliError::Input(e.to_string()))?;
    if let Some((index, attempt)) = opts.replay {
        return replay(&sampler, &opts, index, attempt);
    }
    let n = opts.n.expect("--n is required without --replay");
    // `--out /dev/null`: every sample is made (its files too) and discarded; nothing
    // is read or written. The floor the file system adds to.
    let discard = opts.out == Path::new("/dev/null");
    if !discard {
        prepare_out(&opts.out)?;
    }

    let drape = match opts.formats.drape {
        true => {
            Some((crate::commands::drape::load_fabric(&opts.sim.fabric)?, opts.sim.max_frames.map(|n| n as usize), opts.sim.max_seconds))
        }
        false => None,
    };
    let mut settings = Settings::new(&sampler, opts.formats, drape);
    if let Some(config) = settings.drape.as_mut() {
        // Jobs drape side by side: one thread each, or they would compete for the cores.
        config.threads = usize::from(opts.jobs > 1);
    }
    if let Some(config) = &settings.drape {
        for (b, meshes) in config.meshes.iter().enumerate() {
            if let Err(e) = &meshes[0] {
                note(format_args!("warning: body {}: {e}; its samples' drapes fail (recorded as body_mesh)", body_names[b]));
            }
        }
    }
    let (shard_i, shard_k) = opts.shard.unwrap_or((0, 1));
    let wanted = |i: u64| i % shard_k == shard_i;
    let start = Instant::now();
    // Every record is tallied as it comes and dropped: memory stays flat however
    // large the dataset.
    let mut tally = summary::Tally::new(&body_names);
    let mut made = 0usize;
    let (resumed, jobs, index) = match opts.layout {
        Layout::Folders => {
            let existing = if discard {
                store::Existing { finished: Vec::new(), removed_temps: 0 }
            } else {
                store::scan(&opts.out, &settings, n, wanted, |r| tally.add(&r)).map_err(CliError::Input)?
            };
            if existing.removed_temps > 0 {
                note(format_args!("removed {} unfinished sample folder(s) of an interrupted run", existing.removed_temps));
            }
            let finished = existing.finished;
            // Indices of this shard: shard_i, shard_i + K, ... below n.
            let slots = if shard_i < n { (n - shard_i).div_ceil(shard_k) } else { 0 };
            let todo = slots - finished.len() as u64;
            if !finished.is_empty() {
                note(format_args!("resuming: {} of {slots} samples already made", finished.len()));
            }
            let jobs = opts.jobs.min(todo.max(1) as usize);
            let index_of = |slot: u64| Some(shard_i + slot * shard_k).filter(|i| finished.binary_search(i).is_err());
            let work = |arena: &mut Arena, index: u64| match discard {
                true => store::draw(&settings, arena, index).map(|(record, _files)| record),
                false => store::make(&opts.out, &settings, arena, index),
            };
            let collect = |record: Record| {
                tally.add(&record);
                made += 1;
                Ok(())
            };
            pool(jobs, 16 * jobs, slots, todo, index_of, work, collect, report.take())?;
            (finished.len(), jobs, None)
        }
        Layout::Shards(size) => {
            let count = n.div_ceil(size);
            let wanted_shard = |k: u64| k % shard_k == shard_i;
            let mut writer = match discard {
                true => None,
                false => Some(shards::IndexWriter::new(&opts.out, &shards::index_file_name(opts.shard)).map_err(CliError::Failed)?),
            };
            let mut resumed = 0;
            let existing = match &mut writer {
                None => shards::Existing { done: Vec::new(), missing: Vec::new(), removed_temps: 0 },
                Some(writer) => {
                    let on_shard = |k: u64, records: &[Record], lines: &str| {
                        records.iter().for_each(|r| tally.add(r));
                        resumed += records.len();
                        writer.add(k, lines)
                    };
                    shards::scan(&opts.out, &settings, n, size, wanted_shard, on_shard).map_err(CliError::Input)?
                }
            };
            if existing.removed_temps > 0 {
                note(format_args!("removed {} unfinished shard(s) of an interrupted run", existing.removed_temps));
            }
            // Samples absent from a finished shard had every design rejected; their
            // records are drawn again (and a shard missing an accepted sample is not ours).
            let mut arena = Arena::new();
            for index in existing.missing {
                let (record, files) = store::draw(&settings, &mut arena, index).map_err(CliError::Failed)?;
                if files.is_some() {
                    return Err(CliError::Input(format!(
                        "{}: has no {}: the dataset was made with another --n or shard size; choose another --out or the same --layout and --n",
                        opts.out.join(shards::shard_name(index / size)).display(),
                        sample_name(index)
                    )));
                }
                tally.add(&record);
                resumed += 1;
            }
            let todo_shards: Vec<u64> = (0..count).filter(|&k| wanted_shard(k) && existing.done.binary_search(&k).is_err()).collect();
            let todo: u64 = todo_shards.iter().map(|&k| shards::range(k, size, n).count() as u64).sum();
            if !existing.done.is_empty() {
                note(format_args!("resuming: {} of {} shards already made", existing.done.len(), existing.done.len() + todo_shards.len()));
            }
            let jobs = opts.jobs.min(todo.max(1) as usize);
            let slots = todo_shards.len() as u64 * size;
            let index_of = |slot: u64| Some(todo_shards[(slot / size) as usize] * size + slot % size).filter(|&i| i < n);
            let work = |arena: &mut Arena, index: u64| store::draw(&settings, arena, index);
            // Shards in progress, each written as its samples come in.
            let mut writers: BTreeMap<u64, shards::ShardWriter> = BTreeMap::new();
            let out = (!discard).then_some(opts.out.as_path());
            let collect = |(record, files): (Record, Option<store::Files>)| {
                let k = record.index / size;
                let shard = writers.entry(k).or_insert_with(|| shards::ShardWriter::new(out, k, shards::range(k, size, n)));
                if let Some(lines) = shard.add(&record, files)? {
                    writers.remove(&k);
                    if let Some(writer) = &mut writer {
                        writer.add(k, &lines)?;
                    }
                }
                tally.add(&record);
                made += 1;
                Ok(())
            };
            // Finished samples wait in memory with their files: a few megabytes each with meshes.
            let queue = if opts.formats.mesh || opts.formats.drape { jobs } else { 16 * jobs };
            pool(jobs, queue, slots, todo, index_of, work, collect, report.take())?;
            (resumed, jobs, writer)
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    let about = summary::About {
        seed: opts.seed,
        n,
        shard: opts.shard,
        design_space: &space_label,
        bodies: body_names,
        formats: opts.formats.names(),
        seconds,
        made,
        resumed,
        jobs,
    };
    let props = opts.out.join(summary::file_name(opts.shard));
    let summary_at = if discard { "none written (--out /dev/null)".to_string() } else { format!("summary in {}", props.display()) };
    if let Some(index) = index {
        index.finish().map_err(CliError::Failed)?;
    }
    if !discard {
        let mut set = OutputSet::default();
        set.add(&summary::file_name(opts.shard), tally.properties(&about));
        set.write_files_into(&opts.out).map_err(|e| CliError::Failed(format!("cannot write {}: {e}", props.display())))?;
    }

    let failed = tally.failed();
    let rate = if seconds > 0.0 { made as f64 / seconds } else { 0.0 };
    note(format_args!(
        "{}: {} samples ({made} made in {seconds:.2} s, {rate:.0}/s; {resumed} already there); {} designs rejected and drawn again; {summary_at}",
        opts.out.display(),
        tally.samples(),
        tally.rejected(),
    ));
    if opts.formats.drape && tally.failed_drapes() > 0 {
        note(format_args!("{} drape(s) failed (kept with their other files; by reason in the summary)", tally.failed_drapes()));
    }
    if !failed.is_empty() {
        let shown: Vec<&str> = failed.iter().take(10).map(String::as_str).collect();
        return Err(CliError::Failed(format!(
            "{} sample(s) had every one of {MAX_ATTEMPTS} designs rejected: {}{} ({summary_at})",
            failed.len(),
            shown.join(", "),
            if failed.len() > shown.len() { ", ..." } else { "" },
        )));
    }
    Ok(0)
}

/// Run `work` over `jobs` threads on the sample indices of `slots` slots
/// (`index_of` gives a slot's index, `None` to skip it), handing each result to
/// `collect` on this thread. Stops at the first error, after the samples in
/// progress. `todo` is the number of samples, for the progress line (or for
/// `report`, which replaces it); at most `queue` results wait for `collect`
/// (workers wait beyond that).
fn pool<T: Send>(
    jobs: usize,
    queue: usize,
    slots: u64,
    todo: u64,
    index_of: impl Fn(u64) -> Option<u64> + Sync,
    work: impl Fn(&mut Arena, u64) -> Result<T, String> + Sync,
    mut collect: impl FnMut(T) -> Result<(), String>,
    mut report: Option<Report>,
) -> Result<(), CliError> {
    let next = AtomicU64::new(0);
    let stop = AtomicBool::new(false);
    // Bounded, so that workers faster than the collector (a slow disk, large mesh
    // files) wait instead of piling results up in memory.
    let (tx, rx) = mpsc::sync_channel::<Result<T, String>>(queue);
    let mut error: Option<String> = None;
    let mut progress = progress::Progress::new(todo);
    let mut done_count = 0u64;
    let collector = std::thread::current();
    let running = AtomicUsize::new(jobs);
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            let tx = tx.clone();
            let (next, stop, index_of, work) = (&next, &stop, &index_of, &work);
            let (collector, running) = (&collector, &running);
            scope.spawn(move || {
                // The last worker to finish wakes the collector at once.
                struct Done<'a>(&'a AtomicUsize, &'a std::thread::Thread);
                impl Drop for Done<'_> {
                    fn drop(&mut self) {
                        if self.0.fetch_sub(1, Ordering::AcqRel) == 1 {
                            self.1.unpark();
                        }
                    }
                }
                let _done = Done(running, collector);
                // Declared after `_done`, so dropped (closing the channel) before it.
                let tx = tx;
                let mut arena = Arena::new();
                while !stop.load(Ordering::Relaxed) {
                    let slot = next.fetch_add(1, Ordering::Relaxed);
                    if slot >= slots {
                        break;
                    }
                    let Some(index) = index_of(slot) else { continue };
                    let result = work(&mut arena, index);
                    if result.is_err() {
                        stop.store(true, Ordering::Relaxed);
                    }
                    let sent = match tx.try_send(result) {
                        Ok(()) => Ok(()),
                        // Full: wake the collector, then wait for room.
                        Err(mpsc::TrySendError::Full(result)) => {
                            collector.unpark();
                            tx.send(result).map_err(|_| ())
                        }
                        Err(mpsc::TrySendError::Disconnected(_)) => Err(()),
                    };
                    if sent.is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        // Results are collected in batches: waking this thread for every sample
        // (thousands a second) would take the cores from the workers.
        let mut done = false;
        while !done {
            std::thread::park_timeout(Duration::from_millis(20));
            loop {
                match rx.try_recv() {
                    Ok(Ok(made)) => {
                        if error.is_none()
                            && let Err(e) = collect(made)
                        {
                            stop.store(true, Ordering::Relaxed);
                            error = Some(e);
                        }
                        progress.inc();
                        done_count += 1;
                    }
                    Ok(Err(e)) => {
                        error.get_or_insert(e);
                    }
                    Err(mpsc::TryRecvError::Empty) => break,
                    Err(mpsc::TryRecvError::Disconnected) => {
                        done = true;
                        break;
                    }
                }
            }
            match report.as_mut() {
                Some(report) => {
                    if let Err(e) = report(done_count, todo) {
                        stop.store(true, Ordering::Relaxed);
                        error.get_or_insert(e);
                    }
                }
                None => progress.tick(),
            }
        }
    });
    match report {
        Some(report) => {
            if let Err(e) = report(done_count, todo) {
                error.get_or_insert(e);
            }
        }
        None => progress.finish(),
    }
    match error {
        Some(e) => Err(CliError::Failed(format!("{e}\nstopped; the samples written so far are complete, rerun to resume"))),
        None => Ok(()),
    }
}

/// `--unpack SHARD.tar ... --out DIR`.
fn unpack(shards: &[PathBuf], out: &Path) -> Result<i32, CliError> {
    shards::check_archives(shards).map_err(CliError::Input)?;
    prepare_out(out)?;
    let count = shards::unpack(shards, out).map_err(CliError::Input)?;
    eprintln!("{}: {count} sample folder(s) from {} shard(s)", out.display(), shards.len());
    Ok(0)
}

/// The drape files of a replayed sample (`--formats ...,drape`) on its body's mesh; returns
/// the drape's failure reasons.
fn replay_drape(
    set: &mut OutputSet,
    opts: &Options,
    pattern: &garmentcode::Pattern,
    mesh: &garmentcode::mesh::BoxMesh,
    body: (&garmentcode::Body, &str),
) -> Result<Vec<&'static str>, CliError> {
    use crate::commands::drape;
    let fabric = drape::load_fabric(&opts.sim.fabric)?;
    let (body_mesh, source) = drape::load_body_mesh(None, body.1, body.0)?;
    let setup = drape::DrapeSetup {
        body: &body_mesh,
        body_source: &source,
        measurements: body,
        fabric: &fabric,
        max_frames: opts.sim.max_frames.map(|n| n as usize),
        max_seconds: opts.sim.max_seconds,
        threads: 0,
    };
    let mut progress = drape::ProgressLine::new(false);
    let draped = drape::drape_files(pattern, mesh, &setup, |p| progress.frame(p));
    progress.finish();
    let draped = draped.map_err(|e| CliError::Failed(format!("{}: cannot drape on {}: {e}", pattern.name, body.1)))?;
    for (file, bytes) in draped.files {
        set.add(&file, bytes);
    }
    Ok(draped.fails)
}

/// `--replay INDEX[:ATTEMPT]`: rebuild one sample (or one attempt of it, accepted
/// or rejected) into `--out` as `garmentcode build` would, with its checks.
fn replay(sampler: &DatasetSampler, opts: &Options, index: u64, attempt: Option<u32>) -> Result<i32, CliError> {
    let mut arena = Arena::new();
    let name = sample_name(index);
    let attempt = match attempt {
        Some(a) => a,
        None => match sampler.draw_in(&mut arena, index) {
            Outcome::Accepted(s) => s.attempt,
            Outcome::Exhausted { .. } => {
                return Err(CliError::Rejected(format!(
                    "{name}: every one of {MAX_ATTEMPTS} designs was rejected; replay one with --replay {index}:ATTEMPT"
                )));
            }
        },
    };
    let (design, body) = sampler.attempt(index, attempt);
    let verdict = match sampler.check(&mut arena, &design, body, &name) {
        Ok(_) => "accepted".to_string(),
        Err((reason, message)) => format!("rejected ({reason}: {message})"),
    };
    let mut set = OutputSet::default();
    set.add("design_params.yaml", write_design(&design, sampler.space()));
    set.add("body_measurements.yaml", sampler.body_for(body, &design).to_yaml());
    // Rebuild without the filters to write whatever the garment program makes.
    match garments::build::build_in(&mut arena, &design, &sampler.bodies()[body].body, &name) {
        Ok(built) => {
            set.add("specification.json", built.pattern.to_json().map_err(|e| CliError::Failed(e.to_string()))?);
            if opts.formats.svg || opts.formats.png {
                crate::commands::add_drawings(&mut set, &built.pattern, opts.formats.png, garmentcode::draw::Layout::Placed)
                    .map_err(|e| CliError::Failed(e.to_string()))?;
            }
            if opts.formats.mesh || opts.formats.drape {
                let mesh = garmentcode::mesh::BoxMesh::new(&built.pattern, garmentcode::mesh::DEFAULT_RESOLUTION)
                    .map_err(|e| CliError::Failed(format!("{name}: cannot mesh the pattern: {e}")))?;
                if opts.formats.drape {
                    let fails = replay_drape(
                        &mut set,
                        opts,
                        &built.pattern,
                        &mesh,
                        (&sampler.body_for(body, &design), &sampler.bodies()[body].name),
                    )?;
                    if !fails.is_empty() {
                        eprintln!("{name}: the drape failed the reference's checks: {}", fails.join(", "));
                    }
                }
                crate::commands::add_mesh(&mut set, mesh);
            }
            set.add("checks.json", built.checks.to_json());
        }
        Err(e) => set.add("error.txt", format!("{e}\n")),
    }
    crate::commands::write_folder(&set, &opts.out, false)?;
    eprintln!("{name} attempt {attempt} on {}: {verdict}; wrote {}", sampler.bodies()[body].name, opts.out.display());
    Ok(0)
}
