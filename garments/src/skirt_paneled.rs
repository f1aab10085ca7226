//! Paneled skirts: the two-panel skirt, the many-gore skirt and the fitted pencil
//! skirt with darts, slits and decorative side cuts.

use crate::common::{eval_rise, tan_deg, v2, v3};
use crate::design::{self, SideCut};
use crate::shapes;
use crate::shared::{BottomOptions, Darts, GatherTo, Pleating};
use garmentcode::curves::quadratic_from_tangents;
use garmentcode::math::close_enough;
use garmentcode::ops::{Cut, DartSize, EdgeSide, ShapeOrder, cut_into_edge, cut_many_into_edge, dart_shape, distribute_y, side_with_cut};
use garmentcode::{
    Arena, Body, Component, Curve, EdgeId, EdgeSeq, Gather, InterfaceId, PanelId, Result, Rotation, StitchRule, Vec2, Vec3, VertexId,
};
use std::f64::consts::PI;

/// A quadratic edge between two vertices with end tangents fitted as the reference's
/// `curve_from_tangents` does.
pub(crate) fn tangent_curve(a: &mut Arena, s: VertexId, e: VertexId, t0: Option<Vec2>, t1: Option<Vec2>, guess: Vec2) -> Result<EdgeId> {
    let curve = quadratic_from_tangents(a.pos(s), a.pos(e), t0, t1, guess);
    a.edge(s, e, curve)
}

/// One panel of a two-panel skirt: a trapezoid with an optionally gathered waist and
/// optional side slits at the hem.
#[derive(Clone, Debug, Component)]
pub struct SkirtPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Right side (above the slit).
    #[interface]
    pub right: InterfaceId,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Left side (above the slit).
    #[interface]
    pub left: InterfaceId,
    /// Hem.
    #[interface]
    pub bottom: InterfaceId,
}

impl SkirtPanel {
    /// Trapezoid of waist `waist_length·ruffles` widened by `flare` per side at the
    /// hem; the waist gathered to `gather.top` (or by `ruffles` when not set). With
    /// `pleats`, the waist is wider by what they take in and they are laid into it,
    /// so that its flat parts are `waist_length·ruffles` long.
    pub fn new(
        a: &mut Arena,
        name: &str,
        waist_length: f64,
        length: f64,
        ruffles: f64,
        gather: GatherTo,
        bottom_cut: f64,
        flare: f64,
        pleats: Option<Pleating>,
    ) -> Result<SkirtPanel> {
        let top_width = waist_length * ruffles + pleats.map_or(0.0, |p| p.intake());
        let low_width = top_width + 2.0 * flare;
        let x_shift_top = (low_width - top_width) / 2.0;
        let origin = a.vertex(v2(0.0, 0.0));
        let waist_start = a.vertex(v2(x_shift_top, length));
        let right = if bottom_cut != 0.0 {
            side_with_cut(a, origin, waist_start, bottom_cut / length, 0.0)?
        } else {
            EdgeSeq(vec![a.edge(origin, waist_start, Curve::Line)?])
        };
        let waist_end = a.vertex(v2(x_shift_top + top_width, length));
        let waist = a.edge(waist_start, waist_end, Curve::Line)?;
        let low = a.vertex(v2(low_width, 0.0));
        let left = if bottom_cut != 0.0 {
            side_with_cut(a, waist_end, low, 0.0, bottom_cut / length)?
        } else {
            EdgeSeq(vec![a.edge(waist_end, low, Curve::Line)?])
        };
        let bottom = a.edge(low, origin, Curve::Line)?;
        let mut edges = right.clone();
        edges.push(waist);
        edges.extend(left.iter().copied());
        edges.push(bottom);
        let panel = a.panel_with_edges(name, edges);
        let r = a.interface(panel, right.last_edge());
        let waist = match pleats {
            None => EdgeSeq::from(waist),
            Some(p) => {
                let mark = (length / 3.0).min(20.0);
                garmentcode::inner::pleats(a, &panel, "waist", waist, p.count, p.depth, p.kind, mark)?.flat
            }
        };
        let ruffle = match gather.top {
            Some(m) => waist.length(a) / m,
            None => ruffles,
        };
        let top = a.interface_gathered(panel, waist, ruffle)?.reverse(a, true);
        let l = a.interface(panel, left[0]);
        let b = a.interface(panel, bottom);
        panel.top_center_pivot(a);
        panel.center_x(a);
        Ok(SkirtPanel { panel, right: r, top, left: l, bottom: b })
    }
}

