//! Upper garments: loose (t-shirt) and fitted (darted) bodice panels, a bodice half
//! with its sleeve and collar, and the shirts made of two halves.

use crate::collars::Collar;
use crate::common::{tan_deg, v2, v3};
use crate::design::{self, CollarComponent};
use crate::shared::{Fit, Resolved, Side};
use crate::sleeves::Sleeve;
use garmentcode::math::lerp;
use garmentcode::ops::{Cut, DartSize, EdgeSide, cut_corner, dart_shape};
use garmentcode::{Align, Arena, Body, Component, EdgeSeq, InterfaceId, PanelId, PartExt, Result, StitchRule, Vec2};

/// How a torso panel reports its width at a level below the shoulder.
#[derive(Clone, Copy, Debug, PartialEq)]
enum WidthRule {
    /// From the slope of its side seam.
    SideSlope,
    /// Side slope plus the panel's extra width over half the shoulders (loose shirts).
    SideSlopePlusWidth,
    /// Constant (fitted back).
    Constant,
}

/// Front or back half of a bodice (loose or fitted).
#[derive(Clone, Debug, Component)]
pub struct TorsoPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Side seam.
    #[interface]
    pub outside: InterfaceId,
    /// Centre-front or centre-back seam.
    #[interface]
    pub inside: InterfaceId,
    /// Shoulder seam.
    #[interface]
    pub shoulder: InterfaceId,
    /// Hem.
    #[interface]
    pub bottom: InterfaceId,
    /// Side and shoulder: the corner the armhole is cut into.
    pub shoulder_corner: InterfaceId,
    /// Shoulder and centre: the corner the neckline is cut into.
    pub collar_corner: InterfaceId,
    /// Half width at the chest.
    pub width: f64,
    rule: WidthRule,
}

impl TorsoPanel {
    /// Width of the panel `level` cm below the shoulder (the top assumed as wide as
    /// half the shoulders).
    pub fn get_width(&self, a: &Arena, body: &Body, level: f64) -> f64 {
        if self.rule == WidthRule::Constant {
            return self.width;
        }
        let side = self.outside.edges(a).last_edge();
        let g = a.geom(side);
        let (mut x, mut y) = (g.end.x - g.start.x, g.end.y - g.start.y);
        if y < 0.0 {
            x = -x;
            y = -y;
        }
        let base = level * x / y + body.shoulder_w / 2.0;
        match self.rule {
            WidthRule::SideSlopePlusWidth => base + self.width - body.shoulder_w / 2.0,
            _ => base,
        }
    }

    fn finish(panel: PanelId, ifaces: [InterfaceId; 6], width: f64, rule: WidthRule) -> TorsoPanel {
        let [outside, inside, shoulder, bottom, shoulder_corner, collar_corner] = ifaces;
        TorsoPanel { panel, outside, inside, shoulder, bottom, shoulder_corner, collar_corner, width, rule }
    }

