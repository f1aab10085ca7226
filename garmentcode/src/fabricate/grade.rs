//! Size runs: one design built on several bodies, printed nested.
//!
//! Every size's pieces are made as for a single pattern ([`super::pieces`]); pieces
//! of the same name across sizes form one nest. Each size's piece is aligned at
//! the **grade reference point**, the centre of its sew line's bounding box (on
//! grain, since every piece's grain runs up the page), so the sizes grow evenly
//! around it, as nested commercial patterns are drawn; a piece cut on the fold is
//! aligned on its fold line instead, so all sizes share the fold. On the sheet each size has
//! its own pen ([`super::sheet::SIZE_PENS`]: colour and dash) for its cut line and notches, and
//! its name next to its outline; the grainline, fold and labels are drawn once,
//! from the middle size. The title block adds a legend of the pens. In the
//! DXF-AAMA file each piece of each size is a block of its own (`PIECE_SIZE`, with
//! its `Size:` field), inserted at the same point as the other sizes of its piece,
//! and the drawing carries the size list (`Size List:`, `Sample Size:`).

use super::dxf::{self, Block, block_name};
use super::geom::{Rect, Xf};
use super::sheet::{self, GAP, PAGE_MARGIN, Placed, Prim, Sheet, Style};
use super::types::{Piece, PrintOptions};
use super::{pdf, piece, svg};
use crate::error::{Error, Result};
use crate::math::Vec2;
use crate::pattern::Pattern;

/// Names of the files [`size_run_files`] writes, in its order.
pub const SIZE_RUN_FILE_NAMES: [&str; 4] = ["pattern-tiled.pdf", "pattern-sheet.pdf", "pattern-sheet.svg", "pattern.dxf"];