/// One gore of the many-panel skirt: a trapezoid with an optionally curved hem.
#[derive(Clone, Debug, Component)]
pub struct ThinSkirtPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Side towards the previous gore.
    #[interface]
    pub right: InterfaceId,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Side towards the next gore.
    #[interface]
    pub left: InterfaceId,
    /// Hem.
    #[interface]
    pub bottom: InterfaceId,
}

impl ThinSkirtPanel {
    /// Gore of the given top and bottom widths; `b_curvature` bends the hem.
    pub fn new(a: &mut Arena, name: &str, top_width: f64, bottom_width: f64, length: f64, b_curvature: f64) -> Result<ThinSkirtPanel> {
        let flare = (bottom_width - top_width) / 2.0;
        let mut edges = EdgeSeq::from_points(
            a,
            &[v2(0.0, 0.0), v2(flare, length), v2(flare + top_width, length), v2(flare * 2.0 + top_width, 0.0)],
            false,
        )?;
        if close_enough(b_curvature, 0.0, 1e-4) {
            edges.close_loop(a)?;
        } else {
            let (s, e) = (a.end(edges.last_edge()), a.start(edges[0]));
            let through = garmentcode::math::rel_to_abs(a.pos(s), a.pos(e), v2(0.5, b_curvature));
            let cy = garmentcode::curves::cy_from_three_points(a.pos(s), a.pos(e), through);
            edges.push(a.edge(s, e, Curve::Arc { cy })?);
        }
        let panel = a.panel_with_edges(name, edges.clone());
        let pivot = a.pos(a.end(edges[0]));
        panel.set_pivot(a, pivot, false);
        let right = a.interface(panel, edges[0]);
        let top = a.interface(panel, edges[1]);
        let left = a.interface(panel, edges[2]);
        let bottom = a.interface(panel, edges.last_edge());
        Ok(ThinSkirtPanel { panel, right, top, left, bottom })
    }
}

/// Options of a fitted skirt panel that differ between front and back.
pub struct FittedPanelSpec<'s> {
    /// Half-panel waist width.
    pub waist: f64,
    /// Half-panel hip width.
    pub hips: f64,
    /// Waist-to-hip depth.
    pub hips_depth: f64,
    /// Length below the hip line.
    pub length: f64,
    /// Extension of the hip depth (back panels).
    pub hipline_ext: f64,
    /// Distance of the darts from the centre.
    pub dart_position: f64,
    /// Dart depth as a fraction of the hip depth.
    pub dart_frac: f64,
    /// One or two darts per side.
    pub darts: Darts,
    /// Waist measure the top interface's gathers are proportioned to.
    pub match_top_int_to: Option<f64>,
    /// Centre slit (fraction of the length).
    pub slit: f64,
    /// Left side slit (fraction of the side).
    pub left_slit: f64,
    /// Right side slit (fraction of the side).
    pub right_slit: f64,
    /// Decorative side cut shapes.
    pub side_cut: Option<&'s SideCutShape>,
    /// The side cut as drawn or mirrored.
    pub side_cut_order: ShapeOrder,
}

/// A decorative cut: one chain, or several chains drawn in one frame.
#[derive(Clone, Debug)]
pub enum SideCutShape {
    /// One chain.
    Single(EdgeSeq),
    /// Several chains with vertical openings.
    Many(Vec<EdgeSeq>),
}

