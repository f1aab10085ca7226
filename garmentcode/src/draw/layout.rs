//! The sheet: panels placed as the reference places them (pattern-format.md §11.1),
//! plus the annotations drawn over them. Shared by the SVG writer and the rasteriser
//! so that both show the same picture.
//!
//! All coordinates here are sheet coordinates: centimetres, x right, y down.

use std::cmp::Ordering;
use std::collections::HashMap;

use super::font;
use super::options::{DrawOptions, FLAT_ROW_WIDTH, Layout};
use crate::arc::SvgArc;
use crate::bezier::Bezier;
use crate::error::{Error, Result};
use crate::math::{Vec2, Vec3, rel_to_abs, rotate2d, vector_angle_clamped};
use crate::pattern::{Curvature, EdgePlace, EdgeSpec, HoleKind, LineKind, PanelSpec, Pattern};

/// An sRGB colour.
pub type Rgb = [u8; 3];

/// Panel fill of the reference.
pub const PANEL_FILL: Rgb = [227, 175, 186];
/// Panel outline of the reference.
pub const PANEL_STROKE: Rgb = [51, 51, 51];
/// Outline width of the reference (cm).
pub const PANEL_STROKE_WIDTH: f64 = 0.2;
/// Colour of panel names (reference).
pub const NAME_FILL: Rgb = [31, 31, 31];
/// Colour of vertex indices (reference).
pub const VERTEX_ID_FILL: Rgb = [245, 96, 66];
/// Colour of edge indices (reference).
pub const EDGE_ID_FILL: Rgb = [44, 131, 68];
/// Font size of names and indices (reference), cm.
pub const FONT_SIZE: f64 = 7.0;
/// Radius of a stitch marker disc, cm: big enough for two digits at 3 px/cm.
pub const MARKER_RADIUS: f64 = 2.4;
/// Font size of the number in a stitch marker, cm (at [`MARKER_RADIUS`]; a
/// smaller disc has a proportionally smaller number).
pub const MARKER_FONT_SIZE: f64 = 3.4;
/// Sizes a marker is tried at, as fractions of [`MARKER_RADIUS`]: where a full-size
/// disc does not fit, a smaller one may; the last is the floor (digits still about
/// 5 px high at 3 px/cm).
pub const MARKER_SCALES: [f64; 3] = [1.0, 0.85, 0.7];
/// How many rows of discs deep into the panel a marker is tried.
const MARKER_DEPTHS: usize = 3;
/// Directions tried on each ring of spots outside a panel, in degrees from
/// straight out of the edge.
const LEADER_TURNS: [f64; 12] = [0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0, 120.0, -120.0, 150.0, -150.0, 180.0];
/// Most rings of spots tried outside a panel (bounds the work on absurd sizes).
const MAX_LEADER_RINGS: f64 = 2000.0;
/// Width of the leader line from an edge to its marker moved outside the panel, cm.
pub const LEADER_WIDTH: f64 = 0.2;
/// Width of the coloured trace over a stitched edge, cm.
pub const MARKER_TRACE_WIDTH: f64 = 0.6;
/// White ring around a marker disc, cm, to separate it from the trace.
pub const MARKER_RING_WIDTH: f64 = 0.25;
/// Gap between an edge and its marker disc, cm.
const MARKER_GAP: f64 = 0.5;
/// Horizontal spacing between the front and the back panels (reference).
const BACK_SPACING: f64 = 10.0;
/// Edge indices sit this far above the edge midpoint (reference).
const EDGE_ID_LIFT: f64 = 3.0;

/// Shape of one outline piece between its end points.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// Straight line.
    Line,
    /// Quadratic Bézier with its absolute control point.
    Quad(Vec2),
    /// Cubic Bézier with its absolute control points.
    Cubic(Vec2, Vec2),
    /// Circular arc (explicit centre parametrisation; `sweep` is in y-down numbers).
    Arc(SvgArc),
}

/// One drawn edge.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    /// Start point.
    pub start: Vec2,
    /// End point.
    pub end: Vec2,
    /// Shape between them.
    pub shape: Shape,
    /// Index of the start vertex in the panel (to see where the outline is broken).
    pub from: usize,
    /// Index of the end vertex.
    pub to: usize,
}

/// Axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BBox {
    /// Lowest x and y.
    pub min: Vec2,
    /// Highest x and y.
    pub max: Vec2,
}

impl BBox {
    fn of_point(p: Vec2) -> BBox {
        BBox { min: p, max: p }
    }

    fn add(&mut self, p: Vec2) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    fn union(&self, o: &BBox) -> BBox {
        BBox { min: self.min.min(o.min), max: self.max.max(o.max) }
    }

    /// A square of half-side `r` around `c`.
    fn around(c: Vec2, r: f64) -> BBox {
        BBox { min: c - Vec2::splat(r), max: c + Vec2::splat(r) }
    }

    /// Whether the two boxes share more than a boundary.
    pub fn overlaps(&self, o: &BBox) -> bool {
        self.min.x < o.max.x && o.min.x < self.max.x && self.min.y < o.max.y && o.min.y < self.max.y
    }

