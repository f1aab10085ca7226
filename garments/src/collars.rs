//! Necklines and collar components: the plain neckline (no panels), turtle neck,
//! simple lapel and two-panel hood.

use crate::bands::StraightBandPanel;
use crate::circle_skirt::CircleArcPanel;
use crate::common::{v2, v3};
use crate::design::{self, CollarStyle};
use crate::shapes::{self, NeckArgs};
use crate::shared::{GatherTo, Resolved};
use garmentcode::curves::match_tangents;
use garmentcode::{Arena, Body, Component, Curve, Edge, EdgeSeq, InterfaceId, PanelId, Result, Rotation, StitchRule};

/// The lapel's front piece.
#[derive(Clone, Debug, Component)]
pub struct SimpleLapelPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Edge sewn to the lapel back.
    #[interface]
    pub to_collar: InterfaceId,
    /// Edge sewn to the bodice.
    #[interface]
    pub to_bodice: InterfaceId,
}

impl SimpleLapelPanel {
    /// A `max_depth × length` piece with a curved outer edge.
    pub fn new(a: &mut Arena, name: &str, length: f64, max_depth: f64) -> Result<SimpleLapelPanel> {
        let mut edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(max_depth, 0.0), v2(max_depth, -length)], false)?;
        let (s, e) = (a.end(edges.last_edge()), a.start(edges[0]));
        edges.push(a.edge(s, e, Curve::Quadratic(v2(0.7, 0.2)))?);
        let panel = a.panel_with_edges(name, edges.clone());
        let to_collar = a.interface(panel, edges[0]);
        let to_bodice = a.interface(panel, edges[1]);
        Ok(SimpleLapelPanel { panel, to_collar, to_bodice })
    }
}

/// One side of the two-piece hood; its bottom follows the necklines.
#[derive(Clone, Debug, Component)]
pub struct HoodPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Seam with the other hood half.
    #[interface]
    pub to_other_side: InterfaceId,
    /// Seam with the bodice neckline.
    #[interface]
    pub to_bodice: InterfaceId,
}

impl HoodPanel {
    /// Hood side over necklines of the given depths and lengths.
    pub fn new(
        a: &mut Arena,
        name: &str,
        f_depth: f64,
        b_depth: f64,
        f_length: f64,
        b_length: f64,
        width: f64,
        in_length: f64,
        depth: f64,
    ) -> Result<HoodPanel> {
        let width = width / 2.0;
        let length = in_length + width / 2.0;
        let fit = |start, end, c1, c2, target: f64| {
            let e = Edge { start, end, curve: Curve::Cubic(c1, c2) };
            match_tangents(&e, v2(1.0, 0.0), v2(1.0, 0.0), target)
        };
        let back_curve = fit(v2(-width, -b_depth), v2(0.0, 0.0), v2(0.3, -0.2), v2(0.6, 0.2), b_length);
        let bottom_back = a.add_edge(back_curve)?;
        let front_curve = fit(a.pos(a.end(bottom_back)), v2(width, -f_depth), v2(0.3, 0.2), v2(0.6, -0.2), f_length);
        // The two fitted curves meet at equal coordinates but separate vertices.
        let bottom_front = a.add_edge(front_curve)?;
        let top = EdgeSeq::from_points(a, &[v2(width * 1.2, length), v2(width * 1.2 - depth, length)], false)?;
        let (fe, ts) = (a.end(bottom_front), a.start(top[0]));
        let link = a.edge(fe, ts, Curve::Line)?;
        let mut edges = EdgeSeq(vec![bottom_back, bottom_front, link, top[0]]);
        let (s, e) = (a.end(edges.last_edge()), a.start(edges[0]));
        edges.push(a.edge(s, e, Curve::Quadratic(v2(0.2, -0.5)))?);
        let panel = a.panel_with_edges(name, edges.clone());
        let to_other_side = a.interface(panel, edges.slice(-2, edges.len() as isize));
        let to_bodice = a.interface(panel, edges.slice(0, 2)).reverse(a, false);
        panel.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, -90.0, 0.0]));
        panel.translate_by(a, v3(-width, 0.0, 0.0));
        Ok(HoodPanel { panel, to_other_side, to_bodice })
    }
}

