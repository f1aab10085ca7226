//! The dataset folder: one folder per sample, each written into a temporary sibling
//! and renamed into place (so it appears whole or not at all), and the record of
//! each sample (`sample_info.json`) that lets a rerun skip finished samples and
//! still summarise the whole dataset.

use garmentcode::io::DesignWriter;
use garmentcode::{Choice, Params};
use garments::sample::{DatasetSampler, GarmentType, Outcome, Reason, Sample, sample_name};
use serde_json::{Value, json};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// The per-sample record file.
pub const INFO: &str = "sample_info.json";

/// Output formats of the pattern.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Formats {
    /// `<name>_specification.json`.
    pub json: bool,
    /// `<name>_pattern.svg`.
    pub svg: bool,
    /// `<name>_pattern.png`.
    pub png: bool,
    /// The simulation box mesh at the default resolution: `<name>_boxmesh.obj` and the
    /// other files of [`garmentcode::mesh::write::FILE_SUFFIXES`].
    pub mesh: bool,
    /// The garment draped on its body (`garmentcode drape`'s files; the mesh files too).
    pub drape: bool,
}

impl Formats {
    /// The names, in a fixed order.
    pub fn names(&self) -> Vec<&'static str> {
        [(self.json, "json"), (self.svg, "svg"), (self.png, "png"), (self.mesh, "mesh"), (self.drape, "drape")]
            .into_iter()
            .filter(|f| f.0)
            .map(|f| f.1)
            .collect()
    }

    /// Files a finished sample has for these formats (a drape's own files only when it
    /// could run: its record says).
    pub fn files(&self, name: &str) -> Vec<String> {
        let mut out = Vec::new();
        if self.json {
            out.push(format!("{name}_specification.json"));
        }
        if self.svg {
            out.push(format!("{name}_pattern.svg"));
        }
        if self.png {
            out.push(format!("{name}_pattern.png"));
        }
        if self.mesh || self.drape {
            out.extend(garmentcode::mesh::write::FILE_SUFFIXES.iter().map(|suffix| format!("{name}{suffix}")));
        }
        out
    }
}

/// A rejected attempt, as recorded.
#[derive(Clone, Debug, PartialEq)]
pub struct RejectionRecord {
    /// Attempt number within the sample.
    pub attempt: u32,
    /// Body name.
    pub body: String,
    /// Filter that rejected it.
    pub reason: Reason,
    /// The filter's message.
    pub message: String,
}

/// An accepted sample, as recorded.
#[derive(Clone, Debug, PartialEq)]
pub struct Accepted {
    /// The accepted attempt.
    pub attempt: u32,
    /// Body name.
    pub body: String,
    /// Upper garment kind (`none` without one); likewise `waistband`, `bottom`.
    pub upper: String,
    /// Waistband kind.
    pub waistband: String,
    /// Bottom kind.
    pub bottom: String,
    /// Main garment type (reference statistics).
    pub main: String,
    /// Style tags (reference statistics).
    pub styles: Vec<String>,
    /// Number of panels.
    pub panels: usize,
}

/// What became of one sample index.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// Sample index.
    pub index: u64,
    /// `None` when every attempt was rejected (no folder is written).
    pub accepted: Option<Accepted>,
    /// Rejected attempts (before the accepted one).
    pub rejections: Vec<RejectionRecord>,
    /// With the `drape` format, how the accepted sample's drape went.
    pub drape: Option<DrapeRecord>,
}

/// How a sample's drape went, as the reference records simulations: the reasons it
/// counts as failed (its names: `static_equilibrium`, `simulation_timeout`,
/// `cloth_body_intersection`, `cloth_self_intersection`; and `meshgen`, `body_mesh` or
/// `crashes` when it could not run, with `message`). Empty when it settled within limits.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct DrapeRecord {
    /// Failure reasons, in the order found.
    pub fails: Vec<String>,
    /// Why the drape could not run (its files are missing then).
    pub message: Option<String>,
    /// Frames simulated.
    pub frames: u64,
}

/// How `--formats ...,drape` drapes: the fabric, the limits and the body meshes.
pub struct DrapeConfig {
    /// The fabric.
    pub fabric: garmentcode_drape::Fabric,
    /// Frame limit (the reference's when `None`).
    pub max_frames: Option<usize>,
    /// Time limit of one simulation (s).
    pub max_seconds: f64,
    /// Threads of each drape (0: every core; 1 with several jobs).
    pub threads: usize,
    /// Per body of the sampler, the mesh to drape on without and with pants (as the
    /// measurements differ), or why there is none.
    pub meshes: Vec<[Result<garmentcode_drape::BodyMesh, String>; 2]>,
}

