//! The meta garment: chooses the upper garment, waistband and bottom from the design,
//! connects them by interfaces and places them; and the reference's validity checks.

use crate::bands::Waistband;
use crate::bodice::Shirt;
use crate::circle_skirt::SkirtCircle;
use crate::design::{BottomKind, Design, GodetBase, LevelsBase, UpperKind, WaistbandKind};
use crate::extension::Lower;
use crate::godet::{GodetBaseSkirt, GodetSkirt};
use crate::pants::Pants;
use crate::shared::{BottomOptions, Fit, SkirtGroups, Symmetry};
use crate::skirt_levels::{SkirtLevels, Stackable};
use crate::skirt_paneled::{PencilSkirt, Skirt2, SkirtManyPanels};
use garmentcode::slots::{Bottom, Top};
use garmentcode::{Align, Arena, Body, Component, InterfaceId, PanelId, Part, PartExt, Result, SlotExt, StitchRule, Vec3};

/// The bottom garment of a design: one of the library's skirts or the pants. Each
/// exposes a `top` to sew to the waist.
#[derive(Component)]
#[component(slots(Top))]
pub enum BottomGarment {
    /// Circle skirt (also the asymmetric one).
    Circle(SkirtCircle),
    /// Two-panel skirt.
    Skirt2(Skirt2),
    /// Pencil skirt.
    Pencil(PencilSkirt),
    /// Many-panel skirt.
    ManyPanels(SkirtManyPanels),
    /// Skirt with godets.
    Godet(GodetSkirt),
    /// Pants.
    Pants(Pants),
    /// Tiered skirt.
    Levels(SkirtLevels),
}

impl BottomGarment {
    /// The panels of a skirt that face front (where hip pockets go): the front panel
    /// (of the base skirt, of the top tier), or the two gores of a many-panel skirt
    /// nearest to either side of the front, 35° off the centre (one gore if the same).
    /// None for pants.
    pub fn front_panels(&self, a: &Arena) -> Vec<PanelId> {
        let stackable = |s: &Stackable| match s {
            Stackable::Skirt2(s) => s.front.panel,
            Stackable::Pencil(s) => s.front.panel,
            Stackable::Circle(s) => s.front,
        };
        match self {
            BottomGarment::Circle(s) => vec![s.front],
            BottomGarment::Skirt2(s) => vec![s.front.panel],
            BottomGarment::Pencil(s) => vec![s.front.panel],
            BottomGarment::Godet(s) => vec![match &s.base {
                GodetBaseSkirt::Skirt2(s) => s.front.panel,
                GodetBaseSkirt::Pencil(s) => s.front.panel,
            }],
            BottomGarment::Levels(s) => s.tiers.first().map(stackable).into_iter().collect(),
            BottomGarment::ManyPanels(s) => {
                let centre = |p: PanelId| {
                    let c = p.point_to_3d(a, p.center_2d(a));
                    Vec3::new(c.x, 0.0, c.z).normalize_or_zero()
                };
                let nearest = |side: f64| {
                    let aim = Vec3::new(side * 35f64.to_radians().sin(), 0.0, 35f64.to_radians().cos());
                    s.panels.iter().map(|g| g.panel).max_by(|p, q| centre(*p).dot(aim).total_cmp(&centre(*q).dot(aim)))
                };
                let mut gores: Vec<PanelId> = [nearest(-1.0), nearest(1.0)].into_iter().flatten().collect();
                gores.dedup();
                gores
            }
            BottomGarment::Pants(_) => Vec::new(),
        }
    }

    /// How high the garment sits (1 = natural waist).
    pub fn rise(&self) -> f64 {
        match self {
            BottomGarment::Circle(s) => s.rise,
            BottomGarment::Skirt2(s) => s.rise,
            BottomGarment::Pencil(s) => s.rise,
            BottomGarment::ManyPanels(s) => s.rise,
            BottomGarment::Godet(s) => s.rise(),
            BottomGarment::Pants(p) => p.rise(),
            BottomGarment::Levels(s) => s.rise,
        }
    }
}

/// A complete garment.
#[derive(Component)]
#[component(name = "MetaGarment", length = Self::garment_length)]
pub struct MetaGarment {
    /// Upper garment.
    #[part]
    pub upper: Option<Shirt>,
    /// Waistband.
    #[part]
    pub belt: Option<Waistband>,
    /// Bottom garment.
    #[part]
    pub lower: Option<BottomGarment>,
    /// Pieces sewn on top (patch pockets: `design.extension`).
    #[part]
    pub pockets: Vec<PanelId>,
    /// Upper to band to bottom.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl MetaGarment {
    /// Build the garment a design describes on a body.
    pub fn new(a: &mut Arena, body: &Body, design: &Design) -> Result<MetaGarment> {
        let meta = &design.meta;
        let mut upper = match meta.upper {
            None => None,
            Some(kind) => {
                let fit = match kind {
                    UpperKind::Shirt => Fit::Loose,
                    UpperKind::FittedShirt => Fit::Fitted,
                };
                let s = Shirt::new(a, body, &design.shirt, &design.collar, &design.sleeve, &design.left, fit)?;
                s.set_panel_label(a, "body", false);
                Some(s)
            }
        };
        // A fitted top forces the bottom to sit at the natural waist.
        let forced_rise = if meta.upper == Some(UpperKind::FittedShirt) { Some(1.0) } else { None };
        let lower = match meta.bottom {
            None => None,
            Some(kind) => Some(build_bottom(a, body, design, kind, forced_rise)?),
        };
        let mut stitches = Vec::new();
        let mut prev_bottom: Option<InterfaceId> = upper.as_ref().map(|u| u.iface::<Bottom>());
        let belt = match meta.wb {
            None => None,
            Some(kind) => {
                let rise = lower.as_ref().map(|l| l.rise()).unwrap_or(1.0);
                let fit = match kind {
                    WaistbandKind::StraightWB => Fit::Loose,
                    WaistbandKind::FittedWB => Fit::Fitted,
                };
                let wb = Waistband::new(a, body, &design.waistband, rise, fit)?;
                if let Some(prev) = prev_bottom {
                    wb.place_by_interface(a, wb.top, prev, 5.0, Align::Center);
                    stitches.push(StitchRule::new(a, prev, wb.top)?);
                }
                wb.top.propagate_label(a, "lower_interface");
                wb.set_panel_label(a, "body", false);
                prev_bottom = Some(wb.bottom);
                Some(wb)
            }
        };
        if let Some(lower) = &lower {
            let top = lower.iface::<Top>();
            if let Some(prev) = prev_bottom {
                lower.place_by_interface(a, top, prev, 5.0, Align::Center);
                stitches.push(StitchRule::new(a, prev, top)?);
            }
            if belt.is_none() {
                top.propagate_label(a, "lower_interface");
            }
            lower.set_panel_label(a, "leg", false);
        }
        let to_extend = match &lower {
            Some(BottomGarment::Pants(p)) => Lower::Pants(p),
            Some(skirt) => Lower::Skirt(skirt.front_panels(a)),
            None => Lower::Other,
        };
        let pockets = crate::extension::apply(a, &design.extension, upper.as_mut(), to_extend)?;
        Ok(MetaGarment { upper, belt, lower, pockets, stitches })
    }

