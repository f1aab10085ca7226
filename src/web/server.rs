//! The configurator's server: a listener that gives every connection its own
//! thread (up to [`MAX_CONNECTIONS`] at once), which reads one request within the
//! limits, answers it through [`api::route`](super::api::route) and closes the
//! connection.
//!
//! A page and a handful of API calls per change need nothing more: no async
//! runtime, no framework. A thread per connection means a stalled client holds
//! only its own thread (until the request deadline), never the others; beyond the
//! cap new connections get an immediate 503. Every failure is contained to its
//! connection, so the server keeps serving after any bad request.

use std::io::{Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream, ToSocketAddrs};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use super::api::{ApiError, error_response, route};
use super::http::{Limits, read_request, write_response};

/// Connections served at once; more get 503 until one finishes.
pub const MAX_CONNECTIONS: usize = 32;

/// Bind `host:port` (`port` 0 lets the system choose).
pub fn bind(host: &str, port: u16) -> std::io::Result<TcpListener> {
    let addrs: Vec<SocketAddr> = (host, port).to_socket_addrs()?.collect();
    TcpListener::bind(&addrs[..])
}

/// Whether the listener only accepts connections from this machine.
pub fn is_loopback(addr: &SocketAddr) -> bool {
    addr.ip().is_loopback()
}

/// The page's address, for printing.
pub fn url(addr: &SocketAddr) -> String {
    match addr {
        SocketAddr::V4(a) => format!("http://{}:{}/", a.ip(), a.port()),
        SocketAddr::V6(a) => format!("http://[{}]:{}/", a.ip(), a.port()),
    }
}

/// Serve forever on `listener`; `log` gets one line per refused request
/// (4xx/5xx).
pub fn serve(listener: TcpListener, limits: Limits, log: fn(&str)) {
    let active = Arc::new(AtomicUsize::new(0));
    for conn in listener.incoming() {
        let Ok(mut stream) = conn else {
            // Out of file descriptors and the like: wait a little, keep going.
            std::thread::sleep(Duration::from_millis(50));
            continue;
        };
        if active.load(Ordering::SeqCst) >= MAX_CONNECTIONS {
            let busy = ApiError { status: 503, message: "the server is busy; try again".into(), problems: Vec::new() };
            let _ = stream.set_write_timeout(Some(Duration::from_millis(200)));
            let _ = write_response(&mut stream, &error_response(&busy), false);
            log("refused a connection: too many at once (503)");
            continue;
        }
        let slot = Slot::take(&active);
        let spawned = std::thread::Builder::new().name("garmentcode-http".into()).spawn(move || {
            let _slot = slot; // given back when the connection is done, even on a panic
            if let Ok(peer) = stream.peer_addr() {
                handle(stream, peer, &limits, log);
            }
        });
        if spawned.is_err() {
            log("cannot start a thread for a connection");
        }
    }
}

/// One of the [`MAX_CONNECTIONS`] places, given back on drop.
struct Slot(Arc<AtomicUsize>);

impl Slot {
    fn take(active: &Arc<AtomicUsize>) -> Slot {
        active.fetch_add(1, Ordering::SeqCst);
        Slot(Arc::clone(active))
    }
}

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Start serving in a background thread (for tests and embedding); returns the
/// bound address.
pub fn spawn(host: &str, port: u16) -> std::io::Result<SocketAddr> {
    let listener = bind(host, port)?;
    let addr = listener.local_addr()?;
    std::thread::spawn(move || serve(listener, Limits::default(), |_| {}));
    Ok(addr)
}

fn handle(mut stream: TcpStream, peer: SocketAddr, limits: &Limits, log: fn(&str)) {
    let _ = stream.set_write_timeout(Some(limits.deadline));
    let _ = stream.set_nodelay(true);
    let (response, head_only, what) = match read_request(&mut stream, limits) {
        Ok(req) => {
            let what = format!("{} {}", req.method, req.path);
            (route(&req), req.method == "HEAD", what)
        }
        Err(e) => {
            let what = format!("malformed request ({})", e.message);
            (error_response(&ApiError { status: e.status, message: e.message.clone(), problems: vec![e.message] }), false, what)
        }
    };
    if response.status >= 400 {
        log(&format!("{peer}: {what} -> {}", response.status));
    }
    let _ = write_response(&mut stream, &response, head_only);
    // Let the client read the answer before the socket closes: closing with unread
    // input (an oversized body we refused to read) would reset the connection and
    // could lose the response. Drain a bounded amount for a short while.
    let _ = stream.shutdown(Shutdown::Write);
    let _ = stream.set_read_timeout(Some(Duration::from_millis(200)));
    let mut sink = [0u8; 16 * 1024];
    let mut drained = 0usize;
    let since = std::time::Instant::now();
    while drained < 4 * 1024 * 1024 && since.elapsed() < Duration::from_secs(1) {
        match stream.read(&mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => drained += n,
        }
    }
    let _ = stream.flush();
}
