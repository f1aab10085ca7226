//! The measuring guide: how to take each body measurement, with a drawing of where
//! the tape goes.
//!
//! Every measurement of [`MEASUREMENTS`] has a sentence saying how to take it
//! ([`how_to_measure`]) and a figure ([`figure_svg`]): a front and a back view of a
//! simple mannequin drawn from the body's own measurements (so the figure of a
//! tall or a broad body looks it), with the tape in red: a girth as a loop around
//! the body at its level, a width or length as a line between the points it joins,
//! a height as a dimension line beside the figure, an angle as an arc against its
//! reference line. [`guide_html`] puts them together into one printable page.
//!
//! The mannequin is a line drawing, not the body mesh: its levels are the body's
//! (floor, crotch, hips, waist, bust, armpit, shoulders, neck, head), its widths
//! follow the girths (a girth `c` drawn as a body `c / (1.7 π)` wide on each side
//! of the centre, as an ellipse of depth 0.7 times its width would be), and its
//! arms hang at the body's `arm_pose_angle`.
//!
//! ```
//! use garmentcode::guide::{figure_svg, how_to_measure};
//! let text = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../garments/data/bodies/mean_all.yaml"));
//! let body = garmentcode::Body::from_yaml(text, "mean_all.yaml")?;
//! let svg = figure_svg(&body, "waist").unwrap();
//! assert!(svg.starts_with("<svg") && svg.contains("class=\"tape\""));
//! assert!(how_to_measure("waist").unwrap().contains("narrowest"));
//! # Ok::<(), garmentcode::BodyError>(())
//! ```

use crate::body::{Body, MEASUREMENTS};
use crate::math::Vec2;
use std::f64::consts::PI;
use std::fmt::Write;

/// How to take each measurement: one or two sentences, in [`MEASUREMENTS`] order.
const HOW: &[(&str, &str)] = &[
    (
        "waist",
        "Tape around the natural waist, the narrowest part of the torso between the ribs and the hips, snug but not tight, breathing out normally.",
    ),
    ("bust", "Tape around the fullest part of the bust, over the bust points, level all around the back; with the bra you will wear."),
    ("underbust", "Tape around the ribcage just under the bust, level and snug."),
    ("hips", "Tape around the fullest part of the hips and seat, level all around, standing with the feet together."),
    ("leg_circ", "Tape around one thigh at its thickest, just below the crotch."),
    ("wrist", "Tape around the wrist, over the wrist bone."),
    (
        "waist_back_width",
        "Across the back at the waist level, from one side seam (the balance line under the arm) to the other: the back part of the waist girth.",
    ),
    ("back_width", "Across the back at the bust level, from one side seam to the other: the back part of the bust girth."),
    ("hip_back_width", "Across the back at the hip level, from one side seam to the other over the seat: the back part of the hip girth."),
    ("neck_w", "Across the back of the neck, between the points where the neck meets the shoulders."),
    ("waist_line", "Down the centre back, from the prominent bone at the base of the neck (the nape) to the waist."),
    ("waist_over_bust_line", "From the point where the neck meets the shoulder, down over the bust point to the waist, in front."),
    ("bust_line", "From the point where the neck meets the shoulder down to the bust point."),
    (
        "vert_bust_line",
        "Straight down (plumb, not over the body) from the nape level to the bust level; leave it out if you do not have it.",
    ),
    ("arm_length", "From the shoulder point (the outer end of the shoulder) down the outside of the slightly bent arm to the wrist bone."),
    ("height", "Standing straight against a wall without shoes, from the floor to the top of the head."),
    ("head_l", "Straight down from the top of the head to the nape level (the base of the neck at the back)."),
    ("shoulder_w", "Across the front, between the outer ends of the collarbones (the shoulder points)."),
    ("armscye_depth", "On the back, straight down from the shoulder level to the bottom of the armpit (hold a ruler in the armpit)."),
    ("bust_points", "Straight across between the two bust points (apexes)."),
    ("hips_line", "At the side, straight down from the waist level to the hip level (the fullest part of the hips)."),
    ("bum_points", "Straight across the back between the two fullest points of the seat."),
    (
        "crotch_hip_diff",
        "Straight down from the hip level to the crotch (sitting on a hard chair: from the hip level to the seat, less about 1 cm).",
    ),
    (
        "hip_inclination",
        "The slope of the side from the waist to the hips, in degrees from the vertical (0 when the side runs straight down; read it off a photo taken from the front).",
    ),
    ("shoulder_incl", "The slope of the shoulder from the neck to the shoulder point, in degrees from the horizontal."),
    (
        "arm_pose_angle",
        "The angle of the arms from the sides of the body in the pose the body mesh stands in (about 45 degrees for the built-in bodies); keep the base body's value unless you drape on your own body mesh.",
    ),
];

