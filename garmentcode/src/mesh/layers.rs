//! Where the box mesh starts panels that a pattern places on top of each other in one plane.
//!
//! A garment program places each panel by its own rule, and some rules put several panels
//! in one plane over each other: the levels of a tiered skirt, each placed by the centre of
//! its top edge under the centre of the level above it, are rings of one plane that cover
//! each other when the levels are circle skirts. Two layers in one plane are exactly on
//! each other (a simulator cannot tell which is in front, and they cross as soon as they
//! move), and the seam between one level's hem and the next level's top joins edges many
//! cm apart, so its merged vertices, halfway, pull the seam faces across both panels.
//!
//! So, before the stitches are merged, a panel that overlaps another panel of its plane and
//! is sewn to one of them is turned and shifted in that plane so that its seam lies on the
//! seam of the panel it is sewn to (the rigid motion nearest in the least-squares sense
//! over the seam's paired vertices): a level continues the level above it, as the layout
//! of a tiered circle skirt does. The panels that stay are those of the overlapping set
//! sewn to a panel outside every such set (a tiered skirt's first level, sewn to the
//! skirt's base); the others follow them seam by seam, in stitch order. Panels that overlap
//! no other panel of their plane are not touched.

use std::collections::VecDeque;

use super::{PanelMesh, StitchMesh};
use crate::{Vec2, Vec3};

/// Two panels are in one plane when their normals are parallel and their planes' distance
/// is below this (cm).
const SAME_PLANE: f64 = 1e-6;

/// Whether two panels are placed in one plane (their local `z` axes parallel, either way).
fn same_plane(a: &PanelMesh, b: &PanelMesh) -> bool {
    let (na, nb) = (a.rotation * Vec3::Z, b.rotation * Vec3::Z);
    na.cross(nb).length() <= 1e-9 && na.dot(a.translation - b.translation).abs() <= SAME_PLANE
}

/// A point of the plane of panel `frame` in 2D: its coordinates along the placed panel's
/// local x and y axes.
fn in_plane(frame: &PanelMesh, x: Vec3) -> Vec2 {
    Vec2::new((frame.rotation * Vec3::X).dot(x), (frame.rotation * Vec3::Y).dot(x))
}

/// The outline of panel `p` (its first `n_outline_edges` edges' samples, a closed polygon)
/// in the 2D frame of `frame`'s plane.
fn outline(frame: &PanelMesh, p: &PanelMesh, n_outline_edges: usize) -> Vec<Vec2> {
    let mut out: Vec<Vec2> = Vec::new();
    for e in &p.edges[..n_outline_edges] {
        for &l in &e.local[..e.local.len() - 1] {
            out.push(in_plane(frame, p.to_3d(p.points[l])));
        }
    }
    out
}

/// Even–odd rule.
fn inside(poly: &[Vec2], q: Vec2) -> bool {
    let mut odd = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            odd = !odd;
        }
    }
    odd
}

