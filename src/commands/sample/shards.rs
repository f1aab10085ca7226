//! The shard layout (`--layout shards[:N]`): WebDataset-style tar archives of `N`
//! samples each. Shard `k` (`shard-00000k.tar`) holds the samples of index
//! `k·N .. (k+1)·N` of the whole dataset, so a shard's content depends on the seed,
//! the settings, `N` and `--n` alone, never on `--jobs` or `--shard`.
//!
//! Inside a shard every file of a sample is named after its key: the folder
//! layout's `rand_0000042/rand_0000042_specification.json` becomes
//! `rand_0000042.specification.json`, `rand_0000042/design_params.yaml` becomes
//! `rand_0000042.design_params.yaml`, and so on; unpacking reverses the mapping.
//!
//! The tar headers are written here rather than with the `tar` crate: the format
//! needed is one fixed ustar header per regular file (about thirty lines), every
//! field of it must be pinned for byte-identical shards (mtime 0, uid/gid 0, mode
//! 0644, no user or group names), and the reader only has to accept what this
//! writer produces (plus the end-of-archive blocks other tools add), with clear
//! errors for anything else.

use super::store::{self, Files, Record, Settings};
use garments::sample::sample_name;
use std::collections::BTreeMap;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Samples per shard when `--layout shards` gives no `:N`.
pub const DEFAULT_SIZE: u64 = 1000;

const BLOCK: usize = 512;

/// The file name of shard `k`.
pub fn shard_name(k: u64) -> String {
    format!("shard-{k:06}.tar")
}