/// Settings that make samples of one dataset: a rerun into the same folder must
/// have the same, or its samples would not belong together.
pub struct Settings<'a> {
    pub sampler: &'a DatasetSampler,
    /// FNV-1a hash of the design space and the bodies.
    pub fingerprint: String,
    pub formats: Formats,
    /// Writes `design_params.yaml` (as `write_design` does, faster).
    pub writer: DesignWriter,
    /// `body_measurements.yaml` of each body, straight and with legs apart.
    pub body_files: Vec<[String; 2]>,
    /// How to drape, with the `drape` format.
    pub drape: Option<DrapeConfig>,
}

impl<'a> Settings<'a> {
    /// Settings of a run; renders what every sample shares once. `drape` (fabric and
    /// limits) is used with the `drape` format.
    pub fn new(
        sampler: &'a DatasetSampler,
        formats: Formats,
        drape: Option<(garmentcode_drape::Fabric, Option<usize>, f64)>,
    ) -> Settings<'a> {
        let mut with_pants = garments::Design::defaults();
        with_pants.meta.bottom = Some(garments::design::BottomKind::Pants);
        let mut without = garments::Design::defaults();
        without.meta.bottom = None;
        let bodies = |b: usize| [sampler.body_for(b, &without), sampler.body_for(b, &with_pants)];
        let body_files = (0..sampler.bodies().len()).map(|b| bodies(b).map(|body| body.to_yaml())).collect();
        let mut fingerprint = fingerprint(sampler);
        let drape = drape.filter(|_| formats.drape).map(|(fabric, max_frames, max_seconds)| {
            // Drapes of another fabric or frame limit do not belong to the same dataset.
            let mut h = crate::output::Fnv1a::default();
            h.write(fingerprint.as_bytes());
            h.write(format!("{:?}{max_frames:?}", fabric.values()).as_bytes());
            fingerprint = format!("{:016x}", h.finish());
            let meshes = (0..sampler.bodies().len())
                .map(|b| {
                    let name = &sampler.bodies()[b].name;
                    bodies(b).map(|body| {
                        let name = crate::commands::drape::body_mesh_name(name, &body);
                        garmentcode_drape::BodyMesh::for_body(&name, &body).map_err(|e| e.to_string())
                    })
                })
                .collect();
            DrapeConfig { fabric, max_frames, max_seconds, threads: 0, meshes }
        });
        Settings { sampler, fingerprint, formats, writer: DesignWriter::new(sampler.space()), body_files, drape }
    }
}

/// FNV-1a (64 bit) of the design space and the bodies: a stable fingerprint of
/// everything besides the seed that decides the samples.
fn fingerprint(sampler: &DatasetSampler) -> String {
    let mut h = crate::output::Fnv1a::default();
    let mut eat = |s: &str| {
        h.write(s.as_bytes());
        h.write(&[0xff]);
    };
    eat(&sampler.space().to_yaml());
    for b in sampler.bodies() {
        eat(&b.name);
        eat(&b.body.to_yaml());
    }
    format!("{:016x}", h.finish())
}

fn tmp_name(name: &str) -> String {
    format!(".{name}.tmp-{}", std::process::id())
}

/// A sample's files as its folder names them (`rand_NNNNNNN_specification.json`,
/// `design_params.yaml`, ...), in memory.
pub type Files = Vec<(String, Vec<u8>)>;

/// Make sample `index` and write its folder; returns its record.
pub fn make(dir: &Path, s: &Settings, arena: &mut garmentcode::Arena, index: u64) -> Result<Record, String> {
    let (record, files) = draw(s, arena, index)?;
    if let Some(files) = files {
        write_folder(dir, &sample_name(index), &files)
            .map_err(|e| format!("cannot write {}: {e}", dir.join(sample_name(index)).display()))?;
    }
    Ok(record)
}

/// Make sample `index` in memory: its record, and its files unless every attempt
/// was rejected.
pub fn draw(s: &Settings, arena: &mut garmentcode::Arena, index: u64) -> Result<(Record, Option<Files>), String> {
    let sampler = s.sampler;
    let body_name = |i: usize| sampler.bodies()[i].name.clone();
    match sampler.draw_in(arena, index) {
        Outcome::Exhausted { index, rejections } => {
            let rejections = rejections
                .into_iter()
                .map(|r| RejectionRecord { attempt: r.attempt, body: body_name(r.body), reason: r.reason, message: r.message })
                .collect();
            Ok((Record { index, accepted: None, rejections, drape: None }, None))
        }
        Outcome::Accepted(sample) => {
            let mut record = record_of(sampler, &sample);
            let files = files_of(s, &sample, &mut record)?;
            Ok((record, Some(files)))
        }
    }
}

