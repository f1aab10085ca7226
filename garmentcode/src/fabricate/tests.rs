//! Properties of the printable pattern over every reference case.

use super::geom::{self, Rect};
use super::sheet::{self, Prim};
use super::*;
use crate::math::Vec2;
use crate::test_data::cases;

#[path = "../../tests/support/ezdxf.rs"]
mod ezdxf;

fn opts(name: &str) -> PrintOptions {
    PrintOptions { garment: name.into(), size: "mean_all".into(), ..Default::default() }
}

/// Panels whose outline crosses itself (the reference makes a few): their cut
/// lines cannot be checked against the sew line.
fn crossing(p: &Pattern) -> Vec<String> {
    crate::validate(p).into_iter().filter(|x| x.kind == crate::ProblemKind::SelfIntersection).filter_map(|x| x.panel).collect()
}

/// Tolerance of the geometric checks (cm): 0.1 mm.
const TOL: f64 = 0.01;

/// Points of an exact edge, densely.
fn edge_samples(e: &crate::Edge, n: usize) -> Vec<Vec2> {
    let seg = e.segment();
    (0..=n).map(|i| seg.point(i as f64 / n as f64)).collect()
}

/// A closed polyline that does not cross itself.
fn is_simple(p: &[Vec2]) -> bool {
    let n = p.len();
    for i in 0..n {
        for j in i + 2..n {
            if (j + 1) % n == i {
                continue;
            }
            let (a0, a1, b0, b1) = (p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]);
            let (r, s) = (a1 - a0, b1 - b0);
            let den = r.perp_dot(s);
            if den.abs() < 1e-12 {
                continue;
            }
            let q = b0 - a0;
            let (t, u) = (q.perp_dot(s) / den, q.perp_dot(r) / den);
            if (1e-9..1.0 - 1e-9).contains(&t) && (1e-9..1.0 - 1e-9).contains(&u) {
                return false;
            }
        }
    }
    true
}

