//! Reading Wavefront OBJ meshes: the workspace's one OBJ reader (box meshes read back,
//! body meshes for the drape).
//!
//! Only what triangle meshes need: `v x y z` vertices and `f` faces (`a`, `a/t`, `a/t/n`
//! or `a//n` corners, 1-based, negative indices counting back from the last vertex);
//! polygons become triangle fans; every other line is skipped. Coordinates must be
//! finite, and the counts stay within the caller's [`ObjLimits`], so a hostile file is
//! refused before it takes unbounded memory.
//!
//! ```
//! use garmentcode::mesh::obj::{ObjLimits, ObjMesh};
//!
//! let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
//! let mesh = ObjMesh::parse(quad, ObjLimits::default())?;
//! assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
//! let err = ObjMesh::parse("v 0 nan 0\n", ObjLimits::default()).unwrap_err();
//! assert_eq!(err.to_string(), r#"line 1: vertex coordinate "nan" is not finite"#);
//! # Ok::<(), garmentcode::mesh::obj::ObjError>(())
//! ```

use crate::Vec3;

/// Vertices and triangles of an OBJ text, in the file's units.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjMesh {
    /// Vertex positions in file order.
    pub vertices: Vec<Vec3>,
    /// Triangles (0-based vertex indices), polygons split into fans.
    pub triangles: Vec<[usize; 3]>,
}

/// Most vertices and triangles a read may hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ObjLimits {
    /// Most vertices.
    pub max_vertices: usize,
    /// Most triangles (after splitting polygons).
    pub max_triangles: usize,
}

impl Default for ObjLimits {
    /// A million vertices, two million triangles.
    fn default() -> Self {
        ObjLimits { max_vertices: 1_000_000, max_triangles: 2_000_000 }
    }
}

/// What is wrong with an OBJ text.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ObjError {
    /// A malformed line.
    #[error("line {line}: {reason}")]
    Line {
        /// 1-based line number.
        line: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// More vertices or triangles than the limits allow.
    #[error("{what} (at most {limit} allowed)")]
    TooLarge {
        /// What is too large.
        what: &'static str,
        /// The limit.
        limit: usize,
    },
}

impl ObjMesh {
    /// Reads an OBJ text within `limits`.
    pub fn parse(text: &str, limits: ObjLimits) -> Result<ObjMesh, ObjError> {
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        let mut corners = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let bad = |reason: String| ObjError::Line { line: n + 1, reason };
            let mut it = line.split_whitespace();
            match it.next() {
                Some("v") => {
                    let mut c = [0.0; 3];
                    for x in &mut c {
                        let t = it.next().ok_or_else(|| bad("a vertex needs three coordinates".into()))?;
                        *x = t.parse::<f64>().map_err(|e| bad(format!("vertex coordinate {}: {e}", crate::message::quote(t))))?;
                        if !x.is_finite() {
                            return Err(bad(format!("vertex coordinate {} is not finite", crate::message::quote(t))));
                        }
                    }
                    if vertices.len() == limits.max_vertices {
                        return Err(ObjError::TooLarge { what: "more vertices", limit: limits.max_vertices });
                    }
                    vertices.push(Vec3::new(c[0], c[1], c[2]));
                }
                Some("f") => {
                    corners.clear();
                    for t in it {
                        let s = t.split('/').next().unwrap_or("");
                        let i: i64 = s.parse().map_err(|e| bad(format!("face index {}: {e}", crate::message::quote(t))))?;
                        let i = if i < 0 { vertices.len() as i64 + i } else { i - 1 };
                        if i < 0 || i >= vertices.len() as i64 {
                            return Err(bad(format!(
                                "face index {} names no vertex (there are {} so far)",
                                crate::message::quote(t),
                                vertices.len()
                            )));
                        }
                        corners.push(i as usize);
                    }
                    if corners.len() < 3 {
                        return Err(bad("a face needs at least three corners".into()));
                    }
                    if triangles.len() + corners.len() - 2 > limits.max_triangles {
                        return Err(ObjError::TooLarge { what: "more triangles", limit: limits.max_triangles });
                    }
                    triangles.extend((1..corners.len() - 1).map(|k| [corners[0], corners[k], corners[k + 1]]));
                }
                _ => {}
            }
        }
        Ok(ObjMesh { vertices, triangles })
    }
}
