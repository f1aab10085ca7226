//! Body measurements, read from the reference's body YAML files, and the derived
//! values the garment programs use.
//!
//! Every measurement is declared once, in the table [`MEASUREMENTS`] (written
//! with the `measurements!` macro below): its name, unit, description and
//! plausible range. The [`Body`] struct, reading and writing body files, the
//! per-measurement checks, and the listings tools show (the web configurator's
//! schema, the docs) all come from that table; the derived values likewise come
//! from one table ([`DERIVED_VALUES`]).
//!
//! Garments are retargeted to a new body by changing measurements alone, so the
//! measurements are checked on load: every one must be present, finite and within
//! its plausible range (adult and child anthropometry with a generous margin), and
//! the derived values must make sense (the waist above the floor, ...). A value
//! outside its range is an error that names the range and the likely cause, such
//! as a length typed in metres.

use crate::message::{quote, short};
use crate::parity::yaml::{self, Node, Value as Y};
use std::fmt;

/// One raw body measurement as declared in the body table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measurement {
    /// Key in body files (the reference's name).
    pub name: &'static str,
    /// `cm` for lengths, `deg` for angles.
    pub unit: &'static str,
    /// What is measured, in a sentence.
    pub description: &'static str,
    /// Smallest plausible value (inclusive).
    pub min: f64,
    /// Largest plausible value (inclusive).
    pub max: f64,
    /// Whether a body file may leave it out.
    pub optional: bool,
}

/// One value derived from the measurements, as declared in the derived table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DerivedValue {
    /// Key in written body files (`_` + the [`Derived`] field name).
    pub name: &'static str,
    /// What it is, in a sentence.
    pub description: &'static str,
}

/// A body file that cannot be used.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyError {
    /// File name as given.
    pub file: String,
    /// One line per problem.
    pub problems: Vec<String>,
}

/// Problems a [`BodyError`] shows; the rest are counted.
const MAX_SHOWN: usize = 20;

impl fmt::Display for BodyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let [one] = &self.problems[..] {
            return write!(f, "{}: {one}", self.file);
        }
        write!(f, "{}: {} problems", self.file, self.problems.len())?;
        for p in self.problems.iter().take(MAX_SHOWN) {
            write!(f, "\n  {p}")?;
        }
        if self.problems.len() > MAX_SHOWN {
            write!(f, "\n  ... and {} more", self.problems.len() - MAX_SHOWN)?;
        }
        Ok(())
    }
}

impl std::error::Error for BodyError {}

/// A field type of [`Body`]: a required (`f64`) or optional (`Option<f64>`)
/// measurement.
trait Slot {
    const OPTIONAL: bool;
    fn value(&self) -> Option<f64>;
    fn from_value(v: Option<f64>) -> Self;
}

impl Slot for f64 {
    const OPTIONAL: bool = false;
    fn value(&self) -> Option<f64> {
        Some(*self)
    }
    fn from_value(v: Option<f64>) -> Self {
        v.unwrap_or(0.0)
    }
}

impl Slot for Option<f64> {
    const OPTIONAL: bool = true;
    fn value(&self) -> Option<f64> {
        *self
    }
    fn from_value(v: Option<f64>) -> Self {
        v
    }
}

/// Declares the raw measurements: `name: type = "unit" [min, max] "description";`
/// generates the [`Body`] struct (one documented field each), the
/// [`MEASUREMENTS`] table and access by name.
macro_rules! measurements {
    ($( $name:ident : $ty:ty = $unit:literal [$min:literal, $max:literal] $desc:literal; )*) => {
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
            $(
                #[doc = $desc]
                #[doc = ""]
                #[doc = concat!("Unit: ", $unit, "; plausible range ", stringify!($min), " to ", stringify!($max), ".")]
                pub $name: $ty,
            )*
            /// Name of the body mesh for simulation (dataset generation), if any.
            pub body_sample: Option<String>,
        }

        /// Every raw measurement, in the reference's order: the one declaration
        /// that body files, checks and listings are generated from.
        pub const MEASUREMENTS: &[Measurement] = &[
            $( Measurement {
                name: stringify!($name),
                unit: $unit,
                description: $desc,
                min: $min,
                max: $max,
                optional: <$ty as Slot>::OPTIONAL,
            }, )*
        ];

        impl Body {
            /// A raw measurement by name: `None` for an unknown name, `Some(None)`
            /// for an absent optional one.
            fn slot(&self, name: &str) -> Option<Option<f64>> {
                match name {
                    $( stringify!($name) => Some(Slot::value(&self.$name)), )*
                    _ => None,
                }
            }

            /// Set a raw measurement by name; `false` for unknown names.
            fn set_slot(&mut self, name: &str, v: f64) -> bool {
                match name {
                    $( stringify!($name) => self.$name = Slot::from_value(Some(v)), )*
                    _ => return false,
                }
                true
            }

            /// A body from values in [`MEASUREMENTS`] order.
            fn from_values(values: &[Option<f64>], body_sample: Option<String>) -> Body {
                let mut it = values.iter().copied();
                Body { $( $name: Slot::from_value(it.next().flatten()), )* body_sample }
            }
        }
    };
}

