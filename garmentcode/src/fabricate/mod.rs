//! Patterns a person can print, cut and sew.
//!
//! [`pieces`] turns every panel of a [`Pattern`] into a pattern piece: the sew line
//! (the panel's outline), the cut line at the seam allowance around it, notches,
//! a grainline, the cut count and labels. [`files`] lays the pieces out and writes
//! what a sewist or a cutting room needs:
//!
//! - `pattern-tiled.pdf`: the one-sheet drawing on A4 or Letter pages at 1:1, with a
//!   cover page (title block, cut list and page map), overlap margins, row/column
//!   labels and alignment marks on every page, and blank pages left out;
//! - `pattern-sheet.pdf` and `pattern-sheet.svg`: every piece on one sheet (A0 or a
//!   roll width) for a plotter or a copy shop (a PDF sheet longer than 5 m comes in
//!   parts, see below);
//! - `pattern.dxf`: DXF-AAMA (R12, millimetres), one block per piece;
//! - `cutting-layout.svg` and `cutting-layout.txt`: the pieces on a fabric width,
//!   each as many times as it is cut, and the length of fabric needed.
//!
//! [`size_run_files`] prints one design in several sizes nested: every piece's
//! outlines for all sizes on one sheet, each size in its own pen (see its module
//! for the grade reference point), the tiled PDF, and a DXF-AAMA file with one
//! block per piece and size.
//!
//! # The pieces
//!
//! **Frame.** Each piece is turned so that its grain runs up the page: the grain is
//! the world's vertical seen in the panel's plane (its placement on the body), or
//! the panel's own y axis when the panel lies flat. Pieces are never rotated off
//! grain when they are nested.
//!
//! **Seam allowance.** One width for the pattern (1 cm by default), a wider hem on
//! the unstitched edges labelled `lower_interface` when asked, and per-panel or
//! per-edge overrides ([`EdgeSeam`]). The cut line is the exact offset of the sew line
//! sampled along each edge: every sample is the sew-line point moved along the
//! exact normal of its line, arc or Bézier, so it lies on the true offset curve;
//! curved edges are sampled at most every [`CURVE_STEP`] cm, which keeps the
//! polyline within 0.05 mm of the true curve for radii above 2 cm (the tests check
//! 0.1 mm over every reference pattern). Outer corners are mitred (squared off when
//! the mitre would run further than three allowances from the corner), inner
//! corners and tight inward curves are trimmed where the offsets cross. The
//! offset is our own rather than an offsetting crate's because a generic offset
//! rounds outer corners, where pattern makers mitre them.
//!
//! **Notches.** Every stitch gets notches at both ends of both of its edges and, on
//! seams longer than [`MATCH_SPACING`] cm, match notches in between, at the same
//! length fractions on both sides (so the two pieces line up when sewn). A stitch
//! whose sides differ in length by more than [`GATHER_RATIO`] is a gather: the
//! longer side gets a wavy gathering line between its end notches. A notch is a
//! [`NOTCH_LENGTH`] cm slit from the cut line into the allowance, along the edge's
//! normal.
//!
//! **Cut count.** Two panels of the same outline, one the mirror image of the other,
//! are one piece: "Cut 1 on fold" when they are stitched together along a straight
//! edge on their mirror line (that edge gets no allowance and a fold marker), "Cut 2
//! (mirrored pair)" otherwise; two identical panels are "Cut 2".
//!
//! # Formats
//!
//! PDF is written with `pdf-writer` (uncompressed, no dates, so the bytes depend on
//! the pattern alone) and the standard Type 1 font Helvetica, which every PDF reader
//! has built in and which needs no embedding.
//!
//! **Long sheets.** PDF readers limit a page to 200 inches (14 400 pt, 508 cm) a
//! side, and a long layout (a narrow roll, a maxi dress) can run past that. Such a
//! one-sheet PDF is split into the fewest equal parts of at most 5 m
//! (`MAX_PAGE`), each printed at 1:1 and joined as the tiled pages are: an overlap
//! strip with a dashed line and registration marks, and the part's name and its
//! neighbours' on every part. We do not use the alternative, PDF 1.6's `UserUnit`
//! (one page with bigger units): readers that ignore it, such as poppler (`pdfinfo`,
//! `pdftoppm` and the Linux viewers built on it), show and print the page scaled
//! down, and a pattern printed at the wrong scale is worse than none, while parts
//! of a roll at 1:1 print correctly everywhere and a copy shop prints each as one
//! length of roll. The SVG has no such limit and stays one sheet. The SVG names the same font. The DXF
//! is written by hand ([`dxf`]): AAMA files are plain R12 (`AC1009`), a small text
//! format without handles, and the `dxf` crate writes newer versions' structure
//! and a creation time into every file, which would break byte-identical output.
//! [`read_dxf`] reads such files back for the tests.
//!
//! The module is behind the `print` cargo feature (on by default) for its one
//! dependency, `pdf-writer`.

pub mod dxf;
pub mod geom;
mod grade;
mod inner;
mod pdf;
mod piece;
pub mod sheet;
mod svg;
mod types;

#[cfg(test)]
mod tests;

pub use dxf::{DxfBlock, DxfDrawing, DxfEntity, read_dxf};
pub use grade::{SIZE_RUN_FILE_NAMES, size_run_files};
pub use piece::{CURVE_STEP, GATHER_RATIO, MATCH_SPACING, stitch_fractions};
pub use types::NOTCH_LENGTH;

pub use types::{Cut, EdgeSeam, Notch, Paper, Piece, PrintOptions};

use crate::error::Result;
use crate::pattern::Pattern;

/// The pattern pieces of `p`.
///
/// ```
/// use garmentcode::fabricate::{Cut, PrintOptions, pieces};
/// use garmentcode::{Arena, EdgeSeq, PartExt, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges);
/// let pattern = PartExt::assemble(&panel, &mut a, "demo")?;
/// let ps = pieces(&pattern, &PrintOptions::default())?;
/// assert_eq!((ps.len(), ps[0].cut), (1, Cut::One));
/// // A 20 × 30 rectangle with a 1 cm allowance all round cuts 22 × 32.
/// let b = garmentcode::fabricate::geom::Rect::of(ps[0].cut_line.iter().copied());
/// assert!((b.size() - Vec2::new(22.0, 32.0)).length() < 1e-9);
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn pieces(p: &Pattern, opts: &PrintOptions) -> Result<Vec<Piece>> {
    opts.check()?;
    piece::build(p, opts)
}

/// Names of the files [`files`] writes, in its order.
pub const FILE_NAMES: [&str; 6] =
    ["pattern-tiled.pdf", "pattern-sheet.pdf", "pattern-sheet.svg", "pattern.dxf", "cutting-layout.svg", "cutting-layout.txt"];

/// Every printable file of `p`: name and bytes, in the order of [`FILE_NAMES`].
pub fn files(p: &Pattern, opts: &PrintOptions) -> Result<Vec<(String, Vec<u8>)>> {
    let pieces = pieces(p, opts)?;
    let sheet = sheet::one_sheet(&pieces, opts);
    let layout = sheet::cutting_layout(&pieces, opts.fabric_width);
    let bytes = [
        pdf::tiled(&sheet, &pieces, opts),
        pdf::one_sheet(&sheet),
        svg::sheet(&sheet).into_bytes(),
        dxf::write(&pieces, &sheet, opts).into_bytes(),
        svg::cutting(&layout, &pieces, opts).into_bytes(),
        sheet::cutting_report(&layout, &pieces, opts).into_bytes(),
    ];
    Ok(FILE_NAMES.iter().map(|n| n.to_string()).zip(bytes).collect())
}
