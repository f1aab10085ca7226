//! PDF output: the one-sheet drawing on one page, and the same drawing tiled onto
//! home-printer pages behind a cover page.

use super::geom::Rect;
use super::sheet::{self, OVERLAP, PAGE_MARGIN, Prim, SIZE_PENS, Sheet, Style, Tile};
use super::types::{Piece, PrintOptions};
use crate::math::Vec2;
use pdf_writer::{Content, Name, Pdf, Rect as PdfRect, Ref, Str};

/// Points per centimetre.
const PT: f64 = 72.0 / 2.54;

/// A page: its size (cm) and its content.
struct PageOut {
    size: Vec2,
    content: Vec<u8>,
}

/// Assemble pages into a PDF with Helvetica as font `F1`.
fn document(pages: Vec<PageOut>, title: &str) -> Vec<u8> {
    let mut pdf = Pdf::new();
    let (catalog, tree, font, info) = (Ref::new(1), Ref::new(2), Ref::new(3), Ref::new(4));
    pdf.catalog(catalog).pages(tree);
    let ids: Vec<(Ref, Ref)> = (0..pages.len()).map(|i| (Ref::new(5 + 2 * i as i32), Ref::new(6 + 2 * i as i32))).collect();
    pdf.pages(tree).kids(ids.iter().map(|(p, _)| *p)).count(pages.len() as i32);
    pdf.type1_font(font).base_font(Name(b"Helvetica")).encoding_predefined(Name(b"WinAnsiEncoding"));
    pdf.document_info(info).title(pdf_writer::TextStr(title)).producer(pdf_writer::TextStr("garmentcode"));
    for (page, (pid, cid)) in pages.iter().zip(&ids) {
        let mut p = pdf.page(*pid);
        p.parent(tree).media_box(PdfRect::new(0.0, 0.0, (page.size.x * PT) as f32, (page.size.y * PT) as f32)).contents(*cid);
        p.resources().fonts().pair(Name(b"F1"), font);
        drop(p);
        pdf.stream(*cid, &page.content);
    }
    pdf.finish()
}

/// Text as WinAnsi bytes (ASCII kept, anything else shown as `?`).
fn ascii(s: &str) -> Vec<u8> {
    s.chars().map(|c| if c.is_ascii() && !c.is_ascii_control() { c as u8 } else { b'?' }).collect()
}

/// Pen of a style: width (pt), grey or colour, dash.
fn pen(c: &mut Content, style: Style) {
    let (w, rgb, dash): (f32, [f32; 3], &[f32]) = match style {
        Style::Cut => (1.2, [0.0; 3], &[]),
        Style::Sew => (0.5, [0.33; 3], &[4.0, 2.0]),
        Style::Notch => (1.0, [0.0; 3], &[]),
        Style::Grain => (0.8, [0.0; 3], &[]),
        Style::Fold => (1.0, [0.1, 0.31, 0.63], &[]),
        Style::Internal => (0.5, [0.33; 3], &[]),
        Style::Frame | Style::Text => (0.8, [0.0; 3], &[]),
        Style::Size(k) => {
            let (rgb, dash) = SIZE_PENS[k as usize % SIZE_PENS.len()];
            c.set_line_width(1.0);
            c.set_stroke_rgb(rgb[0], rgb[1], rgb[2]);
            c.set_dash_pattern(dash.iter().map(|d| (d * PT) as f32), 0.0);
            return;
        }
    };
    c.set_line_width(w);
    c.set_stroke_rgb(rgb[0], rgb[1], rgb[2]);
    c.set_dash_pattern(dash.iter().copied(), 0.0);
}

/// Draw sheet things; `map` takes sheet cm (y down) to page points (y up).
fn draw(c: &mut Content, prims: &[Prim], map: &dyn Fn(Vec2) -> (f32, f32), scale: f64) {
    for p in prims {
        match p {
            Prim::Path { pts, closed, style } => {
                if pts.len() < 2 {
                    continue;
                }
                pen(c, *style);
                let (x, y) = map(pts[0]);
                c.move_to(x, y);
                for q in &pts[1..] {
                    let (x, y) = map(*q);
                    c.line_to(x, y);
                }
                if *closed {
                    c.close_path();
                }
                c.stroke();
            }
            Prim::Text { at, size, text, angle } => text_at(c, map(*at), (size * scale) as f32, *angle, text),
        }
    }
}

