//! The server's view of HTTP, independent of the HTTP stack: a request as the API
//! reads it, a response as it writes it, and the limits the server enforces. The
//! protocol itself (parsing, keep-alive, chunked bodies) is hyper's, in
//! [`server`](super::server).

use std::time::Duration;

/// Size, time and concurrency limits of the server.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Request line and headers together, bytes (431 beyond).
    pub max_head: usize,
    /// Body, bytes (413 beyond).
    pub max_body: usize,
    /// Time to receive a request's headers, and then its body (408 beyond; an
    /// idle keep-alive connection is closed after it too).
    pub deadline: Duration,
    /// Time from a request's arrival to its answer, waiting for a build slot
    /// included: a request still waiting then is cancelled (503) and its build
    /// never starts.
    pub work_deadline: Duration,
    /// Open connections at once; beyond, new ones get an immediate 503.
    pub max_connections: usize,
    /// Builds (POST requests) running at once, independent of connections.
    pub max_builds: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_head: 16 * 1024,
            max_body: 2 * 1024 * 1024,
            deadline: Duration::from_secs(10),
            work_deadline: Duration::from_secs(20),
            max_connections: 1024,
            max_builds: std::thread::available_parallelism().map(|n| n.get()).unwrap_or(2),
        }
    }
}

/// A parsed request.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// Method, as sent (`GET`, `POST`, ...).
    pub method: String,
    /// Percent-decoded path, without the query string.
    pub path: String,
    /// Header names (lower case) and values, in order.
    pub headers: Vec<(String, String)>,
    /// The body (empty without `Content-Length`).
    pub body: Vec<u8>,
}

impl Request {
    /// The first header of this (lower-case) name.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers.iter().find(|(n, _)| n == name).map(|(_, v)| v.as_str())
    }
}

/// A response about to be written.
#[derive(Clone, Debug, PartialEq)]
pub struct Response {
    /// Status code.
    pub status: u16,
    /// `Content-Type`.
    pub content_type: &'static str,
    /// Extra headers (`Content-Disposition`, `Allow`).
    pub headers: Vec<(&'static str, String)>,
    /// The body.
    pub body: Vec<u8>,
}

/// The reason phrase of a status code.
pub fn reason(status: u16) -> &'static str {
    match status {
        100 => "Continue",
        200 => "OK",
        204 => "No Content",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        411 => "Length Required",
        413 => "Content Too Large",
        415 => "Unsupported Media Type",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        503 => "Service Unavailable",
        501 => "Not Implemented",
        505 => "HTTP Version Not Supported",
        _ => "Unknown",
    }
}

/// Decode `%XX` escapes; `None` for malformed escapes or a result that is not UTF-8.
pub fn percent_decode(s: &str) -> Option<String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = std::str::from_utf8(b.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decoded_paths() {
        assert_eq!(percent_decode("/api/body/mean%5Fall").as_deref(), Some("/api/body/mean_all"));
        assert_eq!(percent_decode("/%zz"), None);
        assert_eq!(percent_decode("/%ff"), None, "not UTF-8");
    }

    #[test]
    fn every_status_the_server_sends_has_a_reason() {
        for s in [200, 400, 403, 404, 405, 408, 413, 415, 500, 503] {
            assert_ne!(reason(s), "Unknown", "{s}");
        }
    }
}
