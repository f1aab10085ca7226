//! The sheet as an SVG document.
//!
//! Layers, bottom to top: panels (one `<g id="NAME">` each, the outline as one
//! `<path>` with any cut-out holes as more subpaths, then one `<path class=KIND>` per
//! dart and inner line), panel names, fold-line labels, stitch markers (the traced edges and leader lines, then
//! the discs; kept above the names, which they never overlap), indices.
//! Every number is written with at most 3 decimals (arc radii: 6) and without `-0`,
//! so the bytes only change when the drawing does.

use std::fmt::Write;

use super::layout::{
    Anchor, LEADER_WIDTH, MARK_STROKE_WIDTH, MARKER_RING_WIDTH, MARKER_TRACE_WIDTH, MarkKind, PANEL_FILL, PANEL_STROKE, PANEL_STROKE_WIDTH,
    PlacedPanel, Rgb, Segment, Shape, Sheet, Text, TextKind,
};
use crate::math::Vec2;
use crate::pattern::EdgePlace;

/// A number with at most 3 decimals, trailing zeros dropped, never `-0`.
pub fn num(x: f64) -> String {
    fixed(x, 3)
}

/// A number with at most `places` decimals (≤ 9), trailing zeros dropped, never `-0`.
fn fixed(x: f64, places: u32) -> String {
    let scale = 10f64.powi(places as i32);
    let m = (x * scale).round();
    if m == 0.0 || !m.is_finite() {
        return "0".into();
    }
    let (neg, m, scale) = (m < 0.0, m.abs() as u64, 10u64.pow(places));
    let mut s = String::new();
    if neg {
        s.push('-');
    }
    s.push_str(&(m / scale).to_string());
    if m % scale != 0 {
        let frac = format!("{:0width$}", m % scale, width = places as usize);
        s.push('.');
        s.push_str(frac.trim_end_matches('0'));
    }
    s
}

/// A point rounded as [`num`] writes it.
fn rounded(p: Vec2) -> Vec2 {
    let r = |v: f64| (v * 1000.0).round() / 1000.0;
    Vec2::new(r(p.x), r(p.y))
}

/// Text escaped for XML content and attribute values.
pub fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            _ => s.push(c),
        }
    }
    s
}

fn rgb(c: Rgb) -> String {
    format!("rgb({},{},{})", c[0], c[1], c[2])
}

fn pt(p: Vec2) -> String {
    format!("{},{}", num(p.x), num(p.y))
}

/// Path command drawing `s` from its start (which the caller has moved to).
fn command(s: &Segment) -> String {
    match s.shape {
        Shape::Line => format!("L {}", pt(s.end)),
        Shape::Quad(c) => format!("Q {} {}", pt(c), pt(s.end)),
        Shape::Cubic(c1, c2) => format!("C {} {} {}", pt(c1), pt(c2), pt(s.end)),
        Shape::Arc(a) => {
            // Near half circles the arc's bulge is very sensitive to the radius and the
            // chord (h² = r² − L²/4): fit the radius to the end points as written, keeping
            // the exact centre offset h, and write it with 6 decimals.
            let h2 = (a.radius * a.radius - (a.end - a.start).length_squared() / 4.0).max(0.0);
            let half = (rounded(s.end) - rounded(s.start)).length() / 2.0;
            let r = fixed((half * half + h2).sqrt(), 6);
            format!("A {r},{r} 0 {} {} {}", a.large_arc as u8, a.sweep as u8, pt(s.end))
        }
    }
}

/// The outline as path data, with the holes cut out of the panel as more subpaths
/// (drawn with the even-odd rule).
pub fn outline(q: &PlacedPanel) -> String {
    let cuts = q.marks.iter().filter(|m| m.kind == MarkKind::Cut);
    std::iter::once(path_data(&q.segments)).chain(cuts.map(|m| path_data(&m.segments))).collect::<Vec<_>>().join(" ")
}

/// Segments as path data: a new subpath wherever an edge does not start at the
/// previous edge's end vertex, closed with `Z` when it returns to its first vertex.
fn path_data(segments: &[Segment]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut first = 0;
    for (k, s) in segments.iter().enumerate() {
        if k == 0 || segments[k - 1].to != s.from {
            parts.push(format!("M {}", pt(s.start)));
            first = s.from;
        }
        parts.push(command(s));
        let ends_subpath = k + 1 == segments.len() || segments[k + 1].from != s.to;
        if ends_subpath && s.to == first {
            parts.push("Z".into());
        }
    }
    parts.join(" ")
}

