//! The simulation "box mesh" of a pattern, as the reference's `BoxMesh` builds it.
//!
//! A cloth simulator starts from one triangle mesh of the whole garment: every panel
//! triangulated at about the resolution (1 cm by default), placed in 3D by its rotation
//! and translation, and the two sides of every stitch merged into shared vertices that
//! sit halfway between the panels (hence "box" mesh). [`BoxMesh::new`] makes it from
//! any [`Pattern`] (built by a garment program or read by [`Pattern::from_json`]):
//!
//! 1. **Edge sampling.** Every edge gets `ceil(length / res) + 1` vertices including its
//!    corners, the length as the reference computes it ([`MeshCurve::reference_length`]:
//!    for an edge of a whole number of resolutions the last digit decides); both sides
//!    of a stitch get the count of the longer one. Lines and arcs are sampled at uniform
//!    parameter, Béziers at uniform arc length ([`MeshCurve`]).
//! 2. **Per-panel vertices.** Stitched edges first, then free edges, each as its start
//!    corner (unless already present), its interior samples, its end corner; the panel's
//!    first `n_stitch_side` local vertices are those of stitched edges.
//! 3. **Triangulation.** Interior points are laid out, not searched for: a row along the
//!    outline (one point over the middle of each outline segment, so the triangles on the
//!    outline are about isosceles) and blue noise inside it (a fixed tile of Poisson-disk
//!    points, an irregular interior like the reference's refinement makes). One
//!    constrained Delaunay triangulation (`spade`) joins them, never splitting the
//!    outline: no extra boundary points. Edges longer than `1.43·res` are split. The
//!    even–odd rule decides what is inside. Faces are wound like the outline (the panel
//!    normal is decided, as in the reference, by the outline points lying on its bounding
//!    box).
//! 4. **Stitching.** Per stitch, side 0's vertex range is reversed unless the stitch is
//!    `right_wrong`, and pairs are merged into global stitch vertices (midpoints,
//!    sequentially averaged), each labelled `stitch_k` ([`VertexLabel`]).
//! 5. **Assembly.** Stitch vertices first, then each panel's other vertices; faces in
//!    panel order (faces collapsed by merged dart tips are dropped); rest lengths of the
//!    edges of faces touching a stitch, in the panel's own 2D frame, with the reference's
//!    rule for seam edges seen from two panels ([`BoxMesh::rest_lengths`]).
//!
//! The format extension (`docs/pattern-extension.md`) goes through the same steps:
//! a panel's holes' and inner lines' edges follow its outline's (sampled, stitched and
//! numbered like them); holes bound the triangulation like the outline (left open),
//! lines are constraints that bound nothing (rows of mesh edges); inner stitches follow
//! the stitches; [`Fold`]s turn part of a panel when it is placed in 3D (a part folded
//! flat, once the stitches are merged, lies behind the other part's seams); a pleat's
//! stitched pairs start on a ridge behind the panel, as deep as the pleat, not all at
//! one point in its plane; the vertex labels name lines, holes and layers.
//!
//! The files the reference writes (`<name>_boxmesh.obj`, `<name>_sim_segmentation.txt`,
//! `<name>_orig_lens.pickle`, `<name>_vertex_labels.yaml`, `<name>_material.mtl`) come from
//! [`BoxMesh::write_files`], laid out byte for byte as the reference's readers expect.
//! The rest-length pickle is written by hand (pickle protocol 2: an empty dict, then the
//! `(i, j) → length` items as 4-byte ints and 8-byte big-endian floats in one batch); no
//! crate is needed for that handful of opcodes, and Python reads it as plain ints and
//! floats, which compare equal to the reference's numpy scalars. Also written: a welded
//! mesh in metres (`<name>_sim_mesh.obj`, plain OBJ) and a PLY (`<name>_boxmesh.ply`) with
//! each vertex's segment as an attribute.
//!
//! Real faults of a pattern are errors naming the panel and edge ([`MeshError`]); the
//! triangulation itself does not fail on self-crossing outlines (crossings become
//! outline vertices). Before any work, a pattern with structural errors (those of
//! [`structural_errors`](crate::structural_errors), what `garmentcode check` calls
//! errors) is refused, and so is one that would need more than [`MAX_MESH_VERTICES`]
//! vertices at the resolution asked (estimated from its edges' lengths and panels'
//! areas), naming the resolution that fits: time and memory are bounded.

mod curve;
mod flat_fold;
mod pleat;
mod triangulate;

use triangulate::HashMap;
pub mod obj;
pub mod write;

use thiserror::Error;

pub use curve::MeshCurve;
pub use triangulate::SIZE_BOUND;

use crate::{PanelSpec, Pattern, panel_order};
use crate::{Vec2, Vec3};

/// The reference simulator's default resolution (`sim.config.resolution_scale`), cm.
pub const DEFAULT_RESOLUTION: f64 = 1.0;

/// Most vertices one edge may get (guards memory against absurd lengths).
const MAX_EDGE_VERTICES: usize = 1_000_000;

/// Most vertices a whole mesh may have: a pattern whose panels would need more at the
/// resolution asked is refused, with the resolution that would do (the largest
/// built-in garment has 21,419 vertices at 1 cm).
pub const MAX_MESH_VERTICES: usize = 1_000_000;

