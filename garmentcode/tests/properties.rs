//! Property tests of the geometry: many random edges, panels and interfaces drawn
//! from a fixed-seed generator (so failures reproduce), each checked for an
//! invariant the runtime promises.

use garmentcode::curves::cy_from_three_points;
use garmentcode::math::{abs_to_rel, rel_to_abs};
use garmentcode::{Arena, Curve, Edge, EdgeSeq, Gather, PanelId, Rotation, StitchRule, Vec2, Vec3};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{RngCore, SeedableRng};

const CASES: usize = 300;

struct Gen(ChaCha8Rng);

impl Gen {
    fn new(seed: u64) -> Gen {
        Gen(ChaCha8Rng::seed_from_u64(seed))
    }
    /// Uniform in `[lo, hi)`.
    fn f(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + u * (hi - lo)
    }
    fn usize(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.0.next_u64() % (hi - lo + 1) as u64) as usize
    }
    fn point(&mut self, r: f64) -> Vec2 {
        Vec2::new(self.f(-r, r), self.f(-r, r))
    }
    /// A random edge of any kind, at least 5 cm long chord.
    fn edge(&mut self) -> Edge {
        let start = self.point(50.0);
        let end = loop {
            let e = self.point(50.0);
            if (e - start).length() > 5.0 {
                break e;
            }
        };
        let curve = match self.usize(0, 3) {
            0 => Curve::Line,
            1 => Curve::Arc { cy: self.f(-0.9, 0.9) },
            2 => Curve::Quadratic(Vec2::new(self.f(-0.2, 1.2), self.f(-0.8, 0.8))),
            _ => Curve::Cubic(Vec2::new(self.f(-0.2, 0.6), self.f(-0.6, 0.6)), Vec2::new(self.f(0.4, 1.2), self.f(-0.6, 0.6))),
        };
        Edge { start, end, curve }
    }
    /// Fractions in (0, 1) summing to one.
    fn fractions(&mut self, n: usize) -> Vec<f64> {
        let raw: Vec<f64> = (0..n).map(|_| self.f(0.2, 1.0)).collect();
        let sum: f64 = raw.iter().sum();
        raw.iter().map(|x| x / sum).collect()
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
}

fn close_v(a: Vec2, b: Vec2, tol: f64) -> bool {
    (a - b).length() <= tol * (1.0 + a.length().max(b.length()))
}

#[test]
fn relative_and_absolute_control_points_round_trip() {
    let mut g = Gen::new(1);
    for _ in 0..CASES {
        let e = g.edge();
        // Point conversions.
        let p = g.point(80.0);
        assert!(close_v(rel_to_abs(e.start, e.end, abs_to_rel(e.start, e.end, p)), p, 1e-12));
        assert!(close_v(e.to_abs(e.to_rel(p)), p, 1e-12));
        // The relative frame: (0,0) is the start, (1,0) the end, (0,1) to the left.
        assert!(close_v(e.to_abs(Vec2::ZERO), e.start, 1e-12));
        assert!(close_v(e.to_abs(Vec2::X), e.end, 1e-12));
        let chord = e.end - e.start;
        assert!(close_v(e.to_abs(Vec2::Y) - e.start, Vec2::new(-chord.y, chord.x), 1e-12));
        // Absolute control points read back into the same relative ones.
        let abs = e.abs_controls();
        let rel: Vec<Vec2> = abs.iter().map(|&c| e.to_rel(c)).collect();
        match e.curve {
            Curve::Quadratic(c) => assert!(close_v(rel[0], c, 1e-12)),
            Curve::Cubic(c1, c2) => assert!(close_v(rel[0], c1, 1e-12) && close_v(rel[1], c2, 1e-12)),
            _ => {}
        }
    }
}

#[test]
fn arc_through_three_points_passes_through_them() {
    let mut g = Gen::new(2);
    for _ in 0..CASES {
        let (s, t) = (g.point(40.0), g.point(40.0));
        if (s - t).length() < 5.0 {
            continue;
        }
        // A point well off the chord, between its ends.
        let along = g.f(0.2, 0.8);
        let off = g.f(2.0, 20.0) * if g.usize(0, 1) == 0 { 1.0 } else { -1.0 };
        let p = rel_to_abs(s, t, Vec2::new(along, off / (t - s).length()));
        let e = Edge { start: s, end: t, curve: Curve::Arc { cy: cy_from_three_points(s, t, p) } };
        let pts = e.linearize(4000);
        let nearest = pts.iter().map(|q| (*q - p).length()).fold(f64::INFINITY, f64::min);
        assert!(nearest < 0.05, "{p} is {nearest} cm from the arc {e:?}");
    }
}

