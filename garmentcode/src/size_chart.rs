//! Size charts: a run of sizes, each given by a few measurements over a base body.
//!
//! A size chart file lists sizes by the measurements a chart gives (bust, waist,
//! hips, height, ...) over one of the built-in bodies; every other measurement of a
//! size follows its base in proportion (see [`crate::PROPORTIONS`]), exactly as in
//! a body file with `base:`:
//!
//! ```yaml
//! size_chart:
//!   name: Women, height 168
//!   base: mean_female
//!   units: cm            # or in
//!   sizes:
//!     "36": {bust: 84, waist: 68, hips: 92}
//!     "38": {bust: 88, waist: 72, hips: 96}
//! ```

use crate::body::{Body, BodyError, BodyValue, yaml_entries};
use crate::message::quote_name;
use crate::parity::yaml::{self, Value as Y};

/// Most sizes in one chart (a run is printed nested on one sheet).
pub const MAX_SIZES: usize = 20;

/// A size chart read from a file: its name and its sizes in the file's order.
///
/// The file lists sizes by the measurements a chart gives over one of the
/// built-in bodies; every other measurement of a size follows its base in
/// proportion (see [`crate::PROPORTIONS`]), as in a body file with `base:`:
///
/// ```yaml
/// size_chart:
///   name: Women, height 168
///   base: mean_female
///   units: cm            # or in
///   sizes:
///     "36": {bust: 84, waist: 68, hips: 92}
///     "38": {bust: 88, waist: 72, hips: 96}
/// ```
///
/// ```
/// use garmentcode::SizeChart;
/// let female = "body:\n  height: 166\n  head_l: 25.5\n  waist_line: 35.8\n  waist_over_bust_line: 40\n  bust_line: 25.6\n  hips_line: 22.6\n  crotch_hip_diff: 7.9\n  armscye_depth: 12.6\n  arm_length: 51.6\n  bust: 97.4\n  underbust: 80.7\n  waist: 80.3\n  hips: 104\n  leg_circ: 60.7\n  wrist: 15.9\n  neck_w: 17.8\n  shoulder_w: 34.7\n  back_width: 46.2\n  waist_back_width: 37.8\n  hip_back_width: 55.7\n  bust_points: 16.2\n  bum_points: 17.7\n  shoulder_incl: 20.9\n  hip_inclination: 12.7\n  arm_pose_angle: 45.5\n";
/// let chart = "size_chart:\n  name: demo\n  base: f\n  sizes:\n    S: {bust: 84, waist: 68, hips: 92}\n    M: {bust: 92, waist: 76, hips: 100}\n";
/// let c = SizeChart::from_yaml(chart, "chart.yaml", &[("f", female)])?;
/// assert_eq!(c.sizes.len(), 2);
/// assert_eq!((c.sizes[1].0.as_str(), c.sizes[1].1.waist), ("M", 76.0));
/// # Ok::<(), garmentcode::BodyError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SizeChart {
    /// The chart's name (`name:`, or the file's).
    pub name: String,
    /// Each size's name and body.
    pub sizes: Vec<(String, Body)>,
}