/// Pencil-skirt panel: hips and waist fitted with darts and the side slope.
#[derive(Clone, Debug, Component)]
pub struct FittedSkirtPanel {
    /// The panel.
    #[panel]
    pub panel: PanelId,
    /// Hem.
    #[interface]
    pub bottom: InterfaceId,
    /// Right side seam.
    #[interface]
    pub right: InterfaceId,
    /// Left side seam.
    #[interface]
    pub left: InterfaceId,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
}

impl FittedSkirtPanel {
    /// Build the panel from the pencil-skirt design and the per-side spec.
    pub fn new(a: &mut Arena, name: &str, body: &Body, design: &design::PencilSkirt, s: &FittedPanelSpec) -> Result<FittedSkirtPanel> {
        let d = body.derived();
        let low_angle = design.low_angle as f64;
        let hip_side_incl = d.hip_inclination.to_radians();
        let flare = design.flare;
        let low_width = body.hips * (flare - 1.0) / 4.0 + s.hips;
        let adj_hips_depth = s.hips_depth * s.hipline_ext;
        let dart_depth = s.hips_depth * s.dart_frac;
        let dart_depth = f64::max(dart_depth - (s.hips_depth - adj_hips_depth), 0.0);
        let w_diff = s.hips - s.waist;
        let mut hw_shift = hip_side_incl.tan() * adj_hips_depth;
        if hw_shift > w_diff {
            hw_shift = w_diff;
        }
        let angle_shift = tan_deg(low_angle) * low_width;
        let straight = close_enough(flare, 1.0, 1e-4);
        let p0 = a.vertex(v2(s.hips - low_width, angle_shift));
        let p1 = a.vertex(v2(0.0, s.length));
        let mut right_bottom =
            if straight { a.edge(p0, p1, Curve::Line)? } else { tangent_curve(a, p0, p1, None, Some(v2(0.0, 1.0)), v2(0.75, 0.0))? };
        let p2 = a.vertex(v2(hw_shift, s.length + adj_hips_depth));
        let right_top = tangent_curve(a, p1, p2, Some(v2(0.0, 1.0)), None, v2(0.5, 0.0))?;
        let mut right = EdgeSeq(vec![right_bottom, right_top]);
        let p3 = a.vertex(v2(s.hips * 2.0 - hw_shift, s.length + adj_hips_depth));
        let top = a.edge(p2, p3, Curve::Line)?;
        let p4 = a.vertex(v2(s.hips * 2.0, s.length));
        let left_top = tangent_curve(a, p3, p4, None, Some(v2(0.0, -1.0)), v2(0.5, 0.0))?;
        let p5 = a.vertex(v2(s.hips + low_width, -angle_shift));
        let mut left_bottom =
            if straight { a.edge(p4, p5, Curve::Line)? } else { tangent_curve(a, p4, p5, Some(v2(0.0, -1.0)), None, v2(0.25, 0.0))? };
        let mut left = EdgeSeq(vec![left_top, left_bottom]);
        let mut edges = EdgeSeq(vec![right_bottom, right_top, top, left_top, left_bottom]);
        edges.close_loop(a)?;
        let hem = edges.last_edge();
        let mut bottom = EdgeSeq(vec![hem]);
        let panel = a.new_panel(name);
        if s.slit != 0.0 {
            let shape = dart_shape(a, 2.0, DartSize::Depth(s.slit * s.length))?;
            let len = a.edge_length(hem);
            let cut = cut_into_edge(a, &shape, hem, len / 2.0, EdgeSide::Right)?;
            edges.substitute(hem, &cut.edges)?;
            bottom = cut.leftovers;
        }
        if s.left_slit != 0.0 {
            let frac = s.left_slit;
            let pieces = a.subdivide(left_bottom, &[1.0 - frac, frac], true)?;
            left.substitute(left_bottom, &pieces[..1])?;
            edges.substitute(left_bottom, &pieces)?;
            left_bottom = pieces[0];
        }
        if s.right_slit != 0.0 {
            let frac = s.right_slit;
            let pieces = a.subdivide(right_bottom, &[frac, 1.0 - frac], true)?;
            right.substitute(right_bottom, &pieces[1..])?;
            edges.substitute(right_bottom, &pieces)?;
            right_bottom = pieces[1];
        }
        let _ = right_bottom;
        if let Some(shape) = s.side_cut {
            // QUIRK: any failure to fit the decorative cut silently skips it.
            let len = a.edge_length(left_bottom);
            let cut = match shape {
                SideCutShape::Single(seq) => cut_into_edge(a, seq, left_bottom, len / 2.0, EdgeSide::Right),
                SideCutShape::Many(seqs) => cut_many_into_edge(a, seqs, left_bottom, len / 2.0, EdgeSide::Right, s.side_cut_order),
            };
            if let Ok(cut) = cut {
                edges.substitute(left_bottom, &cut.edges)?;
                left.substitute(left_bottom, &cut.edges)?;
            }
        }
        panel.set_edges(a, edges.clone());
        panel.top_center_pivot(a);
        panel.set_translation(a, Vec3::new(-s.hips / 2.0, 5.0, 0.0));
        let bottom_i = a.interface(panel, bottom);
        let mut right_ruffle = vec![1.0; right.len() - 1];
        right_ruffle.push(s.hipline_ext);
        let right_i = a.interface_gathered(panel, right.clone(), Gather::PerEdge(right_ruffle))?;
        let mut left_ruffle = vec![s.hipline_ext];
        left_ruffle.extend(vec![1.0; left.len() - 1]);
        let left_i = a.interface_gathered(panel, left.clone(), Gather::PerEdge(left_ruffle))?;
        set_flip(a, left_i, 0);
        let last = right.len() - 1;
        set_flip(a, right_i, last);
        let top_i = if w_diff > hw_shift {
            let (top_edges, int_edges) =
                add_darts(a, panel, top, w_diff - hw_shift, dart_depth, s.dart_position, s.darts, DartsFrom::Middle)?;
            let ruffle = s.match_top_int_to.map(|m| int_edges.length(a) / m).unwrap_or(1.0);
            let i = a.interface_gathered(panel, int_edges, ruffle)?;
            let mut loop_edges = panel.edges(a).clone();
            loop_edges.substitute(top, &top_edges)?;
            panel.set_edges(a, loop_edges);
            i
        } else {
            let ruffle = s.match_top_int_to.map(|m| a.edge_length(top) / m).unwrap_or(1.0);
            a.interface_gathered(panel, top, ruffle)?
        };
        Ok(FittedSkirtPanel { panel, bottom: bottom_i, right: right_i, left: left_i, top: top_i })
    }
}

