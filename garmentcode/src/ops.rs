//! Operators on edge sequences and panels: shape factories (darts, sides with cuts),
//! projecting a shape into an edge or onto a corner, distributing copies, and the
//! sleeve-opening balancing.

use crate::arena::EdgeSeq;
use crate::arena::{Arena, EdgeId, InterfaceId, PanelId, VertexId};
use crate::component::{PanelPart, PartExt};
use crate::edge::{Curve, Segment};
use crate::error::{Error, Result};
use crate::intersect;
use crate::math::{SignumOrZero, Vec2, Vec3, close_enough, cross, norm, vector_angle};
use crate::parity::svgpath::{Num, Seg, try_intersect_as};
use crate::remap::Remap;
use crate::rotation::Rotation;

/// Size of a triangular dart besides its width.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DartSize {
    /// Length of each leg.
    Side(f64),
    /// Distance from the opening to the tip.
    Depth(f64),
}

/// The open triangle `(0,0) → (width/2, −depth) → (width, 0)`: a dart, slit or cut
/// shape whose tip points to the right of its opening direction.
///
/// ```
/// use garmentcode::ops::{DartSize, dart_shape};
/// use garmentcode::{Arena, Vec2};
///
/// let mut a = Arena::new();
/// let dart = dart_shape(&mut a, 4.0, DartSize::Depth(10.0))?;
/// assert_eq!(dart.vert_positions(&a), [Vec2::ZERO, Vec2::new(2.0, -10.0), Vec2::new(4.0, 0.0)]);
/// let by_side = dart_shape(&mut a, 6.0, DartSize::Side(5.0))?;
/// assert_eq!(by_side.vert_positions(&a)[1], Vec2::new(3.0, -4.0));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn dart_shape(a: &mut Arena, width: f64, size: DartSize) -> Result<EdgeSeq> {
    let depth = match size {
        DartSize::Depth(d) => d,
        DartSize::Side(side) => {
            if width / 2.0 > side {
                return Err(Error::Dart(format!("width {width} with side length {side} does not form a triangle")));
            }
            (side * side - (width / 2.0) * (width / 2.0)).sqrt()
        }
    };
    EdgeSeq::from_points(a, &[Vec2::ZERO, Vec2::new(width / 2.0, -depth), Vec2::new(width, 0.0)], false)
}

/// A straight side from `start` to `end` with extra vertices at fraction
/// `start_cut` after the start and `end_cut` before the end (when positive), so
/// that only part of the side can be stitched.
pub fn side_with_cut(a: &mut Arena, start: VertexId, end: VertexId, start_cut: f64, end_cut: f64) -> Result<EdgeSeq> {
    let (s, e) = (a.pos(start), a.pos(end));
    let mut verts = vec![start];
    if start_cut > 0.0 {
        verts.push(a.vertex(s + start_cut * (e - s)));
    }
    if end_cut > 0.0 {
        verts.push(a.vertex(e - end_cut * (e - s)));
    }
    verts.push(end);
    EdgeSeq::polyline(a, &verts, false)
}

/// Which side of an edge, looking along its direction, a shape is cut into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeSide {
    /// To the right of `start → end`.
    Right,
    /// To the left of `start → end`.
    Left,
}

/// How [`cut_many_into_edge`] takes its shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeOrder {
    /// As drawn.
    AsDrawn,
    /// Mirrored (their order along the edge reversed) first.
    Mirrored,
}

/// Result of [`cut_into_edge`] (and of [`PanelId::add_dart`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Cut {
    /// Every edge replacing the base edge, in order.
    pub edges: EdgeSeq,
    /// The inserted shape's edges.
    pub shape: EdgeSeq,
    /// What is left of the base edge (zero, one or two pieces).
    pub leftovers: EdgeSeq,
}