/// What can make a pattern impossible to mesh.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MeshError {
    /// The resolution is not a positive number.
    #[error("mesh resolution must be a positive number of cm, not {0}")]
    Resolution(f64),
    /// The panel order names a panel that does not exist.
    #[error("panel order names panel '{0}', which the pattern does not have")]
    UnknownPanel(String),
    /// A stitch refers to a panel that is not meshed or an edge the panel lacks.
    #[error("stitch {stitch}: panel '{panel}' has no edge {edge} to stitch")]
    MissingEdge {
        /// Stitch index.
        stitch: usize,
        /// Panel name.
        panel: String,
        /// Edge index.
        edge: usize,
    },
    /// An edge takes part in two stitches.
    #[error("panel '{panel}' edge {edge} is stitched twice (stitches {first} and {second})")]
    StitchedTwice {
        /// Panel name.
        panel: String,
        /// Edge index.
        edge: usize,
        /// The first stitch using it.
        first: usize,
        /// The second stitch using it.
        second: usize,
    },
    /// The two edges of a stitch carry different labels.
    #[error("stitch {stitch}: its edges carry different labels '{first}' and '{second}'")]
    LabelMismatch {
        /// Stitch index.
        stitch: usize,
        /// Label of side 0.
        first: String,
        /// Label of side 1.
        second: String,
    },
    /// An edge that cannot be sampled (bad corner index, coincident ends, endless length).
    #[error("panel '{panel}' edge {edge}: {reason}")]
    BadEdge {
        /// Panel name.
        panel: String,
        /// Edge index.
        edge: usize,
        /// What is wrong.
        reason: String,
    },
    /// The pattern has a structural error (what `garmentcode check` calls an error).
    #[error("{0} (`garmentcode check` lists every problem)")]
    Structural(String),
    /// The mesh would have more than [`MAX_MESH_VERTICES`] vertices at this resolution.
    #[error(
        "the pattern needs about {needed} vertices at {resolution} cm, more than the {MAX_MESH_VERTICES} a mesh may have: \
         mesh it at {coarser} cm or coarser"
    )]
    TooLarge {
        /// Estimated number of vertices.
        needed: usize,
        /// Resolution asked (cm).
        resolution: f64,
        /// A resolution within the limit (cm).
        coarser: f64,
    },
    /// A panel whose normal (the side its faces face) is undefined, or that cannot be triangulated.
    #[error("panel '{panel}': {reason}")]
    DegeneratePanel {
        /// Panel name.
        panel: String,
        /// What is wrong.
        reason: String,
    },
}

/// The segmentation label of a mesh vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VertexLabel {
    /// A merged stitch vertex: the stitches that merged it, in order of accumulation
    /// (written `stitch_3,stitch_7`; repetitions possible).
    Stitch(Vec<usize>),
    /// A vertex of one panel only (index into [`BoxMesh::panels`]).
    Panel(usize),
}

/// One triangle of the mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshFace {
    /// Global vertex ids, wound like the panel outline.
    pub vertices: [usize; 3],
    /// Texture (UV) ids of the corners: panel-local vertex ids offset by [`PanelMesh::texture_offset`].
    pub uvs: [usize; 3],
    /// Panel the face belongs to (index into [`BoxMesh::panels`]).
    pub panel: usize,
}

/// The samples of one panel edge.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeSamples {
    /// Panel-local vertex ids from start to end corner.
    pub local: Vec<usize>,
    /// Stitch this edge belongs to.
    pub stitch: Option<usize>,
    /// Curve length (cm).
    pub length: f64,
}

/// One meshed panel.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelMesh {
    /// Panel name.
    pub name: String,
    /// Panel-local 2D points (cm): boundary samples, then added points.
    pub points: Vec<Vec2>,
    /// Local ids below this are vertices of stitched edges.
    pub n_stitch_side: usize,
    /// Number of sampled boundary points (local ids below it).
    pub n_boundary: usize,
    /// Samples of each edge, in edge order.
    pub edges: Vec<EdgeSamples>,
    /// Triangles in local ids, wound like the outline.
    pub faces: Vec<[usize; 3]>,
    /// Global vertex of each local vertex (stitch-side ones through the merged stitch vertices).
    pub global: Vec<usize>,
    /// Rotation matrix of the panel (local 2D → 3D direction).
    pub rotation: glam::DMat3,
    /// Translation of the panel (cm).
    pub translation: Vec3,
    /// The outline runs counter-clockwise (faces face `+R·ẑ`).
    pub counter_clockwise: bool,
    /// Grain direction in 3D: the panel's local y axis (`R·ŷ`), the direction the
    /// reference's panels are drawn with their length along.
    pub grain: Vec3,
    /// First texture id of this panel's local vertices.
    pub texture_offset: usize,
    /// The panel's fold lines (format extension), applied in this order by [`to_3d`](Self::to_3d).
    pub folds: Vec<Fold>,
}

/// How far (cm) the part of a panel folded flat stands off the other part in the box
/// mesh (see [`Fold`]): twice the simulator's particle radius and more.
pub const FOLD_GAP: f64 = 0.5;

/// A fold line of a panel, as the box mesh places it: the part of the panel to the
/// right of the line (through its first and last vertex, looking along it) turns
/// about it by `angle`, right-handed about its direction (towards the panel's `−z`,
/// away from its front, for angles under 180°; at 180° it lies folded flat behind the
/// left part). That is for an outline running counter-clockwise (by its area); one
/// running clockwise faces `−z`, and its folds turn towards `+z` (mirrored). The turned part stands [`FOLD_GAP`] off along its own normal, scaled by
/// `(1 − cos angle) / 2` (all of it when folded flat, none when flat) and ramping in
/// over the first `FOLD_GAP` from the line: two layers folded flat would otherwise lie
/// exactly on each other, and a simulator could not tell which is in front.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fold {
    /// A point of the line (panel-local, cm).
    pub at: Vec2,
    /// The line's unit direction.
    pub direction: Vec2,
    /// The turn, radians.
    pub angle: f64,
    /// The panel's outline runs clockwise: the turn goes towards `+z`.
    pub mirrored: bool,
}

