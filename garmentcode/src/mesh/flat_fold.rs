//! Where the box mesh starts the part of a panel folded flat (format extension).
//!
//! A fold of 180° ([`Fold`]) lays the part of a panel beyond its line flat behind the
//! other part, [`FOLD_GAP`] off it: a doubled cuff's free half inside the half sewn on.
//! Turned by the panel's placement alone, the folded layer is a flat copy of the other
//! part. But the other part's seam vertices are merged halfway to the panels they are
//! sewn to, so its faces along a seam turn steeply away (to a sleeve a few cm behind),
//! while the folded layer runs on flat to its free edge and comes out through them. And
//! where two folded layers meet at a seam (a cuff's front and back), their opposite gaps
//! cancel in the mean: the inner layer's seam starts on the outer layer's.
//!
//! So, once the stitches are merged, a vertex of a part folded flat whose mirror image
//! across the line lies in a face of the other part that touches a seam, drawn by the seam
//! towards the folded side, starts on that face as it lies in 3D (at the image), the gap
//! behind it along the face's normal (ramping in from the line as in [`Fold`]). Where a
//! seam draws the other part away from the folded side, the flat layer is behind it
//! already and stays. A merged vertex all of whose sides are
//! such vertices starts at their mean: behind both panels' seam faces, not between their
//! gaps. The faces of the vertices so placed keep their 2D rest lengths (as faces
//! touching a seam do), so only the start changes. Elsewhere the other part lies flat
//! and the placement is [`Fold`]'s.

use super::{FOLD_GAP, Fold, GlobalStitch, HashMap, PanelMesh};
use crate::{Vec2, Vec3};

impl Fold {
    /// How far `p` lies right of the line: the side that turns.
    pub(super) fn beyond(&self, p: Vec2) -> f64 {
        -self.direction.perp_dot(p - self.at)
    }

    /// The fold of a part folded flat (180°).
    fn flat(&self) -> bool {
        self.angle == std::f64::consts::PI
    }
}

/// Barycentric coordinates of `p` in triangle `t` (outside, for a triangle of no area).
fn barycentric(t: [Vec2; 3], p: Vec2) -> [f64; 3] {
    let area = (t[1] - t[0]).perp_dot(t[2] - t[0]);
    if area == 0.0 {
        return [f64::NEG_INFINITY; 3];
    }
    let b1 = (p - t[0]).perp_dot(t[2] - t[0]) / area;
    let b2 = (t[1] - t[0]).perp_dot(p - t[0]) / area;
    [1.0 - b1 - b2, b1, b2]
}

/// The seam faces by square cells of the panel's plane, as large as the largest face's
/// box: a face holding a point overlaps the point's cell, so a point is looked up among a
/// few faces, not all of them (time linear in the panel's vertices, whatever its size).
struct FaceGrid {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<usize>>,
}

impl FaceGrid {
    fn new(faces: &[[usize; 3]], points: &[Vec2]) -> FaceGrid {
        let boxes: Vec<(Vec2, Vec2)> = faces
            .iter()
            .map(|f| {
                let p = f.map(|k| points[k]);
                (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]))
            })
            .collect();
        let cell = boxes.iter().map(|(lo, hi)| (*hi - *lo).max_element()).fold(0.0, f64::max).max(1e-9);
        let mut cells: HashMap<(i64, i64), Vec<usize>> = HashMap::default();
        let key = |v: f64| (v / cell).floor() as i64;
        for (i, (lo, hi)) in boxes.iter().enumerate() {
            for x in key(lo.x)..=key(hi.x) {
                for y in key(lo.y)..=key(hi.y) {
                    cells.entry((x, y)).or_default().push(i);
                }
            }
        }
        FaceGrid { cell, cells }
    }

    /// The faces that may hold `p`, in the order they were given.
    fn near(&self, p: Vec2) -> &[usize] {
        let key = ((p.x / self.cell).floor() as i64, (p.y / self.cell).floor() as i64);
        self.cells.get(&key).map_or(&[], Vec::as_slice)
    }
}

