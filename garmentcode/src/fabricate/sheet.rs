//! Laying pieces out: the one-sheet drawing (what every print format shows), its
//! tiling onto home-printer pages, and the cutting layout on a fabric width.

use super::geom::{Rect, Xf};
use super::types::{Cut, Piece, PrintOptions};
use crate::math::Vec2;

/// Gap between nested pieces (cm).
pub const GAP: f64 = 1.5;
/// Unprintable margin of a home printer's page (cm).
pub const PAGE_MARGIN: f64 = 1.0;
/// Overlap of neighbouring tiled pages (cm).
pub const OVERLAP: f64 = 1.0;
/// Side of the metric scale box (cm).
pub const SCALE_BOX_CM: f64 = 10.0;
/// Side of the imperial scale box (cm): 4 inches.
pub const SCALE_BOX_IN: f64 = 4.0 * 2.54;

/// How a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Cut line: solid, heavy.
    Cut,
    /// Sew line: dashed, thin.
    Sew,
    /// Notch slits.
    Notch,
    /// Grainline and its arrows.
    Grain,
    /// Fold line and its marker.
    Fold,
    /// Internal lines (gathering).
    Internal,
    /// Frames of the title block and scale boxes.
    Frame,
    /// Text.
    Text,
    /// The cut line and notches of one size of a size run: its index into
    /// [`SIZE_PENS`] (taken in turn).
    Size(u8),
}

/// The pens of a size run's sizes, in turn: colour (RGB, 0 to 1) and dash pattern
/// (dash and gap lengths in cm; empty for a solid line). Colour and dash both differ
/// from one size to the next, so that a black-and-white print still tells them apart.
pub const SIZE_PENS: [([f32; 3], &[f64]); 8] = [
    ([0.0, 0.0, 0.0], &[]),
    ([0.8, 0.1, 0.1], &[0.6, 0.25]),
    ([0.1, 0.35, 0.8], &[0.15, 0.15]),
    ([0.1, 0.55, 0.2], &[0.6, 0.2, 0.15, 0.2]),
    ([0.55, 0.25, 0.7], &[1.2, 0.3]),
    ([0.85, 0.5, 0.0], &[0.3, 0.3]),
    ([0.0, 0.55, 0.6], &[0.6, 0.15, 0.15, 0.15, 0.15, 0.15]),
    ([0.5, 0.35, 0.15], &[]),
];

impl Style {
    /// The pen of the `k`-th size of a size run.
    pub fn size(k: usize) -> Style {
        Style::Size((k % SIZE_PENS.len()) as u8)
    }
}

/// One thing drawn on the sheet (coordinates in cm, y down, origin top left).
#[derive(Clone, Debug, PartialEq)]
pub enum Prim {
    /// A polyline.
    Path {
        /// Points.
        pts: Vec<Vec2>,
        /// Closed back to the first point.
        closed: bool,
        /// Line style.
        style: Style,
    },
    /// A line of text.
    Text {
        /// Left end of the baseline.
        at: Vec2,
        /// Text height (cm).
        size: f64,
        /// The text (ASCII).
        text: String,
        /// Counter-clockwise rotation on the page (degrees).
        angle: f64,
    },
}

impl Prim {
    /// Bounding box (text estimated at 0.6 em per character).
    pub fn bounds(&self) -> Rect {
        match self {
            Prim::Path { pts, .. } => Rect::of(pts.iter().copied()),
            Prim::Text { at, size, text, angle } => {
                let w = 0.6 * size * text.len() as f64;
                let (s, c) = angle.to_radians().sin_cos();
                let along = Vec2::new(c, -s) * w;
                let up = Vec2::new(-s, -c) * *size;
                Rect::of([*at, *at + along, *at + up, *at + along + up])
            }
        }
    }
}

/// A piece on the sheet: its frame is mapped by `xf` (y flipped to the page).
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// Index into the pieces.
    pub piece: usize,
    /// Piece frame → sheet.
    pub xf: Xf,
}

/// The one-sheet drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    /// Width and height (cm).
    pub size: Vec2,
    /// Everything drawn.
    pub prims: Vec<Prim>,
    /// Where each piece went.
    pub placed: Vec<Placed>,
    /// Title of the pattern.
    pub title: String,
}

