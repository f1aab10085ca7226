//! The design space of the garment configurator: every parameter with its type,
//! range or options, default and sampling probability, as in the reference's
//! default design file. `Design::design_space()` is the schema; design files in the
//! reference's YAML format read into [`Design`].

use garmentcode::{Choice, Params};

/// Upper garment choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum UpperKind {
    /// Fitted bodice with darts.
    FittedShirt,
    /// Loose shirt (t-shirt block).
    Shirt,
}

/// Waistband choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum WaistbandKind {
    /// Straight (rectangular) band.
    StraightWB,
    /// Curved band following the body (yoke).
    FittedWB,
}

/// Bottom garment choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum BottomKind {
    /// Circle skirt.
    SkirtCircle,
    /// Circle skirt, shorter in front.
    AsymmSkirtCircle,
    /// Skirt with triangular inserts in the hem.
    GodetSkirt,
    /// Trousers.
    Pants,
    /// Two-panel skirt.
    Skirt2,
    /// Skirt of many gores.
    SkirtManyPanels,
    /// Fitted pencil skirt.
    PencilSkirt,
    /// Tiered skirt.
    SkirtLevels,
}

/// Half-neckline shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum NeckShape {
    /// Round neckline (half of a circular arc).
    CircleNeckHalf,
    /// S-shaped cubic neckline.
    CurvyNeckHalf,
    /// V neckline.
    VNeckHalf,
    /// Square neckline.
    SquareNeckHalf,
    /// Trapezoid neckline.
    TrapezoidNeckHalf,
    /// Circular arc of a given angle.
    CircleArcNeckHalf,
    /// Quadratic Bézier neckline.
    Bezier2NeckHalf,
}

/// Collar components.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum CollarStyle {
    /// Turtle neck band.
    Turtle,
    /// Simple lapel.
    SimpleLapel,
    /// Two-panel hood.
    Hood2Panels,
}

/// Armhole shapes (sleeveless designs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum ArmholeShape {
    /// Square cut-out.
    ArmholeSquare,
    /// Angled cut-out.
    ArmholeAngle,
    /// Curved (Bézier) cut-out.
    ArmholeCurve,
}

/// Cuff styles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum CuffKind {
    /// Straight band.
    CuffBand,
    /// Flared skirt-like cuff.
    CuffSkirt,
    /// Band with a flared skirt below it.
    CuffBandSkirt,
}

/// Base skirt of a godet skirt.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum GodetBase {
    /// Two-panel skirt.
    Skirt2,
    /// Pencil skirt.
    PencilSkirt,
}

/// Decorative side cut of a pencil skirt.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum SideCut {
    /// Sun-like rays.
    Sun,
    /// The SIGGRAPH logo.
    #[allow(non_camel_case_types)]
    SIGGRAPH_logo,
}

/// Base (top tier) of a tiered skirt.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum LevelsBase {
    /// Two-panel skirt.
    Skirt2,
    /// Pencil skirt.
    PencilSkirt,
    /// Circle skirt.
    SkirtCircle,
    /// Asymmetric circle skirt.
    AsymmSkirtCircle,
}

/// Tiers of a tiered skirt.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum LevelKind {
    /// Two-panel skirt.
    Skirt2,
    /// Circle skirt.
    SkirtCircle,
    /// Asymmetric circle skirt.
    AsymmSkirtCircle,
}