    /// Centre of the box.
    pub fn centre(&self) -> Vec2 {
        (self.min + self.max) / 2.0
    }
}

/// A panel placed on the sheet.
#[derive(Clone, Debug)]
pub struct PlacedPanel {
    /// Panel name.
    pub name: String,
    /// Edges in file order (segment `k` is edge `k`).
    pub segments: Vec<Segment>,
    /// Exact bounding box of the outline (curve extrema included).
    pub bbox: BBox,
    /// Whether the outline runs counter-clockwise in sheet numbers (interior on the
    /// left of the travel direction, taking x right and y as the second axis).
    pub ccw: bool,
    /// The panel's holes, then its inner lines (format extension), placed with it.
    pub marks: Vec<Mark>,
}

impl PlacedPanel {
    /// Edge `edge` of the outline, of hole `k` or of inner line `k`, if there is one.
    pub fn edge_segment(&self, place: EdgePlace, edge: usize) -> Option<&Segment> {
        let is_hole = |m: &&Mark| matches!(m.kind, MarkKind::Cut | MarkKind::Dart);
        match place {
            EdgePlace::Outline => self.segments.get(edge),
            EdgePlace::Hole(k) => self.marks.iter().filter(is_hole).nth(k)?.segments.get(edge),
            EdgePlace::Line(k) => self.marks.iter().filter(|m| !is_hole(m)).nth(k)?.segments.get(edge),
        }
    }

    /// Move the panel, its marks and its box by `d`.
    fn translate(&mut self, d: Vec2) {
        for s in self.segments.iter_mut().chain(self.marks.iter_mut().flat_map(|m| &mut m.segments)) {
            s.translate(d);
        }
        self.bbox = BBox { min: self.bbox.min + d, max: self.bbox.max + d };
    }
}

/// What a [`Mark`] is, and so how it is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MarkKind {
    /// A hole cut out: an opening in the panel, outlined.
    Cut,
    /// A dart inside the panel: a dashed loop.
    Dart,
    /// A fold line: dash-dot, labelled "fold".
    Fold,
    /// Where a piece sewn on top goes: dashed.
    Placement,
    /// A pleat's fold: long dashes.
    PleatFold,
    /// Where a pleat's fold is laid: dotted.
    PleatPlacement,
}

impl MarkKind {
    /// The SVG class and the dash pattern (cm; none for a solid line).
    pub fn style(self) -> (&'static str, &'static [f64]) {
        match self {
            MarkKind::Cut => ("cut", &[]),
            MarkKind::Dart => ("dart", &[0.8, 0.4]),
            MarkKind::Fold => ("fold", &[1.6, 0.4, 0.3, 0.4]),
            MarkKind::Placement => ("placement", &[0.6, 0.4]),
            MarkKind::PleatFold => ("pleat-fold", &[1.6, 0.6]),
            MarkKind::PleatPlacement => ("pleat-placement", &[0.2, 0.4]),
        }
    }
}

/// Stroke width of hole and inner-line marks, cm.
pub const MARK_STROKE_WIDTH: f64 = 0.15;
/// Font size of the "fold" label on fold lines, cm.
pub const MARK_FONT_SIZE: f64 = 2.0;

/// A hole or an inner line of a panel, placed on the sheet.
#[derive(Clone, Debug)]
pub struct Mark {
    /// What it is.
    pub kind: MarkKind,
    /// Its name in the pattern.
    pub name: String,
    /// Its edges (`from` and `to` index its own vertices).
    pub segments: Vec<Segment>,
}

/// Where and how a text is anchored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// Text starts at the point, baseline through it (SVG defaults).
    StartBaseline,
    /// Centred horizontally, baseline through the point.
    MiddleBaseline,
    /// Centred horizontally, vertical middle (half the x-height) at the point.
    MiddleMiddle,
    /// Centred horizontally and on the digit/capital height.
    MiddleCentral,
}

/// Which annotation layer a text belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextKind {
    /// Panel name.
    Name,
    /// Vertex index.
    VertexId,
    /// Edge index.
    EdgeId,
    /// Number in a stitch marker.
    Marker,
    /// Label of a fold line ("fold").
    MarkLabel,
}

/// A text on the sheet.
#[derive(Clone, Debug)]
pub struct Text {
    /// Anchor point.
    pub pos: Vec2,
    /// The text.
    pub text: String,
    /// Font size, cm.
    pub size: f64,
    /// Colour.
    pub fill: Rgb,
    /// How `pos` relates to the text.
    pub anchor: Anchor,
    /// Layer.
    pub kind: TextKind,
}