fn record_of(sampler: &DatasetSampler, sample: &Sample) -> Record {
    let d = &sample.design;
    let kind = |n: Option<&'static str>| n.unwrap_or("none").to_string();
    let t = GarmentType::of(d);
    let accepted = Accepted {
        attempt: sample.attempt,
        body: sampler.bodies()[sample.body].name.clone(),
        upper: kind(d.meta.upper.map(|k| k.name())),
        waistband: kind(d.meta.wb.map(|k| k.name())),
        bottom: kind(d.meta.bottom.map(|k| k.name())),
        main: t.main.to_string(),
        styles: t.styles.iter().map(|s| s.to_string()).collect(),
        panels: sample.built.pattern.panels.len(),
    };
    let rejections = sample
        .rejections
        .iter()
        .map(|r| RejectionRecord {
            attempt: r.attempt,
            body: sampler.bodies()[r.body].name.clone(),
            reason: r.reason,
            message: r.message.clone(),
        })
        .collect();
    Record { index: sample.index, accepted: Some(accepted), rejections, drape: None }
}

/// The files of a sample folder, in memory; the drape's outcome goes into `record`.
fn files_of(s: &Settings, sample: &Sample, record: &mut Record) -> Result<Files, String> {
    let name = sample_name(sample.index);
    let pattern = &sample.built.pattern;
    let fail = |what: &str, e: garmentcode::Error| format!("{name}: cannot write the {what}: {e}");
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    if s.formats.json {
        files.push((format!("{name}_specification.json"), pattern.to_json().map_err(|e| fail("specification", e))?.into_bytes()));
    }
    let opts = garmentcode::draw::DrawOptions::default();
    if s.formats.svg {
        files.push((
            format!("{name}_pattern.svg"),
            garmentcode::draw::to_svg(pattern, &opts).map_err(|e| fail("SVG drawing", e))?.into_bytes(),
        ));
    }
    if s.formats.png {
        files.push((format!("{name}_pattern.png"), garmentcode::draw::to_png(pattern, &opts).map_err(|e| fail("PNG drawing", e))?));
    }
    if s.formats.mesh || s.formats.drape {
        let mesh = garmentcode::mesh::BoxMesh::new(pattern, garmentcode::mesh::DEFAULT_RESOLUTION);
        match (mesh, &s.drape) {
            (Ok(mesh), drape) => {
                let mesh = garmentcode::mesh::BoxMesh { name: name.clone(), ..mesh };
                files.extend(mesh.files());
                if let Some(config) = drape {
                    let pants = sample.design.meta.bottom == Some(garments::design::BottomKind::Pants);
                    let outcome = drape_sample(s, config, sample, pants, &mesh);
                    record.drape = Some(match outcome {
                        Ok(draped) => {
                            files.extend(draped.files);
                            DrapeRecord {
                                fails: draped.fails.iter().map(|f| f.to_string()).collect(),
                                message: None,
                                frames: draped.stats.frames as u64,
                            }
                        }
                        Err((reason, message)) => DrapeRecord { fails: vec![reason.into()], message: Some(message), frames: 0 },
                    });
                }
            }
            // A failed drape is recorded and the sample kept; without a drape the mesh is
            // what was asked for, and its failure the run's.
            (Err(e), Some(_)) => {
                record.drape =
                    Some(DrapeRecord { fails: vec!["meshgen".into()], message: Some(format!("cannot mesh the pattern: {e}")), frames: 0 })
            }
            (Err(e), None) => return Err(format!("{name}: cannot mesh the pattern: {e}")),
        }
    }
    files.push(("design_params.yaml".into(), s.writer.write(&sample.design).into_bytes()));
    let pants = sample.design.meta.bottom == Some(garments::design::BottomKind::Pants);
    files.push(("body_measurements.yaml".into(), s.body_files[sample.body][usize::from(pants)].clone().into_bytes()));
    files.push((INFO.into(), info_json(s, record).into_bytes()));
    Ok(files)
}

