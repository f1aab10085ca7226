//! Trousers: leg panels with a crotch curve and waist darts, optional cuffs.

use crate::bands::{Cuff, CuffParams};
use crate::common::{eval_rise, v2, v3};
use crate::design;
use crate::shared::{BottomOptions, Darts};
use crate::skirt_paneled::{DartsFrom, add_darts, tangent_curve};
use garmentcode::math::close_enough;
use garmentcode::slots::Top;
use garmentcode::{
    Align, Arena, Body, Component, Curve, EdgeSeq, Gather, InterfaceId, PanelId, PartExt, Result, SlotExt, StitchRule, Vec3,
};

/// Front or back half of one trouser leg.
#[derive(Clone, Debug, Component)]
pub struct PantPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Outseam.
    #[interface]
    pub outside: InterfaceId,
    /// Crotch seam.
    #[interface]
    pub crotch: InterfaceId,
    /// Inseam.
    #[interface]
    pub inside: InterfaceId,
    /// Hem.
    #[interface]
    pub bottom: InterfaceId,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
}

/// Measurements of a front or back leg panel.
pub struct PantSpec {
    /// Leg length below the hip line.
    pub length: f64,
    /// Half-panel waist width.
    pub waist: f64,
    /// Half-panel hip width.
    pub hips: f64,
    /// Waist-to-hip depth.
    pub hips_depth: f64,
    /// Crotch extension.
    pub crotch_width: f64,
    /// Distance of the darts from the side.
    pub dart_position: f64,
    /// Waist measure the top interface's gathers are proportioned to.
    pub match_top_int_to: Option<f64>,
    /// Extension of the hip depth (back).
    pub hipline_ext: f64,
    /// One or two darts.
    pub darts: Darts,
}

impl PantPanel {
    /// Build one leg panel.
    pub fn new(a: &mut Arena, name: &str, body: &Body, design: &design::Pants, s: &PantSpec) -> Result<PantPanel> {
        let flare = body.leg_circ * (design.flare - 1.0) / 4.0;
        let hips_depth = s.hips_depth * s.hipline_ext;
        let hip_side_incl = body.derived().hip_inclination.to_radians();
        let dart_depth = hips_depth * 0.8;
        let crotch_depth_diff = body.crotch_hip_diff;
        let w_diff = s.hips - s.waist;
        let mut hw_shift = hip_side_incl.tan() * hips_depth;
        if hw_shift > w_diff {
            hw_shift = w_diff;
        }
        let p0 = a.vertex(v2(-flare, 0.0));
        let p1 = a.vertex(v2(0.0, s.length));
        let right_bottom = if close_enough(design.flare, 1.0, 1e-4) {
            a.edge(p0, p1, Curve::Line)?
        } else {
            tangent_curve(a, p0, p1, None, Some(v2(0.0, 1.0)), v2(0.75, 0.0))?
        };
        let p2 = a.vertex(v2(hw_shift, s.length + hips_depth));
        let right_top = tangent_curve(a, p1, p2, Some(v2(0.0, 1.0)), None, v2(0.5, 0.0))?;
        let p3 = a.vertex(v2(w_diff + s.waist, s.length + hips_depth));
        let top = a.edge(p2, p3, Curve::Line)?;
        let p4 = a.vertex(v2(s.hips, s.length + 0.45 * hips_depth));
        let crotch_top = a.edge(p3, p4, Curve::Line)?;
        let p5 = a.vertex(v2(s.hips + s.crotch_width, s.length - crotch_depth_diff));
        let crotch_bottom = tangent_curve(a, p4, p5, Some(v2(0.0, -1.0)), Some(v2(1.0, 0.0)), v2(0.5, -0.5))?;
        let cb_end = a.pos(p5);
        let y = f64::min(0.0, s.length - crotch_depth_diff * 1.5);
        let p6 = a.vertex(v2(cb_end.x - 2.0 + flare, y));
        let left = tangent_curve(a, p5, p6, None, Some(v2(flare, y - cb_end.y)), v2(0.3, 0.0))?;
        let mut edges = EdgeSeq(vec![right_bottom, right_top, top, crotch_top, crotch_bottom, left]);
        edges.close_loop(a)?;
        let bottom = edges.last_edge();
        let panel = a.panel_with_edges(name, edges);
        panel.set_pivot(a, cb_end, false);
        panel.set_translation(a, Vec3::new(-0.5, -hips_depth - crotch_depth_diff + 5.0, 0.0));
        let outside = a.interface_gathered(panel, EdgeSeq(vec![right_bottom, right_top]), Gather::PerEdge(vec![1.0, s.hipline_ext]))?;
        let crotch = a.interface(panel, EdgeSeq(vec![crotch_top, crotch_bottom]));
        let inside = a.interface(panel, left);
        let bottom_i = a.interface(panel, bottom);
        let ruffle = s.match_top_int_to.map(|m| s.waist / m).unwrap_or(1.0);
        let top_i = if w_diff > hw_shift {
            let (top_edges, int_edges) = add_darts(a, panel, top, w_diff - hw_shift, dart_depth, s.dart_position, s.darts, DartsFrom::End)?;
            let i = a.interface_gathered(panel, int_edges, ruffle)?;
            let mut loop_edges = panel.edges(a).clone();
            loop_edges.substitute(top, &top_edges)?;
            panel.set_edges(a, loop_edges);
            i
        } else {
            a.interface_gathered(panel, top, ruffle)?
        };
        Ok(PantPanel { panel, outside, crotch, inside, bottom: bottom_i, top: top_i })
    }
}

