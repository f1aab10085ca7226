//! The configurator's server: a listener and a few worker threads, each taking
//! one connection at a time, reading one request within the limits, answering it
//! through [`api::route`](super::api::route) and closing the connection.
//!
//! A page and a handful of API calls per change need nothing more: no async
//! runtime, no framework, and a stalled or malformed client ties up one worker for
//! at most the request deadline. Every failure is contained to its connection, so
//! the server keeps serving after any bad request.

use std::io::{Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream, ToSocketAddrs};
use std::time::Duration;

use super::api::{ApiError, error_response, route};
use super::http::{Limits, read_request, write_response};

/// Worker threads by default.
pub const DEFAULT_WORKERS: usize = 4;

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

/// Serve forever on `listener` with `workers` threads; `log` gets one line per
/// refused request (4xx/5xx).
pub fn serve(listener: TcpListener, workers: usize, limits: Limits, log: fn(&str)) -> std::io::Result<()> {
    let mut handles = Vec::new();
    for _ in 0..workers.max(1) {
        let l = listener.try_clone()?;
        handles.push(std::thread::spawn(move || {
            loop {
                match l.accept() {
                    Ok((stream, peer)) => handle(stream, peer, &limits, log),
                    // Out of file descriptors and the like: wait a little, keep going.
                    Err(_) => std::thread::sleep(Duration::from_millis(50)),
                }
            }
        }));
    }
    for h in handles {
        let _ = h.join();
    }
    Ok(())
}

/// Start serving in background threads (for tests and embedding); returns the
/// bound address.
pub fn spawn(host: &str, port: u16, workers: usize) -> std::io::Result<SocketAddr> {
    let listener = bind(host, port)?;
    let addr = listener.local_addr()?;
    std::thread::spawn(move || serve(listener, workers, Limits::default(), |_| {}));
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