impl Fold {
    /// The fold lines of a panel.
    fn of(p: &PanelSpec) -> Vec<Fold> {
        let corner = |k: usize| Vec2::from(p.vertices[k]);
        let area: f64 = p.edges.iter().map(|e| corner(e.endpoints[0]).perp_dot(corner(e.endpoints[1]))).sum();
        p.lines
            .iter()
            .filter_map(|l| match l.kind {
                crate::LineKind::Fold { angle } => {
                    let (a, b) = (Vec2::from(*l.vertices.first()?), Vec2::from(*l.vertices.last()?));
                    let direction = (b - a).try_normalize()?;
                    Some(Fold { at: a, direction, angle: angle.to_radians(), mirrored: area < 0.0 })
                }
                _ => None,
            })
            .collect()
    }

    /// `q` (the panel-local 3D image of the 2D point `p`) turned if `p` lies right of the line.
    fn turn(&self, p: Vec2, q: Vec3) -> Vec3 {
        let beyond = self.beyond(p);
        if beyond <= 0.0 {
            return q;
        }
        if self.mirrored {
            let flip = |v: Vec3| Vec3::new(v.x, v.y, -v.z);
            return flip(Fold { mirrored: false, ..*self }.turn(p, flip(q)));
        }
        let axis = Vec3::new(self.direction.x, self.direction.y, 0.0);
        // Rodrigues' rotation about the line.
        let (s, c) = self.angle.sin_cos();
        let rotate = |r: Vec3| r * c + axis.cross(r) * s + axis * axis.dot(r) * (1.0 - c);
        let gap = FOLD_GAP * (1.0 - c) / 2.0 * (beyond / FOLD_GAP).min(1.0);
        rotate(q - Vec3::new(self.at.x, self.at.y, 0.0)) + rotate(Vec3::Z) * gap + Vec3::new(self.at.x, self.at.y, 0.0)
    }
}

/// Where each of a panel's edges (in the order of `PanelSpec::all_edges`) lies: the
/// ranges of its holes' and its lines' edges.
struct EdgeKinds {
    holes: Vec<std::ops::Range<usize>>,
    lines: Vec<std::ops::Range<usize>>,
}

impl EdgeKinds {
    fn of(p: &PanelSpec) -> EdgeKinds {
        let mut at = p.edges.len();
        let mut next = |n: usize| {
            at += n;
            at - n..at
        };
        let holes = p.holes.iter().map(|h| next(h.edges.len())).collect();
        let lines = p.lines.iter().map(|l| next(l.edges.len())).collect();
        EdgeKinds { holes, lines }
    }

    /// Whether edge `i` starts, and whether it ends, an inner line.
    fn line_ends(&self, i: usize) -> (bool, bool) {
        self.lines.iter().find(|r| r.contains(&i)).map_or((false, false), |r| (i == r.start, i + 1 == r.end))
    }
}

impl PanelMesh {
    /// 3D image of a local 2D point (turned by the panel's folds).
    pub fn to_3d(&self, p: Vec2) -> Vec3 {
        let q = self.folds.iter().fold(Vec3::new(p.x, p.y, 0.0), |q, f| f.turn(p, q));
        self.rotation * q + self.translation
    }

    /// Per-corner texture coordinates of the local vertices: 2D minus the panel's minimum (cm).
    pub fn uv(&self) -> Vec<Vec2> {
        let min = self.points.iter().fold(Vec2::splat(f64::INFINITY), |m, p| m.min(*p));
        self.points.iter().map(|p| *p - min).collect()
    }
}

/// One stitch of the mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct StitchMesh {
    /// `(panel index, edge index)` of both sides.
    pub sides: [(usize, usize); 2],
    /// Starts are paired with starts (else side 0 is reversed).
    pub right_wrong: bool,
    /// Label shared by the stitched edges.
    pub label: Option<String>,
    /// Vertices per side.
    pub n: usize,
}

/// The box mesh of a pattern. See the [module documentation](self).
#[derive(Clone, Debug, PartialEq)]
pub struct BoxMesh {
    /// Pattern name (file prefix).
    pub name: String,
    /// Resolution used (cm).
    pub resolution: f64,
    /// Vertex positions (cm): the stitch vertices, then each panel's own vertices.
    pub vertices: Vec<Vec3>,
    /// Segmentation label of every vertex.
    pub labels: Vec<VertexLabel>,
    /// Number of leading stitch vertices.
    pub n_stitch_vertices: usize,
    /// Triangles in panel order.
    pub faces: Vec<MeshFace>,
    /// Panels in panel order.
    pub panels: Vec<PanelMesh>,
    /// Stitches in pattern order.
    pub stitches: Vec<StitchMesh>,
    /// Rest lengths `(i < j) → cm` of the edges of faces touching a stitch, in the
    /// order the reference's dictionary holds them.
    pub rest_lengths: Vec<([usize; 2], f64)>,
    /// Edge label → vertex ids (free labelled edges' interiors, then labelled stitches' vertices).
    pub vertex_labels: Vec<(String, Vec<usize>)>,
}