/// The shard number of a file name `shard-NNNNNN.tar`.
fn shard_of(name: &str) -> Option<u64> {
    let digits = name.strip_prefix("shard-")?.strip_suffix(".tar")?;
    if digits.len() < 6 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

fn tmp_name(k: u64) -> String {
    format!(".{}.tmp-{}", shard_name(k), std::process::id())
}

/// The member name of a sample file: `rand_N_x` → `rand_N.x`, `x` → `rand_N.x`.
fn member_name(key: &str, file: &str) -> String {
    let rest = file.strip_prefix(key).and_then(|r| r.strip_prefix('_')).unwrap_or(file);
    format!("{key}.{rest}")
}

/// The folder file name of a member's suffix: the inverse of [`member_name`].
fn folder_file_name(key: &str, rest: &str) -> String {
    if rest == "specification.json" || rest.starts_with("pattern.") || mesh_file(rest) { format!("{key}_{rest}") } else { rest.to_string() }
}

/// Whether `rest` is the suffix (without its `_`) of a mesh or drape file.
fn mesh_file(rest: &str) -> bool {
    garmentcode::mesh::write::FILE_SUFFIXES
        .iter()
        .chain(&garmentcode_drape::FILE_SUFFIXES)
        .any(|suffix| suffix.strip_prefix('_') == Some(rest))
}

/// Split a member name into its sample index, key and suffix. The suffix is one
/// of the files a sample has (see [`is_sample_file`]), so unpacking writes
/// nothing else and nowhere else.
fn split_member(name: &str) -> Option<(u64, &str, &str)> {
    let (key, rest) = name.split_once('.')?;
    let index = store::index_of(key)?;
    is_sample_file(rest).then_some((index, key, rest))
}

/// Whether `rest` names a file of a sample in a shard (as [`member_name`] makes
/// them): the pattern, its drawings, the mesh and drape files, the design, body and record.
fn is_sample_file(rest: &str) -> bool {
    mesh_file(rest)
        || ["specification.json", "pattern.svg", "pattern.png", "design_params.yaml", "body_measurements.yaml", store::INFO].contains(&rest)
}

/// Write `value` as zero-padded octal into `field`, ending with NUL.
fn octal(field: &mut [u8], value: u64) {
    let digits = field.len() - 1;
    let text = format!("{value:0digits$o}");
    field[..digits].copy_from_slice(text.as_bytes());
    field[digits] = 0;
}

/// One ustar header block for a regular file.
fn header(name: &str, size: u64) -> Result<[u8; BLOCK], String> {
    let mut h = [0u8; BLOCK];
    if name.len() > 100 {
        return Err(format!("{name}: a member name longer than 100 bytes"));
    }
    h[..name.len()].copy_from_slice(name.as_bytes());
    octal(&mut h[100..108], 0o644);
    octal(&mut h[108..116], 0);
    octal(&mut h[116..124], 0);
    octal(&mut h[124..136], size);
    octal(&mut h[136..148], 0);
    h[156] = b'0';
    h[257..263].copy_from_slice(b"ustar\0");
    h[263..265].copy_from_slice(b"00");
    octal(&mut h[329..337], 0);
    octal(&mut h[337..345], 0);
    h[148..156].fill(b' ');
    let sum: u64 = h.iter().map(|&b| u64::from(b)).sum();
    octal(&mut h[148..155], sum);
    h[155] = b' ';
    Ok(h)
}

/// A tar archive of `members` (name, bytes) in the order given, in memory: what
/// [`ShardWriter`] streams to its file (the tests hold it to that).
#[cfg(test)]
fn tar(members: &[(String, &[u8])]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    for (name, bytes) in members {
        out.extend_from_slice(&header(name, bytes.len() as u64)?);
        out.extend_from_slice(bytes);
        out.resize(out.len().next_multiple_of(BLOCK), 0);
    }
    out.resize(out.len() + 2 * BLOCK, 0);
    Ok(out)
}

/// The value of an octal header field.
fn read_octal(field: &[u8]) -> Option<u64> {
    let text = std::str::from_utf8(field).ok()?.trim_matches(|c: char| c == '\0' || c == ' ');
    if text.is_empty() {
        return Some(0);
    }
    u64::from_str_radix(text, 8).ok()
}

/// The largest sample file unpacked: a box mesh at the mesher's vertex limit
/// stays well below.
const MAX_MEMBER: u64 = 1 << 30;

/// One regular file of a ustar archive: its name and where its bytes are.
struct Member {
    name: String,
    start: u64,
    size: u64,
}

/// A ustar archive read header by header. A member's bytes are read only when
/// asked for ([`read`](Self::read)) and skipped otherwise, so memory holds one
/// member at most whatever the archive's size (a shard of samples with meshes is
/// several GB). Errors name what is wrong: not a tar file, a bad checksum, a
/// truncated member.
struct TarReader<R> {
    r: io::BufReader<R>,
    /// The archive's length.
    len: u64,
    /// Where the next header is.
    next: u64,
    /// Where `r` is.
    pos: u64,
}

impl TarReader<fs::File> {
    /// The archive at `path` (errors name it).
    fn open(path: &Path) -> Result<Self, String> {
        let fail = |e: io::Error| format!("{}: cannot read: {e}", path.display());
        TarReader::new(fs::File::open(path).map_err(fail)?).map_err(fail)
    }
}

impl<R: io::Read + io::Seek> TarReader<R> {
    fn new(mut r: R) -> io::Result<Self> {
        let len = r.seek(io::SeekFrom::End(0))?;
        r.seek(io::SeekFrom::Start(0))?;
        Ok(TarReader { r: io::BufReader::with_capacity(1 << 16, r), len, next: 0, pos: 0 })
    }

    /// `len` bytes from `at` into `buf`.
    fn read_at(&mut self, at: u64, buf: &mut [u8]) -> Result<(), String> {
        use io::Read;
        let fail = |e: io::Error| format!("cannot read: {e}");
        if at != self.pos {
            let offset = i64::try_from(at).ok().zip(i64::try_from(self.pos).ok()).map(|(a, p)| a - p).ok_or("an archive too large")?;
            self.r.seek_relative(offset).map_err(fail)?;
        }
        self.r.read_exact(buf).map_err(fail)?;
        self.pos = at + buf.len() as u64;
        Ok(())
    }

    /// The next regular file (directories are passed over); `None` at the end
    /// blocks.
    fn next_member(&mut self) -> Result<Option<Member>, String> {
        loop {
            let at = self.next;
            if self.len.saturating_sub(at) < BLOCK as u64 {
                return Err(if at == 0 {
                    "not a tar archive (too short)".into()
                } else {
                    "truncated: the archive ends without its end blocks".into()
                });
            }
            let mut h = [0u8; BLOCK];
            self.read_at(at, &mut h)?;
            if h.iter().all(|&b| b == 0) {
                return Ok(None);
            }
            if &h[257..262] != b"ustar" {
                return Err(format!("not a tar archive (no ustar header at byte {at})"));
            }
            let stored = read_octal(&h[148..156]).ok_or("a header with an unreadable checksum")?;
            let sum: u64 = h.iter().enumerate().map(|(i, &b)| if (148..156).contains(&i) { u64::from(b' ') } else { u64::from(b) }).sum();
            if stored != sum {
                return Err(format!("a damaged header at byte {at} (checksum)"));
            }
            let cut = |f: &[u8]| String::from_utf8_lossy(&f[..f.iter().position(|&b| b == 0).unwrap_or(f.len())]).into_owned();
            let (prefix, name) = (cut(&h[345..500]), cut(&h[..100]));
            let name = if prefix.is_empty() { name } else { format!("{prefix}/{name}") };
            let size = read_octal(&h[124..136]).ok_or_else(|| format!("{name}: an unreadable size"))?;
            let start = at + BLOCK as u64;
            if size > self.len - start {
                return Err(format!("{name}: truncated (the archive ends inside it)"));
            }
            self.next = start + size.next_multiple_of(BLOCK as u64);
            match h[156] {
                b'0' | 0 => return Ok(Some(Member { name, start, size })),
                b'5' => {}
                other => return Err(format!("{name}: not a regular file (tar type '{}')", other as char)),
            }
        }
    }

    /// The bytes of `m`, a member of this archive, of at most `limit` bytes.
    fn read(&mut self, m: &Member, limit: u64) -> Result<Vec<u8>, String> {
        if m.size > limit {
            return Err(format!("{}: {} bytes, more than a file of a sample has (at most {limit})", m.name, m.size));
        }
        let size = usize::try_from(m.size).map_err(|_| format!("{}: too large to read", m.name))?;
        let mut bytes = vec![0; size];
        self.read_at(m.start, &mut bytes)?;
        Ok(bytes)
    }
}

/// Every regular file of an archive in memory, in order (tests).
#[cfg(test)]
fn untar(bytes: &[u8]) -> Result<Vec<(String, Vec<u8>)>, String> {
    let mut tar = TarReader::new(io::Cursor::new(bytes)).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    while let Some(m) = tar.next_member()? {
        let bytes = tar.read(&m, MAX_MEMBER)?;
        out.push((m.name, bytes));
    }
    Ok(out)
}

/// Sample indices of shard `k`: `k·size .. min((k+1)·size, n)`.
pub fn range(k: u64, size: u64, n: u64) -> std::ops::Range<u64> {
    (k * size).min(n)..((k + 1) * size).min(n)
}

/// A shard being written: each sample's members are appended to a temporary file in
/// index order as the samples finish (one that finishes early waits in memory), and
/// the file is renamed whole once the shard's last sample is in. Memory holds a few
/// samples and the shard's index lines, not the shard; the bytes are those of
/// [`tar`] over the shard's samples.
pub struct ShardWriter {
    k: u64,
    range: std::ops::Range<u64>,
    next: u64,
    waiting: BTreeMap<u64, (Option<String>, Option<Files>)>,
    /// Index lines of the samples written, in index order.
    lines: String,
    file: Option<Box<dyn Write>>,
    /// `None`: the bytes are made and discarded (`--out /dev/null`).
    paths: Option<(PathBuf, PathBuf)>,
}

impl ShardWriter {
    /// Shard `k` of `dir` (`None`: discarded as it is made), holding the samples of `range`.
    pub fn new(dir: Option<&Path>, k: u64, range: std::ops::Range<u64>) -> ShardWriter {
        let next = range.start;
        let paths = dir.map(|dir| (dir.join(tmp_name(k)), dir.join(shard_name(k))));
        ShardWriter { k, range, next, waiting: BTreeMap::new(), lines: String::new(), file: None, paths }
    }

    /// Takes a sample's record and files (`None`: every design was rejected, no
    /// files); once the shard is complete (written and renamed), returns its index
    /// lines.
    pub fn add(&mut self, record: &Record, files: Option<Files>) -> Result<Option<String>, String> {
        self.waiting.insert(record.index, (index_line(record, self.k), files));
        self.write_ready().map_err(|e| {
            self.file = None;
            let (tmp, target) = self.paths.as_ref().expect("only files fail");
            let _ = fs::remove_file(tmp);
            format!("cannot write {}: {e}", target.display())
        })
    }

    fn write_ready(&mut self) -> io::Result<Option<String>> {
        while let Some((line, files)) = self.waiting.remove(&self.next) {
            self.lines.extend(line);
            if let Some(files) = files {
                let key = sample_name(self.next);
                let mut own: Vec<(String, &[u8])> = files.iter().map(|(f, b)| (member_name(&key, f), b.as_slice())).collect();
                own.sort_by(|a, b| a.0.cmp(&b.0));
                let out = self.open()?;
                for (name, bytes) in own {
                    out.write_all(&header(&name, bytes.len() as u64).map_err(io::Error::other)?)?;
                    out.write_all(bytes)?;
                    out.write_all(&[0; BLOCK][..bytes.len().next_multiple_of(BLOCK) - bytes.len()])?;
                }
            }
            self.next += 1;
        }
        if self.next < self.range.end {
            return Ok(None);
        }
        let out = self.open()?;
        out.write_all(&[0; 2 * BLOCK])?;
        out.flush()?;
        self.file = None;
        if let Some((tmp, target)) = &self.paths {
            fs::rename(tmp, target)?;
        }
        Ok(Some(std::mem::take(&mut self.lines)))
    }

    fn open(&mut self) -> io::Result<&mut Box<dyn Write>> {
        if self.file.is_none() {
            self.file = Some(match &self.paths {
                Some((tmp, _)) => Box::new(io::BufWriter::with_capacity(1 << 20, fs::File::create(tmp)?)),
                None => Box::new(io::sink()),
            });
        }
        Ok(self.file.as_mut().expect("just opened"))
    }
}

/// One line of the index: a sample's key, shard `k` and garment (`None` when
/// every design was rejected).
fn index_line(record: &Record, k: u64) -> Option<String> {
    let a = record.accepted.as_ref()?;
    let v = serde_json::json!({
        "key": sample_name(record.index),
        "shard": shard_name(k),
        "type": a.main,
        "upper": a.upper,
        "waistband": a.waistband,
        "bottom": a.bottom,
        "styles": a.styles,
        "body": a.body,
        "panels": a.panels,
    });
    Some(v.to_string() + "\n")
}

/// The index file's name, per task as the summary's.
pub fn index_file_name(shard: Option<(u64, u64)>) -> String {
    match shard {
        None => "index.jsonl".into(),
        Some((i, k)) => format!("index_shard_{i}_of_{k}.jsonl"),
    }
}

/// The index being written: each shard's lines are appended to a temporary parts
/// file as the shard is complete (in any order), and [`finish`](Self::finish)
/// writes the index in shard order from it. Memory holds a position per shard.
pub struct IndexWriter {
    parts: io::BufWriter<fs::File>,
    parts_path: PathBuf,
    /// `shard → (offset, length)` in the parts file.
    segments: BTreeMap<u64, (u64, u64)>,
    end: u64,
    /// The index, and the temporary name it is written to.
    target: PathBuf,
    tmp: PathBuf,
}

impl IndexWriter {
    /// The index `name` in `dir`; removes the temporaries of this index that
    /// interrupted runs left.
    pub fn new(dir: &Path, name: &str) -> Result<IndexWriter, String> {
        let fail = |e: io::Error| format!("{}: cannot write the index: {e}", dir.join(name).display());
        let stale = [format!(".{name}.parts-"), format!(".{name}.tmp-")];
        for entry in fs::read_dir(dir).map_err(fail)? {
            let path = entry.map_err(fail)?.path();
            let file_name = path.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default();
            if stale.iter().any(|p| file_name.starts_with(p.as_str())) {
                fs::remove_file(&path).map_err(fail)?;
            }
        }
        let parts_path = dir.join(format!(".{name}.parts-{}", std::process::id()));
        let parts = io::BufWriter::new(fs::File::create(&parts_path).map_err(fail)?);
        let (target, tmp) = (dir.join(name), dir.join(format!(".{name}.tmp-{}", std::process::id())));
        Ok(IndexWriter { parts, parts_path, segments: BTreeMap::new(), end: 0, target, tmp })
    }

    /// The lines of shard `k`.
    pub fn add(&mut self, k: u64, lines: &str) -> Result<(), String> {
        self.parts.write_all(lines.as_bytes()).map_err(|e| format!("cannot write {}: {e}", self.parts_path.display()))?;
        self.segments.insert(k, (self.end, lines.len() as u64));
        self.end += lines.len() as u64;
        Ok(())
    }

    /// Write the index (to a temporary name, renamed whole).
    pub fn finish(mut self) -> Result<(), String> {
        use std::io::{Read, Seek};
        let fail = |e: io::Error| format!("cannot write {}: {e}", self.target.display());
        self.parts.flush().map_err(fail)?;
        let mut parts = fs::File::open(&self.parts_path).map_err(fail)?;
        let tmp = &self.tmp;
        let mut write = || -> io::Result<()> {
            let mut out = io::BufWriter::new(fs::File::create(tmp)?);
            for &(offset, len) in self.segments.values() {
                parts.seek(io::SeekFrom::Start(offset))?;
                io::copy(&mut (&mut parts).take(len), &mut out)?;
            }
            out.into_inner().map_err(io::IntoInnerError::into_error)?.sync_all()?;
            fs::rename(tmp, &self.target)
        };
        let result = write();
        if result.is_err() {
            let _ = fs::remove_file(tmp);
        }
        result.map_err(fail)
    }
}

impl Drop for IndexWriter {
    fn drop(&mut self) {
        let _ = fs::remove_file(&self.parts_path);
    }
}

/// What a dataset folder already holds for the shards of this run.
pub struct Existing {
    /// Finished shards.
    pub done: Vec<u64>,
    /// Indices of finished shards that have no sample (every attempt rejected).
    pub missing: Vec<u64>,
    /// Stale temporary shards removed.
    pub removed_temps: usize,
}

/// Scan `dir`: check each finished shard of this run (`wanted`, below `shards`)
/// belongs to this dataset, hand its records (by index) and index lines to
/// `on_shard`, and remove stale temporaries.
pub fn scan(
    dir: &Path,
    s: &Settings,
    n: u64,
    size: u64,
    wanted: impl Fn(u64) -> bool,
    mut on_shard: impl FnMut(u64, &[Record], &str) -> Result<(), String>,
) -> Result<Existing, String> {
    let shards = n.div_ceil(size);
    let mut existing = Existing { done: Vec::new(), missing: Vec::new(), removed_temps: 0 };
    let store::Listing { items, stale } = store::list(dir, shard_of, shards, &wanted)?;
    for (k, _, path) in items {
        let mut records = check_shard(&path, s, range(k, size, n))?;
        records.sort_by_key(|r| r.index);
        let mut have = records.iter().map(|r| r.index).peekable();
        existing.missing.extend(range(k, size, n).filter(|i| have.next_if_eq(i).is_none()));
        let lines: String = records.iter().filter_map(|r| index_line(r, k)).collect();
        on_shard(k, &records, &lines)?;
        existing.done.push(k);
    }
    for t in stale {
        fs::remove_file(&t).map_err(|e| format!("{}: cannot remove a stale temporary shard: {e}", t.display()))?;
        existing.removed_temps += 1;
    }
    existing.done.sort_unstable();
    existing.missing.sort_unstable();
    Ok(existing)
}

/// Read a finished shard: every member a file of a sample in `range`, every
/// sample with its record (of this dataset) and the files of these formats.
fn check_shard(path: &Path, s: &Settings, range: std::ops::Range<u64>) -> Result<Vec<Record>, String> {
    let show = path.display();
    let damaged = |e: String| format!("{show}: a damaged shard ({e}); delete it and rerun to make it again");
    let mut tar = TarReader::open(path)?;
    let mut keys: std::collections::BTreeMap<u64, Vec<String>> = std::collections::BTreeMap::new();
    let mut records = Vec::new();
    while let Some(member) = tar.next_member().map_err(damaged)? {
        let name = &member.name;
        let Some((index, _key, rest)) = split_member(name) else {
            return Err(format!("{show}: '{name}' is not a sample file of this tool; choose another --out"));
        };
        if !range.contains(&index) {
            return Err(format!(
                "{show}: holds {} outside this shard's samples {}..{}: the dataset was made with another shard size or --n; choose another --out or the same --layout and --n",
                sample_name(index),
                range.start,
                range.end
            ));
        }
        keys.entry(index).or_default().push(rest.to_string());
        if rest == store::INFO {
            let data = tar.read(&member, crate::commands::MAX_INPUT_BYTES).map_err(damaged)?;
            let text = std::str::from_utf8(&data).map_err(|_| format!("{show}: {name} is not text"))?;
            records.push(store::parse_info(text, &format_args!("{show}: {name}"), s, index)?);
        }
    }
    for (index, rests) in &keys {
        let key = sample_name(*index);
        let have = |f: &str| rests.iter().any(|r| folder_file_name(&key, r) == f);
        if !have(store::INFO) {
            return Err(format!("{show}: {key} has no {}; delete the shard and rerun", store::INFO));
        }
        if let Some(f) = s.formats.files(&key).into_iter().find(|f| !have(f)) {
            return Err(format!(
                "{show}: {key} has no {}: the dataset was made with other --formats; resume with the same --formats or choose another --out",
                member_name(&key, &f)
            ));
        }
    }
    Ok(records)
}

/// The samples of a shard in archive order: each sample's key and members. A
/// sample's members must be together (as [`ShardWriter`] writes them), so that
/// unpacking holds one sample at a time.
fn shard_samples<R: io::Read + io::Seek>(tar: &mut TarReader<R>) -> Result<Vec<(String, Vec<Member>)>, String> {
    let mut samples: Vec<(String, Vec<Member>)> = Vec::new();
    let mut seen = std::collections::BTreeSet::new();
    while let Some(member) = tar.next_member()? {
        let Some((index, key, _)) = split_member(&member.name) else {
            return Err(format!("'{}' is not a sample file of a garmentcode shard", member.name));
        };
        match samples.last_mut() {
            Some((last, members)) if last == key => members.push(member),
            _ => {
                if !seen.insert(index) {
                    return Err(format!("the files of {key} are not together, as garmentcode writes them"));
                }
                samples.push((key.to_string(), vec![member]));
            }
        }
    }
    if samples.is_empty() {
        return Err("holds no sample".into());
    }
    // Every sample of a dataset has the same files (the run's formats), always
    // its design, body and record: a sample with fewer was cut off.
    let suffixes = |members: &[Member], key: &str| -> std::collections::BTreeSet<String> {
        members.iter().map(|m| m.name[key.len() + 1..].to_string()).collect()
    };
    let first = suffixes(&samples[0].1, &samples[0].0);
    for (key, members) in &samples {
        let have = suffixes(members, key);
        let always = ["design_params.yaml", "body_measurements.yaml", store::INFO];
        let missing: Vec<&str> = always.iter().copied().chain(first.iter().map(String::as_str)).filter(|f| !have.contains(*f)).collect();
        if !missing.is_empty() {
            return Err(format!("{key} lacks {}: the shard was cut or damaged", missing.join(", ")));
        }
        if have != first {
            return Err(format!("{key} has other files than {}: not one dataset's shard", samples[0].0));
        }
    }
    Ok(samples)
}

/// How many samples the dataset's index (`index*.jsonl` in `dir`) lists for
/// each shard file name; empty when `dir` has no index.
fn index_counts(dir: &Path) -> Result<std::collections::BTreeMap<String, usize>, String> {
    use std::io::BufRead;
    let mut counts = std::collections::BTreeMap::new();
    let Ok(entries) = fs::read_dir(dir) else { return Ok(counts) };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if !(name.starts_with("index") && name.ends_with(".jsonl")) {
            continue;
        }
        let file = fs::File::open(e.path()).map_err(|err| format!("{}: cannot read: {err}", e.path().display()))?;
        for line in io::BufReader::new(file).lines() {
            let line = line.map_err(|err| format!("{}: cannot read: {err}", e.path().display()))?;
            let shard = serde_json::from_str::<serde_json::Value>(&line).ok().and_then(|v| v["shard"].as_str().map(str::to_string));
            if let Some(shard) = shard {
                *counts.entry(shard).or_insert(0) += 1;
            }
        }
    }
    Ok(counts)
}

