//! Writing output folders. Files are prepared in memory, or streamed into their
//! file as they are made (the mesh files); a folder (`build`,
//! `render`, `sample --replay`) is written whole into a temporary sibling
//! `.NAME.tmp-PID` and swapped in, so a folder never mixes two runs' files and a
//! failed or killed run leaves the previous folder as it was. Leftovers of dead
//! runs are removed (or, for a folder caught between the two renames of a swap,
//! put back) by the next run on the same folder.
//!
//! Each folder carries a manifest, [`MANIFEST`], with a hash of every file the
//! run wrote. The next run on the folder replaces it whole only if every file in
//! it is still garmentcode's unchanged output, or an input of that run (a design
//! file edited in place and built again); a file edited since (or from a folder
//! without a manifest) is never deleted or overwritten without `--force`. The
//! hash is XXH64, computed while each file is written (`xxh64:HASH NAME` a line);
//! manifests of earlier versions hold FNV-1a hashes (`HASH NAME`), still read.
//! Both are written here in a few lines: a hash only has to notice an edit and
//! stay the same across Rust versions, which std's hasher does not promise (the
//! dataset sampler's settings fingerprint uses FNV-1a).

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use xxhash_rust::xxh64::Xxh64;

/// Names of the files garmentcode writes into an output folder: a folder holding
/// only these may be replaced without `--force`.
pub const OWN_FILES: &[&str] =
    &["specification.json", "pattern.svg", "pattern.png", "design_params.yaml", "body_measurements.yaml", "checks.json", "error.txt"];

/// The hidden file listing what the run that wrote a folder wrote into it, with a
/// hash of each file: `HASH NAME` a line.
pub const MANIFEST: &str = ".garmentcode-files";

/// Suffix of the pattern `garmentcode mesh` writes beside the mesh files (whose
/// suffixes are [`garmentcode::mesh::write::FILE_SUFFIXES`], and the drape's
/// [`garmentcode_drape::FILE_SUFFIXES`]), after the pattern's name.
const MESH_SPEC_SUFFIX: &str = "_specification.json";

/// A file name garmentcode writes into an output folder.
fn is_own_file(name: &str) -> bool {
    let mut mesh_suffixes =
        std::iter::once(MESH_SPEC_SUFFIX).chain(garmentcode::mesh::write::FILE_SUFFIXES).chain(garmentcode_drape::FILE_SUFFIXES);
    OWN_FILES.contains(&name)
        || name == MANIFEST
        || name == "size-run.txt"
        || name == "measuring-guide.html"
        || (name.starts_with("figure-") && name.ends_with(".svg"))
        || garmentcode::fabricate::FILE_NAMES.contains(&name)
        || mesh_suffixes.any(|s| name.len() > s.len() && name.ends_with(s))
}

/// Files of an output folder, written together.
#[derive(Default)]
pub struct OutputSet {
    files: Vec<(String, Content)>,
    /// The run's input files: one of them inside the folder may be replaced even
    /// if it was edited (it was read by this run).
    inputs: Vec<PathBuf>,
}

/// What a file of an output folder holds.
enum Content {
    /// Bytes made beforehand.
    Bytes(Vec<u8>),
    /// Bytes made while the file is written (large files: none held whole in memory).
    Streamed(Box<WriteFn>),
}

/// Writes a file's bytes into the writer it is given.
type WriteFn = dyn Fn(&mut dyn io::Write) -> io::Result<()>;

/// Why an output folder was not written.
#[derive(Debug)]
pub enum WriteError {
    /// The folder holds something garmentcode did not write (`--force` replaces it
    /// when these are files).
    Foreign {
        /// Names of a few of the entries.
        names: Vec<String>,
        /// Whether `--force` would help (false for sub-folders).
        forcible: bool,
    },
    /// Files garmentcode wrote that were edited since (or that no manifest
    /// vouches for), which this run would delete or overwrite.
    Edited {
        /// Names of a few of them.
        names: Vec<String>,
    },
    /// A file system error.
    Io(io::Error),
}

