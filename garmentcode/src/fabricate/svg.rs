//! SVG of the one-sheet drawing and of the cutting layout (sizes in cm).

use super::geom::Rect;
use super::sheet::{CuttingLayout, Prim, SIZE_PENS, Sheet, Style};
use super::types::{Piece, PrintOptions};
use crate::math::Vec2;
use std::fmt::Write;

/// A number with at most three decimals, without trailing zeros.
pub(crate) fn num(x: f64) -> String {
    let s = format!("{:.3}", x);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

fn points(pts: &[Vec2]) -> String {
    pts.iter().map(|p| format!("{},{}", num(p.x), num(p.y))).collect::<Vec<_>>().join(" ")
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// Stroke attributes of a style.
fn stroke(style: Style) -> String {
    match style {
        Style::Cut => r##"stroke="#000" stroke-width="0.06""##.into(),
        Style::Sew => r##"stroke="#555" stroke-width="0.03" stroke-dasharray="0.4 0.2""##.into(),
        Style::Notch => r##"stroke="#000" stroke-width="0.05""##.into(),
        Style::Grain => r##"stroke="#000" stroke-width="0.04""##.into(),
        Style::Fold => r##"stroke="#1a4fa0" stroke-width="0.05""##.into(),
        Style::Internal => r##"stroke="#555" stroke-width="0.03""##.into(),
        Style::Frame | Style::Text => r##"stroke="#000" stroke-width="0.04""##.into(),
        Style::Size(k) => {
            let (rgb, dash) = SIZE_PENS[k as usize % SIZE_PENS.len()];
            let [r, g, b] = rgb.map(|c| (c * 255.0).round() as u8);
            let dash = if dash.is_empty() {
                String::new()
            } else {
                format!(r#" stroke-dasharray="{}""#, dash.iter().map(|d| num(*d)).collect::<Vec<_>>().join(" "))
            };
            format!(r##"stroke="#{r:02x}{g:02x}{b:02x}" stroke-width="0.05"{dash}"##)
        }
    }
}

fn header(out: &mut String, size: Vec2, title: &str) {
    let _ = writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}cm" height="{h}cm" viewBox="0 0 {w} {h}">"#,
        w = num(size.x),
        h = num(size.y)
    );
    let _ = writeln!(out, "<title>{}</title>", escape(title));
    let _ = writeln!(out, r##"<rect width="{}" height="{}" fill="#fff"/>"##, num(size.x), num(size.y));
}

/// The one-sheet drawing as SVG.
pub fn sheet(s: &Sheet) -> String {
    let mut out = String::new();
    header(&mut out, s.size, &s.title);
    for p in &s.prims {
        match p {
            Prim::Path { pts, closed, style } => {
                let tag = if *closed { "polygon" } else { "polyline" };
                let _ = writeln!(out, r#"<{tag} points="{}" fill="none" {}/>"#, points(pts), stroke(*style));
            }
            Prim::Text { at, size, text, angle } => {
                let rot = if *angle != 0.0 {
                    format!(r#" transform="rotate({} {} {})""#, num(-angle), num(at.x), num(at.y))
                } else {
                    String::new()
                };
                let _ = writeln!(
                    out,
                    r#"<text x="{}" y="{}" font-family="Helvetica, Arial, sans-serif" font-size="{}"{rot}>{}</text>"#,
                    num(at.x),
                    num(at.y),
                    num(*size),
                    escape(text)
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}

/// The cutting layout as SVG: the fabric (selvages at the sides), every copy of
/// every piece, the length needed; pieces wider than the fabric in red.
pub fn cutting(l: &CuttingLayout, pieces: &[Piece], opts: &PrintOptions) -> String {
    let margin = 4.0;
    let right = l.cuts.iter().flat_map(|c| c.outlines.iter().flatten()).fold(l.width, |m, p| m.max(p.x));
    let size = Vec2::new(right + 2.0 * margin, l.length + 2.0 * margin + 3.0);
    let mut out = String::new();
    header(&mut out, size, &format!("Cutting layout: {} - size {}", opts.garment, opts.size));
    let _ = writeln!(out, r#"<g transform="translate({m} {m})">"#, m = num(margin));
    let _ = writeln!(
        out,
        r##"<rect width="{}" height="{}" fill="#eef3fa" stroke="#1a4fa0" stroke-width="0.1"/>"##,
        num(l.width),
        num(l.length)
    );
    let font = r#"font-family="Helvetica, Arial, sans-serif""#;
    let _ = writeln!(
        out,
        r#"<text x="0" y="-1" {font} font-size="1.5">fabric {} cm wide: selvages left and right, grain runs down</text>"#,
        num(l.width)
    );
    let _ = writeln!(
        out,
        r#"<text x="0" y="{}" {font} font-size="1.5">fabric needed: {} cm</text>"#,
        num(l.length + 2.5),
        num((l.length * 10.0).round() / 10.0)
    );
    for c in &l.cuts {
        let colour = if c.fits { "#000" } else { "#c00" };
        for o in &c.outlines {
            let _ = writeln!(out, r##"<polygon points="{}" fill="#fff" stroke="{colour}" stroke-width="0.1"/>"##, points(o));
        }
        let b = Rect::of(c.outlines.iter().flatten().copied());
        let centre = (b.min + b.max) / 2.0;
        let size = (b.size().x / (pieces[c.piece].name.len() as f64 * 0.6 + 1.0)).clamp(0.8, 2.5);
        let _ = writeln!(
            out,
            r#"<text x="{}" y="{}" {font} font-size="{}" text-anchor="middle" fill="{colour}">{}</text>"#,
            num(centre.x),
            num(centre.y),
            num(size),
            escape(&pieces[c.piece].name)
        );
    }
    out.push_str("</g>\n</svg>\n");
    out
}
