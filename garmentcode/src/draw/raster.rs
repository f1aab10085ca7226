//! The sheet rasterised with tiny-skia (anti-aliased, pure Rust) and encoded as PNG.
//!
//! Paint order and styles are those of the SVG writer; text is drawn with the
//! built-in stroke font. tiny-skia computes in `f32` on the same inputs every time,
//! so the bytes are deterministic.

use tiny_skia::{Color, FillRule, LineCap, LineJoin, Paint, Path, PathBuilder, Pixmap, Stroke, StrokeDash, Transform};

use super::font;
use super::layout::{
    Anchor, LEADER_WIDTH, MARK_STROKE_WIDTH, MARKER_RING_WIDTH, MARKER_TRACE_WIDTH, MarkKind, PANEL_FILL, PANEL_STROKE, PANEL_STROKE_WIDTH,
    PlacedPanel, Rgb, Segment, Shape, Sheet, Text, TextKind,
};
use super::options::DrawOptions;
use crate::error::{Error, Result};
use crate::math::Vec2;

/// Most pixels of a PNG drawing: 25 million (5,000 × 5,000; 100 MB while drawn). A
/// garment at the default 3 px per cm is under a megapixel; a larger drawing (a
/// high `--dpi`, a pattern in odd units) is drawn at the highest resolution that
/// fits, which `fitted_px_per_cm` gives and the PNG records in a text chunk.
pub const MAX_PNG_PIXELS: u64 = 25_000_000;

/// The resolution a view box is drawn at: `asked`, or lower so that the image
/// has at most [`MAX_PNG_PIXELS`] pixels.
pub fn fitted_px_per_cm(view_box: [f64; 4], asked: f64) -> f64 {
    let mut s = asked;
    for _ in 0..64 {
        let (w, h) = pixel_size(view_box, s);
        let pixels = u64::from(w) * u64::from(h);
        if pixels <= MAX_PNG_PIXELS {
            break;
        }
        s *= (MAX_PNG_PIXELS as f64 / pixels as f64).sqrt() * 0.999;
    }
    s
}

/// Image size for a view box: `ceil(size × px_per_cm)`, ignoring float noise of
/// 1e-9 px, and at least one pixel.
pub fn pixel_size(view_box: [f64; 4], px_per_cm: f64) -> (u32, u32) {
    let px = |cm: f64| ((cm * px_per_cm - 1e-9).ceil().max(1.0)).min(f64::from(u32::MAX)) as u32;
    (px(view_box[2]), px(view_box[3]))
}

fn paint(c: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(Color::from_rgba8(c[0], c[1], c[2], 255));
    p.anti_alias = true;
    p
}

fn round_stroke(width: f64) -> Stroke {
    Stroke { width: width as f32, line_cap: LineCap::Round, line_join: LineJoin::Round, ..Stroke::default() }
}

/// Append `s` (from its start, where the pen already is) to `pb`.
fn push_segment(pb: &mut PathBuilder, s: &Segment) {
    let f = |v: f64| v as f32;
    match s.shape {
        Shape::Line => pb.line_to(f(s.end.x), f(s.end.y)),
        Shape::Quad(c) => pb.quad_to(f(c.x), f(c.y), f(s.end.x), f(s.end.y)),
        Shape::Cubic(c1, c2) => pb.cubic_to(f(c1.x), f(c1.y), f(c2.x), f(c2.y), f(s.end.x), f(s.end.y)),
        Shape::Arc(a) => {
            // Cubic pieces of at most 90°, the standard 4/3·tan(φ/4) handles.
            let n = (a.delta.abs() / 90.0).ceil().max(1.0) as usize;
            let step = (a.delta / n as f64).to_radians();
            let k = 4.0 / 3.0 * (step / 4.0).tan();
            let at = |phi: f64| a.center + Vec2::new(phi.cos(), phi.sin()) * a.radius;
            let tangent = |phi: f64| Vec2::new(-phi.sin(), phi.cos()) * a.radius;
            for i in 0..n {
                let a0 = a.theta.to_radians() + step * i as f64;
                let a1 = a0 + step;
                let (p0, p3) = (at(a0), if i + 1 == n { s.end } else { at(a1) });
                let c1 = p0 + tangent(a0) * k;
                let c2 = p3 - tangent(a1) * k;
                pb.cubic_to(f(c1.x), f(c1.y), f(c2.x), f(c2.y), f(p3.x), f(p3.y));
            }
        }
    }
}

