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
//!   roll width) for a plotter or a copy shop;
//! - `pattern.dxf`: DXF-AAMA (R12, millimetres), one block per piece;
//! - `cutting-layout.svg` and `cutting-layout.txt`: the pieces on a fabric width,
//!   each as many times as it is cut, and the length of fabric needed.
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
//! has built in and which needs no embedding. The SVG names the same font. The DXF
//! is written by hand ([`dxf`]): AAMA files are plain R12 (`AC1009`), a small text
//! format without handles, and the `dxf` crate writes newer versions' structure
//! and a creation time into every file, which would break byte-identical output.
//! [`read_dxf`] reads such files back for the tests.
//!
//! The module is behind the `print` cargo feature (on by default) for its one
//! dependency, `pdf-writer`.

pub mod dxf;
pub mod geom;
mod pdf;
mod piece;
pub mod sheet;
mod svg;

#[cfg(test)]
mod tests;

pub use dxf::{DxfBlock, DxfDrawing, DxfEntity, read_dxf};
pub use piece::{CURVE_STEP, GATHER_RATIO, MATCH_SPACING, NOTCH_LENGTH, stitch_fractions};

use crate::error::{Error, Result};
use crate::math::Vec2;
use crate::pattern::Pattern;
use geom::Xf;

/// A seam-allowance override for one panel, or one edge of it.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeSeam {
    /// Panel name.
    pub panel: String,
    /// Edge index; `None` for every edge of the panel.
    pub edge: Option<usize>,
    /// Allowance in cm (0 for none, e.g. a fold).
    pub cm: f64,
}

impl EdgeSeam {
    /// Parse `PANEL=CM` or `PANEL:EDGE=CM`.
    ///
    /// ```
    /// use garmentcode::fabricate::EdgeSeam;
    /// assert_eq!(EdgeSeam::parse("front:2=3").unwrap(), EdgeSeam { panel: "front".into(), edge: Some(2), cm: 3.0 });
    /// assert_eq!(EdgeSeam::parse("back=0").unwrap().edge, None);
    /// assert!(EdgeSeam::parse("back").is_err());
    /// ```
    pub fn parse(s: &str) -> std::result::Result<EdgeSeam, String> {
        let (target, cm) = s.rsplit_once('=').ok_or_else(|| format!("'{s}': expected PANEL=CM or PANEL:EDGE=CM"))?;
        let cm: f64 = cm.trim().parse().map_err(|_| format!("'{s}': '{cm}' is not a number of cm"))?;
        if !(cm.is_finite() && cm >= 0.0) {
            return Err(format!("'{s}': the allowance must be a non-negative number of cm"));
        }
        let (panel, edge) = match target.rsplit_once(':') {
            Some((p, e)) => (p, Some(e.trim().parse().map_err(|_| format!("'{s}': '{e}' is not an edge index"))?)),
            None => (target, None),
        };
        Ok(EdgeSeam { panel: panel.trim().to_string(), edge, cm })
    }
}

/// Paper for the printed pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Paper {
    /// ISO A4 pages (tiled).
    A4,
    /// US Letter pages (tiled).
    Letter,
    /// One ISO A0 sheet (84.1 cm wide).
    A0,
    /// A plotter roll of this width in cm.
    Roll(f64),
}

impl Paper {
    /// Parse `a4`, `letter`, `a0` or `roll:WIDTH_CM`.
    ///
    /// ```
    /// use garmentcode::fabricate::Paper;
    /// assert_eq!(Paper::parse("roll:91.4").unwrap(), Paper::Roll(91.4));
    /// assert!(Paper::parse("a3").is_err());
    /// ```
    pub fn parse(s: &str) -> std::result::Result<Paper, String> {
        match s.to_ascii_lowercase().as_str() {
            "a4" => Ok(Paper::A4),
            "letter" => Ok(Paper::Letter),
            "a0" => Ok(Paper::A0),
            other => match other.strip_prefix("roll:").map(str::parse::<f64>) {
                Some(Ok(w)) if w.is_finite() && w >= 30.0 => Ok(Paper::Roll(w)),
                Some(_) => Err(format!("'{s}': a roll width is a number of cm, at least 30")),
                None => Err(format!("'{s}': expected a4, letter, a0 or roll:WIDTH_CM")),
            },
        }
    }