    /// Loose front or back half, t-shirt block.
    pub fn loose(a: &mut Arena, name: &str, body: &Body, shirt: &design::Shirt, side: Side) -> Result<TorsoPanel> {
        let front = side == Side::Front;
        let m_width = shirt.width * body.bust;
        let b_width0 = shirt.flare * m_width;
        let body_width = if front { (body.bust - body.back_width) / 2.0 } else { body.back_width / 2.0 };
        let frac = body_width / body.bust;
        let width = frac * m_width;
        let b_width = frac * b_width0;
        let sh_tan = tan_deg(body.derived().shoulder_incl);
        let shoulder_incl = sh_tan * width;
        let mut length = shirt.length * body.waist_line;
        if front {
            let fb_diff = (frac - (0.5 - frac)) * body.bust;
            length -= sh_tan * fb_diff;
        }
        let edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(-b_width, 0.0), v2(-width, length), v2(0.0, length + shoulder_incl)], true)?;
        let panel = a.panel_with_edges(name, edges.clone());
        let outside = a.interface(panel, edges[1]);
        let inside = a.interface(panel, edges.at(-1));
        let shoulder = a.interface(panel, edges.at(-2));
        let match_to = if front { (body.waist - body.waist_back_width) / 2.0 } else { body.waist_back_width / 2.0 };
        let bottom = a.interface_gathered(panel, edges[0], a.edge_length(edges[0]) / match_to)?;
        let shoulder_corner = a.interface(panel, EdgeSeq(vec![edges.at(-3), edges.at(-2)]));
        let collar_corner = a.interface(panel, EdgeSeq(vec![edges.at(-2), edges.at(-1)]));
        let t = TorsoPanel::finish(
            panel,
            [outside, inside, shoulder, bottom, shoulder_corner, collar_corner],
            width,
            WidthRule::SideSlopePlusWidth,
        );
        panel.translate_by(a, v3(0.0, body.height - body.head_l - length - shoulder_incl, 0.0));
        Ok(t)
    }

    /// Fitted front half with a side dart and a waist dart.
    pub fn fitted_front(a: &mut Arena, name: &str, body: &Body) -> Result<TorsoPanel> {
        let d = body.derived();
        let m_bust = body.bust;
        let bust_point = body.bust_points / 2.0;
        let front_frac = (body.bust - body.back_width) / 2.0 / body.bust;
        let width = front_frac * m_bust;
        let waist = (body.waist - body.waist_back_width) / 2.0;
        let sh_tan = tan_deg(d.shoulder_incl);
        let shoulder_incl = sh_tan * width;
        let bottom_d_width = (width - waist) * 2.0 / 3.0;
        let adjustment = sh_tan * (width - body.shoulder_w / 2.0);
        let max_len = body.waist_over_bust_line - adjustment;
        let fb_diff = (front_frac - (0.5 - front_frac)) * body.bust;
        let back_adjustment = sh_tan * (body.back_width / 2.0 - body.shoulder_w / 2.0);
        let side_len = body.waist_line - back_adjustment - sh_tan * fb_diff;
        let mut edges =
            EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(-width, 0.0), v2(-width, max_len), v2(0.0, max_len + shoulder_incl)], false)?;
        edges.close_loop(a)?;
        let panel = a.panel_with_edges(name, EdgeSeq::new());
        // Side dart.
        let bust_line = body.waist_line - d.bust_line;
        let side_d_depth = 0.75 * (width - bust_point);
        let side_d_width = max_len - side_len;
        let shape = dart_shape(a, side_d_width, DartSize::Side(side_d_depth))?;
        let side = edges[1];
        let Cut { edges: s_edge, leftovers: side_interface, .. } =
            panel.add_dart(a, &shape, side, bust_line + side_d_width / 2.0, EdgeSide::Right)?;
        edges.substitute_at(1, &s_edge);
        // Take some fabric from the top to match the shoulder width.
        let tip = a.end(s_edge.last_edge());
        let x_upd = width - body.shoulder_w / 2.0;
        let p = a.pos(tip);
        a.set_pos(tip, Vec2::new(p.x + x_upd, p.y + sh_tan * x_upd));
        // Bottom dart.
        let shape = dart_shape(a, bottom_d_width, DartSize::Side(0.9 * bust_line))?;
        let bottom_edge = edges[0];
        let Cut { edges: b_edge, leftovers: b_interface, .. } =
            panel.add_dart(a, &shape, bottom_edge, bust_point + bottom_d_width / 2.0, EdgeSide::Right)?;
        edges.substitute_at(0, &b_edge);
        let corner = a.end(b_edge.last_edge());
        let p = a.pos(corner);
        a.set_pos(corner, Vec2::new(-(waist + bottom_d_width), p.y));
        panel.set_edges(a, edges.clone());
        let outside = a.interface(panel, side_interface);
        let inside = a.interface(panel, edges.at(-1));
        let shoulder = a.interface(panel, edges.at(-2));
        let bottom = a.interface(panel, b_interface);
        let shoulder_corner = a.interface(panel, EdgeSeq(vec![edges.at(-3), edges.at(-2)]));
        let collar_corner = a.interface(panel, EdgeSeq(vec![edges.at(-2), edges.at(-1)]));
        let t = TorsoPanel::finish(panel, [outside, inside, shoulder, bottom, shoulder_corner, collar_corner], width, WidthRule::SideSlope);
        panel.translate_by(a, v3(0.0, body.height - body.head_l - max_len - shoulder_incl, 0.0));
        Ok(t)
    }

    /// Fitted back half with two waist darts.
    pub fn fitted_back(a: &mut Arena, name: &str, body: &Body) -> Result<TorsoPanel> {
        let d = body.derived();
        let width = body.back_width / 2.0;
        let waist = body.waist_back_width / 2.0;
        let waist_width = if waist < width { width } else { waist };
        let sh_tan = tan_deg(d.shoulder_incl);
        let shoulder_incl = sh_tan * width;
        let back_adjustment = sh_tan * (width - body.shoulder_w / 2.0);
        let length = body.waist_line - back_adjustment;
        let s = a.vertex(v2(0.0, shoulder_incl / 4.0));
        let e = a.vertex(v2(-waist_width, 0.0));
        let edge_0 = crate::skirt_paneled::tangent_curve(a, s, e, Some(v2(-1.0, 0.0)), None, v2(0.5, 0.0))?;
        let v1 = a.vertex(v2(-width, body.waist_line - d.bust_line));
        let v2_ = a.vertex(v2(-width, length));
        let v3_ = a.vertex(v2(0.0, length + shoulder_incl));
        let rest = EdgeSeq::polyline(a, &[e, v1, v2_, v3_], false)?;
        let mut edges = EdgeSeq(vec![edge_0]);
        edges.extend(rest.iter().copied());
        edges.close_loop(a)?;
        let panel = a.panel_with_edges(name, edges.clone());
        let outside = a.interface(panel, EdgeSeq(vec![edges[1], edges[2]]));
        let inside = a.interface(panel, edges.at(-1));
        let shoulder = a.interface(panel, edges.at(-2));
        let mut bottom = a.interface(panel, edges[0]);
        let shoulder_corner = a.interface(panel, EdgeSeq(vec![edges.at(-3), edges.at(-2)]));
        let collar_corner = a.interface(panel, EdgeSeq(vec![edges.at(-2), edges.at(-1)]));
        let t = TorsoPanel::finish(panel, [outside, inside, shoulder, bottom, shoulder_corner, collar_corner], width, WidthRule::Constant);
        // Darts, when the back waist is narrower than the back (QUIRK: the width is
        // the constant half back width whatever the level).
        if waist < t.get_width(a, body, 0.0) {
            let w_diff = waist_width - waist;
            let side_adj = if w_diff < 4.0 { 0.0 } else { w_diff / 6.0 };
            let bottom_d_width = (w_diff - side_adj) / 2.0;
            let bottom_d_depth = 1.0 * (length - d.bust_line);
            let bottom_d_position = body.bum_points / 2.0;
            let dist = bottom_d_position * 0.5;
            let shape = dart_shape(a, bottom_d_width, DartSize::Side(0.9 * bottom_d_depth))?;
            let offset = bottom_d_position + dist / 2.0 + bottom_d_width + bottom_d_width / 2.0;
            let Cut { edges: mut b_edge, leftovers: mut b_interface, .. } = panel.add_dart(a, &shape, edges[0], offset, EdgeSide::Right)?;
            let shape = dart_shape(a, bottom_d_width, DartSize::Side(bottom_d_depth))?;
            let first = b_edge[0];
            let Cut { edges: new_edges, leftovers, .. } =
                panel.add_dart(a, &shape, first, bottom_d_position - dist / 2.0 + bottom_d_width / 2.0, EdgeSide::Right)?;
            b_edge.substitute(first, &new_edges)?;
            b_interface.substitute(first, &leftovers)?;
            let mut loop_edges = panel.edges(a).clone();
            loop_edges.substitute_at(0, &b_edge);
            panel.set_edges(a, loop_edges);
            bottom = a.interface(panel, b_interface);
            let corner = a.end(b_edge.last_edge());
            let p = a.pos(corner);
            a.set_pos(corner, Vec2::new(p.x + side_adj, p.y));
        }
        panel.translate_by(a, v3(0.0, body.height - body.head_l - length - shoulder_incl, 0.0));
        Ok(TorsoPanel { bottom, ..t })
    }
}

