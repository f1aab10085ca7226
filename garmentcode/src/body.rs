//! Body measurements, read from the reference's body YAML files, and the derived
//! values the garment programs use.
//!
//! Garments are retargeted to a new body by changing measurements alone, so the
//! measurements are checked on load: every one must be present and finite, lengths
//! positive, angles non-negative.

use crate::parity::yaml::{self, Node, Value as Y};
use std::fmt;

/// The measurements of one body, in centimetres and degrees.
///
/// Read from a body file; garment programs use the fields and [`Body::derived`]:
///
/// ```
/// use garmentcode::Body;
///
/// # const OTHERS: &str = concat!(
/// #     "  waist_over_bust_line: 40.56\n",
/// #     "  bust_line: 25.69\n",
/// #     "  vert_bust_line: 21.14\n",
/// #     "  hips_line: 23.48\n",
/// #     "  crotch_hip_diff: 8.81\n",
/// #     "  armscye_depth: 12.87\n",
/// #     "  arm_length: 53.97\n",
/// #     "  bust: 99.84\n",
/// #     "  underbust: 86.25\n",
/// #     "  waist: 84.33\n",
/// #     "  hips: 103.48\n",
/// #     "  leg_circ: 60.2\n",
/// #     "  wrist: 16.59\n",
/// #     "  neck_w: 18.93\n",
/// #     "  shoulder_w: 36.46\n",
/// #     "  back_width: 47.68\n",
/// #     "  waist_back_width: 39.14\n",
/// #     "  hip_back_width: 54.82\n",
/// #     "  bust_points: 16.95\n",
/// #     "  bum_points: 18.23\n",
/// #     "  shoulder_incl: 21.68\n",
/// #     "  hip_inclination: 9.86\n",
/// #     "  arm_pose_angle: 45.48\n",
/// # );
/// // A body file lists every measurement (most of them left out here).
/// let text = format!("body:\n  height: 172.0\n  head_l: 26.0\n  waist_line: 37.0\n{OTHERS}");
/// let body = Body::from_yaml(&text, "body.yaml").unwrap();
/// assert_eq!(body.height, 172.0);
/// assert_eq!(body.derived().waist_level, 172.0 - 26.0 - 37.0);
/// assert_eq!(body.get("waist"), Some(84.33));
/// // Every measurement is checked.
/// let short = Body::from_yaml("body:\n  height: 172.0\n", "short.yaml").unwrap_err();
/// assert!(short.to_string().contains("body.waist: missing measurement"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Waist circumference.
    pub waist: f64,
    /// Bust circumference.
    pub bust: f64,
    /// Underbust circumference (not used by the garment programs).
    pub underbust: f64,
    /// Hip circumference.
    pub hips: f64,
    /// Circumference of one thigh at its thickest.
    pub leg_circ: f64,
    /// Wrist circumference.
    pub wrist: f64,
    /// Back part of the waist circumference, balance line to balance line.
    pub waist_back_width: f64,
    /// Back part of the bust circumference.
    pub back_width: f64,
    /// Back part of the hip circumference.
    pub hip_back_width: f64,
    /// Width of the neck base at the back.
    pub neck_w: f64,
    /// Nape of the neck to the waist along the back.
    pub waist_line: f64,
    /// Neck base over the bust point to the waist, in front.
    pub waist_over_bust_line: f64,
    /// Shoulder level to the bust point.
    pub bust_line: f64,
    /// Vertical distance from the nape to the bust level (absent for some bodies).
    pub vert_bust_line: Option<f64>,
    /// Shoulder to wrist.
    pub arm_length: f64,
    /// Floor to the top of the head.
    pub height: f64,
    /// Nape of the neck to the top of the head.
    pub head_l: f64,
    /// Between the outer ends of the collarbones.
    pub shoulder_w: f64,
    /// Shoulder to the bottom of the armpit, on the back.
    pub armscye_depth: f64,
    /// Between the bust apexes.
    pub bust_points: f64,
    /// Waist level down to the hip level.
    pub hips_line: f64,
    /// Between the apexes of the buttocks.
    pub bum_points: f64,
    /// Hip level down to the crotch.
    pub crotch_hip_diff: f64,
    /// Waist-to-hip side slope, degrees (0 = vertical).
    pub hip_inclination: f64,
    /// Shoulder slope, degrees.
    pub shoulder_incl: f64,
    /// Arm abduction of the body's pose, degrees.
    pub arm_pose_angle: f64,
    /// Name of the body mesh for simulation (dataset generation), if any.
    pub body_sample: Option<String>,
}

