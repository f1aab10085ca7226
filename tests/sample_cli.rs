//! `garmentcode sample`: the same dataset whatever the number of threads or shards,
//! resumable, never a partial sample folder, and bad input refused before any work.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, SystemTime};

const BIN: &str = env!("CARGO_BIN_EXE_garmentcode");

/// A fresh scratch folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sample_cli").join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

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