impl Text {
    /// The box the text takes on the sheet (an estimate, as the SVG viewer picks
    /// the font): as wide as the PNG's stroke font sets it or 0.6 em per character,
    /// whichever is wider, and one em high.
    pub fn bbox(&self) -> BBox {
        let chars = self.text.chars().count() as f64;
        let w = font::set(&self.text, self.size).width.max(0.6 * self.size * chars);
        let left = match self.anchor {
            Anchor::StartBaseline => self.pos.x,
            _ => self.pos.x - w / 2.0,
        };
        let top = match self.anchor {
            Anchor::StartBaseline | Anchor::MiddleBaseline => self.pos.y - 0.75 * self.size,
            Anchor::MiddleMiddle | Anchor::MiddleCentral => self.pos.y - 0.5 * self.size,
        };
        BBox { min: Vec2::new(left, top), max: Vec2::new(left + w, top + self.size) }
    }
}

/// One side of a stitch, marked on the sheet.
#[derive(Clone, Debug)]
pub struct Marker {
    /// The stitch's number (shown): its index in `pattern.stitches`, or for inner
    /// stitch `j` (format extension) `pattern.stitches.len() + j`, as the box mesh's
    /// `stitch_K` labels count them.
    pub stitch: usize,
    /// Index of the placed panel in [`Sheet::panels`].
    pub panel: usize,
    /// Where the edge is: the panel's outline, one of its holes or inner lines.
    pub place: EdgePlace,
    /// Edge index within its outline, hole or line.
    pub edge: usize,
    /// Colour of the stitch.
    pub color: Rgb,
    /// Centre of the marker disc.
    pub centre: Vec2,
    /// Radius of the disc: [`MARKER_RADIUS`] or, where that does not fit, one of
    /// the smaller [`MARKER_SCALES`].
    pub radius: f64,
    /// The point of the edge the marker stands for.
    pub anchor: Vec2,
    /// The marker found no room inside its panel and sits outside, joined to
    /// `anchor` by a leader line.
    pub leader: bool,
}

impl Marker {
    /// The edge marked, on `sheet` (the one the marker was placed on).
    pub fn segment<'s>(&self, sheet: &'s Sheet) -> &'s Segment {
        sheet.panels[self.panel].edge_segment(self.place, self.edge).expect("a marker's edge exists")
    }

    /// The stitch number, white and centred on the disc.
    pub fn label(&self) -> Text {
        Text {
            pos: self.centre,
            text: self.stitch.to_string(),
            size: MARKER_FONT_SIZE * self.radius / MARKER_RADIUS,
            fill: [255, 255, 255],
            anchor: Anchor::MiddleCentral,
            kind: TextKind::Marker,
        }
    }

    /// The box of the disc with its white ring.
    pub fn bbox(&self) -> BBox {
        BBox::around(self.centre, self.radius + MARKER_RING_WIDTH / 2.0)
    }
}

/// Everything to draw.
#[derive(Clone, Debug)]
pub struct Sheet {
    /// `[x, y, width, height]` in cm, rounded to 3 decimals (as written).
    pub view_box: [f64; 4],
    /// Panels in drawing order: front panels, then back panels, each by (z, name).
    pub panels: Vec<PlacedPanel>,
    /// Stitch markers, by stitch then side.
    pub markers: Vec<Marker>,
    /// Names first, then vertex and edge indices.
    pub texts: Vec<Text>,
}

/// Round to 3 decimals (the precision of every number written).
pub fn round3(x: f64) -> f64 {
    let r = (x * 1000.0).round() / 1000.0;
    if r == 0.0 { 0.0 } else { r }
}

impl Segment {
    /// Point at parameter `t` in `[0, 1]`.
    pub fn point(&self, t: f64) -> Vec2 {
        match self.shape {
            Shape::Line => self.start + (self.end - self.start) * t,
            Shape::Arc(a) => a.point(t),
            _ => self.bezier().expect("Bézier shape").point(t),
        }
    }

    fn derivative(&self, t: f64) -> Vec2 {
        match self.shape {
            Shape::Line => self.end - self.start,
            Shape::Arc(a) => a.derivative(t),
            _ => self.bezier().expect("Bézier shape").derivative(t),
        }
    }

    /// The Bézier curve of a quadratic or cubic piece.
    fn bezier(&self) -> Option<Bezier> {
        match self.shape {
            Shape::Quad(c) => Some(Bezier::Quadratic([self.start, c, self.end])),
            Shape::Cubic(c1, c2) => Some(Bezier::Cubic([self.start, c1, c2, self.end])),
            _ => None,
        }
    }

    /// Parameter of the point at fraction `f` of the arc length.
    fn length_param(&self, f: f64) -> f64 {
        match self.bezier() {
            // Lines and arcs are uniform in arc length.
            None => f,
            Some(b) => b.inverse_length(b.length() * f).unwrap_or(f),
        }
    }

    /// Arc-length midpoint and the unit tangent there (the chord direction where the
    /// curve has no tangent).
    pub fn midpoint(&self) -> (Vec2, Vec2) {
        self.at_fraction(0.5)
    }

    /// The point at fraction `f` of the arc length and the unit tangent there (the
    /// chord direction where the curve has no tangent).
    pub fn at_fraction(&self, f: f64) -> (Vec2, Vec2) {
        let t = self.length_param(f);
        let d = self.derivative(t);
        let d = if d.length() > 1e-12 { d } else { self.end - self.start };
        let tangent = if d.length() > 1e-12 { d.normalize() } else { Vec2::X };
        (self.point(t), tangent)
    }

