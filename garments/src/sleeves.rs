//! Sleeves: the armhole cut-outs, the sleeve panels built around the inverted
//! armhole (the sleeve opening), cuffs.

use crate::bands::{Cuff, CuffParams};
use crate::common::{v2, v3};
use crate::design::{self, ArmholeShape};
use crate::shapes;
use garmentcode::inner::join_at_fold;
use garmentcode::math::close_enough;
use garmentcode::ops::even_armhole_openings;
use garmentcode::slots::{Bottom, Top};
use garmentcode::{
    Align, Arena, Body, Component, Curve, EdgeSeq, InterfaceId, PanelId, PartExt, Result, Rotation, SlotExt, StitchRule, Vec2,
};

/// Front or back half of a sleeve: cuff edge at x = 0, underarm seam below, the
/// sleeve opening at the far end, shoulder seam on top.
#[derive(Clone, Debug, Component)]
pub struct SleevePanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// The opening (sewn into the armhole).
    #[interface(rename = "in")]
    pub in_: InterfaceId,
    /// The free end (cuff side).
    #[interface]
    pub out: InterfaceId,
    /// Shoulder seam.
    #[interface]
    pub top: InterfaceId,
    /// Underarm seam.
    #[interface]
    pub bottom: InterfaceId,
}

impl SleevePanel {
    /// Build around `open_shape` (the opening chain, moved into the panel).
    pub fn new(a: &mut Arena, name: &str, body: &Body, s: &design::Sleeve, open_shape: &EdgeSeq, length_shift: f64) -> Result<SleevePanel> {
        let d = body.derived();
        let shoulder_angle = d.shoulder_incl.to_radians();
        let rest_angle = f64::max((s.sleeve_angle as f64).to_radians(), shoulder_angle);
        let mut standing = s.standing_shoulder;
        let (o0, o1) = open_shape.shortcut(a);
        let end_width = f64::max(s.end_width * (o0.y - o1.y).abs(), body.wrist / 2.0);
        if !close_enough(s.connect_ruffle, 1.0, 1e-4) {
            open_shape.stretch(a, s.connect_ruffle);
        }
        let (o0, o1) = open_shape.shortcut(a);
        let opening_length = (o0.x - o1.x).abs();
        let arm_width = (o0.y - o1.y).abs();
        let length = f64::max(s.length * (body.arm_length - opening_length) + length_shift, 5.0);
        let mut edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(0.0, -end_width), v2(length, -arm_width)], false)?;
        let joint = a.end(edges.last_edge());
        open_shape.snap_to(a, a.pos(joint));
        a.set_start(open_shape[0], joint);
        edges.extend(open_shape.iter().copied());
        edges.close_loop(a)?;
        if standing {
            if rest_angle > shoulder_angle + 5f64.to_radians() {
                let top_edge = edges.last_edge();
                let start = a.start(top_edge);
                let p = a.pos(start);
                let len = s.standing_shoulder_len;
                let x_shift = len * (rest_angle - shoulder_angle).cos();
                let y_shift = len * (rest_angle - shoulder_angle).sin();
                let new_v = a.vertex(Vec2::new(p.x - x_shift, p.y + y_shift));
                let standing_edge = a.edge(start, new_v, Curve::Line)?;
                a.set_start(top_edge, new_v);
                edges.substitute(top_edge, &[standing_edge, top_edge])?;
            } else {
                standing = false;
            }
        }
        let panel = a.panel_with_edges(name, edges.clone());
        let in_ = a.interface_gathered(panel, open_shape.clone(), s.connect_ruffle)?;
        let out = a.interface_gathered(panel, edges[0], s.cuff.top_ruffle)?;
        let top = if standing { a.interface(panel, edges.slice(-2, edges.len() as isize)) } else { a.interface(panel, edges.last_edge()) };
        let bottom = a.interface(panel, edges[1]);
        panel.set_length_interface(a, bottom);
        let pivot = a.pos(a.start(edges.last_edge()));
        panel.set_pivot(a, pivot, false);
        panel.translate_to(a, v3(-body.shoulder_w / 2.0, body.height - body.head_l, 0.0));
        Ok(SleevePanel { panel, in_, out, top, bottom })
    }
}

/// A sleeve (or just the armhole shapes of a sleeveless side).
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::sleeve_length)]
pub struct Sleeve {
    /// `Sleeve_<side>`.
    pub name: String,
    /// Armhole shape cut into the front torso.
    pub in_front_shape: EdgeSeq,
    /// Armhole shape cut into the back torso.
    pub in_back_shape: EdgeSeq,
    /// Front panel `<side>_sleeve_f`.
    #[part]
    pub front: Option<SleevePanel>,
    /// Back panel `<side>_sleeve_b`.
    #[part]
    pub back: Option<SleevePanel>,
    /// Cuff.
    #[part]
    pub cuff: Option<Cuff>,
    /// The opening, front then back (sewn into the armhole).
    #[interface(rename = "in")]
    pub in_: Option<InterfaceId>,
    /// The free end (of the cuff, if any).
    #[interface]
    pub out: Option<InterfaceId>,
    /// Seams of the sleeve and the cuff.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl Sleeve {
    /// The armhole shapes of side `tag` for an armhole `connecting_width` deep between
    /// torso panels `front_w` and `back_w` wide at that depth: the sleeve before its
    /// panels ([`Sleeve::add_panels`] builds them), so that the torso can be cut and
    /// checked before the costly sleeve-opening inversion.
    pub fn armholes(
        a: &mut Arena,
        tag: &str,
        body: &Body,
        s: &design::Sleeve,
        connecting_width: f64,
        front_w: f64,
        back_w: f64,
    ) -> Result<Sleeve> {
        let sleeve_balance = body.derived().base_sleeve_balance / 2.0;
        let sc = s.smoothing_coeff;
        let mut shape = |incl: f64| match s.armhole_shape {
            _ if !s.sleeveless => shapes::armhole_curve(a, incl, connecting_width),
            ArmholeShape::ArmholeSquare => shapes::armhole_square(a, incl, connecting_width),
            ArmholeShape::ArmholeAngle => shapes::armhole_angle(a, incl, connecting_width, sc, sc),
            ArmholeShape::ArmholeCurve => shapes::armhole_curve(a, incl, connecting_width),
        };
        let in_front_shape = shape(front_w - sleeve_balance)?;
        let in_back_shape = shape(back_w - sleeve_balance)?;
        Ok(Sleeve {
            name: format!("Sleeve_{tag}"),
            in_front_shape,
            in_back_shape,
            front: None,
            back: None,
            cuff: None,
            in_: None,
            out: None,
            stitches: Vec::new(),
        })
    }