/// Insert a copy of `shape` (an open chain) into `base`, centred at arc length
/// `offset` from its start, rotated so its opening lies along the edge and placed on
/// the given `side` of the edge direction. The base edge itself is not changed;
/// the caller substitutes [`Cut::edges`] for it where needed.
///
/// ```
/// use garmentcode::ops::{DartSize, EdgeSide, cut_into_edge, dart_shape};
/// use garmentcode::{Arena, EdgeSeq, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 20.0), Vec2::new(20.0, 20.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("square", edges.clone());
/// let dart = dart_shape(&mut a, 4.0, DartSize::Depth(5.0))?;
/// // A dart in the middle of the bottom edge (20 cm from (20, 0) to (0, 0)), into the panel.
/// let bottom = edges[3];
/// let cut = cut_into_edge(&mut a, &dart, bottom, 10.0, EdgeSide::Right)?;
/// assert_eq!((cut.leftovers.len(), cut.shape.len(), cut.edges.len()), (2, 2, 4));
/// assert_eq!(cut.leftovers.length(&a), 16.0);
/// assert_eq!(cut.shape.vert_positions(&a)[1], Vec2::new(10.0, 5.0));
/// panel.edges_mut(&mut a).substitute(bottom, &cut.edges)?;
/// assert!(panel.edges(&a).is_loop(&a));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn cut_into_edge(a: &mut Arena, shape: &EdgeSeq, base: EdgeId, offset: f64, side: EdgeSide) -> Result<Cut> {
    let right = side == EdgeSide::Right;
    const TOL: f64 = 1e-2;
    let mut new_edges = shape.copy(a);
    new_edges.snap_to(a, Vec2::ZERO);
    let (s0, s1) = new_edges.shortcut(a);
    let width = norm(s1 - s0);
    let base_geom = a.geom(base);
    let edge_len = base_geom.length();
    if offset < width / 2.0 - TOL || offset > edge_len - width / 2.0 + TOL {
        return Err(Error::Cut(format!(
            "a shape of width {width:.3} cm centred at {offset:.3} cm does not fit an edge of length {edge_len:.3} cm"
        )));
    }
    let curve = base_geom.segment();
    let t = curve
        .inverse_length(offset)
        .ok_or_else(|| Error::Cut(format!("offset {offset:.3} cm is outside the edge (length {edge_len:.3} cm)")))?;
    let (shift, fun) = fit_location_on_edge(&curve, t, width);
    if !close_enough(fun, 0.0, 0.01) {
        return Err(Error::Cut(format!("the shape cannot be placed on the edge (residual {fun:.4})")));
    }
    if t + shift[0] > 1.0 + TOL || t - shift[1] < -TOL {
        return Err(Error::Cut(format!("the shape extends past the edge (parameters {:.4}..{:.4})", t - shift[1], t + shift[0])));
    }
    let base_start = a.start(base);
    let base_end = a.end(base);
    let ins_at_start = t - shift[1] <= TOL;
    let fin_at_end = t + shift[0] >= 1.0 - TOL;
    let ins_point = if ins_at_start { a.pos(base_start) } else { curve.point(t - shift[1]) };
    let fin_point = if fin_at_end { a.pos(base_end) } else { curve.point(t + shift[0]) };
    let insert_vector = fin_point - ins_point;
    let angle = vector_angle(s1 - s0, insert_vector);
    new_edges.rotate(a, angle);
    new_edges.snap_to(a, ins_point);

    let verts = new_edges.vert_positions(a);
    let mut avg = Vec2::ZERO;
    for v in &verts {
        avg += *v;
    }
    avg /= verts.len() as f64;
    let first = a.pos(a.start(new_edges[0]));
    let on_right = cross(insert_vector, avg - first).signum_or_zero() == -1.0;
    if on_right != right {
        let (p0, p1) = new_edges.shortcut(a);
        new_edges.reflect(a, p0, p1);
    }

    let mut leftovers = EdgeSeq::new();
    let (mut start_id, mut end_id): (isize, isize) = (0, new_edges.len() as isize);
    if ins_at_start {
        a.set_start(new_edges[0], base_start);
    } else {
        let cut_t = t - shift[1];
        let part = a.subdivide(base, &[cut_t, 1.0 - cut_t], false)?[0];
        a.set_end(part, a.start(new_edges[0]));
        new_edges.insert(0, part);
        leftovers.push(part);
        start_id = 1;
    }
    if fin_at_end {
        let last = new_edges.last_edge();
        a.set_end(last, base_end);
    } else {
        let cut_t = t + shift[0];
        let pieces = a.subdivide(base, &[cut_t, 1.0 - cut_t], false)?;
        let part = *pieces.last().expect("two pieces");
        a.set_start(part, a.end(new_edges.last_edge()));
        new_edges.push(part);
        leftovers.push(part);
        end_id = -1;
    }
    // Reference quirk kept: the end index was taken before a start piece was
    // prepended, so a cut touching only the edge end drops its last shape edge here.
    let shape_edges = new_edges.slice(start_id, end_id);
    Ok(Cut { edges: new_edges, shape: shape_edges, leftovers })
}