impl std::fmt::Display for WriteError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WriteError::Foreign { names, forcible: true } => write!(
                f,
                "the folder holds files garmentcode did not write ({}); choose another folder, or --force to replace it and delete them",
                names.join(", ")
            ),
            WriteError::Foreign { names, forcible: false } => {
                write!(f, "the folder holds sub-folders ({}); garmentcode does not replace it, choose another folder", names.join(", "))
            }
            WriteError::Edited { names } => write!(
                f,
                "{} changed since garmentcode wrote it (or the folder has no record of it), and this run would delete or overwrite it; choose another folder, or --force to replace it",
                names.join(", ")
            ),
            WriteError::Io(e) => write!(f, "{e}"),
        }
    }
}

impl From<io::Error> for WriteError {
    fn from(e: io::Error) -> Self {
        WriteError::Io(e)
    }
}

impl OutputSet {
    /// Add a file (name relative to the folder).
    pub fn add(&mut self, name: &str, bytes: impl Into<Vec<u8>>) {
        self.files.push((name.to_string(), Content::Bytes(bytes.into())));
    }

    /// Add a file whose bytes `write` makes into the file when the folder is written
    /// (hashed on the way for the manifest).
    pub fn add_streamed(&mut self, name: &str, write: impl Fn(&mut dyn io::Write) -> io::Result<()> + 'static) {
        self.files.push((name.to_string(), Content::Streamed(Box::new(write))));
    }

    /// Name an input file of the run: if it lies in the output folder, it may be
    /// replaced there even after an edit (the run read it).
    pub fn add_input(&mut self, path: impl AsRef<Path>) {
        if let Ok(p) = fs::canonicalize(path) {
            self.inputs.push(p);
        }
    }

    /// Names of the files, in the order they were added.
    pub fn names(&self) -> Vec<String> {
        self.files.iter().map(|(n, _)| n.clone()).collect()
    }

    /// Write the folder `dir` whole: the files go into a temporary sibling folder
    /// that then replaces `dir`. An existing `dir` must hold only files
    /// garmentcode writes ([`OWN_FILES`], the mesh files), unless `force`, and none
    /// of them edited since (checked once the new files are written, against their
    /// hashes; a refused run removes its temporary folder).
    pub fn write_folder(&self, dir: &Path, force: bool) -> Result<(), WriteError> {
        let (parent, base) = split(dir)?;
        fs::create_dir_all(&parent)?;
        clean_leftovers(&parent, &base, dir);
        if dir.exists() {
            check_replaceable(dir, force)?;
        }
        let pid = std::process::id();
        let tmp = parent.join(format!(".{base}.tmp-{pid}"));
        let _ = fs::remove_dir_all(&tmp);
        fs::create_dir_all(&tmp)?;
        let written = self.write_each(&tmp).map_err(WriteError::from).and_then(|files| {
            if dir.exists() && !force {
                self.check_unedited(dir, &tmp, &files)?;
            }
            Ok(fs::write(tmp.join(MANIFEST), manifest(&files))?)
        });
        if let Err(e) = written {
            let _ = fs::remove_dir_all(&tmp);
            return Err(e);
        }
        if dir.exists() {
            let old = parent.join(format!(".{base}.old-{pid}"));
            if let Err(e) = fs::rename(dir, &old) {
                let _ = fs::remove_dir_all(&tmp);
                return Err(e.into());
            }
            if let Err(e) = fs::rename(&tmp, dir) {
                let _ = fs::rename(&old, dir);
                let _ = fs::remove_dir_all(&tmp);
                return Err(e.into());
            }
            let _ = fs::remove_dir_all(&old);
        } else if let Err(e) = fs::rename(&tmp, dir) {
            let _ = fs::remove_dir_all(&tmp);
            return Err(e.into());
        }
        Ok(())
    }

    /// Write every file into `dir` under its own name, hashing it on the way;
    /// returns each file's name, XXH64 hash and length, in order.
    fn write_each(&self, dir: &Path) -> io::Result<Vec<Written>> {
        self.files
            .iter()
            .map(|(name, content)| {
                let mut file = Hashed { inner: fs::File::create(dir.join(name))?, hash: Xxh64::new(0), len: 0 };
                content.write(&mut file)?;
                Ok(Written { name: name.clone(), hash: file.hash.digest(), len: file.len })
            })
            .collect()
    }

