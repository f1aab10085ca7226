//! Figures measured on a drape: edges crossing the body, edges crossing the garment.

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;

use crate::body::BodyMesh;
use crate::bvh::{Bvh, segment_crosses};

/// `(body, self)`: how many of the `springs` (vertex pairs) cross the body surface, and how
/// many cross a garment triangle that has neither of their ends, at positions `x`. These are
/// the reference's `body_collisions` and `self_collisions` counts.
pub(crate) fn crossings(mesh: &BoxMesh, x: &[Vec3], body: &BodyMesh, springs: &[([usize; 2], f64)]) -> (usize, usize) {
    let faces: Vec<[usize; 3]> = mesh.faces.iter().map(|f| f.vertices).collect();
    let tris: Vec<[Vec3; 3]> = faces.iter().map(|f| f.map(|i| x[i])).collect();
    let bvh = Bvh::new(&tris);
    let mut body_count = 0;
    let mut self_count = 0;
    for &([a, b], _) in springs {
        if body.segment_crosses(x[a], x[b]) {
            body_count += 1;
        }
        let mut hit = false;
        bvh.for_each_in_box(x[a].min(x[b]), x[a].max(x[b]), |f| {
            hit = hit || (!faces[f].contains(&a) && !faces[f].contains(&b) && segment_crosses(x[a], x[b] - x[a], &tris[f]).is_some());
        });
        if hit {
            self_count += 1;
        }
    }
    (body_count, self_count)
}
