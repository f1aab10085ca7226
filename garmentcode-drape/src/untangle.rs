//! Undoing new crossings of the garment with itself (beyond the reference).
//!
//! The reference exempts the ends of an edge that crosses the garment from new self
//! contacts, so that a crossing is not locked in, and drags the particles of a panel that
//! crosses a panel of *another* body part back onto their part. Nothing undoes a crossing
//! between panels of one part, or of a panel with itself: a fold that slips through a
//! neighbouring fold (gathers at a waistband, a collar turned down) stays crossed, and its
//! exempt particles let the crossing spread.
//!
//! Here an edge that starts crossing a triangle during the drape is pushed back: the frame
//! before, both its ends were on one side of the triangle's plane, so the end that is now on
//! the other side (the one that passed through) is the wrong one, and it is pushed back to
//! that side (as a point–triangle contact whose side was known before the crossing). Where
//! the ends were already on both sides of the plane (the edge came in past the triangle's
//! border), the end nearer the plane is taken: it has just come through. The end stays the
//! wrong one for as long as its edge crosses the garment, whichever face it crosses first.
//! Edges that cross from the start (the box mesh's stretched seam faces, which the seams'
//! closing undoes) are left alone for the first [`START_FRAMES`] frames, then undone from
//! their end nearer the face.

use std::collections::BTreeMap;

use garmentcode::Vec3;

/// One edge being pulled back out of a face: its wrong end, the face, and the side of the
/// face's plane (+1: along its normal, −1: against it) the end must go back to.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pull {
    particle: usize,
    face: usize,
    side: f64,
}

/// The crossings being undone, and the positions of the last frame.
#[derive(Default)]
pub(crate) struct Untangle {
    /// Per crossing edge `[k, l]` (`k < l`), the end that passed through (`None`: the edge
    /// crossed from the start).
    wrong: BTreeMap<[usize; 2], Option<usize>>,
    pulls: Vec<Pull>,
    last_x: Vec<Vec3>,
    /// Frames seen.
    frames: usize,
}

/// Crossings present from the start (the box mesh's stretched seam faces) are left to the
/// seams' closing for this many frames (2 s; the reference's seams are closed by then);
/// those left after that are undone from their end nearer the crossed face.
const START_FRAMES: usize = 120;

/// With more crossing edges than this (the reference's limit for a drape to count, 300), the
/// garment is tangled: pulling single ends back then pushes them through the layers around
/// them and the crossings grow (a shirt whose box mesh starts with 793 had 2,347 at frame 600
/// with the pulls, 707 without), so no end is pulled that frame.
const TANGLED: usize = 300;

/// Signed distance of `p` from the plane of triangle `t` (along its unnormalised normal's direction).
fn side_of(p: Vec3, t: &[Vec3; 3]) -> f64 {
    let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
    n.dot(p - t[0])
}