/// Stitch bookkeeping while merging: one global stitch vertex.
struct GlobalStitch {
    pos: Vec3,
    labels: Vec<usize>,
    members: Vec<(usize, usize)>,
}

impl BoxMesh {
    /// The box mesh of `pattern` at `resolution` cm (see [`DEFAULT_RESOLUTION`]).
    pub fn new(pattern: &Pattern, resolution: f64) -> Result<BoxMesh, MeshError> {
        if !(resolution.is_finite() && resolution > 0.0) {
            return Err(MeshError::Resolution(resolution));
        }
        let scaled;
        let pattern = if pattern.properties.units_in_meter != 100.0 {
            scaled = to_cm(pattern);
            &scaled
        } else {
            pattern
        };
        let order = pattern.panel_order.clone().unwrap_or_else(|| panel_order(pattern));
        let specs: Vec<&PanelSpec> =
            order.iter().map(|n| pattern.panel(n).ok_or_else(|| MeshError::UnknownPanel(n.clone()))).collect::<Result<_, _>>()?;
        let index: HashMap<&str, usize> = specs.iter().enumerate().map(|(i, p)| (p.name.as_str(), i)).collect();

        // Curves, lengths and vertex counts.
        let mut curves = Vec::with_capacity(specs.len());
        let mut counts = Vec::with_capacity(specs.len());
        for p in &specs {
            let mut cs = Vec::with_capacity(p.edges.len());
            let mut ns = Vec::with_capacity(p.edges.len());
            for (i, e) in p.edges.iter().enumerate() {
                let bad = |reason: String| MeshError::BadEdge { panel: p.name.clone(), edge: i, reason };
                if e.endpoints.iter().any(|&v| v >= p.vertices.len()) {
                    return Err(bad(format!("corner index out of range ({} corners)", p.vertices.len())));
                }
                if p.vertex(e.endpoints[0]) == p.vertex(e.endpoints[1]) {
                    return Err(bad("start and end coincide".into()));
                }
                let c = MeshCurve::of_edge(p, i);
                let len = c.length();
                let n = ((c.reference_length() / resolution).ceil() + 1.0).max(2.0);
                if !(n.is_finite() && n <= MAX_EDGE_VERTICES as f64) {
                    return Err(bad(format!("length {len} cm cannot be sampled at {resolution} cm")));
                }
                cs.push((c, len));
                ns.push(n as usize);
            }
            curves.push(cs);
            counts.push(ns);
        }

        // Stitches: sides, labels, equal counts.
        let mut edge_stitch: Vec<Vec<Option<usize>>> = specs.iter().map(|p| vec![None; p.edges.len()]).collect();
        let mut stitches = Vec::with_capacity(pattern.stitches.len() + pattern.inner_stitches.len());
        for (k, s) in pattern.stitches.iter().enumerate() {
            let side = |j: usize| (s.sides[j].panel.as_str(), Some(s.sides[j].edge), s.sides[j].edge);
            join(k, [side(0), side(1)], s.right_wrong, &index, &specs, &mut counts, &mut edge_stitch, &mut stitches)?;
        }
        if let Some(problem) = crate::structural_errors(pattern).into_iter().next() {
            return Err(MeshError::Structural(problem.to_string()));
        }
        // The format extension: each panel's holes' and inner lines' edges follow its
        // outline's (the order of `PanelSpec::all_edges`), stitched by the inner
        // stitches, which follow the stitches.
        for (pi, p) in specs.iter().enumerate() {
            let inner = p.holes.iter().map(|h| (&h.vertices, &h.edges)).chain(p.lines.iter().map(|l| (&l.vertices, &l.edges)));
            for (vertices, inner_edges) in inner {
                let own = PanelSpec::new(&p.name, [0.0; 3], [0.0; 3], vertices.clone(), inner_edges.clone(), None);
                for i in 0..inner_edges.len() {
                    let c = MeshCurve::of_edge(&own, i);
                    let len = c.length();
                    let n = ((c.reference_length() / resolution).ceil() + 1.0).max(2.0);
                    if !(n.is_finite() && n <= MAX_EDGE_VERTICES as f64) {
                        let reason = format!("length {len} cm cannot be sampled at {resolution} cm");
                        return Err(MeshError::BadEdge { panel: p.name.clone(), edge: counts[pi].len(), reason });
                    }
                    curves[pi].push((c, len));
                    counts[pi].push(n as usize);
                }
            }
            edge_stitch[pi].resize(counts[pi].len(), None);
        }
        for (j, s) in pattern.inner_stitches.iter().enumerate() {
            let side = |i: usize| {
                let sd = &s.sides[i];
                (sd.panel.as_str(), pattern.panel(&sd.panel).and_then(|p| p.edge_index(sd.place, sd.edge)), sd.edge)
            };
            join(
                pattern.stitches.len() + j,
                [side(0), side(1)],
                s.right_wrong,
                &index,
                &specs,
                &mut counts,
                &mut edge_stitch,
                &mut stitches,
            )?;
        }
        check_size(&specs, &counts, resolution)?;

        // Panels: local vertices, orientation, triangulation.
        let mut panels = Vec::with_capacity(specs.len());
        let mut texture_offset = 0;
        let mut vertices = 0;
        for (pi, p) in specs.iter().enumerate() {
            let mut points: Vec<Vec2> = Vec::new();
            let mut seen: HashMap<[u64; 2], usize> = HashMap::default();
            let n_all = curves[pi].len();
            let mut edges: Vec<EdgeSamples> = vec![EdgeSamples { local: Vec::new(), stitch: None, length: 0.0 }; n_all];
            let mut samples: Vec<Vec<Vec2>> = Vec::with_capacity(n_all);
            for (i, (c, _)) in curves[pi].iter().enumerate() {
                samples.push(c.samples(counts[pi][i]));
            }
            let kinds = EdgeKinds::of(p);
            let stitched = (0..n_all).filter(|&i| edge_stitch[pi][i].is_some());
            let free = (0..n_all).filter(|&i| edge_stitch[pi][i].is_none());
            let mut n_stitch_side = 0;
            let n_stitched = stitched.clone().count();
            let mut outline_ids: Vec<usize> = Vec::new();
            for (visit, i) in stitched.chain(free).enumerate() {
                let s = &samples[i];
                let corner = |q: Vec2, points: &mut Vec<Vec2>, seen: &mut HashMap<[u64; 2], usize>| {
                    *seen.entry([q.x.to_bits(), q.y.to_bits()]).or_insert_with(|| {
                        points.push(q);
                        points.len() - 1
                    })
                };
                // An inner line's end on the outline is the outline's nearest point (within
                // half the resolution), so that the line's row of edges meets the outline.
                let end = |q: Vec2, chain_end: bool, points: &mut Vec<Vec2>, seen: &mut HashMap<[u64; 2], usize>| {
                    let near = |&k: &usize| (points[k] - q).length();
                    let snap =
                        outline_ids.iter().copied().filter(|k| near(k) <= 0.5 * resolution).min_by(|a, b| near(a).total_cmp(&near(b)));
                    match snap {
                        Some(k) if chain_end => k,
                        _ => corner(q, points, seen),
                    }
                };
                let (starts_line, ends_line) = kinds.line_ends(i);
                let mut local = Vec::with_capacity(s.len());
                local.push(end(s[0], starts_line, &mut points, &mut seen));
                for q in &s[1..s.len() - 1] {
                    seen.entry([q.x.to_bits(), q.y.to_bits()]).or_insert(points.len());
                    local.push(points.len());
                    points.push(*q);
                }
                local.push(end(s[s.len() - 1], ends_line, &mut points, &mut seen));
                if i < p.edges.len() {
                    outline_ids.extend(&local);
                }
                edges[i] = EdgeSamples { local, stitch: edge_stitch[pi][i], length: curves[pi][i].1 };
                if visit + 1 == n_stitched {
                    n_stitch_side = points.len();
                }
            }
            let counter_clockwise = outline_orientation(p, &samples)?;
            // Bounded memory: the outline and its row of points count now, the interior
            // as it is laid out (at most what is left).
            vertices += 2 * points.len();
            if vertices > MAX_MESH_VERTICES {
                return Err(MeshError::DegeneratePanel {
                    panel: p.name.clone(),
                    reason: format!("too large to mesh at {resolution} cm (over {MAX_MESH_VERTICES} vertices)"),
                });
            }
            // The outline and the holes bound the panel (a hole's loop runs against the
            // outline, so that the panel's side of it is the same); inner lines do not.
            let pairs = |i: usize| edges[i].local.windows(2).map(|w| [w[0], w[1]]);
            let mut segments: Vec<[usize; 2]> = (0..p.edges.len()).flat_map(pairs).collect();
            let area = |range: std::ops::Range<usize>| -> f64 { range.flat_map(pairs).map(|[a, b]| points[a].perp_dot(points[b])).sum() };
            let outline_area = area(0..p.edges.len());
            for range in kinds.holes.clone() {
                let against = area(range.clone()) * outline_area < 0.0;
                segments.extend(range.flat_map(pairs).map(|[a, b]| if against { [a, b] } else { [b, a] }));
            }
            let lines: Vec<[usize; 2]> = kinds.lines.iter().flat_map(|r| r.clone().flat_map(pairs)).collect();
            let n_boundary = points.len();
            // A clockwise panel is triangulated mirrored (x → −x, exact) and mirrored back, so
            // that the mesh of a mirrored panel is exactly the mirror of the panel's mesh; the
            // triangles, counter-clockwise in the mirror, come out wound like the outline.
            let mirror = |q: &Vec2| if counter_clockwise { *q } else { Vec2::new(-q.x, q.y) };
            let input: Vec<Vec2> = points.iter().map(mirror).collect();
            let mut tri = triangulate::triangulate(&input, &segments, &lines, resolution, MAX_MESH_VERTICES - vertices)
                .map_err(|reason| MeshError::DegeneratePanel { panel: p.name.clone(), reason })?;
            vertices += tri.points.len() - n_boundary;
            if tri.faces.is_empty() {
                return Err(MeshError::DegeneratePanel { panel: p.name.clone(), reason: "the outline encloses no area".into() });
            }
            tri.points[..n_boundary].copy_from_slice(&points);
            tri.points[n_boundary..].iter_mut().for_each(|q| *q = mirror(q));
            let faces = tri.faces;
            // The reference's mesher reads the angles as `Rz·Ry·Rx` (its readers' convention).
            let rotation = crate::rotation::matrix_zyx_from_degrees(p.rotation);
            let n_local = tri.points.len();
            panels.push(PanelMesh {
                name: p.name.clone(),
                points: tri.points,
                n_stitch_side,
                n_boundary,
                edges,
                faces,
                global: vec![usize::MAX; n_local],
                rotation,
                translation: Vec3::from(p.translation),
                counter_clockwise,
                grain: rotation * Vec3::Y,
                texture_offset,
                folds: Fold::of(p),
            });
            texture_offset += n_local;
        }

        // Stitch vertices.
        let mut globals: Vec<GlobalStitch> = Vec::new();
        let mut loc_glob: HashMap<(usize, usize), usize> = HashMap::default();
        for (k, s) in stitches.iter().enumerate() {
            let [(p0, e0), (p1, e1)] = s.sides;
            let mut r0 = panels[p0].edges[e0].local.clone();
            let r1 = panels[p1].edges[e1].local.clone();
            if !s.right_wrong {
                r0.reverse();
            }
            for (&a, &b) in r0.iter().zip(&r1) {
                let (ka, kb) = ((p0, a), (p1, b));
                let pa = panels[p0].to_3d(panels[p0].points[a]);
                let pb = panels[p1].to_3d(panels[p1].points[b]);
                if ka == kb {
                    match loc_glob.get(&ka) {
                        None => {
                            loc_glob.insert(ka, globals.len());
                            globals.push(GlobalStitch { pos: pa, labels: vec![k], members: vec![ka] });
                        }
                        Some(&g) => globals[g].labels.push(k),
                    }
                    continue;
                }
                match (loc_glob.get(&ka).copied(), loc_glob.get(&kb).copied()) {
                    (Some(ga), Some(gb)) if ga != gb => {
                        let (lo, hi) = (ga.min(gb), ga.max(gb));
                        let gone = globals.remove(hi);
                        let keep = &mut globals[lo];
                        keep.pos = (keep.pos + gone.pos) / 2.0;
                        keep.labels.extend(gone.labels);
                        keep.labels.push(k);
                        keep.members.extend(gone.members);
                        for g in loc_glob.values_mut() {
                            if *g == hi {
                                *g = lo;
                            } else if *g > hi {
                                *g -= 1;
                            }
                        }
                    }
                    (Some(_), Some(_)) => {}
                    (Some(g), None) | (None, Some(g)) => {
                        let (other, pos) = if loc_glob.contains_key(&ka) { (kb, pb) } else { (ka, pa) };
                        loc_glob.insert(other, g);
                        globals[g].pos = (pos + globals[g].pos) / 2.0;
                        globals[g].labels.push(k);
                        globals[g].members.push(other);
                    }
                    (None, None) => {
                        loc_glob.insert(ka, globals.len());
                        loc_glob.insert(kb, globals.len());
                        globals.push(GlobalStitch { pos: (pa + pb) / 2.0, labels: vec![k], members: vec![ka, kb] });
                    }
                }
            }
        }

        pleat::raise_ridges(&specs, &panels, &stitches, &loc_glob, &mut globals);
        let folded = flat_fold::follow_seams(&panels, &loc_glob, &mut globals);

        // Assembly.
        let n_stitch_vertices = globals.len();
        // Sized before they are filled (a mesh's vectors are megabytes: growing by doubling
        // copies them and touches fresh memory at every step).
        let n_vertices = n_stitch_vertices + panels.iter().map(|p| p.points.len() - p.n_stitch_side).sum::<usize>();
        let mut vertices: Vec<Vec3> = Vec::with_capacity(n_vertices);
        vertices.extend(globals.iter().map(|g| g.pos));
        let mut labels: Vec<VertexLabel> = Vec::with_capacity(n_vertices);
        labels.extend(globals.iter().map(|g| VertexLabel::Stitch(g.labels.clone())));
        let mut faces = Vec::with_capacity(panels.iter().map(|p| p.faces.len()).sum());
        let mut lens = RestLengths::default();
        let mut vertex_labels: Vec<(String, Vec<usize>)> = Vec::new();
        for (pi, panel) in panels.iter_mut().enumerate() {
            let offset = vertices.len();
            for l in 0..panel.points.len() {
                panel.global[l] = if l < panel.n_stitch_side { loc_glob[&(pi, l)] } else { l - panel.n_stitch_side + offset };
            }
            for l in panel.n_stitch_side..panel.points.len() {
                vertices.push(folded[pi].get(&l).copied().unwrap_or_else(|| panel.to_3d(panel.points[l])));
                labels.push(VertexLabel::Panel(pi));
            }
            for (e, spec) in panel.edges.iter().zip(specs[pi].all_edges()) {
                if let (None, Some(label)) = (e.stitch, &spec.label) {
                    let ids = e.local[1..e.local.len() - 1].iter().map(|&l| panel.global[l]);
                    push_label(&mut vertex_labels, label, ids);
                }
            }
            for f in &panel.faces {
                let g = f.map(|l| panel.global[l]);
                if g[0] == g[1] || g[1] == g[2] || g[0] == g[2] {
                    continue;
                }
                if f.iter().any(|&l| l < panel.n_stitch_side || folded[pi].contains_key(&l)) {
                    lens.add_face(panel, *f, g);
                }
                faces.push(MeshFace { vertices: g, uvs: f.map(|l| l + panel.texture_offset), panel: pi });
            }
        }
        // The format extension's names: each hole's and inner line's vertices, and the
        // vertices of panels on a facing or lining layer.
        for (pi, panel) in panels.iter().enumerate() {
            let spec = specs[pi];
            let kinds = EdgeKinds::of(spec);
            let named = spec.holes.iter().map(|h| format!("hole_{}_{}", spec.name, h.name)).zip(&kinds.holes).chain(
                spec.lines
                    .iter()
                    .map(|l| {
                        format!("{}_{}_{}", if matches!(l.kind, crate::LineKind::Fold { .. }) { "fold" } else { "line" }, spec.name, l.name)
                    })
                    .zip(&kinds.lines),
            );
            for (name, range) in named {
                let mut ids: Vec<usize> = range.clone().flat_map(|i| panel.edges[i].local.iter().map(|&l| panel.global[l])).collect();
                ids.dedup();
                push_label(&mut vertex_labels, &name, ids);
            }
            let layer = match spec.layer {
                crate::Layer::Outer => continue,
                crate::Layer::Facing => "layer_facing",
                crate::Layer::Lining => "layer_lining",
            };
            let mut ids: Vec<usize> = panel.global.clone();
            ids.sort_unstable();
            ids.dedup();
            push_label(&mut vertex_labels, layer, ids);
        }
        for (v, label) in labels.iter().enumerate() {
            let VertexLabel::Stitch(ks) = label else { break };
            for &k in ks {
                if let Some(l) = &stitches[k].label {
                    push_label(&mut vertex_labels, l, [v]);
                }
            }
        }

        Ok(BoxMesh {
            name: pattern.name.clone(),
            resolution,
            vertices,
            labels,
            n_stitch_vertices,
            faces,
            panels,
            stitches,
            rest_lengths: lens.items,
            vertex_labels,
        })
    }

