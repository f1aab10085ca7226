//! Panels that a pattern places over each other in one plane start apart in the box mesh
//! made for draping (`BoxMesh::for_drape`), and the reference's box mesh (`BoxMesh::new`)
//! keeps them where the pattern puts them.
//!
//! The fixture `tests/data/mesh-extra/tiered_levels_specification.json` is sampled design
//! rand_0000014 (`garmentcode sample -n 200 -s 2026`, f_smpl_average_A40) trimmed to its
//! skirt and first three levels: the levels, circle skirts, are rings of one plane
//! (z = 17.5 cm in front, −12.5 cm behind) on top of each other.

use std::collections::HashMap;
use std::path::Path;

use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION};
use garmentcode::{Pattern, Vec3};

fn tiered_levels() -> Pattern {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh-extra/tiered_levels_specification.json");
    let mut p = Pattern::from_json(&std::fs::read_to_string(path).expect("fixture")).expect("a specification");
    p.name = "tiered_levels".into();
    p
}

/// The edges of the mesh's faces that cross one of its triangles sharing no vertex with
/// them, strictly inside both (as the drape judge counts them).
fn crossing_edges(mesh: &BoxMesh) -> usize {
    let x = &mesh.vertices;
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
    // Triangles by cells of 2 cm, every cell their box touches.
    let cell = 2.0;
    let key = |p: Vec3| (p / cell).floor().as_i64vec3().to_array();
    let bbox = |ps: &[Vec3]| (ps.iter().copied().fold(Vec3::INFINITY, Vec3::min), ps.iter().copied().fold(Vec3::NEG_INFINITY, Vec3::max));
    let mut cells: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for (i, f) in mesh.faces.iter().enumerate() {
        let (lo, hi) = bbox(&f.vertices.map(|v| x[v]));
        let (a, b) = (key(lo), key(hi));
        for cx in a[0]..=b[0] {
            for cy in a[1]..=b[1] {
                for cz in a[2]..=b[2] {
                    cells.entry([cx, cy, cz]).or_default().push(i);
                }
            }
        }
    }
    let crosses = |[a, b]: [usize; 2], t: [usize; 3]| {
        let (o, d) = (x[a], x[b] - x[a]);
        let (e1, e2) = (x[t[1]] - x[t[0]], x[t[2]] - x[t[0]]);
        let p = d.cross(e2);
        let det = e1.dot(p);
        if det.abs() <= 1e-12 {
            return false;
        }
        let s = o - x[t[0]];
        let u = s.dot(p) / det;
        let q = s.cross(e1);
        let v = d.dot(q) / det;
        let w = e2.dot(q) / det;
        let eps = 1e-6;
        u > eps && v > eps && u + v < 1.0 - eps && w > eps && w < 1.0 - eps
    };
    edges
        .iter()
        .filter(|&&e| {
            let (lo, hi) = bbox(&[x[e[0]], x[e[1]]]);
            let (a, b) = (key(lo), key(hi));
            (a[0]..=b[0]).any(|cx| {
                (a[1]..=b[1]).any(|cy| {
                    (a[2]..=b[2]).any(|cz| {
                        cells.get(&[cx, cy, cz]).is_some_and(|ts| {
                            ts.iter().any(|&t| {
                                let t = mesh.faces[t].vertices;
                                !t.contains(&e[0]) && !t.contains(&e[1]) && crosses(e, t)
                            })
                        })
                    })
                })
            })
        })
        .count()
}

#[test]
fn levels_of_one_plane_start_apart_for_draping() {
    let pattern = tiered_levels();
    let reference = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("meshes");
    let drape = BoxMesh::for_drape(&pattern, DEFAULT_RESOLUTION).expect("meshes");
    let (before, after) = (crossing_edges(&reference), crossing_edges(&drape));
    eprintln!("crossing edges: {before} placed by the pattern, {after} apart");
    assert!(before > 300, "the fixture's levels start tangled as the pattern places them: {before} crossing edges");
    assert!(after * 10 < before, "apart, the levels cross much less: {after} crossing edges against {before}");
    // The same mesh otherwise: vertices, faces, rest lengths and labels.
    assert_eq!(reference.faces, drape.faces);
    assert_eq!(reference.labels, drape.labels);
    assert_eq!(reference.rest_lengths, drape.rest_lengths);
    assert_eq!(reference.vertices.len(), drape.vertices.len());
}

#[test]
#[ignore]
fn dump_for_drape() {
    let pattern = tiered_levels();
    let dir = std::path::PathBuf::from(std::env::var("DUMP").unwrap());
    let m = BoxMesh::for_drape(&pattern, DEFAULT_RESOLUTION).unwrap();
    m.write_files(&dir).unwrap();
}
