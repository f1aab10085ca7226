//! The configurator's server: hyper (HTTP/1.1 with keep-alive) on a tokio
//! runtime, in front of [`api::route`](super::api::route).
//!
//! What it defends against, and how:
//! - **Other web pages** the user visits: POSTs must say `Content-Type:
//!   application/json` (a page cannot send that cross-origin without a CORS
//!   preflight, which is never granted: no CORS headers are sent), and the `Host`
//!   header must name this server ([`host_allowed`]), so a DNS-rebinding page
//!   cannot read answers either.
//! - **Many or slow clients**: connections are cheap tasks (up to
//!   [`Limits::max_connections`], then an immediate 503); headers and bodies must
//!   arrive within [`Limits::deadline`]; builds run on a pool of
//!   [`Limits::max_builds`] blocking threads, separate from connections, so idle
//!   or slow connections never take a build's place.
//! - **Expensive requests**: a request waiting for a build slot past
//!   [`Limits::work_deadline`] is dropped before its build starts; a build that
//!   has started is bounded by the library's input checks (every design and body
//!   is refused or built within about a second). A client that closes its
//!   sending side after its request (a half-close, as `nc -N` does) is still
//!   answered: the end of its input is not taken for its departure.
//! - **Shutdown**: Ctrl-C stops accepting, lets requests in progress finish (up to
//!   a few seconds) and returns.
//!
//! Log lines go to a function the caller gives; the command line writes them to
//! stderr without ever failing (a closed stderr is ignored).

use std::convert::Infallible;
use std::net::{IpAddr, SocketAddr, TcpListener, ToSocketAddrs};
use std::sync::Arc;
use std::time::{Duration, Instant};

use http_body_util::{BodyExt, Full, Limited};
use hyper::body::{Bytes, Incoming};
use hyper::header::{CONTENT_LENGTH, CONTENT_TYPE, HOST, HeaderValue};
use hyper::service::service_fn;
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::io::AsyncWriteExt;
use tokio::sync::Semaphore;

use super::api::{ApiError, error_response, route, shown};
use super::http::{Limits, Request, Response, percent_decode};

/// Bind `host:port` (`port` 0 lets the system choose).
pub fn bind(host: &str, port: u16) -> std::io::Result<TcpListener> {
    let addrs: Vec<SocketAddr> = (host, port).to_socket_addrs()?.collect();
    TcpListener::bind(&addrs[..])
}

/// Whether the listener only accepts connections from this machine.
pub fn is_loopback(addr: &SocketAddr) -> bool {
    addr.ip().is_loopback()
}

/// The page's address, for printing: one a browser on this machine can open (a
/// server listening on every interface, 0.0.0.0 or ::, is reached at loopback).
pub fn url(addr: &SocketAddr) -> String {
    match addr.ip() {
        IpAddr::V4(ip) if ip.is_unspecified() => format!("http://127.0.0.1:{}/", addr.port()),
        IpAddr::V6(ip) if ip.is_unspecified() => format!("http://[::1]:{}/", addr.port()),
        IpAddr::V4(ip) => format!("http://{ip}:{}/", addr.port()),
        IpAddr::V6(ip) => format!("http://[{ip}]:{}/", addr.port()),
    }
}

/// Whether a request's `Host` header names this server: its port (a `Host`
/// without one means HTTP's default, 80), and `localhost` or an IP address (any,
/// for a server on every interface; a loopback one otherwise), or this machine's
/// name when the server listens beyond loopback. A DNS-rebinding page's requests
/// carry its own domain name, and a page of another local server its port: both
/// are refused. Requests without a `Host` (HTTP/1.0 tools) are let through:
/// browsers always send one.
pub fn host_allowed(host: Option<&str>, served: &SocketAddr, machine: Option<&str>) -> bool {
    let Some(host) = host else { return true };
    let (name, port) = match host.strip_prefix('[') {
        Some(v6) => match v6.split_once(']') {
            Some((ip, "")) => (ip, None),
            Some((ip, rest)) => match rest.strip_prefix(':') {
                Some(port) => (ip, Some(port)),
                None => return false,
            },
            None => return false,
        },
        None => match host.rsplit_once(':') {
            Some((name, port)) => (name, Some(port)),
            None => (host, None),
        },
    };
    let port_matches = match port {
        None => served.port() == 80,
        Some(p) => p.bytes().all(|b| b.is_ascii_digit()) && p.parse::<u16>() == Ok(served.port()),
    };
    if !port_matches {
        return false;
    }
    let name = name.trim_end_matches('.').to_ascii_lowercase();
    if name == "localhost" {
        return true;
    }
    if let Ok(ip) = name.parse::<IpAddr>() {
        return !served.ip().is_loopback() || ip.is_loopback();
    }
    !served.ip().is_loopback() && machine.is_some_and(|m| m.eq_ignore_ascii_case(&name))
}

