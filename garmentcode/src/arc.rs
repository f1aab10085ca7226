//! Circular arcs.
//!
//! An arc edge stores only `cy`, the relative height of its midpoint above the chord
//! (positive = left of `start → end`); radius, sweep and flags follow from the chord.
//! [`SvgArc`] is the explicit centre parametrisation (the SVG implementation-notes
//! algorithm) used to evaluate, sample and crop arcs the way the reference does.

use crate::math::{Vec2, norm, rel_to_abs, vector_angle};
use std::f64::consts::PI;

/// Radius relative to the chord length, for an arc whose midpoint is at relative
/// height `cy` (circumradius of the triangle (0,0), (1,0), (0.5, cy) by Heron's formula,
/// as the reference computes it).
pub fn rel_radius(cy: f64) -> f64 {
    let a = 1.0;
    let b = norm(Vec2::new(0.5, cy));
    let c = norm(Vec2::new(0.5 - 1.0, cy));
    let p = (a + b + c) / 2.0;
    a * b * c / (p * (p - a) * (p - b) * (p - c)).sqrt() / 4.0
}

/// Whether the arc spans more than half a circle.
pub fn is_large(cy: f64) -> bool {
    cy.abs() > rel_radius(cy)
}

/// Angle swept by the arc, in radians.
pub fn sweep_angle(cy: f64) -> f64 {
    let rho = rel_radius(cy);
    let arc = 2.0 * (1.0 / rho / 2.0).clamp(-1.0, 1.0).asin();
    if is_large(cy) { 2.0 * PI - arc } else { arc }
}

/// `cy` of the arc from `start` to `end` with the given absolute radius.
///
/// `right` makes the arc bulge to the right of `start → end`. Like the reference,
/// a radius within `1e-3` (in squared units) of half the chord gives a half circle,
/// and a radius shorter than half the chord gives NaN.
pub fn cy_from_radius(start: Vec2, end: Vec2, radius: f64, large_arc: bool, right: bool) -> f64 {
    let dist = norm(end - start);
    let h = if (radius * radius - dist * dist / 4.0).abs() < 1e-3 { 0.0 } else { (radius * radius - dist * dist / 4.0).sqrt() };
    let cy = if large_arc { radius + h } else { radius - h };
    let cy = cy / dist;
    if right { -cy } else { cy }
}

/// `cy` of the arc spanning `angle` radians (more than π: the large arc).
pub fn cy_from_angle(angle: f64, right: bool) -> f64 {
    let (angle, to_sum) = if angle > PI { (2.0 * PI - angle, true) } else { (angle, false) };
    let radius = 1.0 / (angle / 2.0).sin() / 2.0;
    let h = 1.0 / (angle / 2.0).tan() / 2.0;
    let cy = if to_sum { radius + h } else { radius - h };
    if right { -cy } else { cy }
}

/// `cy` of the arc from `start` to `end` passing through `point` (any point of the
/// circle; the circle through the three points defines the radius).
pub fn cy_from_three_points(start: Vec2, end: Vec2, point: Vec2) -> f64 {
    // Circumcentre through complex arithmetic, as in the reference.
    let (x, y, z) = (start, point, end);
    let w = cdiv(z - x, y - x);
    let w_abs2 = w.x.hypot(w.y).powi(2);
    // c = (x − y)·(w − |w|²) / 2j / w.imag − x
    let num = cmul(x - y, Vec2::new(w.x - w_abs2, w.y));
    let div2j = cdiv(num, Vec2::new(0.0, 2.0));
    let c = div2j / w.y - x;
    let rad = (c + x).x.hypot((c + x).y);
    let mid_dist = norm(point - (start + end) / 2.0);
    let angle = vector_angle(point - start, end - start);
    cy_from_radius(start, end, rad, mid_dist > rad, angle > 0.0)
}

