//! Fabrics: the material part of the drape [`Settings`], as the reference's simulation
//! property files (`assets/Sim_props/*.yaml`, section `sim.config.material`) give it.
//!
//! The built-in fabrics are the reference's presets for its Warp simulator: `default`
//! (`default_sim_props.yaml`, a very soft fabric), `mid_bending` (`mid_bending.yaml`, also
//! the material of `gui_sim_props.yaml`) and `minimal_bending` (`minimal_bending.yaml`;
//! despite its name the stiffest in bending). They differ only in bending stiffness. The
//! reference's `*_ochra.json` files are for another simulator (their keys have no
//! counterpart here) and are not offered.
//!
//! A fabric file is YAML with a top-level `fabric:` mapping of the keys of [`KEYS`] (the
//! reference's names), each optional (missing ones keep the `base:` fabric's value, the
//! `default` one unless `base:` names another), each range-checked.

use garmentcode::parity::yaml::{self, Value as Y};

use crate::Settings;

/// A fabric: the material settings of a drape.
#[derive(Clone, Debug, PartialEq)]
pub struct Fabric {
    /// Its name (a built-in name or the file's).
    pub name: String,
    /// Edge spring stiffness (`spring_ke`).
    pub spring_ke: f64,
    /// Edge spring damping (`spring_kd`).
    pub spring_kd: f64,
    /// Bending stiffness (`garment_edge_ke`).
    pub bend_ke: f64,
    /// Bending damping (`garment_edge_kd`).
    pub bend_kd: f64,
    /// Mass per cm² (`fabric_density`).
    pub density: f64,
    /// The reference's `fabric_thickness`, which its simulator uses as every particle's base mass.
    pub thickness: f64,
    /// Friction with the body (`fabric_friction`).
    pub friction: f64,
}

/// The keys of a fabric file with their allowed ranges (inclusive; 0 excluded where the
/// lower end is 0 and the value must be positive) and what they mean.
pub const KEYS: [(&str, f64, f64, &str); 7] = [
    ("spring_ke", 10.0, 1e7, "stretch stiffness of the fabric's edges"),
    ("spring_kd", 0.0, 1e3, "stretch damping"),
    ("garment_edge_ke", 1e-3, 1e5, "bending stiffness"),
    ("garment_edge_kd", 0.0, 1e3, "bending damping"),
    ("fabric_density", 1e-3, 100.0, "mass per cm²"),
    ("fabric_thickness", 1e-3, 10.0, "base mass of every particle (the reference's use of it)"),
    ("fabric_friction", 0.0, 2.0, "friction coefficient with the body"),
];

/// The built-in fabrics' names, `default` first.
pub const BUILTIN: [&str; 3] = ["default", "mid_bending", "minimal_bending"];

/// Why a fabric was refused: names the file (or the name asked for) and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}: {problems}", problems = .problems.join("; "))]
pub struct FabricError {
    /// The file, or the built-in name asked for.
    pub file: String,
    /// Each problem, with its line where known.
    pub problems: Vec<String>,
}

impl Default for Fabric {
    /// The reference's default fabric (`default_sim_props.yaml`).
    fn default() -> Fabric {
        let s = Settings::default();
        Fabric {
            name: "default".into(),
            spring_ke: s.spring_ke,
            spring_kd: s.spring_kd,
            bend_ke: s.bend_ke,
            bend_kd: s.bend_kd,
            density: s.density,
            thickness: s.base_mass,
            friction: s.fabric_friction,
        }
    }
}

impl Fabric {
    /// A built-in fabric by name (see [`BUILTIN`]).
    pub fn builtin(name: &str) -> Result<Fabric, FabricError> {
        let bend_ke = match name {
            "default" => 1.0,
            "mid_bending" => 100.0,
            "minimal_bending" => 500.0,
            _ => {
                return Err(FabricError {
                    file: name.into(),
                    problems: vec![format!(
                        "no built-in fabric of that name{} (built-in: {})",
                        did_you_mean(name, &BUILTIN),
                        BUILTIN.join(", ")
                    )],
                });
            }
        };
        Ok(Fabric { name: name.into(), bend_ke, ..Fabric::default() })
    }

    /// Reads a fabric file (see the [module documentation](self)); `file` names it in errors.
    pub fn from_yaml(text: &str, file: &str) -> Result<Fabric, FabricError> {
        let fail = |p: String| FabricError { file: file.into(), problems: vec![p] };
        let doc = yaml::parse(text).map_err(|e| fail(e.to_string()))?;
        let pairs = doc.get("fabric").and_then(|f| f.as_map()).ok_or_else(|| {
            fail(format!("expected a top-level `fabric:` mapping of fabric parameters ({})", KEYS.map(|k| k.0).join(", ")))
        })?;
        let name = std::path::Path::new(file).file_stem().map_or_else(|| file.to_string(), |s| s.to_string_lossy().into_owned());
        let mut fabric = Fabric::default();
        if let Some(base) = pairs.iter().find(|(k, _)| k.as_str() == Some("base")).map(|(_, v)| v) {
            let at = format!("line {}: base", base.line);
            let Some(b) = base.as_str() else {
                return Err(fail(format!("{at}: must be a built-in fabric's name ({})", BUILTIN.join(", "))));
            };
            fabric = Fabric::builtin(b).map_err(|e| fail(format!("{at}: {}", e.problems.join("; "))))?;
        }
        fabric.name = name;
        let mut problems = Vec::new();
        let mut seen = Vec::new();
        for (k, v) in pairs {
            let at = format!("line {}", k.line);
            let Some(key) = k.as_str() else {
                problems.push(format!("{at}: keys must be names"));
                continue;
            };
            if key == "base" {
                continue;
            }
            let known = KEYS.map(|k| k.0);
            let Some(&(_, lo, hi, what)) = KEYS.iter().find(|k| k.0 == key) else {
                problems.push(format!(
                    "{at}: fabric.{key}: unknown fabric parameter{} (known: base, {})",
                    did_you_mean(key, &known),
                    known.join(", ")
                ));
                continue;
            };
            if seen.contains(&key) {
                problems.push(format!("{at}: fabric.{key}: given twice"));
                continue;
            }
            seen.push(key);
            // YAML 1.1 reads `1e5` (no dot) as text: taken as the number it spells.
            let value = match &v.value {
                Y::Int(_) | Y::Float(_) => v.as_f64(),
                Y::Str(t) => t.trim().parse::<f64>().ok(),
                _ => None,
            };
            match value {
                Some(x) if x.is_finite() && (lo..=hi).contains(&x) => fabric.set(key, x),
                _ => problems.push(format!("{at}: fabric.{key} = {}: the {what} must be a number from {lo} to {hi}", source_text(text, v))),
            }
        }
        if problems.is_empty() { Ok(fabric) } else { Err(FabricError { file: file.into(), problems }) }
    }