#[test]
fn seam_allowance_encloses_the_sew_line_at_the_requested_distance() {
    let (mut checked, mut skipped) = (0, 0);
    for (name, p) in cases() {
        let bad = crossing(&p);
        for seam in [1.0, 1.5] {
            let o = PrintOptions { seam, ..opts(&name) };
            let pieces = pieces(&p, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
            for pc in &pieces {
                if pc.panels.iter().any(|(n, _)| bad.contains(n)) {
                    skipped += 1;
                    continue;
                }
                let cut = &pc.cut_line;
                assert!(is_simple(cut), "{name}/{}: the cut line crosses itself", pc.name);
                assert!(geom::signed_area(cut).abs() > geom::signed_area(&pc.sew).abs(), "{name}/{}", pc.name);
                // Along a fold the allowance of the edges meeting it stops at the fold line.
                let near_fold = |q: Vec2| pc.fold.is_some_and(|[a, _]| (q.x - a.x).abs() < seam + TOL);
                // The sew line is inside the cut line, never closer to it than the allowance.
                let n = pc.sew.len();
                for i in 0..n {
                    for f in [0.0, 0.5] {
                        let q = pc.sew[i].lerp(pc.sew[(i + 1) % n], f);
                        if near_fold(q) {
                            continue;
                        }
                        assert!(geom::inside(q, cut), "{name}/{}: sew point {q} outside the cut line", pc.name);
                        let d = geom::distance_to_closed(q, cut);
                        assert!(d >= seam - TOL, "{name}/{}: sew point {q} only {d} cm from the cut line", pc.name);
                    }
                }
                // The cut line runs at the allowance: away from the corners its points
                // are offset samples or crossings of two offsets (at the allowance from
                // both edges); at outer corners a mitre reaches at most three allowances out.
                let corners: Vec<Vec2> = super::piece::grained(p.panel(&pc.name).unwrap()).edges.iter().map(|e| e.start).collect();
                let fold_free: Vec<Vec2> = cut.iter().copied().filter(|q| !near_fold(*q)).collect();
                for &q in &fold_free {
                    let d = geom::distance_to_closed(q, &pc.sew);
                    assert!(d >= seam - TOL && d <= 3.0 * seam + TOL, "{name}/{}: cut point {q} is {d} cm from the sew line", pc.name);
                    let at_corner = corners.iter().any(|c| (*c - q).length() <= 3.0 * seam + TOL);
                    assert!(at_corner || d <= seam + TOL, "{name}/{}: cut point {q} is {d} cm from the sew line", pc.name);
                }
                checked += fold_free.len();
            }
        }
    }
    assert!(checked > 10_000 && skipped < checked / 100, "{checked} samples checked, {skipped} crossing pieces skipped");
}

#[test]
fn hem_and_per_edge_allowances_apply() {
    let mut hems = 0;
    for (name, p) in cases() {
        let bad = crossing(&p);
        let stitched = |panel: &str, e: usize| p.stitches.iter().any(|s| s.sides.iter().any(|sd| sd.panel == panel && sd.edge == e));
        let first = &p.panels[0].name;
        let o = PrintOptions { hem: Some(4.0), edge_seams: vec![EdgeSeam { panel: first.clone(), edge: None, cm: 2.5 }], ..opts(&name) };
        for pc in pieces(&p, &o).unwrap().into_iter().filter(|pc| !bad.contains(&pc.name)) {
            let spec = p.panel(&pc.name).unwrap();
            let g = super::piece::grained(spec);
            for (e, edge) in spec.edges.iter().enumerate() {
                let hem = edge.label.as_deref() == Some("lower_interface") && !stitched(&spec.name, e);
                let dart_leg = p.stitches.iter().any(|s| {
                    super::piece::dart_tip_side(&p, s).is_some() && s.sides.iter().any(|sd| sd.panel == spec.name && sd.edge == e)
                });
                if dart_leg {
                    continue;
                }
                let want = if &spec.name == first {
                    2.5
                } else if hem {
                    4.0
                } else {
                    1.0
                };
                if spec.edge_geom(e).length() < 12.0 || pc.fold.is_some() {
                    continue;
                }
                let (at, n) = super::piece::at_fraction(&g, e, 0.5);
                // Mid-edge, the cut line passes the allowance out along the edge's normal
                // (unless another edge comes closer there and trims it: slits, narrow pieces).
                let sew = super::piece::sew_line(&g.edges);
                if geom::distance_to_closed(at + n * want, &sew) < want - TOL {
                    continue;
                }
                let off = geom::distance_to_closed(at + n * want, &pc.cut_line);
                assert!(off < TOL, "{name}/{} edge {e}: the cut line is {off} cm off the {want} cm offset", pc.name);
                hems += usize::from(hem && want == 4.0);
            }
        }
    }
    assert!(hems > 20, "{hems} hems checked");
}

/// Notches of a piece marking one panel edge: their length fractions along the
/// edge (each notch's sew point must lie on the edge).
fn notches_on(pc: &Piece, p: &Pattern, panel: &str, edge: usize) -> Vec<f64> {
    let (_, xf) = pc.panels.iter().find(|(n, _)| n == panel).unwrap();
    let e = p.panel(panel).unwrap().edge_geom(edge);
    let pts: Vec<Vec2> = edge_samples(&e, 400).into_iter().map(|q| xf.apply(q)).collect();
    let lens: Vec<f64> = std::iter::once(0.0)
        .chain(pts.windows(2).scan(0.0, |s, w| {
            *s += (w[1] - w[0]).length();
            Some(*s)
        }))
        .collect();
    let total = *lens.last().unwrap();
    let mut out = Vec::new();
    for n in pc.notches.iter().filter(|n| n.edges.iter().any(|(pn, pe)| pn == panel && *pe == edge)) {
        let (k, d) = (0..pts.len() - 1)
            .map(|k| (k, geom::point_segment_distance(n.sew, pts[k], pts[k + 1])))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        assert!(d < 0.02, "{}: a notch of {panel}:{edge} is {d} cm off the edge", pc.name);
        // The slit runs from the cut line into the allowance, towards the sew line.
        assert!((n.outer - n.sew).length() >= (n.inner - n.sew).length() - 1e-9);
        out.push((lens[k] + (n.sew - pts[k]).length()) / total);
    }
    out.sort_by(f64::total_cmp);
    out
}

#[test]
fn notches_pair_up_across_every_stitch() {
    let mut stitches = 0;
    for (name, p) in cases() {
        let ps = pieces(&p, &opts(&name)).unwrap();
        let piece_of = |panel: &str| ps.iter().find(|pc| pc.panels.iter().any(|(n, _)| n == panel)).unwrap();
        for (si, s) in p.stitches.iter().enumerate() {
            let [a, b] = &s.sides;
            let dart = super::piece::dart_tip_side(&p, s).is_some();
            let fa = notches_on(piece_of(&a.panel), &p, &a.panel, a.edge);
            let fb = notches_on(piece_of(&b.panel), &p, &b.panel, b.edge);
            assert_eq!(fa.len(), fb.len(), "{name}: stitch {si} has {fa:?} on one side and {fb:?} on the other");
            // The seam along a fold is not sewn: no notches there.
            let fold = ps.iter().any(|pc| {
                pc.cut == Cut::OnFold
                    && pc.panels.iter().any(|(n, _)| n == &a.panel)
                    && pc.panels.iter().any(|(n, _)| n == &b.panel)
                    && fa.is_empty()
                    && fb.is_empty()
            });
            if !fold {
                assert!(fa.len() >= if dart { 1 } else { 2 }, "{name}: stitch {si} has {} notches", fa.len());
                // The same length fractions, read from either end.
                let rev: Vec<f64> = fb.iter().rev().map(|f| 1.0 - f).collect();
                let close = |x: &[f64], y: &[f64]| x.iter().zip(y).all(|(u, v)| (u - v).abs() < 0.01);
                assert!(close(&fa, &fb) || close(&fa, &rev), "{name}: stitch {si}: {fa:?} vs {fb:?}");
                stitches += 1;
            }
        }
    }
    assert!(stitches > 500, "{stitches}");
}

#[test]
fn mirrored_pairs_and_folds_are_found() {
    let (name, p) = cases().into_iter().find(|(n, _)| n == "t-shirt-mean_all").unwrap();
    let ps = pieces(&p, &opts(&name)).unwrap();
    assert_eq!(ps.len(), p.panels.len() / 2, "each left/right pair is one piece");
    assert!(ps.iter().any(|pc| pc.cut == Cut::OnFold && pc.fold.is_some()));
    assert!(ps.iter().all(|pc| pc.panels.len() == 2 && pc.labels.iter().any(|l| l == pc.cut.text())));
    for pc in &ps {
        // Grain runs up the page.
        let [a, b] = pc.grain;
        assert!((b - a).normalize().dot(Vec2::Y) > 0.9999, "{}", pc.name);
    }
}

#[test]
fn tiled_pages_reassemble_to_the_one_sheet() {
    for (name, p) in cases().into_iter().step_by(7) {
        for paper in [Paper::A4, Paper::Letter] {
            let o = PrintOptions { paper, ..opts(&name) };
            let ps = pieces(&p, &o).unwrap();
            let s = sheet::one_sheet(&ps, &o);
            let page = paper.tile_page();
            let (rows, cols, kept) = sheet::tiles(&s, page);
            let step = page - Vec2::splat(2.0 * sheet::PAGE_MARGIN + sheet::OVERLAP);
            // The grid covers the sheet, and each page shows its cell plus the overlap.
            assert!(cols as f64 * step.x + sheet::OVERLAP >= s.size.x && rows as f64 * step.y + sheet::OVERLAP >= s.size.y);
            for t in &kept {
                assert_eq!(t.area.min, Vec2::new(t.col as f64 * step.x, t.row as f64 * step.y));
                assert!((t.area.size() - (step + Vec2::splat(sheet::OVERLAP))).length() < 1e-9);
                // The page puts the tile's corner at the printable corner, at 1:1.
                let map = super::pdf::tile_map(t, page);
                let (x0, y0) = map(t.area.min);
                let (x1, y1) = map(t.area.min + Vec2::new(10.0, 10.0));
                let pt = 72.0 / 2.54;
                assert!((x0 as f64 - pt).abs() < 1e-3 && (y0 as f64 - (page.y - 1.0) * pt).abs() < 1e-3);
                assert!(((x1 - x0) as f64 - 10.0 * pt).abs() < 1e-3 && ((y0 - y1) as f64 - 10.0 * pt).abs() < 1e-3);
            }
            // Everything drawn is on a kept page: the cells of the kept pages cover it.
            for prim in &s.prims {
                let pts: Vec<Vec2> = match prim {
                    Prim::Path { pts, .. } => pts.clone(),
                    Prim::Text { .. } => vec![prim.bounds().min, prim.bounds().max],
                };
                for q in pts {
                    let on = kept.iter().any(|t| {
                        t.area.min.x - 1e-9 <= q.x && q.x <= t.area.max.x + 1e-9 && t.area.min.y - 1e-9 <= q.y && q.y <= t.area.max.y + 1e-9
                    });
                    assert!(on, "{name}: {q} of {prim:?} on no page");
                }
            }
            let dropped = rows * cols - kept.len();
            let pdf = String::from_utf8_lossy(&super::pdf::tiled(&s, &ps, &o)).into_owned();
            let pages = pdf.matches("/Type /Page").count() - pdf.matches("/Type /Pages").count();
            assert_eq!(pages, kept.len() + 1, "{name}: cover + {} pages ({dropped} blank left out)", kept.len());
        }
    }
}

/// Page sizes (points) from a PDF's media boxes.
fn media_boxes(pdf: &[u8]) -> Vec<(f64, f64)> {
    let text = String::from_utf8_lossy(pdf);
    text.split("/MediaBox [")
        .skip(1)
        .map(|rest| {
            let v: Vec<f64> = rest[..rest.find(']').unwrap()].split_whitespace().map(|x| x.parse().unwrap()).collect();
            (v[2] - v[0], v[3] - v[1])
        })
        .collect()
}

/// A pattern of one `w` × `h` cm rectangle.
fn rectangle(w: f64, h: f64) -> Pattern {
    use crate::pattern::{EdgeSpec, PanelSpec};
    let edge = |a, b| EdgeSpec { endpoints: [a, b], label: None, curvature: None };
    let mut p = Pattern::new("rectangle");
    p.panels.push(PanelSpec {
        name: "long".into(),
        translation: [0.0; 3],
        rotation: [0.0; 3],
        vertices: vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]],
        edges: vec![edge(0, 1), edge(1, 2), edge(2, 3), edge(3, 0)],
        label: None,
        holes: Vec::new(),
        lines: Vec::new(),
        layer: Default::default(),
    });
    p
}

