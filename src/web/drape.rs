//! The configurator's drape view: the current design draped on the body by
//! [`garmentcode_drape`], one drape at a time per server, watched by polling.
//!
//! - `POST /api/drape` `{"design", "body", "name", "resolution", "max_frames"}` builds
//!   and meshes the design (as `POST /api/mesh`), stops the drape running (if any),
//!   starts this one on its own thread and answers at once: `ok`, `job` (its id),
//!   `max_frames`, `time_limit` (s), `mesh` (the box mesh, as `POST /api/mesh` gives it)
//!   and `body_mesh` (`positions`, `triangles`: the body it drapes on, cm). A design the
//!   library refuses, or a body without a body mesh, is `ok: false` with the reason.
//! - `GET /api/drape/JOB`: where it is: `state` (`running`, `done`, `stopped`, `failed`),
//!   `frame`, `max_frames`, `non_static_vertices`, `seconds`, `positions` (the garment's
//!   vertices after the last frame, cm, in box-mesh order), and once finished `stats`
//!   (the library's [`Stats`]) or `error`. Only the latest drape is kept: an older job
//!   is 404.
//! - `POST /api/drape/cancel` `{"job"}`: stops it (`state` becomes `stopped`).
//!
//! Bounds: one drape runs at a time (a new one stops the previous, which the page does
//! when the design changes); at most [`MAX_FRAMES`] frames and [`TIME_LIMIT`] of wall
//! time; a drape nobody has asked about for [`ABANDONED`] stops (the page was closed).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use garmentcode::Vec3;
use garmentcode_drape::{BodyMesh, Next, Settings, Stats, drape_with_progress};
use serde_json::{Value as Json, json};

use super::api::{ApiError, json_shown, mesh_json, meshed, write_positions};

/// Most frames a drape of the configurator may run (the library's default limit).
pub const MAX_FRAMES: usize = 2400;
/// Frames when the request does not say.
pub const DEFAULT_FRAMES: usize = 600;
/// Wall time after which a drape is stopped.
pub const TIME_LIMIT: Duration = Duration::from_secs(180);
/// A drape whose progress nobody has asked for this long is stopped.
pub const ABANDONED: Duration = Duration::from_secs(20);

/// The time bounds of a drape job.
#[derive(Clone, Copy, Debug)]
pub struct Bounds {
    /// Wall time after which it is stopped ([`TIME_LIMIT`]).
    pub time: Duration,
    /// Time without a poll after which it is stopped ([`ABANDONED`]).
    pub abandoned: Duration,
}

impl Default for Bounds {
    fn default() -> Bounds {
        Bounds { time: TIME_LIMIT, abandoned: ABANDONED }
    }
}

/// Where a drape is.
#[derive(Clone, Debug, PartialEq)]
enum State {
    Running,
    Done,
    Stopped(String),
    Failed(String),
}

/// What the drape's thread reports and the polls read.
struct Status {
    state: State,
    frame: usize,
    non_static: usize,
    positions: Vec<Vec3>,
    stats: Option<Stats>,
    polled: Instant,
}

/// A drape job.
struct Job {
    id: u64,
    max_frames: usize,
    started: Instant,
    cancel: AtomicBool,
    status: Mutex<Status>,
}

impl Job {
    fn status(&self) -> MutexGuard<'_, Status> {
        // A panic on the drape thread leaves the status as it was: still readable.
        self.status.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// The latest job and the thread running it.
struct Current {
    job: Option<Arc<Job>>,
    thread: Option<JoinHandle<()>>,
}

static CURRENT: Mutex<Current> = Mutex::new(Current { job: None, thread: None });
static NEXT_ID: AtomicU64 = AtomicU64::new(1);
/// Held by a start from stopping the previous drape to starting its own.
static STARTING: Mutex<()> = Mutex::new(());

fn current() -> MutexGuard<'static, Current> {
    CURRENT.lock().unwrap_or_else(|e| e.into_inner())
}

/// `POST /api/drape`: see the [module documentation](self).
pub fn start(input: &Json) -> Result<String, ApiError> {
    start_with(input, Bounds::default())
}