    /// The segmentation line of vertex `v` (`stitch_3,stitch_7` or the panel name).
    pub fn segmentation_label(&self, v: usize) -> String {
        match &self.labels[v] {
            VertexLabel::Stitch(ks) => ks.iter().map(|k| format!("stitch_{k}")).collect::<Vec<_>>().join(","),
            VertexLabel::Panel(p) => self.panels[*p].name.clone(),
        }
    }
}

/// One stitch `k` between `sides` (panel name, edge index in `PanelSpec::all_edges` if
/// it exists, edge index to report): checks, records it, gives both edges the larger
/// vertex count.
#[allow(clippy::too_many_arguments)]
fn join(
    k: usize,
    sides: [(&str, Option<usize>, usize); 2],
    right_wrong: bool,
    index: &HashMap<&str, usize>,
    specs: &[&PanelSpec],
    counts: &mut [Vec<usize>],
    edge_stitch: &mut [Vec<Option<usize>>],
    stitches: &mut Vec<StitchMesh>,
) -> Result<(), MeshError> {
    let mut at = [(0, 0); 2];
    for (j, &(panel, edge, shown)) in sides.iter().enumerate() {
        let missing = || MeshError::MissingEdge { stitch: k, panel: panel.to_string(), edge: shown };
        let p = *index.get(panel).ok_or_else(missing)?;
        let e = edge.filter(|&e| e < counts[p].len()).ok_or_else(missing)?;
        if let Some(first) = edge_stitch[p][e] {
            return Err(MeshError::StitchedTwice { panel: panel.to_string(), edge: shown, first, second: k });
        }
        edge_stitch[p][e] = Some(k);
        at[j] = (p, e);
    }
    let label = |(p, e): (usize, usize)| specs[p].all_edges().nth(e).and_then(|x| x.label.clone());
    let (la, lb) = (label(at[0]), label(at[1]));
    if let (Some(a), Some(b)) = (&la, &lb)
        && a != b
    {
        return Err(MeshError::LabelMismatch { stitch: k, first: a.clone(), second: b.clone() });
    }
    let n = counts[at[0].0][at[0].1].max(counts[at[1].0][at[1].1]);
    for (p, e) in at {
        counts[p][e] = n;
    }
    stitches.push(StitchMesh { sides: at, right_wrong, label: la.or(lb), n });
    Ok(())
}