/// Check that each of `shards` is a whole shard archive (headers only: what
/// [`unpack`] needs), before anything is unpacked.
/// A shard with fewer samples than the dataset's index beside it lists for it
/// was cut between two samples: refused too.
pub fn check_archives(shards: &[PathBuf]) -> Result<(), String> {
    let mut indexes = std::collections::BTreeMap::new();
    for path in shards {
        let show = path.display();
        let mut tar = TarReader::open(path)?;
        let samples = shard_samples(&mut tar).map_err(|e| format!("{show}: {e}"))?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        if !indexes.contains_key(&dir) {
            indexes.insert(dir.clone(), index_counts(&dir)?);
        }
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if let Some(&listed) = indexes[&dir].get(&name)
            && listed != samples.len()
        {
            return Err(format!(
                "{show}: holds {} samples where the index beside it lists {listed}: the shard was cut or damaged",
                samples.len()
            ));
        }
    }
    Ok(())
}

/// `--unpack SHARD.tar ... --out DIR`: each sample of the shards as its folder
/// (written as the folder layout writes it), and the dataset's summaries
/// (`dataset_properties*.yaml`) when the shards come from one folder that has
/// them. Memory holds one sample. Returns the number of samples.
pub fn unpack(shards: &[PathBuf], out: &Path) -> Result<usize, String> {
    let mut count = 0;
    for path in shards {
        let show = path.display();
        let mut tar = TarReader::open(path)?;
        for (key, members) in shard_samples(&mut tar).map_err(|e| format!("{show}: {e}"))? {
            let mut files = Vec::with_capacity(members.len());
            for m in &members {
                // `KEY.SUFFIX`, as `shard_samples` checked.
                let suffix = &m.name[key.len() + 1..];
                files.push((folder_file_name(&key, suffix), tar.read(m, MAX_MEMBER).map_err(|e| format!("{show}: {e}"))?));
            }
            store::write_folder(out, &key, &files).map_err(|e| format!("cannot write {}: {e}", out.join(&key).display()))?;
            count += 1;
        }
    }
    copy_summaries(shards, out)?;
    Ok(count)
}