/// Drapes a sample's box mesh on its body: the drape files, or the failure reason and message.
fn drape_sample(
    s: &Settings,
    config: &DrapeConfig,
    sample: &Sample,
    pants: bool,
    mesh: &garmentcode::mesh::BoxMesh,
) -> Result<crate::commands::drape::Draped, (&'static str, String)> {
    let body_mesh = config.meshes[sample.body][usize::from(pants)].as_ref().map_err(|e| ("body_mesh", e.clone()))?;
    let measurements = s.sampler.body_for(sample.body, &sample.design);
    let name = &s.sampler.bodies()[sample.body].name;
    let setup = crate::commands::drape::DrapeSetup {
        body: body_mesh,
        body_source: &crate::commands::drape::body_mesh_source(&crate::commands::drape::body_mesh_name(name, &measurements)),
        measurements: (&measurements, name),
        fabric: &config.fabric,
        max_frames: config.max_frames,
        max_seconds: config.max_seconds,
        threads: config.threads,
    };
    crate::commands::drape::drape_files(&sample.built.pattern, mesh, &setup, |_| {}).map_err(|e| ("crashes", e))
}

/// Write files into `.name.tmp-PID`, then rename it to `name`. A folder made
/// meanwhile by another process counts as done (it holds the same sample).
pub fn write_folder(dir: &Path, name: &str, files: &[(String, Vec<u8>)]) -> io::Result<()> {
    let tmp = dir.join(tmp_name(name));
    let target = dir.join(name);
    let created = fs::create_dir(&tmp).or_else(|e| {
        if e.kind() != io::ErrorKind::AlreadyExists {
            return Err(e);
        }
        fs::remove_dir_all(&tmp).and_then(|_| fs::create_dir(&tmp))
    });
    let result =
        created.and_then(|_| files.iter().try_for_each(|(f, bytes)| fs::write(tmp.join(f), bytes))).and_then(|_| fs::rename(&tmp, &target));
    if result.is_err() {
        let _ = fs::remove_dir_all(&tmp);
        if target.join(INFO).is_file() {
            return Ok(());
        }
    }
    result
}

fn info_json(s: &Settings, r: &Record) -> String {
    let a = r.accepted.as_ref().expect("only accepted samples have a folder");
    let rejected: Vec<Value> = r
        .rejections
        .iter()
        .map(|x| json!({ "attempt": x.attempt, "body": x.body, "reason": x.reason.key(), "message": x.message }))
        .collect();
    let v = json!({
        "name": sample_name(r.index),
        "seed": s.sampler.seed(),
        "index": r.index,
        "settings": s.fingerprint,
        "attempt": a.attempt,
        "body": a.body,
        "garment": {
            "upper": a.upper,
            "waistband": a.waistband,
            "bottom": a.bottom,
            "main": a.main,
            "styles": a.styles,
            "panels": a.panels,
        },
        "rejected": rejected,
    });
    let mut v = v;
    if let Some(d) = &r.drape {
        v["drape"] = json!({ "fails": d.fails, "message": d.message, "frames": d.frames });
    }
    serde_json::to_string_pretty(&v).expect("record serialises") + "\n"
}

