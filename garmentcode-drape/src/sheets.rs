//! Test fixture: two square sheets of 1 cm squares, one above the other, as the
//! self-collision tests lay layers of cloth on each other.

use garmentcode::Vec3;

/// Faces, positions, springs (every face edge, stiffness 1).
pub(crate) type Sheets = (Vec<[usize; 3]>, Vec<Vec3>, Vec<([usize; 2], f64)>);

/// Two sheets of `side` × `side` vertices 1 cm apart in x and z, the vertex `(i, j)` at
/// height `height(i, j)`, the second sheet moved by `offset`; two triangles per square, and
/// the edges of the faces as springs. Vertices of the second sheet start at `side * side`.
pub(crate) fn two_sheets(side: usize, offset: Vec3, height: impl Fn(f64, f64) -> f64) -> Sheets {
    let (mut faces, mut x) = (Vec::new(), Vec::new());
    for sheet in 0..2 {
        let base = x.len();
        for i in 0..side {
            for j in 0..side {
                let (a, b) = (i as f64, j as f64);
                x.push(offset * sheet as f64 + Vec3::new(a, height(a, b), b));
            }
        }
        let id = |i: usize, j: usize| base + i * side + j;
        for i in 0..side - 1 {
            for j in 0..side - 1 {
                faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
    }
    let mut keys = std::collections::BTreeSet::new();
    for f in &faces {
        for k in 0..3 {
            keys.insert([f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3])]);
        }
    }
    (faces, x, keys.into_iter().map(|e| (e, 1.0)).collect())
}