/// The outline and the holes cut out of it, with the same subpaths as the SVG path data.
fn outline(q: &PlacedPanel) -> Option<Path> {
    let mut pb = PathBuilder::new();
    push_segments(&mut pb, &q.segments);
    for m in q.marks.iter().filter(|m| m.kind == MarkKind::Cut) {
        push_segments(&mut pb, &m.segments);
    }
    pb.finish()
}

/// Append segments, a new subpath wherever one does not start at the previous one's
/// end vertex, closed where it returns to its first vertex.
fn push_segments(pb: &mut PathBuilder, segments: &[Segment]) {
    let mut first = 0;
    for (k, s) in segments.iter().enumerate() {
        if k == 0 || segments[k - 1].to != s.from {
            pb.move_to(s.start.x as f32, s.start.y as f32);
            first = s.from;
        }
        push_segment(pb, s);
        let ends_subpath = k + 1 == segments.len() || segments[k + 1].from != s.to;
        if ends_subpath && s.to == first {
            pb.close();
        }
    }
}

fn draw_text(pm: &mut Pixmap, t: &Text, tf: Transform) {
    let set = font::set(&t.text, t.size);
    let x = match t.anchor {
        Anchor::StartBaseline => t.pos.x,
        _ => t.pos.x - set.width / 2.0,
    };
    let y = match t.anchor {
        Anchor::StartBaseline | Anchor::MiddleBaseline => t.pos.y,
        Anchor::MiddleMiddle => t.pos.y + font::X_HEIGHT * t.size / 2.0,
        Anchor::MiddleCentral => t.pos.y + font::CAP_HEIGHT * t.size / 2.0,
    };
    let mut pb = PathBuilder::new();
    for stroke in &set.strokes {
        for (k, p) in stroke.iter().enumerate() {
            let (px, py) = ((x + p.x) as f32, (y + p.y) as f32);
            if k == 0 { pb.move_to(px, py) } else { pb.line_to(px, py) }
        }
    }
    // Marker digits are small: a bolder stroke keeps them readable at 3 px/cm.
    let weight = if t.kind == TextKind::Marker { 1.4 } else { 1.0 };
    if let Some(path) = pb.finish() {
        pm.stroke_path(&path, &paint(t.fill), &round_stroke(font::STROKE * weight * t.size), tf, None);
    }
}

fn draw_texts(pm: &mut Pixmap, sheet: &Sheet, kind: TextKind, tf: Transform) {
    for t in sheet.texts.iter().filter(|t| t.kind == kind) {
        draw_text(pm, t, tf);
    }
}