/// Shelf packing of boxes (width, height) into rows of at most `width`: the
/// tallest first, left to right, a new row when the next does not fit. Returns the
/// top-left corner of each box and the total height. Boxes wider than `width`
/// get a row of their own.
pub fn shelf_pack(sizes: &[Vec2], width: f64, gap: f64) -> (Vec<Vec2>, f64) {
    let mut order: Vec<usize> = (0..sizes.len()).collect();
    order.sort_by(|&a, &b| sizes[b].y.total_cmp(&sizes[a].y).then(a.cmp(&b)));
    let mut at = vec![Vec2::ZERO; sizes.len()];
    let (mut x, mut y, mut row_h) = (0.0, 0.0, 0.0f64);
    for i in order {
        let s = sizes[i];
        if x > 0.0 && x + s.x > width {
            y += row_h + gap;
            x = 0.0;
            row_h = 0.0;
        }
        at[i] = Vec2::new(x, y);
        x += s.x + gap;
        row_h = row_h.max(s.y);
    }
    (at, y + row_h)
}

/// Map of a piece frame (y up) onto the page (y down) with the cut line's box at `corner`.
pub(super) fn frame_to_page(p: &Piece, corner: Vec2) -> Xf {
    let b = Rect::of(p.cut_line.iter().copied());
    Xf { cols: [Vec2::X, Vec2::new(0.0, -1.0)], t: Vec2::new(corner.x - b.min.x, corner.y + b.max.y) }
}

/// Arrow heads at `tip` pointing along `dir` (unit).
fn arrow_head(tip: Vec2, dir: Vec2, size: f64) -> Vec<Vec2> {
    let side = Vec2::new(-dir.y, dir.x);
    vec![tip - dir * size + side * size * 0.5, tip, tip - dir * size - side * size * 0.5]
}

/// Radius of a drill-hole mark on the drawings, cm.
const DRILL_RADIUS: f64 = 0.3;

/// The drawing of one piece through `xf`.
pub fn piece_prims(p: &Piece, xf: &Xf) -> Vec<Prim> {
    let map = |v: &[Vec2]| v.iter().map(|q| xf.apply(*q)).collect::<Vec<_>>();
    let path = |pts: Vec<Vec2>, closed, style| Prim::Path { pts, closed, style };
    let mut out = vec![path(map(&p.cut_line), true, Style::Cut), path(map(&p.sew), true, Style::Sew)];
    for n in &p.notches {
        out.push(path(map(&[n.outer, n.inner]), false, Style::Notch));
    }
    let [g0, g1] = [xf.apply(p.grain[0]), xf.apply(p.grain[1])];
    out.push(path(vec![g0, g1], false, Style::Grain));
    let dir = (g1 - g0).normalize_or_zero();
    out.push(path(arrow_head(g1, dir, 0.8), false, Style::Grain));
    out.push(path(arrow_head(g0, -dir, 0.8), false, Style::Grain));
    if let Some([a, b]) = p.fold {
        // A bracket inside the fold line with arrows onto it.
        let (a, b) = (xf.apply(a), xf.apply(b));
        let along = (b - a).normalize_or_zero();
        let inward = {
            let c = xf.apply(Rect::of(p.sew.iter().copied()).min.lerp(Rect::of(p.sew.iter().copied()).max, 0.5));
            let n = Vec2::new(-along.y, along.x);
            if (c - a).dot(n) >= 0.0 { n } else { -n }
        };
        let (s, e) = (a.lerp(b, 0.2), a.lerp(b, 0.8));
        // Sized to the piece: a bracket at most a quarter of the piece's width deep,
        // the words along at most 60% of the fold.
        let depth = (Rect::of(p.sew.iter().copied()).size().x * 0.25).min(2.0);
        let text_size = (0.6 * (b - a).length() / (13.0 * 0.6)).min(0.8);
        out.push(path(vec![s, s + inward * depth, e + inward * depth, e], false, Style::Fold));
        out.push(path(arrow_head(s, -inward, 0.6), false, Style::Fold));
        out.push(path(arrow_head(e, -inward, 0.6), false, Style::Fold));
        let angle = -along.y.atan2(along.x).to_degrees();
        let (angle, start) = if angle.abs() > 90.0 { (angle - 180.0f64.copysign(angle), e) } else { (angle, s) };
        let text_at = start + inward * (depth + 0.4 + text_size) + (if start == s { along } else { -along }) * 0.1 * (b - a).length();
        out.push(Prim::Text { at: text_at, size: text_size, text: "PLACE ON FOLD".into(), angle });
    }
    for line in &p.internal {
        out.push(path(map(line), false, Style::Internal));
    }
    for hole in &p.cutouts {
        out.push(path(map(hole), true, Style::Cut));
    }
    for line in &p.mirror_lines {
        out.push(path(map(line), false, Style::Fold));
    }
    for c in &p.drill_holes {
        // A small circle with a cross, as drill holes are marked.
        let c = xf.apply(*c);
        out.push(path(
            (0..16).map(|k| c + Vec2::from_angle(k as f64 / 16.0 * std::f64::consts::TAU) * DRILL_RADIUS).collect(),
            true,
            Style::Internal,
        ));
        out.push(path(vec![c - Vec2::X * DRILL_RADIUS, c + Vec2::X * DRILL_RADIUS], false, Style::Internal));
        out.push(path(vec![c - Vec2::Y * DRILL_RADIUS, c + Vec2::Y * DRILL_RADIUS], false, Style::Internal));
    }
    for (k, text) in p.labels.iter().enumerate() {
        let at = xf.apply(p.label_at - Vec2::new(0.0, 1.25 * p.text_size * k as f64));
        let size = if k == 0 { p.text_size * 1.2 } else { p.text_size };
        out.push(Prim::Text { at, size, text: text.clone(), angle: 0.0 });
    }
    out
}