/// The design groups one bodice half is built from (the design's own groups, or the
/// left side's of an asymmetric top: see [`Shirt::new`]).
#[derive(Clone, Copy, Debug)]
pub struct HalfGroups<'a> {
    /// Body of the half.
    pub shirt: &'a design::Shirt,
    /// Neckline and collar.
    pub collar: &'a design::Collar,
    /// Sleeve.
    pub sleeve: &'a design::Sleeve,
}

/// The collar component group without a collar.
fn without_collar(c: &CollarComponent) -> CollarComponent {
    CollarComponent { style: None, ..c.clone() }
}

/// The armhole interfaces cut into the torso panels, and the torso widths the sleeve
/// is made for (measured before the cut).
struct Armholes {
    front: InterfaceId,
    back: InterfaceId,
    front_w: f64,
    back_w: f64,
}

/// The neckline cut into the torso panels: the shapes (which the collar follows)
/// and the interfaces over the cut.
struct Neckline {
    shapes: (EdgeSeq, EdgeSeq),
    front: InterfaceId,
    back: InterfaceId,
}

/// One half (right or left) of an upper garment with its sleeve and collar.
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::half_length)]
pub struct BodiceHalf {
    /// `right` or `left`.
    pub name: String,
    /// Front torso panel `<name>_ftorso`.
    #[part]
    pub ftorso: TorsoPanel,
    /// Back torso panel `<name>_btorso`.
    #[part]
    pub btorso: TorsoPanel,
    /// Sleeve (no panels when sleeveless).
    #[part]
    pub sleeve: Option<Sleeve>,
    /// Collar component.
    #[part]
    pub collar: Option<Collar>,
    /// Front hem.
    #[interface]
    pub f_bottom: InterfaceId,
    /// Back hem.
    #[interface]
    pub b_bottom: InterfaceId,
    /// Centre-front seam (with the collar's front, if any).
    #[interface]
    pub front_in: InterfaceId,
    /// Centre-back seam (with the collar's back, if any).
    #[interface]
    pub back_in: InterfaceId,
    /// Sleeve, collar, shoulder and side seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl BodiceHalf {
    /// Build the half `name` (`right` or `left`) from its design groups.
    pub fn new(a: &mut Arena, name: &str, body: &Body, design: &HalfGroups<'_>, fit: Fit) -> Result<BodiceHalf> {
        let (ftorso, btorso) = match fit {
            Fit::Fitted => (
                TorsoPanel::fitted_front(a, &format!("{name}_ftorso"), body)?,
                TorsoPanel::fitted_back(a, &format!("{name}_btorso"), body)?,
            ),
            Fit::Loose => (
                TorsoPanel::loose(a, &format!("{name}_ftorso"), body, design.shirt, Side::Front)?,
                TorsoPanel::loose(a, &format!("{name}_btorso"), body, design.shirt, Side::Back)?,
            ),
        };
        ftorso.panel.translate_by(a, v3(0.0, 0.0, 30.0));
        btorso.panel.translate_by(a, v3(0.0, 0.0, -25.0));
        let mut half = BodiceHalf {
            name: name.to_string(),
            f_bottom: ftorso.bottom,
            b_bottom: btorso.bottom,
            front_in: ftorso.inside,
            back_in: btorso.inside,
            ftorso,
            btorso,
            sleeve: None,
            collar: None,
            stitches: Vec::new(),
        };
        let r = half.eval_dep_params(a, body, design)?;
        if design.shirt.strapless && fit == Fit::Fitted {
            half.make_strapless(a, body, &r)?;
            half.check_torso_outlines(a)?;
        } else {
            let armholes = half.cut_armholes(a, body, design, &r)?;
            let neckline = half.cut_neckline(a, design, &r)?;
            // Before the sleeve and collar panels (the costly part) and the rest.
            half.check_torso_outlines(a)?;
            half.add_collar(a, body, design, &r, neckline)?;
            half.add_sleeve_panels(a, body, design, &r, armholes)?;
            let rule = StitchRule::new(a, half.ftorso.shoulder, half.btorso.shoulder)?;
            half.stitches.push(rule);
        }
        let rule = StitchRule::new(a, half.ftorso.outside, half.btorso.outside)?;
        half.stitches.push(rule);
        Ok(half)
    }

