//! Bands: waistbands (straight and fitted) and cuffs (band, skirt, band with skirt).

use crate::circle_skirt::CircleArcPanel;
use crate::common::{v2, v3};
use crate::design::{self, CuffKind};
use crate::shared::{Fit, GatherTo};
use crate::skirt_paneled::SkirtPanel;
use garmentcode::math::lerp;
use garmentcode::slots::{Bottom, Left, Right, Top};
use garmentcode::{Arena, Body, Component, EdgeSeq, InterfaceId, PanelId, PartExt, Result, SlotExt, StitchRule};

/// A rectangle: waistband, cuff band, turtle-neck band, standing lapel back.
#[derive(Clone, Debug, Component)]
pub struct StraightBandPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Right short side.
    #[interface]
    pub right: InterfaceId,
    /// Top long side.
    #[interface]
    pub top: InterfaceId,
    /// Left short side.
    #[interface]
    pub left: InterfaceId,
    /// Bottom long side.
    #[interface]
    pub bottom: InterfaceId,
}

impl StraightBandPanel {
    /// A `width × depth` band whose long sides are gathered to `gather`.
    pub fn new(a: &mut Arena, name: &str, width: f64, depth: f64, gather: GatherTo) -> Result<StraightBandPanel> {
        let edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(0.0, depth), v2(width, depth), v2(width, 0.0)], true)?;
        let panel = a.panel_with_edges(name, edges.clone());
        let ruffle = |m: Option<f64>| m.map(|m| width / m).unwrap_or(1.0);
        let right = a.interface(panel, edges[0]);
        let top = a.interface_gathered(panel, edges[1], ruffle(gather.top))?.reverse(a, true);
        let left = a.interface(panel, edges[2]);
        let bottom = a.interface_gathered(panel, edges[3], ruffle(gather.bottom))?;
        panel.top_center_pivot(a);
        panel.center_x(a);
        Ok(StraightBandPanel { panel, right, top, left, bottom })
    }
}

/// Front or back panel of a waistband.
#[derive(Clone, Debug, Component)]
#[component(slots(Right, Top, Left, Bottom))]
pub enum BandPanel {
    /// Rectangle.
    Straight(StraightBandPanel),
    /// Annulus sector.
    Curved(CircleArcPanel),
}

impl BandPanel {
    fn panel(&self) -> PanelId {
        match self {
            BandPanel::Straight(p) => p.panel,
            BandPanel::Curved(p) => p.panel,
        }
    }
}

/// Waistband: two panels, front and back.
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::band_length)]
pub struct Waistband {
    /// Component name (`StraightWB` or `FittedWB`).
    pub name: String,
    /// Front panel `wb_front`.
    #[part]
    pub front: BandPanel,
    /// Back panel `wb_back`.
    #[part]
    pub back: BandPanel,
    /// Front bottom edge.
    #[interface]
    pub bottom_f: InterfaceId,
    /// Back bottom edge.
    #[interface]
    pub bottom_b: InterfaceId,
    /// Front top edge.
    #[interface]
    pub top_f: InterfaceId,
    /// Back top edge.
    #[interface]
    pub top_b: InterfaceId,
    /// Whole bottom edge.
    #[interface]
    pub bottom: InterfaceId,
    /// Whole top edge.
    #[interface]
    pub top: InterfaceId,
    /// Side seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl Waistband {
    /// A straight (loose) or curved (fitted) band from the `waistband` group, sitting
    /// on top of a bottom garment at `rise`.
    pub fn new(a: &mut Arena, body: &Body, d: &design::Waistband, rise: f64, fit: Fit) -> Result<Waistband> {
        let waist = d.waist * body.waist;
        let waist_back_frac = body.waist_back_width / body.waist;
        let hips = body.hips * d.waist;
        let hips_back_frac = body.hip_back_width / body.hips;
        let mut width = d.width;
        let mut rise = rise;
        if rise + width > 1.0 {
            rise = 1.0 - width;
        }
        let top_width = lerp(hips, waist, rise + width)?;
        let top_back_fraction = lerp(hips_back_frac, waist_back_frac, rise + width)?;
        width *= body.hips_line;
        let (front, back) = if fit == Fit::Loose {
            let back_width = top_width * top_back_fraction;
            let f =
                StraightBandPanel::new(a, "wb_front", top_width - back_width, width, GatherTo::both(body.waist - body.waist_back_width))?;
            let b = StraightBandPanel::new(a, "wb_back", back_width, width, GatherTo::both(body.waist_back_width))?;
            (BandPanel::Straight(f), BandPanel::Straight(b))
        } else {
            let bottom_width = lerp(hips, waist, rise)?;
            let bottom_back_fraction = lerp(hips_back_frac, waist_back_frac, rise)?;
            let m = body.waist - body.waist_back_width;
            let f = CircleArcPanel::from_all_length(
                a,
                "wb_front",
                width,
                top_width * (1.0 - top_back_fraction),
                bottom_width * (1.0 - bottom_back_fraction),
                GatherTo::both(m),
            )?;
            let m = body.waist_back_width;
            let b = CircleArcPanel::from_all_length(
                a,
                "wb_back",
                width,
                top_width * top_back_fraction,
                bottom_width * bottom_back_fraction,
                GatherTo::both(m),
            )?;
            (BandPanel::Curved(f), BandPanel::Curved(b))
        };
        let (fp, fright, ftop, fleft, fbottom) =
            (front.panel(), front.iface::<Right>(), front.iface::<Top>(), front.iface::<Left>(), front.iface::<Bottom>());
        let (bp, bright, btop, bleft, bbottom) =
            (back.panel(), back.iface::<Right>(), back.iface::<Top>(), back.iface::<Left>(), back.iface::<Bottom>());
        let level = body.derived().waist_level;
        fp.translate_by(a, v3(0.0, level, 20.0));
        bp.translate_by(a, v3(0.0, level, -15.0));
        let stitches = vec![StitchRule::new(a, fright, bright)?, StitchRule::new(a, fleft, bleft)?];
        let bottom = a.interface_from(&[fbottom, bbottom]);
        let top = a.interface_from(&[ftop, btop]);
        Ok(Waistband {
            name: match fit {
                Fit::Loose => "StraightWB",
                Fit::Fitted => "FittedWB",
            }
            .into(),
            front,
            back,
            bottom_f: fbottom,
            bottom_b: bbottom,
            top_f: ftop,
            top_b: btop,
            bottom,
            top,
            stitches,
        })
    }