    fn set(&mut self, key: &str, x: f64) {
        match key {
            "spring_ke" => self.spring_ke = x,
            "spring_kd" => self.spring_kd = x,
            "garment_edge_ke" => self.bend_ke = x,
            "garment_edge_kd" => self.bend_kd = x,
            "fabric_density" => self.density = x,
            "fabric_thickness" => self.thickness = x,
            "fabric_friction" => self.friction = x,
            _ => unreachable!("a key of KEYS"),
        }
    }

    /// The fabric's parameters under the keys of [`KEYS`], in that order.
    pub fn values(&self) -> [(&'static str, f64); 7] {
        let v = [self.spring_ke, self.spring_kd, self.bend_ke, self.bend_kd, self.density, self.thickness, self.friction];
        std::array::from_fn(|i| (KEYS[i].0, v[i]))
    }

    /// `settings` with this fabric's material.
    pub fn apply(&self, settings: Settings) -> Settings {
        Settings {
            spring_ke: self.spring_ke,
            spring_kd: self.spring_kd,
            bend_ke: self.bend_ke,
            bend_kd: self.bend_kd,
            density: self.density,
            base_mass: self.thickness,
            fabric_friction: self.friction,
            ..settings
        }
    }
}

/// The text of a scalar value as the file writes it (its line from its column, without a
/// comment), or the kind of a collection.
fn source_text(text: &str, v: &yaml::Node) -> String {
    match &v.value {
        Y::Seq(_) => "a list".into(),
        Y::Map(_) => "a mapping".into(),
        _ => {
            let line = text.lines().nth((v.line as usize).saturating_sub(1)).unwrap_or("");
            let rest: String = line.chars().skip((v.col as usize).saturating_sub(1)).collect();
            let rest = rest.split(" #").next().unwrap_or("").trim();
            if rest.is_empty() { "nothing".into() } else { rest.chars().take(40).collect() }
        }
    }
}

/// ` (did you mean `NAME`?)` for the closest of `known`, at most two edits away.
fn did_you_mean(word: &str, known: &[&str]) -> String {
    let best = known.iter().map(|k| (edit_distance(word, k), *k)).min();
    match best {
        Some((d, k)) if d <= 2 && d < k.len() => format!(" (did you mean `{k}`?)"),
        _ => String::new(),
    }
}

/// Levenshtein distance (characters).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtins_are_the_reference_presets() {
        assert_eq!(Fabric::builtin("default").unwrap(), Fabric::default());
        assert_eq!(Fabric::builtin("mid_bending").unwrap().bend_ke, 100.0);
        assert_eq!(Fabric::builtin("minimal_bending").unwrap().bend_ke, 500.0);
        let e = Fabric::builtin("mid_bendin").unwrap_err().to_string();
        assert!(e.contains("did you mean `mid_bending`"), "{e}");
    }

    #[test]
    fn a_file_overrides_its_base() {
        let f =
            Fabric::from_yaml("fabric:\n  base: mid_bending\n  fabric_friction: 0.3\n  spring_ke: 1e5 # stiffer\n", "silk.yaml").unwrap();
        assert_eq!((f.name.as_str(), f.bend_ke, f.friction, f.spring_ke), ("silk", 100.0, 0.3, 1e5));
        let s = f.apply(Settings::default());
        assert_eq!((s.bend_ke, s.fabric_friction, s.spring_ke), (100.0, 0.3, 1e5));
    }

    #[test]
    fn bad_files_name_the_file_key_and_range() {
        let e = Fabric::from_yaml("fabric:\n  spring_ke: -5\n  fabric_frictoin: 0.3\n  fabric_density: .nan\n", "bad.yaml").unwrap_err();
        let text = e.to_string();
        assert!(text.starts_with("bad.yaml: "), "{text}");
        assert!(
            text.contains(
                "line 2: fabric.spring_ke = -5: the stretch stiffness of the fabric's edges must be a number from 10 to 10000000"
            ),
            "{text}"
        );
        assert!(text.contains("line 3: fabric.fabric_frictoin: unknown fabric parameter (did you mean `fabric_friction`?)"), "{text}");
        assert!(text.contains("line 4: fabric.fabric_density = .nan"), "{text}");
        assert!(Fabric::from_yaml("spring_ke: 5\n", "flat.yaml").unwrap_err().to_string().contains("top-level `fabric:`"));
    }
}
