//! `garmentcode sample`: the same dataset whatever the number of threads or shards,
//! resumable, never a partial sample folder, and bad input refused before any work.

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, SystemTime};

const BIN: &str = env!("CARGO_BIN_EXE_garmentcode");

mod common;
use common::scratch;

fn sample(args: &[&str]) -> Output {
    Command::new(BIN).arg("sample").args(args).output().unwrap()
}

fn sample_ok(args: &[&str]) -> String {
    let out = sample(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "garmentcode sample {args:?} failed: {stderr}");
    stderr
}

/// Every file below `dir` by relative path. The `run:` section of the summaries
/// (time, threads) is cut off: it describes the run, not the dataset.
fn tree(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
        for e in fs::read_dir(dir).unwrap() {
            let path = e.unwrap().path();
            if path.is_dir() {
                walk(root, &path, out);
                continue;
            }
            let rel = path.strip_prefix(root).unwrap().to_string_lossy().into_owned();
            let mut bytes = fs::read(&path).unwrap();
            if rel.starts_with("dataset_properties") {
                let text = String::from_utf8(bytes).unwrap();
                bytes = text.as_bytes()[..text.find("\nrun:\n").expect("a run section")].to_vec();
            }
            out.insert(rel, bytes);
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

/// Only the sample folders' files.
fn samples(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    tree(dir).into_iter().filter(|(k, _)| k.starts_with("rand_")).collect()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every sample folder is whole: the record and every file; no temporaries.
fn assert_whole(dir: &Path, n_files: usize) {
    for e in fs::read_dir(dir).unwrap() {
        let e = e.unwrap();
        let name = e.file_name().to_string_lossy().into_owned();
        assert!(!name.starts_with('.'), "left over: {name}");
        if name.starts_with("rand_") {
            let files = fs::read_dir(e.path()).unwrap().count();
            assert_eq!(files, n_files, "{name} has {files} files");
            let info = fs::read_to_string(e.path().join("sample_info.json")).unwrap();
            serde_json::from_str::<serde_json::Value>(&info).unwrap();
        }
    }
}

#[test]
fn threads_do_not_change_the_dataset() {
    let dir = scratch("threads");
    let (one, two) = (dir.join("one"), dir.join("two"));
    sample_ok(&["--n", "24", "--seed", "3", "--out", s(&one), "--jobs", "1", "--formats", "json,svg,png"]);
    sample_ok(&["--n", "24", "--seed", "3", "--out", s(&two), "--jobs", "2", "--formats", "png,svg,json"]);
    let (a, b) = (tree(&one), tree(&two));
    assert_eq!(a.keys().filter(|k| k.ends_with("sample_info.json")).count(), 24);
    assert!(a.contains_key("rand_0000000/rand_0000000_specification.json"));
    assert!(a.contains_key("rand_0000023/rand_0000023_pattern.svg"));
    assert!(a.contains_key("rand_0000023/rand_0000023_pattern.png"));
    assert!(a.contains_key("dataset_properties.yaml"));
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>());
    for (k, v) in &a {
        assert!(*v == b[k], "{k} differs between --jobs 1 and --jobs 2");
    }
    assert_whole(&one, 6);
    // Another seed, another dataset.
    let other = dir.join("other");
    sample_ok(&["--n", "2", "--seed", "4", "--out", s(&other)]);
    assert_ne!(tree(&other)["rand_0000000/design_params.yaml"], a["rand_0000000/design_params.yaml"]);
}

#[test]
fn shards_make_the_unsharded_dataset() {
    let dir = scratch("shards");
    let whole = dir.join("whole");
    sample_ok(&["--n", "20", "--seed", "9", "--out", s(&whole)]);
    let expected = samples(&whole);
    assert_eq!(expected.keys().filter(|k| k.ends_with("sample_info.json")).count(), 20);

    // Each shard in its own folder: their union is the dataset.
    let mut union = BTreeMap::new();
    for i in 0..3 {
        let part = dir.join(format!("part{i}"));
        sample_ok(&["--n", "20", "--seed", "9", "--out", s(&part), "--shard", &format!("{i}/3"), "--jobs", "1"]);
        let got = samples(&part);
        assert!(got.keys().all(|k| k[5..12].parse::<u64>().unwrap() % 3 == i), "shard {i} made a sample of another shard");
        union.extend(got);
        assert!(part.join(format!("dataset_properties_shard_{i}_of_3.yaml")).is_file());
    }
    assert_eq!(union, expected, "the union of the shards is not the unsharded dataset");

    // All shards into one folder, then an unsharded run: nothing left to make, and
    // the same summary as the unsharded dataset's.
    let shared = dir.join("shared");
    for i in (0..3).rev() {
        sample_ok(&["--n", "20", "--seed", "9", "--out", s(&shared), "--shard", &format!("{i}/3")]);
    }
    let log = sample_ok(&["--n", "20", "--seed", "9", "--out", s(&shared)]);
    assert!(log.contains("0 made"), "{log}");
    let got = tree(&shared);
    assert_eq!(samples(&shared), expected);
    assert_eq!(got["dataset_properties.yaml"], tree(&whole)["dataset_properties.yaml"]);
}

fn mtimes(dir: &Path) -> BTreeMap<String, SystemTime> {
    tree(dir)
        .keys()
        .filter(|k| k.starts_with("rand_"))
        .map(|k| (k.clone(), fs::metadata(dir.join(k)).unwrap().modified().unwrap()))
        .collect()
}

#[test]
fn a_rerun_makes_only_the_missing_samples() {
    let dir = scratch("resume").join("data");
    let args = ["--n", "12", "--seed", "5", "--out", s(&dir)];
    sample_ok(&args);
    let before = tree(&dir);
    let times = mtimes(&dir);
    fs::remove_dir_all(dir.join("rand_0000005")).unwrap();
    // The leftovers of an interrupted run.
    fs::create_dir(dir.join(".rand_0000007.tmp-12345")).unwrap();
    fs::write(dir.join(".rand_0000007.tmp-12345/design_params.yaml"), "partial").unwrap();
    std::thread::sleep(Duration::from_millis(20));

    let log = sample_ok(&args);
    assert!(log.contains("1 made") && log.contains("11 already there"), "{log}");
    assert_eq!(tree(&dir), before, "the dataset after resuming differs");
    assert_whole(&dir, 4);
    for (file, t) in mtimes(&dir) {
        if file.starts_with("rand_0000005/") {
            assert!(t > times[&file], "{file} was not rebuilt");
        } else {
            assert_eq!(t, times[&file], "{file} was rewritten");
        }
    }
    let props = fs::read_to_string(dir.join("dataset_properties.yaml")).unwrap();
    assert!(props.contains("made: 1\n  resumed: 11\n"), "{props}");

    // A larger n extends the dataset; the first samples stay as they are.
    sample_ok(&["--n", "14", "--seed", "5", "--out", s(&dir)]);
    let extended = samples(&dir);
    assert!(samples(&dir).len() > before.len() - 1);
    for (k, v) in before.iter().filter(|(k, _)| k.starts_with("rand_")) {
        assert_eq!(&extended[k], v);
    }
}

#[test]
fn an_interrupted_run_leaves_only_whole_samples() {
    let dir = scratch("interrupt");
    let (cut, full) = (dir.join("cut"), dir.join("full"));
    let mut child = Command::new(BIN)
        .args(["sample", "--n", "400", "--seed", "2", "--jobs", "2", "--out", s(&cut)])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // Kill it (SIGKILL: no chance to clean up) once it has made a few samples.
    let started = std::time::Instant::now();
    while fs::read_dir(&cut).map(|d| d.count()).unwrap_or(0) < 10 && started.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(2));
    }
    let _ = child.kill();
    child.wait().unwrap();
    let made = fs::read_dir(&cut).unwrap().filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().starts_with("rand_")).count();
    assert!(made < 400, "the run was not interrupted");
    for e in fs::read_dir(&cut).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if name.starts_with("rand_") {
            assert_eq!(fs::read_dir(&path).unwrap().count(), 4, "{name} is partial");
        }
    }
    sample_ok(&["--n", "400", "--seed", "2", "--out", s(&cut)]);
    assert_whole(&cut, 4);
    sample_ok(&["--n", "400", "--seed", "2", "--out", s(&full)]);
    assert_eq!(samples(&cut), samples(&full));
}

