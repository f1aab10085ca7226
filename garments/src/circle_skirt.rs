//! Circle skirts: annulus-sector panels, the symmetric circle skirt and the
//! asymmetric (shorter in front) full-circle skirt.

use crate::common::{eval_rise, v2, v3};
use crate::design::FlareSkirt;
use crate::shared::{BottomOptions, GatherTo, Symmetry};
use garmentcode::curves;
use garmentcode::ops::{DartSize, EdgeSide, cut_into_edge, dart_shape};
use garmentcode::{Arena, Body, Component, Curve, EdgeSeq, InterfaceId, PanelId, Result, StitchRule};
use std::f64::consts::PI;

/// A sector of an annulus: circle-skirt panel, fitted waistband, lapel back.
#[derive(Clone, Debug, Component)]
pub struct CircleArcPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Inner arc (waist).
    #[interface]
    pub top: InterfaceId,
    /// Outer arc (hem).
    #[interface]
    pub bottom: InterfaceId,
    /// One side.
    #[interface]
    pub left: InterfaceId,
    /// The other side.
    #[interface]
    pub right: InterfaceId,
}

impl CircleArcPanel {
    /// Sector of inner radius `top_rad`, width `length` and opening `angle` (radians).
    pub fn new(a: &mut Arena, name: &str, top_rad: f64, length: f64, angle: f64, gather: GatherTo) -> Result<CircleArcPanel> {
        let half = angle / 2.0;
        let dist_w = 2.0 * top_rad * half.sin();
        let dist_out = 2.0 * (top_rad + length) * half.sin();
        let vert_len = length * half.cos();
        let large = half > PI / 2.0;
        let p0 = a.vertex(v2(-dist_w / 2.0, 0.0));
        let p1 = a.vertex(v2(dist_w / 2.0, 0.0));
        let cy = curves::cy_from_radius(a.pos(p0), a.pos(p1), top_rad, large, true);
        let top = a.edge(p0, p1, Curve::Arc { cy })?;
        let p2 = a.vertex(v2(dist_out / 2.0, -vert_len));
        let side = a.edge(p1, p2, Curve::Line)?;
        let p3 = a.vertex(v2(-dist_out / 2.0, -vert_len));
        let cy = curves::cy_from_radius(a.pos(p2), a.pos(p3), top_rad + length, large, false);
        let bottom = a.edge(p2, p3, Curve::Arc { cy })?;
        let mut edges = EdgeSeq(vec![top, side, bottom]);
        edges.close_loop(a)?;
        let panel = a.panel_with_edges(name, edges.clone());
        Self::interfaces(a, panel, &edges, gather)
    }

    fn interfaces(a: &mut Arena, panel: PanelId, edges: &EdgeSeq, gather: GatherTo) -> Result<CircleArcPanel> {
        let top_ruffle = gather.top.map(|m| a.edge_length(edges[0]) / m).unwrap_or(1.0);
        let top = a.interface_gathered(panel, edges[0], top_ruffle)?.reverse(a, true);
        let bottom_ruffle = gather.bottom.map(|m| a.edge_length(edges[2]) / m).unwrap_or(1.0);
        let bottom = a.interface_gathered(panel, edges[2], bottom_ruffle)?;
        let left = a.interface(panel, edges[1]);
        let right = a.interface(panel, edges[3]);
        panel.set_length_interface(a, right);
        Ok(CircleArcPanel { panel, top, bottom, left, right })
    }

    /// Sector from its width, top width and fullness (`sun_fraction` of a circle).
    pub fn from_w_length_suns(
        a: &mut Arena,
        name: &str,
        length: f64,
        top_width: f64,
        sun_fraction: f64,
        gather: GatherTo,
    ) -> Result<CircleArcPanel> {
        let arc = sun_fraction * 2.0 * PI;
        let rad = top_width / arc;
        CircleArcPanel::new(a, name, rad, length, arc, gather)
    }

