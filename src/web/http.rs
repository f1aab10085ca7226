//! Just enough HTTP/1.1 for a local configurator: one request per connection
//! (`Connection: close`), a request line, headers and a `Content-Length` body, with
//! strict limits so that a malformed, oversized or stalled request costs little and
//! gets a 4xx answer with a message.
//!
//! Browsers and `curl` speak this subset; chunked request bodies, keep-alive and
//! pipelining are not needed for one page and a JSON API, so they are refused or
//! ignored rather than half-supported.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

/// Size and time limits of one request.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Request line and headers together, bytes (431 beyond).
    pub max_head: usize,
    /// Body, bytes (413 beyond).
    pub max_body: usize,
    /// Time to receive the whole request (408 beyond).
    pub deadline: Duration,
}

impl Default for Limits {
    fn default() -> Self {
        Limits { max_head: 16 * 1024, max_body: 2 * 1024 * 1024, deadline: Duration::from_secs(10) }
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

/// A request that cannot be served: the status and a message for the client.
#[derive(Clone, Debug, PartialEq)]
pub struct HttpError {
    /// 4xx/5xx status.
    pub status: u16,
    /// What is wrong, in words.
    pub message: String,
}

fn fail(status: u16, message: impl Into<String>) -> HttpError {
    HttpError { status, message: message.into() }
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

/// A stream with a read deadline: every read waits at most until the deadline.
pub trait Timed: Read + Write {
    /// Set the timeout of the next reads (`None` never happens here).
    fn set_timeout(&mut self, t: Duration) -> std::io::Result<()>;
}

impl Timed for std::net::TcpStream {
    fn set_timeout(&mut self, t: Duration) -> std::io::Result<()> {
        self.set_read_timeout(Some(t))
    }
}

/// Read one request from `stream` within `limits`. Answers `100 Continue` to a
/// client that waits for it (curl does for bodies over 1 KiB).
pub fn read_request(stream: &mut impl Timed, limits: &Limits) -> Result<Request, HttpError> {
    let start = Instant::now();
    let mut buf: Vec<u8> = Vec::with_capacity(4096);
    let mut chunk = [0u8; 8192];
    // Head: up to the blank line.
    let head_end = loop {
        if let Some(i) = find(&buf, b"\r\n\r\n") {
            break i;
        }
        if buf.len() > limits.max_head {
            return Err(fail(431, format!("request line and headers exceed {} bytes", limits.max_head)));
        }
        let n = read_some(stream, &mut chunk, start, limits)?;
        if n == 0 {
            return Err(fail(400, "connection closed before the end of the headers"));
        }
        buf.extend_from_slice(&chunk[..n]);
    };
    if head_end > limits.max_head {
        return Err(fail(431, format!("request line and headers exceed {} bytes", limits.max_head)));
    }
    let head = std::str::from_utf8(&buf[..head_end]).map_err(|_| fail(400, "headers are not UTF-8"))?;
    let mut lines = head.split("\r\n");
    let request_line = lines.next().unwrap_or("");
    let mut parts = request_line.split(' ');
    let (Some(method), Some(target), Some(version), None) = (parts.next(), parts.next(), parts.next(), parts.next()) else {
        return Err(fail(400, "malformed request line (expected METHOD /path HTTP/1.1)"));
    };
    if method.is_empty() || !method.bytes().all(|b| b.is_ascii_uppercase()) {
        return Err(fail(400, format!("malformed method {method:?}")));
    }
    if !version.starts_with("HTTP/") {
        return Err(fail(400, "malformed request line (expected METHOD /path HTTP/1.1)"));
    }
    if version != "HTTP/1.1" && version != "HTTP/1.0" {
        return Err(fail(505, format!("{version} is not supported; use HTTP/1.1")));
    }
    if !target.starts_with('/') {
        return Err(fail(400, "the request target must be a path starting with /"));
    }
    let raw_path = target.split(['?', '#']).next().unwrap_or("/");
    let path = percent_decode(raw_path).ok_or_else(|| fail(400, "malformed percent-encoding in the path"))?;
    let mut headers = Vec::new();
    for line in lines {
        let Some((name, value)) = line.split_once(':') else {
            return Err(fail(400, format!("malformed header line {:?}", truncate(line, 60))));
        };
        if name.is_empty() || !name.bytes().all(|b| b.is_ascii_alphanumeric() || b"!#$%&'*+-.^_`|~".contains(&b)) {
            return Err(fail(400, format!("malformed header name {:?}", truncate(name, 60))));
        }
        headers.push((name.to_ascii_lowercase(), value.trim().to_string()));
    }
    let mut request = Request { method: method.to_string(), path, headers, body: Vec::new() };
    if request.header("transfer-encoding").is_some() {
        return Err(fail(501, "chunked request bodies are not supported; send a Content-Length"));
    }
    let mut length: Option<usize> = None;
    for (n, v) in &request.headers {
        if n == "content-length" {
            let l: usize = v.parse().map_err(|_| fail(400, format!("malformed Content-Length {:?}", truncate(v, 30))))?;
            if length.is_some_and(|x| x != l) {
                return Err(fail(400, "conflicting Content-Length headers"));
            }
            length = Some(l);
        }
    }
    let length = match length {
        Some(l) => l,
        None if request.method == "POST" || request.method == "PUT" => {
            return Err(fail(411, "a POST needs a Content-Length header"));
        }
        None => 0,
    };
    if length > limits.max_body {
        return Err(fail(413, format!("the body has {length} bytes; at most {} are accepted", limits.max_body)));
    }
    let mut body = buf.split_off(head_end + 4);
    if body.len() < length && request.header("expect").is_some_and(|e| e.eq_ignore_ascii_case("100-continue")) {
        let _ = stream.write_all(b"HTTP/1.1 100 Continue\r\n\r\n");
    }
    while body.len() < length {
        let n = read_some(stream, &mut chunk, start, limits)?;
        if n == 0 {
            return Err(fail(400, format!("connection closed after {} of {length} body bytes", body.len())));
        }
        body.extend_from_slice(&chunk[..n]);
    }
    body.truncate(length); // no pipelining: anything after the body is ignored
    request.body = body;
    Ok(request)
}

fn read_some(stream: &mut impl Timed, chunk: &mut [u8], start: Instant, limits: &Limits) -> Result<usize, HttpError> {
    let timeout = || fail(408, format!("the request was not received within {} s", limits.deadline.as_secs()));
    let left = limits.deadline.checked_sub(start.elapsed()).filter(|d| !d.is_zero()).ok_or_else(timeout)?;
    stream.set_timeout(left).map_err(|e| fail(400, format!("connection error: {e}")))?;
    loop {
        match stream.read(chunk) {
            Ok(n) => return Ok(n),
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) if matches!(e.kind(), std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut) => return Err(timeout()),
            Err(e) => return Err(fail(400, format!("connection error: {e}"))),
        }
    }
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

fn truncate(s: &str, n: usize) -> String {
    s.chars().take(n).collect()
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

/// Write `response` with `Content-Length` and `Connection: close`; `head_only`
/// leaves out the body (HEAD requests).
pub fn write_response(stream: &mut impl Write, response: &Response, head_only: bool) -> std::io::Result<()> {
    let mut head = format!(
        "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nConnection: close\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n",
        response.status,
        reason(response.status),
        response.content_type,
        response.body.len()
    );
    for (n, v) in &response.headers {
        head.push_str(n);
        head.push_str(": ");
        head.push_str(v);
        head.push_str("\r\n");
    }
    head.push_str("\r\n");
    stream.write_all(head.as_bytes())?;
    if !head_only {
        stream.write_all(&response.body)?;
    }
    stream.flush()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    /// An in-memory stream: reads from `input`, collects writes.
    struct Mem {
        input: Cursor<Vec<u8>>,
        output: Vec<u8>,
    }

    impl Read for Mem {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            self.input.read(buf)
        }
    }
    impl Write for Mem {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.output.extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }
    impl Timed for Mem {
        fn set_timeout(&mut self, _: Duration) -> std::io::Result<()> {
            Ok(())
        }
    }

    fn parse(raw: &[u8]) -> Result<Request, HttpError> {
        let mut m = Mem { input: Cursor::new(raw.to_vec()), output: Vec::new() };
        read_request(&mut m, &Limits { max_head: 256, max_body: 64, deadline: Duration::from_secs(5) })
    }

    #[test]
    fn a_post_with_a_body() {
        let r = parse(b"POST /api/pattern?x=1 HTTP/1.1\r\nHost: a\r\nContent-Length: 5\r\n\r\nhello-extra").unwrap();
        assert_eq!(r.method, "POST");
        assert_eq!(r.path, "/api/pattern");
        assert_eq!(r.header("host"), Some("a"));
        assert_eq!(r.body, b"hello");
    }

    #[test]
    fn decoded_paths() {
        assert_eq!(parse(b"GET /api/body/mean%5Fall HTTP/1.1\r\n\r\n").unwrap().path, "/api/body/mean_all");
        assert_eq!(parse(b"GET /%zz HTTP/1.1\r\n\r\n").unwrap_err().status, 400);
    }

    #[test]
    fn malformed_and_oversized_requests_get_their_status() {
        let cases: &[(&[u8], u16)] = &[
            (b"garbage\r\n\r\n", 400),
            (b"GET / HTTP/2\r\n\r\n", 505),
            (b"get / HTTP/1.1\r\n\r\n", 400),
            (b"GET http://x/ HTTP/1.1\r\n\r\n", 400),
            (b"GET / HTTP/1.1\r\nno colon\r\n\r\n", 400),
            (b"GET / HTTP/1.1\r\nContent-Length: x\r\n\r\n", 400),
            (b"POST / HTTP/1.1\r\n\r\n", 411),
            (b"POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 501),
            (b"POST / HTTP/1.1\r\nContent-Length: 65\r\n\r\n", 413),
            (b"POST / HTTP/1.1\r\nContent-Length: 10\r\n\r\nshort", 400),
            (b"GET / HTTP/1.1\r\nHost: a", 400),
            (b"POST / HTTP/1.1\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\nab", 400),
        ];
        for (raw, status) in cases {
            let e = parse(raw).unwrap_err();
            assert_eq!(e.status, *status, "{}: {}", String::from_utf8_lossy(raw), e.message);
            assert!(!e.message.is_empty());
        }
        let mut long = b"GET / HTTP/1.1\r\nX: ".to_vec();
        long.extend(std::iter::repeat_n(b'a', 400));
        long.extend_from_slice(b"\r\n\r\n");
        assert_eq!(parse(&long).unwrap_err().status, 431);
    }

    #[test]
    fn continue_is_sent_when_asked() {
        let mut m = Mem {
            input: Cursor::new(b"POST / HTTP/1.1\r\nExpect: 100-continue\r\nContent-Length: 2\r\n\r\n".to_vec()),
            output: Vec::new(),
        };
        // The body never comes: the request fails, but the client was told to send it.
        assert!(read_request(&mut m, &Limits::default()).is_err());
        assert!(m.output.starts_with(b"HTTP/1.1 100 Continue"));
    }

    #[test]
    fn responses_carry_length_and_close() {
        let mut out = Vec::new();
        let r = Response { status: 404, content_type: "application/json", headers: vec![("Allow", "GET".into())], body: b"{}".to_vec() };
        write_response(&mut out, &r, false).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("HTTP/1.1 404 Not Found\r\n"));
        assert!(text.contains("Content-Length: 2\r\n"));
        assert!(text.contains("Connection: close\r\n"));
        assert!(text.contains("Allow: GET\r\n"));
        assert!(text.ends_with("\r\n\r\n{}"));
    }
}