/// A whole garment design.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Design {
    /// Which components the garment has.
    pub meta: Meta,
    /// Waistband.
    pub waistband: Waistband,
    /// Upper garment body.
    pub shirt: Shirt,
    /// Necklines and collars.
    pub collar: Collar,
    /// Sleeves (the right one, and the left one of symmetric tops).
    pub sleeve: Sleeve,
    /// The left side of asymmetric tops.
    pub left: Left,
    /// Two-panel skirt.
    pub skirt: Skirt,
    /// Circle and many-panel skirts.
    #[param(rename = "flare-skirt")]
    pub flare_skirt: FlareSkirt,
    /// Godet skirt.
    #[param(rename = "godet-skirt")]
    pub godet_skirt: GodetSkirt,
    /// Pencil skirt.
    #[param(rename = "pencil-skirt")]
    pub pencil_skirt: PencilSkirt,
    /// Tiered skirt.
    #[param(rename = "levels-skirt")]
    pub levels_skirt: LevelsSkirt,
    /// Trousers.
    pub pants: Pants,
    /// Past the reference's language (patch pockets, pleats, diamond darts, folded
    /// cuffs and collars, one-piece sleeves, hip ease): all off by default and left out of this design space,
    /// which is the reference's; [`extended_design_space`] adds them.
    #[param(skip)]
    pub extension: Extension,
}

/// The reference's design space followed by the [`Extension`] parameters (under
/// `extension.`): what design files are read with, and what `sample --extended`
/// draws from. The reference's parameters come first, in the same order, so a
/// sampler draws the same values for them whichever of the two spaces it uses.
pub fn extended_design_space() -> garmentcode::DesignSpace {
    use garmentcode::Params;
    let mut params = Design::design_space().params().to_vec();
    Extension::describe("extension", &mut params);
    garmentcode::DesignSpace::new(params)
}

/// The space a design is written with: the reference's, or the extended one when
/// the design sets any [`Extension`] parameter (so that a design within the
/// reference's space is written as before).
pub fn space_of(design: &Design) -> garmentcode::DesignSpace {
    use garmentcode::Params;
    if design.extension == Extension::defaults() { Design::design_space() } else { extended_design_space() }
}

/// Constructs past the reference's language (issue 25), each off by default.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Extension {
    /// Patch pockets sewn on top.
    pub pockets: Pockets,
    /// Pleats at the waist of two-panel skirts.
    pub pleats: Pleats,
    /// Diamond darts in loose shirts (a dress fitted without a waist seam's darts).
    pub darts: DiamondDarts,
    /// Band cuffs twice as long, folded along the middle.
    pub cuff: FoldedCuff,
    /// Turtle necks twice as high, folded along the middle.
    pub collar: FoldedCollar,
    /// Sleeves of one panel, folded along the top of the arm.
    pub sleeve: OnePieceSleeve,
    /// Ease of fitted skirts.
    pub fit: Fit,
}

/// Patch pockets.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Pockets {
    /// A chest pocket on shirts.
    #[param(default = false, prob = 0.8)]
    pub shirt: bool,
    /// Two hip pockets on skirts (on the front panel, the top tier's of tiered skirts,
    /// the gores either side of the front of many-panel skirts).
    #[param(default = false, prob = 0.8)]
    pub skirt: bool,
    /// A pocket on each front leg of trousers.
    #[param(default = false, prob = 0.8)]
    pub pants: bool,
    /// Pocket width, cm (at most 45% of the panel it sits on); its height is 1.15 times this.
    #[param(range = 8..=20, default = 13, prob = 0.5)]
    pub width: f64,
}

/// Pleat styles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum PleatStyle {
    /// Knife pleats, all folded the same way.
    KnifePleats,
    /// Box pleats.
    BoxPleats,
    /// Box pleats in front, knife pleats at the back.
    BoxAndKnife,
}

/// Waist pleats of two-panel skirts (the panel is widened by what they take in).
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Pleats {
    /// Pleat style (none: no pleats).
    #[param(default = None, prob = 0.7)]
    pub style: Option<PleatStyle>,
    /// Pleats on each of the front and back panels.
    #[param(range = 1..=8, default = 4, prob = 0.5)]
    pub count: i64,
    /// Depth of each fold, cm.
    #[param(range = 1..=4, default = 2.5, prob = 0.5)]
    pub depth: f64,
}

/// Diamond darts.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct DiamondDarts {
    /// A diamond dart in each front and back panel of loose shirts.
    #[param(default = false, prob = 0.8)]
    pub diamond: bool,
    /// Width of each dart at its widest, cm.
    #[param(range = 1..=5, default = 3, prob = 0.5)]
    pub width: f64,
}