/// One trouser leg (front and back panels) with its optional cuff.
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::half_length)]
pub struct PantsHalf {
    /// `PantsHalf_r` or `PantsHalf_l`.
    pub name: String,
    /// Front panel `pant_f_<tag>`.
    #[part]
    pub front: PantPanel,
    /// Back panel `pant_b_<tag>`.
    #[part]
    pub back: PantPanel,
    /// Cuff.
    #[part]
    pub cuff: Option<Cuff>,
    /// Front crotch seam.
    #[interface]
    pub crotch_f: InterfaceId,
    /// Back crotch seam.
    #[interface]
    pub crotch_b: InterfaceId,
    /// Front waist.
    #[interface]
    pub top_f: InterfaceId,
    /// Back waist.
    #[interface]
    pub top_b: InterfaceId,
    /// Out- and inseams, and the cuff.
    #[stitches]
    pub stitches: Vec<StitchRule>,
    /// Rise the trousers sit at.
    pub rise: f64,
}

impl PantsHalf {
    /// Build the leg `tag` (`r` or `l`) from the `pants` group with `opts` (its rise).
    pub fn new(a: &mut Arena, tag: &str, body: &Body, d: &design::Pants, opts: &BottomOptions) -> Result<PantsHalf> {
        let rise = opts.rise.unwrap_or(d.rise);
        let (waist, hips_depth, waist_back) = eval_rise(body, rise)?;
        let min_ext = body.leg_circ - body.hips / 2.0 + 5.0;
        let front_hip = (body.hips - body.hip_back_width) / 2.0;
        let crotch_extention = min_ext * d.width;
        let front_extention = front_hip / 4.0;
        let back_extention = crotch_extention - front_extention;
        let (mut length, mut cuff_len) = (d.length, d.cuff.cuff_len);
        if d.cuff.r#type.is_some() {
            // QUIRK: the reference reads the design file's range for the minimum.
            let min_length = 0.2;
            if length - cuff_len < min_length {
                cuff_len = length - min_length;
            }
            length -= cuff_len;
        }
        let leg = body.derived().leg_length;
        length *= leg;
        cuff_len *= leg;
        let level = body.derived().waist_level;
        let front = PantPanel::new(
            a,
            &format!("pant_f_{tag}"),
            body,
            d,
            &PantSpec {
                length,
                waist: (waist - waist_back) / 2.0,
                hips: (body.hips - body.hip_back_width) / 2.0,
                hips_depth,
                crotch_width: front_extention,
                dart_position: body.bust_points / 2.0,
                match_top_int_to: Some((body.waist - body.waist_back_width) / 2.0),
                hipline_ext: 1.0,
                darts: Darts::Single,
            },
        )?;
        front.panel.translate_by(a, v3(0.0, level - 5.0, 25.0));
        let back = PantPanel::new(
            a,
            &format!("pant_b_{tag}"),
            body,
            d,
            &PantSpec {
                length,
                waist: waist_back / 2.0,
                hips: body.hip_back_width / 2.0,
                hips_depth,
                crotch_width: back_extention,
                dart_position: body.bum_points / 2.0,
                match_top_int_to: Some(body.waist_back_width / 2.0),
                hipline_ext: 1.1,
                darts: Darts::Double,
            },
        )?;
        back.panel.translate_by(a, v3(0.0, level - 5.0, -20.0));
        let mut stitches = vec![StitchRule::new(a, front.outside, back.outside)?, StitchRule::new(a, front.inside, back.inside)?];
        let cuff = match d.cuff.r#type {
            None => None,
            Some(kind) => {
                let pant_bottom = a.interface_from(&[front.bottom, back.bottom]);
                let params = CuffParams {
                    b_width: pant_bottom.length(a) / d.cuff.top_ruffle,
                    cuff_len,
                    skirt_fraction: d.cuff.skirt_fraction,
                    skirt_flare: d.cuff.skirt_flare,
                    skirt_ruffle: d.cuff.skirt_ruffle,
                };
                let cuff = Cuff::new(a, kind, &format!("pant_{tag}"), &params)?;
                cuff.place_by_interface(a, cuff.iface::<Top>(), pant_bottom, 5.0, Align::Left);
                stitches.push(StitchRule::new(a, pant_bottom, cuff.iface::<Top>())?);
                Some(cuff)
            }
        };
        Ok(PantsHalf {
            name: format!("PantsHalf_{tag}"),
            crotch_f: front.crotch,
            crotch_b: back.crotch,
            top_f: front.top,
            top_b: back.top,
            front,
            back,
            cuff,
            stitches,
            rise,
        })
    }

    fn half_length(&self, a: &Arena) -> f64 {
        let front = self.front.panel.length(a);
        match &self.cuff {
            Some(c) => front + c.part_length(a),
            None => front,
        }
    }
}

