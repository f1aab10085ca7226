//! The format extension on a piece (`docs/pattern-extension.md`): a panel's holes and
//! inner lines as what a cutting room needs, in the piece's grain frame. Cut-out
//! holes become internal cut-outs; darts, placement and pleat lines internal lines;
//! fold lines mirror lines; placement-line corners and dart points drill holes;
//! the ends of pleat lines on the outline notches.

use super::geom::{self, Xf};
use super::types::{Grained, Notch, slit};
use crate::math::Vec2;
use crate::pattern::{HoleKind, LineKind, PanelSpec};

/// Points per curved edge of the sampled holes and lines.
const STEPS: usize = 32;
/// How far (cm) a pleat line's end may be from the sew line and still get a notch.
const ON_OUTLINE: f64 = 0.05;
/// How far (cm) a drill hole sits from a dart's point, towards the dart's middle (at
/// most a third of the way), as the dart tips of seams are marked.
const DART_DRILL_INSET: f64 = 1.0;

/// What a panel's holes and inner lines add to its piece.
#[derive(Default)]
pub(super) struct InnerMarks {
    /// Darts (closed: the first point repeated), placement and pleat lines.
    pub internal: Vec<Vec<Vec2>>,
    /// Cut-out holes.
    pub cutouts: Vec<Vec<Vec2>>,
    /// Fold lines.
    pub mirror_lines: Vec<Vec<Vec2>>,
    /// Drill holes.
    pub drill_holes: Vec<Vec2>,
    /// Pleat notches.
    pub notches: Vec<Notch>,
}

/// The marks of `panel` (in its grain frame `g`) on a piece with sew line `sew` and
/// cut line `cut`; a notch reaches `reach` cm out to find the cut line.
pub(super) fn marks(panel: &PanelSpec, g: &Grained, sew: &[Vec2], cut: &[Vec2], reach: f64) -> InnerMarks {
    let xf: &Xf = &g.xf;
    let map = |pts: Vec<Vec2>| pts.into_iter().map(|q| xf.apply(q)).collect::<Vec<_>>();
    let mut out = InnerMarks::default();
    for hole in &panel.holes {
        let poly = map(hole.polygon(STEPS));
        match hole.kind {
            HoleKind::Cut => out.cutouts.push(poly),
            HoleKind::Dart => {
                let corners: Vec<Vec2> = hole.vertices.iter().map(|v| xf.apply(Vec2::from(*v))).collect();
                let middle = corners.iter().copied().sum::<Vec2>() / corners.len().max(1) as f64;
                out.drill_holes.extend(corners.iter().map(|c| {
                    let d = middle - *c;
                    *c + d.normalize_or_zero() * DART_DRILL_INSET.min(d.length() / 3.0)
                }));
                let mut closed = poly;
                closed.extend(closed.first().copied());
                out.internal.push(closed);
            }
        }
    }
    for line in &panel.lines {
        let pts = map(line.polyline(STEPS));
        match line.kind {
            LineKind::Fold { .. } => out.mirror_lines.push(pts),
            LineKind::Placement => {
                out.drill_holes.extend(line.vertices.iter().map(|v| xf.apply(Vec2::from(*v))));
                out.internal.push(pts);
            }
            LineKind::PleatFold | LineKind::PleatPlacement => {
                let n = pts.len();
                for (end, next) in [(0, 1), (n - 1, n.saturating_sub(2))] {
                    let at = pts[end];
                    if n >= 2 && geom::distance_to_closed(at, sew) <= ON_OUTLINE {
                        let out_dir = (at - pts[next]).normalize_or_zero();
                        out.notches.push(slit(at, out_dir * reach, cut, vec![(panel.name.clone(), nearest_edge(g, at))]));
                    }
                }
                out.internal.push(pts);
            }
        }
    }
    out
}

/// The outline edge of `g` nearest to `at`.
fn nearest_edge(g: &Grained, at: Vec2) -> usize {
    let distance = |k: usize| (0..=16).map(|i| (g.edges[k].point(i as f64 / 16.0) - at).length()).fold(f64::INFINITY, f64::min);
    (0..g.edges.len()).min_by(|a, b| distance(*a).total_cmp(&distance(*b))).unwrap_or(0)
}