/// Folded cuffs.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct FoldedCuff {
    /// Band cuffs doubled: twice as long, folded back inside along the middle.
    #[param(default = false, prob = 0.8)]
    pub double: bool,
}

/// Folded collars.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct FoldedCollar {
    /// Turtle necks doubled: twice as high, folded down along the middle.
    #[param(default = false, prob = 0.8)]
    pub folded: bool,
}

/// One-piece sleeves.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct OnePieceSleeve {
    /// Each sleeve one panel, front and back joined along a fold line over the top of
    /// the arm instead of a seam (sleeves with a straight top: not with a standing shoulder).
    #[param(default = false, prob = 0.8)]
    pub one_piece: bool,
}

/// Ease of fitted skirts.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Fit {
    /// Ease of pencil skirts at the hips, cm of circumference, shared by the front and
    /// back panels (the reference's pencil skirt has none: it is the body's hips).
    #[param(range = 0..=10, default = 0, prob = 0.5)]
    pub hip_ease: f64,
}

/// Which components the garment has.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Meta {
    /// Upper garment (none: no top).
    #[param(default = None, prob = 0.3)]
    pub upper: Option<UpperKind>,
    /// Waistband (none: no band).
    #[param(default = None, prob = 0.5)]
    pub wb: Option<WaistbandKind>,
    /// Bottom garment (none: no skirt or trousers).
    #[param(default = None, prob = 0.3)]
    pub bottom: Option<BottomKind>,
}

/// Waistband.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Waistband {
    /// Ease: band circumference as a multiple of the body's waist and hips.
    #[param(range = 1.0..=2, default = 1.0, prob = 0.7)]
    pub waist: f64,
    /// Band height as a fraction of the waist-to-hip distance.
    #[param(range = 0.1..=1.0, default = 0.2, prob = 0.5)]
    pub width: f64,
}

/// Upper garment body.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Shirt {
    /// Strapless top (fitted tops only).
    #[param(default = false, prob = 0.8)]
    pub strapless: bool,
    /// Length as a multiple of the back waist length (loose shirts).
    #[param(range = 0.5..=3.5, default = 1.2, prob = 0.7)]
    pub length: f64,
    /// Width as a multiple of the bust (loose shirts).
    #[param(range = 1.0..=1.3, default = 1.05, prob = 0.4)]
    pub width: f64,
    /// Hem width relative to the chest width (loose shirts).
    #[param(range = 0.7..=1.6, default = 1.0, prob = 0.4)]
    pub flare: f64,
}

/// Necklines and collars.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Collar {
    /// Front neckline shape.
    #[param(default = CircleNeckHalf, prob = 0.4)]
    pub f_collar: NeckShape,
    /// Back neckline shape.
    #[param(default = CircleNeckHalf, prob = 0.8)]
    pub b_collar: NeckShape,
    /// Neckline width: 0 = the neck width, 1 = up to the shoulders, negative = narrower than the neck.
    #[param(range = -0.5..=1, default = 0.2, prob = 0.4)]
    pub width: f64,
    /// Front neckline depth as a fraction of the bust-line depth.
    #[param(range = 0.3..=2, default = 0.4, prob = 0.3)]
    pub fc_depth: f64,
    /// Back neckline depth as a fraction of the bust-line depth.
    #[param(range = 0..=2, default = 0, prob = 0.4)]
    pub bc_depth: f64,
    /// Angle of trapezoid and arc front necklines, degrees.
    #[param(range = 70..=110, default = 95)]
    pub fc_angle: i64,
    /// Angle of trapezoid and arc back necklines, degrees.
    #[param(range = 70..=110, default = 95)]
    pub bc_angle: i64,
    /// Control point x of a Bézier front neckline.
    #[param(range = 0.05..=0.95, default = 0.3, prob = 0.4)]
    pub f_bezier_x: f64,
    /// Control point y of a Bézier front neckline.
    #[param(range = 0.05..=0.95, default = 0.55, prob = 0.4)]
    pub f_bezier_y: f64,
    /// Control point x of a Bézier back neckline.
    #[param(range = 0.05..=0.95, default = 0.15, prob = 0.4)]
    pub b_bezier_x: f64,
    /// Control point y of a Bézier back neckline.
    #[param(range = 0.05..=0.95, default = 0.1, prob = 0.4)]
    pub b_bezier_y: f64,
    /// Mirror the curvature of the front neckline.
    #[param(default = false, prob = 0.8)]
    pub f_flip_curve: bool,
    /// Mirror the curvature of the back neckline.
    #[param(default = false, prob = 0.8)]
    pub b_flip_curve: bool,
    /// Collar component.
    pub component: CollarComponent,
}

