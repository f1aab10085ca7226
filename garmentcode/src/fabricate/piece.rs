//! Pattern pieces from a pattern's panels: sew line, cut line, notches, grainline,
//! cut count and labels, each piece in its own frame with the grain pointing up.

use super::geom::{self, OffsetEdge, Rect, Xf};
use super::types::{Cut, Grained, Notch, Piece, PrintOptions, slit};
use crate::edge::{Curve, Edge, Segment};
use crate::error::{Error, Result};
use crate::math::{Vec2, Vec3};
use crate::pattern::{PanelSpec, Pattern};

/// Longest step between sew-line points on curved edges (cm). A circle of radius
/// `R` sampled this finely strays at most `0.25² / 8R` from its chords: under
/// 0.04 mm for every radius above 2 cm.
pub const CURVE_STEP: f64 = 0.25;

/// Seams longer than this get match notches along them (one per this many cm).
pub const MATCH_SPACING: f64 = 15.0;

/// Stitched edges whose lengths differ by more than this fraction are gathered.
pub const GATHER_RATIO: f64 = 0.05;

/// A panel edge: panel name and edge index.
type PanelEdge = (String, usize);

/// Tolerance of the shape comparisons that find mirrored and repeated panels (cm).
const SAME_SHAPE: f64 = 0.05;

/// Points of an edge at `t ∈ [0, 1)` (the end point belongs to the next edge).
fn edge_params(e: &Edge) -> Vec<f64> {
    let n = match e.curve {
        Curve::Line => 1,
        _ => ((e.length() / CURVE_STEP).ceil() as usize).clamp(8, 2000),
    };
    (0..n).map(|i| i as f64 / n as f64).collect()
}

/// Unit tangent of a segment at `t`, robust to vanishing derivatives at Bézier ends.
fn tangent(seg: &Segment, t: f64) -> Vec2 {
    let d = seg.derivative(t);
    if d.length() > 1e-9 {
        return d.normalize();
    }
    let (a, b) = ((t - 1e-4).max(0.0), (t + 1e-4).min(1.0));
    (seg.point(b) - seg.point(a)).normalize_or_zero()
}

/// Outward unit normal of an outline running counter-clockwise (`ccw`) or not.
fn outward(tan: Vec2, ccw: bool) -> Vec2 {
    if ccw { Vec2::new(tan.y, -tan.x) } else { Vec2::new(-tan.y, tan.x) }
}

/// Transform an edge; a mirroring map reflects its curvature.
fn map_edge(e: &Edge, xf: &Xf) -> Edge {
    let curve = if xf.is_mirror() { e.curve.reflected() } else { e.curve };
    Edge { start: xf.apply(e.start), end: xf.apply(e.end), curve }
}

/// The grain direction of a panel in its own plane: the world's up (+y) as seen on
/// the panel, or the panel's own y when the panel lies (nearly) flat. Sleeves
/// (panels labelled `arm`) are the exception: their grain runs along the arm, the
/// panel's x axis, pointing up the arm.
fn grain_direction(p: &PanelSpec) -> Vec2 {
    let r = p.rotation();
    let (ax, ay) = (r.apply(Vec3::X), r.apply(Vec3::Y));
    if p.label.as_deref() == Some("arm") {
        return if ax.y < 0.0 { -Vec2::X } else { Vec2::X };
    }
    let g = Vec2::new(ax.y, ay.y);
    if g.length() < 0.5 {
        return Vec2::Y;
    }
    let g = g.normalize();
    // Keep axis-aligned panels exactly axis-aligned.
    if g.dot(Vec2::Y) > (1f64.to_radians()).cos() { Vec2::Y } else { g }
}

/// The sew line of edges (closed, each edge's points from its start).
pub(crate) fn sew_line(edges: &[Edge]) -> Vec<Vec2> {
    edges.iter().flat_map(|e| edge_params(e).into_iter().map(move |t| e.point(t))).collect()
}