/// A one-sheet layout longer (or wider) than a PDF page may be is split into the
/// fewest equal parts within [`pdf::MAX_PAGE`], each at 1:1 with the tiled pages'
/// overlap, marks and labels; the parts cover the whole sheet. A sheet that fits
/// stays one page of its own size.
#[test]
fn long_sheets_are_split_into_pages_within_the_pdf_limit() {
    let limit_pt = 14_400.0;
    let long: Vec<(String, Pattern)> = cases().into_iter().filter(|(n, _)| ["case-030", "case-060"].contains(&n.as_str())).collect();
    let synthetic = [("very long", rectangle(40.0, 1200.0)), ("very wide", rectangle(700.0, 90.0))];
    let all = long.into_iter().chain(synthetic.into_iter().map(|(n, p)| (n.to_string(), p)));
    let mut split = 0;
    for (name, p) in all {
        let o = PrintOptions { paper: Paper::Roll(30.0), ..opts(&name) };
        let ps = pieces(&p, &o).unwrap();
        let s = sheet::one_sheet(&ps, &o);
        let pdf = super::pdf::one_sheet(&s);
        let boxes = media_boxes(&pdf);
        let pt = 72.0 / 2.54;
        for (w, h) in &boxes {
            assert!(*w <= limit_pt && *h <= limit_pt, "{name}: a {w} x {h} pt page");
        }
        if s.size.x <= super::pdf::MAX_PAGE && s.size.y <= super::pdf::MAX_PAGE {
            assert_eq!(boxes.len(), 1, "{name}");
            assert!((boxes[0].0 - s.size.x * pt).abs() < 0.01 && (boxes[0].1 - s.size.y * pt).abs() < 0.01, "{name}: the sheet's own size");
            continue;
        }
        split += 1;
        let page = super::pdf::page_for_parts(s.size);
        let (rows, cols, kept) = sheet::tiles(&s, page);
        let step = page - Vec2::splat(2.0 * sheet::PAGE_MARGIN + sheet::OVERLAP);
        // Every part within the limit, together covering the sheet, and no fewer would do.
        assert!(page.x <= super::pdf::MAX_PAGE && page.y <= super::pdf::MAX_PAGE, "{name}: {page}");
        assert!(cols as f64 * step.x + sheet::OVERLAP >= s.size.x && rows as f64 * step.y + sheet::OVERLAP >= s.size.y, "{name}");
        let most = super::pdf::MAX_PAGE - 2.0 * sheet::PAGE_MARGIN - sheet::OVERLAP;
        assert!(
            (cols - 1) as f64 * most + sheet::OVERLAP < s.size.x && (rows - 1) as f64 * most + sheet::OVERLAP < s.size.y,
            "{name}: fewest parts"
        );
        assert!(rows * cols > 1 && !kept.is_empty());
        assert_eq!(boxes.len(), kept.len(), "{name}: one page per part with something on it");
        for (w, h) in &boxes {
            assert!((w - page.x * pt).abs() < 0.01 && (h - page.y * pt).abs() < 0.01, "{name}: 1:1");
        }
        let text = String::from_utf8_lossy(&pdf);
        assert!(text.contains("(Page A1)") && text.contains("lay the next page"), "{name}: parts are labelled for joining");
    }
    assert_eq!(split, 4, "every sheet here is too long or too wide for one page");
}

