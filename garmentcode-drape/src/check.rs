//! Figures measured on a drape: edges crossing the body, edges crossing the garment.

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;

use crate::body::BodyMesh;
use crate::selfcol::SelfCollision;

/// `(body, self)`: how many of the `springs` (vertex pairs) cross the body surface, and how
/// many cross a garment triangle that has neither of their ends, at positions `x`. These are
/// the reference's `body_collisions` and `self_collisions` counts.
pub(crate) fn crossings(mesh: &BoxMesh, x: &[Vec3], body: &BodyMesh, springs: &[([usize; 2], f64)]) -> (usize, usize) {
    let garment = SelfCollision::new(mesh.faces.iter().map(|f| f.vertices).collect(), x);
    let body_count = springs.iter().filter(|([a, b], _)| body.segment_crosses(x[*a], x[*b])).count();
    let self_count = springs.iter().filter(|([a, b], _)| garment.first_crossed(x, *a, *b).is_some()).count();
    (body_count, self_count)
}