    fn band_length(&self, a: &Arena) -> f64 {
        self.front.panel().length(a)
    }
}

/// Cuff parameters after the sleeve or trouser leg has fixed its circumference and
/// length.
#[derive(Clone, Debug)]
pub struct CuffParams {
    /// Circumference, cm.
    pub b_width: f64,
    /// Length, cm.
    pub cuff_len: f64,
    /// Fraction that is skirt (band-and-skirt cuffs).
    pub skirt_fraction: f64,
    /// Flare of the skirt.
    pub skirt_flare: f64,
    /// Gathering of the skirt.
    pub skirt_ruffle: f64,
}

/// A straight cuff band.
#[derive(Clone, Debug, Component)]
#[component(length = Self::band_length)]
pub struct CuffBand {
    /// Front panel.
    #[part]
    pub front: StraightBandPanel,
    /// Back panel.
    #[part]
    pub back: StraightBandPanel,
    /// Free end.
    #[interface]
    pub bottom: InterfaceId,
    /// Front of the attached end.
    #[interface]
    pub top_front: InterfaceId,
    /// Back of the attached end.
    #[interface]
    pub top_back: InterfaceId,
    /// Attached end.
    #[interface]
    pub top: InterfaceId,
    /// Side seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl CuffBand {
    /// Panels `<tag>_cuff_f` and `<tag>_cuff_b`, `length` long (cm).
    pub fn new(a: &mut Arena, tag: &str, c: &CuffParams, length: f64) -> Result<CuffBand> {
        let front = StraightBandPanel::new(a, &format!("{tag}_cuff_f"), c.b_width / 2.0, length, GatherTo::NONE)?;
        front.panel.translate_by(a, v3(0.0, 0.0, 15.0));
        let back = StraightBandPanel::new(a, &format!("{tag}_cuff_b"), c.b_width / 2.0, length, GatherTo::NONE)?;
        back.panel.translate_by(a, v3(0.0, 0.0, -15.0));
        let stitches = vec![StitchRule::new(a, front.right, back.right)?, StitchRule::new(a, front.left, back.left)?];
        let bottom = a.interface_from(&[front.bottom, back.bottom]);
        let top = a.interface_from(&[front.top, back.top]);
        Ok(CuffBand { top_front: front.top, top_back: back.top, front, back, bottom, top, stitches })
    }

    fn band_length(&self, a: &Arena) -> f64 {
        self.front.panel.length(a)
    }
}