/// Several shapes (drawn in one frame with vertical openings) cut into one edge,
/// keeping their relative positions.
pub fn cut_many_into_edge(a: &mut Arena, shapes: &[EdgeSeq], base: EdgeId, offset: f64, side: EdgeSide, order: ShapeOrder) -> Result<Cut> {
    let flip = order == ShapeOrder::Mirrored;
    let ys = |a: &Arena, s: &EdgeSeq| {
        let (p, q) = s.shortcut(a);
        (p.y, q.y)
    };
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for s in shapes {
        let (y0, y1) = ys(a, s);
        lo = lo.min(y0.min(y1));
        hi = hi.max(y0.max(y1));
    }
    let median = (hi + lo) / 2.0;
    let mut shapes: Vec<EdgeSeq> = shapes.to_vec();
    if flip {
        shapes = shapes
            .iter()
            .map(|s| {
                let mut c = s.copy(a);
                c.reflect(a, Vec2::new(0.0, median), Vec2::new(1.0, median));
                c.reverse(a);
                c
            })
            .collect();
    }
    let mut placed: Vec<(f64, usize)> = shapes
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (y0, y1) = ys(a, s);
            (offset + ((y0 + y1) / 2.0 - median), i)
        })
        .collect();
    // From the farthest to the closest, each into the first remaining piece.
    placed.sort_by(|x, y| y.0.partial_cmp(&x.0).unwrap_or(std::cmp::Ordering::Equal).then(y.1.cmp(&x.1)));
    let mut proj_edge = base;
    let mut leftovers = EdgeSeq(vec![base]);
    let mut all = EdgeSeq(vec![base]);
    let mut shape_edges = EdgeSeq::new();
    for (off, i) in placed {
        let cut = cut_into_edge(a, &shapes[i], proj_edge, off, side)?;
        all.substitute(proj_edge, &cut.edges)?;
        leftovers.substitute(proj_edge, &cut.leftovers)?;
        shape_edges.extend(cut.shape.iter().copied());
        proj_edge = cut.edges[0];
    }
    Ok(Cut { edges: all, shape: shape_edges, leftovers })
}