/// The title block (pattern name, size, allowances, cut list) and the scale boxes,
/// drawn with their top-left corner at `at`; returns the drawing and its size.
pub(super) fn title_block(pieces: &[Piece], opts: &PrintOptions, at: Vec2) -> (Vec<Prim>, Vec2) {
    let mut lines = vec![
        format!("{} - size {}", opts.garment, opts.size),
        format!("Seam allowance {} cm included{}", opts.seam, opts.hem.map(|h| format!(", hems {h} cm")).unwrap_or_default()),
        "Print at 100% (no scaling); check the scale boxes.".into(),
        "Cut list:".into(),
    ];
    lines.extend(pieces.iter().map(|p| format!("  {}: {}", p.name, p.cut.text())));
    lines.push("Made with garmentcode".into());
    // The scale boxes first, stacked at the sheet's top-left corner: on the first
    // tiled page, whatever the paper.
    let rect = |o: Vec2, s: Vec2| Prim::Path {
        pts: vec![o, o + Vec2::new(s.x, 0.0), o + s, o + Vec2::new(0.0, s.y)],
        closed: true,
        style: Style::Frame,
    };
    let mut out = vec![rect(at, Vec2::splat(SCALE_BOX_CM))];
    out.push(Prim::Text { at: at + Vec2::new(2.5, 5.3), size: 1.0, text: "10 cm".into(), angle: 0.0 });
    out.push(Prim::Text { at: at + Vec2::new(2.5, 6.5), size: 0.5, text: "(must measure 10 cm)".into(), angle: 0.0 });
    let in_at = at + Vec2::new(0.0, SCALE_BOX_CM + 0.8);
    out.push(rect(in_at, Vec2::splat(SCALE_BOX_IN)));
    out.push(Prim::Text { at: in_at + Vec2::new(3.0, 5.3), size: 1.0, text: "4 in".into(), angle: 0.0 });
    let boxes_h = SCALE_BOX_CM + 0.8 + SCALE_BOX_IN;
    let size = 0.6;
    let text_at = at + Vec2::new(SCALE_BOX_IN + 1.0, 0.0);
    let width = lines.iter().map(|l| l.len()).max().unwrap_or(10) as f64 * 0.55 * size + 1.0;
    let text_h = lines.len() as f64 * size * 1.4 + 1.0;
    for (k, l) in lines.iter().enumerate() {
        let s = if k == 0 { size * 1.4 } else { size };
        out.push(Prim::Text { at: text_at + Vec2::new(0.5, 1.0 + size * 1.4 * k as f64), size: s, text: l.clone(), angle: 0.0 });
    }
    out.push(rect(text_at, Vec2::new(width, text_h)));
    (out, Vec2::new(SCALE_BOX_IN + 1.0 + width, boxes_h.max(text_h)))
}

