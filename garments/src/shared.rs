//! Types several garment modules share: the options components take instead of
//! booleans, and the values of a bodice half that its collar and sleeve follow. Every
//! module may depend on this one; it depends on none of them (but the design).

use crate::design::{self, Design};

/// Loose or fitted cut (shirts and waistbands).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// Loose: a t-shirt block, a straight band.
    Loose,
    /// Fitted: darted bodice panels, a band following the body.
    Fitted,
}

/// Front or back of the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Front.
    Front,
    /// Back.
    Back,
}

/// Values a bodice half derives from its design and its torso panels (cm), which
/// its neckline, collar and armholes follow.
#[derive(Clone, Copy, Debug)]
pub struct Resolved {
    /// Armhole height.
    pub connecting_width: f64,
    /// Neckline width.
    pub collar_width: f64,
    /// Front neckline depth at the shoulder line.
    pub fc_depth: f64,
    /// Back neckline depth at the shoulder line.
    pub bc_depth: f64,
    /// Front depth below the shoulder slope (strapless crop).
    pub f_strapless_depth: f64,
    /// Back depth below the shoulder slope.
    pub b_strapless_depth: f64,
}

/// How a bottom garment is built beyond its parameter group. The default builds it as
/// the design describes it; godet and tiered skirts, and a fitted top, change it.
///
/// ```
/// use garments::shared::BottomOptions;
///
/// // The second tier of a tiered skirt: its own length, no slits, no waist gathers.
/// let tier = BottomOptions { tag: "1".into(), length: Some(30.0), without_slits: true, without_gathers: true, ..Default::default() };
/// assert_eq!(tier.name("skirt_front"), "skirt_front_1");
/// assert_eq!(BottomOptions::default().name("skirt_front"), "skirt_front");
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BottomOptions {
    /// Suffix of the panel names (`skirt_front_<tag>`), for the tiers of a tiered
    /// skirt; none when empty.
    pub tag: String,
    /// Length instead of the one the group gives, cm.
    pub length: Option<f64>,
    /// Rise instead of the group's (a fitted top puts the bottom at the natural waist).
    pub rise: Option<f64>,
    /// Leave out the slits and hem cuts (the base of godet and tiered skirts).
    pub without_slits: bool,
    /// Leave out the waist gathers (the lower tiers of a tiered skirt).
    pub without_gathers: bool,
    /// Pleats at the waist of a two-panel skirt, front and back
    /// (`design.extension.pleats`).
    pub pleats: Option<[Pleating; 2]>,
    /// Ease of fitted skirts at the hips, cm of circumference (`design.extension.fit.hip_ease`).
    pub hip_ease: f64,
}

impl BottomOptions {
    /// Only a rise instead of the group's.
    pub fn at_rise(rise: Option<f64>) -> BottomOptions {
        BottomOptions { rise, ..BottomOptions::default() }
    }

    /// A panel's name with the tag.
    pub fn name(&self, base: &str) -> String {
        if self.tag.is_empty() { base.to_string() } else { format!("{base}_{}", self.tag) }
    }
}

/// Symmetric or asymmetric circle skirt.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Symmetry {
    /// Front and back are sectors of the same circle.
    Symmetric,
    /// A full circle, shorter in front.
    Asymmetric,
}

/// The parameter groups of the skirts that godet and tiered skirts are made of.
#[derive(Clone, Copy, Debug)]
pub struct SkirtGroups<'a> {
    /// Two-panel skirt.
    pub skirt: &'a design::Skirt,
    /// Circle skirts.
    pub flare_skirt: &'a design::FlareSkirt,
    /// Pencil skirt.
    pub pencil_skirt: &'a design::PencilSkirt,
}

impl<'a> SkirtGroups<'a> {
    /// The design's skirt groups.
    pub fn of(d: &'a Design) -> SkirtGroups<'a> {
        SkirtGroups { skirt: &d.skirt, flare_skirt: &d.flare_skirt, pencil_skirt: &d.pencil_skirt }
    }
}

/// The body lengths a panel's top and bottom interfaces are gathered to (the seam
/// they are sewn to); none: not gathered.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GatherTo {
    /// Length the top interface is gathered to.
    pub top: Option<f64>,
    /// Length the bottom interface is gathered to.
    pub bottom: Option<f64>,
}

impl GatherTo {
    /// Not gathered.
    pub const NONE: GatherTo = GatherTo { top: None, bottom: None };

    /// Only the top, to `length`.
    pub fn top(length: f64) -> GatherTo {
        GatherTo { top: Some(length), bottom: None }
    }

    /// Top and bottom, both to `length`.
    pub fn both(length: f64) -> GatherTo {
        GatherTo { top: Some(length), bottom: Some(length) }
    }
}

/// One or two darts on each side of a waist.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Darts {
    /// One dart.
    Single,
    /// Two darts, the outer one shorter.
    Double,
}

/// Pleats laid into a skirt panel's waist (see [`garmentcode::inner::pleats`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pleating {
    /// Knife or box pleats.
    pub kind: garmentcode::inner::PleatKind,
    /// How many on the panel.
    pub count: usize,
    /// Depth of each fold, cm.
    pub depth: f64,
}

impl Pleating {
    /// Waist width the pleats take in.
    pub fn intake(&self) -> f64 {
        let folds = if self.kind == garmentcode::inner::PleatKind::BoxPleat { 2.0 } else { 1.0 };
        self.count as f64 * 2.0 * folds * self.depth
    }
}
