//! What the command-line tests share: running the built `garmentcode`, fresh scratch
//! folders, and reading what it printed (each test file uses some of it).
#![allow(dead_code)]

#[path = "../../garmentcode/tests/support/ezdxf.rs"]
pub mod ezdxf;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `garmentcode` binary of this build.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_garmentcode"))
}

/// A fresh, empty scratch folder for one test, under the test file's own folder.
pub fn scratch(name: &str) -> PathBuf {
    let file = module_path!().split("::").next().unwrap_or("tests");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(file).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `garmentcode ARGS` in `cwd`.
pub fn run(args: &[&str], cwd: &Path) -> Output {
    bin().args(args).current_dir(cwd).output().unwrap()
}

/// What the run printed on stderr.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// What the run printed on stdout.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Exit code, and no panic message anywhere.
pub fn code(o: &Output) -> i32 {
    let err = stderr(o);
    assert!(!err.contains("panicked"), "panic: {err}");
    o.status.code().expect("exited normally")
}