impl SizeChart {
    /// Reads a size chart file (`size_chart:` with `name`, `base`, `units` and `sizes`,
    /// each size a mapping of measurements as in a body file); `bases` are the
    /// bodies a chart may start from (`garments::builtin::BODIES`). Every problem is
    /// listed with its line, the size and the measurement.
    pub fn from_yaml(text: &str, file: &str, bases: &[(&str, &str)]) -> Result<SizeChart, BodyError> {
        let fail = |problems: Vec<String>| BodyError { file: file.to_string(), problems };
        let doc = yaml::parse(text).map_err(|e| fail(vec![e.to_string()]))?;
        let chart = doc.get("size_chart").and_then(|c| c.as_map()).ok_or_else(|| {
            fail(vec!["expected a top-level `size_chart:` mapping with `base:` and `sizes:` (see `garmentcode print --help`)".into()])
        })?;
        let mut problems = Vec::new();
        let (mut name, mut base, mut units, mut sizes) = (None, None, None, None);
        for (k, v) in chart {
            let at = format!("line {}: size_chart.", k.line);
            match (k.as_str(), &v.value) {
                (Some("name"), Y::Str(s)) => name = Some(s.clone()),
                (Some("base"), Y::Str(_)) => base = Some(v),
                (Some("units"), Y::Str(_)) => units = Some(v),
                (Some("sizes"), Y::Map(m)) => sizes = Some(m),
                (Some(key @ ("name" | "base" | "units")), other) => {
                    problems.push(format!("{at}{key}: expected a string, got {}", other.type_name()))
                }
                (Some("sizes"), other) => {
                    problems.push(format!("{at}sizes: expected a mapping of size names to measurements, got {}", other.type_name()))
                }
                (Some(key), _) => problems.push(format!("{at}{}: unknown key (expected name, base, units, sizes)", quote_name(key))),
                (None, _) => problems.push(format!("{at}: keys must be strings")),
            }
        }
        let Some(base) = base else {
            problems.push("size_chart.base: missing: the built-in body the sizes start from (e.g. mean_female)".into());
            return Err(fail(problems));
        };
        let Some(sizes) = sizes else {
            problems.push("size_chart.sizes: missing: a mapping of size names to measurements".into());
            return Err(fail(problems));
        };
        if sizes.is_empty() || sizes.len() > MAX_SIZES {
            problems.push(format!("size_chart.sizes: {} sizes; a chart has 1 to {MAX_SIZES}", sizes.len()));
            return Err(fail(problems));
        }
        let mut out = Vec::with_capacity(sizes.len());
        for (k, v) in sizes {
            let size = match &k.value {
                Y::Str(s) => s.clone(),
                Y::Int(i) => i.to_string(),
                _ => k.as_f64().map(|x| crate::message::short(x).to_string()).unwrap_or_default(),
            };
            if let Err(e) = crate::io::check_name("a size name", &size) {
                problems.push(format!("line {}: size_chart.sizes: {e}", k.line));
                continue;
            }
            if out.iter().any(|(n, _)| *n == size) {
                problems.push(format!("line {}: size_chart.sizes: size {} is listed twice", k.line, quote_name(&size)));
                continue;
            }
            let Some(pairs) = v.as_map() else {
                problems.push(format!("line {}: size_chart.sizes.{size}: expected a mapping of measurements", k.line));
                continue;
            };
            let (mut entries, more) = yaml_entries(pairs);
            let mut head = vec![(format!("line {}: ", base.line), "base", text_of(base))];
            if let Some(u) = units {
                head.push((format!("line {}: ", u.line), "units", text_of(u)));
            }
            if let Some((at, name, _)) = entries.iter().find(|(_, n, _)| *n == "base" || *n == "units") {
                problems.push(format!("{at}size_chart.sizes.{size}.{name}: set for the whole chart, not per size"));
                continue;
            }
            head.append(&mut entries);
            problems.extend(more.into_iter().map(|p| format!("size {size}: {p}")));
            match Body::from_entries(&head, bases) {
                Ok(body) => out.push((size, body)),
                Err(more) => problems.extend(
                    more.into_iter().map(|p| format!("size {size}: {}", p.replacen("body.", &format!("size_chart.sizes.{size}."), 1))),
                ),
            }
        }
        if !problems.is_empty() {
            return Err(fail(problems));
        }
        let name = name.unwrap_or_else(|| file.rsplit(['/', '\\']).next().unwrap_or(file).to_string());
        crate::io::check_name("the size chart's name", &name).map_err(|e| fail(vec![format!("size_chart.name: {e}")]))?;
        Ok(SizeChart { name, sizes: out })
    }
}

fn text_of(node: &crate::parity::yaml::Node) -> BodyValue<'_> {
    match &node.value {
        Y::Str(s) => BodyValue::Text(s),
        other => BodyValue::Other(other.type_name().to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bases() -> Vec<(&'static str, String)> {
        vec![(
            "mean_female",
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../garments/data/bodies/mean_female.yaml")).unwrap(),
        )]
    }

    fn read(text: &str) -> Result<SizeChart, String> {
        let b = bases();
        let b: Vec<(&str, &str)> = b.iter().map(|(n, t)| (*n, t.as_str())).collect();
        SizeChart::from_yaml(text, "chart.yaml", &b).map_err(|e| e.to_string())
    }

    #[test]
    fn a_chart_gives_bodies_over_its_base() {
        let c = read("size_chart:\n  name: test\n  base: mean_female\n  units: in\n  sizes:\n    S: {bust: 33, waist: 26, hips: 36}\n    36: {bust: 35, waist: 28, hips: 38}\n")
            .unwrap();
        assert_eq!(c.name, "test");
        assert_eq!(c.sizes.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), ["S", "36"]);
        assert!((c.sizes[0].1.waist - 26.0 * 2.54).abs() < 1e-9);
        let base = Body::from_yaml(&bases()[0].1, "f").unwrap();
        assert_eq!(c.sizes[0].1.height, base.height);
        assert!((c.sizes[0].1.underbust - base.underbust * 33.0 * 2.54 / base.bust).abs() < 1e-9, "proportions apply");
    }

    #[test]
    fn problems_name_the_line_the_size_and_the_measurement() {
        let e =
            read("size_chart:\n  base: mean_female\n  sizes:\n    S: {bust: 84, waist: 6800}\n    M: {bust: 88, wasit: 70}\n").unwrap_err();
        assert!(e.contains("chart.yaml:") && e.contains("size S: line 4: size_chart.sizes.S.waist: 6800"), "{e}");
        assert!(e.contains("size M: line 5: size_chart.sizes.M.wasit: unknown measurement (did you mean `waist`?)"), "{e}");
        let e = read("size_chart:\n  base: mean_femal\n  sizes:\n    S: {bust: 84}\n").unwrap_err();
        assert!(e.contains("no built-in body `mean_femal`"), "{e}");
        let e = read("size_chart:\n  base: mean_female\n  sizes: {}\n").unwrap_err();
        assert!(e.contains("0 sizes; a chart has 1 to 20"), "{e}");
        let e = read("sizes: {}\n").unwrap_err();
        assert!(e.contains("expected a top-level `size_chart:`"), "{e}");
        let e = read("size_chart:\n  base: mean_female\n  colour: red\n  sizes:\n    S: {bust: 84}\n").unwrap_err();
        assert!(e.contains("line 3: size_chart.`colour`: unknown key"), "{e}");
    }
}