impl Untangle {
    /// This frame's pulls at positions `x`, from the edges `crossings` (`(k, l, face first
    /// crossed)`) of the garment's `faces` that `undo` accepts.
    pub fn update(
        &mut self,
        x: &[Vec3],
        faces: &[[usize; 3]],
        crossings: &[(usize, usize, usize)],
        undo: impl Fn(usize, usize, usize) -> bool,
    ) {
        let mut wrong = BTreeMap::new();
        self.pulls.clear();
        let tri = |pos: &[Vec3], f: usize| faces[f].map(|i| pos[i]);
        for &(k, l, face) in crossings {
            if !undo(k, l, face) {
                continue;
            }
            let key = [k.min(l), k.max(l)];
            let (dk, dl) = (side_of(x[k], &tri(x, face)), side_of(x[l], &tri(x, face)));
            let nearer = if dk.abs() < dl.abs() { k } else { l };
            let end = match self.wrong.get(&key) {
                // Crossing from the start, still after the seams had time to close.
                Some(None) if self.frames >= START_FRAMES => Some(nearer),
                Some(&end) => end,
                // A new crossing: the end that changed sides of the face since the last frame
                // (else, when the edge was beside the face, the nearer end: it has just come
                // through).
                None if self.last_x.len() == x.len() => {
                    let before = tri(&self.last_x, face);
                    let (bk, bl) = (side_of(self.last_x[k], &before), side_of(self.last_x[l], &before));
                    Some(match (bk * bl > 0.0, bk * dk < 0.0, bl * dl < 0.0) {
                        (true, true, false) => k,
                        (true, false, true) => l,
                        _ => nearer,
                    })
                }
                // Crossing from the start: left to the seams' closing for a while.
                None => None,
            };
            wrong.insert(key, end);
            let Some(end) = end else { continue };
            // Back to the side of the other end.
            let other = if end == k { dl } else { dk };
            if other != 0.0 {
                self.pulls.push(Pull { particle: end, face, side: other.signum() });
            }
        }
        if crossings.len() > TANGLED {
            self.pulls.clear();
        }
        self.wrong = wrong;
        self.frames += 1;
        self.last_x.clear();
        self.last_x.extend_from_slice(x);
    }

    /// Adds the pulls' corrections at the predicted positions `x` to `delta`: each wrong end
    /// to `r` beyond its face's plane on its side, the mean of its pulls (an end is often the
    /// wrong end of several edges: their sum would throw it through the next layer). The
    /// face's corners are not moved (as the reference's point–triangle contacts move only the
    /// point): moving them pushes their own edges through the layers beside them.
    pub fn project(&self, x: &[Vec3], faces: &[[usize; 3]], r: f64, delta: &mut [Vec3]) {
        let mut sums: BTreeMap<usize, (Vec3, f64)> = BTreeMap::new();
        for pull in &self.pulls {
            let t = faces[pull.face].map(|i| x[i]);
            let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero() * pull.side;
            let gap = n.dot(x[pull.particle] - t[0]) - r;
            let sum = sums.entry(pull.particle).or_insert((Vec3::ZERO, 0.0));
            sum.1 += 1.0;
            if gap < 0.0 {
                sum.0 -= n * gap;
            }
        }
        for (i, (sum, count)) in sums {
            delta[i] += sum / count;
        }
    }

