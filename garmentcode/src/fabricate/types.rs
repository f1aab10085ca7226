//! The pattern pieces and the print options: the types of [`super`].

use super::geom::{self, Xf};
use crate::edge::Edge;
use crate::error::{Error, Result};
use crate::math::Vec2;

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
        if !(0.0..=MAX_ALLOWANCE).contains(&cm) {
            return Err(format!("'{s}': the allowance must be a number of cm from 0 to {MAX_ALLOWANCE}"));
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
                Some(Ok(w)) if (MIN_ROLL..=MAX_ROLL).contains(&w) => Ok(Paper::Roll(w)),
                Some(_) => Err(format!("'{s}': a roll width is a number of cm from {MIN_ROLL} to {MAX_ROLL}")),
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
    /// Refuse negative or non-finite allowances and widths, and labels longer than
    /// [`crate::io::MAX_NAME_CHARS`].
    pub(crate) fn check(&self) -> Result<()> {
        crate::io::check_name("the garment name", &self.garment)?;
        crate::io::check_name("the size", &self.size)?;
        let ok = |x: f64| (0.0..=MAX_ALLOWANCE).contains(&x);
        if !ok(self.seam) || !self.hem.is_none_or(ok) || !self.edge_seams.iter().all(|e| ok(e.cm)) {
            return Err(Error::Input(format!("seam allowances must be numbers of cm from 0 to {MAX_ALLOWANCE}")));
        }
        if !(self.fabric_width > 0.0 && self.fabric_width <= MAX_FABRIC_WIDTH) {
            return Err(Error::Input(format!(
                "the fabric width must be a number of cm above 0 and at most {MAX_FABRIC_WIDTH}, not {}",
                self.fabric_width
            )));
        }
        if let Paper::Roll(w) = self.paper
            && !(MIN_ROLL..=MAX_ROLL).contains(&w)
        {
            return Err(Error::Input(format!("a roll width is a number of cm from {MIN_ROLL} to {MAX_ROLL}, not {w}")));
        }
        Ok(())
    }
}

/// Largest seam allowance or hem, cm (wider is no allowance but a mistake, and would
/// make the drawings and layouts unbounded).
pub const MAX_ALLOWANCE: f64 = 20.0;

/// Narrowest plotter roll, cm.
pub const MIN_ROLL: f64 = 30.0;
/// Widest plotter roll, cm.
pub const MAX_ROLL: f64 = 1000.0;

/// Widest fabric for the cutting layout, cm.
pub const MAX_FABRIC_WIDTH: f64 = 1000.0;

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
    /// Internal lines (gathering marks; the format extension's darts, placement
    /// and pleat lines).
    pub internal: Vec<Vec<Vec2>>,
    /// Holes cut out of the piece (format extension), closed.
    pub cutouts: Vec<Vec<Vec2>>,
    /// Fold lines inside the piece (format extension: the AAMA mirror line).
    pub mirror_lines: Vec<Vec<Vec2>>,
    /// Drill holes (format extension: placement-line corners and dart points).
    pub drill_holes: Vec<Vec2>,
    /// Where the first label line starts (left end of its baseline).
    pub label_at: Vec2,
    /// Height of the label text (cm).
    pub text_size: f64,
    /// Label lines: name, garment, size, cut count, grainline.
    pub labels: Vec<String>,
}

/// Length of a notch slit into the seam allowance (cm).
pub const NOTCH_LENGTH: f64 = 0.6;

/// One panel in its grain frame (grain along +y, sew-line box from the origin).
pub(crate) struct Grained {
    /// The panel's edges in the grain frame.
    pub edges: Vec<Edge>,
    /// Local panel coordinates → grain frame.
    pub xf: Xf,
    /// The outline runs counter-clockwise.
    pub ccw: bool,
    /// Sew-line bounding box width.
    pub width: f64,
}

/// The slit of a notch at `at` whose outer end is the cut line's point nearest to
/// `at + reach`: [`NOTCH_LENGTH`] from the cut line inwards (at most to the sew line).
pub(super) fn slit(at: Vec2, reach: Vec2, cut: &[Vec2], edges: Vec<(String, usize)>) -> Notch {
    let outer = geom::nearest_on_closed(at + reach, cut);
    let len = (outer - at).length();
    let inward = (at - outer).normalize_or_zero();
    Notch { sew: at, outer, inner: outer + inward * NOTCH_LENGTH.min(len), edges }
}