    /// Sector from its width and the lengths of its two arcs. QUIRK: no guard for
    /// equal or inverted widths (division by zero / inverted panel).
    pub fn from_all_length(
        a: &mut Arena,
        name: &str,
        length: f64,
        top_width: f64,
        bottom_width: f64,
        gather: GatherTo,
    ) -> Result<CircleArcPanel> {
        let diff = bottom_width - top_width;
        let arc = diff / length;
        let rad = top_width / arc;
        CircleArcPanel::new(a, name, rad, length, arc, gather)
    }
}

/// Half of an off-centre full-circle skirt.
#[derive(Clone, Debug, Component)]
pub struct AsymHalfCirclePanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Waist arc.
    #[interface]
    pub top: InterfaceId,
    /// Hem arc.
    #[interface]
    pub bottom: InterfaceId,
    /// One side.
    #[interface]
    pub left: InterfaceId,
    /// The other side.
    #[interface]
    pub right: InterfaceId,
}

impl AsymHalfCirclePanel {
    /// Half circle of radius `top_rad`, `length_f` long at the centre and `length_s` at the sides.
    pub fn new(a: &mut Arena, name: &str, top_rad: f64, length_f: f64, length_s: f64, gather: GatherTo) -> Result<AsymHalfCirclePanel> {
        let dist_w = 2.0 * top_rad;
        let dist_out = 2.0 * (top_rad + length_s);
        let p0 = a.vertex(v2(-dist_w / 2.0, 0.0));
        let p1 = a.vertex(v2(dist_w / 2.0, 0.0));
        let cy = curves::cy_from_radius(a.pos(p0), a.pos(p1), top_rad, false, true);
        let top = a.edge(p0, p1, Curve::Arc { cy })?;
        let p2 = a.vertex(v2(dist_out / 2.0, 0.0));
        let side = a.edge(p1, p2, Curve::Line)?;
        let p3 = a.vertex(v2(-dist_out / 2.0, 0.0));
        let cy = curves::cy_from_three_points(a.pos(p2), a.pos(p3), v2(0.0, -(top_rad + length_f)));
        let bottom = a.edge(p2, p3, Curve::Arc { cy })?;
        let mut edges = EdgeSeq(vec![top, side, bottom]);
        edges.close_loop(a)?;
        let panel = a.panel_with_edges(name, edges.clone());
        let c = CircleArcPanel::interfaces(a, panel, &edges, GatherTo { bottom: None, ..gather })?;
        Ok(AsymHalfCirclePanel { panel, top: c.top, bottom: c.bottom, left: c.left, right: c.right })
    }
}

/// Front or back panel of a circle skirt.
#[derive(Clone, Debug)]
pub enum CirclePanel {
    /// Symmetric sector.
    Sector(CircleArcPanel),
    /// Asymmetric half circle.
    Half(AsymHalfCirclePanel),
}

impl CirclePanel {
    fn parts(&self) -> (PanelId, InterfaceId, InterfaceId, InterfaceId, InterfaceId) {
        match self {
            CirclePanel::Sector(p) => (p.panel, p.top, p.bottom, p.left, p.right),
            CirclePanel::Half(p) => (p.panel, p.top, p.bottom, p.left, p.right),
        }
    }
}

/// Circle skirt (symmetric sectors, or the asymmetric full circle).
#[derive(Clone, Debug, Component)]
#[component(length = Self::skirt_length)]
pub struct SkirtCircle {
    /// Front panel.
    #[part]
    pub front: PanelId,
    /// Back panel.
    #[part]
    pub back: PanelId,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Front hem.
    #[interface]
    pub bottom_f: InterfaceId,
    /// Back hem.
    #[interface]
    pub bottom_b: InterfaceId,
    /// Whole hem.
    #[interface]
    pub bottom: InterfaceId,
    /// Side seams.
    #[stitches]
    pub stitches: Vec<StitchRule>,
    /// Rise the skirt sits at.
    pub rise: f64,
}