    /// Refuse to delete or overwrite a file of `dir` that is not garmentcode's
    /// unchanged output (by the folder's manifest) nor an input of this run. The
    /// files this run wrote are `written`, in `tmp`.
    fn check_unedited(&self, dir: &Path, tmp: &Path, written: &[Written]) -> Result<(), WriteError> {
        let manifest = fs::read_to_string(dir.join(MANIFEST)).unwrap_or_default();
        let recorded: std::collections::HashMap<&str, &str> =
            manifest.lines().filter_map(|l| l.split_once(' ')).map(|(h, n)| (n, h)).collect();
        let mut edited = Vec::new();
        for e in fs::read_dir(dir)? {
            let e = e?;
            let name = e.file_name().to_string_lossy().into_owned();
            if name == MANIFEST || !e.file_type()?.is_file() {
                continue;
            }
            let path = e.path();
            if fs::canonicalize(&path).is_ok_and(|p| self.inputs.contains(&p)) {
                continue; // read by this run
            }
            // Read the file once, and only if it can be vouched for: by its hash in
            // the manifest, or by being the bytes this run writes again.
            let hash = recorded.get(name.as_str());
            let same_length = written.iter().any(|w| w.name == name && Some(w.len) == e.metadata().ok().map(|m| m.len()));
            let vouched = (hash.is_some() || same_length)
                && fs::read(&path).is_ok_and(|old| {
                    hash.is_some_and(|h| hash_matches(h, &old)) || (same_length && fs::read(tmp.join(&name)).is_ok_and(|new| new == old))
                });
            if !vouched {
                edited.push(name);
            }
        }
        edited.sort();
        if edited.is_empty() {
            Ok(())
        } else {
            edited.truncate(3);
            Err(WriteError::Edited { names: edited })
        }
    }