#[test]
fn design_space_files_and_bodies_are_honoured() {
    let dir = scratch("space");
    let space = dir.join("space.yaml");
    // Only fitted tops with a pencil skirt, on two bodies.
    fs::write(
        &space,
        "design:\n  meta:\n    upper:\n      v: FittedShirt\n      range: [FittedShirt, Shirt, null]\n      type: select_null\n      default_prob: 1.0\n    bottom:\n      v: PencilSkirt\n      range: [PencilSkirt]\n      type: select_null\n      default_prob: 1.0\n",
    )
    .unwrap();
    let out = dir.join("data");
    sample_ok(&["--n", "6", "--seed", "1", "--out", s(&out), "--design-space", s(&space), "--bodies", "mean_female,mean_male"]);
    let props = fs::read_to_string(out.join("dataset_properties.yaml")).unwrap();
    assert!(props.contains("FittedShirt: 6\n"), "{props}");
    assert!(props.contains("PencilSkirt: 6\n"), "{props}");
    assert!(props.contains(&format!("design_space: {}\n", s(&space))), "{props}");
    assert!(props.contains("bodies:\n- mean_female\n- mean_male\n"), "{props}");
    for i in 0..6 {
        let body = fs::read_to_string(out.join(format!("rand_{i:07}/body_measurements.yaml"))).unwrap();
        assert!(body.contains("body_sample: mean_female\n") || body.contains("body_sample: mean_male\n"), "{body}");
    }

    // A rejected attempt can be rebuilt on its own.
    let replay = dir.join("replay");
    let r =
        sample(&["--seed", "1", "--replay", "0:0", "--out", s(&replay), "--design-space", s(&space), "--bodies", "mean_female,mean_male"]);
    assert!(r.status.success());
    assert!(replay.join("design_params.yaml").is_file() && replay.join("checks.json").is_file());
    // Drawn as `build` draws.
    assert!(replay.join("pattern.svg").is_file() && replay.join("pattern.png").is_file());
    let again = dir.join("again");
    sample_ok(&["--seed", "1", "--replay", "3", "--out", s(&again), "--design-space", s(&space), "--bodies", "mean_female,mean_male"]);
    assert_eq!(fs::read(again.join("design_params.yaml")).unwrap(), fs::read(out.join("rand_0000003/design_params.yaml")).unwrap());
}