    /// Exact bounding box: end points plus the interior extrema of the curve.
    fn bbox(&self) -> BBox {
        let mut b = BBox::of_point(self.start);
        b.add(self.end);
        match self.shape {
            Shape::Line => {}
            Shape::Quad(c) => {
                for t in quad_extrema(self.start, c, self.end) {
                    b.add(self.point(t));
                }
            }
            Shape::Cubic(c1, c2) => {
                for t in cubic_extrema(self.start, c1, c2, self.end) {
                    b.add(self.point(t));
                }
            }
            Shape::Arc(a) => {
                // Axis directions (multiples of 90°) crossed by the swept angle.
                let (lo, hi) = if a.delta >= 0.0 { (a.theta, a.theta + a.delta) } else { (a.theta + a.delta, a.theta) };
                let mut k = (lo / 90.0).ceil();
                while k * 90.0 <= hi {
                    // Exact axis points (cos/sin of multiples of 90° are 0 or ±1).
                    let dir = match (k as i64).rem_euclid(4) {
                        0 => Vec2::X,
                        1 => Vec2::Y,
                        2 => -Vec2::X,
                        _ => -Vec2::Y,
                    };
                    b.add(a.center + dir * a.radius);
                    k += 1.0;
                }
            }
        }
        b
    }

    fn translate(&mut self, d: Vec2) {
        self.start += d;
        self.end += d;
        self.shape = match self.shape {
            Shape::Line => Shape::Line,
            Shape::Quad(c) => Shape::Quad(c + d),
            Shape::Cubic(c1, c2) => Shape::Cubic(c1 + d, c2 + d),
            Shape::Arc(mut a) => {
                a.start += d;
                a.end += d;
                a.center += d;
                Shape::Arc(a)
            }
        };
    }
}

/// Parameters in (0, 1) where a quadratic Bézier has an x or y extremum.
fn quad_extrema(p0: Vec2, p1: Vec2, p2: Vec2) -> Vec<f64> {
    let mut out = Vec::new();
    for axis in 0..2 {
        let (a, b, c) = (p0[axis], p1[axis], p2[axis]);
        let den = a - 2.0 * b + c;
        if den.abs() > 1e-15 {
            let t = (a - b) / den;
            if t > 0.0 && t < 1.0 {
                out.push(t);
            }
        }
    }
    out
}

/// Parameters in (0, 1) where a cubic Bézier has an x or y extremum (roots of the
/// derivative, a quadratic per axis).
fn cubic_extrema(p0: Vec2, p1: Vec2, p2: Vec2, p3: Vec2) -> Vec<f64> {
    let mut out = Vec::new();
    for axis in 0..2 {
        let (a0, a1, a2, a3) = (p0[axis], p1[axis], p2[axis], p3[axis]);
        // B'(t)/3 = a t² + b t + c
        let a = -a0 + 3.0 * a1 - 3.0 * a2 + a3;
        let b = 2.0 * (a0 - 2.0 * a1 + a2);
        let c = a1 - a0;
        let mut roots = Vec::new();
        if a.abs() < 1e-12 {
            if b.abs() > 1e-15 {
                roots.push(-c / b);
            }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc >= 0.0 {
                let s = disc.sqrt();
                roots.push((-b + s) / (2.0 * a));
                roots.push((-b - s) / (2.0 * a));
            }
        }
        out.extend(roots.into_iter().filter(|t| *t > 0.0 && *t < 1.0));
    }
    out
}

/// Lay out the whole sheet.
pub fn layout(p: &Pattern, opts: &DrawOptions) -> Result<Sheet> {
    if p.panels.is_empty() {
        return Err(Error::Design("cannot draw an empty pattern (it has no panels)".into()));
    }
    if !(opts.margin.is_finite() && opts.margin >= 0.0) {
        return Err(Error::Input(format!("drawing margin must be a non-negative number, not {}", opts.margin)));
    }

    // The reference draws panels ordered by (translation z, name).
    let mut order: Vec<&PanelSpec> = p.panels.iter().collect();
    order.sort_by(|a, b| a.translation[2].partial_cmp(&b.translation[2]).unwrap_or(Ordering::Equal).then_with(|| a.name.cmp(&b.name)));
    let mut front = Vec::new();
    let mut back = Vec::new();
    for panel in order {
        let placed = place(panel)?;
        if panel.translation[2] >= 0.0 { front.push(placed) } else { back.push(placed) }
    }

    // Back panels go to the right of the front ones.
    if !front.is_empty() && !back.is_empty() {
        let front_max = front.iter().map(|q| q.bbox.max.x).fold(f64::NEG_INFINITY, f64::max);
        let back_min = back.iter().map(|q| q.bbox.min.x).fold(f64::INFINITY, f64::min);
        let shift = Vec2::new(front_max - back_min + BACK_SPACING, 0.0);
        for q in &mut back {
            q.translate(shift);
        }
    }
    let mut panels = front;
    panels.append(&mut back);
    if opts.layout == Layout::Flat {
        arrange_flat(p, &mut panels);
    }

    let all = panels.iter().skip(1).fold(panels[0].bbox, |acc, q| acc.union(&q.bbox));
    let m = Vec2::splat(opts.margin);
    let texts = texts(&panels, opts);
    let names: Vec<BBox> = texts.iter().filter(|t| matches!(t.kind, TextKind::Name | TextKind::MarkLabel)).map(Text::bbox).collect();
    let markers = if opts.stitch_markers { markers(p, &panels, &names)? } else { Vec::new() };
    // The margin around the panels, and room for markers moved outside them.
    let all = markers.iter().fold(BBox { min: all.min - m, max: all.max + m }, |acc, k| acc.union(&k.bbox()));
    let size = all.max - all.min;
    let view_box = [round3(all.min.x), round3(all.min.y), round3(size.x), round3(size.y)];
    Ok(Sheet { view_box, panels, markers, texts })
}

