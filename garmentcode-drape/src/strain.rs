//! Strain of a drape: how far its edges are from their rest lengths, as the reference's
//! drape judge measures it.

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;

/// Percentiles of `|length / rest − 1|` over the edges of a drape: stitch edges (rest length
/// from the 2D pattern, the box mesh's [`BoxMesh::rest_lengths`]) and fabric edges (rest
/// length as in the box mesh).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Strain {
    /// Stitch edges measured.
    pub seam_edges: usize,
    /// Median strain of stitch edges.
    pub seam_p50: f64,
    /// 99th percentile of stitch edges.
    pub seam_p99: f64,
    /// Fabric (non-stitch) edges measured.
    pub fabric_edges: usize,
    /// Median strain of fabric edges.
    pub fabric_p50: f64,
    /// 99th percentile of fabric edges.
    pub fabric_p99: f64,
}

impl Strain {
    /// The strain of `positions` (one per box-mesh vertex, cm). Edges of zero rest length
    /// are left out; a set without edges has percentiles 0.
    ///
    /// # Panics
    /// If `positions` does not have one entry per box-mesh vertex.
    pub fn of(mesh: &BoxMesh, positions: &[Vec3]) -> Strain {
        assert_eq!(positions.len(), mesh.vertices.len(), "one position per box-mesh vertex");
        let rest: std::collections::HashMap<[usize; 2], f64> = mesh.rest_lengths.iter().copied().collect();
        let mut edges: Vec<[usize; 2]> = mesh
            .faces
            .iter()
            .flat_map(|f| [0, 1, 2].map(|k| (f.vertices[k], f.vertices[(k + 1) % 3])))
            .map(|(a, b)| [a.min(b), a.max(b)])
            .collect();
        edges.sort_unstable();
        edges.dedup();
        let (mut seam, mut fabric) = (Vec::new(), Vec::new());
        for e in edges {
            let len = positions[e[0]].distance(positions[e[1]]);
            let (r, list) = match rest.get(&e) {
                Some(&r) => (r, &mut seam),
                None => (mesh.vertices[e[0]].distance(mesh.vertices[e[1]]), &mut fabric),
            };
            if r > 1e-9 {
                list.push((len / r - 1.0).abs());
            }
        }
        seam.sort_by(f64::total_cmp);
        fabric.sort_by(f64::total_cmp);
        Strain {
            seam_edges: seam.len(),
            seam_p50: percentile(&seam, 50.0),
            seam_p99: percentile(&seam, 99.0),
            fabric_edges: fabric.len(),
            fabric_p50: percentile(&fabric, 50.0),
            fabric_p99: percentile(&fabric, 99.0),
        }
    }
}

/// Linear-interpolated percentile `q` of sorted values (0 for none).
fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    let pos = q / 100.0 * (sorted.len() - 1) as f64;
    let (lo, hi) = (pos.floor() as usize, pos.ceil() as usize);
    sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_interpolate() {
        assert_eq!(percentile(&[], 50.0), 0.0);
        assert_eq!(percentile(&[1.0, 2.0, 3.0], 50.0), 2.0);
        assert!((percentile(&[0.0, 1.0], 99.0) - 0.99).abs() < 1e-12);
    }
}