#[test]
fn bad_input_is_refused_before_any_work() {
    let dir = scratch("bad");
    let bad_space = dir.join("bad_space.yaml");
    fs::write(&bad_space, "design:\n  waistband:\n    waist:\n      v: 1.5\n      range: [2, 1]\n").unwrap();
    let wrong_type = dir.join("wrong_type.yaml");
    fs::write(&wrong_type, "design:\n  meta:\n    upper:\n      v: Shirt\n      type: float\n").unwrap();
    let a_file = dir.join("a_file");
    fs::write(&a_file, "not a folder").unwrap();
    let out = dir.join("out");
    let o = s(&out);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--n", "0", "--seed", "1", "--out", o], "--n"),
        (vec!["--n", "ten", "--seed", "1", "--out", o], "--n"),
        (vec!["--seed", "1", "--out", o], "--n"),
        (vec!["--n", "3", "--out", o], "--seed"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--shard", "3/2"], "--shard"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--shard", "0/0"], "--shard"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--shard", "half"], "--shard"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--jobs", "0"], "--jobs"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--formats", "pdf"], "--formats"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--bodies", "mean_all,giant"], "unknown body 'giant'"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--design-space", s(&bad_space)], "range"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--design-space", s(&wrong_type)], "type"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--design-space", "/no/such/space.yaml"], "cannot read"),
        (vec!["--n", "3", "--seed", "1", "--out", o, "--colour", "red"], "'--colour'"),
    ];
    for (args, expect) in cases {
        let r = sample(&args);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(expect), "{args:?}: expected '{expect}' in: {err}");
        assert!(!out.exists(), "{args:?} wrote something");
    }
    // An output folder that cannot be made.
    let inside_file = a_file.join("out");
    let r = sample(&["--n", "3", "--seed", "1", "--out", s(&inside_file)]);
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("cannot write the output folder"));

    // A folder holding another dataset is refused, and left alone.
    sample_ok(&["--n", "2", "--seed", "1", "--out", o]);
    let before = tree(&out);
    let r = sample(&["--n", "2", "--seed", "2", "--out", o]);
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("seed 1, not 2"));
    let r = sample(&["--n", "2", "--seed", "1", "--out", o, "--bodies", "mean_male"]);
    assert_eq!(r.status.code(), Some(2));
    assert_eq!(tree(&out), before);
}