#[test]
fn blank_pages_are_left_out() {
    // An L-shaped layout: a wide short piece and a narrow tall one leave a blank corner.
    let (name, p) = cases().into_iter().find(|(n, _)| n == "t-shirt-mean_all").unwrap();
    let o = opts(&name);
    let s = sheet::one_sheet(&pieces(&p, &o).unwrap(), &o);
    let (rows, cols, kept) = sheet::tiles(&s, Paper::A4.tile_page());
    assert!(kept.len() < rows * cols, "{rows}x{cols} all kept");
}

fn read_back(p: &Pattern, name: &str) -> (Vec<Piece>, DxfDrawing, String) {
    let o = opts(name);
    let ps = pieces(p, &o).unwrap();
    let text = dxf::write(&ps, &sheet::one_sheet(&ps, &o), &o);
    (ps, read_dxf(&text).unwrap(), text)
}

#[test]
fn dxf_reads_back_with_one_block_per_piece_and_the_pattern_outlines() {
    for (name, p) in cases().into_iter().step_by(3) {
        let (ps, d, _) = read_back(&p, &name);
        assert_eq!(d.version, "AC1009");
        for l in ["1", "4", "7", "8", "14"] {
            assert!(d.layers.iter().any(|x| x == l), "{name}: layer {l}");
        }
        assert_eq!(d.blocks.len(), ps.len());
        let inserts: Vec<&DxfEntity> = d.entities.iter().filter(|e| e.kind == "INSERT").collect();
        assert_eq!(inserts.len(), ps.len());
        for pc in &ps {
            let b = d.blocks.iter().find(|b| b.name == dxf::block_name(&pc.name)).unwrap();
            assert_eq!(inserts.iter().filter(|e| e.text == b.name && e.layer == "1").count(), 1);
            let on = |kind: &str, layer: &str| b.entities.iter().filter(|e| e.kind == kind && e.layer == layer).collect::<Vec<_>>();
            let cut = on("POLYLINE", "1");
            let sew = on("POLYLINE", "14");
            assert!(cut.len() == 1 && sew.len() == 1 && cut[0].closed && sew[0].closed, "{name}/{}", pc.name);
            assert_eq!(on("LINE", "4").len(), pc.notches.len());
            assert_eq!(on("LINE", "7").len(), 1);
            assert!(b.entities.iter().filter(|e| e.kind == "TEXT" && e.layer == "1").any(|e| e.text == format!("Piece Name: {}", pc.name)));
            assert!(b.entities.iter().any(|e| e.kind == "TEXT" && e.text.starts_with("Quantity: ")));
            assert!(b.entities.iter().all(|e| ["1", "4", "6", "7", "8", "14"].contains(&e.layer.as_str())));
            // The sew line is the panel's outline within 0.1 mm (file units: mm).
            let sew_cm: Vec<Vec2> = sew[0].points.iter().map(|q| *q / 10.0).collect();
            let (panel, xf) = &pc.panels[0];
            let spec = p.panel(panel).unwrap();
            for i in 0..spec.edges.len() {
                for q in edge_samples(&spec.edge_geom(i), 50) {
                    let d = geom::distance_to_closed(xf.apply(q), &sew_cm);
                    assert!(d < TOL, "{name}/{panel} edge {i}: {d} cm off the DXF sew line");
                }
            }
            let cut_cm: Vec<Vec2> = cut[0].points.iter().map(|q| *q / 10.0).collect();
            assert_eq!(cut_cm.len(), pc.cut_line.len());
            assert!(cut_cm.iter().zip(&pc.cut_line).all(|(a, b)| (*a - *b).length() < 1e-3));
        }
    }
}

