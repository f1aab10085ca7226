//! DXF-AAMA output and a small reader for it.
//!
//! The AAMA/ASTM D6673 convention for pattern pieces in DXF is plain R12 (`AC1009`)
//! in millimetres: each piece is a block, inserted once in the drawing; inside it
//! the cut line is on layer 1, the mirror (fold) line on 6, notches on 4, the
//! grainline on 7, internal lines on 8 and the sew line on 14; text on layer 1
//! names the piece and its quantity. Patterns using the format extension also get
//! internal cut-outs on layer 11 and drill holes (`POINT`s) on layer 13; their fold
//! lines are mirror lines on 6, their placement, dart and pleat lines internal
//! lines on 8 and their pleat notches notches on 4. R12 needs no object handles and has a tiny
//! structure, so it is written here directly: the `dxf` crate targets newer
//! versions (handles, class tables) and stamps the time into its header, which
//! would make every file different.

use super::sheet::Sheet;
use super::svg::num;
use super::types::{Cut, Piece, PrintOptions};
use crate::math::Vec2;
use std::fmt::Write;

/// Millimetres per centimetre.
const MM: f64 = 10.0;

/// The AAMA layers used, with their colours.
const LAYERS: [(&str, u8); 7] = [("0", 7), ("1", 7), ("4", 1), ("6", 5), ("7", 3), ("8", 4), ("14", 6)];
/// The AAMA layer of internal cut-outs (format extension), with its colour.
const CUTOUT_LAYER: (&str, u8) = ("11", 2);
/// The AAMA layer of drill holes (format extension), with its colour.
const DRILL_LAYER: (&str, u8) = ("13", 1);

/// A block name for a piece (letters, digits, `_` and `-`).
pub fn block_name(piece: &str) -> String {
    piece.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' || c == '_' { c } else { '_' }).collect()
}

struct W(String);

impl W {
    fn pair(&mut self, code: i32, value: &str) {
        let _ = write!(self.0, "{code:>3}\r\n{value}\r\n");
    }
    fn xy(&mut self, base: i32, p: Vec2) {
        self.pair(base, &num(p.x * MM));
        self.pair(base + 10, &num(p.y * MM));
        self.pair(base + 20, "0");
    }
    fn polyline(&mut self, layer: &str, pts: &[Vec2], closed: bool) {
        self.pair(0, "POLYLINE");
        self.pair(8, layer);
        self.pair(66, "1");
        self.xy(10, Vec2::ZERO);
        self.pair(70, if closed { "1" } else { "0" });
        for p in pts {
            self.pair(0, "VERTEX");
            self.pair(8, layer);
            self.xy(10, *p);
        }
        self.pair(0, "SEQEND");
        self.pair(8, layer);
    }
    fn line(&mut self, layer: &str, a: Vec2, b: Vec2) {
        self.pair(0, "LINE");
        self.pair(8, layer);
        self.xy(10, a);
        self.xy(11, b);
    }
    fn text(&mut self, layer: &str, at: Vec2, height: f64, text: &str) {
        self.pair(0, "TEXT");
        self.pair(8, layer);
        self.xy(10, at);
        self.pair(40, &num(height * MM));
        let t: String = text.chars().map(|c| if c.is_ascii() && !c.is_ascii_control() { c } else { '?' }).collect();
        self.pair(1, &t);
    }
}

/// The pieces as a DXF-AAMA file, inserted where the one-sheet drawing puts them.
pub fn write(pieces: &[Piece], sheet: &Sheet, opts: &PrintOptions) -> String {
    let blocks: Vec<Block> = sheet
        .placed
        .iter()
        .map(|pl| {
            let piece = &pieces[pl.piece];
            Block { piece, name: block_name(&piece.name), size: &opts.size, at: pl.xf.t }
        })
        .collect();
    write_blocks(&blocks, &opts.garment, &[])
}

/// One block of a DXF-AAMA file: a piece of one size, and where it is inserted.
pub(crate) struct Block<'a> {
    /// The piece.
    pub piece: &'a Piece,
    /// The block's name.
    pub name: String,
    /// Its `Size:` field.
    pub size: &'a str,
    /// The sheet offset of the piece's frame (cm, y down).
    pub at: Vec2,
}