/// Values derived from the measurements, as the reference computes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Derived {
    /// Height of the waist above the floor.
    pub waist_level: f64,
    /// Height of the hip line above the floor.
    pub leg_length: f64,
    /// Sleeve balance line, slightly inside the shoulder width.
    pub base_sleeve_balance: f64,
    /// Bust-dart level.
    pub bust_line: f64,
    /// Half the hip slope.
    pub hip_inclination: f64,
    /// Shoulder slope (not halved, as in the reference).
    pub shoulder_incl: f64,
    /// Armhole depth with ease.
    pub armscye_depth: f64,
}

/// A body file that cannot be used.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyError {
    /// File name as given.
    pub file: String,
    /// One line per problem.
    pub problems: Vec<String>,
}

impl fmt::Display for BodyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.file)?;
        f.write_str(&self.problems.join("; "))
    }
}

impl std::error::Error for BodyError {}

/// Measurement keys in the reference's order; `true` marks angles (may be zero).
const KEYS: [(&str, bool); 26] = [
    ("waist", false),
    ("bust", false),
    ("underbust", false),
    ("hips", false),
    ("leg_circ", false),
    ("wrist", false),
    ("waist_back_width", false),
    ("back_width", false),
    ("hip_back_width", false),
    ("neck_w", false),
    ("waist_line", false),
    ("waist_over_bust_line", false),
    ("bust_line", false),
    ("vert_bust_line", false),
    ("arm_length", false),
    ("height", false),
    ("head_l", false),
    ("shoulder_w", false),
    ("armscye_depth", false),
    ("bust_points", false),
    ("hips_line", false),
    ("bum_points", false),
    ("crotch_hip_diff", false),
    ("hip_inclination", true),
    ("shoulder_incl", true),
    ("arm_pose_angle", true),
];

impl Body {
    /// Derived values.
    pub fn derived(&self) -> Derived {
        let waist_level = self.height - self.head_l - self.waist_line;
        Derived {
            waist_level,
            leg_length: waist_level - self.hips_line,
            base_sleeve_balance: self.shoulder_w - 2.0,
            bust_line: match self.vert_bust_line {
                Some(v) => (1.0 - 1.0 / 3.0) * v + 1.0 / 3.0 * self.bust_line,
                None => self.bust_line,
            },
            hip_inclination: self.hip_inclination / 2.0,
            shoulder_incl: self.shoulder_incl,
            armscye_depth: self.armscye_depth + 2.5,
        }
    }

    /// Read a body file (`body:` mapping of measurements).
    pub fn from_yaml(text: &str, file: &str) -> Result<Body, BodyError> {
        let fail = |p: String| BodyError { file: file.to_string(), problems: vec![p] };
        let doc = yaml::parse(text).map_err(|e| fail(e.to_string()))?;
        let body = doc.get("body").ok_or_else(|| fail("expected a top-level `body:` mapping of measurements".into()))?;
        let pairs = body.as_map().ok_or_else(|| fail("`body` must be a mapping of measurements".into()))?;
        let mut values: Vec<Option<f64>> = vec![None; KEYS.len()];
        let mut body_sample = None;
        let mut problems = Vec::new();
        for (k, v) in pairs {
            let at = format!("line {}", k.line);
            let Some(name) = k.as_str() else {
                problems.push(format!("{at}: measurement names must be strings"));
                continue;
            };
            if name == "body_sample" {
                body_sample = v.as_str().map(str::to_string);
                continue;
            }
            if name.starts_with('_') {
                continue; // derived values are always recomputed
            }
            let Some(i) = KEYS.iter().position(|(n, _)| *n == name) else {
                problems.push(format!("{at}: unknown measurement `{name}`"));
                continue;
            };
            match v.as_f64() {
                Some(x) if x.is_finite() => values[i] = Some(x),
                _ => problems.push(format!("{at}: body.{name}: expected a number, got {}", describe(v))),
            }
        }
        for (i, (name, _)) in KEYS.iter().enumerate() {
            match values[i] {
                None if *name == "vert_bust_line" => {}
                None => problems.push(format!("body.{name}: missing measurement")),
                Some(x) => {
                    if let Err(e) = Body::check_measurement(name, x) {
                        problems.push(format!("body.{name}: {e}"));
                    }
                }
            }
        }
        if !problems.is_empty() {
            return Err(BodyError { file: file.to_string(), problems });
        }
        let g = |n: &str| values[KEYS.iter().position(|(k, _)| *k == n).expect("known key")].unwrap_or(0.0);
        Ok(Body {
            waist: g("waist"),
            bust: g("bust"),
            underbust: g("underbust"),
            hips: g("hips"),
            leg_circ: g("leg_circ"),
            wrist: g("wrist"),
            waist_back_width: g("waist_back_width"),
            back_width: g("back_width"),
            hip_back_width: g("hip_back_width"),
            neck_w: g("neck_w"),
            waist_line: g("waist_line"),
            waist_over_bust_line: g("waist_over_bust_line"),
            bust_line: g("bust_line"),
            vert_bust_line: values[13],
            arm_length: g("arm_length"),
            height: g("height"),
            head_l: g("head_l"),
            shoulder_w: g("shoulder_w"),
            armscye_depth: g("armscye_depth"),
            bust_points: g("bust_points"),
            hips_line: g("hips_line"),
            bum_points: g("bum_points"),
            crotch_hip_diff: g("crotch_hip_diff"),
            hip_inclination: g("hip_inclination"),
            shoulder_incl: g("shoulder_incl"),
            arm_pose_angle: g("arm_pose_angle"),
            body_sample,
        })
    }