/// How to take the measurement `name`, or `None` for an unknown name.
pub fn how_to_measure(name: &str) -> Option<&'static str> {
    HOW.iter().find(|(n, _)| *n == name).map(|(_, h)| *h)
}

/// The mannequin's points (cm, x right from the centre line, y up from the floor).
struct Mannequin {
    height: f64,
    neck_y: f64,
    neck: f64,
    head: (f64, f64, f64),
    shoulder: Vec2,
    armpit_y: f64,
    bust_y: f64,
    underbust_y: f64,
    waist_y: f64,
    hip_y: f64,
    crotch_y: f64,
    half: [f64; 4],
    thigh: f64,
    wrist: Vec2,
    wrist_r: f64,
    arm_dir: Vec2,
}

fn girth_half(c: f64) -> f64 {
    c / (1.7 * PI)
}

impl Mannequin {
    fn of(b: &Body) -> Mannequin {
        let d = b.derived();
        let neck_y = b.height - b.head_l;
        let neck = b.neck_w / 2.0;
        let shoulder_x = b.shoulder_w / 2.0;
        let shoulder = Vec2::new(shoulder_x, neck_y - (shoulder_x - neck).max(0.0) * b.shoulder_incl.to_radians().tan());
        let bust_y = neck_y - d.bust_line;
        let waist_y = d.waist_level;
        let hip_y = waist_y - b.hips_line;
        let a = b.arm_pose_angle.to_radians();
        let arm_dir = Vec2::new(a.sin(), -a.cos());
        Mannequin {
            height: b.height,
            neck_y,
            neck,
            head: (0.32 * b.head_l, b.height - 0.42 * b.head_l, 0.42 * b.head_l),
            shoulder,
            armpit_y: shoulder.y - b.armscye_depth,
            bust_y,
            underbust_y: bust_y - 0.35 * (bust_y - waist_y),
            waist_y,
            hip_y,
            crotch_y: hip_y - b.crotch_hip_diff,
            half: [girth_half(b.bust), girth_half(b.underbust), girth_half(b.waist), girth_half(b.hips)],
            thigh: girth_half(b.leg_circ) * 1.15,
            wrist: shoulder + arm_dir * b.arm_length,
            wrist_r: girth_half(b.wrist) * 1.2,
            arm_dir,
        }
    }

    /// The right half of the outline (neck down to the floor, inside leg up to the crotch).
    fn right_half(&self) -> Vec<Vec2> {
        let [bust, underbust, waist, hips] = self.half;
        let p = Vec2::new;
        let leg_out = hips.max(self.thigh + 1.0);
        let ankle_c = (leg_out + 1.0) / 2.0;
        vec![
            p(self.neck * 0.7, self.head.1 - self.head.2 + 1.0),
            p(self.neck * 0.7, self.neck_y + 1.5),
            p(self.neck, self.neck_y),
            self.shoulder,
            p(bust.max(self.shoulder.x * 0.9), self.armpit_y),
            p(bust, self.bust_y),
            p(underbust, self.underbust_y),
            p(waist, self.waist_y),
            p(hips, self.hip_y),
            p(leg_out, self.crotch_y),
            p(ankle_c + 3.5, 8.0),
            p(ankle_c + 5.0, 0.0),
            p(ankle_c - 4.0, 0.0),
            p(ankle_c - 3.5, 8.0),
            p(1.0, self.crotch_y),
            p(0.0, self.crotch_y),
        ]
    }