/// The members of a tar archive: name and header fields (mode, uid, gid, mtime as
/// written) and size.
fn members(tar: &[u8]) -> Vec<(String, [String; 4], usize)> {
    let mut out = Vec::new();
    let mut at = 0;
    while tar[at..at + 512].iter().any(|&b| b != 0) {
        let h = &tar[at..at + 512];
        let text = |r: std::ops::Range<usize>| String::from_utf8(h[r].iter().copied().take_while(|&b| b != 0).collect()).unwrap();
        let size = usize::from_str_radix(&text(124..135), 8).unwrap();
        out.push((text(0..100), [text(100..107), text(108..115), text(116..123), text(136..147)], size));
        at += 512 + size.next_multiple_of(512);
    }
    out
}

/// The shard files of a folder, by name.
fn shard_files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    tree(dir).into_iter().filter(|(k, _)| k.starts_with("shard-")).collect()
}

/// `sample --unpack` of the named shards of `sharded` into `out`.
fn unpack<'a>(sharded: &Path, shards: impl Iterator<Item = &'a String>, out: &Path) {
    let paths: Vec<String> = shards.map(|k| s(&sharded.join(k)).to_string()).collect();
    let mut args = vec!["--unpack"];
    args.extend(paths.iter().map(String::as_str));
    args.extend(["--out", s(out)]);
    sample_ok(&args);
}

#[test]
fn shards_hold_the_folder_dataset_and_unpack_to_it() {
    let dir = scratch("shard_layout");
    let (folders, sharded, unpacked) = (dir.join("folders"), dir.join("sharded"), dir.join("unpacked"));
    sample_ok(&["--n", "25", "--seed", "5", "--out", s(&folders), "--formats", "json,svg"]);
    sample_ok(&["--n", "25", "--seed", "5", "--out", s(&sharded), "--formats", "json,svg", "--layout", "shards:10"]);
    let shards = shard_files(&sharded);
    assert_eq!(shards.keys().collect::<Vec<_>>(), ["shard-000000.tar", "shard-000001.tar", "shard-000002.tar"]);

    // Shard 1 holds samples 10..19, five files each, sorted by key, fixed headers.
    let list = members(&shards["shard-000001.tar"]);
    let names: Vec<&str> = list.iter().map(|m| m.0.as_str()).collect();
    let mut sorted = names.clone();
    sorted.sort();
    assert_eq!(names, sorted);
    assert_eq!(names.len(), 50);
    for suffix in ["specification.json", "pattern.svg", "design_params.yaml", "body_measurements.yaml", "sample_info.json"] {
        for i in 10..20 {
            assert!(names.contains(&format!("rand_{i:07}.{suffix}").as_str()), "shard 1 lacks rand_{i:07}.{suffix}");
        }
    }
    for (name, fields, _) in &list {
        assert_eq!(fields, &["0000644", "0000000", "0000000", "00000000000"].map(String::from), "{name}");
    }
    // A member's bytes are the folder's file.
    let info = fs::read(folders.join("rand_0000012/sample_info.json")).unwrap();
    assert!(shards["shard-000001.tar"].windows(info.len()).any(|w| w == info));

    // The index: one line per sample with its shard, type and panels as recorded.
    let index = fs::read_to_string(sharded.join("index.jsonl")).unwrap();
    assert_eq!(index.lines().count(), 25);
    for line in index.lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let key = v["key"].as_str().unwrap();
        let i: u64 = key[5..].parse().unwrap();
        assert_eq!(v["shard"], format!("shard-{:06}.tar", i / 10));
        let info: serde_json::Value =
            serde_json::from_str(&fs::read_to_string(folders.join(key).join("sample_info.json")).unwrap()).unwrap();
        assert_eq!(v["type"], info["garment"]["main"]);
        assert_eq!(v["panels"], info["garment"]["panels"]);
    }

    // Unpacked, the shards are the folder layout byte for byte; the summaries agree
    // but for the run section.
    unpack(&sharded, shards.keys(), &unpacked);
    assert_eq!(tree(&unpacked), tree(&folders), "the unpacked shards are not the folder layout");
    assert_whole(&unpacked, 5);
    assert_eq!(tree(&sharded)["dataset_properties.yaml"], tree(&folders)["dataset_properties.yaml"]);
    // One shard on its own: its samples, with the dataset's summary.
    let one = dir.join("one");
    unpack(&sharded, ["shard-000001.tar".to_string()].iter(), &one);
    let expected: BTreeMap<String, Vec<u8>> = tree(&folders)
        .into_iter()
        .filter(|(k, _)| k.starts_with("dataset_properties") || (10..20).any(|i| k.starts_with(&format!("rand_{i:07}/"))))
        .collect();
    assert_eq!(tree(&one), expected);
}