/// Declares the derived values: `name "description" = |body| expression;`
/// generates the [`Derived`] struct, [`Body::derived`] and the
/// [`DERIVED_VALUES`] table.
macro_rules! derived_values {
    ($( $name:ident $desc:literal = |$b:ident| $e:expr; )*) => {
        /// Values derived from the measurements, as the reference computes them.
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct Derived {
            $( #[doc = $desc] pub $name: f64, )*
        }

        /// Every derived value, sorted by name (the order of written body files).
        pub const DERIVED_VALUES: &[DerivedValue] = &[
            $( DerivedValue { name: concat!("_", stringify!($name)), description: $desc }, )*
        ];

        impl Body {
            /// Derived values.
            pub fn derived(&self) -> Derived {
                Derived { $( $name: { let $b = self; $e }, )* }
            }
        }

        impl Derived {
            /// The values in [`DERIVED_VALUES`] order.
            fn values(&self) -> Vec<f64> {
                vec![$( self.$name ),*]
            }
        }
    };
}

// Plausible ranges: human anthropometry (children from about 90 cm tall to very
// tall or large adults) with a generous margin; the reference's bodies sit well
// inside them. They exist to catch typing mistakes (metres, millimetres, inches),
// which would otherwise make garments thousands of times too big or too small.
measurements! {
    waist: f64 = "cm" [40.0, 220.0] "Waist circumference.";
    bust: f64 = "cm" [45.0, 220.0] "Bust circumference.";
    underbust: f64 = "cm" [40.0, 210.0] "Underbust circumference (not used by the garment programs).";
    hips: f64 = "cm" [45.0, 230.0] "Hip circumference.";
    leg_circ: f64 = "cm" [20.0, 130.0] "Circumference of one thigh at its thickest.";
    wrist: f64 = "cm" [8.0, 35.0] "Wrist circumference.";
    waist_back_width: f64 = "cm" [15.0, 120.0] "Back part of the waist circumference, balance line to balance line.";
    back_width: f64 = "cm" [18.0, 120.0] "Back part of the bust circumference.";
    hip_back_width: f64 = "cm" [18.0, 130.0] "Back part of the hip circumference.";
    neck_w: f64 = "cm" [6.0, 35.0] "Width of the neck base at the back.";
    waist_line: f64 = "cm" [15.0, 70.0] "Nape of the neck to the waist along the back.";
    waist_over_bust_line: f64 = "cm" [15.0, 80.0] "Neck base over the bust point to the waist, in front.";
    bust_line: f64 = "cm" [8.0, 50.0] "Shoulder level to the bust point.";
    vert_bust_line: Option<f64> = "cm" [8.0, 50.0] "Vertical distance from the nape to the bust level (absent for some bodies).";
    arm_length: f64 = "cm" [25.0, 100.0] "Shoulder to wrist.";
    height: f64 = "cm" [80.0, 250.0] "Floor to the top of the head.";
    head_l: f64 = "cm" [12.0, 45.0] "Nape of the neck to the top of the head.";
    shoulder_w: f64 = "cm" [15.0, 65.0] "Between the outer ends of the collarbones.";
    armscye_depth: f64 = "cm" [6.0, 35.0] "Shoulder to the bottom of the armpit, on the back.";
    bust_points: f64 = "cm" [6.0, 40.0] "Between the bust apexes.";
    hips_line: f64 = "cm" [5.0, 45.0] "Waist level down to the hip level.";
    bum_points: f64 = "cm" [5.0, 40.0] "Between the apexes of the buttocks.";
    crotch_hip_diff: f64 = "cm" [2.0, 35.0] "Hip level down to the crotch.";
    hip_inclination: f64 = "deg" [0.0, 35.0] "Waist-to-hip side slope, degrees (0 = vertical).";
    shoulder_incl: f64 = "deg" [0.0, 45.0] "Shoulder slope, degrees.";
    arm_pose_angle: f64 = "deg" [0.0, 90.0] "Arm abduction of the body's pose, degrees.";
}

derived_values! {
    armscye_depth "Armhole depth with ease." = |b| b.armscye_depth + 2.5;
    base_sleeve_balance "Sleeve balance line, slightly inside the shoulder width." = |b| b.shoulder_w - 2.0;
    bust_line "Bust-dart level." = |b| match b.vert_bust_line {
        Some(v) => (1.0 - 1.0 / 3.0) * v + 1.0 / 3.0 * b.bust_line,
        None => b.bust_line,
    };
    hip_inclination "Half the hip slope." = |b| b.hip_inclination / 2.0;
    leg_length "Height of the hip line above the floor (waist level − hips line)." = |b| b.height - b.head_l - b.waist_line - b.hips_line;
    shoulder_incl "Shoulder slope (not halved, as in the reference)." = |b| b.shoulder_incl;
    waist_level "Height of the waist above the floor (height − head − waist line)." = |b| b.height - b.head_l - b.waist_line;
}

/// How a body file over a built-in body (`base:`) fills in what it does not give: each
/// measurement on the left, when the file leaves it out but gives the one on the right,
/// is the base's value scaled by the same ratio as that one (`given / base`). Lengths
/// follow the height, the upper body's girths and widths the bust, the waist's back part
/// the waist, and the lower body's the hips; angles and the driving measurements
/// themselves stay the base's unless given.
pub const PROPORTIONS: &[(&str, &str)] = &[
    ("head_l", "height"),
    ("waist_line", "height"),
    ("waist_over_bust_line", "height"),
    ("bust_line", "height"),
    ("vert_bust_line", "height"),
    ("arm_length", "height"),
    ("armscye_depth", "height"),
    ("hips_line", "height"),
    ("crotch_hip_diff", "height"),
    ("underbust", "bust"),
    ("back_width", "bust"),
    ("bust_points", "bust"),
    ("shoulder_w", "bust"),
    ("neck_w", "bust"),
    ("wrist", "bust"),
    ("waist_back_width", "waist"),
    ("hip_back_width", "hips"),
    ("leg_circ", "hips"),
    ("bum_points", "hips"),
];

/// Plausible ratios between measurements (`a / b` within `[low, high]`), checked by
/// [`Body::check_derived`]: each value may be in its own range and still not fit the
/// others (a waist half as large again as the hips is a typing mistake).
pub const RATIOS: &[(&str, &str, f64, f64)] = &[
    ("waist", "hips", 0.5, 1.5),
    ("bust", "hips", 0.55, 1.6),
    ("bust", "waist", 0.6, 2.2),
    ("underbust", "bust", 0.6, 1.1),
    ("shoulder_w", "bust", 0.2, 0.6),
    ("arm_length", "height", 0.2, 0.6),
    ("head_l", "height", 0.08, 0.25),
];

/// The entries of a body mapping read from YAML (see [`Body::from_entries`]), each
/// prefixed with its line, and the problems of keys that are not names.
pub(crate) fn yaml_entries(pairs: &[(Node, Node)]) -> (Vec<(String, &str, BodyValue<'_>)>, Vec<String>) {
    let mut problems = Vec::new();
    let mut entries = Vec::with_capacity(pairs.len());
    for (k, v) in pairs {
        let at = format!("line {}: ", k.line);
        let Some(name) = k.as_str() else {
            problems.push(format!("{at}measurement names must be strings"));
            continue;
        };
        let value = match (&v.value, v.as_f64()) {
            (_, Some(x)) => BodyValue::Number(x),
            (Y::Str(s), _) => BodyValue::Text(s),
            (Y::Null, _) => BodyValue::Null,
            (other, _) => BodyValue::Other(other.type_name().to_string()),
        };
        entries.push((at, name, value));
    }
    (entries, problems)
}

/// One value of a body mapping, as a body file, a request or a Python dict
/// gives it: the input of [`Body::from_entries`].
#[derive(Clone, Debug, PartialEq)]
pub enum BodyValue<'a> {
    /// A number.
    Number(f64),
    /// A string: the `base` body's name, `body_sample`.
    Text(&'a str),
    /// No value (`null`, `None`): leaves an optional measurement out.
    Null,
    /// Anything else, described for the error (`sequence`, `a JSON object`).
    Other(String),
}

impl BodyValue<'_> {
    /// The value as an error shows it.
    fn describe(&self) -> String {
        match self {
            BodyValue::Number(x) => short(*x).to_string(),
            BodyValue::Text(s) => quote(s),
            BodyValue::Null => "null".into(),
            BodyValue::Other(what) => what.clone(),
        }
    }
}

impl Body {
    /// Read a body file (`body:` mapping of every measurement). A file that
    /// starts from a built-in body (`base:`) needs the built-in bodies: see
    /// [`Body::from_yaml_with_bases`].
    pub fn from_yaml(text: &str, file: &str) -> Result<Body, BodyError> {
        Body::from_yaml_with_bases(text, file, &[])
    }

    /// Read a body file whose `body:` mapping may start from another body:
    /// `base: NAME` takes every measurement of the body `NAME` of `bases` (name
    /// and body file text: `garments::builtin::BODIES`), and the measurements the
    /// file lists replace the base's. Problems name the line, the measurement and
    /// its plausible range (see [`Body::from_entries`]).
    pub fn from_yaml_with_bases(text: &str, file: &str, bases: &[(&str, &str)]) -> Result<Body, BodyError> {
        let fail = |p: String| BodyError { file: file.to_string(), problems: vec![p] };
        let doc = yaml::parse(text).map_err(|e| fail(e.to_string()))?;
        let body = doc.get("body").ok_or_else(|| fail("expected a top-level `body:` mapping of measurements".into()))?;
        let pairs = body.as_map().ok_or_else(|| fail("`body` must be a mapping of measurements".into()))?;
        let (entries, mut problems) = yaml_entries(pairs);
        match Body::from_entries(&entries, bases) {
            Ok(body) if problems.is_empty() => Ok(body),
            Ok(_) => Err(BodyError { file: file.to_string(), problems }),
            Err(more) => {
                problems.extend(more);
                Err(BodyError { file: file.to_string(), problems })
            }
        }
    }

    /// A body from the entries of a body mapping, each `(at, name, value)`, where
    /// `at` prefixes the entry's problems (`line 3: ` in a file, empty
    /// otherwise). The one reading of body mappings: body files, the web API's
    /// measurements and the Python package's dicts all come here.
    ///
    /// - `base`: the name of a body of `bases` (name and body file text) to start
    ///   from; the other entries replace its measurements. Without a base every
    ///   measurement that is not optional must be given.
    /// - a measurement: a finite number within its plausible range
    ///   ([`Body::check_measurement`]); `null` leaves an optional one out.
    /// - `body_sample`: a string (the body mesh of a dataset sample).
    /// - `units`: `cm` (the default) or `in`: the lengths given are in inches
    ///   (angles stay in degrees); the body holds them in cm.
    /// - derived values (`_` names) are ignored: they are always recomputed.
    ///
    /// Every problem is listed, one line each; the body must then pass
    /// [`Body::check_derived`].
    pub fn from_entries(entries: &[(String, &str, BodyValue<'_>)], bases: &[(&str, &str)]) -> Result<Body, Vec<String>> {
        let mut problems = Vec::new();
        let mut base: Option<Body> = None;
        for (at, _, value) in entries.iter().filter(|(_, name, _)| *name == "base") {
            match value {
                BodyValue::Text(name) => match bases.iter().find(|(n, _)| n == name) {
                    Some((n, text)) => {
                        base = Some(Body::from_yaml(text, &format!("<body {n}>")).map_err(|e| vec![format!("{at}body.base: {e}")])?)
                    }
                    None => {
                        let known: Vec<&str> = bases.iter().map(|(n, _)| *n).collect();
                        problems.push(format!(
                            "{at}body.base: no built-in body {}{} (built-in: {})",
                            crate::message::quote_name(name),
                            did_you_mean(name, known.iter().copied()),
                            if known.is_empty() { "none known here".to_string() } else { known.join(", ") }
                        ));
                    }
                },
                other => problems.push(format!("{at}body.base: expected the name of a built-in body, got {}", other.describe())),
            }
        }
        // `units: in`: lengths given in inches (angles stay degrees).
        let mut inches = false;
        for (at, _, value) in entries.iter().filter(|(_, name, _)| *name == "units") {
            match value {
                BodyValue::Text("cm") => inches = false,
                BodyValue::Text("in") => inches = true,
                other => problems.push(format!("{at}body.units: expected cm or in, got {}", other.describe())),
            }
        }
        let base_values: Vec<Option<f64>> = MEASUREMENTS.iter().map(|m| base.as_ref().and_then(|b| b.get(m.name))).collect();
        let mut values = base_values.clone();
        let mut given = vec![false; MEASUREMENTS.len()];
        let mut body_sample = base.as_ref().and_then(|b| b.body_sample.clone());
        for (at, name, value) in entries {
            if *name == "base" || *name == "units" || name.starts_with('_') {
                continue; // read above; derived values are always recomputed
            }
            if *name == "body_sample" {
                if let BodyValue::Text(s) = value {
                    body_sample = Some(s.to_string());
                }
                continue;
            }
            let Some(i) = MEASUREMENTS.iter().position(|m| m.name == *name) else {
                let shown = if name.chars().count() > crate::message::QUOTE_CHARS { quote(name) } else { name.to_string() };
                problems.push(format!("{at}body.{shown}: unknown measurement{}", did_you_mean(name, Body::measurement_names())));
                continue;
            };
            given[i] = true;
            match value {
                BodyValue::Number(x) => {
                    let in_inches = inches && MEASUREMENTS[i].unit == "cm";
                    let cm = if in_inches { x * 2.54 } else { *x };
                    match Body::check_measurement(name, cm) {
                        Ok(()) => values[i] = Some(cm),
                        Err(e) if in_inches => problems.push(format!("{at}body.{name}: {} in: {e}", short(*x))),
                        Err(e) => problems.push(format!("{at}body.{name}: {e}")),
                    }
                }
                BodyValue::Null if MEASUREMENTS[i].optional => values[i] = None,
                other => problems.push(format!("{at}body.{name}: expected a number, got {}", other.describe())),
            }
        }
        // A base that cannot be read is the one problem: the measurements it would
        // have given are not missing.
        let has_base = entries.iter().any(|(_, name, _)| *name == "base");
        for ((m, value), &given) in MEASUREMENTS.iter().zip(&values).zip(&given) {
            if value.is_none() && !m.optional && !given && !has_base {
                problems.push(format!("body.{}: missing measurement ({})", m.name, m.description));
            }
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        // Over a base, a measurement not given follows the one it is in proportion to.
        for &(name, driver) in PROPORTIONS {
            let index = |n: &str| MEASUREMENTS.iter().position(|m| m.name == n).expect("PROPORTIONS names measurements");
            let (i, d) = (index(name), index(driver));
            if let (false, true, Some(value), Some(from), Some(to)) = (given[i], given[d], values[i], base_values[d], values[d]) {
                values[i] = Some(value * to / from);
            }
        }
        let body = Body::from_values(&values, body_sample);
        body.check_derived()?;
        Ok(body)
    }

    /// Check what single measurements cannot show: the derived values and the
    /// back parts of circumferences must make sense together. One line per
    /// problem.
    pub fn check_derived(&self) -> Result<(), Vec<String>> {
        let d = self.derived();
        let mut problems = Vec::new();
        if d.waist_level <= 0.0 {
            problems.push(format!(
                "height ({}) must exceed head_l + waist_line ({}): the waist would be below the floor",
                self.height,
                self.head_l + self.waist_line
            ));
        } else if d.leg_length <= 0.0 {
            problems.push(format!(
                "height − head_l − waist_line ({}) must exceed hips_line ({}): the hips would be below the floor",
                d.waist_level, self.hips_line
            ));
        }
        for (part, whole) in [("waist_back_width", "waist"), ("back_width", "bust"), ("hip_back_width", "hips")] {
            let (p, w) = (self.get(part).unwrap_or(0.0), self.get(whole).unwrap_or(0.0));
            if p >= w {
                problems.push(format!("{part} ({p}) must be smaller than {whole} ({w}), of which it is the back part"));
            }
        }
        for &(a, b, low, high) in RATIOS {
            let (Some(x), Some(y)) = (self.get(a), self.get(b)) else { continue };
            let ratio = x / y;
            if !(low..=high).contains(&ratio) {
                problems.push(format!(
                    "{a} ({}) is {ratio:.2} × {b} ({}): implausible together (a body's {a}/{b} is within {low}..{high}); check both values",
                    short(x),
                    short(y)
                ));
            }
        }
        if problems.is_empty() { Ok(()) } else { Err(problems) }
    }

    /// Measurement values by name (the reference's keys), derived ones with `_`.
    pub fn entries(&self) -> Vec<(&'static str, f64)> {
        let mut out: Vec<(&'static str, f64)> = DERIVED_VALUES.iter().map(|d| d.name).zip(self.derived().values()).collect();
        for m in MEASUREMENTS {
            if let Some(v) = self.get(m.name) {
                out.push((m.name, v));
            }
        }
        out
    }

    /// A raw measurement by name.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.slot(name).flatten()
    }

    /// Set a raw measurement by name (for tools); `false` for unknown names.
    pub fn set(&mut self, name: &str, v: f64) -> bool {
        self.set_slot(name, v)
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
        MEASUREMENTS.iter().map(|m| m.name)
    }

    /// The declaration of a raw measurement.
    pub fn measurement(name: &str) -> Option<&'static Measurement> {
        MEASUREMENTS.iter().find(|m| m.name == name)
    }

    /// Whether a measurement is an angle (degrees) rather than a length.
    pub fn is_angle(name: &str) -> bool {
        Body::measurement(name).is_some_and(|m| m.unit == "deg")
    }

    /// Check one raw measurement as body files are checked: a known name and a
    /// finite number within the measurement's plausible range. The error says
    /// what is allowed and, when the value looks like another unit (metres,
    /// millimetres, inches, radians), what it probably meant (without the name,
    /// which the caller prefixes).
    pub fn check_measurement(name: &str, x: f64) -> Result<(), String> {
        let Some(m) = Body::measurement(name) else {
            return Err(format!("unknown measurement{}", did_you_mean(name, Body::measurement_names())));
        };
        if !x.is_finite() {
            return Err(format!("expected a finite number, got {}", short(x)));
        }
        if (m.min..=m.max).contains(&x) {
            return Ok(());
        }
        let unit = m.unit;
        let mut e = format!(
            "{} {unit} is outside the plausible range {} to {} {unit} ({})",
            short(x),
            m.min,
            m.max,
            m.description.trim_end_matches('.')
        );
        let conversions: &[(f64, &str)] = if unit == "cm" {
            &[(100.0, "metres"), (0.1, "millimetres"), (2.54, "inches")]
        } else {
            &[(180.0 / std::f64::consts::PI, "radians")]
        };
        if let Some((factor, other)) = conversions.iter().find(|(f, _)| (m.min..=m.max).contains(&(x * f))) {
            e.push_str(&format!("; it looks like {other}: in {unit} that is {}", round4(x * factor)));
        }
        Err(e)
    }

    /// What a raw or derived (`_`-prefixed) measurement is, for tools that show
    /// them.
    pub fn describe_measurement(name: &str) -> Option<&'static str> {
        let raw = MEASUREMENTS.iter().find(|m| m.name == name).map(|m| m.description);
        raw.or_else(|| DERIVED_VALUES.iter().find(|d| d.name == name).map(|d| d.description))
    }
}

/// `x` rounded to 4 decimals, for hints.
fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// ` (did you mean `NAME`?)` for the closest of `known`, one or two edits away.
fn did_you_mean<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> String {
    let best = known.map(|k| (edit_distance(name, k), k)).min();
    match best {
        Some((d, n)) if d <= 2 => format!(" (did you mean `{n}`?)"),
        _ => String::new(),
    }
}

/// Levenshtein distance (short names only).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().take(64).collect(), b.chars().collect());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            cur.push((prev[j] + usize::from(ca != cb)).min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mean_female() -> String {
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../garments/data/bodies/mean_female.yaml")).unwrap()
    }

    #[test]
    fn every_reference_body_is_within_the_plausible_ranges() {
        for n in ["mean_all", "mean_female", "mean_male", "f_smpl_average_A40", "m_smpl_average_A40"] {
            let text = std::fs::read_to_string(format!("{}/../garments/data/bodies/{n}.yaml", env!("CARGO_MANIFEST_DIR"))).unwrap();
            let b = Body::from_yaml(&text, n).unwrap();
            for m in MEASUREMENTS {
                if let Some(x) = b.get(m.name) {
                    assert!(x > m.min && x < m.max, "{n}: {} = {x}", m.name);
                }
            }
        }
    }

    #[test]
    fn a_measurement_in_metres_is_refused_with_a_hint() {
        let text = mean_female();
        let text =
            text.lines().map(|l| if l.trim_start().starts_with("leg_circ:") { "  leg_circ: 0.606592" } else { l }).collect::<Vec<_>>();
        let e = Body::from_yaml(&text.join("\n"), "f.yaml").unwrap_err().to_string();
        assert!(e.contains("body.leg_circ: 0.606592 cm is outside the plausible range 20 to 130 cm"), "{e}");
        assert!(e.contains("looks like metres: in cm that is 60.6592"), "{e}");
    }

    #[test]
    fn ranges_and_unit_hints() {
        assert!(Body::check_measurement("height", 170.0).is_ok());
        assert!(Body::check_measurement("height", 1700.0).unwrap_err().contains("millimetres"));
        assert!(Body::check_measurement("height", 66.0).unwrap_err().contains("inches: in cm that is 167.64"));
        assert!(Body::check_measurement("height", 1e6).unwrap_err().contains("outside the plausible range"));
        assert!(Body::check_measurement("height", 1e-6).is_err());
        assert!(Body::check_measurement("shoulder_incl", 0.3).is_ok());
        assert!(Body::check_measurement("arm_pose_angle", 91.0).is_err());
        assert!(Body::check_measurement("heigth", 1.0).unwrap_err().contains("did you mean `height`"));
        assert!(Body::check_measurement("height", f64::NAN).is_err());
    }

    #[test]
    fn a_body_file_may_start_from_a_base_body() {
        let text = mean_female();
        let bases = [("mean_female", text.as_str())];
        let base = Body::from_yaml(&text, "f").unwrap();
        let b = Body::from_yaml_with_bases("body:\n  waist: 70.0\n  base: mean_female\n  hips: 101.5\n", "p.yaml", &bases).unwrap();
        assert_eq!((b.waist, b.hips), (70.0, 101.5));
        assert_eq!(b.height, base.height);
        assert_eq!(b.derived().waist_level, base.derived().waist_level);
        // Problems name the file, the line, the measurement and its range.
        let e = Body::from_yaml_with_bases("body:\n  base: mean_female\n  waist: 0.7\n", "p.yaml", &bases).unwrap_err().to_string();
        assert!(e.starts_with("p.yaml: line 3: body.waist: 0.7 cm is outside the plausible range"), "{e}");
        // An unknown base is named, with a suggestion and the known ones.
        let e = Body::from_yaml_with_bases("body:\n  base: mean_femal\n", "p.yaml", &bases).unwrap_err().to_string();
        assert!(
            e.contains("line 2: body.base: no built-in body `mean_femal` (did you mean `mean_female`?) (built-in: mean_female)"),
            "{e}"
        );
        assert!(!e.contains("missing"), "{e}");
        // Without the built-in bodies, or without a base, nothing is filled in.
        let e = Body::from_yaml("body:\n  base: mean_female\n", "p.yaml").unwrap_err().to_string();
        assert!(e.contains("no built-in body `mean_female`") && e.contains("none known here"), "{e}");
        let e = Body::from_yaml_with_bases("body:\n  waist: 70\n", "p.yaml", &bases).unwrap_err().to_string();
        assert!(e.contains("body.height: missing measurement"), "{e}");
        let e = Body::from_yaml_with_bases("body:\n  base: 3\n", "p.yaml", &bases).unwrap_err().to_string();
        assert!(e.contains("body.base: expected the name of a built-in body, got 3"), "{e}");
    }

    #[test]
    fn a_body_file_may_give_inches() {
        let text = mean_female();
        let bases = [("mean_female", text.as_str())];
        let base = Body::from_yaml(&text, "f").unwrap();
        let b = Body::from_yaml_with_bases("body:\n  base: mean_female\n  units: in\n  waist: 28\n  shoulder_incl: 20\n", "p.yaml", &bases)
            .unwrap();
        assert_eq!(b.waist, 28.0 * 2.54);
        assert_eq!(b.height, base.height, "the base's measurements stay in cm");
        assert_eq!(b.shoulder_incl, 20.0, "angles stay in degrees");
        // A value out of range names what was given and what it is in cm.
        let e = Body::from_yaml_with_bases("body:\n  base: mean_female\n  units: in\n  waist: 700\n", "p.yaml", &bases)
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 4: body.waist: 700 in: 1778 cm is outside the plausible range"), "{e}");
        let e = Body::from_yaml_with_bases("body:\n  base: mean_female\n  units: inch\n", "p.yaml", &bases).unwrap_err().to_string();
        assert!(e.contains("line 3: body.units: expected cm or in, got \"inch\""), "{e}");
    }

    #[test]
    fn measurements_left_out_follow_the_given_ones_in_proportion() {
        let text = mean_female();
        let bases = [("mean_female", text.as_str())];
        let base = Body::from_yaml(&text, "f").unwrap();
        let b = Body::from_yaml_with_bases(
            "body:\n  base: mean_female\n  height: 180\n  bust: 88\n  hips: 110\n  hip_back_width: 50\n",
            "p.yaml",
            &bases,
        )
        .unwrap();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
        assert!(close(b.arm_length, base.arm_length * 180.0 / base.height));
        assert!(close(b.waist_line, base.waist_line * 180.0 / base.height));
        assert!(close(b.underbust, base.underbust * 88.0 / base.bust));
        assert!(close(b.back_width, base.back_width * 88.0 / base.bust));
        assert!(close(b.leg_circ, base.leg_circ * 110.0 / base.hips));
        assert_eq!(b.hip_back_width, 50.0, "a measurement given is kept");
        assert_eq!(b.waist, base.waist, "the waist was not given");
        assert_eq!(b.waist_back_width, base.waist_back_width, "nor what follows it");
        assert_eq!(b.shoulder_incl, base.shoulder_incl, "angles stay");
        // Every proportion names a measurement and its driver.
        for (m, d) in PROPORTIONS {
            assert!(Body::measurement(m).is_some() && Body::measurement(d).is_some(), "{m} {d}");
        }
    }

    #[test]
    fn measurements_that_do_not_fit_together_are_named() {
        let text = mean_female();
        let bases = [("mean_female", text.as_str())];
        let e = Body::from_yaml_with_bases("body:\n  base: mean_female\n  waist: 160\n  hips: 100\n", "p.yaml", &bases)
            .unwrap_err()
            .to_string();
        assert!(e.contains("waist (160) is 1.60 × hips (100): implausible together (a body's waist/hips is within 0.5..1.5)"), "{e}");
    }

    #[test]
    fn derived_checks_catch_inconsistent_bodies() {
        let mut b = Body::from_yaml(&mean_female(), "f").unwrap();
        assert!(b.check_derived().is_ok());
        b.set("waist_back_width", b.waist + 1.0);
        let e = b.check_derived().unwrap_err();
        assert!(e[0].contains("waist_back_width"), "{e:?}");
    }

    #[test]
    fn the_tables_drive_the_struct_and_the_files() {
        let b = Body::from_yaml(&mean_female(), "f").unwrap();
        let written = b.to_yaml();
        for m in MEASUREMENTS.iter().filter(|m| !m.optional) {
            assert!(written.contains(&format!("  {}: ", m.name)), "{}", m.name);
            assert!(Body::describe_measurement(m.name).is_some());
        }
        for d in DERIVED_VALUES {
            assert!(written.contains(&format!("  {}: ", d.name)), "{}", d.name);
        }
        assert_eq!(Body::from_yaml(&written, "again").unwrap(), b);
        let names: Vec<&str> = DERIVED_VALUES.iter().map(|d| d.name).collect();
        let mut sorted = names.clone();
        sorted.sort();
        assert_eq!(names, sorted);
    }
}