/// One line of text at a page point, `size` points high, rotated `angle` degrees.
fn text_at(c: &mut Content, (x, y): (f32, f32), size: f32, angle: f64, text: &str) {
    let (s, co) = (angle.to_radians().sin() as f32, angle.to_radians().cos() as f32);
    c.set_fill_gray(0.0);
    c.begin_text();
    c.set_font(Name(b"F1"), size);
    c.set_text_matrix([co, s, -s, co, x, y]);
    c.show(Str(&ascii(text)));
    c.end_text();
}

/// Longest side of a PDF page (cm). Readers refuse or misdraw pages over 200 in
/// (14 400 pt, 508 cm), the limit of PDF's default user space.
pub const MAX_PAGE: f64 = 500.0;

/// The one-sheet drawing on a single page of its own size; a sheet longer (or
/// wider) than [`MAX_PAGE`] on the fewest pages of equal size within it, joined as
/// tiled pages are (see [`page_for_parts`]).
pub fn one_sheet(s: &Sheet) -> Vec<u8> {
    if s.size.x > MAX_PAGE || s.size.y > MAX_PAGE {
        let page = page_for_parts(s.size);
        let (_, _, tiles) = sheet::tiles(s, page);
        let pages = tiles.iter().map(|t| PageOut { size: page, content: tile_page(s, t, page, &tiles) }).collect();
        return document(pages, &s.title);
    }
    let mut c = Content::new();
    let h = s.size.y;
    draw(&mut c, &s.prims, &|p| ((p.x * PT) as f32, ((h - p.y) * PT) as f32), PT);
    document(vec![PageOut { size: s.size, content: c.finish().to_vec() }], &s.title)
}

/// Page size (cm) that splits a sheet of `size` into the fewest parts of at most
/// [`MAX_PAGE`] per side, laid out as [`sheet::tiles`] lays out home-printer pages:
/// a [`PAGE_MARGIN`] round each part and [`OVERLAP`] shared with its neighbours.
/// Along a side that fits, there is one part.
pub fn page_for_parts(size: Vec2) -> Vec2 {
    let margins = 2.0 * PAGE_MARGIN + OVERLAP;
    let side = |len: f64| {
        let parts = ((len - OVERLAP) / (MAX_PAGE - margins)).ceil().max(1.0);
        // A hair over the exact size, so that rounding never asks for one more part.
        ((len - OVERLAP) / parts + margins + 1e-6).min(MAX_PAGE)
    };
    Vec2::new(side(size.x), side(size.y))
}

/// A registration mark: a circle with a cross.
fn mark(c: &mut Content, (x, y): (f32, f32)) {
    let r = (0.3 * PT) as f32;
    pen(c, Style::Frame);
    c.set_line_width(0.5);
    for k in 0..=24 {
        let a = k as f32 / 24.0 * std::f32::consts::TAU;
        let (px, py) = (x + r * a.cos(), y + r * a.sin());
        if k == 0 {
            c.move_to(px, py)
        } else {
            c.line_to(px, py)
        };
    }
    c.stroke();
    c.move_to(x - 1.6 * r, y).line_to(x + 1.6 * r, y).move_to(x, y - 1.6 * r).line_to(x, y + 1.6 * r).stroke();
}

/// The sheet tiled onto pages behind a cover page.
pub fn tiled(s: &Sheet, pieces: &[Piece], opts: &PrintOptions) -> Vec<u8> {
    let page = opts.paper.tile_page();
    let (rows, cols, tiles) = sheet::tiles(s, page);
    let mut pages = vec![cover(s, pieces, opts, page, rows, cols, &tiles)];
    for t in &tiles {
        pages.push(PageOut { size: page, content: tile_page(s, t, page, &tiles) });
    }
    document(pages, &s.title)
}

/// Page points of a sheet point on the page showing `t`.
pub(crate) fn tile_map(t: &Tile, page: Vec2) -> impl Fn(Vec2) -> (f32, f32) {
    let (min, h) = (t.area.min, page.y);
    move |p: Vec2| (((PAGE_MARGIN + p.x - min.x) * PT) as f32, ((h - PAGE_MARGIN - (p.y - min.y)) * PT) as f32)
}