/// Mark edge `i` of an interface as "treat as reversed" for stitch matching.
pub(crate) fn set_flip(a: &mut Arena, i: InterfaceId, edge: usize) {
    i.set_flip(a, edge, true);
}

/// Where waist darts are measured from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum DartsFrom {
    /// The middle of the waist edge (skirts: darts on both sides).
    Middle,
    /// The end of the waist edge (trousers).
    End,
}

/// Cut waist darts into `top`, measured from the middle of the edge (skirts) or from
/// its end (trousers). Returns the edges replacing `top` and the remaining waist
/// pieces.
pub(crate) fn add_darts(
    a: &mut Arena,
    panel: PanelId,
    top: EdgeId,
    dart_width: f64,
    dart_depth: f64,
    dart_position: f64,
    darts: Darts,
    from: DartsFrom,
) -> Result<(EdgeSeq, EdgeSeq)> {
    let top_len = a.edge_length(top);
    let (double_dart, from_middle) = (darts == Darts::Double, from == DartsFrom::Middle);
    let (offsets, darts): (Vec<f64>, Vec<EdgeSeq>) = if from_middle {
        if double_dart {
            let dist = dart_position * 0.5;
            let offsets = vec![
                -(dart_position + dist / 2.0 + dart_width / 2.0) - dart_width / 4.0,
                -(dart_position - dist / 2.0) - dart_width / 4.0,
                dart_position - dist / 2.0 + dart_width / 4.0,
                dart_position + dist / 2.0 + dart_width / 2.0 + dart_width / 4.0,
            ];
            let full = dart_shape(a, dart_width / 2.0, DartSize::Side(dart_depth))?;
            let small = dart_shape(a, dart_width / 2.0, DartSize::Side(dart_depth * 0.9))?;
            (offsets, vec![small.clone(), full.clone(), full, small])
        } else {
            let offsets = vec![-dart_position - dart_width / 2.0, dart_position + dart_width / 2.0];
            let shape = dart_shape(a, dart_width, DartSize::Side(dart_depth))?;
            (offsets, vec![shape.clone(), shape])
        }
    } else if double_dart {
        let dist = dart_position * 0.5;
        let offsets =
            vec![-(dart_position + dist / 2.0 + dart_width / 2.0 + dart_width / 4.0), -(dart_position - dist / 2.0) - dart_width / 4.0];
        let small = dart_shape(a, dart_width / 2.0, DartSize::Side(dart_depth * 0.9))?;
        let full = dart_shape(a, dart_width / 2.0, DartSize::Side(dart_depth))?;
        (offsets, vec![small, full])
    } else {
        (vec![-dart_position - dart_width / 2.0], vec![dart_shape(a, dart_width, DartSize::Side(dart_depth))?])
    };
    let mut top_edges = EdgeSeq(vec![top]);
    let mut int_edges = EdgeSeq(vec![top]);
    for (off, dart) in offsets.iter().zip(darts.iter()) {
        let last = top_edges.last_edge();
        let left_len = a.edge_length(last);
        let offset = if from_middle { (left_len - top_len / 2.0) + off } else { left_len + off };
        let Cut { edges: new_edges, leftovers, .. } = panel.add_dart(a, dart, last, offset, EdgeSide::Right)?;
        top_edges.substitute(last, &new_edges)?;
        int_edges.substitute(last, &leftovers)?;
    }
    Ok((top_edges, int_edges))
}

