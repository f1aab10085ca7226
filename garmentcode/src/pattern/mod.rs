//! The flat sewing pattern: the reference's `specification.json`.
//!
//! [`Pattern`] is what a garment assembles into and what the file holds: panels
//! (2D outline with relative curvature and a 3D placement), stitches between panel
//! edges, the panel order and format properties. It reads any reference-written file
//! ([`Pattern::from_json`]) and writes the same layout ([`Pattern::to_json`]),
//! deterministically.

pub(crate) mod extension;
pub(crate) mod order;
pub(crate) mod validate;
use crate::arc;
use crate::edge::{Curve, Edge};
use crate::math::Vec2;
use crate::rotation::Rotation;

/// A whole sewing pattern.
///
/// What a garment assembles into; reads and writes `specification.json`:
///
/// ```
/// use garmentcode::{Arena, EdgeSeq, PartExt, Pattern, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges);
/// let pattern = PartExt::assemble(&panel, &mut a, "demo")?;
/// assert_eq!(pattern.panel("front").map(|p| p.vertices.len()), Some(4));
/// let json = pattern.to_json()?;
/// assert_eq!(Pattern::from_json(&json)?.panels, pattern.panels);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern {
    /// Name of the pattern (the garment's name; not written in the file).
    pub name: String,
    /// Panels in file order.
    pub panels: Vec<PanelSpec>,
    /// Stitches between outline edges.
    pub stitches: Vec<StitchSpec>,
    /// Stitches with a side on a hole or an inner line (the format extension; empty
    /// in the reference's patterns).
    pub inner_stitches: Vec<InnerStitch>,
    /// Deterministic panel order by 3D location (written after the stitches).
    pub panel_order: Option<Vec<String>>,
    /// Legacy parametric-template parameters (always `{}` for GarmentCode output).
    pub parameters: serde_json::Value,
    /// Legacy parameter order (always `[]`).
    pub parameter_order: serde_json::Value,
    /// Format properties.
    pub properties: Properties,
}

/// Format flags of a specification file.
#[derive(Clone, Debug, PartialEq)]
pub struct Properties {
    /// `relative` (written) or `absolute` (legacy files).
    pub curvature_coords: String,
    /// Legacy re-centring flag (written `false`).
    pub normalize_panel_translation: bool,
    /// Loops already normalised (written `true`).
    pub normalized_edge_loops: bool,
    /// Units of the file: 100 = centimetres.
    pub units_in_meter: f64,
    /// Any other keys, kept as read.
    pub extra: Vec<(String, serde_json::Value)>,
}

impl Default for Properties {
    fn default() -> Self {
        Properties {
            curvature_coords: "relative".into(),
            normalize_panel_translation: false,
            normalized_edge_loops: true,
            units_in_meter: 100.0,
            extra: Vec::new(),
        }
    }
}

/// One panel as written.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelSpec {
    /// Unique panel name.
    pub name: String,
    /// World position of the local origin (cm).
    pub translation: [f64; 3],
    /// Intrinsic `XYZ` Euler angles, degrees.
    pub rotation: [f64; 3],
    /// Local 2D vertices (cm).
    pub vertices: Vec<[f64; 2]>,
    /// Outline edges in loop order.
    pub edges: Vec<EdgeSpec>,
    /// Semantic label (`body`, `arm`, `leg`...).
    pub label: Option<String>,
    /// Closed loops inside the outline (format extension; empty in the reference's).
    pub holes: Vec<Hole>,
    /// Lines inside the panel (format extension; empty in the reference's).
    pub lines: Vec<InnerLine>,
    /// Layer of a double-layer component ([`Layer::Outer`] in the reference's).
    pub layer: Layer,
}

/// One edge as written.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeSpec {
    /// Start and end vertex indices.
    pub endpoints: [usize; 2],
    /// Semantic label.
    pub label: Option<String>,
    /// Curvature; `None` for a straight edge.
    pub curvature: Option<Curvature>,
}

/// Curvature of a written edge, in the edge's relative frame.
#[derive(Clone, Debug, PartialEq)]
pub enum Curvature {
    /// Quadratic Bézier: one relative control point.
    Quadratic([f64; 2]),
    /// Cubic Bézier: two relative control points.
    Cubic([f64; 2], [f64; 2]),
    /// Circular arc: absolute radius, large-arc flag, bulges to the right.
    Circle {
        /// Radius in cm.
        radius: f64,
        /// Spans more than 180°.
        large_arc: bool,
        /// Bulges to the right of start → end.
        right: bool,
    },
}