fn push_label(labels: &mut Vec<(String, Vec<usize>)>, label: &str, ids: impl IntoIterator<Item = usize>) {
    let i = match labels.iter().position(|(l, _)| l == label) {
        Some(i) => i,
        None => {
            labels.push((label.to_string(), Vec::new()));
            labels.len() - 1
        }
    };
    labels[i].1.extend(ids);
}

/// Rest lengths as the reference accumulates them (see [`BoxMesh::rest_lengths`]).
#[derive(Default)]
struct RestLengths {
    items: Vec<([usize; 2], f64)>,
    index: HashMap<[usize; 2], usize>,
    /// Seam edges: `[low, up, length]` from the triangle inequality of the faces seen.
    seam: HashMap<[usize; 2], [f64; 3]>,
}

impl RestLengths {
    fn set(&mut self, key: [usize; 2], value: f64) {
        match self.index.get(&key) {
            Some(&i) => self.items[i].1 = value,
            None => {
                self.index.insert(key, self.items.len());
                self.items.push((key, value));
            }
        }
    }

    fn add_face(&mut self, panel: &PanelMesh, face: [usize; 3], glob: [usize; 3]) {
        let mut order = [0, 1, 2];
        order.sort_by_key(|&i| glob[i]);
        let g = order.map(|i| glob[i]);
        let l = order.map(|i| face[i]);
        let v = l.map(|i| panel.points[i]);
        let mut el = [(v[1] - v[0]).length(), (v[2] - v[1]).length(), (v[2] - v[0]).length()];
        // Edge k joins corners pair[k]; the other two edges are others[k].
        let pair = [[0, 1], [1, 2], [0, 2]];
        let others = [[1, 2], [0, 2], [0, 1]];
        let mut old = [None; 3];
        for k in 0..3 {
            let key = [g[pair[k][0]], g[pair[k][1]]];
            if let Some(&[low_old, up_old, el_old]) = self.seam.get(&key) {
                old[k] = Some((low_old, up_old));
                let (b, c) = (el[others[k][0]], el[others[k][1]]);
                let min_el = el[k].min(el_old);
                let low = low_old.max((b - c).abs());
                let up = up_old.min(b + c);
                el[k] = if low < min_el && min_el < up {
                    min_el
                } else if low < up && min_el < low {
                    low + 0.02 * (up - low)
                } else {
                    low
                };
            }
            self.set(key, el[k]);
        }
        let stitch_side = l.map(|i| i < panel.n_stitch_side);
        for k in 0..3 {
            if stitch_side[pair[k][0]] && stitch_side[pair[k][1]] {
                let key = [g[pair[k][0]], g[pair[k][1]]];
                let (b, c) = (el[others[k][0]], el[others[k][1]]);
                let entry = match old[k] {
                    // The reference tests the old lower bound for truth: 0.0 starts afresh.
                    Some((low_old, up_old)) if low_old != 0.0 => [low_old.max((b - c).abs()), up_old.min(b + c), el[k]],
                    _ => [(b - c).abs(), b + c, el[k]],
                };
                self.seam.insert(key, entry);
            }
        }
    }
}

