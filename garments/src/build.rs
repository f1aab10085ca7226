//! From a design and a body to a sewing pattern and the reference's validity checks:
//! the one pipeline shared by the command-line tool, the dataset sampler and the web
//! configurator.

use crate::Design;
use crate::meta::{MetaGarment, check_param_combinations};
use garmentcode::{Arena, Body, Component, PartExt, Pattern};
use std::fmt;

/// Why a design cannot be built.
#[derive(Clone, Debug, PartialEq)]
pub enum BuildError {
    /// No upper garment, waistband or bottom: nothing to sew (the reference refuses
    /// to save an empty pattern).
    Empty,
    /// The garment program failed (a neckline wider than its shoulder edge, a dart
    /// that cannot form a triangle, ...).
    Geometry(garmentcode::Error),
}

impl fmt::Display for BuildError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BuildError::Empty => f.write_str(
                "empty garment: the design has no upper garment, waistband or bottom (meta.upper, meta.wb and meta.bottom are null, \
                 as at the design space's defaults; start from a preset instead: `garmentcode schema --design t-shirt`)",
            ),
            BuildError::Geometry(e) => write!(f, "the design cannot be built: {e}"),
        }
    }
}

impl std::error::Error for BuildError {}

impl From<garmentcode::Error> for BuildError {
    fn from(e: garmentcode::Error) -> Self {
        BuildError::Geometry(e)
    }
}

/// The reference's validity checks of a built garment (the design filters of its
/// dataset sampler), with the keys of the reference cases' `checks.json`.
#[derive(Clone, Debug, PartialEq)]
pub struct Checks {
    /// `Ok` or the filter's message (empty garment or lone belt, gathered skirt
    /// without a band, heavy flared skirt without support).
    pub param_combinations: Result<(), &'static str>,
    /// Sum of the parts' lengths, cm.
    pub total_length: f64,
    /// Floor distance from the neck base (`height − head_l`), cm.
    pub floor_length: f64,
    /// `total_length ≤ floor_length + 1`.
    pub total_length_ok: bool,
    /// Some panel outline crosses itself.
    pub self_intersecting: bool,
}

impl Checks {
    /// Every check passed.
    pub fn passed(&self) -> bool {
        self.param_combinations.is_ok() && self.total_length_ok && !self.self_intersecting
    }

    /// Failed checks as readable warnings.
    pub fn warnings(&self) -> Vec<String> {
        let mut out = Vec::new();
        if let Err(m) = self.param_combinations {
            out.push(format!("design filter: {m}"));
        }
        if !self.total_length_ok {
            out.push(format!(
                "too long: the garment is {:.1} cm long but the floor is {:.1} cm below the neck",
                self.total_length, self.floor_length
            ));
        }
        if self.self_intersecting {
            out.push("self-intersection: a panel outline crosses itself".into());
        }
        out
    }

    /// `checks.json`.
    pub fn to_json(&self) -> String {
        let pc = match self.param_combinations {
            Ok(()) => "ok".to_string(),
            Err(m) => format!("IncorrectElementConfiguration: {m}"),
        };
        let v = serde_json::json!({
            "param_combinations": pc,
            "total_length": self.total_length,
            "floor_length": self.floor_length,
            "total_length_ok": self.total_length_ok,
            "self_intersecting": self.self_intersecting,
        });
        serde_json::to_string_pretty(&v).expect("checks serialise") + "\n"
    }
}

/// A built garment.
#[derive(Clone, Debug)]
pub struct Built {
    /// The sewing pattern.
    pub pattern: Pattern,
    /// The validity checks.
    pub checks: Checks,
}

/// Build `design` on `body` into the pattern named `name`, reusing `arena`.
pub fn build_in(arena: &mut Arena, design: &Design, body: &Body, name: &str) -> Result<Built, BuildError> {
    arena.stop_at_self_intersection(false);
    let garment = new_garment(arena, design, body);
    degenerate(arena)?;
    let garment = garment?;
    let (total_length, floor_length) = lengths(arena, &garment, body);
    let self_intersecting = garment.is_self_intersecting(arena);
    degenerate(arena)?;
    let pattern = garment.assemble(arena, name);
    degenerate(arena)?;
    let pattern = readable(pattern?)?;
    let param_combinations = check_param_combinations(design);
    let checks =
        Checks { param_combinations, total_length, floor_length, total_length_ok: total_length <= floor_length + 1.0, self_intersecting };
    Ok(Built { pattern, checks })
}