/// Gap between panels of the flat layout, cm.
const FLAT_GAP: f64 = 4.0;

/// Rearrange placed panels into rows without overlap (shelf packing in the
/// pattern's panel order, or by name for panels the order does not list).
fn arrange_flat(p: &Pattern, panels: &mut [PlacedPanel]) {
    let order = p.panel_order.clone().unwrap_or_else(|| crate::pattern::order::panel_order(p));
    let rank = |name: &str| order.iter().position(|n| n == name).unwrap_or(usize::MAX);
    panels.sort_by(|a, b| rank(&a.name).cmp(&rank(&b.name)).then_with(|| a.name.cmp(&b.name)));
    let widest = panels.iter().map(|q| q.bbox.max.x - q.bbox.min.x).fold(0.0, f64::max);
    let row_width = FLAT_ROW_WIDTH.max(widest);
    let (mut x, mut y, mut row_height) = (0.0, 0.0, 0.0f64);
    for q in panels.iter_mut() {
        let size = q.bbox.max - q.bbox.min;
        if x > 0.0 && x + size.x > row_width {
            x = 0.0;
            y += row_height + FLAT_GAP;
            row_height = 0.0;
        }
        q.translate(Vec2::new(x, y) - q.bbox.min);
        x += size.x + FLAT_GAP;
        row_height = row_height.max(size.y);
    }
}

/// Place one panel as `VisPattern._draw_a_panel` does: flip y, move the bounding box
/// corner of the vertices to the origin, rotate about the first vertex by the
/// in-plane angle of the panel's y axis, translate by the flipped 2D translation.
fn place(panel: &PanelSpec) -> Result<PlacedPanel> {
    let bad = |what: &str| Error::Input(format!("cannot draw panel '{}': {what}", panel.name));
    if panel.edges.is_empty() || panel.vertices.is_empty() {
        return Err(bad("it has no edges"));
    }
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    if !finite(&panel.translation) || !finite(&panel.rotation) || !panel.vertices.iter().all(|v| finite(v)) {
        return Err(bad("non-finite placement or vertex"));
    }

    let flipped: Vec<Vec2> = panel.vertices.iter().map(|v| Vec2::new(v[0], -v[1])).collect();
    let offset = flipped.iter().skip(1).fold(flipped[0], |acc, v| acc.min(*v));
    let origin = flipped[0] - offset;
    let translation = Vec2::new(panel.translation[0], -panel.translation[1]) + offset;

    // In-plane rotation: angle from (0, 1) to the projection of R·(0, 1, 0); a panel
    // whose y axis points straight along z has none.
    let w = panel.rotation().apply(Vec3::Y);
    let w2 = Vec2::new(w.x, w.y);
    let alpha = if w2.length() > 1e-12 { vector_angle_clamped(Vec2::Y, w2) } else { 0.0 };
    // Degrees and back, as the reference does (`path.rotated(degs=-angle)`).
    let theta = (-alpha.to_degrees()).to_radians();
    let place_point = |q: Vec2| rotate2d(q - origin, theta) + origin + translation;

    // The edges `edges` over `vertices` (the outline's, a hole's or a line's; `what`
    // names them in errors) as placed segments.
    let segments_of = |vertices: &[[f64; 2]], edges: &[EdgeSpec], what: &str| -> Result<Vec<Segment>> {
        if !vertices.iter().all(|v| finite(v)) {
            return Err(bad(&format!("{what}non-finite vertex")));
        }
        let local: Vec<Vec2> = vertices.iter().map(|v| Vec2::new(v[0], -v[1]) - offset).collect();
        let mut segments = Vec::with_capacity(edges.len());
        for (k, e) in edges.iter().enumerate() {
            let [i, j] = e.endpoints;
            if let Some(v) = [i, j].into_iter().find(|&v| v >= local.len()) {
                return Err(bad(&format!("{what}edge {k} refers to vertex {v}, but there are {} vertices", local.len())));
            }
            let (s, t) = (local[i], local[j]);
            // Relative control points with y negated: the flip mirrors the edge frame.
            let ctrl = |c: [f64; 2]| -> Result<Vec2> {
                if !finite(&c) {
                    return Err(bad(&format!("{what}edge {k} has a non-finite control point")));
                }
                Ok(place_point(rel_to_abs(s, t, Vec2::new(c[0], -c[1]))))
            };
            let (start, end) = (place_point(s), place_point(t));
            let shape = match &e.curvature {
                None => Shape::Line,
                Some(Curvature::Quadratic(c)) => Shape::Quad(ctrl(*c)?),
                Some(Curvature::Cubic(c1, c2)) => Shape::Cubic(ctrl(*c1)?, ctrl(*c2)?),
                Some(Curvature::Circle { radius, large_arc, right }) => {
                    if !(radius.is_finite() && *radius > 0.0) {
                        return Err(bad(&format!("{what}edge {k} has an invalid arc radius {radius}")));
                    }
                    if start == end {
                        return Err(bad(&format!("{what}arc edge {k} starts where it ends")));
                    }
                    // y-down drawing: the sweep flag is the opposite of `right`.
                    Shape::Arc(SvgArc::new(start, end, *radius, *large_arc, !*right))
                }
            };
            segments.push(Segment { start, end, shape, from: i, to: j });
        }
        Ok(segments)
    };

    let segments = segments_of(&panel.vertices, &panel.edges, "")?;
    let mut marks = Vec::with_capacity(panel.holes.len() + panel.lines.len());
    for h in &panel.holes {
        let kind = match h.kind {
            HoleKind::Cut => MarkKind::Cut,
            HoleKind::Dart => MarkKind::Dart,
        };
        let segments = segments_of(&h.vertices, &h.edges, &format!("hole '{}': ", h.name))?;
        marks.push(Mark { kind, name: h.name.clone(), segments });
    }
    for l in &panel.lines {
        let kind = match l.kind {
            LineKind::Fold { .. } => MarkKind::Fold,
            LineKind::Placement => MarkKind::Placement,
            LineKind::PleatFold => MarkKind::PleatFold,
            LineKind::PleatPlacement => MarkKind::PleatPlacement,
        };
        let segments = segments_of(&l.vertices, &l.edges, &format!("line '{}': ", l.name))?;
        marks.push(Mark { kind, name: l.name.clone(), segments });
    }

    let bbox = segments.iter().skip(1).fold(segments[0].bbox(), |acc, s| acc.union(&s.bbox()));
    let ccw = signed_area(&segments) >= 0.0;
    Ok(PlacedPanel { name: panel.name.clone(), segments, bbox, ccw, marks })
}