/// Refuses, before anything is laid out, a mesh that would have more than
/// [`MAX_MESH_VERTICES`] vertices: the edges' samples, a row of points along them and
/// the interior's density over each panel's area (an estimate; the triangulation counts again).
fn check_size(specs: &[&PanelSpec], counts: &[Vec<usize>], resolution: f64) -> Result<(), MeshError> {
    // Points per cm² of an equilateral lattice of spacing 1 cm (the interior's blue noise has
    // about 5% more; the triangulation counts them exactly).
    let density = 2.0 / 3f64.sqrt();
    let boundary: f64 = counts.iter().flatten().map(|&n| n as f64).sum();
    let area: f64 = specs.iter().map(|p| p.outline_area()).sum();
    let needed = 2.0 * boundary + density * area / (resolution * resolution);
    if needed <= MAX_MESH_VERTICES as f64 {
        return Ok(());
    }
    // At resolution r the estimate is about 2·L/r + density·A/r² (L the edges' length):
    // the r where that is the limit, rounded up to two significant digits.
    let (length, limit) = (boundary * resolution, MAX_MESH_VERTICES as f64);
    let x = (-2.0 * length + (4.0 * length * length + 4.0 * density * area * limit).sqrt()) / (2.0 * density * area).max(f64::MIN_POSITIVE);
    let r = if x > 0.0 && x.is_finite() { 1.0 / x } else { 2.0 * length / limit };
    let e = r.log10().floor() as i32 - 1;
    let coarser = if e < 0 { (r * 10f64.powi(-e)).ceil() / 10f64.powi(-e) } else { (r / 10f64.powi(e)).ceil() * 10f64.powi(e) };
    Err(MeshError::TooLarge { needed: needed.min(usize::MAX as f64) as usize, resolution, coarser })
}

