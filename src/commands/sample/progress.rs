//! Progress on stderr: a redrawn bar with rate and time left on a terminal, plain
//! lines every few seconds otherwise (logs of batch jobs stay readable).

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// Progress of one run.
pub struct Progress {
    total: u64,
    done: u64,
    start: Instant,
    last: Option<Instant>,
    tty: bool,
    every: Duration,
}

impl Progress {
    /// Progress over `total` samples to make in this run.
    pub fn new(total: u64) -> Progress {
        let tty = std::io::stderr().is_terminal();
        let every = if tty { Duration::from_millis(100) } else { Duration::from_secs(10) };
        Progress { total, done: 0, start: Instant::now(), last: None, tty, every }
    }

    /// One more sample done.
    pub fn inc(&mut self) {
        self.done += 1;
    }

    /// Redraw if it is time to.
    pub fn tick(&mut self) {
        let now = Instant::now();
        if self.last.is_none_or(|l| now - l >= self.every) && now - self.start >= self.every.min(Duration::from_secs(1)) {
            self.last = Some(now);
            self.draw(false);
        }
    }

    /// The last line.
    pub fn finish(&mut self) {
        if self.tty || self.last.is_some() {
            self.draw(true);
        }
    }

    fn draw(&self, last: bool) {
        let secs = self.start.elapsed().as_secs_f64();
        let rate = if secs > 0.0 { self.done as f64 / secs } else { 0.0 };
        let left = self.total.saturating_sub(self.done);
        let eta = if rate > 0.0 { clock(left as f64 / rate) } else { "--:--".into() };
        let pct = if self.total == 0 { 100.0 } else { 100.0 * self.done as f64 / self.total as f64 };
        let mut err = std::io::stderr().lock();
        if self.tty {
            const WIDTH: usize = 30;
            let filled = ((pct / 100.0) * WIDTH as f64) as usize;
            let bar: String = "#".repeat(filled) + &"-".repeat(WIDTH - filled.min(WIDTH));
            let _ = write!(err, "\r[{bar}] {}/{} {pct:3.0}%  {rate:.0}/s  {} left ", self.done, self.total, eta);
            if last {
                let _ = writeln!(err);
            }
        } else {
            let _ = writeln!(err, "sampled {}/{} ({pct:.0}%), {rate:.0}/s, {} left", self.done, self.total, eta);
        }
        let _ = err.flush();
    }
}

/// `m:ss` or `h:mm:ss`.
fn clock(secs: f64) -> String {
    let s = secs.round() as u64;
    if s >= 3600 { format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60) } else { format!("{}:{:02}", s / 60, s % 60) }
}