/// This machine's name (Linux), for [`host_allowed`].
fn machine_name() -> Option<String> {
    std::fs::read_to_string("/proc/sys/kernel/hostname").ok().map(|s| s.trim().to_string()).filter(|s| !s.is_empty())
}

/// What every connection shares.
struct Shared {
    limits: Limits,
    served: SocketAddr,
    machine: Option<String>,
    builds: Semaphore,
    log: fn(&str),
}

/// Serve on `listener` until Ctrl-C, then finish the requests in progress (up to
/// a few seconds) and return. `log` gets one line per refused request (4xx/5xx)
/// and per refused connection.
pub fn serve(listener: TcpListener, limits: Limits, log: fn(&str)) -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .max_blocking_threads(limits.max_builds.max(1))
        .thread_name("garmentcode-http")
        .enable_all()
        .build()?;
    runtime.block_on(run(listener, limits, log, async {
        let _ = tokio::signal::ctrl_c().await;
    }))?;
    runtime.shutdown_timeout(Duration::from_secs(1));
    Ok(())
}

/// Start serving in a background thread (for tests, benchmarks and embedding);
/// returns the bound address. The server stops with the process.
pub fn spawn(host: &str, port: u16) -> std::io::Result<SocketAddr> {
    let listener = bind(host, port)?;
    let addr = listener.local_addr()?;
    std::thread::spawn(move || serve(listener, Limits::default(), |_| {}));
    Ok(addr)
}

async fn run(listener: TcpListener, limits: Limits, log: fn(&str), stop: impl std::future::Future<Output = ()>) -> std::io::Result<()> {
    listener.set_nonblocking(true)?;
    let served = listener.local_addr()?;
    let listener = tokio::net::TcpListener::from_std(listener)?;
    let shared = Arc::new(Shared { limits, served, machine: machine_name(), builds: Semaphore::new(limits.max_builds.max(1)), log });
    let connections = Arc::new(Semaphore::new(limits.max_connections.max(1)));
    let graceful = hyper_util::server::graceful::GracefulShutdown::new();
    let mut http = hyper::server::conn::http1::Builder::new();
    // Half-closed connections are answered: many scripted clients (`nc -N`, a
    // `shutdown(SHUT_WR)` after the request) close their sending side once the
    // request is sent, and read the answer. (Without it, hyper takes that end of
    // input for a client gone and drops the request.)
    http.timer(TokioTimer::new())
        .header_read_timeout(limits.deadline)
        .max_buf_size(limits.max_head.max(8192))
        .keep_alive(true)
        .half_close(true);
    tokio::pin!(stop);
    loop {
        let (mut stream, peer) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(c) => c,
                Err(_) => {
                    // Out of file descriptors and the like: wait a little, keep going.
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            () = &mut stop => break,
        };
        let Ok(permit) = Arc::clone(&connections).try_acquire_owned() else {
            log(&format!("{peer}: refused a connection: {} open at once (503)", limits.max_connections));
            tokio::spawn(async move {
                let busy = error_response(&ApiError::new(503, "the server is busy; try again"));
                let head = format!(
                    "HTTP/1.1 503 Service Unavailable\r\nContent-Type: {}\r\nContent-Length: {}\r\nConnection: close\r\nRetry-After: 1\r\n\r\n",
                    busy.content_type,
                    busy.body.len()
                );
                let _ = tokio::time::timeout(Duration::from_millis(500), async {
                    let _ = stream.write_all(head.as_bytes()).await;
                    let _ = stream.write_all(&busy.body).await;
                    let _ = stream.shutdown().await;
                })
                .await;
            });
            continue;
        };
        let _ = stream.set_nodelay(true);
        let shared = Arc::clone(&shared);
        let service = service_fn(move |req| {
            let shared = Arc::clone(&shared);
            async move { Ok::<_, Infallible>(answer(req, peer, &shared).await) }
        });
        let conn = graceful.watch(http.serve_connection(TokioIo::new(stream), service));
        tokio::spawn(async move {
            let _permit = permit; // the connection's place, given back when it closes
            let _ = conn.await;
        });
    }
    drop(listener);
    // Requests in progress finish; idle keep-alive connections close at once.
    let _ = tokio::time::timeout(Duration::from_secs(5), graceful.shutdown()).await;
    Ok(())
}