/// A panel in its grain frame.
pub(crate) fn grained(p: &PanelSpec) -> Grained {
    let local: Vec<Edge> = (0..p.edges.len()).map(|i| p.edge_geom(i)).collect();
    let rot = Xf::rotate_onto_y(grain_direction(p));
    let turned: Vec<Edge> = local.iter().map(|e| map_edge(e, &rot)).collect();
    let sew = sew_line(&turned);
    let b = Rect::of(sew.iter().copied());
    let xf = Xf::translate(-b.min).after(&rot);
    let edges: Vec<Edge> = local.iter().map(|e| map_edge(e, &xf)).collect();
    let ccw = geom::signed_area(&sew) > 0.0;
    Grained { edges, xf, ccw, width: b.size().x }
}

/// Whether two panels (in their grain frames) have the same outline, after
/// mirroring the second across the vertical when `mirror`.
fn same_shape(a: &Grained, b: &Grained, mirror: bool) -> bool {
    if a.edges.len() != b.edges.len() || (a.width - b.width).abs() > SAME_SHAPE {
        return false;
    }
    let m = if mirror { Xf::mirror_x(b.width) } else { Xf::IDENTITY };
    let (pa, pb): (Vec<Vec2>, Vec<Vec2>) = (a.edges.iter().map(|e| e.start).collect(), b.edges.iter().map(|e| m.apply(e.start)).collect());
    let close = |p: &Vec2, q: &[Vec2]| q.iter().any(|x| (*x - *p).length() < SAME_SHAPE);
    let length = |g: &Grained| g.edges.iter().map(Edge::length).sum::<f64>();
    pa.iter().all(|p| close(p, &pb)) && pb.iter().all(|p| close(p, &pa)) && (length(a) - length(b)).abs() < SAME_SHAPE
}

/// Which side of its panel's frame an edge lies on: `Some(false)` on `x = 0`,
/// `Some(true)` on `x = width`, `None` when it is not a straight edge on either.
fn side_of(g: &Grained, edge: usize) -> Option<bool> {
    let e = &g.edges[edge];
    let on = |x: f64| (e.start.x - x).abs() < SAME_SHAPE && (e.end.x - x).abs() < SAME_SHAPE;
    if e.curve != Curve::Line {
        None
    } else if on(0.0) {
        Some(false)
    } else if on(g.width) {
        Some(true)
    } else {
        None
    }
}

/// How the panels group into pieces: representative, partner with the map from
/// the partner's grain frame into the representative's, cut count and fold edge.
pub(crate) struct Group {
    /// Representative panel index.
    pub rep: usize,
    /// Partner panel index and its map into the representative's frame.
    pub partner: Option<(usize, Xf)>,
    /// Cut count.
    pub cut: Cut,
    /// Edge of the representative on the fold.
    pub fold_edge: Option<usize>,
    /// The stitch along the fold (it disappears: the fold is not sewn).
    pub fold_stitch: Option<usize>,
}