    fn eval_dep_params(&self, a: &Arena, body: &Body, design: &HalfGroups<'_>) -> Result<Resolved> {
        let d = body.derived();
        let max_cwidth = a.edge_length(self.ftorso.shoulder_corner.edges(a)[0]) - 1.0;
        let min_cwidth = d.armscye_depth;
        let v = design.sleeve.connecting_width;
        let connecting_width = f64::min(min_cwidth + min_cwidth * v, max_cwidth);
        let max_w = d.base_sleeve_balance - 2.0;
        let min_w = body.neck_w;
        let w = design.collar.width;
        let width = if w >= 0.0 { lerp(min_w, max_w, w)? } else { lerp(0.0, min_w, 1.0 + w)? };
        let tg = tan_deg(d.shoulder_incl);
        let fw0 = self.ftorso.get_width(a, body, 0.0);
        let bw0 = self.btorso.get_width(a, body, 0.0);
        let f_depth_adj = tg * (fw0 - width / 2.0);
        let b_depth_adj = tg * (bw0 - width / 2.0);
        let max_f_len = a.edge_length(self.ftorso.collar_corner.edges(a)[1]) - tg * fw0 - 1.0;
        let max_b_len = a.edge_length(self.btorso.collar_corner.edges(a)[1]) - tg * bw0 - 1.0;
        let f_strapless_depth = f64::min(design.collar.fc_depth * d.bust_line, max_f_len);
        let b_strapless_depth = f64::min(design.collar.bc_depth * d.bust_line, max_b_len);
        Ok(Resolved {
            connecting_width,
            collar_width: width,
            fc_depth: f_strapless_depth + f_depth_adj,
            bc_depth: b_strapless_depth + b_depth_adj,
            f_strapless_depth,
            b_strapless_depth,
        })
    }