/// The outline as a closed polygon: line ends, and `per_curve` points per curve.
fn polygon(segments: &[Segment], per_curve: usize) -> Vec<Vec2> {
    let mut pts = Vec::new();
    for s in segments {
        let n = if matches!(s.shape, Shape::Line) { 1 } else { per_curve };
        pts.extend((0..n).map(|k| s.point(k as f64 / n as f64)));
    }
    pts
}

/// Signed area of the outline (positive: the interior is on the left of the travel
/// direction).
fn signed_area(segments: &[Segment]) -> f64 {
    let pts = polygon(segments, 8);
    let mut area = 0.0;
    for k in 0..pts.len() {
        let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
        area += a.x * b.y - b.x * a.y;
    }
    area / 2.0
}

/// Distance from `p` (on the outline) along the unit vector `dir` to the next
/// crossing of the outline `poly`, if any.
fn ray_distance(poly: &[Vec2], p: Vec2, dir: Vec2) -> Option<f64> {
    let mut best: Option<f64> = None;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        let e = b - a;
        let den = dir.perp_dot(e);
        if den.abs() < 1e-12 {
            continue;
        }
        // p + t·dir = a + u·e
        let t = (a - p).perp_dot(e) / den;
        let u = (a - p).perp_dot(dir) / den;
        // Skip the piece of outline the ray starts on.
        if t > 1e-3 && (0.0..=1.0).contains(&u) && best.is_none_or(|d| t < d) {
            best = Some(t);
        }
    }
    best
}

/// A well-spread, deterministic colour per stitch: hues stepped by the golden angle
/// (neighbours in the list get very different hues), three shades in turn so that
/// stitches whose hues come close again (8 or 13 apart) still differ; all dark
/// enough for white digits and distinct from the pink fill.
pub fn stitch_color(i: usize) -> Rgb {
    let hue = (i as f64 * 137.507_764_050_037_85) % 360.0;
    let (s, l) = [(0.75, 0.38), (0.60, 0.27), (0.90, 0.32)][i % 3];
    hsl_to_rgb(hue, s, l)
}

fn hsl_to_rgb(h: f64, s: f64, l: f64) -> Rgb {
    let c = (1.0 - (2.0 * l - 1.0).abs()) * s;
    let hp = h / 60.0;
    let x = c * (1.0 - (hp % 2.0 - 1.0).abs());
    let (r, g, b) = match hp as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = l - c / 2.0;
    let to8 = |v: f64| ((v + m) * 255.0).round().clamp(0.0, 255.0) as u8;
    [to8(r), to8(g), to8(b)]
}