/// Answer one request (never fails: every problem is a 4xx/5xx with a message).
async fn answer(req: hyper::Request<Incoming>, peer: SocketAddr, shared: &Shared) -> hyper::Response<Full<Bytes>> {
    let arrived = Instant::now();
    let what = format!("{} {}", shown(req.method().as_str()), shown(req.uri().path()));
    let response = match read(req, shared).await {
        Err(e) => error_response(&e),
        // Pages, schemas and built-in data are cheap: answered at once.
        Ok(r) if r.method != "POST" => route(&r),
        Ok(r) => build(r, arrived, shared).await,
    };
    if response.status >= 400 {
        (shared.log)(&format!("{peer}: {what} -> {}", response.status));
    }
    to_hyper(response)
}

/// Check a request's host and content type, and receive its body within the
/// limits.
async fn read(req: hyper::Request<Incoming>, shared: &Shared) -> Result<Request, ApiError> {
    let limits = &shared.limits;
    let header = |name| req.headers().get(name).and_then(|v: &HeaderValue| v.to_str().ok());
    if !host_allowed(header(HOST), &shared.served, shared.machine.as_deref()) {
        return Err(ApiError::new(
            403,
            format!(
                "this server answers to its own address ({}), not to host {}",
                shared.served,
                garmentcode::message::quote(header(HOST).unwrap_or(""))
            ),
        ));
    }
    let path = percent_decode(req.uri().path()).ok_or_else(|| ApiError::bad("malformed percent-encoding in the path"))?;
    if req.method() == hyper::Method::POST {
        let mime = header(CONTENT_TYPE).map(|ct| ct.split(';').next().unwrap_or("").trim().to_ascii_lowercase());
        if mime.as_deref() != Some("application/json") {
            return Err(ApiError::new(
                415,
                format!(
                    "a POST body must be JSON sent with Content-Type: application/json (got {})",
                    mime.as_deref().map_or("none".into(), shown)
                ),
            ));
        }
    }
    let declared = header(CONTENT_LENGTH).and_then(|l| l.parse::<u64>().ok());
    if declared.is_some_and(|l| l > limits.max_body as u64) {
        return Err(too_large(limits));
    }
    let headers = req.headers().iter().filter_map(|(n, v)| Some((n.as_str().to_string(), v.to_str().ok()?.to_string()))).collect();
    let method = req.method().as_str().to_string();
    let body = Limited::new(req.into_body(), limits.max_body);
    let body = match tokio::time::timeout(limits.deadline, body.collect()).await {
        Err(_) => return Err(ApiError::new(408, format!("the request body was not received within {} s", limits.deadline.as_secs()))),
        Ok(Err(e)) if e.downcast_ref::<http_body_util::LengthLimitError>().is_some() => return Err(too_large(limits)),
        Ok(Err(e)) => return Err(ApiError::bad(format!("the request body could not be read: {e}"))),
        Ok(Ok(b)) => b.to_bytes().to_vec(),
    };
    Ok(Request { method, path, headers, body })
}

fn too_large(limits: &Limits) -> ApiError {
    ApiError::new(413, format!("the body is larger than the {} bytes accepted", limits.max_body))
}