fn tile_page(s: &Sheet, t: &Tile, page: Vec2, kept: &[Tile]) -> Vec<u8> {
    let map = tile_map(t, page);
    let mut c = Content::new();
    let area = t.area.size();
    let (x0, y0) = map(t.area.min);
    let (x1, y1) = map(t.area.max);
    // The page's name, large and light behind the drawing.
    let label = t.label();
    let centre = map((t.area.min + t.area.max) / 2.0);
    let big = (4.0 * PT) as f32;
    c.begin_text();
    c.set_fill_gray(0.88);
    c.set_font(Name(b"F1"), big);
    c.set_text_matrix([1.0, 0.0, 0.0, 1.0, centre.0 - big * 0.3 * label.len() as f32, centre.1 - big * 0.35]);
    c.show(Str(&ascii(&label)));
    c.end_text();
    // The drawing, clipped to the printable area.
    c.save_state();
    c.rect(x0, y1, x1 - x0, y0 - y1).clip_nonzero().end_path();
    draw(&mut c, &s.prims, &map, PT);
    c.restore_state();
    // Trim frame, overlap lines and registration marks.
    pen(&mut c, Style::Frame);
    c.set_line_width(0.4);
    c.set_stroke_gray(0.5);
    c.rect(x0, y1, x1 - x0, y0 - y1).stroke();
    c.set_dash_pattern([3.0, 3.0], 0.0);
    let step = area - Vec2::splat(OVERLAP);
    let (xs, _) = map(t.area.min + Vec2::new(step.x, 0.0));
    let (_, ys) = map(t.area.min + Vec2::new(0.0, step.y));
    c.move_to(xs, y0).line_to(xs, y1).move_to(x0, ys).line_to(x1, ys).stroke();
    // Marks in the middle of every overlap strip: the same sheet points on both neighbours.
    let mid = t.area.min + step + Vec2::splat(OVERLAP / 2.0);
    let left = t.area.min + Vec2::splat(OVERLAP / 2.0);
    for p in [
        Vec2::new(mid.x, t.area.min.y + area.y / 2.0),
        Vec2::new(left.x - OVERLAP / 2.0 + OVERLAP / 2.0, t.area.min.y + area.y / 2.0),
        Vec2::new(t.area.min.x + area.x / 2.0, mid.y),
        Vec2::new(t.area.min.x + area.x / 2.0, left.y),
    ] {
        mark(&mut c, map(p));
    }
    // Labels: this page (in the top margin) and its neighbours.
    let small = (0.45 * PT) as f32;
    text_grey(&mut c, (x0, y0 + (0.3 * PT) as f32), (0.5 * PT) as f32, &format!("Page {label}"));
    let has = |r: isize, cl: isize| kept.iter().any(|k| k.row as isize == r && k.col as isize == cl);
    let (r, cl) = (t.row as isize, t.col as isize);
    let nb = |r: isize, cl: isize| sheet::tile_label(r as usize, cl as usize);
    if has(r, cl + 1) {
        text_grey(&mut c, map(Vec2::new(t.area.max.x - 2.2, t.area.min.y + area.y / 2.0 - 1.0)), small, &format!("{} ->", nb(r, cl + 1)));
    }
    if cl > 0 && has(r, cl - 1) {
        text_grey(&mut c, map(Vec2::new(t.area.min.x + 1.2, t.area.min.y + area.y / 2.0 - 1.0)), small, &format!("<- {}", nb(r, cl - 1)));
    }
    if r > 0 && has(r - 1, cl) {
        text_grey(&mut c, map(Vec2::new(t.area.min.x + area.x / 2.0 + 1.0, t.area.min.y + 1.3)), small, &format!("^ {}", nb(r - 1, cl)));
    }
    if has(r + 1, cl) {
        text_grey(&mut c, map(Vec2::new(t.area.min.x + area.x / 2.0 + 1.0, t.area.max.y - 1.4)), small, &format!("v {}", nb(r + 1, cl)));
    }
    let foot = format!(
        "{} - page {label} (row {}, column {}) - 1:1 - lay the next page's edge on the dashed line",
        s.title,
        &label[..label.find(|ch: char| ch.is_ascii_digit()).unwrap_or(1)],
        t.col + 1
    );
    text_grey(&mut c, (x0, y1 - (0.45 * PT) as f32), (0.3 * PT) as f32, &foot);
    c.finish().to_vec()
}