/// Trousers.
#[derive(Clone, Debug, Component)]
#[component(length = Self::pants_length)]
pub struct Pants {
    /// Right leg.
    #[part]
    pub right: PantsHalf,
    /// Left leg (mirrored).
    #[part]
    pub left: PantsHalf,
    /// Front waist.
    #[interface]
    pub top_f: InterfaceId,
    /// Back waist.
    #[interface]
    pub top_b: InterfaceId,
    /// Whole waist, around the body from the front right.
    #[interface]
    pub top: InterfaceId,
    /// Crotch seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl Pants {
    /// Build both legs from the `pants` group with `opts` (its rise).
    pub fn new(a: &mut Arena, body: &Body, d: &design::Pants, opts: &BottomOptions) -> Result<Pants> {
        let right = PantsHalf::new(a, "r", body, d, opts)?;
        let left = PantsHalf::new(a, "l", body, d, opts)?;
        left.mirror(a);
        let stitches = vec![StitchRule::new(a, right.crotch_f, left.crotch_f)?, StitchRule::new(a, right.crotch_b, left.crotch_b)?];
        let top_f = a.interface_from(&[right.top_f, left.top_f]);
        let top_b = a.interface_from(&[right.top_b, left.top_b]);
        let parts = [right.top_f.flip_edges(a), left.top_f.reverse(a, true), left.top_b.flip_edges(a), right.top_b.reverse(a, true)];
        let top = a.interface_from(&parts);
        Ok(Pants { right, left, top_f, top_b, top, stitches })
    }

    /// Rise of the trousers.
    pub fn rise(&self) -> f64 {
        self.right.rise
    }

    fn pants_length(&self, a: &Arena) -> f64 {
        self.right.part_length(a)
    }
}