#[test]
fn shards_are_the_same_whatever_jobs_and_shard() {
    let dir = scratch("shard_determinism");
    let (one, two, split) = (dir.join("one"), dir.join("two"), dir.join("split"));
    let base = ["--n", "23", "--seed", "8", "--layout", "shards:6"];
    sample_ok(&[&base[..], &["--out", s(&one), "--jobs", "1"]].concat());
    sample_ok(&[&base[..], &["--out", s(&two), "--jobs", "2"]].concat());
    sample_ok(&[&base[..], &["--out", s(&split), "--jobs", "2", "--shard", "1/2"]].concat());
    // Task 1 of 2 writes shards 1 and 3 only.
    assert_eq!(shard_files(&split).keys().collect::<Vec<_>>(), ["shard-000001.tar", "shard-000003.tar"]);
    assert!(split.join("index_shard_1_of_2.jsonl").is_file() && split.join("dataset_properties_shard_1_of_2.yaml").is_file());
    sample_ok(&[&base[..], &["--out", s(&split), "--jobs", "1", "--shard", "0/2"]].concat());
    let expected = shard_files(&one);
    assert_eq!(expected.len(), 4);
    assert_eq!(shard_files(&two), expected, "--jobs 2 made other shards than --jobs 1");
    assert_eq!(shard_files(&split), expected, "--shard 0/2 + 1/2 made other shards than one run");
    // The two tasks' indexes together are the whole index.
    let whole = fs::read_to_string(one.join("index.jsonl")).unwrap();
    let mut lines: Vec<String> = ["index_shard_0_of_2.jsonl", "index_shard_1_of_2.jsonl"]
        .iter()
        .flat_map(|f| fs::read_to_string(split.join(f)).unwrap().lines().map(String::from).collect::<Vec<_>>())
        .collect();
    lines.sort();
    assert_eq!(lines, whole.lines().map(String::from).collect::<Vec<_>>());
}