/// Pair mirrored and repeated panels; a mirrored pair stitched along a straight
/// centre edge is cut on the fold.
pub(crate) fn groups(p: &Pattern, g: &[Grained]) -> Vec<Group> {
    let mut used = vec![false; g.len()];
    let mut out = Vec::new();
    for i in 0..g.len() {
        if used[i] {
            continue;
        }
        used[i] = true;
        let mut group = Group { rep: i, partner: None, cut: Cut::One, fold_edge: None, fold_stitch: None };
        for j in i + 1..g.len() {
            if used[j] {
                continue;
            }
            let (mirrored, same) = (same_shape(&g[i], &g[j], true), same_shape(&g[i], &g[j], false));
            if !mirrored && !same {
                continue;
            }
            used[j] = true;
            let (ni, nj) = (&p.panels[i].name, &p.panels[j].name);
            // Cut on the fold: the two are stitched along straight edges on their
            // frames' sides, and folding one onto the other along that edge matches
            // them (edges on opposite sides: mirror images; on the same side: equal).
            let fold = p.stitches.iter().enumerate().find_map(|(si, s)| {
                let [a, b] = &s.sides;
                let (ei, ej) = if (&a.panel, &b.panel) == (ni, nj) {
                    (a.edge, b.edge)
                } else if (&b.panel, &a.panel) == (ni, nj) {
                    (b.edge, a.edge)
                } else {
                    return None;
                };
                match (side_of(&g[i], ei), side_of(&g[j], ej)) {
                    (Some(x), Some(y)) if x != y && mirrored => Some((ei, si, Xf::mirror_x(g[j].width))),
                    (Some(x), Some(y)) if x == y && same => Some((ei, si, Xf::IDENTITY)),
                    _ => None,
                }
            });
            let xf = match fold {
                Some((_, _, xf)) => xf,
                None if mirrored => Xf::mirror_x(g[j].width),
                None => Xf::IDENTITY,
            };
            group.partner = Some((j, xf));
            group.fold_edge = fold.map(|f| f.0);
            group.fold_stitch = fold.map(|f| f.1);
            let fold = fold.map(|f| f.0);
            group.cut = match (fold.is_some(), mirrored) {
                (true, _) => Cut::OnFold,
                (false, true) => Cut::MirroredPair,
                (false, false) => Cut::Two,
            };
            break;
        }
        out.push(group);
    }
    out
}

/// The seam allowance of one panel edge.
pub(crate) fn allowance(opts: &PrintOptions, panel: &PanelSpec, edge: usize, stitched: bool) -> f64 {
    let exact = opts.edge_seams.iter().find(|o| o.panel == panel.name && o.edge == Some(edge));
    let whole = opts.edge_seams.iter().find(|o| o.panel == panel.name && o.edge.is_none());
    if let Some(o) = exact.or(whole) {
        return o.cm;
    }
    let hem = !stitched && panel.edges[edge].label.as_deref() == Some("lower_interface");
    match (hem, opts.hem) {
        (true, Some(h)) => h,
        _ => opts.seam,
    }
}

/// The shared vertex of a dart: a stitch between two edges of one panel that meet
/// end to start. Returns the side whose edge ends at the tip (0 or 1).
pub(crate) fn dart_tip_side(p: &Pattern, s: &crate::pattern::StitchSpec) -> Option<usize> {
    let [a, b] = &s.sides;
    if a.panel != b.panel {
        return None;
    }
    let panel = p.panel(&a.panel)?;
    let (ea, eb) = (panel.edges.get(a.edge)?, panel.edges.get(b.edge)?);
    if ea.endpoints[1] == eb.endpoints[0] {
        Some(0)
    } else if eb.endpoints[1] == ea.endpoints[0] {
        Some(1)
    } else {
        None
    }
}

/// Notch positions of every stitch, per side, as length fractions along the side's
/// edge. A seam gets the same fractions on both sides, symmetric, so the edges'
/// directions do not matter: both ends, and match points every [`MATCH_SPACING`]
/// cm. A dart (two edges of one panel meeting at its tip) is notched where its legs
/// open, not at the tip.
pub fn stitch_fractions(p: &Pattern) -> Vec<[Vec<f64>; 2]> {
    p.stitches
        .iter()
        .map(|s| {
            if let Some(tip_side) = dart_tip_side(p, s) {
                // The side ending at the tip opens at its start, the other at its end.
                return if tip_side == 0 { [vec![0.0], vec![1.0]] } else { [vec![1.0], vec![0.0]] };
            }
            let len = s.sides.iter().filter_map(|side| p.panel(&side.panel).map(|pp| pp.edge_geom(side.edge).length())).fold(0.0, f64::max);
            let inner = (len / MATCH_SPACING).floor() as usize;
            let f: Vec<f64> = (0..inner + 2).map(|k| k as f64 / (inner + 1) as f64).collect();
            [f.clone(), f]
        })
        .collect()
}