/// [`start`] with other time bounds.
pub fn start_with(input: &Json, bounds: Bounds) -> Result<String, ApiError> {
    let max_frames = match input.get("max_frames") {
        None | Some(Json::Null) => DEFAULT_FRAMES,
        Some(v) => v.as_u64().filter(|n| (1..=MAX_FRAMES as u64).contains(n)).map(|n| n as usize).ok_or_else(|| {
            ApiError::bad(format!("max_frames: expected a whole number of frames from 1 to {MAX_FRAMES}, got {}", json_shown(v)))
        })?,
    };
    let m = meshed(input, &["max_frames"])?;
    let refused = |reason: String| json!({ "ok": false, "name": m.name, "error": reason, "problems": [reason] }).to_string();
    let (pattern, mesh) = match m.result {
        Ok(r) => r,
        Err(reason) => return Ok(refused(reason)),
    };
    let body_mesh = match BodyMesh::for_body(&crate::commands::drape::body_mesh_name(&m.body_name, &m.body), &m.body) {
        Ok(b) => b,
        Err(e) => return Ok(refused(format!("no body to drape on: {e}"))),
    };
    let mut settings = Settings::for_body(&m.body).with_panel_labels(&pattern);
    settings.max_frames = max_frames;

    let job = Arc::new(Job {
        id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        max_frames,
        started: Instant::now(),
        cancel: AtomicBool::new(false),
        status: Mutex::new(Status {
            state: State::Running,
            frame: 0,
            non_static: mesh.vertices.len(),
            positions: mesh.vertices.clone(),
            stats: None,
            polled: Instant::now(),
        }),
    });
    let mut text =
        json!({ "ok": true, "job": job.id, "name": m.name, "max_frames": max_frames, "time_limit": bounds.time.as_secs() }).to_string();
    text.pop(); // the closing brace
    text.push_str(",\"body_mesh\":{\"name\":");
    text.push_str(&Json::String(body_mesh.name.clone()).to_string());
    text.push_str(",\"positions\":");
    write_positions(&mut text, &body_mesh.vertices);
    text.push_str(",\"triangles\":[");
    for (i, f) in body_mesh.faces.iter().enumerate() {
        let sep = if i == 0 { "" } else { "," };
        text.push_str(&format!("{sep}{},{},{}", f[0], f[1], f[2]));
    }
    text.push_str("]},\"mesh\":");
    text.push_str(&mesh_json(&mesh));
    text.push('}');

    // One drape at a time: starts take turns; each stops the running drape and waits
    // for its thread (it stops after its current frame) before starting its own. The
    // polls only need `CURRENT`, which is not held while waiting.
    let _turn = STARTING.lock().unwrap_or_else(|e| e.into_inner());
    let old = {
        let mut cur = current();
        if let Some(old) = &cur.job {
            old.cancel.store(true, Ordering::Relaxed);
        }
        cur.thread.take()
    };
    if let Some(thread) = old {
        let _ = thread.join();
    }
    let worker = Arc::clone(&job);
    let thread = std::thread::Builder::new()
        .name(format!("garmentcode-drape-{}", job.id))
        .spawn(move || run(&worker, &mesh, &body_mesh, &settings, bounds))
        .map_err(|e| ApiError::new(503, format!("cannot start a drape: {e}")))?;
    *current() = Current { job: Some(job), thread: Some(thread) };
    Ok(text)
}

/// The drape itself, on its own thread.
fn run(job: &Job, mesh: &garmentcode::mesh::BoxMesh, body: &BodyMesh, settings: &Settings, bounds: Bounds) {
    let mut stopped = None;
    let result = drape_with_progress(mesh, body, settings, |p| {
        let mut s = job.status();
        s.frame = p.frame;
        s.non_static = p.non_static_vertices;
        s.positions.copy_from_slice(p.positions);
        stopped = if job.cancel.load(Ordering::Relaxed) {
            Some("cancelled".to_string())
        } else if job.started.elapsed() > bounds.time {
            Some(format!("the time limit of {} s was reached", bounds.time.as_secs()))
        } else if s.polled.elapsed() > bounds.abandoned {
            Some(format!("nobody asked for its progress for {} s", bounds.abandoned.as_secs()))
        } else {
            None
        };
        if stopped.is_some() { Next::Stop } else { Next::Continue }
    });
    let mut s = job.status();
    match result {
        Ok(d) => {
            s.positions = d.positions;
            s.frame = d.stats.frames;
            s.non_static = d.stats.non_static_vertices;
            s.state = match stopped {
                Some(why) => State::Stopped(why),
                None => State::Done,
            };
            s.stats = Some(d.stats);
        }
        Err(e) => s.state = State::Failed(e.to_string()),
    }
}

/// The latest job, if its id is `id`.
fn job(id: &str) -> Result<Arc<Job>, ApiError> {
    let latest = current().job.clone();
    let wanted: Option<u64> = id.parse().ok();
    match latest {
        Some(job) if Some(job.id) == wanted => Ok(job),
        _ => Err(ApiError::new(
            404,
            format!(
                "no drape job {} (only the latest drape is kept{})",
                super::api::shown(id),
                latest.map_or(String::new(), |j| format!(": job {}", j.id))
            ),
        )),
    }
}

/// `GET /api/drape/JOB`: see the [module documentation](self).
pub fn status(id: &str) -> Result<String, ApiError> {
    let job = job(id)?;
    let mut s = job.status();
    s.polled = Instant::now();
    let (state, error) = match &s.state {
        State::Running => ("running", None),
        State::Done => ("done", None),
        State::Stopped(why) => ("stopped", Some(why.clone())),
        State::Failed(why) => ("failed", Some(why.clone())),
    };
    let mut head = json!({
        "ok": true,
        "job": job.id,
        "state": state,
        "frame": s.frame,
        "max_frames": job.max_frames,
        "non_static_vertices": s.non_static,
        "seconds": (job.started.elapsed().as_secs_f64() * 100.0).round() / 100.0,
    });
    if let Some(e) = error {
        head["error"] = json!(e);
    }
    if let Some(st) = &s.stats {
        head["stats"] = json!({
            "frames": st.frames,
            "seconds": st.seconds,
            "converged": st.converged,
            "at_rest": st.at_rest,
            "non_static_vertices": st.non_static_vertices,
            "body_penetrations": st.body_penetrations,
            "self_intersections": st.self_intersections,
        });
    }
    let mut text = head.to_string();
    text.pop();
    text.push_str(",\"positions\":");
    write_positions(&mut text, &s.positions);
    text.push('}');
    Ok(text)
}

/// `POST /api/drape/cancel` `{"job"}`: see the [module documentation](self).
pub fn cancel(input: &Json) -> Result<Json, ApiError> {
    let id = match input.get("job") {
        Some(v @ Json::Number(_)) => v.to_string(),
        other => {
            return Err(ApiError::bad(format!(
                "job: expected the number of a drape job, got {}",
                other.map_or("nothing".into(), json_shown)
            )));
        }
    };
    let job = job(&id)?;
    job.cancel.store(true, Ordering::Relaxed);
    Ok(json!({ "ok": true, "job": job.id }))
}

/// Waits until the latest drape's thread has ended (for tests).
#[cfg(test)]
pub(crate) fn wait() {
    let thread = current().thread.take();
    if let Some(t) = thread {
        let _ = t.join();
    }
}