/// A flared, skirt-like cuff.
#[derive(Clone, Debug, Component)]
#[component(length = Self::band_length)]
pub struct CuffSkirt {
    /// Front panel.
    #[part]
    pub front: SkirtPanel,
    /// Back panel.
    #[part]
    pub back: SkirtPanel,
    /// Attached end.
    #[interface]
    pub top: InterfaceId,
    /// Front of the attached end.
    #[interface]
    pub top_front: InterfaceId,
    /// Back of the attached end.
    #[interface]
    pub top_back: InterfaceId,
    /// Free end.
    #[interface]
    pub bottom: InterfaceId,
    /// Side seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl CuffSkirt {
    /// Panels `<tag>_cuff_skirt_f` and `<tag>_cuff_skirt_b`, `length` long (cm).
    pub fn new(a: &mut Arena, tag: &str, c: &CuffParams, length: f64) -> Result<CuffSkirt> {
        let width = c.b_width;
        let flare_diff = (c.skirt_flare - 1.0) * width / 2.0;
        let front =
            SkirtPanel::new(a, &format!("{tag}_cuff_skirt_f"), width / 2.0, length, c.skirt_ruffle, GatherTo::NONE, 0.0, flare_diff, None)?;
        front.panel.translate_by(a, v3(0.0, 0.0, 15.0));
        let back =
            SkirtPanel::new(a, &format!("{tag}_cuff_skirt_b"), width / 2.0, length, c.skirt_ruffle, GatherTo::NONE, 0.0, flare_diff, None)?;
        back.panel.translate_by(a, v3(0.0, 0.0, -15.0));
        let stitches = vec![StitchRule::new(a, front.right, back.right)?, StitchRule::new(a, front.left, back.left)?];
        let top = a.interface_from(&[front.top, back.top]);
        let bottom = a.interface_from(&[front.bottom, back.bottom]);
        Ok(CuffSkirt { top, top_front: front.top, top_back: back.top, bottom, front, back, stitches })
    }

    fn band_length(&self, a: &Arena) -> f64 {
        self.front.panel.length(a)
    }
}

/// A cuff band with a flared skirt sewn below it.
#[derive(Clone, Debug, Component)]
#[component(name = "CuffBandSkirt", length = Self::band_length)]
pub struct CuffBandSkirt {
    /// The band.
    #[part]
    pub cuff: CuffBand,
    /// The skirt.
    #[part]
    pub skirt: CuffSkirt,
    /// Attached end.
    #[interface]
    pub top: InterfaceId,
    /// Front of the attached end.
    #[interface]
    pub top_front: InterfaceId,
    /// Back of the attached end.
    #[interface]
    pub top_back: InterfaceId,
    /// Free end.
    #[interface]
    pub bottom: InterfaceId,
    /// Band to skirt.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl CuffBandSkirt {
    /// Band of length `cuff_len·(1 − skirt_fraction)` over a skirt of the rest.
    pub fn new(a: &mut Arena, tag: &str, c: &CuffParams) -> Result<CuffBandSkirt> {
        let cuff = CuffBand::new(a, tag, c, c.cuff_len * (1.0 - c.skirt_fraction))?;
        let skirt = CuffSkirt::new(a, tag, c, c.cuff_len * c.skirt_fraction)?;
        skirt.place_below(a, &cuff, 2.0);
        let stitches = vec![StitchRule::new(a, cuff.bottom, skirt.top)?];
        Ok(CuffBandSkirt { top: cuff.top, top_front: cuff.top_front, top_back: cuff.top_back, bottom: skirt.bottom, cuff, skirt, stitches })
    }

    fn band_length(&self, a: &Arena) -> f64 {
        self.cuff.part_length(a) + self.skirt.part_length(a)
    }
}

/// Any cuff: attached by its `top`, free at its `bottom`.
#[derive(Clone, Debug, Component)]
#[component(slots(Top, Bottom))]
pub enum Cuff {
    /// Band.
    Band(CuffBand),
    /// Skirt.
    Skirt(CuffSkirt),
    /// Band with skirt.
    BandSkirt(CuffBandSkirt),
}

impl Cuff {
    /// Build the cuff of the given kind.
    pub fn new(a: &mut Arena, kind: CuffKind, tag: &str, c: &CuffParams) -> Result<Cuff> {
        Ok(match kind {
            CuffKind::CuffBand => Cuff::Band(CuffBand::new(a, tag, c, c.cuff_len)?),
            CuffKind::CuffSkirt => Cuff::Skirt(CuffSkirt::new(a, tag, c, c.cuff_len)?),
            CuffKind::CuffBandSkirt => Cuff::BandSkirt(CuffBandSkirt::new(a, tag, c)?),
        })
    }
}
