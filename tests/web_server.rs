//! `garmentcode serve` over real sockets: it prints its address, answers the API,
//! refuses malformed, oversized and stalled requests with 4xx and a message, and
//! keeps serving afterwards.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The server process, stopped on drop.
struct Server {
    child: Child,
    addr: SocketAddr,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn start(args: &[&str]) -> Server {
    let mut child = Command::new(env!("CARGO_BIN_EXE_garmentcode"))
        .arg("serve")
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("start garmentcode serve");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).unwrap();
    let url = line.split_whitespace().find(|w| w.starts_with("http://")).unwrap_or_else(|| panic!("no address in {line:?}"));
    let hostport = url.trim_start_matches("http://").trim_end_matches('/');
    Server { child, addr: hostport.parse().unwrap_or_else(|e| panic!("{hostport}: {e}")) }
}

/// Send raw bytes, read the whole answer: (status, body).
fn raw(addr: SocketAddr, bytes: &[u8]) -> (u16, String) {
    let mut s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
    let _ = s.write_all(bytes);
    let mut out = Vec::new();
    let _ = s.read_to_end(&mut out);
    let text = String::from_utf8_lossy(&out).into_owned();
    let status = text.split(' ').nth(1).and_then(|c| c.parse().ok()).unwrap_or_else(|| panic!("no status in {text:?}"));
    let body = text.split_once("\r\n\r\n").map(|(_, b)| b.to_string()).unwrap_or_default();
    (status, body)
}

fn post(addr: SocketAddr, path: &str, json: &str) -> (u16, String) {
    raw(
        addr,
        format!("POST {path} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n{json}", json.len())
            .as_bytes(),
    )
}

fn get(addr: SocketAddr, path: &str) -> (u16, String) {
    raw(addr, format!("GET {path} HTTP/1.1\r\nHost: x\r\n\r\n").as_bytes())
}

fn still_serving(addr: SocketAddr) {
    let (status, body) = post(addr, "/api/pattern", r#"{"design": {"meta.upper": "Shirt"}}"#);
    assert_eq!(status, 200, "{body}");
    assert!(body.contains("\"ok\":true"));
}

#[test]
fn serves_the_page_and_the_api_on_loopback() {
    let s = start(&["--port", "0"]);
    assert!(s.addr.ip().is_loopback(), "loopback by default: {}", s.addr);
    let (status, html) = get(s.addr, "/");
    assert_eq!(status, 200);
    assert!(html.contains("<script src=\"/app.js\">"));
    for path in ["/app.js", "/style.css", "/api/schema", "/api/body/mean_all", "/api/design/t-shirt", "/api"] {
        assert_eq!(get(s.addr, path).0, 200, "{path}");
    }
    let (status, body) = raw(s.addr, b"HEAD /api/schema HTTP/1.1\r\n\r\n");
    assert_eq!((status, body.as_str()), (200, ""), "HEAD has headers only");
    still_serving(s.addr);
}

#[test]
fn bad_requests_get_4xx_and_the_server_keeps_serving() {
    let s = start(&["--port", "0"]);
    let mut huge_head = b"GET / HTTP/1.1\r\nX-Big: ".to_vec();
    huge_head.extend(std::iter::repeat_n(b'a', 64 * 1024));
    huge_head.extend_from_slice(b"\r\n\r\n");
    let mut huge_body =
        format!("POST /api/pattern HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n", 5 << 20).into_bytes();
    huge_body.extend(std::iter::repeat_n(b' ', 256 * 1024)); // starts sending 5 MiB
    let cases: Vec<(Vec<u8>, u16)> = vec![
        (b"\x00\x01\x02garbage\r\n\r\n".to_vec(), 400),
        (b"GET / HTTP/9.9\r\n\r\n".to_vec(), 505),
        (huge_head, 431),
        (huge_body, 413),
        (b"POST /api/pattern HTTP/1.1\r\nContent-Length: 99999999999\r\n\r\n".to_vec(), 413),
        (b"POST /api/pattern HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n".to_vec(), 501),
        (b"POST /api/pattern HTTP/1.1\r\n\r\n".to_vec(), 411),
        (b"POST /api/pattern HTTP/1.1\r\nContent-Length: 9\r\n\r\n{\"design\"".to_vec(), 400),
        (b"PUT /api/pattern HTTP/1.1\r\nContent-Length: 0\r\n\r\n".to_vec(), 405),
        (b"GET /../../etc/passwd HTTP/1.1\r\n\r\n".to_vec(), 404),
    ];
    for (bytes, expected) in cases {
        let (status, body) = raw(s.addr, &bytes);
        assert_eq!(status, expected, "{}: {body}", String::from_utf8_lossy(&bytes[..bytes.len().min(60)]));
        assert!(body.contains("\"error\""), "a message: {body}");
        still_serving(s.addr);
    }
    // Values outside their range name the parameter and the range.
    let (status, body) = post(s.addr, "/api/pattern", r#"{"design": {"sleeve.length": 7}}"#);
    assert_eq!(status, 400);
    assert!(body.contains("design.sleeve.length") && body.contains("[0.1, 1.15]"), "{body}");
    // A client that connects and sends nothing, or half a request, does not hold
    // up the others.
    let idle: Vec<TcpStream> = (0..6).map(|_| TcpStream::connect(s.addr).unwrap()).collect();
    let mut half = TcpStream::connect(s.addr).unwrap();
    half.write_all(b"POST /api/pattern HTTP/1.1\r\nContent-Length: 100\r\n\r\n{").unwrap();
    let t = Instant::now();
    still_serving(s.addr);
    assert!(t.elapsed() < Duration::from_secs(5), "answered while other clients stall");
    drop(idle);
    drop(half);
    // A client that hangs up mid-request.
    {
        let mut c = TcpStream::connect(s.addr).unwrap();
        c.write_all(b"POST /api/pattern HTTP/1.1\r\nContent-Length: 1000\r\n\r\n{\"des").unwrap();
    }
    still_serving(s.addr);
}

#[test]
fn host_and_port_options() {
    let s = start(&["--port", "0", "--host", "localhost"]);
    assert!(s.addr.ip().is_loopback());
    still_serving(s.addr);
    let o = Command::new(env!("CARGO_BIN_EXE_garmentcode")).args(["serve", "--port", "http"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--port"));
    // A port in use is an error that says what to do.
    let o = Command::new(env!("CARGO_BIN_EXE_garmentcode"))
        .args(["serve", "--port", &s.addr.port().to_string(), "--host", &s.addr.ip().to_string()])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--port 0"), "{}", String::from_utf8_lossy(&o.stderr));
}