/// One written stitch.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct StitchSpec {
    /// Both sides: panel name and edge index.
    pub sides: [StitchSide; 2],
    /// One fabric is flipped (`"right_wrong"`).
    pub right_wrong: bool,
}

/// One side of a stitch.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct StitchSide {
    /// Panel name.
    pub panel: String,
    /// Edge index in the panel's `edges`.
    pub edge: usize,
}

impl Pattern {
    /// Where the pattern holds a number that is not finite (NaN or infinite), if
    /// anywhere: the first such place, as `panel 'NAME' vertex 3` and the like. A
    /// pattern with one cannot be written (see [`Pattern::to_json`]).
    ///
    /// ```
    /// let mut p = garmentcode::Pattern::from_json(r#"{"pattern": {"panels": {"a": {"translation": [0, 0, 0],
    ///     "rotation": [0, 0, 0], "vertices": [[0, 0], [1, 0], [0, 1]],
    ///     "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 0]}]}}, "stitches": []},
    ///     "properties": {"curvature_coords": "relative", "normalize_panel_translation": false,
    ///     "normalized_edge_loops": true, "units_in_meter": 100}}"#).unwrap();
    /// assert_eq!(p.non_finite(), None);
    /// p.panels[0].vertices[2][1] = f64::NAN;
    /// assert_eq!(p.non_finite().as_deref(), Some("panel 'a' vertex 2"));
    /// ```
    pub fn non_finite(&self) -> Option<String> {
        let bad = |xs: &[f64]| xs.iter().any(|x| !x.is_finite());
        for p in &self.panels {
            if bad(&p.translation) {
                return Some(format!("panel '{}' translation", p.name));
            }
            if bad(&p.rotation) {
                return Some(format!("panel '{}' rotation", p.name));
            }
            if let Some(i) = p.vertices.iter().position(|v| bad(v)) {
                return Some(format!("panel '{}' vertex {i}", p.name));
            }
            for (h, hole) in p.holes.iter().enumerate() {
                if let Some(i) = hole.vertices.iter().position(|v| bad(v)) {
                    return Some(format!("panel '{}' hole {h} vertex {i}", p.name));
                }
            }
            for (l, line) in p.lines.iter().enumerate() {
                if let Some(i) = line.vertices.iter().position(|v| bad(v)) {
                    return Some(format!("panel '{}' line {l} vertex {i}", p.name));
                }
                if matches!(line.kind, LineKind::Fold { angle } if !angle.is_finite()) {
                    return Some(format!("panel '{}' line {l} fold angle", p.name));
                }
            }
            for (i, e) in p.all_edges().enumerate() {
                let finite = match &e.curvature {
                    None => true,
                    Some(Curvature::Quadratic(c)) => !bad(c),
                    Some(Curvature::Cubic(c1, c2)) => !bad(c1) && !bad(c2),
                    Some(Curvature::Circle { radius, .. }) => radius.is_finite(),
                };
                if !finite {
                    return Some(format!("panel '{}' {} curvature", p.name, p.edge_path(i)));
                }
            }
        }
        None
    }

    /// An empty pattern.
    pub fn new(name: &str) -> Pattern {
        Pattern {
            name: name.to_string(),
            panels: Vec::new(),
            stitches: Vec::new(),
            inner_stitches: Vec::new(),
            panel_order: None,
            parameters: serde_json::Value::Object(Default::default()),
            parameter_order: serde_json::Value::Array(Vec::new()),
            properties: Properties::default(),
        }
    }

    /// A panel by name.
    pub fn panel(&self, name: &str) -> Option<&PanelSpec> {
        self.panels.iter().find(|p| p.name == name)
    }

    /// No panels.
    pub fn is_empty(&self) -> bool {
        self.panels.is_empty()
    }

    /// Whether the pattern says anything past the reference's format (holes, inner
    /// lines, layers, stitches on them: [`Hole`], [`InnerLine`], [`Layer`], [`InnerStitch`]).
    pub fn uses_extension(&self) -> bool {
        !self.inner_stitches.is_empty() || self.panels.iter().any(PanelSpec::uses_extension)
    }
}