    /// [`PanelId::check_outline`] of both torso panels, once their outlines are cut
    /// (the seams sewn later only split their edges).
    fn check_torso_outlines(&self, a: &Arena) -> Result<()> {
        self.ftorso.panel.check_outline(a)?;
        self.btorso.panel.check_outline(a)
    }

    /// Cut the armholes into the torso panels (the sleeve's shapes, without its
    /// panels yet: see [`BodiceHalf::add_sleeve_panels`]).
    fn cut_armholes(&mut self, a: &mut Arena, body: &Body, design: &HalfGroups<'_>, r: &Resolved) -> Result<Armholes> {
        let front_w = self.ftorso.get_width(a, body, r.connecting_width);
        let back_w = self.btorso.get_width(a, body, r.connecting_width);
        let sleeve = Sleeve::armholes(a, &self.name, body, design.sleeve, r.connecting_width, front_w, back_w)?;
        let front = cut_corner(a, &sleeve.in_front_shape, self.ftorso.shoulder_corner)?.interface;
        let back = cut_corner(a, &sleeve.in_back_shape, self.btorso.shoulder_corner)?.interface;
        self.sleeve = Some(sleeve);
        Ok(Armholes { front, back, front_w, back_w })
    }

    /// Build the sleeve into the armholes cut by [`BodiceHalf::cut_armholes`]. Its
    /// stitch comes first among the half's stitches, as in the reference, which builds
    /// the sleeve before the collar.
    fn add_sleeve_panels(&mut self, a: &mut Arena, body: &Body, design: &HalfGroups<'_>, r: &Resolved, armholes: Armholes) -> Result<()> {
        let Armholes { front: f_int, back: b_int, front_w, back_w } = armholes;
        let sleeve = self.sleeve.as_mut().expect("armholes cut first");
        sleeve.add_panels(a, &self.name, body, design.sleeve, r.connecting_width, front_w, back_w)?;
        if let Some(sleeve_in) = sleeve.in_ {
            let f = f_int.reverse(a, true);
            let b = b_int.reverse(a, false);
            let bodice_int = a.interface_from(&[f, b]);
            self.stitches.insert(0, StitchRule::new(a, sleeve_in, bodice_int)?);
            let gap = -1.0 - body.arm_pose_angle / 10.0;
            sleeve.place_by_interface(a, sleeve_in, bodice_int, gap, Align::Top);
        }
        // QUIRK: labels go to the corner-cut interfaces, which do not see the splits
        // the sleeve stitch made; split armhole edges lose their label.
        let label = format!("{}_armhole", self.name);
        f_int.propagate_label(a, &label);
        b_int.propagate_label(a, &label);
        Ok(())
    }

