//! Tiered skirt: a base skirt with further skirts sewn below it, each gathered into
//! the hem of the one above.

use crate::circle_skirt::SkirtCircle;
use crate::design::{self, LevelKind, LevelsBase};
use crate::shared::{BottomOptions, SkirtGroups, Symmetry};
use crate::skirt_paneled::{PencilSkirt, Skirt2};
use garmentcode::slots::{Bottom, BottomB, Top};
use garmentcode::{Align, Arena, Body, Component, InterfaceId, PartExt, Result, Rotation, SlotExt, StitchRule};

/// A skirt that can carry another skirt below it.
#[derive(Clone, Debug, Component)]
#[component(slots(Top, Bottom, BottomB))]
pub enum Stackable {
    /// Two-panel skirt.
    Skirt2(Skirt2),
    /// Pencil skirt.
    Pencil(PencilSkirt),
    /// Circle skirt.
    Circle(SkirtCircle),
}

/// Tiered skirt.
#[derive(Clone, Debug, Component)]
pub struct SkirtLevels {
    /// The base and the tiers, top to bottom.
    #[part]
    pub tiers: Vec<Stackable>,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Tier to tier.
    #[stitches]
    pub stitches: Vec<StitchRule>,
    /// Rise the skirt sits at.
    pub rise: f64,
}

impl SkirtLevels {
    /// Build from the `levels-skirt` group, the base and tiers from `skirts`, with
    /// `opts` (its rise).
    pub fn new(a: &mut Arena, body: &Body, l: &design::LevelsSkirt, skirts: SkirtGroups<'_>, opts: &BottomOptions) -> Result<SkirtLevels> {
        let leg = body.derived().leg_length;
        let total = l.length * leg;
        let base_len0 = total * l.base_length_frac;
        let level_len = (total - base_len0) / l.num_levels as f64;
        // QUIRK: the base always adds the hip depth of the *parameter* rise.
        let base_len = body.hips_line * l.rise + base_len0;
        let rise = opts.rise.unwrap_or(l.rise);
        let base_opts = BottomOptions { length: Some(base_len), rise: Some(rise), without_slits: true, ..opts.clone() };
        let base = match l.base {
            LevelsBase::Skirt2 => Stackable::Skirt2(Skirt2::new(a, body, skirts.skirt, &base_opts)?),
            LevelsBase::PencilSkirt => Stackable::Pencil(PencilSkirt::new(a, body, skirts.pencil_skirt, &base_opts)?),
            LevelsBase::SkirtCircle => Stackable::Circle(SkirtCircle::new(a, body, skirts.flare_skirt, Symmetry::Symmetric, &base_opts)?),
            LevelsBase::AsymmSkirtCircle => {
                Stackable::Circle(SkirtCircle::new(a, body, skirts.flare_skirt, Symmetry::Asymmetric, &base_opts)?)
            }
        };
        let angle = match &base {
            Stackable::Pencil(p) => p.low_angle,
            _ => 0.0,
        };
        let mut tiers = vec![base];
        let mut stitches = Vec::new();
        let mut lbody = body.clone();
        let ruffle = l.level_ruffle;
        for i in 0..l.num_levels {
            let prev = tiers.last().expect("base");
            lbody.waist = ruffle * prev.iface::<Bottom>().length(a);
            lbody.waist_back_width = ruffle * prev.iface::<BottomB>().length(a);
            // QUIRK: a tier takes its own `rise` parameter with the overwritten waist.
            let tier = BottomOptions {
                tag: i.to_string(),
                length: Some(level_len),
                rise: None,
                without_slits: true,
                without_gathers: true,
                pleats: None,
                hip_ease: opts.hip_ease,
            };
            let level = match l.level {
                LevelKind::Skirt2 => Stackable::Skirt2(Skirt2::new(a, &lbody, skirts.skirt, &tier)?),
                LevelKind::SkirtCircle => Stackable::Circle(SkirtCircle::new(a, &lbody, skirts.flare_skirt, Symmetry::Symmetric, &tier)?),
                LevelKind::AsymmSkirtCircle => {
                    Stackable::Circle(SkirtCircle::new(a, &lbody, skirts.flare_skirt, Symmetry::Asymmetric, &tier)?)
                }
            };
            level.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, 0.0, -angle]));
            let prev_bottom = tiers.last().expect("base").iface::<Bottom>();
            level.place_by_interface(a, level.iface::<Top>(), prev_bottom, 5.0, Align::Center);
            stitches.push(StitchRule::new(a, prev_bottom, level.iface::<Top>())?);
            tiers.push(level);
        }
        Ok(SkirtLevels { top: tiers[0].iface::<Top>(), tiers, stitches, rise })
    }
}
