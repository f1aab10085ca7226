//! Server-side cost of one change in the web configurator: the request the page
//! sends when a control moves (every design value, the body's measurements) goes
//! through the API's router to the response the page receives (drawing,
//! `specification.json`, checks), on one thread, without sockets.
//!
//! The fixed set: designs sampled from the default design space (seed 2026, the
//! five built-in bodies in turn) that the library builds, as the page would send
//! them, plus a share of designs the library refuses (answered with the reason).
//!
//! `cargo bench --bench web` prints divan's figures for the whole set, then the
//! distribution of single requests over several rounds (p50, p90, p99, worst),
//! against the target p99 < 5 ms.

use std::sync::OnceLock;
use std::time::Instant;

use garmentcode::{DesignSpace, Params, Sampler, Value, sample_rng};
use garmentcode_cli::web::api::{body_json, route};
use garmentcode_cli::web::http::Request;
use garments::Design;
use serde_json::{Map, Value as Json, json};

const BUILDABLE: usize = 200;
const SEED: u64 = 2026;
const ROUNDS: usize = 5;
const TARGET_P99_MS: f64 = 5.0;

fn space() -> &'static DesignSpace {
    static SPACE: OnceLock<DesignSpace> = OnceLock::new();
    SPACE.get_or_init(Design::design_space)
}

fn value_json(v: &Value) -> Json {
    match v {
        Value::Null => Json::Null,
        Value::Bool(b) => json!(b),
        Value::Int(i) => json!(i),
        Value::Float(f) => json!(f),
        Value::Str(s) => json!(s),
    }
}

/// Requests as the page sends them: (request, whether the library builds it).
fn requests() -> &'static [(Request, bool)] {
    static SET: OnceLock<Vec<(Request, bool)>> = OnceLock::new();
    SET.get_or_init(|| {
        let sampler = Sampler::new(space().clone());
        let bodies: Vec<(&str, Json)> = garments::builtin::BODIES
            .iter()
            .map(|(n, _)| (*n, body_json(n, &garments::builtin::body(n).expect("built-in body"))["measurements"].clone()))
            .collect();
        let mut out = Vec::new();
        let mut built = 0;
        for index in 0.. {
            if built == BUILDABLE {
                break;
            }
            let values = sampler.sample_values(&mut sample_rng(SEED, index));
            let design: Map<String, Json> = values.iter().map(|(p, v)| (p.clone(), value_json(v))).collect();
            let (name, measurements) = &bodies[index as usize % bodies.len()];
            let body = json!({ "design": design, "body": { "base": name, "name": name, "measurements": measurements }, "name": "random" });
            let req = Request {
                method: "POST".into(),
                path: "/api/pattern".into(),
                headers: vec![("content-type".into(), "application/json".into())],
                body: body.to_string().into_bytes(),
            };
            let response = route(&req);
            assert_eq!(response.status, 200, "{}", String::from_utf8_lossy(&response.body));
            let ok = response.body.starts_with(b"{\"ok\":true");
            built += usize::from(ok);
            out.push((req, ok));
        }
        out
    })
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn page_change_requests(bencher: divan::Bencher) {
    let set = requests();
    bencher.counter(divan::counter::ItemsCount::new(set.len())).bench_local(|| set.iter().map(|(r, _)| route(r).body.len()).sum::<usize>());
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

fn summary(label: &str, mut ms: Vec<f64>) -> f64 {
    ms.sort_by(f64::total_cmp);
    let p99 = percentile(&ms, 0.99);
    println!(
        "{label:<28} {:>5} requests  p50 {:>6.3} ms  p90 {:>6.3} ms  p99 {:>6.3} ms  worst {:>6.3} ms",
        ms.len(),
        percentile(&ms, 0.5),
        percentile(&ms, 0.9),
        p99,
        ms.last().copied().unwrap_or(0.0)
    );
    p99
}

fn main() {
    divan::main();
    if !std::env::args().any(|a| a == "--bench") {
        return; // under `cargo test` the harness runs each benchmark once
    }
    let set = requests();
    let mut built = Vec::new();
    let mut refused = Vec::new();
    for _ in 0..ROUNDS {
        for (req, ok) in set {
            let start = Instant::now();
            std::hint::black_box(route(req));
            let ms = start.elapsed().as_secs_f64() * 1e3;
            if *ok { built.push(ms) } else { refused.push(ms) }
        }
    }
    println!();
    println!("One page change, request JSON to response JSON, one thread ({ROUNDS} rounds over the set):");
    let mut all = built.clone();
    all.extend_from_slice(&refused);
    let p99 = summary("all requests", all);
    summary("designs that build", built);
    if !refused.is_empty() {
        summary("designs the library refuses", refused);
    }
    println!("target p99 < {TARGET_P99_MS} ms: {}", if p99 < TARGET_P99_MS { "met" } else { "NOT met" });
}