/// Shifts `(s0, s1)` such that the points `C(t + s0)` and `C(t − s1)` are `width`
/// apart and equally far from `C(t)`: the zero of the reference's objective, found
/// by Newton's method. Returns the shifts and the objective value there.
fn fit_location_on_edge(curve: &Segment, t: f64, width: f64) -> ([f64; 2], f64) {
    let pc = curve.point(t);
    let residual = |s: [f64; 2]| {
        let p1 = curve.point(t + s[0]);
        let p2 = curve.point(t - s[1]);
        [norm(p1 - p2) - width, norm(p1 - pc) - norm(p2 - pc)]
    };
    let objective = |r: [f64; 2]| r[0] * r[0] + r[1] * r[1];
    let speed = norm(curve.derivative(t)).max(1e-12);
    let mut s = [width / (2.0 * speed); 2];
    let mut r = residual(s);
    for _ in 0..60 {
        if objective(r) < 1e-28 {
            break;
        }
        let p1 = curve.point(t + s[0]);
        let p2 = curve.point(t - s[1]);
        let d1 = curve.derivative(t + s[0]);
        let d2 = curve.derivative(t - s[1]);
        let u = (p1 - p2) / norm(p1 - p2);
        let u1 = (p1 - pc) / norm(p1 - pc);
        let u2 = (p2 - pc) / norm(p2 - pc);
        let j = [[u.dot(d1), u.dot(d2)], [u1.dot(d1), u2.dot(d2)]];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let ds = [(r[0] * j[1][1] - r[1] * j[0][1]) / det, (j[0][0] * r[1] - j[1][0] * r[0]) / det];
        // Damped step: never leave the feasible box [0, 1] and never increase the residual.
        let mut step = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let cand = [(s[0] - step * ds[0]).clamp(0.0, 1.0), (s[1] - step * ds[1]).clamp(0.0, 1.0)];
            let rc = residual(cand);
            if objective(rc) < objective(r) {
                s = cand;
                r = rc;
                accepted = true;
                break;
            }
            step *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    (s, objective(r))
}

/// Result of [`cut_corner`].
#[derive(Clone, Debug, PartialEq)]
pub struct CornerCut {
    /// The inserted copy of the shape, in the panel's loop.
    pub shape: EdgeSeq,
    /// A new interface of the panel over the inserted shape.
    pub interface: InterfaceId,
}

/// Replace the corner between the two edges of `corner` (an interface of one panel)
/// by a copy of `shape`, placed so that its opening vector spans the corner. Every
/// interface of the panel that used the corner edges now uses their remaining
/// pieces; a new interface of the panel over the inserted shape is returned with
/// the shape's edges.
///
/// ```
/// use garmentcode::ops::cut_corner;
/// use garmentcode::{Arena, EdgeSeq, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 20.0), Vec2::new(20.0, 20.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("square", edges.clone());
/// let top = a.interface(panel, edges[1]);
/// // The top-left corner: the end of the left side and the start of the top.
/// let corner = a.interface(panel, edges.slice(0, 2));
/// let notch = EdgeSeq::from_points(&mut a, &[Vec2::ZERO, Vec2::new(3.0, 1.0), Vec2::new(4.0, 4.0)], false)?;
/// let cut = cut_corner(&mut a, &notch, corner)?;
/// assert_eq!((cut.shape.len(), panel.edges(&a).len()), (2, 6));
/// assert_eq!(cut.interface.edges(&a), &cut.shape);
/// // The top interface now holds what is left of the top edge.
/// assert!(top.length(&a) < 20.0);
/// assert!(panel.edges(&a).is_loop(&a));
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn cut_corner(a: &mut Arena, shape: &EdgeSeq, corner: InterfaceId) -> Result<CornerCut> {
    let mut corner_shape = shape.copy(a);
    let panel: PanelId = corner.panels(a)[0];
    {
        let targets = &a.iface(corner).edges;
        let (t0, tl) = (targets[0], targets.last_edge());
        if a.start(t0) == a.end(tl) {
            // The corner was reversed by orientation fixes: restore its order.
            a.iface_mut(corner).edges.0.reverse();
        }
    }
    if a.start(corner_shape[0]) == a.end(corner_shape.last_edge()) {
        corner_shape.0.reverse();
    }
    if a.pos(a.start(corner_shape[0])).y > a.pos(a.end(corner_shape.last_edge())).y {
        corner_shape.reverse(a);
        corner_shape.snap_to(a, Vec2::ZERO);
    }
    let (sc0, sc1) = corner_shape.shortcut(a);
    let opening = sc1 - sc0;
    let targets = a.iface(corner).edges.clone();
    let (e0, e1) = (targets[0], targets[1]);
    let (mut c1, mut c2) = (a.geom(e0).segment(), a.geom(e1).segment());
    let swapped = a.pos(a.start(e0)).y > a.pos(a.end(targets.last_edge())).y;
    if swapped {
        std::mem::swap(&mut c1, &mut c2);
    }
    let mut loc = fit_location_on_corner(&c1, &c2, opening);
    let point1 = c1.point(loc[0]);
    corner_shape.snap_to(a, point1);
    if swapped {
        corner_shape.reverse(a);
        loc.swap(0, 1);
    }
    let cut1 = a.subdivide(e0, &[loc[0], 1.0 - loc[0]], false)?[0];
    let cut2 = a.subdivide(e1, &[loc[1], 1.0 - loc[1]], false)?[1];
    a.set_end(cut1, a.start(corner_shape[0]));
    a.set_start(cut2, a.end(corner_shape.last_edge()));
    corner_shape.insert(0, cut1);
    corner_shape.push(cut2);

    let mut loop_edges = std::mem::take(panel.edges_mut(a));
    let res = loop_edges.remove_edge(e0).and_then(|_| loop_edges.substitute(e1, &corner_shape));
    *panel.edges_mut(a) = loop_edges;
    res?;
    let registered: Vec<InterfaceId> = panel.interfaces(a).to_vec();
    for i in registered {
        i.replace_edge(a, e0, cut1);
        i.replace_edge(a, e1, cut2);
    }
    let inserted = corner_shape.slice(1, -1);
    let interface = a.interface(panel, inserted.clone());
    Ok(CornerCut { shape: inserted, interface })
}

/// Parameters `(l0, l1)` in `[0, 1]²` minimising `|c2(l1) − c1(l0) − opening|²`.
/// For straight edges (the only case in garment programs) this is a box-constrained
/// linear least-squares problem solved exactly; curved edges use projected
/// Gauss–Newton.
fn fit_location_on_corner(c1: &Segment, c2: &Segment, opening: Vec2) -> [f64; 2] {
    let res = |l: [f64; 2]| c2.point(l[1]) - c1.point(l[0]) - opening;
    let obj = |l: [f64; 2]| res(l).length_squared();
    if let (Segment::Line(s1, e1), Segment::Line(s2, e2)) = (c1, c2) {
        // r(l) = (s2 − s1 − opening) + l1·d2 − l0·d1
        let (d1, d2) = (*e1 - *s1, *e2 - *s2);
        let b = *s2 - *s1 - opening;
        let min_1d = |dir: Vec2, rest: Vec2| -> f64 {
            // minimise |rest + x·dir|² over x in [0, 1]
            let dd = dir.dot(dir);
            if dd == 0.0 { 0.0 } else { (-(rest.dot(dir)) / dd).clamp(0.0, 1.0) }
        };
        let det = cross(-d1, d2);
        if det != 0.0 {
            // Solve l0·(−d1) + l1·d2 = −b.
            let l0 = cross(-b, d2) / det;
            let l1 = cross(-d1, -b) / det;
            if (0.0..=1.0).contains(&l0) && (0.0..=1.0).contains(&l1) {
                return [l0, l1];
            }
        }
        let mut best = [0.0, 0.0];
        let mut best_f = f64::INFINITY;
        for fixed in [0.0, 1.0] {
            let l1 = min_1d(d2, b - fixed * d1);
            let cand = [fixed, l1];
            let f = obj(cand);
            if f < best_f {
                best_f = f;
                best = cand;
            }
            let l0 = min_1d(-d1, b + fixed * d2);
            let cand = [l0, fixed];
            let f = obj(cand);
            if f < best_f {
                best_f = f;
                best = cand;
            }
        }
        return best;
    }
    let mut l = [0.5, 0.5];
    for _ in 0..100 {
        let r = res(l);
        let j0 = -c1.derivative(l[0]);
        let j1 = c2.derivative(l[1]);
        let (a11, a12, a22) = (j0.dot(j0), j0.dot(j1), j1.dot(j1));
        let (g0, g1) = (j0.dot(r), j1.dot(r));
        let det = a11 * a22 - a12 * a12;
        if det.abs() < 1e-300 {
            break;
        }
        let step = [(a22 * g0 - a12 * g1) / det, (a11 * g1 - a12 * g0) / det];
        let next = [(l[0] - step[0]).clamp(0.0, 1.0), (l[1] - step[1]).clamp(0.0, 1.0)];
        if obj(next) >= obj(l) {
            break;
        }
        l = next;
    }
    l
}

/// Copies of a panel (or panel class) distributed around the world y axis: the
/// original is renamed `<tag>_0`, copy `i` is copy `i−1` rotated by 360°/n about y.
/// Each copy is the same type as the original, with its own interfaces.
///
/// ```
/// use garmentcode::ops::distribute_y;
/// use garmentcode::{Arena, EdgeSeq, Vec2, Vec3};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 20.0), Vec2::new(20.0, 20.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("square", edges.clone());
/// panel.translate_to(&mut a, Vec3::new(0.0, 0.0, 30.0));
/// let gores = distribute_y(&mut a, panel, 4, "gore");
/// assert_eq!(gores.iter().map(|p| p.name(&a)).collect::<Vec<_>>(), ["gore_0", "gore_1", "gore_2", "gore_3"]);
/// // A quarter turn each: the second gore sits on the +x side.
/// assert!((gores[1].translation(&a) - Vec3::new(30.0, 0.0, 0.0)).length() < 1e-9);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn distribute_y<T: PanelPart + Remap>(a: &mut Arena, first: T, n: usize, tag: &str) -> Vec<T> {
    first.panel_id().set_name(a, &format!("{tag}_0"));
    let q = Rotation::from_euler_xyz_degrees([0.0, 360.0 / n as f64, 0.0]);
    let mut out = vec![first];
    for i in 1..n {
        let copy = out.last().expect("at least one panel").deep_copy(a);
        let p = copy.panel_id();
        p.set_name(a, &format!("{tag}_{i}"));
        p.rotate_by(a, q);
        let t = q.apply(p.translation(a));
        p.translate_to(a, t);
        out.push(copy);
    }
    out
}