impl PanelSpec {
    /// A panel with no holes, no inner lines, on the outer layer (all the reference's
    /// format holds).
    pub fn new(
        name: &str,
        translation: [f64; 3],
        rotation: [f64; 3],
        vertices: Vec<[f64; 2]>,
        edges: Vec<EdgeSpec>,
        label: Option<String>,
    ) -> PanelSpec {
        PanelSpec {
            name: name.to_string(),
            translation,
            rotation,
            vertices,
            edges,
            label,
            holes: Vec::new(),
            lines: Vec::new(),
            layer: Layer::Outer,
        }
    }

    /// Whether the panel has holes, inner lines or a layer other than the outer one.
    pub fn uses_extension(&self) -> bool {
        !self.holes.is_empty() || !self.lines.is_empty() || self.layer != Layer::Outer
    }

    /// Vertex `i` as a point.
    pub fn vertex(&self, i: usize) -> Vec2 {
        Vec2::from(self.vertices[i])
    }

    /// Geometry of edge `i` (indices must be valid: see [`validate`](crate::validate)).
    pub fn edge_geom(&self, i: usize) -> Edge {
        edge_geometry(&self.vertices, &self.edges[i])
    }

    /// The outline as a polygon, relative to the first edge's start: each edge's start
    /// and, on curves, `steps − 1` points between (edges and corners must be valid).
    pub fn outline_polygon(&self, steps: usize) -> Vec<Vec2> {
        let Some(first) = self.edges.first() else { return Vec::new() };
        let origin = self.vertex(first.endpoints[0]);
        let mut out = Vec::new();
        for i in 0..self.edges.len() {
            let e = self.edge_geom(i);
            let n = if matches!(e.curve, Curve::Line) { 1 } else { steps.max(1) };
            out.extend((0..n).map(|k| e.point(k as f64 / n as f64) - origin));
        }
        out
    }

    /// Area enclosed by the outline: the shoelace formula over [`outline_polygon`](Self::outline_polygon)
    /// with curves at 16 points (for curves an estimate).
    pub fn outline_area(&self) -> f64 {
        let q = self.outline_polygon(16);
        (0..q.len()).map(|k| q[k].perp_dot(q[(k + 1) % q.len()])).sum::<f64>().abs() / 2.0
    }

    /// Rotation of the panel.
    pub fn rotation(&self) -> Rotation {
        Rotation::from_euler_xyz_degrees(self.rotation)
    }

    /// World position of a local point.
    pub fn point_to_3d(&self, p: Vec2) -> crate::math::Vec3 {
        self.rotation().apply(crate::math::Vec3::new(p.x, p.y, 0.0)) + crate::math::Vec3::from(self.translation)
    }

    /// Edge-type string (`L`, `A`, `Q`, `C` per edge).
    pub fn edge_types(&self) -> String {
        self.edges
            .iter()
            .map(|e| match e.curvature {
                None => 'L',
                Some(Curvature::Quadratic(_)) => 'Q',
                Some(Curvature::Cubic(..)) => 'C',
                Some(Curvature::Circle { .. }) => 'A',
            })
            .collect()
    }
}

/// Geometry of `e` over `vertices` (an outline's, a hole's or an inner line's; the
/// indices must be valid).
pub(crate) fn edge_geometry(vertices: &[[f64; 2]], e: &EdgeSpec) -> Edge {
    let (s, t) = (Vec2::from(vertices[e.endpoints[0]]), Vec2::from(vertices[e.endpoints[1]]));
    let curve = match &e.curvature {
        None => Curve::Line,
        Some(Curvature::Quadratic(c)) => Curve::Quadratic(Vec2::from(*c)),
        Some(Curvature::Cubic(c1, c2)) => Curve::Cubic(Vec2::from(*c1), Vec2::from(*c2)),
        Some(Curvature::Circle { radius, large_arc, right }) => Curve::Arc { cy: arc::cy_from_radius(s, t, *radius, *large_arc, *right) },
    };
    Edge { start: s, end: t, curve }
}