#[test]
fn dxf_reads_back_in_ezdxf() {
    let (name, p) = cases().into_iter().find(|(n, _)| n == "t-shirt-mean_all").unwrap();
    let (ps, ours, text) = read_back(&p, &name);
    let script = r#"
import sys, json
import ezdxf
doc = ezdxf.readfile(sys.argv[1])
out = {"version": doc.dxfversion, "blocks": {}, "inserts": []}
for b in doc.blocks:
    if b.name.startswith("*"):
        continue
    ents = []
    for e in b:
        pts = []
        if e.dxftype() == "POLYLINE":
            pts = [[v.dxf.location.x, v.dxf.location.y] for v in e.vertices]
        elif e.dxftype() == "LINE":
            pts = [[e.dxf.start.x, e.dxf.start.y], [e.dxf.end.x, e.dxf.end.y]]
        ents.append([e.dxftype(), e.dxf.layer, pts])
    out["blocks"][b.name] = ents
for e in doc.modelspace():
    out["inserts"].append([e.dxftype(), e.dxf.layer, e.dxf.name if e.dxftype() == "INSERT" else ""])
auditor = doc.audit()
out["errors"] = len(auditor.errors)
print(json.dumps(out))
"#;
    let Some(v) = ezdxf::read_back_text("dxf_reads_back_in_ezdxf", &text, script) else { return };
    assert_eq!(v["version"], "AC1009");
    assert_eq!(v["errors"], 0, "{v}");
    let inserts = v["inserts"].as_array().unwrap();
    assert_eq!(inserts.len(), ps.len());
    assert!(inserts.iter().all(|i| i[0] == "INSERT" && i[1] == "1"));
    for (pc, b) in ps.iter().zip(&ours.blocks) {
        let ents = v["blocks"][&b.name].as_array().unwrap_or_else(|| panic!("no block {}", b.name));
        assert_eq!(ents.len(), b.entities.len(), "{}", b.name);
        for (e, o) in ents.iter().zip(&b.entities) {
            assert_eq!((e[0].as_str().unwrap(), e[1].as_str().unwrap()), (o.kind.as_str(), o.layer.as_str()));
        }
        let sew = ents.iter().find(|e| e[0] == "POLYLINE" && e[1] == "14").unwrap();
        let pts: Vec<Vec2> =
            sew[2].as_array().unwrap().iter().map(|q| Vec2::new(q[0].as_f64().unwrap(), q[1].as_f64().unwrap()) / 10.0).collect();
        assert_eq!(pts.len(), pc.sew.len());
        assert!(pts.iter().zip(&pc.sew).all(|(a, b)| (*a - *b).length() < TOL), "{}", pc.name);
    }
}