    /// Measurement values by name (the reference's keys), derived ones with `_`.
    pub fn entries(&self) -> Vec<(&'static str, f64)> {
        let d = self.derived();
        let mut out = vec![
            ("_armscye_depth", d.armscye_depth),
            ("_base_sleeve_balance", d.base_sleeve_balance),
            ("_bust_line", d.bust_line),
            ("_hip_inclination", d.hip_inclination),
            ("_leg_length", d.leg_length),
            ("_shoulder_incl", d.shoulder_incl),
            ("_waist_level", d.waist_level),
        ];
        for (name, _) in KEYS {
            if let Some(v) = self.get(name) {
                out.push((name, v));
            }
        }
        out
    }

    /// A raw measurement by name.
    pub fn get(&self, name: &str) -> Option<f64> {
        Some(match name {
            "waist" => self.waist,
            "bust" => self.bust,
            "underbust" => self.underbust,
            "hips" => self.hips,
            "leg_circ" => self.leg_circ,
            "wrist" => self.wrist,
            "waist_back_width" => self.waist_back_width,
            "back_width" => self.back_width,
            "hip_back_width" => self.hip_back_width,
            "neck_w" => self.neck_w,
            "waist_line" => self.waist_line,
            "waist_over_bust_line" => self.waist_over_bust_line,
            "bust_line" => self.bust_line,
            "vert_bust_line" => return self.vert_bust_line,
            "arm_length" => self.arm_length,
            "height" => self.height,
            "head_l" => self.head_l,
            "shoulder_w" => self.shoulder_w,
            "armscye_depth" => self.armscye_depth,
            "bust_points" => self.bust_points,
            "hips_line" => self.hips_line,
            "bum_points" => self.bum_points,
            "crotch_hip_diff" => self.crotch_hip_diff,
            "hip_inclination" => self.hip_inclination,
            "shoulder_incl" => self.shoulder_incl,
            "arm_pose_angle" => self.arm_pose_angle,
            _ => return None,
        })
    }

    /// Set a raw measurement by name (for tools); `false` for unknown names.
    pub fn set(&mut self, name: &str, v: f64) -> bool {
        let slot = match name {
            "waist" => &mut self.waist,
            "bust" => &mut self.bust,
            "underbust" => &mut self.underbust,
            "hips" => &mut self.hips,
            "leg_circ" => &mut self.leg_circ,
            "wrist" => &mut self.wrist,
            "waist_back_width" => &mut self.waist_back_width,
            "back_width" => &mut self.back_width,
            "hip_back_width" => &mut self.hip_back_width,
            "neck_w" => &mut self.neck_w,
            "waist_line" => &mut self.waist_line,
            "waist_over_bust_line" => &mut self.waist_over_bust_line,
            "bust_line" => &mut self.bust_line,
            "vert_bust_line" => {
                self.vert_bust_line = Some(v);
                return true;
            }
            "arm_length" => &mut self.arm_length,
            "height" => &mut self.height,
            "head_l" => &mut self.head_l,
            "shoulder_w" => &mut self.shoulder_w,
            "armscye_depth" => &mut self.armscye_depth,
            "bust_points" => &mut self.bust_points,
            "hips_line" => &mut self.hips_line,
            "bum_points" => &mut self.bum_points,
            "crotch_hip_diff" => &mut self.crotch_hip_diff,
            "hip_inclination" => &mut self.hip_inclination,
            "shoulder_incl" => &mut self.shoulder_incl,
            "arm_pose_angle" => &mut self.arm_pose_angle,
            _ => return false,
        };
        *slot = v;
        true
    }