#[test]
fn a_sharded_run_resumes_shard_by_shard() {
    let dir = scratch("shard_resume");
    let out = dir.join("data");
    let args = ["--n", "25", "--seed", "6", "--layout", "shards:10", "--out", s(&out)];
    sample_ok(&args);
    let before = tree(&out);
    // Shard 1 deleted, a temporary of shard 2 and one of shard 1 left behind, and
    // the index being gathered by a killed run.
    fs::remove_file(out.join("shard-000001.tar")).unwrap();
    fs::write(out.join(".shard-000001.tar.tmp-99999"), b"half a shard").unwrap();
    fs::write(out.join(".shard-000002.tar.tmp-99998"), b"half a shard").unwrap();
    fs::write(out.join(".index.jsonl.parts-99997"), b"{\"key\": \"rand_0000003\"}\n").unwrap();
    let err = sample_ok(&args);
    assert!(err.contains("removed 2 unfinished shard(s)"), "{err}");
    assert!(err.contains("resuming: 2 of 3 shards already made"), "{err}");
    assert!(err.contains("(10 made"), "only shard 1 is made again: {err}");
    assert_eq!(tree(&out), before, "the resumed dataset differs from the uninterrupted one");
    assert!(fs::read_dir(&out).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().starts_with('.')));
    // Nothing to do: every shard is checked and kept.
    let err = sample_ok(&args);
    assert!(err.contains("(0 made"), "{err}");
}

#[test]
fn bad_shard_input_is_a_clear_error() {
    let dir = scratch("shard_errors");
    let out = dir.join("data");
    for (layout, says) in [("shards:0", "shards:N with N >= 1"), ("shards:x", "--layout"), ("tiles", "--layout")] {
        let r = sample(&["--n", "2", "--seed", "1", "--out", s(&out), "--layout", layout]);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(2), "{layout}: {err}");
        assert!(err.contains(says), "{layout}: {err}");
    }
    let args = ["--n", "12", "--seed", "1", "--layout", "shards:5", "--out", s(&out)];
    sample_ok(&args);
    let fail = |args: &[&str], says: &str| {
        let r = sample(args);
        let err = String::from_utf8_lossy(&r.stderr).into_owned();
        assert_eq!(r.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    };
    // Another shard size into the same folder.
    fail(&["--n", "12", "--seed", "1", "--layout", "shards:4", "--out", s(&out)], "another shard size");
    // Another seed.
    fail(&["--n", "12", "--seed", "2", "--layout", "shards:5", "--out", s(&out)], "seed 1, not 2");
    // A damaged shard is named, and left for the user to delete.
    let shard = out.join("shard-000001.tar");
    let bytes = fs::read(&shard).unwrap();
    fs::write(&shard, &bytes[..bytes.len() / 2]).unwrap();
    fail(&args, "shard-000001.tar: a damaged shard");
    assert!(shard.is_file());
    // Unpacking what is not a shard.
    let not_tar = dir.join("notes.json");
    fs::write(&not_tar, "{\"not\": \"a tar archive, but long enough to hold a header block of 512 bytes\"}".repeat(10)).unwrap();
    fail(&["--unpack", s(&not_tar), "--out", s(&dir.join("u1"))], "not a tar archive");
    fail(&["--unpack", s(&dir.join("missing.tar")), "--out", s(&dir.join("u2"))], "cannot read");
    fail(&["--unpack", s(&shard), "--out", s(&dir.join("u3")), "--n", "3"], "cannot be used with");
    // Every shard is checked before anything is unpacked.
    let u4 = dir.join("u4");
    fail(&["--unpack", s(&out.join("shard-000000.tar")), s(&shard), "--out", s(&u4)], "shard-000001.tar");
    assert!(!u4.exists(), "a run that failed wrote {}", u4.display());
}