/// Whether the panel's outline runs counter-clockwise, decided as the reference does:
/// by the majority turn of the outline points lying on its bounding box.
fn outline_orientation(p: &PanelSpec, samples: &[Vec<Vec2>]) -> Result<bool, MeshError> {
    let bad = |reason: &str| MeshError::DegeneratePanel { panel: p.name.clone(), reason: reason.into() };
    let mut outline: Vec<Vec2> = Vec::new();
    for (i, e) in p.edges.iter().enumerate() {
        let pts: Vec<Vec2> = if e.curvature.is_none() { vec![samples[i][0], samples[i][samples[i].len() - 1]] } else { samples[i].clone() };
        for q in pts {
            if outline.last() != Some(&q) {
                outline.push(q);
            }
        }
    }
    if outline.len() < 3 {
        return Err(bad("fewer than three outline points"));
    }
    let (lo, hi) =
        outline.iter().fold((Vec2::splat(f64::INFINITY), Vec2::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
    let mut on_box: Vec<Vec2> = outline.iter().copied().filter(|q| q.x == lo.x || q.x == hi.x || q.y == lo.y || q.y == hi.y).collect();
    if on_box.len() < 2 {
        return Err(bad("the outline's bounding box is touched by fewer than two points"));
    }
    if on_box.len() == 2 {
        let corner = if on_box.contains(&lo) { Vec2::new(lo.x, hi.y) } else { lo };
        on_box.insert(1, corner);
    }
    let c = on_box.iter().copied().sum::<Vec2>() / on_box.len() as f64;
    let turn: f64 = (0..on_box.len()).map(|i| (on_box[i] - c).perp_dot(on_box[(i + 1) % on_box.len()] - c).signum()).sum();
    if turn == 0.0 || turn.is_nan() {
        return Err(bad("the panel normal is undefined (the outline turns neither way)"));
    }
    Ok(turn > 0.0)
}

/// A copy of the pattern in centimetres.
fn to_cm(pattern: &Pattern) -> Pattern {
    let s = 100.0 / pattern.properties.units_in_meter;
    let mut p = pattern.clone();
    for panel in &mut p.panels {
        let inner = panel.holes.iter_mut().flat_map(|h| &mut h.vertices).chain(panel.lines.iter_mut().flat_map(|l| &mut l.vertices));
        for v in panel.vertices.iter_mut().chain(inner) {
            *v = [v[0] * s, v[1] * s];
        }
        panel.translation = panel.translation.map(|t| t * s);
        for e in panel.all_edges_mut() {
            if let Some(crate::Curvature::Circle { radius, .. }) = &mut e.curvature {
                *radius *= s;
            }
        }
    }
    p.properties.units_in_meter = 100.0;
    p
}
