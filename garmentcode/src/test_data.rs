//! The workspace's test data for the crate's unit tests: the reference cases and
//! other patterns under `tests/data`.

use crate::pattern::Pattern;
use std::path::{Path, PathBuf};

/// The patterns in the folders of `dir` (relative to the workspace's test data)
/// that hold a `specification.json`, by folder name (which also names the pattern).
pub(crate) fn patterns_in(dir: &str) -> Vec<(String, Pattern)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data").join(dir);
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("specification.json").exists())
        .collect();
    dirs.sort();
    dirs.into_iter()
        .map(|d| {
            let name = d.file_name().unwrap().to_string_lossy().to_string();
            let mut p = Pattern::from_json(&std::fs::read_to_string(d.join("specification.json")).unwrap()).unwrap();
            p.name = name.clone();
            (name, p)
        })
        .collect()
}

/// The reference cases.
pub(crate) fn cases() -> Vec<(String, Pattern)> {
    let all = patterns_in("cases");
    assert!(all.len() > 40, "the reference cases are missing");
    all
}