/// Fitted pencil skirt.
#[derive(Clone, Debug, Component)]
#[component(length = Self::skirt_length)]
pub struct PencilSkirt {
    /// Front panel.
    #[part]
    pub front: FittedSkirtPanel,
    /// Back panel.
    #[part]
    pub back: FittedSkirtPanel,
    /// Front waist.
    #[interface]
    pub top_f: InterfaceId,
    /// Back waist.
    #[interface]
    pub top_b: InterfaceId,
    /// Whole waist.
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
    /// Hem tilt (degrees), read by tiered skirts.
    pub low_angle: f64,
}

impl PencilSkirt {
    /// Build from the `pencil-skirt` group with `opts` (a length there includes the
    /// hip depth).
    pub fn new(a: &mut Arena, body: &Body, d: &design::PencilSkirt, opts: &BottomOptions) -> Result<PencilSkirt> {
        let (shape_l, shape_r) = match d.style_side_cut {
            None => (None, None),
            Some(kind) => {
                let depth = 0.7 * (body.hips / 4.0 - body.bust_points / 2.0);
                match kind {
                    SideCut::Sun => {
                        let s = shapes::sun(a, depth * 1.5, depth, 6, depth * 0.2)?;
                        (Some(SideCutShape::Single(s.clone())), Some(SideCutShape::Single(s)))
                    }
                    SideCut::SIGGRAPH_logo => {
                        let (l, r) = shapes::siggraph_logo(a, depth * 1.5)?;
                        (Some(SideCutShape::Many(l)), Some(SideCutShape::Many(r)))
                    }
                }
            }
        };
        let rise = opts.rise.unwrap_or(d.rise);
        let (waist, hips_depth, back_waist) = eval_rise(body, rise)?;
        let length = match opts.length {
            None => d.length * body.derived().leg_length,
            Some(l) => l - hips_depth,
        };
        let pick = |x: f64| if opts.without_slits { 0.0 } else { x };
        let waist_level = body.derived().waist_level;
        let front = FittedSkirtPanel::new(
            a,
            "skirt_front",
            body,
            d,
            &FittedPanelSpec {
                waist: (waist - back_waist) / 2.0,
                hips: (body.hips - body.hip_back_width + opts.hip_ease / 2.0) / 2.0,
                hips_depth,
                length,
                hipline_ext: 1.0,
                dart_position: body.bust_points / 2.0,
                dart_frac: 0.8,
                darts: Darts::Single,
                match_top_int_to: Some(body.waist - body.waist_back_width),
                slit: pick(d.front_slit),
                left_slit: pick(d.left_slit),
                right_slit: pick(d.right_slit),
                side_cut: shape_l.as_ref(),
                side_cut_order: ShapeOrder::AsDrawn,
            },
        )?;
        front.panel.translate_to(a, v3(0.0, waist_level, 25.0));
        let back = FittedSkirtPanel::new(
            a,
            "skirt_back",
            body,
            d,
            &FittedPanelSpec {
                waist: back_waist / 2.0,
                hips: (body.hip_back_width + opts.hip_ease / 2.0) / 2.0,
                hips_depth,
                length,
                hipline_ext: 1.05,
                dart_position: body.bum_points / 2.0,
                dart_frac: 0.85,
                darts: Darts::Double,
                match_top_int_to: Some(body.waist_back_width),
                slit: pick(d.back_slit),
                left_slit: pick(d.left_slit),
                right_slit: pick(d.right_slit),
                side_cut: shape_r.as_ref(),
                side_cut_order: ShapeOrder::AsDrawn,
            },
        )?;
        back.panel.translate_to(a, v3(0.0, waist_level, -20.0));
        let stitches = vec![StitchRule::new(a, front.right, back.right)?, StitchRule::new(a, front.left, back.left)?];
        let f_top = front.top.flip_edges(a);
        let b_top = back.top.reverse(a, true);
        let top = a.interface_from(&[f_top, b_top]);
        let bottom = a.interface_from(&[front.bottom, back.bottom]);
        Ok(PencilSkirt {
            top_f: front.top,
            top_b: back.top,
            top,
            bottom_f: front.bottom,
            bottom_b: back.bottom,
            bottom,
            front,
            back,
            stitches,
            rise,
            low_angle: d.low_angle as f64,
        })
    }