fn text(out: &mut String, t: &Text) {
    let anchor = match t.anchor {
        Anchor::StartBaseline => "",
        Anchor::MiddleBaseline => " text-anchor=\"middle\"",
        Anchor::MiddleMiddle => " text-anchor=\"middle\" dominant-baseline=\"middle\"",
        Anchor::MiddleCentral => " text-anchor=\"middle\" dominant-baseline=\"central\"",
    };
    let _ = writeln!(
        out,
        "<text x=\"{}\" y=\"{}\" font-size=\"{}\" fill=\"{}\"{anchor}>{}</text>",
        num(t.pos.x),
        num(t.pos.y),
        num(t.size),
        rgb(t.fill),
        escape(&t.text)
    );
}

/// Write the document.
pub fn write(sheet: &Sheet, title: &str) -> String {
    let mut out = String::new();
    let [x, y, w, h] = sheet.view_box;
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n");
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{}cm\" height=\"{}cm\" viewBox=\"{} {} {} {}\">",
        num(w),
        num(h),
        num(x),
        num(y),
        num(w),
        num(h)
    );
    if !title.is_empty() {
        let _ = writeln!(out, "<title>{}</title>", escape(title));
    }

    out.push_str("<g class=\"panels\">\n");
    for q in &sheet.panels {
        let even_odd = if q.marks.iter().any(|m| m.kind == MarkKind::Cut) { " fill-rule=\"evenodd\"" } else { "" };
        let _ = write!(
            out,
            "<g id=\"{}\"><path d=\"{}\" fill=\"{}\"{even_odd} stroke=\"{}\" stroke-width=\"{}\"/>",
            escape(&q.name),
            outline(q),
            rgb(PANEL_FILL),
            rgb(PANEL_STROKE),
            num(PANEL_STROKE_WIDTH)
        );
        for m in q.marks.iter().filter(|m| m.kind != MarkKind::Cut) {
            let (class, dash) = m.kind.style();
            let dash: Vec<String> = dash.iter().map(|d| num(*d)).collect();
            let _ = write!(
                out,
                "\n<path class=\"{class}\" data-name=\"{}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"{}\"/>",
                escape(&m.name),
                path_data(&m.segments),
                rgb(PANEL_STROKE),
                num(MARK_STROKE_WIDTH),
                dash.join(" ")
            );
        }
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n");

    texts(&mut out, sheet, TextKind::Name, "names");
    texts(&mut out, sheet, TextKind::MarkLabel, "mark-labels");
    markers(&mut out, sheet);
    texts(&mut out, sheet, TextKind::VertexId, "vertex-ids");
    texts(&mut out, sheet, TextKind::EdgeId, "edge-ids");
    out.push_str("</svg>\n");
    out
}

/// Texts of one kind in their own group (nothing when there are none).
fn texts(out: &mut String, sheet: &Sheet, kind: TextKind, class: &str) {
    let texts: Vec<&Text> = sheet.texts.iter().filter(|t| t.kind == kind).collect();
    if texts.is_empty() {
        return;
    }
    let _ = writeln!(out, "<g class=\"{class}\" font-family=\"sans-serif\">");
    for t in texts {
        text(out, t);
    }
    out.push_str("</g>\n");
}

/// The stitch markers: first every stitched edge traced in its stitch's colour
/// (with the leader lines of markers outside their panels), then one group per
/// stitch side with its disc and number, so that no line runs over a disc.
fn markers(out: &mut String, sheet: &Sheet) {
    if sheet.markers.is_empty() {
        return;
    }
    out.push_str("<g class=\"stitches\" font-family=\"sans-serif\">\n<g class=\"traces\" fill=\"none\">\n");
    for m in &sheet.markers {
        let s = m.segment(sheet);
        let color = rgb(m.color);
        let _ = writeln!(
            out,
            "<path d=\"M {} {}\" stroke=\"{color}\" stroke-width=\"{}\" stroke-linecap=\"round\"/>",
            pt(s.start),
            command(s),
            num(MARKER_TRACE_WIDTH)
        );
        if m.leader {
            let _ = writeln!(
                out,
                "<path class=\"leader\" d=\"M {} L {}\" stroke=\"{color}\" stroke-width=\"{}\"/>",
                pt(m.anchor),
                pt(m.centre),
                num(LEADER_WIDTH)
            );
        }
    }
    out.push_str("</g>\n");
    for m in &sheet.markers {
        let place = match m.place {
            EdgePlace::Outline => String::new(),
            EdgePlace::Hole(k) => format!(" data-hole=\"{k}\""),
            EdgePlace::Line(k) => format!(" data-line=\"{k}\""),
        };
        let _ = writeln!(
            out,
            "<g class=\"stitch\" data-stitch=\"{}\" data-panel=\"{}\"{place} data-edge=\"{}\">",
            m.stitch,
            escape(&sheet.panels[m.panel].name),
            m.edge
        );
        let _ = writeln!(
            out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"rgb(255,255,255)\" stroke-width=\"{}\"/>",
            num(m.centre.x),
            num(m.centre.y),
            num(m.radius),
            rgb(m.color),
            num(MARKER_RING_WIDTH)
        );
        text(out, &m.label());
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n");
}