/// The one-sheet drawing: the title block, then the pieces nested on grain in rows
/// as wide as the paper allows.
pub fn one_sheet(pieces: &[Piece], opts: &PrintOptions) -> Sheet {
    let width = opts.paper.sheet_width() - 2.0 * PAGE_MARGIN;
    let (title, title_size) = title_block(pieces, opts, Vec2::splat(PAGE_MARGIN));
    let sizes: Vec<Vec2> = pieces.iter().map(|p| Rect::of(p.cut_line.iter().copied()).size()).collect();
    let (at, height) = shelf_pack(&sizes, width, GAP);
    let top = PAGE_MARGIN + title_size.y + GAP;
    let mut prims = title;
    let mut placed = Vec::new();
    let mut right = PAGE_MARGIN + title_size.x;
    for (i, p) in pieces.iter().enumerate() {
        let corner = Vec2::new(PAGE_MARGIN, top) + at[i];
        let xf = frame_to_page(p, corner);
        prims.extend(piece_prims(p, &xf));
        placed.push(Placed { piece: i, xf });
        right = right.max(corner.x + sizes[i].x);
    }
    let size = Vec2::new(right.max(width) + PAGE_MARGIN, top + height + PAGE_MARGIN);
    Sheet { size, prims, placed, title: format!("{} - size {}", opts.garment, opts.size) }
}

/// One page of the tiled print: the sheet rectangle it shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tile {
    /// Row (0 = top).
    pub row: usize,
    /// Column (0 = left).
    pub col: usize,
    /// The part of the sheet printed on the page (cm): the page's printable area.
    pub area: Rect,
}

impl Tile {
    /// Row letter and column number, e.g. `B3`.
    pub fn label(&self) -> String {
        tile_label(self.row, self.col)
    }
}

/// `A1`, `B3`, … (rows beyond Z continue `AA`, `AB`, …).
pub fn tile_label(row: usize, col: usize) -> String {
    let mut r = String::new();
    let mut n = row + 1;
    while n > 0 {
        n -= 1;
        r.insert(0, (b'A' + (n % 26) as u8) as char);
        n /= 26;
    }
    format!("{r}{}", col + 1)
}

/// The grid of pages covering a sheet of `size` on pages of `page` (cm): each page
/// prints its area inside a [`PAGE_MARGIN`], neighbours share [`OVERLAP`]; pages
/// with nothing drawn in their own cell (the page less its overlap with the next
/// ones) are left out. Returns the rows, columns and kept tiles.
pub fn tiles(sheet: &Sheet, page: Vec2) -> (usize, usize, Vec<Tile>) {
    let area = page - Vec2::splat(2.0 * PAGE_MARGIN);
    let step = area - Vec2::splat(OVERLAP);
    let cols = ((sheet.size.x - OVERLAP) / step.x).ceil().max(1.0) as usize;
    let rows = ((sheet.size.y - OVERLAP) / step.y).ceil().max(1.0) as usize;
    let mut out = Vec::new();
    for row in 0..rows {
        for col in 0..cols {
            let min = Vec2::new(col as f64 * step.x, row as f64 * step.y);
            // A page is needed when something is drawn in its own cell: what lies
            // in the overlap with the next page is printed on that page too.
            let cell = Rect { min, max: min + step };
            if sheet.prims.iter().any(|p| touches(p, &cell)) {
                out.push(Tile { row, col, area: Rect { min, max: min + area } });
            }
        }
    }
    (rows, cols, out)
}

/// Whether a drawn thing shows inside `r`.
fn touches(p: &Prim, r: &Rect) -> bool {
    match p {
        Prim::Text { .. } => p.bounds().overlaps(r),
        Prim::Path { pts, closed, .. } => {
            let n = pts.len();
            let segs = if *closed { n } else { n.saturating_sub(1) };
            (0..segs).any(|i| segment_meets_rect(pts[i], pts[(i + 1) % n], r))
        }
    }
}

/// Liang–Barsky: does the segment reach into the rectangle?
fn segment_meets_rect(a: Vec2, b: Vec2, r: &Rect) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, a.x - r.min.x), (d.x, r.max.x - a.x), (-d.y, a.y - r.min.y), (d.y, r.max.y - a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    t0 <= t1
}