fn text_grey(c: &mut Content, at: (f32, f32), size: f32, text: &str) {
    c.begin_text();
    c.set_fill_gray(0.35);
    c.set_font(Name(b"F1"), size);
    c.set_text_matrix([1.0, 0.0, 0.0, 1.0, at.0, at.1]);
    c.show(Str(&ascii(text)));
    c.end_text();
}

/// The cover: title, instructions, cut list and the page map.
fn cover(s: &Sheet, pieces: &[Piece], opts: &PrintOptions, page: Vec2, rows: usize, cols: usize, tiles: &[Tile]) -> PageOut {
    let mut c = Content::new();
    let top = |y_cm: f64| ((page.y - y_cm) * PT) as f32;
    let x = (1.5 * PT) as f32;
    text_at(&mut c, (x, top(2.5)), 20.0, 0.0, &s.title);
    let mut lines = vec![
        format!("{} pages of {} rows x {} columns (blank pages left out), plus this cover.", tiles.len(), rows, cols),
        "Print at 100% / actual size. The 10 cm box on page A1 must measure 10 cm.".to_string(),
        format!("Pages overlap by {OVERLAP} cm: trim each page on its grey frame, lay it on the dashed"),
        "line of its neighbour and match the circle marks; tape.".to_string(),
        format!(
            "Seam allowance {} cm included{}. Notches mark where seams meet.",
            opts.seam,
            opts.hem.map(|h| format!(", hems {h} cm")).unwrap_or_default()
        ),
        "Cut list:".to_string(),
    ];
    lines.extend(pieces.iter().map(|p| format!("    {}: {}", p.name, p.cut.text())));
    for (k, l) in lines.iter().enumerate() {
        text_at(&mut c, (x, top(3.6 + 0.55 * k as f64)), 10.0, 0.0, l);
    }
    // Page map: the sheet scaled into the rest of the page.
    let map_top = 3.6 + 0.55 * lines.len() as f64 + 1.0;
    let avail = Vec2::new(page.x - 3.0, page.y - map_top - 1.5);
    let step = page - Vec2::splat(2.0 * PAGE_MARGIN + OVERLAP);
    let extent = Vec2::new(cols as f64 * step.x + OVERLAP, rows as f64 * step.y + OVERLAP);
    let k = (avail.x / extent.x).min(avail.y / extent.y);
    let map = |p: Vec2| (((1.5 + p.x * k) * PT) as f32, ((page.y - map_top - p.y * k) * PT) as f32);
    for p in &s.prims {
        if let Prim::Path { pts, closed: true, style: Style::Cut | Style::Frame } = p {
            draw(&mut c, &[Prim::Path { pts: pts.clone(), closed: true, style: Style::Sew }], &map, PT * k);
        }
    }
    for row in 0..rows {
        for col in 0..cols {
            let kept = tiles.iter().find(|t| t.row == row && t.col == col);
            let min = Vec2::new(col as f64 * step.x, row as f64 * step.y);
            let r = Rect { min, max: min + step };
            let (a, b) = (map(r.min), map(r.max));
            c.set_line_width(if kept.is_some() { 0.8 } else { 0.3 });
            c.set_stroke_gray(if kept.is_some() { 0.0 } else { 0.7 });
            c.set_dash_pattern(if kept.is_some() { vec![] } else { vec![2.0, 2.0] }, 0.0);
            c.rect(a.0, b.1, b.0 - a.0, a.1 - b.1).stroke();
            if let Some(t) = kept {
                let size = ((step.x * k).min(step.y * k) * 0.3 * PT).min(14.0) as f32;
                text_at(&mut c, (a.0 + 2.0, b.1 + 2.0 + (b.1 - a.1).abs() * 0.0 + ((a.1 - b.1) - size) / 2.0), size, 0.0, &t.label());
            }
        }
    }
    PageOut { size: page, content: c.finish().to_vec() }
}
