//! Where the box mesh starts a pleat's stitched vertices (format extension).
//!
//! A pleat ([`crate::inner::pleats`]) is written as a stitch between two consecutive,
//! collinear pieces of a panel's edge, each `depth` long: the fabric between their far
//! ends is folded under, and the pair `u` from where the pieces meet (the inner fold)
//! is sewn together. Averaged as any stitch is, every pair would start at the one
//! point where the pieces meet, in the panel's plane: the folded layers would lie
//! flat on each other, a simulator could not tell which way they fold, and they
//! cross. So, once the stitches are merged, each pair starts on a ridge behind the
//! panel (away from its outer face), `depth − u` deep: nothing where the pleat meets
//! the flat parts (the far ends' merged vertex, wherever the seam to the next piece
//! put it), the whole depth at the inner fold. The ridge runs from that merged vertex
//! and is shifted as it is; a box pleat's two folds share the vertex and their ridges
//! part towards their inner folds. Every pleat vertex keeps its pieces' 2D rest
//! lengths (its faces touch a stitch), so only the start changes.

use super::{GlobalStitch, HashMap, PanelMesh, StitchMesh};
use crate::{LineKind, PanelSpec, Vec2, Vec3};

/// A pleat stitch of one panel: where its pieces meet and how long they are.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tuck {
    /// Where the two stitched pieces meet: the inner fold (panel-local, cm).
    corner: Vec2,
    /// A piece's far end (panel-local): where the pleat meets a flat part.
    far: usize,
    /// The pleat's depth: the pieces' mean length (cm).
    depth: f64,
}

impl Tuck {
    /// The pleat of a stitch between edges `e0` and `e1` of one panel, if it is one:
    /// the panel has pleat lines, and the two outline edges meet at one end, running
    /// on in one straight line.
    fn of(spec: &PanelSpec, panel: &PanelMesh, e0: usize, e1: usize) -> Option<Tuck> {
        let pleated = spec.lines.iter().any(|l| matches!(l.kind, LineKind::PleatFold | LineKind::PleatPlacement));
        if !pleated || e0 >= spec.edges.len() || e1 >= spec.edges.len() {
            return None;
        }
        let ends = |e: usize| {
            let local = &panel.edges[e].local;
            (local[0], local[local.len() - 1])
        };
        let ((s0, t0), (s1, t1)) = (ends(e0), ends(e1));
        let (corner, far0, far1) = if t0 == s1 {
            (t0, s0, t1)
        } else if t1 == s0 {
            (t1, s1, t0)
        } else {
            return None;
        };
        let [c, f0, f1] = [corner, far0, far1].map(|l| panel.points[l]);
        let (a, b) = (c - f0, f1 - c);
        let straight = a.dot(b) > 0.0 && a.perp_dot(b).abs() <= 1e-6 * a.length() * b.length();
        straight.then(|| Tuck { corner: c, far: far0, depth: (a.length() + b.length()) / 2.0 })
    }
}

/// Move the merged vertices of every pleat stitch onto its ridge (see the module
/// documentation). Vertices that another stitch merged too are left where they are.
pub(super) fn raise_ridges(
    specs: &[&PanelSpec],
    panels: &[PanelMesh],
    stitches: &[StitchMesh],
    loc_glob: &HashMap<(usize, usize), usize>,
    globals: &mut [GlobalStitch],
) {
    for (k, s) in stitches.iter().enumerate() {
        let [(p, e0), (q, e1)] = s.sides;
        if p != q {
            continue;
        }
        let panel = &panels[p];
        let Some(tuck) = Tuck::of(specs[p], panel, e0, e1) else { continue };
        let top = loc_glob[&(p, tuck.far)];
        // Where the far ends' merged vertex would be without the other seams: the mean of
        // this panel's points in it (the pleat's middle for a knife pleat, the box
        // pleat's for a box pleat); the seams moved it by `top − mid`.
        let own: Vec<Vec2> = globals[top].members.iter().filter(|m| m.0 == p).map(|m| panel.points[m.1]).collect();
        let mid = panel.to_3d(own.iter().copied().sum::<Vec2>() / own.len() as f64);
        let origin = globals[top].pos;
        let toward_fold = panel.to_3d(tuck.corner) - mid;
        let outward = if panel.counter_clockwise { panel.rotation * Vec3::Z } else { -(panel.rotation * Vec3::Z) };
        for &l in panel.edges[e0].local.iter().chain(&panel.edges[e1].local) {
            let g = loc_glob[&(p, l)];
            if g == top || globals[g].labels.iter().any(|&j| j != k) {
                continue;
            }
            let deep = (tuck.depth - (panel.points[l] - tuck.corner).length()).clamp(0.0, tuck.depth);
            globals[g].pos = origin + toward_fold * (deep / tuck.depth) - outward * deep;
        }
    }
}