#[test]
fn reversal_keeps_shape_and_length() {
    let mut g = Gen::new(3);
    for _ in 0..CASES {
        let e = g.edge();
        let r = e.reversed();
        assert_eq!((r.start, r.end), (e.end, e.start));
        assert!(close(r.length(), e.length(), 1e-9));
        for t in [0.0, 0.13, 0.5, 0.77, 1.0] {
            assert!(close_v(r.point(1.0 - t), e.point(t), 1e-9), "{e:?} at {t}");
        }
        let rr = r.reversed();
        assert!(close_v(rr.start, e.start, 0.0) && close_v(rr.end, e.end, 0.0));
        match (rr.curve, e.curve) {
            (Curve::Arc { cy: a }, Curve::Arc { cy: b }) => assert!(close(a, b, 1e-15)),
            (Curve::Quadratic(a), Curve::Quadratic(b)) => assert!(close_v(a, b, 1e-15)),
            (Curve::Cubic(a1, a2), Curve::Cubic(b1, b2)) => assert!(close_v(a1, b1, 1e-15) && close_v(a2, b2, 1e-15)),
            (Curve::Line, Curve::Line) => {}
            other => panic!("kind changed: {other:?}"),
        }
    }
}

#[test]
fn subdivision_keeps_length_and_shape() {
    let mut g = Gen::new(4);
    for _ in 0..CASES {
        let e = g.edge();
        let n = g.usize(2, 5);
        let fr = g.fractions(n);
        for by_length in [true, false] {
            let pieces = e.split(&fr, by_length);
            assert_eq!(pieces.len(), n);
            assert!(close_v(pieces[0].start, e.start, 1e-12) && close_v(pieces[n - 1].end, e.end, 1e-9));
            for w in pieces.windows(2) {
                assert!(close_v(w[0].end, w[1].start, 1e-12), "pieces chain");
            }
            let total: f64 = pieces.iter().map(Edge::length).sum();
            assert!(close(total, e.length(), 1e-6), "{e:?}: {total} vs {}", e.length());
            if by_length {
                for (p, f) in pieces.iter().zip(&fr) {
                    assert!(close(p.length(), f * e.length(), 1e-5), "piece {} vs {}", p.length(), f * e.length());
                }
            }
            // Every piece's midpoint lies on the original curve.
            let dense = e.linearize(3000);
            for p in &pieces {
                let m = p.point(0.5);
                let d = dense.iter().map(|q| (*q - m).length()).fold(f64::INFINITY, f64::min);
                assert!(d < 0.1, "{e:?}: piece midpoint {d} cm off the curve");
            }
        }
    }
}

#[test]
fn arena_subdivision_keeps_the_loop_and_its_length() {
    let mut g = Gen::new(5);
    for _ in 0..50 {
        let mut a = Arena::new();
        let pts: Vec<Vec2> = (0..g.usize(3, 6))
            .map(|i| {
                let ang = i as f64 * 1.0;
                Vec2::new(ang.cos(), ang.sin()) * g.f(20.0, 40.0)
            })
            .collect();
        let mut s = EdgeSeq::from_points(&mut a, &pts, true).unwrap();
        let before = s.length(&a);
        let i = g.usize(0, s.len() - 1);
        let e = s[i];
        let fr = g.fractions(3);
        let pieces = a.subdivide(e, &fr, true).unwrap();
        s.substitute(e, &pieces).unwrap();
        assert!(s.is_loop(&a));
        assert!(close(s.length(&a), before, 1e-9));
    }
}

/// A random star-shaped panel, placed somewhere.
fn random_panel(g: &mut Gen, a: &mut Arena, name: &str) -> PanelId {
    let n = g.usize(3, 7);
    let pts: Vec<Vec2> = (0..n)
        .map(|i| {
            let ang = i as f64 / n as f64 * std::f64::consts::TAU;
            Vec2::new(ang.cos(), ang.sin()) * g.f(15.0, 40.0)
        })
        .collect();
    let s = EdgeSeq::from_points(a, &pts, true).unwrap();
    for &e in s.iter() {
        if g.usize(0, 2) == 0 {
            a.set_curve(e, Curve::Quadratic(Vec2::new(0.5, g.f(-0.2, 0.2))));
        }
    }
    let p = a.panel_with_edges(name, s);
    p.translate_to(a, Vec3::new(g.f(-50.0, 50.0), g.f(0.0, 150.0), g.f(-30.0, 30.0)));
    p.rotate_by(a, Rotation::from_euler_xyz_degrees([g.f(-30.0, 30.0), g.f(-180.0, 180.0), g.f(-30.0, 30.0)]));
    p
}