    /// How many edges are being pulled back this frame.
    #[cfg(test)]
    fn pulled(&self) -> usize {
        self.pulls.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::selfcol::SelfCollision;

    /// Two flat 8 × 8 cm sheets of 1 cm squares, 1 cm apart (y = 0 and y = 1, the upper one
    /// shifted by a fraction of a square), and the edges of their faces.
    fn sheets() -> crate::sheets::Sheets {
        crate::sheets::two_sheets(9, Vec3::new(0.3, 1.0, 0.2), |_, _| 0.0)
    }

    /// The upper sheet's middle point, and the sheets' positions with it pushed 0.6 cm
    /// through the lower sheet (a tongue, as a fold poking through its neighbour).
    fn tongue() -> (usize, Vec<Vec3>) {
        let tip = 81 + 4 * 9 + 4;
        let (_, mut x, _) = sheets();
        x[tip].y = -0.6;
        (tip, x)
    }

    /// Runs `frames` frames of a tiny solver on the sheets, which held positions `x0` the
    /// frame before and start at `start` (the springs' rest shape: a fold pressed through
    /// stays where it is): each frame the crossings and self contacts are found, then 10
    /// substeps of the contacts, the pulls (if `untangle`) and the springs. Returns the
    /// crossing edges left and the positions.
    fn settle(x0: &[Vec3], start: &[Vec3], untangle: bool, frames: usize) -> (usize, Vec<Vec3>) {
        let (faces, _, edges) = sheets();
        let rest: Vec<f64> = edges.iter().map(|([a, b], _)| (start[*a] - start[*b]).length()).collect();
        let inv_mass = vec![1.0; x0.len()];
        let mut sc = SelfCollision::new(faces.clone(), x0);
        let mut pulls = Untangle::default();
        let v = vec![Vec3::ZERO; x0.len()];
        let step = (Vec3::ZERO, 1.0 / 60.0, 0.1);
        sc.detect(x0, &v, &inv_mass, &edges, step, true, 1);
        pulls.update(x0, &faces, &sc.crossings, |_, _, _| untangle);
        let mut x = start.to_vec();
        for _ in 0..frames {
            sc.detect(&x, &v, &inv_mass, &edges, step, true, 1);
            pulls.update(&x, &faces, &sc.crossings, |_, _, _| untangle);
            for _ in 0..10 {
                let mut delta = vec![Vec3::ZERO; x.len()];
                sc.project(&x, &inv_mass, 0.1, &mut delta);
                pulls.project(&x, &faces, 0.1, &mut delta);
                for (&([a, b], _), &len) in edges.iter().zip(&rest) {
                    let d = x[b] - x[a];
                    let c = d.length() - len;
                    let n = d.normalize_or_zero();
                    delta[a] += n * (0.05 * c);
                    delta[b] -= n * (0.05 * c);
                }
                for (p, d) in x.iter_mut().zip(&delta) {
                    *p += *d;
                }
            }
        }
        sc.detect(&x, &v, &inv_mass, &edges, step, false, 1);
        (sc.crossings.len(), x)
    }

    #[test]
    fn a_point_pushed_through_another_layer_is_pulled_back() {
        let (_, x0, _) = sheets();
        let (tip, start) = tongue();
        let (left, _) = settle(&x0, &start, false, 20);
        assert!(left > 0, "without the pulls the tongue stays through the lower sheet");
        let (left, x) = settle(&x0, &start, true, 20);
        assert_eq!(left, 0, "no edge crosses the garment any more");
        assert!(x[tip].y > x[4 * 9 + 4].y, "the tip is back above the lower sheet: {} against {}", x[tip].y, x[4 * 9 + 4].y);
    }

    #[test]
    fn crossings_present_from_the_start_are_left_to_the_seams_for_a_while() {
        let (faces, x0, edges) = sheets();
        let (tip, start) = tongue();
        let inv_mass = vec![1.0; x0.len()];
        let v = vec![Vec3::ZERO; x0.len()];
        let mut sc = SelfCollision::new(faces.clone(), &start);
        let mut pulls = Untangle::default();
        sc.detect(&start, &v, &inv_mass, &edges, (Vec3::ZERO, 1.0 / 60.0, 0.1), false, 1);
        assert!(!sc.crossings.is_empty());
        for frame in 0..=START_FRAMES {
            pulls.update(&start, &faces, &sc.crossings, |_, _, _| true);
            if frame < START_FRAMES {
                assert_eq!(pulls.pulled(), 0, "frame {frame}: no side is known for a crossing without a frame before it");
            }
        }
        // Not while the garment is tangled.
        let many: Vec<(usize, usize, usize)> = sc.crossings.iter().cycle().take(TANGLED + 1).copied().collect();
        pulls.update(&start, &faces, &many, |_, _, _| true);
        assert_eq!(pulls.pulled(), 0);
        pulls.update(&start, &faces, &sc.crossings, |_, _, _| true);
        // Then from the end nearer the crossed face: the tip, 0.6 cm below it.
        assert_eq!(pulls.pulled(), sc.crossings.len());
        let up = |p: &Pull| {
            let t = faces[p.face].map(|i| start[i]);
            (t[1] - t[0]).cross(t[2] - t[0]).y * p.side > 0.0
        };
        let tips: Vec<&Pull> = pulls.pulls.iter().filter(|p| p.particle == tip).collect();
        assert!(tips.len() >= 4 && tips.iter().all(|p| up(p)), "the tip is pulled back up: {:?}", pulls.pulls);
    }
}