    /// Page size of a home printer's sheet (cm): the paper itself for A4 and
    /// Letter, A4 otherwise.
    pub fn tile_page(self) -> Vec2 {
        match self {
            Paper::Letter => Vec2::new(21.59, 27.94),
            _ => Vec2::new(21.0, 29.7),
        }
    }

    /// Width of the one-sheet drawing (cm): the roll's width, A0's otherwise.
    pub fn sheet_width(self) -> f64 {
        match self {
            Paper::Roll(w) => w,
            _ => 84.1,
        }
    }
}

/// What to print and how.
#[derive(Clone, Debug, PartialEq)]
pub struct PrintOptions {
    /// Seam allowance of every edge (cm).
    pub seam: f64,
    /// Allowance of hems (unstitched `lower_interface` edges), when different.
    pub hem: Option<f64>,
    /// Per-panel and per-edge overrides (an edge's beats its panel's).
    pub edge_seams: Vec<EdgeSeam>,
    /// Paper of the tiled PDF and width of the one-sheet.
    pub paper: Paper,
    /// Width of the fabric for the cutting layout (cm).
    pub fabric_width: f64,
    /// Garment name on the labels.
    pub garment: String,
    /// Size on the labels (the body's name).
    pub size: String,
}

impl Default for PrintOptions {
    fn default() -> Self {
        PrintOptions {
            seam: 1.0,
            hem: None,
            edge_seams: Vec::new(),
            paper: Paper::A4,
            fabric_width: 140.0,
            garment: "garment".into(),
            size: "unspecified".into(),
        }
    }
}

impl PrintOptions {
    fn check(&self) -> Result<()> {
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        if !ok(self.seam) || !self.hem.is_none_or(ok) {
            return Err(Error::Input("seam allowances must be non-negative numbers of cm".into()));
        }
        if !(self.fabric_width.is_finite() && self.fabric_width > 0.0) {
            return Err(Error::Input(format!("the fabric width must be a positive number of cm, not {}", self.fabric_width)));
        }
        Ok(())
    }
}

/// How many times a piece is cut.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cut {
    /// Once.
    One,
    /// Twice, the same way up.
    Two,
    /// Twice, the second mirrored (fabric doubled, or the piece flipped).
    MirroredPair,
    /// Once on a fold of the fabric (the piece is half of the cut shape).
    OnFold,
}

impl Cut {
    /// The cut list wording.
    pub fn text(self) -> &'static str {
        match self {
            Cut::One => "Cut 1",
            Cut::Two => "Cut 2",
            Cut::MirroredPair => "Cut 2 (mirrored pair)",
            Cut::OnFold => "Cut 1 on fold",
        }
    }
}

/// A notch: a slit from the cut line into the seam allowance.
#[derive(Clone, Debug, PartialEq)]
pub struct Notch {
    /// The point on the sew line it marks.
    pub sew: Vec2,
    /// Its end on the cut line.
    pub outer: Vec2,
    /// Its end inside the allowance.
    pub inner: Vec2,
    /// The panel edges (panel name, edge index) whose seams it marks.
    pub edges: Vec<(String, usize)>,
}

/// One pattern piece, in its own frame (cm, y up, grain along +y).
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// Name (its panel's).
    pub name: String,
    /// The panels it stands for, with the map from each panel's 2D coordinates into
    /// this frame (the second of a pair is mirrored when the pair is).
    pub panels: Vec<(String, Xf)>,
    /// How many to cut.
    pub cut: Cut,
    /// The sew line, closed.
    pub sew: Vec<Vec2>,
    /// The cut line, closed.
    pub cut_line: Vec<Vec2>,
    /// Notches.
    pub notches: Vec<Notch>,
    /// The grainline's two ends.
    pub grain: [Vec2; 2],
    /// The edge to place on the fold, when cut on the fold.
    pub fold: Option<[Vec2; 2]>,
    /// Internal lines (gathering marks).
    pub internal: Vec<Vec<Vec2>>,
    /// Where the first label line starts (left end of its baseline).
    pub label_at: Vec2,
    /// Height of the label text (cm).
    pub text_size: f64,
    /// Label lines: name, garment, size, cut count, grainline.
    pub labels: Vec<String>,
}

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