    /// Write every file into the folder `dir`, which may hold other files (a
    /// dataset's summary beside its samples): each file is replaced atomically.
    pub fn write_files_into(&self, dir: &Path) -> io::Result<()> {
        fs::create_dir_all(dir)?;
        let mut temps = Vec::new();
        for (name, content) in &self.files {
            let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
            if let Err(e) = fs::File::create(&tmp).and_then(|mut f| content.write(&mut f)) {
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

impl Content {
    /// Write the bytes into `out`.
    fn write(&self, out: &mut dyn io::Write) -> io::Result<()> {
        match self {
            Content::Bytes(bytes) => out.write_all(bytes),
            Content::Streamed(write) => write(out),
        }
    }
}

/// A file written into a folder: its name, XXH64 hash and length.
struct Written {
    name: String,
    hash: u64,
    len: u64,
}

/// The manifest of the files written: `xxh64:HASH NAME` a line.
fn manifest(written: &[Written]) -> String {
    written.iter().map(|w| format!("{XXH64_TAG}{:016x} {}\n", w.hash, w.name)).collect()
}

/// The prefix of an XXH64 hash in a manifest; a hash without it is FNV-1a (the
/// manifests of garmentcode 0.1 before streamed files).
const XXH64_TAG: &str = "xxh64:";

/// Whether `bytes` hash to `recorded`, a manifest's hash of either kind.
fn hash_matches(recorded: &str, bytes: &[u8]) -> bool {
    match recorded.strip_prefix(XXH64_TAG) {
        Some(hex) => format!("{:016x}", xxh64(bytes)) == hex,
        None => format!("{:016x}", fnv1a(bytes)) == recorded,
    }
}

/// A writer that hashes (XXH64) and counts the bytes it passes on.
struct Hashed<W> {
    inner: W,
    hash: Xxh64,
    len: u64,
}

impl<W: io::Write> io::Write for Hashed<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = self.inner.write(buf)?;
        self.hash.update(&buf[..n]);
        self.len += n as u64;
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}

/// The 64-bit FNV-1a hash, fed piece by piece: a stable fingerprint of files and
/// settings (std's hasher may change between Rust versions).
pub struct Fnv1a(u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Fnv1a(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv1a {
    /// Feed `bytes`.
    pub fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    /// The hash so far.
    pub fn finish(&self) -> u64 {
        self.0
    }
}

/// The 64-bit FNV-1a hash of `bytes`.
fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h = Fnv1a::default();
    h.write(bytes);
    h.finish()
}

/// The XXH64 hash (seed 0) of `bytes`: the hash of the files in a manifest
/// (`xxhash-rust`: four lanes of 8 bytes per step, about ten times the speed of
/// byte-by-byte FNV-1a over megabytes of mesh text).
fn xxh64(bytes: &[u8]) -> u64 {
    xxhash_rust::xxh64::xxh64(bytes, 0)
}

/// Parent folder and name of `dir` (`.` and `..` resolved).
fn split(dir: &Path) -> io::Result<(PathBuf, String)> {
    let abs = if dir.exists() { fs::canonicalize(dir)? } else { std::path::absolute(dir)? };
    let parent = abs.parent().map(Path::to_path_buf).ok_or_else(|| io::Error::other("cannot write over the root folder"))?;
    let base = abs.file_name().map(|n| n.to_string_lossy().into_owned()).ok_or_else(|| io::Error::other("the folder has no name"))?;
    Ok((parent, base))
}

/// Refuse a folder holding entries garmentcode did not write (files allowed
/// with `force`, sub-folders never).
fn check_replaceable(dir: &Path, force: bool) -> Result<(), WriteError> {
    if !dir.is_dir() {
        return Err(io::Error::new(io::ErrorKind::AlreadyExists, "it exists and is not a folder").into());
    }
    let mut files = Vec::new();
    let mut folders = Vec::new();
    for e in fs::read_dir(dir)? {
        let e = e?;
        let name = e.file_name().to_string_lossy().into_owned();
        if e.file_type()?.is_dir() {
            folders.push(name);
        } else if !is_own_file(&name) {
            files.push(name);
        }
    }
    folders.sort();
    files.sort();
    if !folders.is_empty() {
        folders.truncate(3);
        return Err(WriteError::Foreign { names: folders, forcible: false });
    }
    if !files.is_empty() && !force {
        files.truncate(3);
        return Err(WriteError::Foreign { names: files, forcible: true });
    }
    Ok(())
}

/// Remove `.NAME.tmp-PID` folders of runs that are no longer alive; a
/// `.NAME.old-PID` of a dead run is the previous folder caught mid-swap: put it
/// back if the folder is missing, else remove it.
fn clean_leftovers(parent: &Path, base: &str, dir: &Path) {
    let Ok(entries) = fs::read_dir(parent) else { return };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(rest) = name.strip_prefix(&format!(".{base}.")) else { continue };
        let (kind, pid) = match rest.split_once('-') {
            Some((k @ ("tmp" | "old"), pid)) => (k, pid),
            _ => continue,
        };
        let Ok(pid) = pid.parse::<u32>() else { continue };
        if pid == std::process::id() || is_alive(pid) {
            continue;
        }
        if kind == "old" && !dir.exists() {
            let _ = fs::rename(e.path(), dir);
        } else {
            let _ = fs::remove_dir_all(e.path());
        }
    }
}

/// Whether a process with this id runs (Linux: `/proc/PID`). Elsewhere every
/// process counts as alive, so nothing of a possibly running writer is removed.
fn is_alive(pid: u32) -> bool {
    let proc = Path::new("/proc");
    !proc.join("self").exists() || proc.join(pid.to_string()).exists()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("garmentcode-output-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    fn set(files: &[&str]) -> OutputSet {
        let mut s = OutputSet::default();
        for f in files {
            s.add(f, f.as_bytes());
        }
        s
    }

    #[test]
    fn a_folder_is_replaced_whole() {
        let d = scratch("whole");
        let out = d.join("out");
        set(&["specification.json", "pattern.png"]).write_folder(&out, false).unwrap();
        set(&["specification.json"]).write_folder(&out, false).unwrap();
        assert!(out.join("specification.json").exists());
        assert!(!out.join("pattern.png").exists(), "no file of the previous run is left");
        let names: Vec<_> = fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1, "no temporary folder left: {names:?}");
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn foreign_files_need_force_and_folders_are_never_replaced() {
        let d = scratch("foreign");
        let out = d.join("out");
        fs::create_dir_all(&out).unwrap();
        fs::write(out.join("notes.txt"), "mine").unwrap();
        let e = set(&["checks.json"]).write_folder(&out, false).unwrap_err();
        assert!(e.to_string().contains("notes.txt") && e.to_string().contains("--force"), "{e}");
        assert_eq!(fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
        set(&["checks.json"]).write_folder(&out, true).unwrap();
        assert!(!out.join("notes.txt").exists());
        fs::create_dir_all(out.join("sub")).unwrap();
        assert!(matches!(set(&["checks.json"]).write_folder(&out, true), Err(WriteError::Foreign { forcible: false, .. })));
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn an_edited_file_is_never_deleted_or_overwritten_without_force() {
        let d = scratch("edited");
        let out = d.join("out");
        set(&["specification.json", "design_params.yaml"]).write_folder(&out, false).unwrap();
        // Unchanged: a run that does not write it removes it.
        set(&["specification.json"]).write_folder(&out, false).unwrap();
        assert!(!out.join("design_params.yaml").exists());
        set(&["specification.json", "design_params.yaml"]).write_folder(&out, false).unwrap();
        fs::write(out.join("design_params.yaml"), "edited by hand").unwrap();
        // A run that would delete it, or overwrite it with other bytes, is refused.
        let e = set(&["specification.json"]).write_folder(&out, false).unwrap_err();
        assert!(matches!(e, WriteError::Edited { .. }) && e.to_string().contains("design_params.yaml"), "{e}");
        let mut other = OutputSet::default();
        other.add("design_params.yaml", "another design");
        assert!(matches!(other.write_folder(&out, false), Err(WriteError::Edited { .. })));
        assert_eq!(fs::read_to_string(out.join("design_params.yaml")).unwrap(), "edited by hand");
        // Read by the run (a design edited in place and built again): replaced.
        other.add_input(out.join("design_params.yaml"));
        other.write_folder(&out, false).unwrap();
        assert_eq!(fs::read_to_string(out.join("design_params.yaml")).unwrap(), "another design");
        // --force replaces an edited file.
        fs::write(out.join("design_params.yaml"), "edited again").unwrap();
        set(&["specification.json"]).write_folder(&out, true).unwrap();
        assert!(!out.join("design_params.yaml").exists());
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_folder_without_a_manifest_keeps_what_the_run_would_change() {
        let d = scratch("legacy");
        let out = d.join("out");
        fs::create_dir_all(&out).unwrap();
        fs::write(out.join("specification.json"), "specification.json").unwrap();
        fs::write(out.join("checks.json"), "{}").unwrap();
        // The same bytes are no loss; a file the run would delete is.
        let e = set(&["specification.json"]).write_folder(&out, false).unwrap_err();
        assert_eq!(e.to_string().split(" changed").next(), Some("checks.json"));
        set(&["specification.json", "checks.json"]).write_folder(&out, true).unwrap();
        assert_eq!(fs::read_to_string(out.join(MANIFEST)).unwrap().lines().count(), 2);
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn xxh64_matches_the_published_test_values() {
        // Values of the reference implementation (Python's `xxhash.xxh64(b).hexdigest()`).
        let long: Vec<u8> = (0..3).flat_map(|_| 0..=255u8).chain(*b"xyz").collect();
        let cases: [(&[u8], u64); 5] = [
            (b"", 0xef46_db37_51d8_e999),
            (b"a", 0xd24e_c4f1_a98c_6e5b),
            (b"abc", 0x44bc_2cf5_ad77_0999),
            (b"0123456789abcdefghijklmnopqrstuvwxyz!", 0xdde9_d7f1_25de_8f22),
            (&long, 0xe921_a1b4_5bd7_79f8),
        ];
        for (bytes, expected) in cases {
            assert_eq!(xxh64(bytes), expected, "{} bytes", bytes.len());
            // Fed in uneven pieces, as a streamed file is.
            let mut h = Xxh64::new(0);
            for piece in bytes.chunks(7) {
                h.update(piece);
            }
            assert_eq!(h.digest(), expected, "{} bytes in pieces", bytes.len());
        }
    }

    #[test]
    fn a_streamed_file_is_written_and_vouched_for_by_its_hash() {
        let d = scratch("streamed");
        let out = d.join("out");
        let text: Vec<u8> = (0..100_000u32).flat_map(|i| format!("v {i}\n").into_bytes()).collect();
        let streamed = |text: Vec<u8>| {
            let mut s = OutputSet::default();
            s.add_streamed("case_boxmesh.obj", move |w| text.chunks(4096).try_for_each(|c| w.write_all(c)));
            s
        };
        streamed(text.clone()).write_folder(&out, false).unwrap();
        assert_eq!(fs::read(out.join("case_boxmesh.obj")).unwrap(), text);
        let manifest = fs::read_to_string(out.join(MANIFEST)).unwrap();
        assert_eq!(manifest, format!("xxh64:{:016x} case_boxmesh.obj\n", xxh64(&text)));
        // Unchanged: replaced by a run that writes other bytes.
        streamed(b"v 1\n".to_vec()).write_folder(&out, false).unwrap();
        // Edited: refused, and the run leaves nothing behind.
        fs::write(out.join("case_boxmesh.obj"), "edited").unwrap();
        let e = streamed(text.clone()).write_folder(&out, false).unwrap_err();
        assert!(matches!(e, WriteError::Edited { .. }), "{e}");
        assert_eq!(fs::read_to_string(out.join("case_boxmesh.obj")).unwrap(), "edited");
        let names: Vec<_> = fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1, "no temporary folder left: {names:?}");
        // Without a manifest, the same bytes written again are no loss.
        fs::write(out.join("case_boxmesh.obj"), &text).unwrap();
        fs::remove_file(out.join(MANIFEST)).unwrap();
        streamed(text.clone()).write_folder(&out, false).unwrap();
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_manifest_of_fnv1a_hashes_still_vouches() {
        let d = scratch("fnv1a");
        let out = d.join("out");
        fs::create_dir_all(&out).unwrap();
        fs::write(out.join("checks.json"), "{}").unwrap();
        fs::write(out.join(MANIFEST), format!("{:016x} checks.json\n", fnv1a(b"{}"))).unwrap();
        set(&["specification.json"]).write_folder(&out, false).unwrap();
        assert!(!out.join("checks.json").exists());
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn leftovers_of_dead_runs_are_cleaned() {
        let d = scratch("leftovers");
        let out = d.join("out");
        // A pid far above any real one on Linux (pid_max is at most 2^22).
        let dead = 4_000_000_000u32;
        fs::create_dir_all(d.join(format!(".out.tmp-{dead}"))).unwrap();
        fs::create_dir_all(d.join(format!(".out.old-{dead}"))).unwrap();
        fs::write(d.join(format!(".out.old-{dead}/specification.json")), "previous").unwrap();
        let manifest = format!("{:016x} specification.json\n", fnv1a(b"previous"));
        fs::write(d.join(format!(".out.old-{dead}/{MANIFEST}")), manifest).unwrap();
        fs::create_dir_all(d.join(format!(".other.tmp-{dead}"))).unwrap();
        // The folder itself is missing: the old copy is put back, then replaced.
        set(&["checks.json"]).write_folder(&out, false).unwrap();
        let mut names: Vec<String> = fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        assert_eq!(names, vec![format!(".other.tmp-{dead}"), "out".to_string()]);
        assert!(out.join("checks.json").exists() && !out.join("specification.json").exists());
        fs::remove_dir_all(&d).unwrap();
    }
}
