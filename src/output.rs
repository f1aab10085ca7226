//! Writing an output folder all at once: files are prepared in memory, written into a
//! temporary sibling folder and moved into place, so a failed run never leaves a
//! partial folder behind.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Files of an output folder, written together.
#[derive(Default)]
pub struct OutputSet {
    files: Vec<(String, Vec<u8>)>,
}

impl OutputSet {
    /// Add a file (name relative to the folder).
    pub fn add(&mut self, name: &str, bytes: impl Into<Vec<u8>>) {
        self.files.push((name.to_string(), bytes.into()));
    }

    /// Write every file into `dir`: a new folder appears whole; in an existing
    /// folder every file is replaced atomically.
    pub fn write(&self, dir: &Path) -> io::Result<()> {
        let parent = match dir.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        fs::create_dir_all(&parent)?;
        let base = dir.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
        if !dir.exists() {
            let tmp = parent.join(format!(".{base}.tmp-{}", std::process::id()));
            let _ = fs::remove_dir_all(&tmp);
            fs::create_dir_all(&tmp)?;
            let result = self.files.iter().try_for_each(|(name, bytes)| fs::write(tmp.join(name), bytes));
            if let Err(e) = result.and_then(|_| fs::rename(&tmp, dir)) {
                let _ = fs::remove_dir_all(&tmp);
                return Err(e);
            }
            return Ok(());
        }
        if !dir.is_dir() {
            return Err(io::Error::new(io::ErrorKind::AlreadyExists, format!("{} exists and is not a folder", dir.display())));
        }
        let mut temps = Vec::new();
        for (name, bytes) in &self.files {
            let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
            if let Err(e) = fs::write(&tmp, bytes) {
                for t in &temps {
                    let _ = fs::remove_file(t);
                }
                let _ = fs::remove_file(&tmp);
                return Err(e);
            }
            temps.push(tmp);
        }
        for ((name, _), tmp) in self.files.iter().zip(&temps) {
            fs::rename(tmp, dir.join(name))?;
        }
        Ok(())
    }
}