/// One piece cut from the fabric: its outlines in fabric coordinates (cm, y down
/// from the cut end, x from one selvage).
#[derive(Clone, Debug, PartialEq)]
pub struct Cutting {
    /// Index into the pieces.
    pub piece: usize,
    /// Which copy (0 or 1).
    pub copy: usize,
    /// Outline(s): a piece cut on the fold is the piece and its mirror image.
    pub outlines: Vec<Vec<Vec2>>,
    /// Fits the fabric width.
    pub fits: bool,
}

/// The cutting layout: every copy of every piece on the fabric, and the length used.
#[derive(Clone, Debug, PartialEq)]
pub struct CuttingLayout {
    /// Fabric width (cm).
    pub width: f64,
    /// Length of fabric needed (cm).
    pub length: f64,
    /// The pieces as cut.
    pub cuts: Vec<Cutting>,
}

/// The outlines of every copy of a piece to cut, in its frame (y up).
fn copies(p: &Piece) -> Vec<Vec<Vec<Vec2>>> {
    let cut = p.cut_line.clone();
    let b = Rect::of(cut.iter().copied());
    let mirrored = |m: &Xf| cut.iter().rev().map(|q| m.apply(*q)).collect::<Vec<_>>();
    match p.cut {
        Cut::One => vec![vec![cut]],
        Cut::Two => vec![vec![cut.clone()], vec![cut]],
        Cut::MirroredPair => {
            let m = Xf::mirror_x(b.min.x + b.max.x);
            vec![vec![cut.clone()], vec![mirrored(&m)]]
        }
        Cut::OnFold => {
            let [a, _] = p.fold.expect("a fold piece has a fold");
            let m = Xf::mirror_x(2.0 * a.x);
            vec![vec![cut.clone(), mirrored(&m)]]
        }
    }
}

/// Lay every copy of every piece on a fabric `width` cm wide, on grain (the grain
/// along the selvage, down the fabric), shelf-packed. Copies wider than the fabric
/// are placed on their own row and marked as not fitting.
pub fn cutting_layout(pieces: &[Piece], width: f64) -> CuttingLayout {
    let mut items = Vec::new();
    for (i, p) in pieces.iter().enumerate() {
        for (copy, outlines) in copies(p).into_iter().enumerate() {
            items.push((i, copy, outlines));
        }
    }
    let boxes: Vec<Rect> = items.iter().map(|(_, _, o)| Rect::of(o.iter().flatten().copied())).collect();
    let sizes: Vec<Vec2> = boxes.iter().map(Rect::size).collect();
    let (at, length) = shelf_pack(&sizes, width, 1.0);
    let cuts = items
        .into_iter()
        .enumerate()
        .map(|(k, (piece, copy, outlines))| {
            let xf = Xf { cols: [Vec2::X, Vec2::new(0.0, -1.0)], t: Vec2::new(at[k].x - boxes[k].min.x, at[k].y + boxes[k].max.y) };
            let outlines = outlines.iter().map(|o| o.iter().map(|q| xf.apply(*q)).collect()).collect();
            Cutting { piece, copy, outlines, fits: sizes[k].x <= width }
        })
        .collect();
    CuttingLayout { width, length, cuts }
}

/// The cutting layout as text: fabric needed and what does not fit.
pub fn cutting_report(l: &CuttingLayout, pieces: &[Piece], opts: &PrintOptions) -> String {
    let mut s = format!("Cutting layout: {} - size {}\n", opts.garment, opts.size);
    s += &format!("Fabric width: {:.1} cm\n", l.width);
    s += &format!("Fabric length needed: {:.1} cm ({:.2} m, {:.2} yd)\n", l.length, l.length / 100.0, l.length / 91.44);
    s += "Pieces (all on grain, grain along the selvage):\n";
    for (i, p) in pieces.iter().enumerate() {
        s += &format!("  {}: {}\n", p.name, p.cut.text());
        for c in l.cuts.iter().filter(|c| c.piece == i && !c.fits) {
            let w = Rect::of(c.outlines.iter().flatten().copied()).size().x;
            s += &format!("    TOO WIDE: copy {} is {w:.1} cm wide, the fabric {:.1} cm\n", c.copy + 1, l.width);
        }
    }
    s
}