#[test]
fn mesh_samples_carry_the_box_mesh_in_both_layouts() {
    let dir = scratch("mesh_samples");
    let (folders, sharded, unpacked) = (dir.join("folders"), dir.join("sharded"), dir.join("unpacked"));
    sample_ok(&["--n", "4", "--seed", "3", "--out", s(&folders), "--formats", "json,mesh"]);
    sample_ok(&["--n", "4", "--seed", "3", "--out", s(&sharded), "--formats", "json,mesh", "--layout", "shards:2", "--jobs", "1"]);
    for i in 0..4 {
        let key = format!("rand_{i:07}");
        let folder = folders.join(&key);
        // The mesh is the pattern's: what `garmentcode mesh` makes of the sample's specification.
        let remeshed = dir.join(format!("remeshed-{i}"));
        let spec = folder.join(format!("{key}_specification.json"));
        let out = Command::new(BIN).args(["mesh", s(&spec), "--out", s(&remeshed)]).output().unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        for suffix in garmentcode::mesh::write::FILE_SUFFIXES {
            let file = format!("{key}{suffix}");
            let ours = fs::read(folder.join(&file)).unwrap_or_else(|e| panic!("{key} lacks {file}: {e}"));
            assert_eq!(ours, fs::read(remeshed.join(&file)).unwrap(), "{file} differs from garmentcode mesh's");
        }
        // One segmentation line per OBJ vertex.
        let obj = fs::read_to_string(folder.join(format!("{key}_boxmesh.obj"))).unwrap();
        let seg = fs::read_to_string(folder.join(format!("{key}_sim_segmentation.txt"))).unwrap();
        assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), seg.lines().count());
    }
    // The shards hold the same files, and unpack to the folder layout.
    let shards = shard_files(&sharded);
    let names: Vec<String> = members(&shards["shard-000000.tar"]).into_iter().map(|m| m.0).collect();
    assert!(names.contains(&"rand_0000001.boxmesh.obj".to_string()), "{names:?}");
    unpack(&sharded, shards.keys(), &unpacked);
    assert_eq!(samples(&unpacked), samples(&folders));
    // A rerun with the same formats finds every sample whole.
    let again = sample_ok(&["--n", "4", "--seed", "3", "--out", s(&sharded), "--formats", "json,mesh", "--layout", "shards:2"]);
    assert!(again.contains("0 made") || again.contains("4 already there"), "{again}");
}

#[test]
fn samples_made_into_dev_null_are_discarded() {
    if !Path::new("/dev/null").exists() {
        eprintln!("skipped: this system has no /dev/null");
        return;
    }
    for layout in ["folders", "shards:4"] {
        let err = sample_ok(&["--n", "9", "--seed", "3", "--layout", layout, "--jobs", "2", "--out", "/dev/null"]);
        assert!(err.contains("/dev/null: 9 samples (9 made"), "{layout}: {err}");
        assert!(err.contains("none written"), "{layout}: {err}");
    }
    // The same tally as the run that writes.
    let dir = scratch("dev_null");
    let err = sample_ok(&["--n", "9", "--seed", "3", "--out", s(&dir.join("data"))]);
    let rejected = |e: &str| e.split("; ").find(|p| p.contains("designs rejected")).map(str::to_string);
    let null = sample_ok(&["--n", "9", "--seed", "3", "--out", "/dev/null"]);
    assert_eq!(rejected(&err), rejected(&null));
}

/// Issue 27: the design space `garmentcode schema` prints is the one the sampler
/// draws from: read back with `--design-space`, the same seed gives the same shards
/// and index byte for byte.
#[test]
fn the_printed_design_space_samples_the_same_dataset() {
    let dir = scratch("schema_roundtrip");
    let schema = Command::new(BIN).arg("schema").output().unwrap();
    assert!(schema.status.success());
    let space = dir.join("space.yaml");
    fs::write(&space, &schema.stdout).unwrap();
    let (a, b) = (dir.join("a"), dir.join("b"));
    let args = ["--n", "120", "--seed", "3", "--layout", "shards:40"];
    sample_ok(&[&args[..], &["--out", s(&a)]].concat());
    sample_ok(&[&args[..], &["--out", s(&b), "--design-space", s(&space)]].concat());
    let index = |d: &Path| fs::read(d.join("index.jsonl")).unwrap();
    assert!(index(&a) == index(&b), "the index differs");
    let (sa, sb) = (shard_files(&a), shard_files(&b));
    assert_eq!(sa.len(), 3);
    assert!(sa == sb, "the shards differ");
    // A preset is not the space: read as one, it draws another dataset (what
    // `schema` printed before it printed the space).
    let preset = Command::new(BIN).args(["schema", "--design", "t-shirt"]).output().unwrap();
    fs::write(dir.join("preset.yaml"), &preset.stdout).unwrap();
    let c = dir.join("c");
    sample_ok(&[&args[..], &["--out", s(&c), "--design-space", s(&dir.join("preset.yaml"))]].concat());
    assert!(index(&a) != index(&c), "the t-shirt preset as a design space draws the same garments");
}