/// Places the vertices of panels with one fold, of 180°, that follow the other part's
/// seams (see the module documentation): moves the merged vertices in `globals`, and
/// returns, per panel, the other local vertices moved and where to.
pub(super) fn follow_seams(
    panels: &[PanelMesh],
    loc_glob: &HashMap<(usize, usize), usize>,
    globals: &mut [GlobalStitch],
) -> Vec<HashMap<usize, Vec3>> {
    let mut moved: Vec<HashMap<usize, Vec3>> = vec![HashMap::default(); panels.len()];
    for (pi, panel) in panels.iter().enumerate() {
        let [fold] = panel.folds[..] else { continue };
        if !fold.flat() {
            continue;
        }
        let stitched = |l: usize| l < panel.n_stitch_side;
        let at = |l: usize| if stitched(l) { globals[loc_glob[&(pi, l)]].pos } else { panel.to_3d(panel.points[l]) };
        let seam_faces: Vec<[usize; 3]> = panel
            .faces
            .iter()
            .filter(|f| f.iter().any(|&l| stitched(l)) && f.iter().all(|&l| fold.beyond(panel.points[l]) <= 0.0))
            .copied()
            .collect();
        let grid = FaceGrid::new(&seam_faces, &panel.points);
        let right = Vec2::new(fold.direction.y, -fold.direction.x);
        for (l, &p) in panel.points.iter().enumerate() {
            let beyond = fold.beyond(p);
            if beyond <= 0.0 {
                continue;
            }
            let image = p - right * (2.0 * beyond);
            let inside = |b: &[f64; 3]| b.iter().copied().fold(f64::INFINITY, f64::min);
            let best = grid
                .near(image)
                .iter()
                .map(|&i| &seam_faces[i])
                .map(|f| (f, barycentric(f.map(|k| panel.points[k]), image)))
                .max_by(|a, b| inside(&a.1).total_cmp(&inside(&b.1)));
            let Some((f, b)) = best.filter(|(_, b)| inside(b) >= -1e-9) else { continue };
            let x = f.map(at);
            let on = x[0] * b[0] + x[1] * b[1] + x[2] * b[2];
            // Only where the seam drew the other part towards the folded side: turned away
            // from it, the other part leaves the flat layer behind it.
            let flat = panel.rotation * Vec3::new(image.x, image.y, 0.0) + panel.translation;
            if (on - flat).dot(panel.to_3d(p) - flat) <= 0.0 {
                continue;
            }
            // Faces are wound like the outline, and the fold turns away from the side their
            // winding faces.
            let normal = (x[1] - x[0]).cross(x[2] - x[0]).normalize_or_zero();
            let gap = FOLD_GAP * (beyond / FOLD_GAP).min(1.0);
            moved[pi].insert(l, on - normal * gap);
        }
    }
    for g in globals.iter_mut() {
        let sides: Option<Vec<Vec3>> = g.members.iter().map(|(p, l)| moved[*p].get(l).copied()).collect();
        if let Some(sides) = sides {
            g.pos = sides.iter().sum::<Vec3>() / sides.len() as f64;
        }
    }
    moved
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn barycentric_coordinates_place_a_point_and_refuse_a_flat_triangle() {
        let t = [Vec2::new(0.0, 0.0), Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0)];
        let b = barycentric(t, Vec2::new(0.5, 0.5));
        assert!((b[0] - 0.5).abs() < 1e-12 && (b[1] - 0.25).abs() < 1e-12 && (b[2] - 0.25).abs() < 1e-12, "{b:?}");
        let flat = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(2.0, 0.0)];
        assert!(barycentric(flat, Vec2::new(1.0, 0.0)).iter().all(|c| *c < -1.0));
    }

    #[test]
    fn the_grid_offers_every_face_that_holds_a_point() {
        // A strip of 40 triangles of 1 × 1 cm (and one long thin one) over 20 cm.
        let mut points: Vec<Vec2> = (0..21).flat_map(|i| [Vec2::new(i as f64, 0.0), Vec2::new(i as f64, 1.0)]).collect();
        let mut faces: Vec<[usize; 3]> = (0..20).flat_map(|i| [[2 * i, 2 * i + 2, 2 * i + 3], [2 * i, 2 * i + 3, 2 * i + 1]]).collect();
        points.extend([Vec2::new(0.0, 1.0), Vec2::new(20.0, 1.0), Vec2::new(10.0, 3.0)]);
        faces.push([42, 43, 44]);
        let grid = FaceGrid::new(&faces, &points);
        for k in 0..400 {
            let p = Vec2::new(0.05 * k as f64 + 0.013, 0.0075 * k as f64 % 3.0);
            let holding: Vec<usize> =
                (0..faces.len()).filter(|&i| barycentric(faces[i].map(|v| points[v]), p).iter().all(|c| *c >= -1e-9)).collect();
            let near = grid.near(p);
            assert!(holding.iter().all(|i| near.contains(i)), "{p:?}: {holding:?} not all in {near:?}");
            assert!(near.windows(2).all(|w| w[0] < w[1]));
        }
    }
}
