//! Body meshes: the static collider the garment drapes onto.

use std::collections::HashMap;
use std::path::Path;

use garmentcode::Vec3;
use garmentcode::mesh::obj::{ObjError, ObjLimits, ObjMesh};

use crate::bvh::{Bvh, Closest, Feature};

/// Largest body file read (bytes): the reference's bodies are about 2 MB.
pub const MAX_FILE_BYTES: u64 = 64 << 20;
/// Most vertices a body may have.
pub const MAX_VERTICES: usize = 1_000_000;
/// Most triangles a body may have (after splitting polygons into fans).
pub const MAX_TRIANGLES: usize = 2_000_000;
/// Magic bytes of the packed body format ([`BodyMesh::to_packed`]).
const PACKED_MAGIC: &[u8; 8] = b"GCBODY1\0";

/// Packed coordinates are integers in this unit (cm): 0.1 mm.
const PACKED_UNIT: f64 = 0.01;

/// The built-in bodies, packed at 0.1 mm resolution with their part segmentations: the
/// reference's `mean_all`, `mean_female` and `mean_male` (23,752 vertices, 47,500 triangles,
/// segmentation `ggg_body_segmentation.json`; MIT) and the SMPL averages `f_smpl_average_A40`,
/// `m_smpl_average_A40` (6,890 vertices, 13,776 triangles, SMPL's vertex segmentation grouped
/// into [`PARTS`]; CC BY 4.0). Other bodies get a mannequin ([`BodyMesh::for_body`]).
pub const BUILTIN: [(&str, &[u8]); 5] = [
    ("mean_all", include_bytes!("../data/mean_all.body")),
    ("mean_female", include_bytes!("../data/mean_female.body")),
    ("mean_male", include_bytes!("../data/mean_male.body")),
    ("f_smpl_average_A40", include_bytes!("../data/f_smpl_average_A40.body")),
    ("m_smpl_average_A40", include_bytes!("../data/m_smpl_average_A40.body")),
];

/// The body parts of a segmentation, in the reference's order.
pub const PARTS: [&str; 6] = ["body", "left_arm", "left_leg", "right_arm", "right_leg", "face_internal"];

/// SMPL's vertex segmentation grouped into [`PARTS`]: the arm from the upper arm to the
/// fingers, the leg from the thigh to the toes, the rest (head, neck, shoulders, spine, hips)
/// the body.
pub const SMPL_PARTS: [(&str, &str); 24] = [
    ("head", "body"),
    ("neck", "body"),
    ("spine", "body"),
    ("spine1", "body"),
    ("spine2", "body"),
    ("hips", "body"),
    ("leftShoulder", "body"),
    ("rightShoulder", "body"),
    ("leftArm", "left_arm"),
    ("leftForeArm", "left_arm"),
    ("leftHand", "left_arm"),
    ("leftHandIndex1", "left_arm"),
    ("rightArm", "right_arm"),
    ("rightForeArm", "right_arm"),
    ("rightHand", "right_arm"),
    ("rightHandIndex1", "right_arm"),
    ("leftUpLeg", "left_leg"),
    ("leftLeg", "left_leg"),
    ("leftFoot", "left_leg"),
    ("leftToeBase", "left_leg"),
    ("rightUpLeg", "right_leg"),
    ("rightLeg", "right_leg"),
    ("rightFoot", "right_leg"),
    ("rightToeBase", "right_leg"),
];

/// Plausible body heights (cm, after scaling): outside this the file is not a body in metres.
pub const HEIGHT_RANGE: (f64, f64) = (30.0, 300.0);