/// The printable files of a size run: `sizes` are each size's name and pattern (the
/// same design built on each size's body), smallest first as they should be
/// listed; `opts.size` is ignored (each size is named by its own). Name and bytes,
/// in the order of [`SIZE_RUN_FILE_NAMES`].
///
/// ```
/// use garmentcode::fabricate::{PrintOptions, read_dxf, size_run_files};
/// use garmentcode::{Arena, EdgeSeq, PartExt, Vec2};
///
/// let square = |side: f64| {
///     let mut a = Arena::new();
///     let corners = [Vec2::ZERO, Vec2::new(0.0, side), Vec2::new(side, side), Vec2::new(side, 0.0)];
///     let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
///     let panel = a.panel_with_edges("front", edges);
///     PartExt::assemble(&panel, &mut a, "demo")
/// };
/// let sizes = vec![("S".to_string(), square(20.0)?), ("M".to_string(), square(22.0)?)];
/// let files = size_run_files(&sizes, &PrintOptions::default())?;
/// let dxf = read_dxf(std::str::from_utf8(&files[3].1).unwrap()).unwrap();
/// let names: Vec<&str> = dxf.blocks.iter().map(|b| b.name.as_str()).collect();
/// assert_eq!(names, ["front_S", "front_M"]);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn size_run_files(sizes: &[(String, Pattern)], opts: &PrintOptions) -> Result<Vec<(String, Vec<u8>)>> {
    if sizes.is_empty() || sizes.len() > crate::MAX_SIZES {
        return Err(Error::Input(format!("a size run has 1 to {} sizes, not {}", crate::MAX_SIZES, sizes.len())));
    }
    let mut per_size = Vec::with_capacity(sizes.len());
    for (name, pattern) in sizes {
        let o = PrintOptions { size: name.clone(), ..opts.clone() };
        o.check()?;
        let pieces = piece::build(pattern, &o).map_err(|e| Error::Input(format!("size {name}: {e}")))?;
        per_size.push(pieces.into_iter().map(centred).collect::<Vec<Piece>>());
    }
    // One nest per piece name, in the order the sizes first have them.
    let mut names: Vec<&str> = Vec::new();
    for p in per_size.iter().flatten() {
        if !names.contains(&p.name.as_str()) {
            names.push(&p.name);
        }
    }
    let nests: Vec<Vec<(usize, &Piece)>> = names
        .iter()
        .map(|n| per_size.iter().enumerate().filter_map(|(k, ps)| ps.iter().find(|p| p.name == *n).map(|p| (k, p))).collect())
        .collect();
    let size_names: Vec<&str> = sizes.iter().map(|(n, _)| n.as_str()).collect();
    let listed = size_names.join(", ");
    let run = PrintOptions { size: listed.clone(), ..opts.clone() };
    // The representative of each nest: its middle size.
    let middle: Vec<Piece> = nests.iter().map(|nest| nest[nest.len() / 2].1.clone()).collect();

    let width = opts.paper.sheet_width() - 2.0 * PAGE_MARGIN;
    let (mut prims, title_size) = sheet::title_block(&middle, &run, Vec2::splat(PAGE_MARGIN));
    // The legend under the title block: each size's pen and name.
    let legend_top = PAGE_MARGIN + title_size.y + 0.8;
    for (k, name) in size_names.iter().enumerate() {
        let y = legend_top + 0.8 * k as f64;
        prims.push(Prim::Path {
            pts: vec![Vec2::new(PAGE_MARGIN, y), Vec2::new(PAGE_MARGIN + 3.0, y)],
            closed: false,
            style: Style::size(k),
        });
        prims.push(Prim::Text { at: Vec2::new(PAGE_MARGIN + 3.5, y + 0.2), size: 0.5, text: format!("size {name}"), angle: 0.0 });
    }
    let head = title_size.y + 0.8 + 0.8 * size_names.len() as f64;
    let bounds: Vec<Rect> = nests.iter().map(|nest| Rect::of(nest.iter().flat_map(|(_, p)| p.cut_line.iter().copied()))).collect();
    let (at, height) = sheet::shelf_pack(&bounds.iter().map(Rect::size).collect::<Vec<_>>(), width, GAP);
    let top = PAGE_MARGIN + head + GAP;
    let mut placed = Vec::new();
    let mut blocks_of: Vec<(usize, &Piece, Xf)> = Vec::new();
    let mut right = PAGE_MARGIN + title_size.x;
    for (i, nest) in nests.iter().enumerate() {
        let corner = Vec2::new(PAGE_MARGIN, top) + at[i];
        let b = bounds[i];
        let xf = Xf { cols: [Vec2::X, Vec2::new(0.0, -1.0)], t: Vec2::new(corner.x - b.min.x, corner.y + b.max.y) };
        for &(k, p) in nest {
            let map = |v: &[Vec2]| v.iter().map(|q| xf.apply(*q)).collect::<Vec<_>>();
            prims.push(Prim::Path { pts: map(&p.cut_line), closed: true, style: Style::size(k) });
            for n in &p.notches {
                prims.push(Prim::Path { pts: map(&[n.outer, n.inner]), closed: false, style: Style::size(k) });
            }
            // The size's name just right of its outline's rightmost point.
            let tip = p.cut_line.iter().copied().max_by(|a, b| a.x.total_cmp(&b.x)).unwrap_or(Vec2::ZERO);
            prims.push(Prim::Text { at: xf.apply(tip) + Vec2::new(0.15, 0.15), size: 0.4, text: size_names[k].to_string(), angle: 0.0 });
            blocks_of.push((k, p, xf));
        }
        // Grainline, fold, gathering lines and labels once, from the middle size
        // (its cut line, sew line and notches are drawn above in its pen).
        let mut rep = middle[i].clone();
        rep.notches.clear();
        for l in &mut rep.labels {
            if l.starts_with("Size: ") {
                *l = format!("Sizes: {listed}");
            }
        }
        prims.extend(sheet::piece_prims(&rep, &xf).into_iter().skip(2));
        placed.push(Placed { piece: i, xf });
        right = right.max(corner.x + b.size().x);
    }
    let size = Vec2::new(right.max(width) + PAGE_MARGIN, top + height + PAGE_MARGIN);
    let title = format!("{} - sizes {listed}", opts.garment);
    let sheet = Sheet { size, prims, placed, title };
    let blocks: Vec<Block> = blocks_of
        .iter()
        .map(|&(k, piece, xf)| Block {
            piece,
            name: format!("{}_{}", block_name(&piece.name), block_name(size_names[k])),
            size: size_names[k],
            at: xf.t,
        })
        .collect();
    let notes = vec![format!("Size List: {}", size_names.join(" ")), format!("Sample Size: {}", size_names[size_names.len() / 2])];
    let bytes = [
        pdf::tiled(&sheet, &middle, &run),
        pdf::one_sheet(&sheet),
        svg::sheet(&sheet).into_bytes(),
        dxf::write_blocks(&blocks, &opts.garment, &notes).into_bytes(),
    ];
    Ok(SIZE_RUN_FILE_NAMES.iter().map(|n| n.to_string()).zip(bytes).collect())
}

/// The piece moved so that its grade reference point is its frame's origin: the
/// centre of its sew line's bounding box, moved across onto the fold line for a
/// piece cut on the fold (so that every size's fold is the same line).
fn centred(mut p: Piece) -> Piece {
    let b = Rect::of(p.sew.iter().copied());
    let mut reference = (b.min + b.max) / 2.0;
    if let Some([f0, f1]) = p.fold {
        // The fold runs along the grain (up the page): its x is the reference's.
        reference.x = (f0.x + f1.x) / 2.0;
    }
    let d = -reference;
    let shift = |v: &mut Vec<Vec2>| v.iter_mut().for_each(|q| *q += d);
    shift(&mut p.sew);
    shift(&mut p.cut_line);
    for n in &mut p.notches {
        n.sew += d;
        n.outer += d;
        n.inner += d;
    }
    p.grain = p.grain.map(|q| q + d);
    if let Some(f) = &mut p.fold {
        *f = f.map(|q| q + d);
    }
    p.internal.iter_mut().chain(&mut p.cutouts).chain(&mut p.mirror_lines).for_each(shift);
    p.drill_holes.iter_mut().for_each(|q| *q += d);
    p.label_at += d;
    for (_, xf) in &mut p.panels {
        xf.t += d;
    }
    p
}