impl SkirtCircle {
    /// Build from the `flare-skirt` group, symmetric or not, with `opts` (the hem cut
    /// is its slit).
    pub fn new(a: &mut Arena, body: &Body, d: &FlareSkirt, symmetry: Symmetry, opts: &BottomOptions) -> Result<SkirtCircle> {
        let rise = opts.rise.unwrap_or(d.rise);
        let (waist, hips_depth, _) = eval_rise(body, rise)?;
        let length = opts.length.unwrap_or(hips_depth + d.length * body.derived().leg_length);
        let length = length.max(5.0);
        let name = |base: &str| opts.name(base);
        let waist_level = body.derived().waist_level;
        let (front, back) = if symmetry == Symmetry::Symmetric {
            let f = CircleArcPanel::from_w_length_suns(
                a,
                &name("skirt_front"),
                length,
                waist / 2.0,
                d.suns / 2.0,
                GatherTo::top(body.waist - body.waist_back_width),
            )?;
            f.panel.translate_by(a, v3(0.0, waist_level, 15.0));
            let b = CircleArcPanel::from_w_length_suns(
                a,
                &name("skirt_back"),
                length,
                waist / 2.0,
                d.suns / 2.0,
                GatherTo::top(body.waist_back_width),
            )?;
            b.panel.translate_by(a, v3(0.0, waist_level, -15.0));
            (CirclePanel::Sector(f), CirclePanel::Sector(b))
        } else {
            let w_rad = waist / 2.0 / PI;
            let f_length = d.asymm.front_length * length;
            let tot_len = w_rad * 2.0 + length + f_length;
            let del_r = tot_len / 2.0 - f_length - w_rad;
            let s_length = ((tot_len / 2.0).powi(2) - del_r * del_r).sqrt() - w_rad;
            let f = AsymHalfCirclePanel::new(
                a,
                &name("skirt_front"),
                w_rad,
                f_length,
                s_length,
                GatherTo::top(body.waist - body.waist_back_width),
            )?;
            f.panel.translate_by(a, v3(0.0, waist_level, 15.0));
            let b = AsymHalfCirclePanel::new(a, &name("skirt_back"), w_rad, length, s_length, GatherTo::top(body.waist_back_width))?;
            b.panel.translate_by(a, v3(0.0, waist_level, -15.0));
            (CirclePanel::Half(f), CirclePanel::Half(b))
        };
        let (fp, ftop, fbottom, fleft, fright) = front.parts();
        let (bp, btop, bbottom, bleft, bright) = back.parts();
        if d.cut.add && !opts.without_slits {
            if d.cut.place > 0.0 {
                add_cut(a, fp, fbottom, d, length)?;
            } else {
                add_cut(a, bp, bbottom, d, length)?;
            }
        }
        let stitches = vec![StitchRule::new(a, fright, bright)?, StitchRule::new(a, fleft, bleft)?];
        let top = a.interface_from(&[ftop, btop]);
        let bottom = a.interface_from(&[fbottom, bbottom]);
        Ok(SkirtCircle { front: fp, back: bp, top, bottom_f: fbottom, bottom_b: bbottom, bottom, stitches, rise })
    }

    fn skirt_length(&self, a: &Arena) -> f64 {
        self.front.length(a)
    }
}

/// Cut an open slit into the hem of a circle-skirt panel.
fn add_cut(a: &mut Arena, panel: PanelId, bottom: InterfaceId, d: &FlareSkirt, sk_length: f64) -> Result<()> {
    let (width, depth) = (d.cut.width * sk_length, d.cut.depth * sk_length);
    let target = bottom.edges(a)[0];
    let t_len = a.edge_length(target);
    let offset = (d.cut.place * t_len).abs().max(width / 2.0).min(t_len - width / 2.0);
    // QUIRK: the side is decided from the current (post-orientation) edge direction.
    let side = if a.pos(a.start(target)).x > a.pos(a.end(target)).x { EdgeSide::Right } else { EdgeSide::Left };
    let shape = dart_shape(a, width, DartSize::Depth(depth))?;
    let cut = cut_into_edge(a, &shape, target, offset, side)?;
    let mut loop_edges = std::mem::take(panel.edges_mut(a));
    let res = loop_edges.substitute(target, &cut.edges);
    *panel.edges_mut(a) = loop_edges;
    res?;
    bottom.substitute(a, target, &cut.leftovers, panel)
}