    /// The right arm's outline (a tapered band from the shoulder to the wrist, and the hand).
    fn right_arm(&self) -> Vec<Vec2> {
        let side = Vec2::new(-self.arm_dir.y, self.arm_dir.x);
        let top = self.shoulder + Vec2::new(-1.5, -2.0);
        let under = Vec2::new(self.half[0].max(self.shoulder.x * 0.9), self.armpit_y);
        let hand = self.wrist + self.arm_dir * 16.0;
        vec![
            top,
            self.wrist + side * self.wrist_r,
            hand + side * self.wrist_r * 0.9,
            hand - side * self.wrist_r * 0.9,
            self.wrist - side * self.wrist_r,
            under,
        ]
    }
}

/// Half-width of the figure with its arms (cm).
fn reach(m: &Mannequin) -> f64 {
    m.right_arm().iter().chain(m.right_half().iter()).map(|p| p.x).fold(0.0, f64::max) + 8.0
}

fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// The figure for measurement `name` on body `b`: an SVG document (front view on the
/// left, back view on the right, the tape in red), or `None` for an unknown name.
pub fn figure_svg(b: &Body, name: &str) -> Option<String> {
    MEASUREMENTS.iter().find(|m| m.name == name)?;
    let m = Mannequin::of(b);
    let r = reach(&m);
    let back_x = 2.0 * r;
    let (w, h) = (4.0 * r, m.height + 12.0);
    // Sheet coordinates: x from the front figure's left, y down from above the head.
    let at = |c: f64, p: Vec2| Vec2::new(r + c + p.x, m.height + 4.0 - p.y);
    let path = |c: f64, pts: &[Vec2], closed: bool| {
        let mut d = String::new();
        for (k, p) in pts.iter().enumerate() {
            let q = at(c, *p);
            let _ = write!(d, "{}{} {}", if k == 0 { "M" } else { " L" }, num(q.x), num(q.y));
        }
        if closed {
            d.push_str(" Z");
        }
        d
    };
    let mirror = |pts: &[Vec2]| pts.iter().map(|p| Vec2::new(-p.x, p.y)).collect::<Vec<_>>();
    let mut out = String::new();
    let _ = write!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {} {}" width="{}" height="{}" role="img" aria-label="where to measure {name}">"#,
        num(w),
        num(h),
        num(w * 2.0),
        num(h * 2.0)
    );
    out.push_str(r#"<style>.body{fill:#f3ede6;stroke:#777;stroke-width:0.5}.tape{fill:none;stroke:#d0202a;stroke-width:1.2;stroke-linecap:round}.ref{fill:none;stroke:#999;stroke-width:0.5;stroke-dasharray:1.5 1}.dot{fill:#d0202a}text{font:5px sans-serif;fill:#555}</style>"#);
    for c in [0.0, back_x] {
        let half = m.right_half();
        let mut outline = half.clone();
        outline.extend(mirror(&half).into_iter().rev());
        let _ = write!(out, r#"<path class="body" d="{}"/>"#, path(c, &outline, true));
        for arm in [m.right_arm(), mirror(&m.right_arm())] {
            let _ = write!(out, r#"<path class="body" d="{}"/>"#, path(c, &arm, true));
        }
        let (rx, cy, ry) = m.head;
        let q = at(c, Vec2::new(0.0, cy));
        let _ = write!(out, r#"<ellipse class="body" cx="{}" cy="{}" rx="{}" ry="{}"/>"#, num(q.x), num(q.y), num(rx), num(ry));
        let label = at(c, Vec2::new(-6.0, -6.5));
        let _ = write!(out, r#"<text x="{}" y="{}">{}</text>"#, num(label.x), num(label.y), if c == 0.0 { "front" } else { "back" });
    }
    let floor = [at(0.0, Vec2::new(-r, 0.0)), at(back_x, Vec2::new(r, 0.0))];
    let _ = write!(out, r#"<path class="ref" d="M{} {} L{} {}"/>"#, num(floor[0].x), num(floor[0].y), num(floor[1].x), num(floor[1].y));
    // The tape.
    let line = |c: f64, pts: &[Vec2]| format!(r#"<path class="tape" d="{}"/>"#, path(c, pts, false));
    let loop_at = |c: f64, centre: Vec2, half: f64| {
        let q = at(c, centre);
        format!(r#"<ellipse class="tape" cx="{}" cy="{}" rx="{}" ry="{}"/>"#, num(q.x), num(q.y), num(half + 1.0), num((half + 1.0) * 0.22))
    };
    let dots = |c: f64, pts: &[Vec2]| {
        pts.iter()
            .map(|p| {
                let q = at(c, *p);
                format!(r#"<circle class="dot" cx="{}" cy="{}" r="1.3"/>"#, num(q.x), num(q.y))
            })
            .collect::<String>()
    };
    // A height as a dimension line left of the figure, with ticks at both ends.
    let dimension = |c: f64, x: f64, y0: f64, y1: f64| {
        let p = |y| Vec2::new(x, y);
        let tick = |y| line(c, &[Vec2::new(x - 2.0, y), Vec2::new(x + 2.0, y)]);
        format!("{}{}{}", line(c, &[p(y0), p(y1)]), tick(y0), tick(y1))
    };
    let arc = |c: f64, centre: Vec2, from: f64, to: f64, radius: f64| {
        let pts: Vec<Vec2> = (0..=12).map(|k| centre + Vec2::from_angle(from + (to - from) * k as f64 / 12.0) * radius).collect();
        line(c, &pts)
    };
    let reference = |c: f64, a: Vec2, b: Vec2| format!(r#"<path class="ref" d="{}"/>"#, path(c, &[a, b], false));
    let [bust, _, waist, hips] = m.half;
    let p = Vec2::new;
    let bp = b.bust_points / 2.0;
    let left = -r + 6.0;
    let tape = match name {
        "waist" => loop_at(0.0, p(0.0, m.waist_y), waist),
        "bust" => loop_at(0.0, p(0.0, m.bust_y), bust),
        "underbust" => loop_at(0.0, p(0.0, m.underbust_y), m.half[1]),
        "hips" => loop_at(0.0, p(0.0, m.hip_y), hips),
        "leg_circ" => loop_at(0.0, p((hips.max(m.thigh + 1.0) + 1.0) / 2.0, m.crotch_y - 3.0), m.thigh / 2.0 + 0.5),
        "wrist" => {
            let q = at(0.0, m.wrist);
            let angle = m.arm_dir.y.atan2(m.arm_dir.x).to_degrees();
            format!(
                r#"<ellipse class="tape" cx="{}" cy="{}" rx="{}" ry="{}" transform="rotate({} {} {})"/>"#,
                num(q.x),
                num(q.y),
                num(m.wrist_r * 0.3),
                num(m.wrist_r + 0.8),
                num(-angle),
                num(q.x),
                num(q.y)
            )
        }
        "waist_back_width" => line(back_x, &[p(-waist, m.waist_y), p(waist, m.waist_y)]),
        "back_width" => line(back_x, &[p(-bust, m.bust_y), p(bust, m.bust_y)]),
        "hip_back_width" => line(back_x, &[p(-hips, m.hip_y), p(hips, m.hip_y)]),
        "neck_w" => line(back_x, &[p(-m.neck, m.neck_y), p(m.neck, m.neck_y)]),
        "waist_line" => line(back_x, &[p(0.0, m.neck_y), p(0.0, m.waist_y)]),
        "waist_over_bust_line" => line(0.0, &[p(m.neck, m.neck_y), p(bp, m.bust_y), p(bp, m.waist_y)]) + &dots(0.0, &[p(bp, m.bust_y)]),
        "bust_line" => line(0.0, &[p(m.neck, m.neck_y), p(bp, m.bust_y)]) + &dots(0.0, &[p(bp, m.bust_y)]),
        "vert_bust_line" => {
            dimension(0.0, left, m.neck_y, m.bust_y)
                + &reference(0.0, p(left, m.neck_y), p(0.0, m.neck_y))
                + &reference(0.0, p(left, m.bust_y), p(bp, m.bust_y))
        }
        "arm_length" => line(0.0, &[m.shoulder, m.wrist]),
        "height" => dimension(0.0, left, 0.0, m.height) + &reference(0.0, p(left, m.height), p(0.0, m.height)),
        "head_l" => {
            dimension(0.0, left, m.neck_y, m.height)
                + &reference(0.0, p(left, m.height), p(0.0, m.height))
                + &reference(0.0, p(left, m.neck_y), p(-m.neck, m.neck_y))
        }
        "shoulder_w" => {
            line(0.0, &[p(-m.shoulder.x, m.shoulder.y), m.shoulder]) + &dots(0.0, &[p(-m.shoulder.x, m.shoulder.y), m.shoulder])
        }
        "armscye_depth" => {
            let x = m.shoulder.x * 0.85;
            dimension(back_x, x, m.shoulder.y, m.armpit_y)
                + &reference(back_x, p(x, m.armpit_y), p(bust.max(m.shoulder.x * 0.9), m.armpit_y))
        }
        "bust_points" => line(0.0, &[p(-bp, m.bust_y), p(bp, m.bust_y)]) + &dots(0.0, &[p(-bp, m.bust_y), p(bp, m.bust_y)]),
        "hips_line" => {
            dimension(0.0, left, m.waist_y, m.hip_y)
                + &reference(0.0, p(left, m.waist_y), p(-waist, m.waist_y))
                + &reference(0.0, p(left, m.hip_y), p(-hips, m.hip_y))
        }
        "bum_points" => {
            let y = m.hip_y + 2.0;
            let x = b.bum_points / 2.0;
            line(back_x, &[p(-x, y), p(x, y)]) + &dots(back_x, &[p(-x, y), p(x, y)])
        }
        "crotch_hip_diff" => {
            dimension(0.0, left, m.hip_y, m.crotch_y)
                + &reference(0.0, p(left, m.hip_y), p(-hips, m.hip_y))
                + &reference(0.0, p(left, m.crotch_y), p(0.0, m.crotch_y))
        }
        "hip_inclination" => {
            let (top, bottom) = (p(waist, m.waist_y), p(hips, m.hip_y));
            line(0.0, &[top, bottom]) + &reference(0.0, top, p(waist, m.hip_y - 3.0))
        }
        "shoulder_incl" => {
            let neck = p(m.neck, m.neck_y);
            let a = (m.shoulder.y - neck.y).atan2(m.shoulder.x - neck.x);
            line(0.0, &[neck, m.shoulder]) + &reference(0.0, neck, p(m.shoulder.x + 3.0, m.neck_y)) + &arc(0.0, neck, a, 0.0, 6.0)
        }
        "arm_pose_angle" => {
            let down = -PI / 2.0;
            let a = m.arm_dir.y.atan2(m.arm_dir.x);
            line(0.0, &[m.shoulder, m.shoulder + m.arm_dir * 30.0])
                + &reference(0.0, m.shoulder, m.shoulder + p(0.0, -30.0))
                + &arc(0.0, m.shoulder, down, a, 14.0)
        }
        _ => String::new(),
    };
    out.push_str(&tape);
    out.push_str("</svg>\n");
    Some(out)
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The whole guide as one printable HTML page (no scripts, no external files): for
/// every measurement its figure on `body`, what it is, how to take it, its
/// plausible range and `body`'s value. `title` names the body.
pub fn guide_html(body: &Body, title: &str) -> String {
    let mut out = String::new();
    let _ = write!(
        out,
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>Measuring guide</title>
<style>
body{{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}}
.grid{{display:grid;grid-template-columns:repeat(auto-fill,minmax(20em,1fr));gap:1em}}
.card{{border:1px solid #ccc;border-radius:6px;padding:.6em;break-inside:avoid}}
.card svg{{width:100%;height:auto;max-height:18em}}
h2{{font-size:1.05em;margin:.2em 0}} code{{background:#f4f4f4;padding:0 .2em}}
.range{{color:#666;font-size:.9em}}
@media print{{body{{margin:0}} .card{{page-break-inside:avoid}}}}
</style></head><body>
<h1>Measuring guide</h1>
<p>How to take each measurement of a body file, drawn on {title}. Measure over light underwear, standing straight and relaxed, with a flexible tape held level and snug (not tight); a friend helps. Write the values into a body file over the built-in body closest to you (<code>base: mean_female</code>), in cm or with <code>units: in</code>: measurements you leave out follow the ones you give, in proportion.</p>
<div class="grid">
"#,
        title = escape(title)
    );
    for m in MEASUREMENTS {
        let value = body.get(m.name).map_or_else(|| "not given".to_string(), |v| format!("{} {}", num(v), m.unit));
        let _ = writeln!(
            out,
            r#"<section class="card" id="{name}">{svg}<h2><code>{name}</code></h2><p>{what}</p><p>{how}</p><p class="range">Plausible: {min} to {max} {unit}{optional}. {title}: {value}.</p></section>"#,
            name = m.name,
            svg = figure_svg(body, m.name).unwrap_or_default(),
            what = escape(m.description),
            how = escape(how_to_measure(m.name).unwrap_or("")),
            min = num(m.min),
            max = num(m.max),
            unit = m.unit,
            optional = if m.optional { " (optional)" } else { "" },
            title = escape(title),
        );
    }
    out.push_str("</div>\n</body></html>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bodies() -> Vec<(String, Body)> {
        ["mean_all", "mean_female", "mean_male", "f_smpl_average_A40", "m_smpl_average_A40"]
            .iter()
            .map(|n| {
                let text = std::fs::read_to_string(format!("{}/../garments/data/bodies/{n}.yaml", env!("CARGO_MANIFEST_DIR"))).unwrap();
                (n.to_string(), Body::from_yaml(&text, n).unwrap())
            })
            .collect()
    }

    #[test]
    fn every_measurement_has_a_sentence_and_a_figure_with_a_tape() {
        assert_eq!(HOW.len(), MEASUREMENTS.len());
        for (m, (n, _)) in MEASUREMENTS.iter().zip(HOW) {
            assert_eq!(m.name, *n, "HOW follows MEASUREMENTS' order");
        }
        for (name, b) in bodies() {
            for m in MEASUREMENTS {
                let svg = figure_svg(&b, m.name).unwrap();
                assert!(svg.contains(r#"class="tape""#), "{name}: {}", m.name);
                assert!(!svg.contains("NaN") && !svg.contains("inf"), "{name}: {}", m.name);
            }
        }
        assert!(figure_svg(&bodies()[0].1, "nose").is_none());
    }

    #[test]
    fn the_figure_follows_the_body() {
        let b = &bodies()[1].1;
        let mut tall = b.clone();
        tall.height += 20.0;
        let viewbox = |svg: &str| -> f64 {
            let v = svg.split("viewBox=\"0 0 ").nth(1).unwrap();
            v.split(['"', ' ']).nth(1).unwrap().parse().unwrap()
        };
        assert_eq!(viewbox(&figure_svg(&tall, "height").unwrap()) - viewbox(&figure_svg(b, "height").unwrap()), 20.0);
    }

    #[test]
    fn the_page_lists_every_measurement_with_its_value() {
        let (name, b) = &bodies()[0];
        let html = guide_html(b, name);
        for m in MEASUREMENTS {
            assert!(html.contains(&format!(r#"id="{}""#, m.name)), "{}", m.name);
        }
        assert!(html.contains(&format!("mean_all: {} cm", num(b.waist))));
        assert!(!html.contains("<script"));
    }
}