/// A DXF-AAMA file of `blocks` (each defined, then inserted, in this order) for the
/// style `garment`, with `notes` as text lines on layer 1 above the drawing (a size
/// run's size list).
pub(crate) fn write_blocks(blocks: &[Block], garment: &str, notes: &[String]) -> String {
    let mut w = W(String::new());
    let all: Vec<Vec2> = blocks.iter().flat_map(|b| b.piece.cut_line.iter().map(|p| insert_point(b.at) + *p)).collect();
    let ext = super::geom::Rect::of(all);
    w.pair(0, "SECTION");
    w.pair(2, "HEADER");
    w.pair(9, "$ACADVER");
    w.pair(1, "AC1009");
    w.pair(9, "$EXTMIN");
    w.xy(10, ext.min);
    w.pair(9, "$EXTMAX");
    w.xy(10, ext.max);
    w.pair(0, "ENDSEC");
    w.pair(0, "SECTION");
    w.pair(2, "TABLES");
    w.pair(0, "TABLE");
    w.pair(2, "LTYPE");
    w.pair(70, "1");
    w.pair(0, "LTYPE");
    w.pair(2, "CONTINUOUS");
    w.pair(70, "0");
    w.pair(3, "Solid line");
    w.pair(72, "65");
    w.pair(73, "0");
    w.pair(40, "0");
    w.pair(0, "ENDTAB");
    // The layers of the format extension only where a piece uses them (so that
    // files without them stay as they were), in the numeric order of the rest.
    let uses = |f: fn(&Piece) -> bool| blocks.iter().any(|b| f(b.piece));
    let mut layers: Vec<(&str, u8)> = LAYERS.to_vec();
    if uses(|p| !p.cutouts.is_empty()) {
        layers.insert(layers.len() - 1, CUTOUT_LAYER);
    }
    if uses(|p| !p.drill_holes.is_empty()) {
        layers.insert(layers.len() - 1, DRILL_LAYER);
    }
    w.pair(0, "TABLE");
    w.pair(2, "LAYER");
    w.pair(70, &layers.len().to_string());
    for (name, colour) in layers {
        w.pair(0, "LAYER");
        w.pair(2, name);
        w.pair(70, "0");
        w.pair(62, &colour.to_string());
        w.pair(6, "CONTINUOUS");
    }
    w.pair(0, "ENDTAB");
    w.pair(0, "ENDSEC");
    w.pair(0, "SECTION");
    w.pair(2, "BLOCKS");
    for b in blocks {
        let p = b.piece;
        w.pair(0, "BLOCK");
        w.pair(8, "1");
        w.pair(2, &b.name);
        w.pair(70, "0");
        w.xy(10, Vec2::ZERO);
        w.pair(3, &b.name);
        w.polyline("1", &p.cut_line, true);
        w.polyline("14", &p.sew, true);
        for n in &p.notches {
            w.line("4", n.outer, n.inner);
        }
        w.line("7", p.grain[0], p.grain[1]);
        if let Some([a, b]) = p.fold {
            w.line("6", a, b);
        }
        for l in &p.internal {
            w.polyline("8", l, false);
        }
        for l in &p.mirror_lines {
            w.polyline("6", l, false);
        }
        for c in &p.cutouts {
            w.polyline("11", c, true);
        }
        for d in &p.drill_holes {
            w.pair(0, "POINT");
            w.pair(8, "13");
            w.xy(10, *d);
        }
        let h = p.text_size;
        let texts = [
            format!("Piece Name: {}", p.name),
            format!("Style Name: {garment}"),
            format!("Size: {}", b.size),
            format!(
                "Quantity: {}",
                match p.cut {
                    Cut::One | Cut::OnFold => 1,
                    _ => 2,
                }
            ),
            format!("Annotation: {}", p.cut.text()),
        ];
        for (k, t) in texts.iter().enumerate() {
            w.text("1", p.label_at - Vec2::new(0.0, 1.25 * h * k as f64), h, t);
        }
        w.pair(0, "ENDBLK");
        w.pair(8, "1");
    }
    w.pair(0, "ENDSEC");
    w.pair(0, "SECTION");
    w.pair(2, "ENTITIES");
    for (k, note) in notes.iter().enumerate() {
        w.text("1", Vec2::new(ext.min.x, ext.max.y + 2.0 + 1.5 * (notes.len() - 1 - k) as f64), 1.0, note);
    }
    for b in blocks {
        w.pair(0, "INSERT");
        w.pair(8, "1");
        w.pair(2, &b.name);
        w.xy(10, insert_point(b.at));
    }
    w.pair(0, "ENDSEC");
    w.pair(0, "EOF");
    w.0
}

/// Where a piece's frame origin goes in the DXF (cm, y up) for its sheet offset.
fn insert_point(sheet_offset: Vec2) -> Vec2 {
    Vec2::new(sheet_offset.x, -sheet_offset.y)
}

/// One entity read back.
#[derive(Clone, Debug, PartialEq)]
pub struct DxfEntity {
    /// `POLYLINE`, `LINE`, `TEXT`, `INSERT`...
    pub kind: String,
    /// Layer name.
    pub layer: String,
    /// Points in file units (vertices, line ends, text or insert position).
    pub points: Vec<Vec2>,
    /// A closed polyline.
    pub closed: bool,
    /// Text, or the block name of an insert.
    pub text: String,
}

/// One block read back.
#[derive(Clone, Debug, PartialEq)]
pub struct DxfBlock {
    /// Block name.
    pub name: String,
    /// Its entities.
    pub entities: Vec<DxfEntity>,
}