/// Read a finished sample's record, checking that it belongs to this dataset.
fn read_info(path: &Path, s: &Settings, index: u64) -> Result<Record, String> {
    let text = crate::commands::read_text(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    parse_info(&text, &path.display(), s, index)
}

/// Parse a sample record read from `show` (a file, or a member of a shard),
/// checking that it belongs to this dataset.
pub fn parse_info(text: &str, show: &dyn std::fmt::Display, s: &Settings, index: u64) -> Result<Record, String> {
    let v: Value = serde_json::from_str(text).map_err(|e| format!("{show}: {e}"))?;
    let bad = || format!("{show}: not a sample record of this tool");
    let seed = v["seed"].as_u64().ok_or_else(bad)?;
    if seed != s.sampler.seed() || v["index"].as_u64() != Some(index) {
        return Err(format!(
            "{show}: this folder holds a dataset of seed {seed}, not {}; choose another --out or the same --seed",
            s.sampler.seed()
        ));
    }
    if v["settings"].as_str() != Some(s.fingerprint.as_str()) {
        return Err(format!(
            "{show}: this folder holds a dataset made with another design space or other bodies; choose another --out or the same settings"
        ));
    }
    let text_of = |x: &Value| x.as_str().map(str::to_string).ok_or_else(bad);
    let g = &v["garment"];
    let accepted = Accepted {
        attempt: v["attempt"].as_u64().ok_or_else(bad)? as u32,
        body: text_of(&v["body"])?,
        upper: text_of(&g["upper"])?,
        waistband: text_of(&g["waistband"])?,
        bottom: text_of(&g["bottom"])?,
        main: text_of(&g["main"])?,
        styles: g["styles"].as_array().ok_or_else(bad)?.iter().map(text_of).collect::<Result<_, _>>()?,
        panels: g["panels"].as_u64().ok_or_else(bad)? as usize,
    };
    let mut rejections = Vec::new();
    for x in v["rejected"].as_array().ok_or_else(bad)? {
        rejections.push(RejectionRecord {
            attempt: x["attempt"].as_u64().ok_or_else(bad)? as u32,
            body: text_of(&x["body"])?,
            reason: x["reason"].as_str().and_then(Reason::from_key).ok_or_else(bad)?,
            message: text_of(&x["message"])?,
        });
    }
    let drape = match &v["drape"] {
        Value::Null if !s.formats.drape => None,
        d if s.formats.drape => Some(DrapeRecord {
            fails: d["fails"].as_array().ok_or_else(bad)?.iter().map(text_of).collect::<Result<_, _>>()?,
            message: d["message"].as_str().map(str::to_string),
            frames: d["frames"].as_u64().ok_or_else(bad)?,
        }),
        _ => {
            return Err(format!(
                "{show}: the dataset was made with other --formats (drape or not); resume with the same --formats or choose another --out"
            ));
        }
    };
    Ok(Record { index, accepted: Some(accepted), rejections, drape })
}

/// The entries of a dataset folder, found by [`list`].
pub struct Listing {
    /// `(index, file name, path)` of the entries of this run, in listing order.
    pub items: Vec<(u64, String, PathBuf)>,
    /// Temporaries `.<name>.tmp-PID` of this run's entries, left by interrupted runs.
    pub stale: Vec<PathBuf>,
}

/// List `dir`: the entries whose name `parse` reads as an index below `limit` that
/// `wanted` keeps (sample folders or shards), and the stale temporaries of such
/// entries. Other entries are passed over.
pub fn list(dir: &Path, parse: impl Fn(&str) -> Option<u64>, limit: u64, wanted: impl Fn(u64) -> bool) -> Result<Listing, String> {
    let mut listing = Listing { items: Vec::new(), stale: Vec::new() };
    let entries = fs::read_dir(dir).map_err(|e| format!("{}: cannot list: {e}", dir.display()))?;
    for entry in entries {
        let entry = entry.map_err(|e| format!("{}: cannot list: {e}", dir.display()))?;
        let file_name = entry.file_name();
        let Some(name) = file_name.to_str() else { continue };
        if let Some(rest) = name.strip_prefix('.')
            && let Some((item, _pid)) = rest.split_once(".tmp-")
            && parse(item).is_some_and(&wanted)
        {
            listing.stale.push(entry.path());
            continue;
        }
        let Some(index) = parse(name) else { continue };
        if index >= limit || !wanted(index) {
            continue;
        }
        listing.items.push((index, name.to_string(), entry.path()));
    }
    Ok(listing)
}

/// The sample index of a folder name `rand_NNNNNNN` (digits only).
pub fn index_of(name: &str) -> Option<u64> {
    let digits = name.strip_prefix("rand_")?;
    if digits.len() < 7 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// What a dataset folder already holds for the indices of this run.
pub struct Existing {
    /// Indices of finished samples (of the wanted indices), sorted.
    pub finished: Vec<u64>,
    /// Stale temporary folders removed.
    pub removed_temps: usize,
}

/// Scan `dir`: remove stale temporaries of the wanted indices (left by an
/// interrupted run) and read the records of finished samples, checking they
/// belong to this dataset and have every requested file; each record is handed to
/// `on_record` (in no particular order). `wanted` says whether an index belongs to
/// this run (its shard).
pub fn scan(dir: &Path, s: &Settings, n: u64, wanted: impl Fn(u64) -> bool, mut on_record: impl FnMut(Record)) -> Result<Existing, String> {
    let mut finished = Vec::new();
    let mut removed_temps = 0;
    let Listing { items, stale } = list(dir, index_of, n, &wanted)?;
    for (index, name, path) in items {
        let info = path.join(INFO);
        if !info.is_file() {
            return Err(format!("{}: not a sample folder of this tool (no {INFO}); choose another --out", path.display()));
        }
        let record = read_info(&info, s, index)?;
        for f in s.formats.files(&name) {
            if !path.join(&f).is_file() {
                return Err(format!(
                    "{}: has no {f}: the dataset was made with other --formats; resume with the same --formats or choose another --out",
                    path.display()
                ));
            }
        }
        on_record(record);
        finished.push(index);
    }
    // Checked above, removed only now: a folder with foreign samples is left untouched.
    for t in stale {
        fs::remove_dir_all(&t).map_err(|e| format!("{}: cannot remove a stale temporary folder: {e}", t.display()))?;
        removed_temps += 1;
    }
    finished.sort_unstable();
    Ok(Existing { finished, removed_temps })
}