/// Markers of both sides of every stitch, placed one after the other so that no
/// marker overlaps a panel name (`names`) or a marker placed before it.
///
/// Each marker is tried at full size, then at the smaller [`MARKER_SCALES`]; at
/// each size at the arc-length midpoint of its edge, then ever further towards the
/// edge's ends ([`marker_fractions`]); at each point just inside the panel, then
/// one or two disc rows deeper. A candidate must lie inside the panel with its disc
/// clear of the outline (in a panel narrower than the disc, such as a waistband or
/// a cuff, centred across it instead, where it is at least a radius across). When no candidate is free, the full-size
/// marker goes outside the panel, to the free spot nearest the edge's midpoint on
/// rings around it (starting straight out from the edge), and a leader line joins
/// it to the edge. The order is fixed, so the result is deterministic.
fn markers(p: &Pattern, panels: &[PlacedPanel], names: &[BBox]) -> Result<Vec<Marker>> {
    let by_name: HashMap<&str, usize> = panels.iter().enumerate().map(|(k, q)| (q.name.as_str(), k)).collect();
    let mut polygons: Vec<Option<Vec<Vec2>>> = vec![None; panels.len()];
    let mut taken: Vec<BBox> = names.to_vec();
    let mut out = Vec::with_capacity(2 * (p.stitches.len() + p.inner_stitches.len()));
    // The stitches, then the inner stitches numbered on after them.
    let outline = p.stitches.iter().map(|st| st.sides.each_ref().map(|s| (s.panel.as_str(), EdgePlace::Outline, s.edge)));
    let inner = p.inner_stitches.iter().map(|st| st.sides.each_ref().map(|s| (s.panel.as_str(), s.place, s.edge)));
    for (i, sides) in outline.chain(inner).enumerate() {
        for (panel, place, edge) in sides {
            let &k = by_name.get(panel).ok_or_else(|| Error::Input(format!("stitch {i} refers to a missing panel '{panel}'")))?;
            let q = &panels[k];
            let seg = q
                .edge_segment(place, edge)
                .ok_or_else(|| Error::Input(format!("stitch {i} refers to a missing edge {edge} of panel '{panel}'")))?;
            let poly = polygons[k].get_or_insert_with(|| polygon(&q.segments, 16));
            let (centre, radius, anchor, leader) = place_marker(seg, q.ccw, poly, &taken);
            let marker = Marker { stitch: i, panel: k, place, edge, color: stitch_color(i), centre, radius, anchor, leader };
            taken.push(marker.bbox());
            out.push(marker);
        }
    }
    Ok(out)
}

/// Arc-length fractions of an edge `length` cm long at which a marker of radius
/// `r` is tried: the midpoint, then alternately either side of it, about half a
/// radius apart (at least 1/32 and at most 1/8 of the edge), short of the ends.
fn marker_fractions(length: f64, r: f64) -> Vec<f64> {
    let step = (0.5 * r / length).clamp(1.0 / 32.0, 1.0 / 8.0);
    let mut out = vec![0.5];
    let mut k = 1.0;
    while k * step < 0.5 - 1e-9 {
        out.extend([0.5 - k * step, 0.5 + k * step]);
        k += 1.0;
    }
    out
}

/// Where the marker of edge `seg` of the panel outlined by `poly` goes, clear of
/// the boxes `taken`: disc centre, radius, the edge point it stands for, and
/// whether it sits outside the panel with a leader line.
fn place_marker(seg: &Segment, ccw: bool, poly: &[Vec2], taken: &[BBox]) -> (Vec2, f64, Vec2, bool) {
    let free = |c: Vec2, r: f64| {
        let b = BBox::around(c, r + MARKER_RING_WIDTH / 2.0);
        !taken.iter().any(|t| t.overlaps(&b))
    };
    // An edge point and the unit normal into the panel there.
    let at = |f: f64| {
        let (at, tangent) = seg.at_fraction(f);
        let left = Vec2::new(-tangent.y, tangent.x);
        (at, if ccw { left } else { -left })
    };
    let edge: Vec<Vec2> = (0..=16).map(|k| seg.point(k as f64 / 16.0)).collect();
    let length: f64 = edge.windows(2).map(|w| (w[1] - w[0]).length()).sum();
    for scale in MARKER_SCALES {
        let r = MARKER_RADIUS * scale;
        for f in marker_fractions(length, r) {
            let (at, inward) = at(f);
            let across = ray_distance(poly, at, inward).unwrap_or(f64::INFINITY);
            let first = (r + MARKER_GAP).min(across / 2.0);
            for row in 0..MARKER_DEPTHS {
                let depth = first + row as f64 * (2.0 * r + MARKER_GAP);
                if row > 0 && depth + first > across {
                    break;
                }
                let c = at + inward * depth;
                // Free, inside, and the disc clear of the outline (but for a tenth
                // of its radius) unless the panel is narrower than the disc; a
                // panel less than a radius across is too thin to hold it.
                // Deeper rows only where no other edge is much nearer than its own.
                let clear = distance_to_polyline(poly, true, c);
                let fits = across >= r && clear >= 0.9 * r.min(across / 2.0) && distance_to_polyline(&edge, false, c) <= clear + r;
                if free(c, r) && inside(poly, c) && fits {
                    return (c, r, at, false);
                }
            }
        }
    }
    // Outside the panel: rings around the midpoint a radius apart, each tried from
    // straight out of the edge round to the other side. Beyond `reach` (every box
    // taken and the panel itself) the first spot of a ring is free and outside.
    let r = MARKER_RADIUS;
    let (mid, inward) = at(0.5);
    let farthest = |acc: f64, p: Vec2| acc.max((p - mid).length());
    let reach = taken
        .iter()
        .flat_map(|b| [b.min, b.max, Vec2::new(b.min.x, b.max.y), Vec2::new(b.max.x, b.min.y)])
        .chain(poly.iter().copied())
        .fold(0.0, farthest);
    let rings = ((reach / r).ceil() + 4.0).min(MAX_LEADER_RINGS);
    let mut ring = 0.0;
    while ring < rings {
        let distance = r + MARKER_GAP + ring * r;
        for turn in LEADER_TURNS {
            let c = mid + rotate2d(-inward, turn.to_radians()) * distance;
            if free(c, r) && !inside(poly, c) {
                return (c, r, mid, true);
            }
        }
        ring += 1.0;
    }
    (mid - inward * (reach + 3.0 * r), r, mid, true)
}

