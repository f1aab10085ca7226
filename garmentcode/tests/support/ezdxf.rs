//! Reading a DXF file back with Python's ezdxf, shared by the DXF tests of both crates
//! (included with `#[path]`: garmentcode's print unit tests, its extension tests and the
//! command line's size-run test).
//!
//! `.ci/run` points `GARMENTCODE_EZDXF_PYTHON` at a virtual environment with ezdxf. Where
//! Python or ezdxf is missing the check prints `SKIPPED <test>: <why>` on the test's real
//! stderr and the caller returns: a skip is always said.

use std::io::Write;
use std::path::Path;
use std::process::Command;

/// Run `script` (Python that reads the DXF file named by `sys.argv[1]` with ezdxf and prints
/// one JSON value) on `dxf`; its JSON, or `None` after printing why the check was skipped.
/// Panics (fails the test) when ezdxf is there but the script fails, e.g. on a file ezdxf
/// cannot read.
pub fn read_back(test: &str, dxf: &Path, script: &str) -> Option<serde_json::Value> {
    let python = std::env::var("GARMENTCODE_EZDXF_PYTHON").unwrap_or_else(|_| "python3".into());
    let skip = |why: String| {
        let _ = std::io::stderr().write_all(format!("SKIPPED {test}: {why}\n").as_bytes());
        None
    };
    match Command::new(&python).arg("-c").arg(script).arg(dxf).output() {
        Ok(o) if o.status.success() => Some(
            serde_json::from_slice(&o.stdout)
                .unwrap_or_else(|e| panic!("{test}: the ezdxf script printed no JSON ({e}): {}", String::from_utf8_lossy(&o.stdout))),
        ),
        Ok(o) if String::from_utf8_lossy(&o.stderr).contains("No module named 'ezdxf'") => {
            skip("Python's ezdxf is not installed (pip install ezdxf)".into())
        }
        Ok(o) => panic!("{test}: ezdxf failed: {}", String::from_utf8_lossy(&o.stderr)),
        Err(e) => skip(format!("{python} cannot run ({e})")),
    }
}

/// [`read_back`] for DXF text not yet on disk: written to a temporary file for the script.
pub fn read_back_text(test: &str, dxf: &str, script: &str) -> Option<serde_json::Value> {
    let file = std::env::temp_dir().join(format!("garmentcode-{test}-{}.dxf", std::process::id()));
    std::fs::write(&file, dxf).expect("write the DXF for ezdxf");
    let v = read_back(test, &file, script);
    let _ = std::fs::remove_file(&file);
    v
}