/// A DXF file read back: version, layer table, blocks and top-level entities.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DxfDrawing {
    /// `$ACADVER`.
    pub version: String,
    /// Layer names of the layer table.
    pub layers: Vec<String>,
    /// Blocks in file order.
    pub blocks: Vec<DxfBlock>,
    /// Entities of the ENTITIES section.
    pub entities: Vec<DxfEntity>,
}

/// Read an ASCII DXF file of the kind `files` writes (entities
/// `POLYLINE`/`VERTEX`/`SEQEND`, `LINE`, `TEXT`, `INSERT`); other entities are kept
/// with their first point.
pub fn read_dxf(text: &str) -> std::result::Result<DxfDrawing, String> {
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    if !lines.len().is_multiple_of(2) {
        return Err("odd number of lines: not group code / value pairs".into());
    }
    let pairs: Vec<(i32, &str)> = lines
        .chunks(2)
        .map(|c| c[0].parse::<i32>().map(|g| (g, c[1])).map_err(|_| format!("bad group code '{}'", c[0])))
        .collect::<Result<_, _>>()?;
    let mut d = DxfDrawing::default();
    let mut section = "";
    let mut block: Option<DxfBlock> = None;
    let mut current: Option<DxfEntity> = None;
    let mut in_polyline = false;
    let mut i = 0;
    let flush = |cur: &mut Option<DxfEntity>, block: &mut Option<DxfBlock>, d: &mut DxfDrawing| {
        if let Some(e) = cur.take() {
            match block {
                Some(b) => b.entities.push(e),
                None => d.entities.push(e),
            }
        }
    };
    while i < pairs.len() {
        let (code, value) = pairs[i];
        if code == 0 {
            match value {
                "SECTION" => {
                    section = pairs.get(i + 1).map(|p| p.1).unwrap_or("");
                    i += 2;
                    continue;
                }
                "ENDSEC" | "EOF" | "TABLE" | "ENDTAB" => {}
                "BLOCK" => block = Some(DxfBlock { name: String::new(), entities: Vec::new() }),
                "ENDBLK" => {
                    flush(&mut current, &mut block, &mut d);
                    d.blocks.extend(block.take());
                }
                "LAYER" if section == "TABLES" => {
                    if let Some(name) = pairs[i + 1..].iter().take_while(|p| p.0 != 0).find(|p| p.0 == 2) {
                        d.layers.push(name.1.to_string());
                    }
                }
                "VERTEX" if in_polyline => {
                    let (mut x, mut y) = (0.0, 0.0);
                    for &(c, v) in pairs[i + 1..].iter().take_while(|p| p.0 != 0) {
                        match c {
                            10 => x = v.parse().map_err(|_| format!("bad number {v}"))?,
                            20 => y = v.parse().map_err(|_| format!("bad number {v}"))?,
                            _ => {}
                        }
                    }
                    if let Some(e) = current.as_mut() {
                        e.points.push(Vec2::new(x, y));
                    }
                }
                "SEQEND" => {
                    in_polyline = false;
                    flush(&mut current, &mut block, &mut d);
                }
                kind if section == "ENTITIES" || (section == "BLOCKS" && block.is_some()) => {
                    flush(&mut current, &mut block, &mut d);
                    let mut e =
                        DxfEntity { kind: kind.to_string(), layer: String::new(), points: Vec::new(), closed: false, text: String::new() };
                    let (mut p0, mut p1) = (Vec2::ZERO, Vec2::ZERO);
                    for &(c, v) in pairs[i + 1..].iter().take_while(|p| p.0 != 0) {
                        let num = || v.parse::<f64>().map_err(|_| format!("bad number {v}"));
                        match c {
                            8 => e.layer = v.to_string(),
                            1 | 2 => e.text = v.to_string(),
                            10 => p0.x = num()?,
                            20 => p0.y = num()?,
                            11 => p1.x = num()?,
                            21 => p1.y = num()?,
                            70 => e.closed = v.parse::<i32>().map(|f| f & 1 == 1).unwrap_or(false),
                            _ => {}
                        }
                    }
                    match kind {
                        "POLYLINE" => in_polyline = true,
                        "LINE" => e.points = vec![p0, p1],
                        _ => e.points = vec![p0],
                    }
                    current = Some(e);
                }
                _ => {}
            }
        } else if code == 2 && section == "BLOCKS" {
            if let Some(b) = block.as_mut().filter(|b| b.name.is_empty() && current.is_none()) {
                b.name = value.to_string();
            }
        } else if code == 9 && value == "$ACADVER" {
            d.version = pairs.get(i + 1).map(|p| p.1.to_string()).unwrap_or_default();
        }
        i += 1;
    }
    flush(&mut current, &mut block, &mut d);
    Ok(d)
}
