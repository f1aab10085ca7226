//! The sheet: panels placed as the reference places them (pattern-format.md §11.1),
//! plus the annotations drawn over them. Shared by the SVG writer and the rasteriser
//! so that both show the same picture.
//!
//! All coordinates here are sheet coordinates: centimetres, x right, y down.

use std::cmp::Ordering;
use std::collections::HashMap;

use super::options::{DrawOptions, FLAT_ROW_WIDTH, Layout};
use crate::arc::SvgArc;
use crate::bezier::Bezier;
use crate::error::{Error, Result};
use crate::math::{Vec2, Vec3, rel_to_abs, rotate2d, vector_angle_clamped};
use crate::pattern::{Curvature, PanelSpec, Pattern};

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
/// Font size of the number in a stitch marker, cm.
pub const MARKER_FONT_SIZE: f64 = 3.4;
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

/// One side of a stitch, marked on the sheet.
#[derive(Clone, Debug)]
pub struct Marker {
    /// Index of the stitch in `pattern.stitches` (the number shown).
    pub stitch: usize,
    /// Index of the placed panel in [`Sheet::panels`].
    pub panel: usize,
    /// Edge index within the panel.
    pub edge: usize,
    /// Colour of the stitch.
    pub color: Rgb,
    /// Centre of the marker disc.
    pub centre: Vec2,
}

impl Marker {
    /// The stitch number, white and centred on the disc.
    pub fn label(&self) -> Text {
        Text {
            pos: self.centre,
            text: self.stitch.to_string(),
            size: MARKER_FONT_SIZE,
            fill: [255, 255, 255],
            anchor: Anchor::MiddleCentral,
            kind: TextKind::Marker,
        }
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

    /// Parameter of the arc-length midpoint.
    fn mid_param(&self) -> f64 {
        match self.bezier() {
            // Lines and arcs are uniform in arc length.
            None => 0.5,
            Some(b) => b.inverse_length(b.length() / 2.0).unwrap_or(0.5),
        }
    }

    /// Arc-length midpoint and the unit tangent there (the chord direction where the
    /// curve has no tangent).
    pub fn midpoint(&self) -> (Vec2, Vec2) {
        let t = self.mid_param();
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
            for s in &mut q.segments {
                s.translate(shift);
            }
            q.bbox = BBox { min: q.bbox.min + shift, max: q.bbox.max + shift };
        }
    }
    let mut panels = front;
    panels.append(&mut back);
    if opts.layout == Layout::Flat {
        arrange_flat(p, &mut panels);
    }

    let all = panels.iter().skip(1).fold(panels[0].bbox, |acc, q| acc.union(&q.bbox));
    let m = opts.margin;
    let size = all.max - all.min;
    let view_box = [round3(all.min.x - m), round3(all.min.y - m), round3(size.x + 2.0 * m), round3(size.y + 2.0 * m)];

    let markers = if opts.stitch_markers { markers(p, &panels)? } else { Vec::new() };
    let texts = texts(&panels, opts);
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
        let shift = Vec2::new(x, y) - q.bbox.min;
        for s in &mut q.segments {
            s.translate(shift);
        }
        q.bbox = BBox { min: q.bbox.min + shift, max: q.bbox.max + shift };
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
    let local: Vec<Vec2> = flipped.iter().map(|v| *v - offset).collect();
    let translation = Vec2::new(panel.translation[0], -panel.translation[1]) + offset;

    // In-plane rotation: angle from (0, 1) to the projection of R·(0, 1, 0); a panel
    // whose y axis points straight along z has none.
    let w = panel.rotation().apply(Vec3::Y);
    let w2 = Vec2::new(w.x, w.y);
    let alpha = if w2.length() > 1e-12 { vector_angle_clamped(Vec2::Y, w2) } else { 0.0 };
    // Degrees and back, as the reference does (`path.rotated(degs=-angle)`).
    let theta = (-alpha.to_degrees()).to_radians();
    let origin = local[0];
    let place_point = |q: Vec2| rotate2d(q - origin, theta) + origin + translation;

    let mut segments = Vec::with_capacity(panel.edges.len());
    for (k, e) in panel.edges.iter().enumerate() {
        let [i, j] = e.endpoints;
        if let Some(v) = [i, j].into_iter().find(|&v| v >= local.len()) {
            return Err(bad(&format!("edge {k} refers to vertex {v}, but the panel has {} vertices", local.len())));
        }
        let (s, t) = (local[i], local[j]);
        // Relative control points with y negated: the flip mirrors the edge frame.
        let ctrl = |c: [f64; 2]| -> Result<Vec2> {
            if !finite(&c) {
                return Err(bad(&format!("edge {k} has a non-finite control point")));
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
                    return Err(bad(&format!("edge {k} has an invalid arc radius {radius}")));
                }
                if start == end {
                    return Err(bad(&format!("arc edge {k} starts where it ends")));
                }
                // y-down drawing: the sweep flag is the opposite of `right`.
                Shape::Arc(SvgArc::new(start, end, *radius, *large_arc, !*right))
            }
        };
        segments.push(Segment { start, end, shape, from: i, to: j });
    }

    let bbox = segments.iter().skip(1).fold(segments[0].bbox(), |acc, s| acc.union(&s.bbox()));
    let ccw = signed_area(&segments) >= 0.0;
    Ok(PlacedPanel { name: panel.name.clone(), segments, bbox, ccw })
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

/// Markers of both sides of every stitch: a disc just inside the panel, next to the
/// arc-length midpoint of the stitched edge; in a panel narrower than the disc
/// (waistbands, cuffs) it is centred across the panel instead.
fn markers(p: &Pattern, panels: &[PlacedPanel]) -> Result<Vec<Marker>> {
    let by_name: HashMap<&str, usize> = panels.iter().enumerate().map(|(k, q)| (q.name.as_str(), k)).collect();
    let mut polygons: Vec<Option<Vec<Vec2>>> = vec![None; panels.len()];
    let mut out = Vec::with_capacity(2 * p.stitches.len());
    for (i, st) in p.stitches.iter().enumerate() {
        for side in &st.sides {
            let &k = by_name
                .get(side.panel.as_str())
                .ok_or_else(|| Error::Input(format!("stitch {i} refers to a missing panel '{}'", side.panel)))?;
            let q = &panels[k];
            let seg = q
                .segments
                .get(side.edge)
                .ok_or_else(|| Error::Input(format!("stitch {i} refers to a missing edge {} of panel '{}'", side.edge, side.panel)))?;
            let (mid, tangent) = seg.midpoint();
            let left = Vec2::new(-tangent.y, tangent.x);
            let inward = if q.ccw { left } else { -left };
            let poly = polygons[k].get_or_insert_with(|| polygon(&q.segments, 16));
            let across = ray_distance(poly, mid, inward).unwrap_or(f64::INFINITY);
            let offset = (MARKER_RADIUS + MARKER_GAP).min(across / 2.0);
            out.push(Marker { stitch: i, panel: k, edge: side.edge, color: stitch_color(i), centre: mid + inward * offset });
        }
    }
    Ok(out)
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
