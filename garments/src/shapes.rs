//! Shapes projected into panels: half necklines, armholes (with the inverted sleeve
//! opening) and decorative side cuts. Each is an open chain of edges in its own
//! frame; `cut_corner` / `cut_into_edge` place copies of it.

use crate::common::v2;
use crate::design::NeckShape;
use garmentcode::curves::{self, match_tangents};
use garmentcode::math::{close_enough, norm};
use garmentcode::parity::svgpath::{SvgPath, halves_from_outlines};
use garmentcode::{Arena, Curve, Edge, EdgeSeq, Result, SvgArc, Vec2};

/// Parameters of a half neckline shape.
#[derive(Clone, Copy, Debug)]
pub struct NeckArgs {
    /// Angle of trapezoid and arc necklines, degrees.
    pub angle: f64,
    /// Mirror the curvature.
    pub flip: bool,
    /// Bézier control point x.
    pub x: f64,
    /// Bézier control point y.
    pub y: f64,
}

/// A half neckline from (0, 0) to (width/2, −depth).
pub fn neckline(a: &mut Arena, shape: NeckShape, depth: f64, width: f64, args: NeckArgs) -> Result<EdgeSeq> {
    let end = v2(width / 2.0, -depth);
    match shape {
        NeckShape::VNeckHalf => v_neck(a, depth, width),
        NeckShape::SquareNeckHalf => EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(0.0, -depth), end], false),
        NeckShape::TrapezoidNeckHalf => {
            let angle = args.angle;
            if close_enough(angle, 180.0, 1.0) || close_enough(angle, 0.0, 1.0) {
                return v_neck(a, depth, width);
            }
            let rad = angle.to_radians();
            let bottom_x = -depth * rad.cos() / rad.sin();
            if bottom_x > width / 2.0 {
                // The shape would overlap itself: the reference falls back to a V.
                return v_neck(a, depth, width);
            }
            EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(bottom_x, -depth), end], false)
        }
        NeckShape::CurvyNeckHalf => {
            let sign = if args.flip { -1.0 } else { 1.0 };
            let e = a.add_edge(Edge { start: v2(0.0, 0.0), end, curve: Curve::Cubic(v2(0.4, sign * 0.3), v2(0.8, sign * -0.3)) })?;
            Ok(EdgeSeq(vec![e]))
        }
        NeckShape::CircleArcNeckHalf => {
            let cy = curves::cy_from_angle(args.angle.to_radians(), !args.flip);
            Ok(EdgeSeq(vec![a.add_edge(Edge { start: v2(0.0, 0.0), end, curve: Curve::Arc { cy } })?]))
        }
        NeckShape::CircleNeckHalf => circle_neck(a, depth, width),
        NeckShape::Bezier2NeckHalf => {
            let sign = if args.flip { 1.0 } else { -1.0 };
            let e = a.add_edge(Edge { start: v2(0.0, 0.0), end, curve: Curve::Quadratic(v2(args.x, sign * args.y)) })?;
            Ok(EdgeSeq(vec![e]))
        }
    }
}

fn v_neck(a: &mut Arena, depth: f64, width: f64) -> Result<EdgeSeq> {
    Ok(EdgeSeq(vec![a.line(v2(0.0, 0.0), v2(width / 2.0, -depth))?]))
}

/// Half of a circular arc through (0,0), (width/2, −depth) and (width, 0): stitched
/// to its mirror image it forms a perfect arc.
pub fn circle_neck(a: &mut Arena, depth: f64, width: f64) -> Result<EdgeSeq> {
    let (s, e) = (v2(0.0, 0.0), v2(width, 0.0));
    let cy = curves::cy_from_three_points(s, e, v2(width / 2.0, -depth));
    let full = a.add_edge(Edge { start: s, end: e, curve: Curve::Arc { cy } })?;
    let halves = a.subdivide(full, &[0.5, 0.5], true)?;
    Ok(EdgeSeq(vec![halves[0]]))
}

/// Straight armhole cut: `(0,0) → (incl, 0) → (incl, width)`.
pub fn armhole_square(a: &mut Arena, incl: f64, width: f64) -> Result<EdgeSeq> {
    EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(incl, 0.0), v2(incl, width)], false)
}

/// Angled armhole cut.
pub fn armhole_angle(a: &mut Arena, incl: f64, width: f64, incl_coeff: f64, w_coeff: f64) -> Result<EdgeSeq> {
    EdgeSeq::from_points(a, &[v2(0.0, 0.0), v2(incl * (1.0 - incl_coeff), w_coeff * width), v2(incl, width)], false)
}