/// Whether two panels of one plane cover each other: their outlines' boxes overlap and a
/// face centre of one lies inside the other's outline.
fn overlap(frame: &PanelMesh, a: &PanelMesh, na: usize, b: &PanelMesh, nb: usize) -> bool {
    let centres = |p: &PanelMesh| -> Vec<Vec2> {
        p.faces.iter().map(|f| in_plane(frame, p.to_3d((p.points[f[0]] + p.points[f[1]] + p.points[f[2]]) / 3.0))).collect()
    };
    let (oa, ob) = (outline(frame, a, na), outline(frame, b, nb));
    let bounds =
        |o: &[Vec2]| o.iter().fold((Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
    let ((la, ha), (lb, hb)) = (bounds(&oa), bounds(&ob));
    if la.x >= hb.x || lb.x >= ha.x || la.y >= hb.y || lb.y >= ha.y {
        return false;
    }
    centres(a).into_iter().any(|c| inside(&ob, c)) || centres(b).into_iter().any(|c| inside(&oa, c))
}

/// The vertex pairs of stitch `s` (local ids of side 0 and side 1), as the merging pairs them.
fn pairs(panels: &[PanelMesh], s: &StitchMesh) -> Vec<(usize, usize)> {
    let [(p0, e0), (p1, e1)] = s.sides;
    let mut r0 = panels[p0].edges[e0].local.clone();
    if !s.right_wrong {
        r0.reverse();
    }
    r0.into_iter().zip(panels[p1].edges[e1].local.iter().copied()).collect()
}

/// Turns and shifts panel `p` in its plane so that its points `from` (local ids) come
/// nearest, in the least-squares sense, to the placed points `to` (3D, in its plane).
fn fit(p: &mut PanelMesh, from: &[usize], to: &[Vec3]) {
    let a: Vec<Vec2> = from.iter().map(|&l| in_plane(p, p.to_3d(p.points[l]))).collect();
    let b: Vec<Vec2> = to.iter().map(|&x| in_plane(p, x)).collect();
    let n = a.len() as f64;
    let (ca, cb) = (a.iter().sum::<Vec2>() / n, b.iter().sum::<Vec2>() / n);
    let (mut dot, mut cross) = (0.0, 0.0);
    for (x, y) in a.iter().zip(&b) {
        dot += (*x - ca).dot(*y - cb);
        cross += (*x - ca).perp_dot(*y - cb);
    }
    let angle = cross.atan2(dot);
    let (u, v, normal) = (p.rotation * Vec3::X, p.rotation * Vec3::Y, p.rotation * Vec3::Z);
    let offset = normal * normal.dot(p.translation);
    let (from_c, to_c) = (u * ca.x + v * ca.y + offset, u * cb.x + v * cb.y + offset);
    let turn = glam::DMat3::from_axis_angle(normal, angle);
    p.rotation = turn * p.rotation;
    p.translation = turn * (p.translation - from_c) + to_c;
    p.grain = p.rotation * Vec3::Y;
}

/// Moves the panels that overlap another panel of their plane (see the module
/// documentation). `n_outline` is each panel's number of outline edges.
pub(super) fn separate(panels: &mut [PanelMesh], n_outline: &[usize], stitches: &[StitchMesh]) {
    let n = panels.len();
    let mut layered = vec![false; n];
    for a in 0..n {
        for b in a + 1..n {
            if same_plane(&panels[a], &panels[b]) && overlap(&panels[a], &panels[a], n_outline[a], &panels[b], n_outline[b]) {
                layered[a] = true;
                layered[b] = true;
            }
        }
    }
    if !layered.contains(&true) {
        return;
    }
    if std::env::var("LAYERS_DEBUG").is_ok() {
        eprintln!("layered: {:?}", (0..n).filter(|&p| layered[p]).map(|p| &panels[p].name).collect::<Vec<_>>());
    }
    // The panels that stay: layered, sewn to a panel that is not.
    let mut placed: Vec<bool> = (0..n)
        .map(|p| layered[p] && stitches.iter().any(|s| s.sides.iter().any(|&(q, _)| q == p) && s.sides.iter().any(|&(q, _)| !layered[q])))
        .collect();
    let mut queue: VecDeque<usize> = (0..n).filter(|&p| placed[p]).collect();
    let mut depth = vec![0usize; n];
    while let Some(p) = queue.pop_front() {
        for s in stitches {
            let [(p0, _), (p1, _)] = s.sides;
            let (q, q_is_0) = if p0 == p && p1 != p {
                (p1, false)
            } else if p1 == p && p0 != p {
                (p0, true)
            } else {
                continue;
            };
            if placed[q] || !layered[q] || !same_plane(&panels[p], &panels[q]) {
                continue;
            }
            let (from, to): (Vec<usize>, Vec<Vec3>) = pairs(panels, s)
                .into_iter()
                .map(
                    |(l0, l1)| {
                        if q_is_0 { (l0, panels[p].to_3d(panels[p].points[l1])) } else { (l1, panels[p].to_3d(panels[p].points[l0])) }
                    },
                )
                .unzip();
            fit(&mut panels[q], &from, &to);
            depth[q] = depth[p] + 1;
            if let Ok(g) = std::env::var("LAYERS_GAP") {
                let g: f64 = g.parse().unwrap();
                let facing = if panels[q].counter_clockwise { panels[q].rotation * Vec3::Z } else { -(panels[q].rotation * Vec3::Z) };
                panels[q].translation -= facing * g * depth[q] as f64;
            }
            if std::env::var("LAYERS_DEBUG").is_ok() {
                let r: f64 = from.iter().zip(&to).map(|(&l, x)| (panels[q].to_3d(panels[q].points[l]) - *x).length()).sum::<f64>()
                    / from.len() as f64;
                eprintln!("moved {} onto {}: mean residual {r:.2} cm", panels[q].name, panels[p].name);
            }
            placed[q] = true;
            queue.push_back(q);
        }
    }
}
