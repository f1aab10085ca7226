//! Local profiling harness (not committed): the bench's design set, phase timings.
use garmentcode::params::{Sampler, read_design, sample_rng, write_design};
use garmentcode::{Arena, Body, Component, PartExt, Params};
use garments::Design;
use garments::meta::MetaGarment;
use std::time::Instant;


fn main() {
    let space = Design::design_space();
    let sampler = Sampler::new(space.clone());
    let bodies: Vec<Body> = garments::builtin::BODIES.iter().map(|(n, _)| garments::builtin::body(n).unwrap()).collect();
    let mut cases = Vec::new();
    let mut arena = Arena::new();
    for index in 0.. {
        if cases.len() == 300 { break; }
        let design: Design = sampler.sample(&mut sample_rng(2026, index));
        let body = bodies[index as usize % bodies.len()].clone();
        if let Ok(built) = garments::build::build_in(&mut arena, &design, &body, "design") {
            let ws = built.pattern.panels.iter().any(|p| p.name.contains("sleeve") || p.name.contains("hood"));
            cases.push((write_design(&design, &space), body, ws));
        }
    }
    let reps: usize = std::env::args().nth(1).map(|s| s.parse().unwrap()).unwrap_or(20);
    let only_nosleeve = std::env::args().nth(2).is_some_and(|s| s == "ns");
    let only_sleeve = std::env::args().nth(2).is_some_and(|s| s == "s");
    if std::env::args().nth(3).is_some_and(|s| s == "read") {
        let t0 = Instant::now();
        for _ in 0..reps {
            for (yaml, _, _) in &cases {
                let d: Design = read_design(yaml, "design.yaml", &space).unwrap();
                std::hint::black_box(d);
            }
        }
        println!("read only: {:.4} ms", t0.elapsed().as_secs_f64() / (reps * cases.len()) as f64 * 1e3);
        let t0 = Instant::now();
        for _ in 0..reps {
            for (yaml, _, _) in &cases {
                std::hint::black_box(garmentcode::yaml::parse(yaml).unwrap());
            }
        }
        println!("yaml parse only: {:.4} ms", t0.elapsed().as_secs_f64() / (reps * cases.len()) as f64 * 1e3);
        return;
    }
    if std::env::args().nth(3).is_some_and(|s| s == "sizes") {
        let mut sizes: Vec<usize> = cases.iter().map(|(yaml, body, _)| {
            let design: Design = read_design(yaml, "design.yaml", &space).unwrap();
            let p = garments::build::build_in(&mut arena, &design, body, "design").unwrap().pattern;
            let n: usize = p.panels.iter().map(|q| q.vertices.len() + q.edges.len() + 8).sum::<usize>() + p.stitches.len() * 2;
            let len = p.to_json().unwrap().len();
            eprintln!("ratio {:.1}", len as f64 / n as f64);
            len
        }).collect();
        sizes.sort();
        println!("json sizes: min {} median {} max {}", sizes[0], sizes[sizes.len() / 2], sizes[sizes.len() - 1]);
        return;
    }
    let mut best = [f64::INFINITY; 6];
    let mut n = 0usize;
    for _ in 0..reps {
        let mut t = [0f64; 6];
        n = 0;
        for (yaml, body, ws) in &cases {
            if only_nosleeve && *ws { continue; }
            if only_sleeve && !*ws { continue; }
            n += 1;
            let t0 = Instant::now();
            let design: Design = read_design(yaml, "design.yaml", &space).unwrap();
            let t1 = Instant::now();
            arena.clear();
            let g = MetaGarment::new(&mut arena, body, &design).unwrap();
            let t2 = Instant::now();
            let len = Component::length(&g, &arena);
            let t3 = Instant::now();
            let si = g.is_self_intersecting(&arena);
            let t4 = Instant::now();
            let p = g.assemble(&mut arena, "design").unwrap();
            let t5 = Instant::now();
            let j = p.to_json().unwrap();
            let t6 = Instant::now();
            std::hint::black_box((len, si, j));

            let ts = [t0, t1, t2, t3, t4, t5, t6];
            for k in 0..6 { t[k] += (ts[k + 1] - ts[k]).as_secs_f64(); }
        }
        for k in 0..6 { best[k] = best[k].min(t[k]); }
    }
    let t = best;
    let names = ["read", "new", "length", "selfint", "assemble", "json"];
    let mut tot = 0.0;
    for k in 0..6 { println!("{:>10} {:8.4} ms", names[k], t[k] / n as f64 * 1e3); tot += t[k]; }
    println!("{:>10} {:8.4} ms", "total", tot / n as f64 * 1e3);
}
#[allow(dead_code)]
fn json_sizes() {}
