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

/// The edges of `mesh`'s faces (each once, ends in increasing order) that cross one of its
/// triangles having neither of their ends, with the positions `x` (one per box-mesh vertex;
/// `mesh.vertices` for the box mesh itself), each with the index in `mesh.faces` of the
/// first triangle it crosses from its lower end. Their number is what the drape judge and
/// the reference count as self-intersections.
///
/// ```
/// use garmentcode::Vec3;
/// use garmentcode::mesh::BoxMesh;
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let pattern = garmentcode::Pattern::from_json(&std::fs::read_to_string(concat!(
///     env!("CARGO_MANIFEST_DIR"),
///     "/tests/data/waistband_specification.json"
/// ))?)?;
/// let mesh = BoxMesh::new(&pattern, 1.0)?;
/// // Lay every vertex on one plane: nothing crosses a flat garment.
/// let flat: Vec<Vec3> = mesh.vertices.iter().map(|v| Vec3::new(v.x, v.y, 0.0)).collect();
/// assert!(garmentcode_drape::crossing_edges(&mesh, &flat).is_empty());
/// # Ok(())
/// # }
/// ```
///
/// # Panics
/// If `x` does not have one entry per box-mesh vertex.
pub fn crossing_edges(mesh: &BoxMesh, x: &[Vec3]) -> Vec<([usize; 2], usize)> {
    assert_eq!(x.len(), mesh.vertices.len(), "one position per box-mesh vertex");
    let mut edges: Vec<[usize; 2]> = mesh
        .faces
        .iter()
        .flat_map(|f| {
            let v = f.vertices;
            (0..3).map(move |k| [v[k].min(v[(k + 1) % 3]), v[k].max(v[(k + 1) % 3])])
        })
        .collect();
    edges.sort_unstable();
    edges.dedup();
    let garment = SelfCollision::new(mesh.faces.iter().map(|f| f.vertices).collect(), x);
    edges.into_iter().filter_map(|[a, b]| garment.first_crossed(x, a, b).map(|f| ([a, b], f))).collect()
}