#[test]
fn files_are_deterministic_and_complete() {
    let (name, p) = cases().into_iter().find(|(n, _)| n == "t-shirt-mean_all").unwrap();
    let a = files(&p, &opts(&name)).unwrap();
    let b = files(&p.clone(), &opts(&name)).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), FILE_NAMES);
    assert!(a[0].1.starts_with(b"%PDF-") && a[1].1.starts_with(b"%PDF-"));
    let report = String::from_utf8(a[5].1.clone()).unwrap();
    assert!(report.contains("Fabric length needed:"), "{report}");
}

#[test]
fn pieces_wider_than_the_fabric_are_reported() {
    let (name, p) = cases().into_iter().find(|(n, _)| n == "t-shirt-mean_all").unwrap();
    let o = PrintOptions { fabric_width: 30.0, ..opts(&name) };
    let ps = pieces(&p, &o).unwrap();
    let l = sheet::cutting_layout(&ps, 30.0);
    assert!(l.cuts.iter().any(|c| !c.fits));
    assert!(sheet::cutting_report(&l, &ps, &o).contains("TOO WIDE"));
    let wide = sheet::cutting_layout(&ps, 140.0);
    assert!(wide.cuts.iter().all(|c| c.fits));
    assert_eq!(wide.cuts.len(), ps.iter().map(|pc| if matches!(pc.cut, Cut::Two | Cut::MirroredPair) { 2 } else { 1 }).sum::<usize>());
    // Copies do not overlap on the fabric.
    let boxes: Vec<Rect> = wide.cuts.iter().map(|c| Rect::of(c.outlines.iter().flatten().copied())).collect();
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            assert!(!boxes[i].overlaps(&boxes[j]));
        }
        assert!(boxes[i].max.y <= wide.length + 1e-9 && boxes[i].min.x >= -1e-9 && boxes[i].max.x <= 140.0 + 1e-9);
    }
}