    /// Cut the neckline into the torso panels (the collar's panels come later: see
    /// [`BodiceHalf::add_collar`]).
    fn cut_neckline(&mut self, a: &mut Arena, design: &HalfGroups<'_>, r: &Resolved) -> Result<Neckline> {
        let shapes = Collar::necklines(a, design.collar, r)?;
        let front = cut_corner(a, &shapes.0, self.ftorso.collar_corner)?.interface;
        let back = cut_corner(a, &shapes.1, self.btorso.collar_corner)?.interface;
        Ok(Neckline { shapes, front, back })
    }

    /// Build the collar over the neckline cut by [`BodiceHalf::cut_neckline`].
    fn add_collar(&mut self, a: &mut Arena, body: &Body, design: &HalfGroups<'_>, r: &Resolved, neckline: Neckline) -> Result<()> {
        let Neckline { shapes, front: fc, back: bc } = neckline;
        let collar = Collar::new(a, &self.name, body, design.collar, r, shapes)?;
        if let Some(bottom) = collar.bottom() {
            let both = a.interface_from(&[fc, bc]);
            self.stitches.push(StitchRule::new(a, both, bottom)?);
        }
        if let Some(front) = collar.front() {
            self.front_in = a.interface_from(&[self.ftorso.inside, front]);
        }
        if let Some(back) = collar.back() {
            self.back_in = a.interface_from(&[self.btorso.inside, back]);
        }
        let label = format!("{}_collar", self.name);
        fc.propagate_label(a, &label);
        bc.propagate_label(a, &label);
        self.collar = Some(collar);
        Ok(())
    }

    fn make_strapless(&mut self, a: &mut Arena, body: &Body, r: &Resolved) -> Result<()> {
        let d = body.derived();
        let shoulder_angle = d.shoulder_incl.to_radians();
        let sleeve_balance = d.base_sleeve_balance / 2.0;
        let back_w = self.btorso.get_width(a, body, 0.0);
        let shoulder_adj = shoulder_angle.tan() * (back_w - sleeve_balance);
        let out_depth = r.connecting_width - shoulder_adj;
        adjust_top_level(a, &self.btorso, out_depth, r.b_strapless_depth, None);
        let len_back = self.btorso.outside.length(a);
        let len_front = self.ftorso.outside.length(a);
        adjust_top_level(a, &self.ftorso, out_depth, r.f_strapless_depth, Some(len_front - len_back));
        self.ftorso.shoulder.propagate_label(a, "strapless_top");
        self.btorso.shoulder.propagate_label(a, "strapless_top");
        Ok(())
    }

    fn half_length(&self, a: &Arena) -> f64 {
        self.btorso.panel.length(a)
    }
}