/// Why the circular arc `e` cannot be drawn, if its radius is under half the distance
/// between its ends (beyond the tolerance [`crate::arc::cy_from_radius`] rounds to a
/// half circle): the message says the radius it needs at least.
pub(crate) fn arc_radius_too_small(vertices: &[[f64; 2]], e: &EdgeSpec) -> Option<String> {
    let Some(Curvature::Circle { radius, .. }) = e.curvature else { return None };
    let (s, t) = (Vec2::from(vertices[e.endpoints[0]]), Vec2::from(vertices[e.endpoints[1]]));
    let half = (t - s).length() / 2.0;
    (radius * radius < half * half - 1e-3).then(|| {
        format!(
            "arc radius {} cm is under half the distance between its ends: no circle of that radius joins them (at least {} cm)",
            crate::message::short(radius),
            crate::message::short(half)
        )
    })
}

// The format extension's types (see `extension.rs` for what they mean and their methods).

/// A closed loop of edges inside a panel's outline.
#[derive(Clone, Debug, PartialEq)]
pub struct Hole {
    /// Name, unique among the panel's holes and lines.
    pub name: String,
    /// What the loop is: cut out, or a dart sewn closed.
    pub kind: HoleKind,
    /// Panel-local vertices (cm).
    pub vertices: Vec<[f64; 2]>,
    /// The loop's edges in order; the last ends where the first starts.
    pub edges: Vec<EdgeSpec>,
}

/// What a [`Hole`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HoleKind {
    /// Cut out of the fabric (a keyhole, a welt-pocket opening): an internal cut-out on
    /// prints, an opening in the mesh.
    Cut,
    /// A dart inside the panel (a diamond dart): its sides are sewn together, the
    /// fabric between them is folded away. Printed as marked lines with drill holes, an
    /// opening in the mesh whose sides are stitched.
    Dart,
}

/// An open line of edges inside a panel (not on its outline).
#[derive(Clone, Debug, PartialEq)]
pub struct InnerLine {
    /// Name, unique among the panel's holes and lines.
    pub name: String,
    /// What the line is for.
    pub kind: LineKind,
    /// Panel-local vertices (cm).
    pub vertices: Vec<[f64; 2]>,
    /// The line's edges in order, each starting where the one before ends.
    pub edges: Vec<EdgeSpec>,
}

/// What an [`InnerLine`] is for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LineKind {
    /// The panel is folded along the line (a one-piece sleeve, a double cuff or
    /// turtleneck folded along its middle): the AAMA mirror line on prints, a row of
    /// mesh edges. `angle` is the fold's dihedral turn in degrees at which the box mesh
    /// places the side of the panel to the line's right (0: flat; 180: folded flat
    /// over the left side).
    Fold {
        /// Turn of the right side about the line, degrees, 0 to 180.
        angle: f64,
    },
    /// Where a piece sewn on top goes (a patch pocket, a flounce): an internal line
    /// on prints with drill holes at its corners, a row of mesh edges that stitches
    /// may use.
    Placement,
    /// The fold of a pleat (the edge of the fabric that is folded over).
    PleatFold,
    /// Where a pleat's fold is laid down.
    PleatPlacement,
}

/// Which layer of a double-layer component a panel is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Layer {
    /// The outside (every panel of the reference's format).
    #[default]
    Outer,
    /// A facing: the inside layer of a collar, cuff or neckline, joined to the outer
    /// layer along edges.
    Facing,
    /// A lining.
    Lining,
}

/// Where a stitched edge lies in its panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum EdgePlace {
    /// On the outline (`edges`).
    Outline,
    /// On the panel's hole with this index.
    Hole(usize),
    /// On the panel's inner line with this index.
    Line(usize),
}

/// One side of an [`InnerStitch`].
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct InnerSide {
    /// Panel name.
    pub panel: String,
    /// Outline, hole or line of the panel.
    pub place: EdgePlace,
    /// Edge index in that outline, hole or line.
    pub edge: usize,
}

/// A stitch with at least one side on a hole or an inner line (stitches between
/// outline edges only are [`StitchSpec`]s, as the reference has them).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct InnerStitch {
    /// Both sides.
    pub sides: [InnerSide; 2],
    /// One fabric is flipped.
    pub right_wrong: bool,
}

/// Version of the format extension this code writes (`properties.extension_version`).
pub const EXTENSION_VERSION: u32 = 1;