#[test]
fn one_sheet_pieces_do_not_overlap() {
    for (name, p) in cases() {
        let o = opts(&name);
        let ps = pieces(&p, &o).unwrap();
        let s = sheet::one_sheet(&ps, &o);
        let boxes: Vec<Rect> = s.placed.iter().map(|pl| Rect::of(ps[pl.piece].cut_line.iter().map(|q| pl.xf.apply(*q)))).collect();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                assert!(!boxes[i].overlaps(&boxes[j]), "{name}");
            }
            assert!(boxes[i].min.x >= 0.0 && boxes[i].max.x <= s.size.x && boxes[i].max.y <= s.size.y);
        }
    }
}

/// A small two-panel pattern: a front with a curved neckline and a back, sewn at the sides.
fn small() -> Pattern {
    let json = r#"{"pattern": {"panels": {
      "front": {"translation": [0, 0, 10], "rotation": [0, 0, 0], "vertices": [[0, 0], [20, 0], [20, 25], [0, 25]],
        "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3], "curvature": {"type": "quadratic", "params": [[0.5, 0.2]]}}, {"endpoints": [3, 0]}]},
      "back": {"translation": [0, 0, -10], "rotation": [0, 180, 0], "vertices": [[0, 0], [20, 0], [20, 25], [0, 25]],
        "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3], "curvature": {"type": "circle", "params": [25, 0, 1]}}, {"endpoints": [3, 0]}]}},
      "stitches": [[{"panel": "front", "edge": 1}, {"panel": "back", "edge": 3}], [{"panel": "front", "edge": 3}, {"panel": "back", "edge": 1}]]},
      "properties": {"curvature_coords": "relative", "normalize_panel_translation": false, "normalized_edge_loops": true, "units_in_meter": 100}}"#;
    Pattern::from_json(json).unwrap()
}

#[test]
fn snapshot_of_a_small_pattern() {
    let p = small();
    let o = PrintOptions { garment: "demo".into(), size: "mean_all".into(), ..Default::default() };
    let ps = pieces(&p, &o).unwrap();
    let s = sheet::one_sheet(&ps, &o);
    insta::assert_snapshot!("small_dxf", dxf::write(&ps, &s, &o));
    insta::assert_snapshot!("small_svg", super::svg::sheet(&s));
}

/// Implausible allowances, fabric widths and rolls are refused at once, with the
/// allowed range (a 1e9 cm allowance or a 1e308 cm roll used to run without end).
#[test]
fn implausible_options_are_refused_with_their_range() {
    let p = small();
    let refused = |opts: PrintOptions, range: &str| {
        let e = files(&p, &opts).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains(range), "{opts:?}: {e}");
    };
    refused(PrintOptions { seam: 1e9, ..Default::default() }, "from 0 to 20");
    refused(PrintOptions { hem: Some(f64::NAN), ..Default::default() }, "from 0 to 20");
    let edge = EdgeSeam::parse("a=1").unwrap();
    refused(PrintOptions { edge_seams: vec![EdgeSeam { cm: 21.0, ..edge }], ..Default::default() }, "from 0 to 20");
    refused(PrintOptions { fabric_width: 1e9, ..Default::default() }, "at most 1000");
    refused(PrintOptions { paper: Paper::Roll(1e308), ..Default::default() }, "from 30 to 1000");
    assert!(Paper::parse("roll:1e308").unwrap_err().contains("from 30 to 1000"));
    assert!(EdgeSeam::parse("a=1e9").unwrap_err().contains("from 0 to 20"));
    assert!(files(&p, &PrintOptions { seam: 20.0, fabric_width: 1000.0, ..Default::default() }).is_ok());
}