    fn skirt_length(&self, a: &Arena) -> f64 {
        self.front.panel.length(a)
    }
}

/// Two-panel skirt.
#[derive(Clone, Debug, Component)]
#[component(length = Self::skirt_length)]
pub struct Skirt2 {
    /// Front panel.
    #[part]
    pub front: SkirtPanel,
    /// Back panel.
    #[part]
    pub back: SkirtPanel,
    /// Front waist.
    #[interface]
    pub top_f: InterfaceId,
    /// Back waist.
    #[interface]
    pub top_b: InterfaceId,
    /// Whole waist.
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

impl Skirt2 {
    /// Build from the `skirt` group with `opts`.
    pub fn new(a: &mut Arena, body: &Body, d: &design::Skirt, opts: &BottomOptions) -> Result<Skirt2> {
        let rise = opts.rise.unwrap_or(d.rise);
        let (waist, hip_line, back_waist) = eval_rise(body, rise)?;
        let length = opts.length.unwrap_or(hip_line + d.length * body.derived().leg_length).max(5.0);
        let name = |base: &str| opts.name(base);
        let ruffles = if opts.without_gathers { 1.0 } else { d.ruffle };
        // QUIRK: the slit is scaled by the length *parameter*, not the length in cm.
        let bottom_cut = if opts.without_slits { 0.0 } else { d.bottom_cut * d.length };
        let waist_level = body.derived().waist_level;
        let flare = d.flare as f64;
        let front = SkirtPanel::new(
            a,
            &name("skirt_front"),
            waist - back_waist,
            length,
            ruffles,
            GatherTo::top(body.waist - body.waist_back_width),
            bottom_cut,
            flare,
            opts.pleats.map(|p| p[0]),
        )?;
        front.panel.translate_to(a, v3(0.0, waist_level, 25.0));
        // Placed in front, the panel is turned round (its edges reversed, see
        // `autonorm`); its waist's edges, made before, still list from the right as at
        // the back. Pleats split the waist into flat parts: list them the other way so
        // that the band pairs each with the part it lies against, not its mirror
        // image (one edge, unpleated: no change).
        front.top.reverse(a, false);
        let back = SkirtPanel::new(
            a,
            &name("skirt_back"),
            back_waist,
            length,
            ruffles,
            GatherTo::top(body.waist_back_width),
            bottom_cut,
            flare,
            opts.pleats.map(|p| p[1]),
        )?;
        back.panel.translate_to(a, v3(0.0, waist_level, -20.0));
        let stitches = vec![StitchRule::new(a, front.right, back.right)?, StitchRule::new(a, front.left, back.left)?];
        let top = a.interface_from(&[front.top, back.top]);
        let bottom = a.interface_from(&[front.bottom, back.bottom]);
        Ok(Skirt2 {
            top_f: front.top,
            top_b: back.top,
            top,
            bottom_f: front.bottom,
            bottom_b: back.bottom,
            bottom,
            front,
            back,
            stitches,
            rise,
        })
    }

