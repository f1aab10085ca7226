//! Godet skirt: a base skirt with triangular inserts sewn into slits of its hem.

use crate::common::{v2, v3};
use crate::design::{self, GodetBase};
use crate::shared::{BottomOptions, SkirtGroups};
use crate::skirt_paneled::{PencilSkirt, Skirt2};
use garmentcode::math::SignumOrZero;
use garmentcode::ops::{EdgeSide, cut_into_edge, distribute_horizontally};
use garmentcode::slots::{Bottom, Top};
use garmentcode::{Arena, Body, Component, EdgeId, EdgeSeq, InterfaceId, PanelId, PartExt, Result, SlotExt, StitchRule};

/// A triangular insert, apex up.
#[derive(Clone, Debug, Component)]
pub struct GodetInsert {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Both slanted sides, sewn into a slit.
    #[interface]
    pub sides: InterfaceId,
}

impl GodetInsert {
    /// Insert `Insert_<id>`, `width` wide at the hem and `depth` high.
    pub fn new(a: &mut Arena, id: usize, width: f64, depth: f64) -> Result<GodetInsert> {
        let edges = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(width / 2.0, depth), v2(width, 0.0)], true)?;
        let panel = a.panel_with_edges(&format!("Insert_{id}"), edges.clone());
        let sides = a.interface(panel, edges.slice(0, 2));
        panel.top_center_pivot(a);
        panel.center_x(a);
        Ok(GodetInsert { panel, sides })
    }
}

/// The base skirt of a godet skirt.
#[derive(Clone, Debug, Component)]
#[component(slots(Top, Bottom))]
pub enum GodetBaseSkirt {
    /// Two-panel skirt.
    Skirt2(Skirt2),
    /// Pencil skirt.
    Pencil(PencilSkirt),
}

impl GodetBaseSkirt {
    fn rise(&self) -> f64 {
        match self {
            GodetBaseSkirt::Skirt2(s) => s.rise,
            GodetBaseSkirt::Pencil(s) => s.rise,
        }
    }
}

/// Skirt with godets.
#[derive(Clone, Debug, Component)]
#[component(length = Self::skirt_length)]
pub struct GodetSkirt {
    /// Base skirt.
    #[part]
    pub base: GodetBaseSkirt,
    /// Inserts, `ins_<panel>_<i>`.
    #[part]
    pub inserts: Vec<GodetInsert>,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Inserts to slits.
    #[stitches]
    pub stitches: Vec<StitchRule>,
}

impl GodetSkirt {
    /// Build from the `godet-skirt` group on a base skirt from `skirts`, with `opts`
    /// (its rise).
    pub fn new(a: &mut Arena, body: &Body, g: &design::GodetSkirt, skirts: SkirtGroups<'_>, opts: &BottomOptions) -> Result<GodetSkirt> {
        let opts = BottomOptions { without_slits: true, ..opts.clone() };
        let base = match g.base {
            GodetBase::Skirt2 => GodetBaseSkirt::Skirt2(Skirt2::new(a, body, skirts.skirt, &opts)?),
            GodetBase::PencilSkirt => GodetBaseSkirt::Pencil(PencilSkirt::new(a, body, skirts.pencil_skirt, &opts)?),
        };
        let bottom = base.iface::<Bottom>();
        let pairs: Vec<(EdgeId, PanelId)> = bottom.edges(a).iter().copied().zip(bottom.panels(a).iter().copied()).collect();
        let mut skirt = GodetSkirt { top: base.iface::<Top>(), base, inserts: Vec::new(), stitches: Vec::new() };
        let per_edge = g.num_inserts as f64 / pairs.len() as f64;
        for (edge, panel) in pairs {
            skirt.add_inserts(a, edge, panel, g.insert_w as f64, g.insert_depth as f64, per_edge, g.cuts_distance as f64)?;
        }
        Ok(skirt)
    }

    fn add_inserts(
        &mut self,
        a: &mut Arena,
        bottom_edge: EdgeId,
        panel: PanelId,
        ins_w: f64,
        ins_depth: f64,
        num: f64,
        cuts_dist: f64,
    ) -> Result<()> {
        let n = num as usize;
        let bottom_len = a.edge_length(bottom_edge);
        let (lo, hi) = panel.bbox3d(a);
        let t = panel.translation(a);
        let z = t.z + t.z.signum_or_zero() * 5.0;
        let (y_base, x_shift) = (lo.y, (lo.x + hi.x) / 2.0);
        let mut cut_width = (bottom_len - cuts_dist * n as f64) / n as f64;
        let mut cuts_dist = cuts_dist;
        if cut_width < 1.0 {
            cut_width = 1.0;
            cuts_dist = (bottom_len - cut_width * n as f64) / n as f64;
        }
        let insert = GodetInsert::new(a, 0, ins_w, ins_depth)?;
        insert.translate_by(a, v3(x_shift - n as f64 * ins_w / 2.0 + ins_w / 2.0, y_base + ins_depth, z));
        let copies = distribute_horizontally(a, insert, n, -ins_w, &format!("ins_{}", panel.name(a)));
        self.inserts.extend(copies.iter().cloned());
        let side_len = ((ins_w / 2.0).powi(2) + ins_depth.powi(2)).sqrt();
        let cut_depth = if side_len > cut_width / 2.0 {
            (side_len * side_len - (cut_width / 2.0).powi(2)).sqrt()
        } else {
            cut_width = 2.0 * (side_len * side_len - 1.0).sqrt();
            1.0
        };
        let shape = EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(cut_width / 2.0, cut_depth), v2(cut_width, 0.0)], false)?;
        let right = z < 0.0;
        let mut edge = bottom_edge;
        for i in 0..n {
            let offset = cut_width / 2.0 + if i == 0 { cuts_dist / 2.0 } else { cuts_dist };
            let side = if right { EdgeSide::Right } else { EdgeSide::Left };
            let cut = cut_into_edge(a, &shape, edge, offset, side)?;
            let mut loop_edges = std::mem::take(panel.edges_mut(a));
            let res = loop_edges.substitute(edge, &cut.edges);
            *panel.edges_mut(a) = loop_edges;
            res?;
            edge = cut.edges.last_edge();
            let mut cut_i = a.interface(panel, cut.shape);
            if right {
                cut_i = cut_i.reverse(a, false);
            }
            let insert = if right { &copies[n - 1 - i] } else { &copies[i] };
            self.stitches.push(StitchRule::new(a, insert.sides, cut_i)?);
        }
        Ok(())
    }

    /// Rise of the base skirt.
    pub fn rise(&self) -> f64 {
        self.base.rise()
    }

    fn skirt_length(&self, a: &Arena) -> f64 {
        self.base.part_length(a)
    }
}