/// Point and outward normal at a length fraction of an edge of a grained panel.
pub(crate) fn at_fraction(g: &Grained, edge: usize, f: f64) -> (Vec2, Vec2) {
    let e = &g.edges[edge];
    let seg = e.segment();
    let t = seg.inverse_length(f.clamp(0.0, 1.0) * seg.length()).unwrap_or(f);
    (seg.point(t), outward(tangent(&seg, t), g.ccw))
}

/// The cut line of a grained panel with per-edge allowances.
pub(crate) fn cut_line(g: &Grained, allow: &[f64]) -> Vec<Vec2> {
    // Offsetting works on a counter-clockwise loop: walk a clockwise one backwards.
    let order: Vec<usize> = if g.ccw { (0..g.edges.len()).collect() } else { (0..g.edges.len()).rev().collect() };
    let edges: Vec<(Edge, f64)> = order.iter().map(|&i| (if g.ccw { g.edges[i] } else { g.edges[i].reversed() }, allow[i])).collect();
    let offsets: Vec<OffsetEdge> = edges
        .iter()
        .map(|(e, d)| {
            let seg = e.segment();
            let mut ts = edge_params(e);
            ts.push(1.0);
            let points = ts.iter().map(|&t| seg.point(t) + outward(tangent(&seg, t), true) * *d).collect();
            OffsetEdge { points, t0: tangent(&seg, 0.0), t1: tangent(&seg, 1.0), d: *d }
        })
        .collect();
    let corners: Vec<Vec2> = edges.iter().map(|(e, _)| e.start).collect();
    geom::join_offsets(&offsets, &corners)
}

/// Notch marks of one grained panel (in its grain frame): for each stitch side on
/// this panel with an allowance, the sew-line point at each of the stitch's
/// fractions and where its notch meets the cut line, the edge's allowance out along
/// its outward normal (for a dart leg: along the leg, out of the dart's opening).
pub(crate) fn panel_notches(
    p: &Pattern,
    panel: usize,
    g: &Grained,
    allow: &[f64],
    fracs: &[[Vec<f64>; 2]],
) -> Vec<(usize, Vec2, Vec2, usize)> {
    let name = &p.panels[panel].name;
    let mut out = Vec::new();
    for (si, s) in p.stitches.iter().enumerate() {
        let dart = dart_tip_side(p, s);
        for (k, side) in s.sides.iter().enumerate().filter(|(_, sd)| &sd.panel == name) {
            if allow[side.edge] <= 0.0 {
                continue;
            }
            for &f in &fracs[si][k] {
                let (at, n) = at_fraction(g, side.edge, f);
                let dir = match dart {
                    // The leg ending at the tip opens at its start, the other at its end.
                    Some(tip) => {
                        let seg = g.edges[side.edge].segment();
                        if tip == k { -tangent(&seg, 0.0) } else { tangent(&seg, 1.0) }
                    }
                    None => n,
                };
                out.push((si, at, dir * allow[side.edge], side.edge));
            }
        }
    }
    out
}

/// A point well inside a polygon and its distance to the outline: of the grid
/// points at least 95% as far from the outline as the farthest, the one nearest
/// the middle of the polygon's box (so long strips get their label in the middle).
pub(crate) fn interior_point(poly: &[Vec2]) -> (Vec2, f64) {
    let b = Rect::of(poly.iter().copied());
    let middle = (b.min + b.max) / 2.0;
    let steps = 24;
    let mut scored = Vec::new();
    for i in 0..=steps {
        for j in 0..=steps {
            let q = b.min + b.size() * Vec2::new(i as f64 / steps as f64, j as f64 / steps as f64);
            if geom::inside(q, poly) {
                scored.push((q, geom::distance_to_closed(q, poly)));
            }
        }
    }
    let far = scored.iter().map(|s| s.1).fold(0.0, f64::max);
    scored
        .into_iter()
        .filter(|s| s.1 >= 0.95 * far)
        .min_by(|a, b| (a.0 - middle).length().total_cmp(&(b.0 - middle).length()))
        .unwrap_or((middle, 0.0))
}