/// Why [`build_valid_in`] turned a design down.
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// The design cannot be built.
    Build(BuildError),
    /// The garment is longer than the floor allows (`total_length > floor_length + 1`).
    TooLong {
        /// Sum of the parts' lengths, cm.
        total_length: f64,
        /// Height minus head length, cm.
        floor_length: f64,
    },
    /// A panel outline crosses itself.
    SelfIntersecting,
}

/// As [`build_in`] for a design that must pass the geometric checks (length, then
/// self-intersection): stops at the first that fails, without the work the rest
/// would take (the dataset sampler turns down about half of what it draws).
/// The parameter-combination filter is the caller's: it needs no building.
///
/// The garments accepted are those [`build_in`] finds valid, but a design failing
/// several checks is refused for the first in build order: the torso outlines of a
/// top are checked as soon as its armholes and neckline are cut, before the sleeves,
/// the collar and the rest of the garment are built (with
/// [`Arena::stop_at_self_intersection`]). The seams sewn later (sleeve, collar,
/// shoulders, sides, waist) only split torso edges, which keeps their points, so a
/// torso crossing itself then still does at the end.
pub fn build_valid_in(arena: &mut Arena, design: &Design, body: &Body, name: &str) -> Result<Built, Refusal> {
    arena.stop_at_self_intersection(true);
    let garment = new_garment(arena, design, body);
    degenerate(arena).map_err(Refusal::Build)?;
    let garment = garment.map_err(|e| match e {
        BuildError::Geometry(garmentcode::Error::SelfIntersecting { .. }) => Refusal::SelfIntersecting,
        e => Refusal::Build(e),
    })?;
    let (total_length, floor_length) = lengths(arena, &garment, body);
    degenerate(arena).map_err(Refusal::Build)?;
    if total_length > floor_length + 1.0 {
        return Err(Refusal::TooLong { total_length, floor_length });
    }
    let self_intersecting = garment.is_self_intersecting(arena);
    degenerate(arena).map_err(Refusal::Build)?;
    if self_intersecting {
        return Err(Refusal::SelfIntersecting);
    }
    let pattern = garment.assemble(arena, name);
    degenerate(arena).map_err(Refusal::Build)?;
    let pattern = pattern.map_err(BuildError::from).and_then(readable).map_err(Refusal::Build)?;
    let param_combinations = check_param_combinations(design);
    let checks = Checks { param_combinations, total_length, floor_length, total_length_ok: true, self_intersecting: false };
    Ok(Built { pattern, checks })
}

/// The pattern, if it would read back: its numbers finite and within the limits
/// of a specification file ([`Pattern::check_limits`]), so that what `build`
/// writes, `check`, `render`, `mesh` and `print` read (an arc of a radius beyond
/// 100 m is written as the straight edge it is). A garment program can
/// compute NaN, or a control point far off a tiny edge, on extreme designs (seen
/// once in 100,000 random ones); such a pattern is refused (the dataset sampler
/// draws again).
fn readable(mut pattern: Pattern) -> Result<Pattern, BuildError> {
    let fail = |what: String| BuildError::Geometry(garmentcode::Error::Geometry(what));
    pattern.straighten_flat_arcs();
    if let Some(place) = pattern.non_finite() {
        return Err(fail(format!("the pattern has a number that is not finite at {place}")));
    }
    pattern.check_limits().map_err(|e| fail(format!("the pattern would be out of a specification's limits: {e}")))?;
    Ok(pattern)
}

/// Fail as the reference does when a linearisation so far made a piece whose ends
/// coincide (see [`Arena::take_degenerate_linearization`]).
fn degenerate(arena: &mut Arena) -> Result<(), BuildError> {
    arena.take_degenerate_linearization().map_or(Ok(()), |e| Err(e.into()))
}

/// The garment program run on a cleared arena; an empty garment is an error.
fn new_garment(arena: &mut Arena, design: &Design, body: &Body) -> Result<MetaGarment, BuildError> {
    arena.clear();
    let garment = MetaGarment::new(arena, body, design)?;
    if garment.panel_ids().is_empty() {
        return Err(BuildError::Empty);
    }
    Ok(garment)
}

/// The garment's total length and the floor length it must not exceed (by more
/// than 1 cm).
fn lengths(arena: &Arena, garment: &MetaGarment, body: &Body) -> (f64, f64) {
    (Component::length(garment, arena), body.height - body.head_l)
}

/// Build `design` on `body` into the pattern named `name`.
pub fn build(design: &Design, body: &Body, name: &str) -> Result<Built, BuildError> {
    build_in(&mut Arena::new(), design, body, name)
}