fn cmul(a: Vec2, b: Vec2) -> Vec2 {
    Vec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

fn cdiv(a: Vec2, b: Vec2) -> Vec2 {
    // Python's complex division (Smith's algorithm).
    let (ar, ai, br, bi) = (a.x, a.y, b.x, b.y);
    if br.abs() >= bi.abs() {
        if br == 0.0 && bi == 0.0 {
            return Vec2::new(f64::NAN, f64::NAN);
        }
        let ratio = bi / br;
        let denom = br + bi * ratio;
        Vec2::new((ar + ai * ratio) / denom, (ai - ar * ratio) / denom)
    } else {
        let ratio = br / bi;
        let denom = br * ratio + bi;
        Vec2::new((ar * ratio + ai) / denom, (ai * ratio - ar) / denom)
    }
}

/// An arc with an explicit centre: start and end points, radius, and the SVG flags
/// (`sweep` = counter-clockwise in a y-up frame = bulging to the right).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvgArc {
    /// Start point.
    pub start: Vec2,
    /// End point.
    pub end: Vec2,
    /// Radius (scaled up if the chord is longer than the diameter).
    pub radius: f64,
    /// Spans more than 180°.
    pub large_arc: bool,
    /// Counter-clockwise around the centre (y up).
    pub sweep: bool,
    /// Centre of the circle.
    pub center: Vec2,
    /// Angle of the start point around the centre, degrees.
    pub theta: f64,
    /// Signed swept angle, degrees.
    pub delta: f64,
}

impl SvgArc {
    /// Build the centre parametrisation from end points, radius and flags.
    pub fn new(start: Vec2, end: Vec2, radius: f64, large_arc: bool, sweep: bool) -> SvgArc {
        let mut rx = radius.abs();
        let mut rx_sqd = rx * rx;
        let zp1 = (start - end) / 2.0;
        let (x1p, y1p) = (zp1.x, zp1.y);
        let x1p_sqd = x1p * x1p;
        let y1p_sqd = y1p * y1p;
        let radius_check = x1p_sqd / rx_sqd + y1p_sqd / rx_sqd;
        if radius_check > 1.0 {
            rx *= radius_check.sqrt();
            rx_sqd = rx * rx;
        }
        let tmp = rx_sqd * y1p_sqd + rx_sqd * x1p_sqd;
        let radicand = (rx_sqd * rx_sqd - tmp) / tmp;
        let radical = if radicand.abs() <= 1e-8 { 0.0 } else { radicand.sqrt() };
        let base = Vec2::new(rx * y1p / rx, -(rx * x1p / rx));
        let cp = if large_arc == sweep { -radical * base } else { radical * base };
        let center = cp + (start + end) / 2.0;
        let clip = |v: Vec2| Vec2::new(v.x.clamp(-1.0, 1.0), v.y.clamp(-1.0, 1.0));
        let u1 = clip(Vec2::new((x1p - cp.x) / rx, (y1p - cp.y) / rx));
        let u2 = clip(Vec2::new((-x1p - cp.x) / rx, (-y1p - cp.y) / rx));
        let degrees = |r: f64| r * (180.0 / PI);
        let theta = if u1.y > 0.0 {
            degrees(u1.x.acos())
        } else if u1.y < 0.0 {
            -degrees(u1.x.acos())
        } else if u1.x > 0.0 {
            0.0
        } else {
            180.0
        };
        let det_uv = u1.x * u2.y - u1.y * u2.x;
        let dot = u1.x * u2.x + u1.y * u2.y;
        let acosand = dot.clamp(-1.0, 1.0);
        let mut delta = if det_uv > 0.0 {
            degrees(acosand.acos())
        } else if det_uv < 0.0 {
            -degrees(acosand.acos())
        } else if dot > 0.0 {
            0.0
        } else {
            180.0
        };
        if !sweep && delta >= 0.0 {
            delta -= 360.0;
        } else if large_arc && delta <= 0.0 {
            delta += 360.0;
        }
        SvgArc { start, end, radius: rx, large_arc, sweep, center, theta, delta }
    }