/// Why a body mesh was refused. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum BodyError {
    /// The file could not be read.
    #[error("{file}: cannot read the body mesh: {reason}")]
    Read {
        /// The file.
        file: String,
        /// What went wrong.
        reason: String,
    },
    /// A line of the OBJ file is malformed.
    #[error("{file}:{line}: {reason}")]
    Parse {
        /// The file.
        file: String,
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        reason: String,
    },
    /// Too many vertices or triangles, or a file too large.
    #[error("{file}: {what} (at most {limit} allowed)")]
    TooLarge {
        /// The file.
        file: String,
        /// What is too large, with its size.
        what: String,
        /// The limit.
        limit: u64,
    },
    /// The mesh is not a closed surface, or has no triangles.
    #[error("{file}: the body mesh must be a closed surface: {reason}")]
    NotClosed {
        /// The file.
        file: String,
        /// Which edges are open or shared by more than two triangles.
        reason: String,
    },
    /// No mannequin can be made from the body's measurements.
    #[error("{file}: cannot make a mannequin: {reason}")]
    Mannequin {
        /// The body file.
        file: String,
        /// Which measurements disagree.
        reason: String,
    },
    /// The mesh's height (y extent, after metres → cm) is implausible.
    #[error("{file}: body height {height:.3} cm (y extent × 100) is outside {min}..{max} cm: the body mesh must be in metres, y up")]
    Height {
        /// The file.
        file: String,
        /// The height found (cm).
        height: f64,
        /// Lowest plausible height.
        min: f64,
        /// Highest plausible height.
        max: f64,
    },
}

/// A closed triangle mesh of a body, in centimetres, y up, ready for closest-point queries.
#[derive(Clone, Debug)]
pub struct BodyMesh {
    /// Name (file stem or built-in name).
    pub name: String,
    /// Vertices (cm).
    pub vertices: Vec<Vec3>,
    /// Triangles (counter-clockwise seen from outside).
    pub faces: Vec<[u32; 3]>,
    /// Body parts of each vertex, a bit per entry of [`PARTS`] (empty without a segmentation).
    parts: Vec<u8>,
    tris: Vec<[Vec3; 3]>,
    /// Per triangle: pseudo-normals of its corners, then of its edges `k → k+1`, then its own.
    normals: Vec<[Vec3; 7]>,
    bvh: Bvh,
}

/// The closest point of the body to a point, with the side the point is on.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BodyPoint {
    /// Point on the surface (cm).
    pub point: Vec3,
    /// Distance (cm), negative inside.
    pub signed: f64,
    /// Outward pseudo-normal of the closest feature (not unit).
    pub normal: Vec3,
    /// The triangle it lies on.
    pub face: usize,
}