    /// The reference's body file layout: `body:` with keys sorted (derived `_` keys
    /// first), full precision.
    pub fn to_yaml(&self) -> String {
        let mut entries: Vec<(String, Node)> = self.entries().into_iter().map(|(k, v)| (k.to_string(), Node::new(Y::Float(v)))).collect();
        if let Some(s) = &self.body_sample {
            entries.push(("body_sample".into(), Node::new(Y::Str(s.clone()))));
        }
        entries.sort_by(|a, b| a.0.cmp(&b.0));
        let map = entries.into_iter().map(|(k, v)| (Node::new(Y::Str(k)), v)).collect();
        yaml::to_string(&Node::new(Y::Map(vec![(Node::new(Y::Str("body".into())), Node::new(Y::Map(map)))])))
    }

    /// Names of every raw measurement, in the reference's order.
    pub fn measurement_names() -> impl Iterator<Item = &'static str> {
        KEYS.iter().map(|(n, _)| *n)
    }

    /// Whether a measurement is an angle (degrees) rather than a length.
    pub fn is_angle(name: &str) -> bool {
        KEYS.iter().any(|(n, a)| *n == name && *a)
    }

    /// Check one raw measurement as body files are checked: a known name, a finite
    /// number, lengths positive, angles non-negative. The error says what is
    /// allowed (without the name, which the caller prefixes).
    pub fn check_measurement(name: &str, x: f64) -> Result<(), String> {
        let Some((_, angle)) = KEYS.iter().find(|(n, _)| *n == name) else {
            return Err("unknown measurement".into());
        };
        if !x.is_finite() {
            return Err(format!("expected a finite number, got {x}"));
        }
        if *angle && x < 0.0 {
            return Err(format!("{x} must not be negative (degrees)"));
        }
        if !*angle && x <= 0.0 {
            return Err(format!("{x} must be positive (cm)"));
        }
        Ok(())
    }

    /// What a raw or derived (`_`-prefixed) measurement is, for tools that show
    /// them (the same words as the field documentation).
    pub fn describe_measurement(name: &str) -> Option<&'static str> {
        Some(match name {
            "waist" => "Waist circumference.",
            "bust" => "Bust circumference.",
            "underbust" => "Underbust circumference (not used by the garment programs).",
            "hips" => "Hip circumference.",
            "leg_circ" => "Circumference of one thigh at its thickest.",
            "wrist" => "Wrist circumference.",
            "waist_back_width" => "Back part of the waist circumference, balance line to balance line.",
            "back_width" => "Back part of the bust circumference.",
            "hip_back_width" => "Back part of the hip circumference.",
            "neck_w" => "Width of the neck base at the back.",
            "waist_line" => "Nape of the neck to the waist along the back.",
            "waist_over_bust_line" => "Neck base over the bust point to the waist, in front.",
            "bust_line" => "Shoulder level to the bust point.",
            "vert_bust_line" => "Vertical distance from the nape to the bust level (optional).",
            "arm_length" => "Shoulder to wrist.",
            "height" => "Floor to the top of the head.",
            "head_l" => "Nape of the neck to the top of the head.",
            "shoulder_w" => "Between the outer ends of the collarbones.",
            "armscye_depth" => "Shoulder to the bottom of the armpit, on the back.",
            "bust_points" => "Between the bust apexes.",
            "hips_line" => "Waist level down to the hip level.",
            "bum_points" => "Between the apexes of the buttocks.",
            "crotch_hip_diff" => "Hip level down to the crotch.",
            "hip_inclination" => "Waist-to-hip side slope, degrees (0 = vertical).",
            "shoulder_incl" => "Shoulder slope, degrees.",
            "arm_pose_angle" => "Arm abduction of the body's pose, degrees.",
            "_waist_level" => "Height of the waist above the floor (height − head − waist line).",
            "_leg_length" => "Height of the hip line above the floor.",
            "_base_sleeve_balance" => "Sleeve balance line, slightly inside the shoulder width.",
            "_bust_line" => "Bust-dart level.",
            "_hip_inclination" => "Half the hip slope.",
            "_shoulder_incl" => "Shoulder slope.",
            "_armscye_depth" => "Armhole depth with ease.",
            _ => return None,
        })
    }
}

fn describe(n: &Node) -> String {
    match &n.value {
        Y::Str(s) => format!("\"{s}\""),
        other => other.type_name().to_string(),
    }
}