/// Collar component.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct CollarComponent {
    /// Collar style (none: just the neckline).
    #[param(default = None, prob = 0.6)]
    pub style: Option<CollarStyle>,
    /// Collar height, cm.
    #[param(range = 2..=8, default = 7)]
    pub depth: i64,
    /// Standing (band) back of the lapel.
    #[param(default = false)]
    pub lapel_standing: bool,
    /// Hood depth relative to the neckline width.
    #[param(range = 1..=2, default = 1, prob = 0.6)]
    pub hood_depth: f64,
    /// Hood length relative to the head.
    #[param(range = 1..=1.5, default = 1, prob = 0.6)]
    pub hood_length: f64,
}

/// Sleeves (the right one, and both of symmetric tops).
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Sleeve {
    /// No sleeve.
    #[param(default = true, prob = 0.7)]
    pub sleeveless: bool,
    /// Armhole cut of sleeveless designs.
    #[param(default = ArmholeCurve, prob = 0.7)]
    pub armhole_shape: ArmholeShape,
    /// Sleeve length as a fraction of the arm.
    #[param(range = 0.1..=1.15, default = 0.3)]
    pub length: f64,
    /// Armhole depth: extra fraction of the armscye depth.
    #[param(range = 0..=2, default = 0.2, prob = 0.6)]
    pub connecting_width: f64,
    /// Width of the sleeve end relative to the armhole.
    #[param(range = 0.2..=2, default = 1.0, prob = 0.4)]
    pub end_width: f64,
    /// Rest angle of the sleeve, degrees.
    #[param(range = 10..=50, default = 10)]
    pub sleeve_angle: i64,
    /// Direction of the sleeve opening: towards vertical (positive) or horizontal (negative).
    #[param(range = -0.9..=0.8, default = 0.1, prob = 1.0)]
    pub opening_dir_mix: f64,
    /// Square "standing" shoulder.
    #[param(default = false, prob = 0.8)]
    pub standing_shoulder: bool,
    /// Length of the standing shoulder, cm.
    #[param(range = 4..=10, default = 5.0)]
    pub standing_shoulder_len: f64,
    /// Gathering of the sleeve cap.
    #[param(range = 1..=2, default = 1, prob = 0.4)]
    pub connect_ruffle: f64,
    /// Smoothing of angled armholes.
    #[param(range = 0.1..=0.4, default = 0.25, prob = 0.8)]
    pub smoothing_coeff: f64,
    /// Cuff.
    pub cuff: Cuff,
}

/// Cuff of a sleeve or a trouser leg (as on the right sleeve; the left sleeve and
/// the trousers override some of it).
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Cuff {
    /// Cuff style (none: no cuff).
    #[param(default = None)]
    pub r#type: Option<CuffKind>,
    /// Gathering of the garment end into the cuff.
    #[param(range = 1..=3, default = 1)]
    pub top_ruffle: f64,
    /// Cuff length as a fraction of the limb.
    #[param(range = 0.05..=0.9, default = 0.1, prob = 0.7)]
    pub cuff_len: f64,
    /// Fraction of the cuff that is skirt (band-and-skirt cuffs).
    #[param(range = 0.1..=0.9, default = 0.5, prob = 0.5)]
    pub skirt_fraction: f64,
    /// Flare of the cuff skirt.
    #[param(range = 1..=2, default = 1.2)]
    pub skirt_flare: f64,
    /// Gathering of the cuff skirt.
    #[param(range = 1..=1.5, default = 1.0, prob = 0.3)]
    pub skirt_ruffle: f64,
}