/// The summaries (`dataset_properties.yaml`, and a task's
/// `dataset_properties_shard_I_of_K.yaml`) of the folder the shards come from, if
/// they all come from one, copied into `out` (each written whole).
fn copy_summaries(shards: &[PathBuf], out: &Path) -> Result<(), String> {
    let dirs: std::collections::BTreeSet<PathBuf> =
        shards.iter().filter_map(|p| Some(fs::canonicalize(p).ok()?.parent()?.to_path_buf())).collect();
    let Some(dir) = dirs.first().filter(|_| dirs.len() == 1) else { return Ok(()) };
    if fs::canonicalize(out).ok().as_ref() == Some(dir) {
        return Ok(());
    }
    let Ok(entries) = fs::read_dir(dir) else { return Ok(()) };
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("dataset_properties") && n.ends_with(".yaml"))
        .collect();
    names.sort();
    for name in names {
        let (from, to, tmp) = (dir.join(&name), out.join(&name), out.join(format!(".{name}.tmp-{}", std::process::id())));
        let result = fs::copy(&from, &tmp).and_then(|_| fs::rename(&tmp, &to));
        if let Err(e) = result {
            let _ = fs::remove_file(&tmp);
            return Err(format!("cannot copy {} into {}: {e}", from.display(), out.display()));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_map_both_ways() {
        let key = "rand_0000042";
        for f in ["rand_0000042_specification.json", "rand_0000042_pattern.svg", "design_params.yaml", "sample_info.json"] {
            let m = member_name(key, f);
            let (index, k, rest) = split_member(&m).unwrap();
            assert_eq!((index, k), (42, key));
            assert_eq!(folder_file_name(key, rest), f);
        }
        for bad in ["rand_0000001..", "rand_0000001.a/b", "rand_0000001.a\\b", "rand_0000001.", "rand_0000001..hidden", "rand_x.json"] {
            assert_eq!(split_member(bad), None, "{bad}");
        }
        assert_eq!(member_name(key, "rand_0000042_specification.json"), "rand_0000042.specification.json");
    }

    #[test]
    fn archives_read_back_and_damage_is_found() {
        let a = b"hello".to_vec();
        let b = vec![7u8; 1300];
        let bytes = tar(&[("x.a".into(), &a), ("x.b".into(), &b)]).unwrap();
        assert_eq!(bytes.len() % BLOCK, 0);
        let back = untar(&bytes).unwrap();
        assert_eq!(back, vec![("x.a".to_string(), a.clone()), ("x.b".to_string(), b.clone())]);
        assert!(untar(&bytes[..bytes.len() - 1500]).unwrap_err().contains("truncated"));
        let mut bad = bytes.clone();
        bad[3] ^= 1;
        assert!(untar(&bad).unwrap_err().contains("checksum"));
        assert!(untar(b"{\"not\": \"a tar\"}").unwrap_err().contains("not a tar"));
    }

    /// A reader that counts the bytes read through it.
    struct Counting<R> {
        inner: R,
        read: std::rc::Rc<std::cell::Cell<u64>>,
    }

    impl<R: io::Read> io::Read for Counting<R> {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let n = self.inner.read(buf)?;
            self.read.set(self.read.get() + n as u64);
            Ok(n)
        }
    }

    impl<R: io::Seek> io::Seek for Counting<R> {
        fn seek(&mut self, pos: io::SeekFrom) -> io::Result<u64> {
            self.inner.seek(pos)
        }
    }

    #[test]
    fn listing_an_archive_reads_its_headers_not_its_members() {
        let big = vec![1u8; 4 << 20];
        let info = b"{}".to_vec();
        let bytes = tar(&[
            ("rand_0000000.body_measurements.yaml".into(), &info),
            ("rand_0000000.boxmesh.obj".into(), &big),
            ("rand_0000000.design_params.yaml".into(), &info),
            ("rand_0000000.sample_info.json".into(), &info),
            ("rand_0000001.body_measurements.yaml".into(), &info),
            ("rand_0000001.boxmesh.obj".into(), &big),
            ("rand_0000001.design_params.yaml".into(), &info),
            ("rand_0000001.sample_info.json".into(), &info),
        ])
        .unwrap();
        let read = std::rc::Rc::new(std::cell::Cell::new(0));
        let mut reader = TarReader::new(Counting { inner: io::Cursor::new(&bytes), read: read.clone() }).unwrap();
        let samples = shard_samples(&mut reader).unwrap();
        let keys: Vec<&str> = samples.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(keys, ["rand_0000000", "rand_0000001"]);
        assert!(read.get() < 1 << 20, "listing read {} of {} bytes", read.get(), bytes.len());
        // A member is read when asked for.
        assert_eq!(reader.read(&samples[1].1[3], 2).unwrap(), info);
        assert_eq!(reader.read(&samples[0].1[1], MAX_MEMBER).unwrap(), big);
        assert!(reader.read(&samples[0].1[1], 1 << 20).unwrap_err().contains("more than a file of a sample has"));
    }

    #[test]
    fn a_sample_whose_files_are_apart_is_refused() {
        let x = b"x".to_vec();
        let bytes = tar(&[
            ("rand_0000001.specification.json".into(), &x),
            ("rand_0000002.sample_info.json".into(), &x),
            ("rand_0000001.sample_info.json".into(), &x),
        ])
        .unwrap();
        let err = shard_samples(&mut TarReader::new(io::Cursor::new(&bytes)).unwrap()).map(|_| ()).unwrap_err();
        assert!(err.contains("the files of rand_0000001 are not together"), "{err}");
        let empty = tar(&[]).unwrap();
        assert_eq!(shard_samples(&mut TarReader::new(io::Cursor::new(&empty)).unwrap()).map(|_| ()).unwrap_err(), "holds no sample");
    }

    #[test]
    fn the_index_is_in_shard_order_whatever_order_shards_finish_in() {
        let dir = std::env::temp_dir().join(format!("garmentcode-index-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        // Left by an interrupted run; another index's temporaries are not ours.
        fs::write(dir.join(".index.jsonl.parts-1"), "stale").unwrap();
        fs::write(dir.join(".index.jsonl.tmp-1"), "stale").unwrap();
        fs::write(dir.join(".index_shard_0_of_2.jsonl.parts-1"), "other").unwrap();
        let mut w = IndexWriter::new(&dir, "index.jsonl").unwrap();
        w.add(3, "d\n").unwrap();
        w.add(0, "a\nb\n").unwrap();
        w.add(7, "").unwrap();
        w.add(1, "c\n").unwrap();
        w.finish().unwrap();
        assert_eq!(fs::read_to_string(dir.join("index.jsonl")).unwrap(), "a\nb\nc\nd\n");
        let mut left: Vec<String> = fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        left.sort();
        assert_eq!(left, [".index_shard_0_of_2.jsonl.parts-1", "index.jsonl"]);
        // A run stopped by an error leaves no parts file.
        let mut w = IndexWriter::new(&dir, "index.jsonl").unwrap();
        w.add(0, "x\n").unwrap();
        drop(w);
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 2);
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_streamed_shard_is_the_archive_of_its_samples_whatever_their_order() {
        let dir = std::env::temp_dir().join(format!("garmentcode-shardwriter-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let files = |i: u64| -> Files {
            let key = sample_name(i);
            vec![(format!("{key}_specification.json"), vec![b'{'; 700 + i as usize]), ("sample_info.json".into(), vec![b'x'; 3])]
        };
        let record = |i: u64, accepted: bool| Record {
            index: i,
            accepted: accepted.then(|| store::Accepted {
                attempt: 0,
                body: "mean_all".into(),
                upper: "Shirt".into(),
                waistband: "none".into(),
                bottom: "none".into(),
                main: "upper_garment".into(),
                styles: vec![],
                panels: 4,
            }),
            rejections: vec![],
            drape: None,
        };
        let mut w = ShardWriter::new(Some(&dir), 2, 20..24);
        // 22 finishes first, 21 had every design rejected.
        assert_eq!(w.add(&record(22, true), Some(files(22))).unwrap(), None);
        assert_eq!(w.add(&record(20, true), Some(files(20))).unwrap(), None);
        assert!(!dir.join(shard_name(2)).exists(), "renamed before the last sample");
        assert_eq!(w.add(&record(23, true), Some(files(23))).unwrap(), None);
        let lines = w.add(&record(21, false), None).unwrap().expect("the shard is complete");
        let keys: Vec<String> =
            lines.lines().map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap()["key"].as_str().unwrap().to_string()).collect();
        assert_eq!(keys, ["rand_0000020", "rand_0000022", "rand_0000023"]);
        assert!(lines.lines().all(|l| l.contains("\"shard\":\"shard-000002.tar\"")));
        let written = fs::read(dir.join(shard_name(2))).unwrap();
        let mut members: Vec<(String, Vec<u8>)> = Vec::new();
        for i in [20, 22, 23] {
            let key = sample_name(i);
            let mut own: Vec<(String, Vec<u8>)> = files(i).into_iter().map(|(f, b)| (member_name(&key, &f), b)).collect();
            own.sort();
            members.extend(own);
        }
        let refs: Vec<(String, &[u8])> = members.iter().map(|(n, b)| (n.clone(), b.as_slice())).collect();
        assert_eq!(written, tar(&refs).unwrap());
        assert!(!dir.join(tmp_name(2)).exists());
        let _ = fs::remove_dir_all(&dir);
    }
}
