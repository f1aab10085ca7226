//! `panel_order`: a deterministic ordering of panels by their 3D location (x, then y,
//! then z, with a 10 cm fuzzy grouping), computed exactly as the reference does
//! (including its use of the `Rz·Ry·Rx` convention for the stored angles).

use super::{EdgePlace, InnerSide, InnerStitch, PanelSpec, Pattern, StitchSide, StitchSpec};
use crate::math::Vec3;
use crate::rotation::matrix_zyx_from_degrees;
use crate::stitch::StitchRecord;

impl Pattern {
    /// Pattern from assembled panels and stitch records, with its panel order.
    pub fn from_parts(name: &str, panels: Vec<PanelSpec>, stitches: Vec<StitchRecord>) -> Pattern {
        let mut p = Pattern::new(name);
        p.panels = panels;
        for r in stitches {
            if r.places == [EdgePlace::Outline; 2] {
                p.stitches.push(StitchSpec { sides: r.sides.map(|(panel, edge)| StitchSide { panel, edge }), right_wrong: r.right_wrong });
            } else {
                let [(p0, e0), (p1, e1)] = r.sides;
                let sides = [InnerSide { panel: p0, place: r.places[0], edge: e0 }, InnerSide { panel: p1, place: r.places[1], edge: e1 }];
                p.inner_stitches.push(InnerStitch { sides, right_wrong: r.right_wrong });
            }
        }
        if !p.panels.is_empty() {
            p.panel_order = Some(panel_order(&p));
        }
        p
    }
}

/// Group tolerance of the fuzzy sort, in cm.
const TOLERANCE: f64 = 10.0;

/// Panel names ordered by location.
pub fn panel_order(p: &Pattern) -> Vec<String> {
    let locations: Vec<(String, Vec3)> = p.panels.iter().map(|panel| (panel.name.clone(), universal_translation(panel))).collect();
    let names: Vec<usize> = (0..locations.len()).collect();
    order(&names, &locations, 0).into_iter().map(|i| locations[i].0.clone()).collect()
}

/// World position of the midpoint of the (vertex) bounding-box side that is highest
/// in 3D.
fn universal_translation(panel: &super::PanelSpec) -> Vec3 {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for v in &panel.vertices {
        for k in 0..2 {
            lo[k] = lo[k].min(v[k]);
            hi[k] = hi[k].max(v[k]);
        }
    }
    let mid = [(hi[0] + lo[0]) / 2.0, (hi[1] + lo[1]) / 2.0];
    let candidates = [[mid[0], hi[1]], [mid[0], lo[1]], [hi[0], mid[1]], [lo[0], mid[1]]];
    let r = matrix_zyx_from_degrees(panel.rotation);
    let t = Vec3::from(panel.translation);
    let mut best = Vec3::splat(f64::NAN);
    let mut best_y = f64::NEG_INFINITY;
    for c in candidates {
        let w = r * Vec3::new(c[0], c[1], 0.0) + t;
        if w.y > best_y || best.x.is_nan() {
            if w.y > best_y {
                best_y = w.y;
            }
            best = w;
        }
    }
    best
}

fn order(items: &[usize], loc: &[(String, Vec3)], dim: usize) -> Vec<usize> {
    if items.is_empty() {
        return Vec::new();
    }
    let mut sorted: Vec<usize> = items.to_vec();
    sorted.sort_by(|&a, &b| {
        loc[a].1[dim].partial_cmp(&loc[b].1[dim]).unwrap_or(std::cmp::Ordering::Equal).then_with(|| loc[a].0.cmp(&loc[b].0))
    });
    if dim + 1 < 3 {
        let (mut start, mut end) = (0usize, 0usize);
        for e in 1..sorted.len() {
            end = e;
            if loc[sorted[e]].1[dim] - loc[sorted[start]].1[dim] >= TOLERANCE {
                if e - start > 1 {
                    let group = order(&sorted[start..e], loc, dim + 1);
                    sorted.splice(start..e, group);
                }
                start = e;
            }
        }
        if start != end {
            let group = order(&sorted[start..], loc, dim + 1);
            sorted.splice(start.., group);
        }
    }
    sorted
}