/// Curved armhole cut `(0,0) → (incl, width)`.
pub fn armhole_curve(a: &mut Arena, incl: f64, width: f64) -> Result<EdgeSeq> {
    Ok(EdgeSeq(vec![a.add_edge(armhole_cut(incl, width).reversed())?]))
}

/// The curve of [`armhole_curve`], from the armhole's bottom up.
fn armhole_cut(incl: f64, width: f64) -> Edge {
    Edge { start: v2(incl, width), end: v2(0.0, 0.0), curve: Curve::Cubic(v2(0.5, 0.2), v2(0.8, 0.35)) }
}

/// The sleeve opening matching the curved armhole cut of [`armhole_curve`]: the cut's
/// curve turned down by the sleeve's rest `angle`, re-fitted so it leaves vertically
/// and keeps the cut's length (the inversion, the costly part of a sleeve).
pub fn sleeve_opening(a: &mut Arena, incl: f64, width: f64, angle: f64, bottom_angle_mix: f64) -> Result<EdgeSeq> {
    let cut = armhole_cut(incl, width);
    let reversed = cut.reversed();
    // QUIRK: reversing the reference's edge mutated its control-point list, so the
    // initial guess is derived from the *reversed* points with the last y negated.
    let Curve::Cubic(c1, c2) = reversed.curve else { unreachable!() };
    let inv_cps = (c1, v2(c2.x, -c2.y));
    let start = v2(incl, width);
    let down = v2(0.0, -1.0);
    let inv = Edge { start, end: start + down * cut.chord_length(), curve: Curve::Cubic(inv_cps.0, inv_cps.1) }.rotated(-angle);
    let shortcut = inv.end - inv.start;
    let rotated_dir = shortcut / norm(shortcut);
    let left = v2(-1.0, 0.0);
    let mix = bottom_angle_mix;
    let dir = (1.0 - mix) * rotated_dir + if mix > 0.0 { mix * down } else { -mix * left };
    let opening = match_tangents(&inv, down, dir, cut.length()).reversed();
    Ok(EdgeSeq(vec![a.add_edge(opening)?]))
}

/// Sun-like decorative cut: rays alternating between two concentric arcs.
pub fn sun(a: &mut Arena, width: f64, depth: f64, n_rays: usize, d_rays: f64) -> Result<EdgeSeq> {
    let out_cy = curves::cy_from_three_points(v2(0.0, 0.0), v2(width, 0.0), v2(width / 2.0, depth));
    let in_cy = curves::cy_from_three_points(v2(d_rays, 0.0), v2(width - d_rays, 0.0), v2(width / 2.0, depth - d_rays));
    let out_edge = Edge { start: v2(0.0, 0.0), end: v2(width, 0.0), curve: Curve::Arc { cy: out_cy } };
    let in_edge = Edge { start: v2(d_rays, 0.0), end: v2(width - d_rays, 0.0), curve: Curve::Arc { cy: in_cy } };
    let (out_curve, in_curve) = (curves::svg_arc(out_edge.start, out_edge.end, out_cy), curves::svg_arc(in_edge.start, in_edge.end, in_cy));
    let (out_len, in_len) = (out_edge.length(), in_edge.length());
    let (out_stride, in_stride) = (out_len / n_rays as f64, in_len / n_rays as f64);
    let sample = |c: &SvgArc, length: f64, stride: f64, n: usize, shift: f64| -> Vec<Vec2> {
        (0..n).map(|i| c.point((shift + i as f64 * stride) / length)).collect()
    };
    let outer = sample(&out_curve, out_len, out_stride, n_rays, out_stride / 2.0);
    let inner = sample(&in_curve, in_len, in_stride, n_rays + 1, 0.0);
    let mut verts = outer;
    for (i, p) in inner.into_iter().enumerate() {
        verts.insert(i * 2, p);
    }
    EdgeSeq::from_points(a, &verts, false)
}

/// The SIGGRAPH logo split into left and right halves of chains (decorative cut),
/// `width` high: the bundled outlines ([`crate::logo`]) through
/// [`garmentcode::parity::svgpath::halves_from_outlines`]. Which short pieces are left out
/// depends on the scale, so the halves are computed for every width.
pub fn siggraph_logo(a: &mut Arena, width: f64) -> Result<(Vec<EdgeSeq>, Vec<EdgeSeq>)> {
    let outlines: Vec<SvgPath> = crate::logo::OUTLINES.iter().map(|o| SvgPath(o.to_vec())).collect();
    halves_from_outlines(a, &outlines, Some(width))
}