/// Copies of a panel (or panel class) in a horizontal row, `stride` apart along the
/// horizontal direction in the panel plane: the original is renamed `<tag>_0`.
pub fn distribute_horizontally<T: PanelPart + Remap>(a: &mut Arena, first: T, n: usize, stride: f64, tag: &str) -> Vec<T> {
    let panel = first.panel_id();
    panel.set_name(a, &format!("{tag}_0"));
    let dir = panel.rotation(a).apply(Vec3::Z).cross(Vec3::Y);
    let delta = dir / dir.length() * stride;
    let mut out = vec![first];
    for i in 1..n {
        let copy = out.last().expect("at least one panel").deep_copy(a);
        let p = copy.panel_id();
        p.set_name(a, &format!("{tag}_{i}"));
        p.translate_by(a, delta);
        out.push(copy);
    }
    out
}

/// Make the front and back sleeve openings span the same height (so two symmetric
/// sleeve panels can be built): if needed, the part of the front opening beyond the
/// balance line is moved to the back opening; then both are turned upright.
pub fn even_armhole_openings(a: &mut Arena, front: &mut EdgeSeq, back: &mut EdgeSeq, tol: f64) -> Result<()> {
    let cfront = front.copy(a);
    let mut cback = back.copy(a);
    cback.reflect(a, Vec2::ZERO, Vec2::X);
    cback.reverse(a);
    let front_end = a.pos(a.end(cfront.last_edge()));
    cback.snap_to(a, front_end);
    let s0 = a.pos(a.start(cfront[0]));
    let s1 = a.pos(a.end(cback.last_edge()));
    let slope = s1 - s0;
    let slope_perp = Vec2::new(-slope.y, slope.x);
    let mid = (s0 + s1) / 2.0;
    let (l0, l1) = (mid - 20.0 * slope_perp, mid + 20.0 * slope_perp);
    let line = Seg::Line([[l0.x, l0.y], [l1.x, l1.y]]);
    let target = intersect::to_seg(&a.geom(cfront.last_edge()).segment());
    // The reference builds this line from Python complex numbers, the curve from numpy ones.
    let hits = try_intersect_as(&target, Num::Numpy, &line, Num::Python)
        .map_err(|e| Error::Geometry(format!("balancing the sleeve openings: {e}")))?;
    if let Some(&(t, _)) = hits.first() {
        if !(close_enough(t, 0.0, tol) || close_enough(t, 1.0, tol)) {
            let last = front.last_edge();
            let pieces = a.subdivide(last, &[t, 1.0 - t], false)?;
            let n = front.len();
            front.substitute_at(n - 1, &pieces[..1]);
            // The moved part gets vertices of its own.
            let moved = pieces[1];
            let (ps, pe) = (a.pos(a.start(moved)), a.pos(a.end(moved)));
            let (vs, ve) = (a.vertex(ps), a.vertex(pe));
            a.set_start(moved, vs);
            a.set_end(moved, ve);
            let mut m = EdgeSeq(vec![moved]);
            m.reflect(a, Vec2::ZERO, Vec2::X);
            m.reverse(a);
            let back_end = a.end(back.last_edge());
            m.snap_to(a, a.pos(back_end));
            a.set_start(moved, back_end);
            back.push(moved);
        }
    }
    let angle = (-slope.x / slope.y).atan();
    front.rotate(a, -angle);
    back.rotate(a, angle);
    Ok(())
}