/// Turtle-neck band (`Turtle_<side>`).
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::collar_length)]
pub struct Turtle {
    /// Component name.
    pub name: String,
    /// Front band.
    #[part]
    pub front: StraightBandPanel,
    /// Back band.
    #[part]
    pub back: StraightBandPanel,
    /// Front centre seam.
    #[interface]
    pub front_i: InterfaceId,
    /// Back centre seam.
    #[interface]
    pub back_i: InterfaceId,
    /// Sewn to the neckline.
    #[interface]
    pub bottom: InterfaceId,
    /// Side seam.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl Turtle {
    fn collar_length(&self, a: &Arena) -> f64 {
        self.back_i.length(a)
    }
}

/// Simple lapel (the reference names it `Turtle_<side>` too).
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::collar_length)]
pub struct SimpleLapel {
    /// Component name.
    pub name: String,
    /// Front piece.
    #[part]
    pub front: SimpleLapelPanel,
    /// Back piece (band or arc).
    #[part]
    pub back: PanelId,
    /// Back centre seam.
    #[interface]
    pub back_i: InterfaceId,
    /// Sewn to the neckline.
    #[interface]
    pub bottom: InterfaceId,
    /// Front to back.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl SimpleLapel {
    fn collar_length(&self, a: &Arena) -> f64 {
        self.back_i.length(a)
    }
}

/// Two-panel hood (`Hood_<side>`).
#[derive(Clone, Debug, Component)]
#[component(name = self.name, length = Self::collar_length)]
pub struct Hood2Panels {
    /// Component name.
    pub name: String,
    /// The hood half.
    #[part]
    pub panel: HoodPanel,
    /// Seam with the other half.
    #[interface]
    pub back: InterfaceId,
    /// Sewn to the neckline.
    #[interface]
    pub bottom: InterfaceId,
}

impl Hood2Panels {
    fn collar_length(&self, a: &Arena) -> f64 {
        self.panel.panel.length(a)
    }
}

/// The collar of one bodice half.
#[derive(Clone, Debug, Component)]
pub enum Collar {
    /// Just the neckline.
    NoPanels(NoCollar),
    /// Turtle neck.
    Turtle(Turtle),
    /// Lapel.
    Lapel(SimpleLapel),
    /// Hood.
    Hood(Hood2Panels),
}

/// The collar of a plain neckline: no panels.
#[derive(Clone, Debug, Component)]
#[component(name = "NoPanelsCollar")]
pub struct NoCollar {}

impl Collar {
    /// The front and back neckline shapes the collar style cuts into the torso:
    /// known before the collar's panels are built ([`Collar::new`]).
    pub fn necklines(a: &mut Arena, c: &design::Collar, r: &Resolved) -> Result<(EdgeSeq, EdgeSeq)> {
        let width = r.collar_width;
        Ok(match c.component.style {
            None => {
                let f = NeckArgs { angle: c.fc_angle as f64, flip: c.f_flip_curve, x: c.f_bezier_x, y: c.f_bezier_y };
                let b = NeckArgs { angle: c.bc_angle as f64, flip: c.b_flip_curve, x: c.b_bezier_x, y: c.b_bezier_y };
                (shapes::neckline(a, c.f_collar, r.fc_depth, width, f)?, shapes::neckline(a, c.b_collar, r.bc_depth, width, b)?)
            }
            Some(CollarStyle::Turtle | CollarStyle::Hood2Panels) => {
                (shapes::circle_neck(a, r.fc_depth, width)?, shapes::circle_neck(a, r.bc_depth, width)?)
            }
            Some(CollarStyle::SimpleLapel) => {
                // QUIRK: the lapel does not pass the Bézier parameters to the front
                // neckline (its defaults x = 0.5, y = 0.3 apply).
                let args = NeckArgs { angle: c.fc_angle as f64, flip: c.f_flip_curve, x: 0.5, y: 0.3 };
                (shapes::neckline(a, c.f_collar, r.fc_depth, width, args)?, shapes::circle_neck(a, r.bc_depth, width)?)
            }
        })
    }