/// The left side of asymmetric tops.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Left {
    /// Design the left side separately.
    #[param(default = false, prob = 0.8)]
    pub enable_asym: bool,
    /// Left body (its length is the right side's).
    #[param(length(skip), strapless(doc = "Strapless left side (fitted tops only)."), width(default = 1.0))]
    pub shirt: Shirt,
    /// Left neckline (its depths are the right side's; no collar component).
    #[param(
        width(range = 0..=1, default = 0.5, doc = "Neckline width (0 = the neck width, 1 = up to the shoulders)."),
        fc_depth(skip),
        bc_depth(skip),
        f_bezier_x(default = 0.5),
        f_bezier_y(default = 0.3, prob = None),
        b_bezier_x(default = 0.5),
        b_bezier_y(default = 0.3, prob = None),
        component(skip)
    )]
    pub collar: Collar,
    /// Left sleeve.
    #[param(opening_dir_mix(default = 0.2), cuff(top_ruffle(range = 1..=2)))]
    pub sleeve: Sleeve,
}

/// Two-panel skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Skirt {
    /// Length below the hips as a fraction of the leg.
    #[param(range = -0.2..=0.95, default = 0.2)]
    pub length: f64,
    /// Waist position: 1 = natural waist, smaller = lower.
    #[param(range = 0.5..=1, default = 1, prob = 0.3)]
    pub rise: f64,
    /// Gathering at the waist.
    #[param(range = 1..=2, default = 1.3, prob = 0.3)]
    pub ruffle: f64,
    /// Side slits at the hem.
    #[param(range = 0..=0.9, default = 0, prob = 0.3)]
    pub bottom_cut: f64,
    /// Extra hem width per side, cm.
    #[param(range = 0..=20, default = 0, prob = 0.5)]
    pub flare: i64,
}

/// Circle and many-panel skirts.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct FlareSkirt {
    /// Length below the hips as a fraction of the leg.
    #[param(range = -0.2..=0.95, default = 0.2)]
    pub length: f64,
    /// Waist position: 1 = natural waist, smaller = lower.
    #[param(range = 0.5..=1, default = 1, prob = 0.3)]
    pub rise: f64,
    /// Fullness: fraction of a full circle.
    #[param(range = 0.1..=1.95, default = 0.75)]
    pub suns: f64,
    /// Many-panel skirt.
    #[param(rename = "skirt-many-panels")]
    pub skirt_many_panels: SkirtManyPanels,
    /// Asymmetric circle skirt.
    pub asymm: Asymm,
    /// Cut in the hem.
    pub cut: Cut,
}

/// Many-panel skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct SkirtManyPanels {
    /// Number of gores.
    #[param(range = 4..=15, default = 4)]
    pub n_panels: i64,
    /// Hem curvature of each gore.
    #[param(options = [-0.35, -0.25, -0.15, 0, 0.15, 0.25, 0.35, 0.45], default = 0)]
    pub panel_curve: f64,
}

/// Asymmetric circle skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Asymm {
    /// Front length relative to the back.
    #[param(range = 0.1..=0.9, default = 0.5, prob = 0.5)]
    pub front_length: f64,
}

/// Cut in the hem of a circle skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Cut {
    /// Add a cut.
    #[param(default = false, prob = 0.6)]
    pub add: bool,
    /// Cut depth as a fraction of the skirt length.
    #[param(range = 0.05..=0.95, default = 0.5, prob = 0.6)]
    pub depth: f64,
    /// Cut width as a fraction of the skirt length.
    #[param(range = 0.05..=0.4, default = 0.1)]
    pub width: f64,
    /// Position along the hem; the sign picks front (+) or back (−).
    #[param(range = -1..=1, default = -0.5)]
    pub place: f64,
}