#[test]
fn mirroring_twice_is_identity() {
    let mut g = Gen::new(6);
    for k in 0..CASES {
        let mut a = Arena::new();
        let p = random_panel(&mut g, &mut a, &format!("p{k}"));
        let verts = |a: &Arena| p.edges(a).vert_positions(a);
        let curves = |a: &Arena| p.edges(a).iter().map(|&e| a.curve(e)).collect::<Vec<_>>();
        let (v0, c0, t0, r0) = (verts(&a), curves(&a), p.translation(&a), p.rotation(&a));
        let n0 = p.norm(&a);
        p.mirror(&mut a);
        let n1 = p.norm(&a);
        assert!((n1 - Vec3::new(-n0.x, n0.y, n0.z)).length() < 1e-9, "the normal is mirrored: {n0} → {n1}");
        p.mirror(&mut a);
        let (v2, c2, t2, r2) = (verts(&a), curves(&a), p.translation(&a), p.rotation(&a));
        assert!((t2 - t0).length() < 1e-9);
        let (m0, m2) = (r0.matrix(), r2.matrix());
        assert!((m0 - m2).to_cols_array().iter().all(|d| d.abs() < 1e-9), "rotation {m0} vs {m2}");
        assert_eq!(v2.len(), v0.len());
        for (x, y) in v0.iter().zip(&v2) {
            assert!(close_v(*x, *y, 1e-9));
        }
        assert_eq!(c0, c2);
    }
}

/// Flattening an abstract stitch splits edges but keeps each side's total length
/// and gives both sides the same number of edges with matching (gather-scaled)
/// length fractions.
#[test]
fn stitch_flattening_keeps_interface_lengths() {
    let mut g = Gen::new(7);
    for k in 0..CASES {
        let mut a = Arena::new();
        let side = |a: &mut Arena, name: &str, g: &mut Gen| {
            // An open chain of random segments along x, closed into a panel below.
            let n = g.usize(1, 5);
            let mut pts = vec![Vec2::ZERO];
            for _ in 0..n {
                let last = *pts.last().unwrap();
                pts.push(last + Vec2::new(g.f(3.0, 20.0), g.f(-2.0, 2.0)));
            }
            let top = EdgeSeq::from_points(a, &pts, false).unwrap();
            let (first, last) = (a.start(top[0]), a.end(top.last_edge()));
            let (fp, lp) = (a.pos(first), a.pos(last));
            let low_r = a.vertex(lp - Vec2::new(0.0, 30.0));
            let low_l = a.vertex(fp - Vec2::new(0.0, 30.0));
            let mut loop_edges = top.clone();
            loop_edges.extend(EdgeSeq::polyline(a, &[last, low_r, low_l, first], false).unwrap().iter().copied());
            let p = a.panel_with_edges(name, loop_edges);
            (p, top)
        };
        let (pa, ta) = side(&mut a, &format!("a{k}"), &mut g);
        let (pb, tb) = side(&mut a, &format!("b{k}"), &mut g);
        let gather = if g.usize(0, 1) == 0 { 1.0 } else { g.f(1.0, 2.0) };
        let ia = a.interface_gathered(pa, ta.clone(), Gather::Uniform(gather)).unwrap();
        let ib = a.interface(pb, tb.clone());
        let (la, lb) = (ia.length(&a), ib.length(&a));
        let rule = StitchRule::new(&mut a, ia, ib).unwrap();
        assert!(close(ia.length(&a), la, 1e-9) && close(ib.length(&a), lb, 1e-9), "lengths kept");
        assert_eq!(ia.len(&a), ib.len(&a), "one edge on each side per stitch");
        assert!(rule.is_matching(&a));
        let (fa, fb) = (ia.projecting_fractions(&a), ib.projecting_fractions(&a));
        for (x, y) in fa.iter().zip(&fb) {
            assert!((x - y).abs() < 0.05, "fractions {fa:?} vs {fb:?}");
        }
        // The panels stay closed loops whose length did not change.
        for p in [pa, pb] {
            assert!(p.edges(&a).is_loop(&a));
        }
    }
}