impl BodyMesh {
    /// Reads a body OBJ file in metres (as the reference's `assets/bodies/*.obj`), scaled to cm.
    pub fn load(path: &Path) -> Result<BodyMesh, BodyError> {
        let file = path.display().to_string();
        let read = |reason: String| BodyError::Read { file: file.clone(), reason };
        let meta = std::fs::metadata(path).map_err(|e| read(e.to_string()))?;
        if meta.len() > MAX_FILE_BYTES {
            return Err(BodyError::TooLarge { file, what: format!("file of {} bytes", meta.len()), limit: MAX_FILE_BYTES });
        }
        let mut text = String::new();
        use std::io::Read as _;
        std::fs::File::open(path).and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_string(&mut text)).map_err(|e| read(e.to_string()))?;
        if text.len() as u64 > MAX_FILE_BYTES {
            return Err(BodyError::TooLarge { file, what: "file longer than its size said".into(), limit: MAX_FILE_BYTES });
        }
        let name = path.file_stem().map_or_else(|| file.clone(), |s| s.to_string_lossy().into_owned());
        BodyMesh::from_obj(&text, &file).map(|b| BodyMesh { name, ..b })
    }

    /// A built-in body by name (see [`BUILTIN`]), with its part segmentation.
    pub fn builtin(name: &str) -> Result<BodyMesh, BodyError> {
        let (name, bytes) = BUILTIN.iter().find(|(n, _)| *n == name || format!("{n}.obj") == name).ok_or_else(|| BodyError::Read {
            file: name.to_string(),
            reason: format!(
                "no built-in body of that name (built in: {}); give the body mesh as an OBJ file",
                BUILTIN.map(|(n, _)| n).join(", ")
            ),
        })?;
        BodyMesh::from_packed(bytes, name)
    }

    /// The body mesh to drape on for a body: the built-in mesh when `name` is a built-in
    /// body ([`BUILTIN`]), else a mannequin made from `measurements`
    /// ([`crate::mannequin::mannequin`]; `name` names the body file in errors).
    pub fn for_body(name: &str, measurements: &garmentcode::Body) -> Result<BodyMesh, BodyError> {
        if BUILTIN.iter().any(|(n, _)| *n == name) {
            return BodyMesh::builtin(name);
        }
        crate::mannequin::mannequin(measurements, name)
    }

    /// This body with the part bits of every vertex (one per entry of [`PARTS`]).
    pub(crate) fn with_part_bits(mut self, parts: Vec<u8>) -> BodyMesh {
        debug_assert_eq!(parts.len(), self.vertices.len());
        self.parts = parts;
        self
    }

    /// The compact form of this body (for [`BUILTIN`]): magic `GCBODY1\0`, vertex and
    /// triangle counts (u32 LE), the vertices as differences from the previous vertex in
    /// units of 0.1 mm (i16 LE, x y z), the triangles (u16 LE corners when there are at most
    /// 65,536 vertices, else u32), then the part bits of every vertex if the body has a
    /// segmentation. Fails if two successive vertices are more than 3.2 m apart.
    pub fn to_packed(&self) -> Result<Vec<u8>, String> {
        let mut out = Vec::with_capacity(16 + self.vertices.len() * 7 + self.faces.len() * 6);
        out.extend_from_slice(PACKED_MAGIC);
        out.extend_from_slice(&(self.vertices.len() as u32).to_le_bytes());
        out.extend_from_slice(&(self.faces.len() as u32).to_le_bytes());
        let mut last = [0i64; 3];
        for (i, v) in self.vertices.iter().enumerate() {
            for k in 0..3 {
                let q = (v[k] / PACKED_UNIT).round() as i64;
                let d = i16::try_from(q - last[k]).map_err(|_| format!("vertex {i} is too far from the previous one to pack"))?;
                out.extend_from_slice(&d.to_le_bytes());
                last[k] = q;
            }
        }
        let small = self.vertices.len() <= 1 << 16;
        for f in &self.faces {
            for &i in f {
                if small {
                    out.extend_from_slice(&(i as u16).to_le_bytes());
                } else {
                    out.extend_from_slice(&i.to_le_bytes());
                }
            }
        }
        out.extend_from_slice(&self.parts);
        Ok(out)
    }

    /// Reads the compact form written by [`BodyMesh::to_packed`]; `name` names it in errors.
    pub fn from_packed(bytes: &[u8], name: &str) -> Result<BodyMesh, BodyError> {
        let bad = |reason: &str| BodyError::Parse { file: name.to_string(), line: 0, reason: format!("packed body: {reason}") };
        let rest = bytes.strip_prefix(PACKED_MAGIC).ok_or_else(|| bad("not a packed body (bad magic)"))?;
        let count = |at: usize| rest.get(at..at + 4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize);
        let (nv, nf) = (count(0).ok_or_else(|| bad("truncated header"))?, count(4).ok_or_else(|| bad("truncated header"))?);
        if nv > MAX_VERTICES || nf > MAX_TRIANGLES {
            return Err(bad("too many vertices or triangles"));
        }
        let index_size = if nv <= 1 << 16 { 2 } else { 4 };
        let (v_end, f_end) = (8 + nv * 6, 8 + nv * 6 + nf * 3 * index_size);
        if rest.len() != f_end && rest.len() != f_end + nv {
            return Err(bad("its length does not match its vertex and triangle counts"));
        }
        let mut last = [0i64; 3];
        let vertices = rest[8..v_end]
            .chunks_exact(6)
            .map(|c| {
                for k in 0..3 {
                    last[k] += i16::from_le_bytes([c[2 * k], c[2 * k + 1]]) as i64;
                }
                Vec3::new(last[0] as f64, last[1] as f64, last[2] as f64) * PACKED_UNIT
            })
            .collect();
        let index =
            |c: &[u8]| if index_size == 2 { u16::from_le_bytes([c[0], c[1]]) as u32 } else { u32::from_le_bytes([c[0], c[1], c[2], c[3]]) };
        let faces = rest[v_end..f_end].chunks_exact(3 * index_size).map(|c| [0, 1, 2].map(|k| index(&c[k * index_size..]))).collect();
        let mut body = BodyMesh::new(name, vertices, faces)?;
        body.parts = rest[f_end..].to_vec();
        Ok(body)
    }

    /// Parses an OBJ text in metres (`v x y z`, `f a b c ...`; polygons become fans), scaled
    /// to cm. `file` names the source in errors.
    pub fn from_obj(text: &str, file: &str) -> Result<BodyMesh, BodyError> {
        let limits = ObjLimits { max_vertices: MAX_VERTICES, max_triangles: MAX_TRIANGLES };
        let obj = ObjMesh::parse(text, limits).map_err(|e| match e {
            ObjError::Line { line, reason } => BodyError::Parse { file: file.to_string(), line, reason },
            ObjError::TooLarge { what, limit } => BodyError::TooLarge { file: file.to_string(), what: what.into(), limit: limit as u64 },
        })?;
        let vertices = obj.vertices.into_iter().map(|v| v * 100.0).collect();
        let faces = obj.triangles.into_iter().map(|t| t.map(|i| i as u32)).collect();
        BodyMesh::new(file, vertices, faces)
    }

    /// A body from vertices (cm) and triangles, checked: closed (every edge in exactly two
    /// triangles) and of plausible height. `name` names it in errors.
    pub fn new(name: &str, vertices: Vec<Vec3>, faces: Vec<[u32; 3]>) -> Result<BodyMesh, BodyError> {
        let not_closed = |reason: String| BodyError::NotClosed { file: name.to_string(), reason };
        if faces.is_empty() {
            return Err(not_closed("it has no faces".into()));
        }
        if let Some(f) = faces.iter().position(|f| f.iter().any(|&i| i as usize >= vertices.len())) {
            return Err(not_closed(format!("triangle {f} names a vertex out of range")));
        }
        let (lo, hi) = vertices.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v.y), hi.max(v.y)));
        let height = hi - lo;
        if !(HEIGHT_RANGE.0..=HEIGHT_RANGE.1).contains(&height) {
            return Err(BodyError::Height { file: name.into(), height, min: HEIGHT_RANGE.0, max: HEIGHT_RANGE.1 });
        }
        // Each undirected edge → the triangles using it, as (triangle, edge slot).
        let mut edges: HashMap<(u32, u32), Vec<(usize, usize)>> = HashMap::with_capacity(faces.len() * 3 / 2);
        for (f, t) in faces.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                edges.entry((a.min(b), a.max(b))).or_default().push((f, k));
            }
        }
        let bad: Vec<(u32, u32)> = {
            let mut bad: Vec<_> = edges.iter().filter(|(_, v)| v.len() != 2).map(|(k, _)| *k).collect();
            bad.sort_unstable();
            bad
        };
        if !bad.is_empty() {
            let (a, b) = bad[0];
            return Err(not_closed(format!(
                "{} edge(s) are not shared by exactly two triangles (the first between vertices {} and {})",
                bad.len(),
                a + 1,
                b + 1
            )));
        }
        let tris: Vec<[Vec3; 3]> = faces.iter().map(|f| f.map(|i| vertices[i as usize])).collect();
        let face_n: Vec<Vec3> = tris.iter().map(|t| (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero()).collect();
        // Angle-weighted vertex normals.
        let mut vn = vec![Vec3::ZERO; vertices.len()];
        for (f, t) in tris.iter().enumerate() {
            for k in 0..3 {
                let (e1, e2) = (t[(k + 1) % 3] - t[k], t[(k + 2) % 3] - t[k]);
                let angle = e1.angle_between(e2);
                if angle.is_finite() {
                    vn[faces[f][k] as usize] += face_n[f] * angle;
                }
            }
        }
        let mut normals: Vec<[Vec3; 7]> = Vec::with_capacity(faces.len());
        for (f, t) in faces.iter().enumerate() {
            let mut n = [Vec3::ZERO; 7];
            for k in 0..3 {
                n[k] = vn[t[k] as usize];
                let (a, b) = (t[k], t[(k + 1) % 3]);
                n[3 + k] = edges[&(a.min(b), a.max(b))].iter().map(|&(g, _)| face_n[g]).sum();
            }
            n[6] = face_n[f];
            normals.push(n);
        }
        let bvh = Bvh::new(&tris);
        Ok(BodyMesh { name: name.to_string(), vertices, faces, parts: Vec::new(), tris, normals, bvh })
    }

    /// Adds the body's part segmentation, in the reference's format
    /// (`ggg_body_segmentation.json`: `{"body": [vertex ids], "left_arm": [...], ...}`, parts
    /// among [`PARTS`]) or SMPL's (`smpl_vert_segmentation.json`, its 24 parts grouped as
    /// [`SMPL_PARTS`] says); other keys are ignored. `file` names the source in errors.
    pub fn with_parts_json(mut self, text: &str, file: &str) -> Result<BodyMesh, BodyError> {
        let parse = |reason: String| BodyError::Parse { file: file.to_string(), line: 1, reason };
        let value: serde_json::Value =
            serde_json::from_str(text).map_err(|e| BodyError::Parse { file: file.to_string(), line: e.line(), reason: e.to_string() })?;
        let map = value.as_object().ok_or_else(|| parse("the segmentation must be an object of part → vertex ids".into()))?;
        let mut parts = vec![0u8; self.vertices.len()];
        for (name, ids) in map {
            let part = SMPL_PARTS.iter().find(|(smpl, _)| smpl == name).map_or(name.as_str(), |(_, part)| part);
            let Some(bit) = PARTS.iter().position(|p| *p == part) else { continue };
            let ids = ids.as_array().ok_or_else(|| parse(format!("part '{name}' must be a list of vertex ids")))?;
            for id in ids {
                let i = id
                    .as_u64()
                    .filter(|&i| (i as usize) < parts.len())
                    .ok_or_else(|| parse(format!("part '{name}': {id} is not a vertex id (0..{})", self.vertices.len())))?;
                parts[i as usize] |= 1 << bit;
            }
        }
        self.parts = parts;
        Ok(self)
    }

    /// Body parts of every vertex (a bit per entry of [`PARTS`]), if the body has a segmentation.
    pub fn parts(&self) -> Option<&[u8]> {
        (!self.parts.is_empty()).then_some(self.parts.as_slice())
    }

    /// The lowest and highest corner (cm).
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.vertices.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), v| (lo.min(*v), hi.max(*v)))
    }

    /// The closest surface point to `p` within `sqrt(max_dist2)` cm.
    pub(crate) fn closest(&self, p: Vec3, max_dist2: f64) -> Option<BodyPoint> {
        let Closest { point, dist2, face, feature } = self.bvh.closest(&self.tris, p, max_dist2)?;
        let normal = self.normals[face][match feature {
            Feature::Vertex(k) => k,
            Feature::Edge(k) => 3 + k,
            Feature::Face => 6,
        }];
        let side = if (p - point).dot(normal) < 0.0 { -1.0 } else { 1.0 };
        Some(BodyPoint { point, signed: side * dist2.sqrt(), normal, face })
    }

    /// The body's triangles (cm).
    pub(crate) fn tris(&self) -> &[[Vec3; 3]] {
        &self.tris
    }

    /// Signed distance (cm) from `p` to the body surface: negative inside.
    pub fn signed_distance(&self, p: Vec3) -> f64 {
        self.closest(p, f64::INFINITY).map_or(f64::INFINITY, |h| h.signed)
    }

    /// The edges of the mesh (vertex pairs, 0-based) that cross one of its triangles (one
    /// they do not belong to): none for a surface that does not pass through itself.
    pub fn self_intersections(&self) -> Vec<(u32, u32)> {
        let mut edges: Vec<(u32, u32)> =
            self.faces.iter().flat_map(|f| [0, 1, 2].map(|k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3])))).collect();
        edges.sort_unstable();
        edges.dedup();
        edges
            .iter()
            .filter(|&&(a, b)| {
                let (p, q) = (self.vertices[a as usize], self.vertices[b as usize]);
                let mut hit = false;
                self.bvh.for_each_in_box(p.min(q), p.max(q), |f| {
                    hit = hit
                        || (!self.faces[f].contains(&a)
                            && !self.faces[f].contains(&b)
                            && crate::bvh::segment_crosses(p, q - p, &self.tris[f]).is_some())
                });
                hit
            })
            .copied()
            .collect()
    }

    /// Whether segment `a`–`b` crosses the body surface.
    pub(crate) fn segment_crosses(&self, a: Vec3, b: Vec3) -> bool {
        let mut hit = false;
        self.bvh.for_each_in_box(a.min(b), a.max(b), |f| hit = hit || crate::bvh::segment_crosses(a, b - a, &self.tris[f]).is_some());
        hit
    }
}