/// Run a POST on the build pool: wait for a slot until the request's deadline
/// (cancelled if the connection fails meanwhile: this future is dropped), then
/// build on a blocking thread.
async fn build(r: Request, arrived: Instant, shared: &Shared) -> Response {
    let left = shared.limits.work_deadline.saturating_sub(arrived.elapsed());
    let busy = || error_response(&ApiError::new(503, "the server is busy building other garments; try again"));
    let Ok(Ok(slot)) = tokio::time::timeout(left, shared.builds.acquire()).await else {
        return busy();
    };
    let job = tokio::task::spawn_blocking(move || route(&r));
    let answer = job.await;
    drop(slot);
    answer.unwrap_or_else(|_| error_response(&ApiError::new(500, "internal error while building")))
}

fn to_hyper(r: Response) -> hyper::Response<Full<Bytes>> {
    let mut out = hyper::Response::new(Full::new(Bytes::from(r.body)));
    *out.status_mut() = hyper::StatusCode::from_u16(r.status).unwrap_or(hyper::StatusCode::INTERNAL_SERVER_ERROR);
    let h = out.headers_mut();
    h.insert(CONTENT_TYPE, HeaderValue::from_static(r.content_type));
    h.insert("cache-control", HeaderValue::from_static("no-store"));
    h.insert("x-content-type-options", HeaderValue::from_static("nosniff"));
    for (name, value) in r.headers {
        if let Ok(v) = HeaderValue::from_str(&value) {
            h.insert(name, v);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hosts_of_a_loopback_server() {
        let served: SocketAddr = "127.0.0.1:8000".parse().unwrap();
        for ok in
            [None, Some("localhost:8000"), Some("127.0.0.1:8000"), Some("[::1]:8000"), Some("LOCALHOST:8000"), Some("localhost.:8000")]
        {
            assert!(host_allowed(ok, &served, Some("box")), "{ok:?}");
        }
        for bad in [Some("evil.example:8000"), Some("box:8000"), Some("192.168.1.5:8000"), Some(""), Some("localhost.evil.example:8000")] {
            assert!(!host_allowed(bad, &served, Some("box")), "{bad:?}");
        }
    }

    /// The port must be the server's: a page served by another program on this
    /// machine (another port) cannot use it either.
    #[test]
    fn hosts_name_the_servers_port() {
        let served: SocketAddr = "127.0.0.1:8000".parse().unwrap();
        for bad in [
            "127.0.0.1",
            "localhost",
            "127.0.0.1:80",
            "127.0.0.1:8001",
            "localhost:9000",
            "[::1]:8001",
            "[::1]",
            "[::1]x",
            "127.0.0.1:",
            "127.0.0.1:+8000",
            "127.0.0.1:65536000",
            "[::1:8000",
        ] {
            assert!(!host_allowed(Some(bad), &served, Some("box")), "{bad}");
        }
        assert!(host_allowed(Some("127.0.0.1:08000"), &served, None), "the same number");
        // Without a port, a Host names port 80.
        let on_80: SocketAddr = "127.0.0.1:80".parse().unwrap();
        for ok in ["localhost", "127.0.0.1", "[::1]", "127.0.0.1:80"] {
            assert!(host_allowed(Some(ok), &on_80, None), "{ok}");
        }
        assert!(!host_allowed(Some("localhost:8000"), &on_80, None));
        let everywhere: SocketAddr = "0.0.0.0:8000".parse().unwrap();
        assert!(!host_allowed(Some("192.168.1.5:8001"), &everywhere, None));
        assert!(!host_allowed(Some("box"), &everywhere, Some("box")));
    }

    #[test]
    fn hosts_of_a_server_on_every_interface() {
        let served: SocketAddr = "0.0.0.0:8000".parse().unwrap();
        for ok in [Some("192.168.1.5:8000"), Some("box:8000"), Some("localhost:8000"), Some("[fe80::1]:8000")] {
            assert!(host_allowed(ok, &served, Some("box")), "{ok:?}");
        }
        assert!(!host_allowed(Some("rebind.evil.example:8000"), &served, Some("box")));
    }

    #[test]
    fn addresses_to_open() {
        assert_eq!(url(&"0.0.0.0:8000".parse().unwrap()), "http://127.0.0.1:8000/");
        assert_eq!(url(&"[::]:80".parse().unwrap()), "http://[::1]:80/");
        assert_eq!(url(&"127.0.0.1:8000".parse().unwrap()), "http://127.0.0.1:8000/");
    }
}