    /// Build the sleeve panels (and cuff) of a sleeve made by [`Sleeve::armholes`]
    /// with the same arguments; nothing for a sleeveless side.
    pub fn add_panels(
        &mut self,
        a: &mut Arena,
        tag: &str,
        body: &Body,
        s: &design::Sleeve,
        connecting_width: f64,
        front_w: f64,
        back_w: f64,
    ) -> Result<()> {
        if s.sleeveless {
            return Ok(());
        }
        let d = body.derived();
        let sleeve_balance = d.base_sleeve_balance / 2.0;
        let rest_angle = f64::max((s.sleeve_angle as f64).to_radians(), d.shoulder_incl.to_radians());
        let opening = |a: &mut Arena, incl: f64| shapes::sleeve_opening(a, incl, connecting_width, rest_angle, s.opening_dir_mix);
        let mut front_opening = opening(a, front_w - sleeve_balance)?;
        let mut back_opening = opening(a, back_w - sleeve_balance)?;
        if front_w != back_w {
            let tol = 0.2 / front_opening.length(a);
            even_armhole_openings(a, &mut front_opening, &mut back_opening, tol)?;
        }
        let cuff_len_adj = match s.cuff.r#type {
            None => 0.0,
            Some(_) => f64::min(s.cuff.cuff_len * body.arm_length, s.length * body.arm_length * 0.7),
        };
        let front = SleevePanel::new(a, &format!("{tag}_sleeve_f"), body, s, &front_opening, -cuff_len_adj)?;
        front.panel.translate_by(a, v3(0.0, 0.0, 15.0));
        let back = SleevePanel::new(a, &format!("{tag}_sleeve_b"), body, s, &back_opening, -cuff_len_adj)?;
        back.panel.translate_by(a, v3(0.0, 0.0, -15.0));
        self.stitches.push(StitchRule::new(a, front.top, back.top)?);
        self.stitches.push(StitchRule::new(a, front.bottom, back.bottom)?);
        let back_in = back.in_.reverse(a, true);
        self.in_ = Some(a.interface_from(&[front.in_, back_in]));
        let mut out = a.interface_from(&[front.out, back.out]);
        self.front = Some(front);
        self.back = Some(back);
        if let Some(kind) = s.cuff.r#type {
            let circ = f64::max(out.length(a) / s.cuff.top_ruffle, body.wrist);
            let params = CuffParams {
                b_width: circ,
                cuff_len: cuff_len_adj,
                skirt_fraction: s.cuff.skirt_fraction,
                skirt_flare: s.cuff.skirt_flare,
                skirt_ruffle: s.cuff.skirt_ruffle,
            };
            let cuff = Cuff::new(a, kind, &format!("sl_{tag}"), &params)?;
            cuff.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, 0.0, -90.0]));
            cuff.place_by_interface(a, cuff.iface::<Top>(), out, 2.0, Align::Top);
            self.stitches.push(StitchRule::new(a, cuff.iface::<Top>(), out)?);
            out = cuff.iface::<Bottom>();
            self.cuff = Some(cuff);
        }
        self.out = Some(out);
        self.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, 0.0, body.arm_pose_angle]));
        self.set_panel_label(a, "arm", true);
        Ok(())
    }

    /// Make the sleeve one panel (`design.extension.sleeve.one_piece`): the back panel
    /// joined to the front across their shoulder seam, which becomes a fold line
    /// ([`join_at_fold`], turning by 90°: the two halves open over the arm as the two
    /// panels were placed). The panel keeps the front's name; every other seam stays.
    /// Sleeves with a standing shoulder (a corner in the seam) cannot fold and are
    /// refused; a sleeveless side is left as it is.
    pub fn join_panels(&mut self, a: &mut Arena) -> Result<()> {
        let (Some(front), Some(back)) = (&self.front, &self.back) else { return Ok(()) };
        if front.top.len(a) != 1 || back.top.len(a) != 1 {
            return Err(garmentcode::Error::Design(format!(
                "{}: a one-piece sleeve (extension.sleeve.one_piece) folds along a straight top; \
                 its standing shoulder (sleeve.standing_shoulder) makes a corner there",
                self.name
            )));
        }
        let (top, back_top) = (front.top, back.top);
        join_at_fold(a, &front.panel, top.edges(a)[0], &back.panel, back_top.edges(a)[0], "fold", 90.0)?;
        self.stitches.retain(|s| s.a != top && s.b != top);
        self.back = None;
        Ok(())
    }

    fn sleeve_length(&self, a: &Arena) -> f64 {
        let Some(front) = &self.front else { return 0.0 };
        let l = front.panel.length(a);
        match &self.cuff {
            Some(c) => l + c.part_length(a),
            None => l,
        }
    }
}