/// Godet skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct GodetSkirt {
    /// Base skirt.
    #[param(default = PencilSkirt, prob = 0.7)]
    pub base: GodetBase,
    /// Insert width, cm.
    #[param(range = 10..=50, default = 15)]
    pub insert_w: i64,
    /// Insert depth, cm.
    #[param(range = 10..=50, default = 20)]
    pub insert_depth: i64,
    /// Number of inserts.
    #[param(options = [4, 6, 8, 10, 12], default = 4)]
    pub num_inserts: i64,
    /// Distance between cuts, cm.
    #[param(range = 0..=10, default = 5)]
    pub cuts_distance: i64,
}

/// Pencil skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct PencilSkirt {
    /// Length below the hips as a fraction of the leg.
    #[param(range = 0.2..=0.95, default = 0.4)]
    pub length: f64,
    /// Waist position: 1 = natural waist, smaller = lower.
    #[param(range = 0.5..=1, default = 1, prob = 0.3)]
    pub rise: f64,
    /// Hem width relative to the hips.
    #[param(range = 0.6..=1.5, default = 1.0, prob = 0.3)]
    pub flare: f64,
    /// Tilt of the hem, degrees.
    #[param(range = -30..=30, default = 0, prob = 0.7)]
    pub low_angle: i64,
    /// Front slit as a fraction of the length.
    #[param(range = 0..=0.9, default = 0, prob = 0.4)]
    pub front_slit: f64,
    /// Back slit as a fraction of the length.
    #[param(range = 0..=0.9, default = 0, prob = 0.4)]
    pub back_slit: f64,
    /// Left side slit as a fraction of the side.
    #[param(range = 0..=0.9, default = 0, prob = 0.6)]
    pub left_slit: f64,
    /// Right side slit as a fraction of the side.
    #[param(range = 0..=0.9, default = 0, prob = 0.6)]
    pub right_slit: f64,
    /// Decorative side cut (none: no cut).
    #[param(default = None, prob = 1.0, null_option = false)]
    pub style_side_cut: Option<SideCut>,
}

/// Tiered skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct LevelsSkirt {
    /// Top tier.
    #[param(default = PencilSkirt)]
    pub base: LevelsBase,
    /// Lower tiers.
    #[param(default = Skirt2)]
    pub level: LevelKind,
    /// Number of lower tiers.
    #[param(range = 1..=5, default = 1)]
    pub num_levels: i64,
    /// Gathering of each tier into the one above.
    #[param(range = 1..=1.7, default = 1.0)]
    pub level_ruffle: f64,
    /// Total length as a fraction of the leg.
    #[param(range = 0.2..=0.95, default = 0.5)]
    pub length: f64,
    /// Waist position: 1 = natural waist, smaller = lower.
    #[param(range = 0.5..=1, default = 1, prob = 0.3)]
    pub rise: f64,
    /// Fraction of the length taken by the top tier.
    #[param(range = 0.2..=0.8, default = 0.5)]
    pub base_length_frac: f64,
}

/// Trousers.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Pants {
    /// Length as a fraction of the leg.
    #[param(range = 0.2..=0.9, default = 0.3)]
    pub length: f64,
    /// Width of the seat (crotch extension).
    #[param(range = 1.0..=1.5, default = 1.0, prob = 0.5)]
    pub width: f64,
    /// Flare of the legs.
    #[param(range = 0.5..=1.2, default = 1.0, prob = 0.3)]
    pub flare: f64,
    /// Waist position: 1 = natural waist, smaller = lower.
    #[param(range = 0.5..=1, default = 1.0, prob = 0.3)]
    pub rise: f64,
    /// Cuffs.
    #[param(
        r#type(prob = 0.5),
        top_ruffle(range = 1..=2),
        cuff_len(prob = 0.3),
        skirt_fraction(prob = None),
        skirt_ruffle(prob = None)
    )]
    pub cuff: Cuff,
}