/// Rasterise and encode.
pub fn render(sheet: &Sheet, opts: &DrawOptions) -> Result<(Vec<u8>, f64)> {
    let asked = opts.px_per_cm;
    if !(asked.is_finite() && asked > 0.0) {
        return Err(Error::Input(format!("PNG resolution must be a positive number of px per cm, not {}", crate::message::short(asked))));
    }
    let s = fitted_px_per_cm(sheet.view_box, asked);
    let (w, h) = pixel_size(sheet.view_box, s);
    let mut pm = Pixmap::new(w, h).ok_or_else(|| Error::Input(format!("cannot allocate a {w} × {h} px image")))?;
    if let Some(c) = opts.background {
        pm.fill(Color::from_rgba8(c[0], c[1], c[2], 255));
    }
    let [vx, vy, _, _] = sheet.view_box;
    let tf = Transform::from_row(s as f32, 0.0, 0.0, s as f32, (-vx * s) as f32, (-vy * s) as f32);

    let outline_stroke = Stroke { width: PANEL_STROKE_WIDTH as f32, ..Stroke::default() };
    for q in &sheet.panels {
        if let Some(path) = outline(q) {
            let rule = if q.marks.iter().any(|m| m.kind == MarkKind::Cut) { FillRule::EvenOdd } else { FillRule::Winding };
            pm.fill_path(&path, &paint(PANEL_FILL), rule, tf, None);
            pm.stroke_path(&path, &paint(PANEL_STROKE), &outline_stroke, tf, None);
        }
        for m in q.marks.iter().filter(|m| m.kind != MarkKind::Cut) {
            let mut pb = PathBuilder::new();
            push_segments(&mut pb, &m.segments);
            let dash = StrokeDash::new(m.kind.style().1.iter().map(|d| *d as f32).collect(), 0.0);
            let stroke = Stroke { width: MARK_STROKE_WIDTH as f32, dash, ..Stroke::default() };
            if let Some(path) = pb.finish() {
                pm.stroke_path(&path, &paint(PANEL_STROKE), &stroke, tf, None);
            }
        }
    }

    // Names under the stitch markers (which are small and must stay visible), indices on top.
    draw_texts(&mut pm, sheet, TextKind::Name, tf);
    draw_texts(&mut pm, sheet, TextKind::MarkLabel, tf);
    // Every trace and leader line first, so that none runs over a disc.
    for m in &sheet.markers {
        let seg = m.segment(sheet);
        let mut pb = PathBuilder::new();
        pb.move_to(seg.start.x as f32, seg.start.y as f32);
        push_segment(&mut pb, seg);
        if let Some(path) = pb.finish() {
            pm.stroke_path(&path, &paint(m.color), &round_stroke(MARKER_TRACE_WIDTH), tf, None);
        }
        if m.leader {
            let mut pb = PathBuilder::new();
            pb.move_to(m.anchor.x as f32, m.anchor.y as f32);
            pb.line_to(m.centre.x as f32, m.centre.y as f32);
            if let Some(path) = pb.finish() {
                pm.stroke_path(&path, &paint(m.color), &Stroke { width: LEADER_WIDTH as f32, ..Stroke::default() }, tf, None);
            }
        }
    }
    for m in &sheet.markers {
        if let Some(disc) = PathBuilder::from_circle(m.centre.x as f32, m.centre.y as f32, m.radius as f32) {
            pm.fill_path(&disc, &paint(m.color), FillRule::Winding, tf, None);
            let ring = Stroke { width: MARKER_RING_WIDTH as f32, ..Stroke::default() };
            pm.stroke_path(&disc, &paint([255, 255, 255]), &ring, tf, None);
        }
        draw_text(&mut pm, &m.label(), tf);
    }

    draw_texts(&mut pm, sheet, TextKind::VertexId, tf);
    draw_texts(&mut pm, sheet, TextKind::EdgeId, tf);

    let note = (s < asked)
        .then(|| format!("drawn at {s:.4} px per cm instead of the {asked:.4} asked: at most {MAX_PNG_PIXELS} pixels are drawn"));
    Ok((encode(pm, note.as_deref())?, s))
}

/// PNG bytes of the pixmap: RGBA, 8 bits, with png's fast (fdeflate) compression,
/// several times faster than the default level for a slightly larger file.
/// A `note` goes into a `Comment` text chunk.
fn encode(pm: Pixmap, note: Option<&str>) -> Result<Vec<u8>> {
    let (w, h) = (pm.width(), pm.height());
    let rgba = pm.take_demultiplied();
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, w, h);
    enc.set_color(png::ColorType::Rgba);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let fail = |e: png::EncodingError| Error::Input(format!("PNG encoding failed: {e}"));
    if let Some(note) = note {
        enc.add_text_chunk("Comment".into(), note.into()).map_err(fail)?;
    }
    let mut writer = enc.write_header().map_err(fail)?;
    writer.write_image_data(&rgba).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(out)
}