    fn skirt_length(&self, a: &Arena) -> f64 {
        self.front.panel.length(a)
    }
}

/// Skirt of many gores distributed around the body.
#[derive(Clone, Debug, Component)]
#[component(length = Self::skirt_length)]
pub struct SkirtManyPanels {
    /// The gores, `skirt_panel_0..n`.
    #[part]
    pub panels: Vec<ThinSkirtPanel>,
    /// Waist.
    #[interface]
    pub top: InterfaceId,
    /// Seams between neighbouring gores.
    #[stitches]
    pub stitches: Vec<StitchRule>,
    /// Rise the skirt sits at.
    pub rise: f64,
}

impl SkirtManyPanels {
    /// Build from the `flare-skirt` group with `opts` (its rise).
    pub fn new(a: &mut Arena, body: &Body, d: &design::FlareSkirt, opts: &BottomOptions) -> Result<SkirtManyPanels> {
        let rise = opts.rise.unwrap_or(d.rise);
        let (waist, hip_line, _) = eval_rise(body, rise)?;
        let n = d.skirt_many_panels.n_panels as usize;
        let length = (hip_line + d.length * body.derived().leg_length).max(5.0);
        let flare_coeff_pi = 1.0 + d.suns * length * 2.0 * PI / waist;
        let panel_w = waist / n as f64;
        let front = ThinSkirtPanel::new(a, "front", panel_w, panel_w * flare_coeff_pi, length, d.skirt_many_panels.panel_curve)?;
        let p = front.panel;
        let dist = front.bottom.length(a) / (2.0 * (PI / n as f64).tan());
        p.translate_to(a, v3(-dist, body.derived().waist_level, 0.0));
        p.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, -90.0, 0.0]));
        p.rotate_align(a, v3(-dist, 0.0, panel_w / 2.0));
        front.top.reverse(a, true);
        let panels = distribute_y(a, front, n, "skirt_panel");
        let mut stitches = Vec::with_capacity(n);
        for i in 1..n {
            stitches.push(StitchRule::new(a, panels[i - 1].left, panels[i].right)?);
        }
        stitches.push(StitchRule::new(a, panels[n - 1].left, panels[0].right)?);
        let tops: Vec<InterfaceId> = panels.iter().map(|p| p.top).collect();
        let top = a.interface_from(&tops);
        Ok(SkirtManyPanels { panels, top, stitches, rise })
    }

    fn skirt_length(&self, a: &Arena) -> f64 {
        self.panels[0].panel.length(a)
    }
}