/// Whether `p` lies inside the closed polygon (even-odd rule).
pub(super) fn inside(poly: &[Vec2], p: Vec2) -> bool {
    let mut c = false;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            c = !c;
        }
    }
    c
}

/// Distance from `p` to a polyline (`closed`: back to its first point).
fn distance_to_polyline(pts: &[Vec2], closed: bool, p: Vec2) -> f64 {
    let pieces = if closed { pts.len() } else { pts.len().saturating_sub(1) };
    let mut best = f64::INFINITY;
    for k in 0..pieces {
        let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
        let e = b - a;
        let t = if e.length_squared() > 0.0 { ((p - a).dot(e) / e.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
        best = best.min((a + e * t - p).length());
    }
    best
}

/// Font size of a panel's name: the reference's [`FONT_SIZE`], smaller when the
/// name (about 0.6 em per character) would not fit in 90% of the panel's width or
/// half its height, but never below [`MIN_NAME_SIZE`].
fn name_size(name: &str, bbox: &BBox) -> f64 {
    let size = bbox.max - bbox.min;
    let chars = name.chars().count().max(1) as f64;
    let fit = (0.9 * size.x / (0.6 * chars)).min(0.5 * size.y);
    // Whole millimetres keep the written numbers short.
    (fit.min(FONT_SIZE) * 10.0).floor().max(MIN_NAME_SIZE * 10.0) / 10.0
}

/// Smallest font size of panel names, cm.
pub const MIN_NAME_SIZE: f64 = 1.0;

/// Panel names and (optionally) vertex and edge indices, placed as the reference does.
fn texts(panels: &[PlacedPanel], opts: &DrawOptions) -> Vec<Text> {
    let mut out = Vec::new();
    if opts.with_text {
        for q in panels {
            out.push(Text {
                pos: q.bbox.centre(),
                text: q.name.clone(),
                size: name_size(&q.name, &q.bbox),
                fill: NAME_FILL,
                anchor: Anchor::MiddleMiddle,
                kind: TextKind::Name,
            });
        }
    }
    if opts.with_text {
        // "fold" beside the middle of each fold line.
        for m in panels.iter().flat_map(|q| &q.marks).filter(|m| m.kind == MarkKind::Fold && !m.segments.is_empty()) {
            let (mid, tangent) = m.segments[m.segments.len() / 2].midpoint();
            out.push(Text {
                pos: mid + Vec2::new(-tangent.y, tangent.x) * MARK_FONT_SIZE * 0.6,
                text: "fold".into(),
                size: MARK_FONT_SIZE,
                fill: PANEL_STROKE,
                anchor: Anchor::MiddleMiddle,
                kind: TextKind::MarkLabel,
            });
        }
    }
    if opts.view_ids {
        for q in panels {
            for s in &q.segments {
                out.push(Text {
                    pos: s.start,
                    text: s.from.to_string(),
                    size: FONT_SIZE,
                    fill: VERTEX_ID_FILL,
                    anchor: Anchor::StartBaseline,
                    kind: TextKind::VertexId,
                });
            }
            for (k, s) in q.segments.iter().enumerate() {
                let (mid, _) = s.midpoint();
                out.push(Text {
                    pos: mid - Vec2::new(0.0, EDGE_ID_LIFT),
                    text: k.to_string(),
                    size: FONT_SIZE,
                    fill: EDGE_ID_FILL,
                    anchor: Anchor::MiddleBaseline,
                    kind: TextKind::EdgeId,
                });
            }
        }
    }
    out
}