/// A straight edge between two existing vertices, as a one-edge sequence.
pub fn line_between(a: &mut Arena, s: VertexId, e: VertexId) -> Result<EdgeId> {
    a.edge(s, e, Curve::Line)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn dart_into_straight_edge() {
        let mut a = Arena::new();
        let base = a.line(v(0., 0.), v(20., 0.)).unwrap();
        let dart = dart_shape(&mut a, 4.0, DartSize::Depth(6.0)).unwrap();
        let cut = cut_into_edge(&mut a, &dart, base, 10.0, EdgeSide::Right).unwrap();
        assert_eq!(cut.edges.len(), 4);
        assert_eq!(cut.shape.len(), 2);
        assert_eq!(cut.leftovers.len(), 2);
        assert!(cut.edges.is_chained(&a));
        let tip = a.pos(a.end(cut.shape[0]));
        assert!((tip - v(10., -6.)).length() < 1e-9, "tip {tip}");
        assert!((a.pos(a.start(cut.shape[0])) - v(8., 0.)).length() < 1e-9);
        // Same shape on the left of the edge.
        let cut = cut_into_edge(&mut a, &dart, base, 10.0, EdgeSide::Left).unwrap();
        assert!((a.pos(a.end(cut.shape[0])) - v(10., 6.)).length() < 1e-9);
        // Too close to the end.
        assert!(cut_into_edge(&mut a, &dart, base, 1.0, EdgeSide::Right).is_err());
    }

    #[test]
    fn dart_into_curved_edge_keeps_width() {
        let mut a = Arena::new();
        let s = a.vertex(v(0., 0.));
        let e = a.vertex(v(20., 0.));
        let base = a.edge(s, e, Curve::Quadratic(v(0.5, -0.2))).unwrap();
        let dart = dart_shape(&mut a, 3.0, DartSize::Side(5.0)).unwrap();
        let cut = cut_into_edge(&mut a, &dart, base, 9.0, EdgeSide::Right).unwrap();
        let p = a.pos(a.start(cut.shape[0]));
        let q = a.pos(a.end(cut.shape[1]));
        assert!(((p - q).length() - 3.0).abs() < 1e-9);
        assert!(cut.edges.is_chained(&a));
        assert_eq!(a.start(cut.edges[0]), s);
        assert_eq!(a.end(cut.edges.last_edge()), e);
    }

    #[test]
    fn corner_cut_replaces_corner() {
        let mut a = Arena::new();
        let mut edges = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(10., 0.), v(10., 10.), v(0., 10.)], true).unwrap();
        let p = a.new_panel("p");
        p.set_edges(&mut a, edges.clone());
        let corner = a.interface(p, EdgeSeq(vec![edges[0], edges[1]]));
        let shape = EdgeSeq::from_points(&mut a, &[v(0., 0.), v(3., 1.), v(4., 4.)], false).unwrap();
        let CornerCut { shape: inserted, interface: int } = cut_corner(&mut a, &shape, corner).unwrap();
        assert_eq!(inserted.len(), 2);
        let loop_edges = p.edges(&a).clone();
        assert_eq!(loop_edges.len(), 6);
        assert!(loop_edges.is_loop(&a) && loop_edges.is_chained(&a));
        assert_eq!(p.interfaces(&a), &[corner, int], "the new interface belongs to the panel");
        let start = a.pos(a.start(inserted[0]));
        let end = a.pos(a.end(inserted[1]));
        assert!((end - start - v(4., 4.)).length() < 1e-9);
        assert!(start.y.abs() < 1e-12 && (end.x - 10.0).abs() < 1e-12);
        edges.clear();
    }
}