/// Offsets of the member headers of a tar archive.
fn header_offsets(tar: &[u8]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut at = 0;
    while tar[at..at + 512].iter().any(|&b| b != 0) {
        out.push(at);
        let size = usize::from_str_radix(std::str::from_utf8(&tar[at + 124..at + 135]).unwrap(), 8).unwrap();
        at += 512 + size.next_multiple_of(512);
    }
    out
}

#[test]
fn cut_or_foreign_shards_are_refused_whole() {
    let dir = scratch("cut_shards");
    let data = dir.join("data");
    sample_ok(&["--n", "5", "--seed", "2", "--layout", "shards:5", "--out", s(&data)]);
    let shard = fs::read(data.join("shard-000000.tar")).unwrap();
    let headers = header_offsets(&shard);
    assert_eq!(headers.len(), 20, "5 samples of 4 files");
    let end = [0u8; 1024];
    let unpack_err = |name: &str, bytes: Vec<u8>| {
        // Beside a copy of the index, as a dataset's shards are.
        let d = dir.join(name);
        fs::create_dir_all(&d).unwrap();
        fs::copy(data.join("index.jsonl"), d.join("index.jsonl")).unwrap();
        fs::write(d.join("shard-000000.tar"), bytes).unwrap();
        let out = dir.join(format!("{name}-out"));
        let o = sample(&["--unpack", s(&d.join("shard-000000.tar")), "--out", s(&out)]);
        assert_eq!(o.status.code(), Some(2), "{name}");
        assert!(!out.exists(), "{name}: nothing unpacked");
        String::from_utf8_lossy(&o.stderr).into_owned()
    };
    // Cut inside a sample (between two of its files), end blocks added.
    let err = unpack_err("inside", [&shard[..headers[7]], &end[..]].concat());
    assert!(err.contains("rand_0000001 lacks") && err.contains("cut"), "{err}");
    // Cut exactly between two samples: the index beside it lists five.
    let err = unpack_err("between", [&shard[..headers[8]], &end[..]].concat());
    assert!(err.contains("holds 2 samples where the index beside it lists 5"), "{err}");
    // A member with a suffix no sample file has.
    let mut foreign = shard.clone();
    let h = headers[2];
    let name = String::from_utf8(foreign[h..h + 100].iter().copied().take_while(|&b| b != 0).collect()).unwrap();
    assert_eq!(name, "rand_0000000.sample_info.json");
    foreign[h + name.len() - 4..h + name.len()].copy_from_slice(b"exe\0");
    foreign[h + 148..h + 156].copy_from_slice(b"        ");
    let sum: u32 = foreign[h..h + 512].iter().map(|&b| u32::from(b)).sum();
    foreign[h + 148..h + 156].copy_from_slice(format!("{sum:06o}\0 ").as_bytes());
    let err = unpack_err("foreign", foreign);
    assert!(err.contains("is not a sample file"), "{err}");
}

#[test]
fn extended_sampling_draws_the_extension_parameters_too() {
    use garmentcode::Params;
    let dir = scratch("extended");
    let out = dir.join("ext");
    sample_ok(&["--n", "8", "--seed", "5", "--extended", "-j", "1", "--out", s(&out)]);
    let space = garments::design::extended_design_space();
    let designs: Vec<garments::Design> = samples(&out)
        .into_iter()
        .filter(|(k, _)| k.ends_with("design_params.yaml"))
        .map(|(k, v)| garmentcode::io::read_design(&String::from_utf8(v).unwrap(), &k, &space).unwrap())
        .collect();
    assert_eq!(designs.len(), 8);
    let defaults = garments::design::Extension::defaults();
    assert!(designs.iter().any(|d| d.extension != defaults), "some sample uses the extension");
    let props = fs::read_to_string(out.join("dataset_properties.yaml")).unwrap();
    assert!(props.contains("built-in, extended"), "{props}");
}