    /// Total length: upper + band + bottom, as the reference measures it.
    pub fn total_length(&self, a: &Arena) -> f64 {
        Component::length(self, a)
    }

    /// The parts' lengths summed, pieces sewn on top (pockets) left out.
    fn garment_length(&self, a: &Arena) -> f64 {
        let mut total = 0.0;
        let parts: [Option<&dyn Part>; 3] = [
            self.upper.as_ref().map(|p| p as &dyn Part),
            self.belt.as_ref().map(|p| p as &dyn Part),
            self.lower.as_ref().map(|p| p as &dyn Part),
        ];
        for p in parts.into_iter().flatten() {
            total += p.node().length(a);
        }
        total
    }
}

fn build_bottom(a: &mut Arena, body: &Body, design: &Design, kind: BottomKind, rise: Option<f64>) -> Result<BottomGarment> {
    let opts = BottomOptions {
        pleats: crate::extension::pleating(&design.extension),
        hip_ease: design.extension.fit.hip_ease,
        ..BottomOptions::at_rise(rise)
    };
    let skirts = SkirtGroups::of(design);
    Ok(match kind {
        BottomKind::SkirtCircle => SkirtCircle::new(a, body, &design.flare_skirt, Symmetry::Symmetric, &opts)?.into(),
        BottomKind::AsymmSkirtCircle => SkirtCircle::new(a, body, &design.flare_skirt, Symmetry::Asymmetric, &opts)?.into(),
        BottomKind::GodetSkirt => GodetSkirt::new(a, body, &design.godet_skirt, skirts, &opts)?.into(),
        BottomKind::Pants => Pants::new(a, body, &design.pants, &opts)?.into(),
        BottomKind::Skirt2 => Skirt2::new(a, body, &design.skirt, &opts)?.into(),
        BottomKind::SkirtManyPanels => SkirtManyPanels::new(a, body, &design.flare_skirt, &opts)?.into(),
        BottomKind::PencilSkirt => PencilSkirt::new(a, body, &design.pencil_skirt, &opts)?.into(),
        BottomKind::SkirtLevels => SkirtLevels::new(a, body, &design.levels_skirt, skirts, &opts)?.into(),
    })
}

/// The reference dataset sampler's filter on parameter combinations: `Err` with its
/// message for empty garments and lone belts, gathered two-panel skirts without a
/// fitting band, and heavy flared skirts without support.
pub fn check_param_combinations(d: &Design) -> std::result::Result<(), &'static str> {
    let meta = &d.meta;
    if meta.upper.is_some() {
        return Ok(());
    }
    let Some(lower) = meta.bottom else {
        return Err("ERROR::IncorrectParams::Empty pattern or singular belt");
    };
    if matches!(lower, BottomKind::Pants | BottomKind::PencilSkirt) {
        return Ok(());
    }
    let skirt2_based = lower == BottomKind::Skirt2
        || (lower == BottomKind::GodetSkirt && d.godet_skirt.base == GodetBase::Skirt2)
        || (lower == BottomKind::SkirtLevels && d.levels_skirt.base == LevelsBase::Skirt2);
    if skirt2_based && d.skirt.ruffle > 1.0 && (meta.wb.is_none() || d.waistband.waist > 1.0) {
        return Err("ERROR::IncorrectParams::Skirt2 ruffles + belt");
    }
    let flare_family = |k: BottomKind| matches!(k, BottomKind::SkirtCircle | BottomKind::AsymmSkirtCircle | BottomKind::SkirtManyPanels);
    let levels_on_flare =
        lower == BottomKind::SkirtLevels && matches!(d.levels_skirt.base, LevelsBase::SkirtCircle | LevelsBase::AsymmSkirtCircle);
    if (flare_family(lower) || levels_on_flare) && (meta.wb.is_none() || d.waistband.waist > 1.0 || d.waistband.width <= 0.25) {
        let length = if lower == BottomKind::SkirtLevels { d.levels_skirt.length } else { d.flare_skirt.length };
        if length > 0.5 || d.flare_skirt.suns > 0.75 {
            return Err("ERROR::IncorrectParams::Flare skirts + belt");
        }
    }
    Ok(())
}