    /// Point at parameter `t` (uniform in angle, hence in arc length).
    pub fn point(&self, t: f64) -> Vec2 {
        let angle = (self.theta + t * self.delta) * PI / 180.0;
        Vec2::new(self.radius * angle.cos() + self.center.x, self.radius * angle.sin() + self.center.y)
    }

    /// Arc length.
    pub fn length(&self) -> f64 {
        self.radius * (self.delta * PI / 180.0).abs()
    }

    /// Tangent direction (not normalised) at `t`.
    pub fn derivative(&self, t: f64) -> Vec2 {
        let angle = (self.theta + t * self.delta) * PI / 180.0;
        let k = self.delta * PI / 180.0;
        Vec2::new(-self.radius * angle.sin(), self.radius * angle.cos()) * k
    }

    /// The part between the parameters `t0` and `t1`, as a new arc through the
    /// cropped end points (same radius and sweep).
    pub fn crop(&self, t0: f64, t1: f64) -> SvgArc {
        let large = (self.delta * (t1 - t0)).abs() > 180.0;
        SvgArc::new(self.point(t0), self.point(t1), self.radius, large, self.sweep)
    }
}

/// Centre parametrisation of the arc edge `start → end` with midpoint height `cy`.
pub fn svg_arc(start: Vec2, end: Vec2, cy: f64) -> SvgArc {
    let radius = rel_radius(cy) * norm(end - start);
    SvgArc::new(start, end, radius, is_large(cy), cy < 0.0)
}

/// Absolute midpoint of the arc edge.
pub fn midpoint(start: Vec2, end: Vec2, cy: f64) -> Vec2 {
    rel_to_abs(start, end, Vec2::new(0.5, cy))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn worked_example_of_the_format() {
        // pattern-format.md §12: arc from (0,40) to (0,0) through (−5,20).
        let (s, e) = (v(0., 40.), v(0., 0.));
        let cy = cy_from_three_points(s, e, v(-5., 20.));
        assert!((cy + 0.125).abs() < 1e-12, "{cy}");
        assert!((rel_radius(cy) * 40.0 - 42.5).abs() < 1e-9);
        assert!(!is_large(cy));
        let len = rel_radius(cy) * 40.0 * sweep_angle(cy);
        assert!((len - 41.6464).abs() < 1e-4);
        let arc = svg_arc(s, e, cy);
        assert!((arc.center - v(37.5, 20.0)).length() < 1e-9);
        assert!((arc.point(0.5) - v(-5.0, 20.0)).length() < 1e-9);
        assert!((arc.point(0.0) - s).length() < 1e-9);
        assert!((arc.point(1.0) - e).length() < 1e-9);
        assert!((arc.length() - len).abs() < 1e-9);
    }

    #[test]
    fn radius_round_trip_for_small_and_large_arcs() {
        let (s, e) = (v(1., 2.), v(7., 4.));
        for &cy in &[0.1, -0.3, 0.49, 0.8, -1.7] {
            let r = rel_radius(cy) * norm(e - s);
            let back = cy_from_radius(s, e, r, is_large(cy), cy < 0.0);
            assert!((back - cy).abs() < 1e-9, "{cy} -> {back}");
            let arc = svg_arc(s, e, cy);
            assert!((arc.point(0.5) - midpoint(s, e, cy)).length() < 1e-9, "cy {cy}");
        }
    }

    #[test]
    fn angle_constructor() {
        let cy = cy_from_angle(PI / 2.0, false);
        assert!((sweep_angle(cy) - PI / 2.0).abs() < 1e-12);
        let big = cy_from_angle(1.5 * PI, true);
        assert!(big < 0.0 && is_large(big));
        assert!((sweep_angle(big) - 1.5 * PI).abs() < 1e-9);
    }

    #[test]
    fn crop_halves() {
        let arc = svg_arc(v(0., 0.), v(10., 0.), -0.3);
        let a = arc.crop(0.0, 0.5);
        let b = arc.crop(0.5, 1.0);
        assert!((a.length() + b.length() - arc.length()).abs() < 1e-9);
        assert!((a.end - b.start).length() < 1e-12);
    }
}