    /// Build the collar component the design asks for (none or unknown: just the
    /// neckline) over the `necklines` made by [`Collar::necklines`].
    pub fn new(a: &mut Arena, tag: &str, body: &Body, c: &design::Collar, r: &Resolved, necklines: (EdgeSeq, EdgeSeq)) -> Result<Collar> {
        let width = r.collar_width;
        let (f, b) = necklines;
        match c.component.style {
            None => Ok(Collar::NoPanels(NoCollar {})),
            Some(CollarStyle::Turtle) => {
                let depth = c.component.depth as f64;
                let (lf, lb) = (f.length(a), b.length(a));
                let hp = body.height - body.head_l + depth;
                let front = StraightBandPanel::new(a, &format!("{tag}_collar_front"), lf, depth, GatherTo::NONE)?;
                front.panel.translate_by(a, v3(-lf / 2.0, hp, 10.0));
                let back = StraightBandPanel::new(a, &format!("{tag}_collar_back"), lb, depth, GatherTo::NONE)?;
                back.panel.translate_by(a, v3(-lb / 2.0, hp, -10.0));
                let stitches = vec![StitchRule::new(a, front.right, back.right)?];
                let bottom = a.interface_from(&[front.bottom, back.bottom]);
                let t = Turtle { name: format!("Turtle_{tag}"), front_i: front.left, back_i: back.left, front, back, bottom, stitches };
                Ok(Collar::Turtle(t))
            }
            Some(CollarStyle::SimpleLapel) => {
                let depth = c.component.depth as f64;
                let (lf, lb) = (f.length(a), b.length(a));
                let hp = body.height - body.head_l + depth * 2.0;
                let front = SimpleLapelPanel::new(a, &format!("{tag}_collar_front"), lf, depth)?;
                front.panel.translate_by(a, v3(-depth * 2.0, hp, 35.0));
                let (back_panel, back_right, back_left, back_bottom) = if c.component.lapel_standing {
                    let back = StraightBandPanel::new(a, &format!("{tag}_collar_back"), lb, depth, GatherTo::NONE)?;
                    back.panel.translate_by(a, v3(-lb / 2.0, hp, -10.0));
                    back.right.set_right_wrong(a, true);
                    (back.panel, back.right, back.left, back.bottom)
                } else {
                    let (rad, angle, _) = a.geom(b[0]).arc_radius_angle().expect("a circular neckline");
                    let back = CircleArcPanel::new(a, &format!("{tag}_collar_back"), rad, depth, angle, GatherTo::NONE)?;
                    back.panel.translate_by(a, v3(-lb, hp, -10.0));
                    back.panel.rotate_by(a, Rotation::from_euler_xyz_degrees([90.0, 45.0, 0.0]));
                    let top = back.top.set_right_wrong(a, true);
                    (back.panel, back.right, back.left, top)
                };
                let stitches = vec![StitchRule::new(a, front.to_collar, back_right)?];
                let to_bodice = front.to_bodice.set_right_wrong(a, true);
                let bottom = a.interface_from(&[to_bodice, back_bottom]);
                let l = SimpleLapel { name: format!("Turtle_{tag}"), front, back: back_panel, back_i: back_left, bottom, stitches };
                Ok(Collar::Lapel(l))
            }
            Some(CollarStyle::Hood2Panels) => {
                let (lf, lb) = (f.length(a), b.length(a));
                let panel = HoodPanel::new(
                    a,
                    &format!("{tag}_hood"),
                    r.fc_depth,
                    r.bc_depth,
                    lf,
                    lb,
                    width,
                    body.head_l * c.component.hood_length,
                    width / 2.0 * c.component.hood_depth,
                )?;
                panel.panel.translate_by(a, v3(0.0, body.height - body.head_l + 10.0, 0.0));
                let h = Hood2Panels { name: format!("Hood_{tag}"), back: panel.to_other_side, bottom: panel.to_bodice, panel };
                Ok(Collar::Hood(h))
            }
        }
    }

    /// Interface sewn to the neckline, if the collar has panels.
    pub fn bottom(&self) -> Option<InterfaceId> {
        match self {
            Collar::NoPanels(_) => None,
            Collar::Turtle(t) => Some(t.bottom),
            Collar::Lapel(l) => Some(l.bottom),
            Collar::Hood(h) => Some(h.bottom),
        }
    }

    /// Interface joining the centre-front seam.
    pub fn front(&self) -> Option<InterfaceId> {
        match self {
            Collar::Turtle(t) => Some(t.front_i),
            _ => None,
        }
    }

    /// Interface joining the centre-back seam.
    pub fn back(&self) -> Option<InterfaceId> {
        match self {
            Collar::Turtle(t) => Some(t.back_i),
            Collar::Lapel(l) => Some(l.back_i),
            Collar::Hood(h) => Some(h.back),
            Collar::NoPanels(_) => None,
        }
    }
}