/// Crop the top of a torso panel for a strapless design: the neck side drops by
/// `in_level`, the shoulder tip by `out_level` along the side seam (for the front,
/// so that it loses exactly `target_remove` of side length).
fn adjust_top_level(a: &mut Arena, panel: &TorsoPanel, out_level: f64, in_level: f64, target_remove: Option<f64>) {
    let top = panel.shoulder.edges(a)[0];
    let (s, e) = (a.start(top), a.end(top));
    let min_y = f64::min(a.pos(s).y, a.pos(e).y);
    let (ins, out) = if a.pos(s).y < a.pos(e).y { (e, s) } else { (s, e) };
    let p = a.pos(ins);
    a.set_pos(ins, Vec2::new(p.x, min_y - in_level));
    let side = panel.outside.edges(a).last_edge();
    let (mut bot, _top_v) = (a.start(side), a.end(side));
    if bot == out {
        bot = a.end(side);
    }
    let mut out_level = out_level;
    let (o, b) = (a.pos(out), a.pos(bot));
    if let Some(target) = target_remove {
        let angle_sin = (o.y - b.y).abs() / a.edge_length(side);
        let curr_remove = out_level / angle_sin;
        let length_diff = target - curr_remove;
        out_level += length_diff * angle_sin;
    }
    let angle_cotan = (o.x - b.x).abs() / (o.y - b.y).abs();
    a.set_pos(out, Vec2::new(o.x - out_level * angle_cotan, min_y - out_level));
}

/// Shirt (loose or fitted): two bodice halves sewn at the centre.
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::shirt_length)]
pub struct Shirt {
    /// `Shirt` or `FittedShirt`.
    pub name: String,
    /// Right half.
    #[part]
    pub right: BodiceHalf,
    /// Left half (mirrored).
    #[part]
    pub left: BodiceHalf,
    /// Hem, around the body.
    #[interface]
    pub bottom: InterfaceId,
    /// Centre seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl Shirt {
    /// Build the shirt from the design's upper-garment groups: `shirt`, `collar` and
    /// `sleeve` for the right half (and both halves of symmetric tops), `left` for
    /// the left half of asymmetric ones.
    pub fn new(
        a: &mut Arena,
        body: &Body,
        shirt: &design::Shirt,
        collar: &design::Collar,
        sleeve: &design::Sleeve,
        left: &design::Left,
        fit: Fit,
    ) -> Result<Shirt> {
        let (right, left) = if left.enable_asym {
            // Collar components need both halves alike: asymmetric tops have none.
            let right_collar = design::Collar { component: without_collar(&collar.component), ..collar.clone() };
            let right = BodiceHalf::new(a, "right", body, &HalfGroups { shirt, collar: &right_collar, sleeve }, fit)?;
            // The left side's own groups, but what meets the right half at the centre
            // seams comes from the right: the shirt length and the neckline depths.
            let left_shirt = design::Shirt { length: shirt.length, ..left.shirt.clone() };
            let left_collar = design::Collar {
                fc_depth: collar.fc_depth,
                bc_depth: collar.bc_depth,
                component: without_collar(&collar.component),
                ..left.collar.clone()
            };
            let groups = HalfGroups { shirt: &left_shirt, collar: &left_collar, sleeve: &left.sleeve };
            (right, BodiceHalf::new(a, "left", body, &groups, fit)?)
        } else {
            let groups = HalfGroups { shirt, collar, sleeve };
            (BodiceHalf::new(a, "right", body, &groups, fit)?, BodiceHalf::new(a, "left", body, &groups, fit)?)
        };
        left.mirror(a);
        let stitches = vec![StitchRule::new(a, right.front_in, left.front_in)?, StitchRule::new(a, right.back_in, left.back_in)?];
        let parts = [right.f_bottom.reverse(a, false), left.f_bottom, left.b_bottom.reverse(a, false), right.b_bottom];
        let bottom = a.interface_from(&parts);
        let name = match fit {
            Fit::Loose => "Shirt",
            Fit::Fitted => "FittedShirt",
        };
        Ok(Shirt { name: name.into(), right, left, bottom, stitches })
    }

    fn shirt_length(&self, a: &Arena) -> f64 {
        self.right.part_length(a)
    }
}