/// Vertical extent of a polygon at `x` around `y`: the inside interval holding `y`.
fn vertical_span(poly: &[Vec2], x: f64, y: f64) -> Option<(f64, f64)> {
    let n = poly.len();
    let mut ys: Vec<f64> = (0..n)
        .filter_map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            ((a.x > x) != (b.x > x)).then(|| a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y))
        })
        .collect();
    ys.sort_by(f64::total_cmp);
    ys.chunks(2).find(|c| c.len() == 2 && c[0] <= y && y <= c[1]).map(|c| (c[0], c[1]))
}

/// Build every piece of a pattern.
pub(crate) fn build(p: &Pattern, opts: &PrintOptions) -> Result<Vec<Piece>> {
    if p.panels.is_empty() {
        return Err(Error::Design("the pattern has no panels to print".into()));
    }
    if let Some(e) = crate::validate(p).into_iter().find(|x| x.severity == crate::Severity::Error) {
        return Err(Error::Input(format!("cannot print a pattern with structural errors: {e}")));
    }
    let grained: Vec<Grained> = p.panels.iter().map(grained).collect();
    let groups = groups(p, &grained);
    let fracs = stitch_fractions(p);
    let stitched = |panel: &str, e: usize| p.stitches.iter().any(|s| s.sides.iter().any(|sd| sd.panel == panel && sd.edge == e));
    let mut pieces = Vec::new();
    for gr in groups {
        let panel = &p.panels[gr.rep];
        let g = &grained[gr.rep];
        let mut allow: Vec<f64> = (0..panel.edges.len()).map(|e| allowance(opts, panel, e, stitched(&panel.name, e))).collect();
        if let Some(f) = gr.fold_edge {
            allow[f] = 0.0;
        }
        let sew = sew_line(&g.edges);
        let cut = cut_line(g, &allow);
        let mut marks: Vec<(Vec2, Vec2, PanelEdge)> =
            panel_notches(p, gr.rep, g, &allow, &fracs).into_iter().map(|(_, at, r, e)| (at, r, (panel.name.clone(), e))).collect();
        let mut placements = vec![(panel.name.clone(), g.xf)];
        if let Some((j, m)) = gr.partner {
            let other = &p.panels[j];
            let og = &grained[j];
            // The partner's notches, drawn on the representative (its edges sit where
            // the mirrored or repeated outline puts them); none on the fold.
            let oallow: Vec<f64> = (0..other.edges.len()).map(|e| allowance(opts, other, e, stitched(&other.name, e))).collect();
            for (si, at, r, e) in panel_notches(p, j, og, &oallow, &fracs) {
                if gr.fold_stitch != Some(si) {
                    marks.push((m.apply(at), m.apply_vec(r), (other.name.clone(), e)));
                }
            }
            placements.push((other.name.clone(), m.after(&og.xf)));
        }
        // One notch per point and direction: notches of seams meeting at a point
        // within 8° of each other become one, along their mean direction.
        let mut merged: Vec<(Vec2, Vec2, usize, Vec<PanelEdge>)> = Vec::new();
        for (at, r, id) in marks {
            match merged.iter_mut().find(|(q, m, _, _)| (*q - at).length() < 0.05 && m.normalize().dot(r.normalize()) > 0.99) {
                Some((_, m, count, ids)) => {
                    *m += r;
                    *count += 1;
                    if !ids.contains(&id) {
                        ids.push(id);
                    }
                }
                None => merged.push((at, r, 1, vec![id])),
            }
        }
        let mut notches: Vec<Notch> = merged
            .into_iter()
            .map(|(at, r, count, ids)| slit(at, r / count as f64, &cut, ids))
            .filter(|s| (s.outer - s.sew).length() > 1e-6)
            .collect();
        // Gathered edges: a wavy line just inside the sew line between the notches.
        let mut internal = Vec::new();
        for s in &p.stitches {
            let lens: Vec<f64> = s.sides.iter().map(|sd| p.panel(&sd.panel).map_or(0.0, |pp| pp.edge_geom(sd.edge).length())).collect();
            let (long, short) = if lens[0] >= lens[1] { (0, 1) } else { (1, 0) };
            if lens[long] <= lens[short] * (1.0 + GATHER_RATIO) || s.sides[long].panel != panel.name {
                continue;
            }
            let e = s.sides[long].edge;
            let n = ((lens[long] / 0.5).ceil() as usize).max(4);
            let wave: Vec<Vec2> = (0..=n)
                .map(|k| {
                    let (at, out) = at_fraction(g, e, k as f64 / n as f64);
                    at - out * if k % 2 == 0 { 0.4 } else { 0.8 }
                })
                .collect();
            internal.push(wave);
        }
        // Dart tips: a drill-hole circle 1 cm short of the tip, on the dart's centre line.
        for s in &p.stitches {
            if s.sides[0].panel != panel.name {
                continue;
            }
            let Some(tip_side) = dart_tip_side(p, s) else { continue };
            let into = &g.edges[s.sides[tip_side].edge];
            let out_of = &g.edges[s.sides[1 - tip_side].edge];
            let tip = into.end;
            let axis = ((into.start - tip).normalize_or_zero() + (out_of.end - tip).normalize_or_zero()).normalize_or_zero();
            let c = tip + axis * 1.0_f64.min(into.length() / 3.0);
            internal.push((0..=16).map(|k| c + Vec2::from_angle(k as f64 / 16.0 * std::f64::consts::TAU) * 0.3).collect());
        }
        // Holes and inner lines (format extension).
        let reach = allow.iter().copied().fold(0.0, f64::max) + 1.0;
        let ext = super::inner::marks(panel, g, &sew, &cut, reach);
        internal.extend(ext.internal);
        notches.extend(ext.notches);
        let fold = gr.fold_edge.map(|f| [g.edges[f].start, g.edges[f].end]);
        let cut_text = opts_cut_text(gr.cut);
        let (centre, room) = interior_point(&sew);
        let lines = vec![
            panel.name.clone(),
            opts.garment.clone(),
            format!("Size: {}", opts.size),
            cut_text.to_string(),
            "Grainline: parallel to the selvage".to_string(),
        ];
        let chars = lines.iter().map(|l| l.len()).max().unwrap_or(1) as f64;
        let (bw, bh) = (0.55 * chars, 1.25 * lines.len() as f64);
        let text_size = (1.7 * room / bw.hypot(bh)).clamp(0.25, 1.2);
        let grain_x = centre.x - bw * text_size / 2.0 - 0.5;
        let grain_x = if geom::inside(Vec2::new(grain_x, centre.y), &sew) { grain_x } else { centre.x };
        let (y0, y1) = vertical_span(&sew, grain_x, centre.y).unwrap_or((centre.y - 5.0, centre.y + 5.0));
        let margin = (y1 - y0) * 0.12;
        let grain = [Vec2::new(grain_x, y0 + margin), Vec2::new(grain_x, y1 - margin)];
        let label_at = Vec2::new(grain_x + 0.5, centre.y + bh * text_size / 2.0 - text_size);
        pieces.push(Piece {
            name: panel.name.clone(),
            panels: placements,
            cut: gr.cut,
            sew,
            cut_line: cut,
            notches,
            grain,
            fold,
            internal,
            cutouts: ext.cutouts,
            mirror_lines: ext.mirror_lines,
            drill_holes: ext.drill_holes,
            label_at,
            text_size,
            labels: lines,
        });
    }
    Ok(pieces)
}

/// The cut list wording of a cut count.
fn opts_cut_text(c: Cut) -> &'static str {
    c.text()
}
