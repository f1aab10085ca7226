//! Random garments: the dataset sampler's logic, shared by `garmentcode sample` and
//! the web configurator's "random design".
//!
//! Sample `index` of seed `seed` depends on `(seed, index)` alone: everything about
//! it (each attempt's design, then its body, and the re-draws after rejections) is
//! drawn in order from the one generator [`sample_rng`]`(seed, index)`. So a sample is
//! the same on every machine, in any shard and with any number of threads, and any
//! attempt, accepted or rejected, can be regenerated alone ([`DatasetSampler::attempt`]).
//!
//! Like the reference's dataset sampler, a drawn design is rejected and drawn again
//! (up to [`MAX_ATTEMPTS`] times) when it fails a filter: the parameter-combination
//! filter (empty garment or lone belt, gathered skirt without a band, heavy flared
//! skirt without support), a garment program error, a garment longer than the floor
//! allows, or a self-intersecting panel outline. A design failing several is
//! counted under the first in build order (see [`build_valid_in`]: the torso of a
//! top is checked before its sleeves and collar are built). Unlike the reference,
//! which checks each design on the neutral body and on a random body, a sample here
//! has one body (drawn from the given bodies) and is checked on it.

use crate::Design;
use crate::build::{Built, Refusal, build_valid_in};
use crate::design::{BottomKind, GodetBase, UpperKind};
use crate::meta::check_param_combinations;
use garmentcode::io::DesignError;
use garmentcode::{Arena, Body, DesignSpace, Params, Sampler, below, sample_rng};
use rand_chacha::rand_core::RngCore;
use std::fmt;

/// Attempts per sample before giving up (the reference's limit).
pub const MAX_ATTEMPTS: u32 = 100;

/// The folder (and pattern) name of sample `index`: `rand_` and the index in at
/// least seven digits. GarmentCodeData names samples `rand_` + ten random
/// characters; a number keeps the name deterministic, sortable, and the same for a
/// sample whatever the dataset's size, so a dataset can be extended by a larger `n`.
pub fn sample_name(index: u64) -> String {
    format!("rand_{index:07}")
}

/// Why a drawn design was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Reason {
    /// No upper garment and no bottom (nothing, or a lone waistband).
    EmptyOrSingularBelt,
    /// Gathered two-panel skirt without a fitting waistband (it would slide down).
    Skirt2RufflesBelt,
    /// Long or very flared circle skirt without a supporting waistband.
    FlareSkirtsBelt,
    /// The garment program failed on this design and body.
    BuildError,
    /// The garment is longer than the distance from the neck to the floor.
    TooLong,
    /// A panel outline crosses itself.
    SelfIntersecting,
}

impl Reason {
    /// Every reason, in the order the filters run.
    pub const ALL: [Reason; 6] = [
        Reason::EmptyOrSingularBelt,
        Reason::Skirt2RufflesBelt,
        Reason::FlareSkirtsBelt,
        Reason::BuildError,
        Reason::TooLong,
        Reason::SelfIntersecting,
    ];

    /// Stable key, as written in summaries.
    pub fn key(self) -> &'static str {
        match self {
            Reason::EmptyOrSingularBelt => "empty_or_singular_belt",
            Reason::Skirt2RufflesBelt => "skirt2_ruffles_belt",
            Reason::FlareSkirtsBelt => "flare_skirts_belt",
            Reason::BuildError => "build_error",
            Reason::TooLong => "too_long",
            Reason::SelfIntersecting => "self_intersecting",
        }
    }

    /// The reason with this key.
    pub fn from_key(key: &str) -> Option<Reason> {
        Reason::ALL.into_iter().find(|r| r.key() == key)
    }

    /// The reason of a parameter-combination filter message.
    fn of_combination(message: &str) -> Reason {
        if message.contains("Skirt2") {
            Reason::Skirt2RufflesBelt
        } else if message.contains("Flare") {
            Reason::FlareSkirtsBelt
        } else {
            Reason::EmptyOrSingularBelt
        }
    }
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// One rejected attempt.
#[derive(Clone, Debug, PartialEq)]
pub struct Rejection {
    /// Attempt number (0-based) within the sample.
    pub attempt: u32,
    /// Index of the body it was drawn with.
    pub body: usize,
    /// Why it was rejected.
    pub reason: Reason,
    /// The filter's message.
    pub message: String,
}

/// An accepted sample.
#[derive(Clone, Debug)]
pub struct Sample {
    /// Sample index.
    pub index: u64,
    /// The accepted attempt (0-based); earlier attempts are in `rejections`.
    pub attempt: u32,
    /// Index of the body (in [`DatasetSampler::bodies`]).
    pub body: usize,
    /// The design.
    pub design: Design,
    /// The garment built on the body, named [`sample_name`]`(index)`.
    pub built: Built,
    /// The attempts rejected before this one.
    pub rejections: Vec<Rejection>,
}

/// What became of a sample index.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// A design passed every filter.
    Accepted(Box<Sample>),
    /// Every one of [`MAX_ATTEMPTS`] attempts was rejected.
    Exhausted {
        /// Sample index.
        index: u64,
        /// Every attempt, all rejected.
        rejections: Vec<Rejection>,
    },
}

/// A body with the name samples record for it.
#[derive(Clone, Debug)]
pub struct NamedBody {
    /// Name (a built-in body's name or a body file's stem).
    pub name: String,
    /// Measurements.
    pub body: Body,
}

/// Draws samples of a dataset: a seed, a design space and the bodies to choose from.
#[derive(Clone, Debug)]
pub struct DatasetSampler {
    seed: u64,
    sampler: Sampler,
    bodies: Vec<NamedBody>,
}

impl DatasetSampler {
    /// A sampler over `space` (check it first: see [`DesignSpace::problems`]) and
    /// `bodies` (at least one).
    pub fn new(seed: u64, space: DesignSpace, bodies: Vec<NamedBody>) -> Result<DatasetSampler, DesignError> {
        let problems = space.problems();
        if !problems.is_empty() {
            return Err(DesignError { file: "<design space>".into(), problems });
        }
        if bodies.is_empty() {
            return Err(DesignError { file: "<bodies>".into(), problems: vec!["no bodies to sample from".into()] });
        }
        Ok(DatasetSampler { seed, sampler: Sampler::new(space), bodies })
    }

    /// The default: the built-in design space and the neutral body.
    pub fn with_defaults(seed: u64) -> DatasetSampler {
        let body = crate::builtin::body(crate::builtin::DEFAULT_BODY).expect("the default body is built in");
        let bodies = vec![NamedBody { name: crate::builtin::DEFAULT_BODY.into(), body }];
        DatasetSampler::new(seed, Design::design_space(), bodies).expect("the built-in design space is valid")
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The design space.
    pub fn space(&self) -> &DesignSpace {
        self.sampler.space()
    }

    /// The bodies samples are drawn on.
    pub fn bodies(&self) -> &[NamedBody] {
        &self.bodies
    }

    /// Draw sample `index`.
    pub fn draw(&self, index: u64) -> Outcome {
        self.draw_in(&mut Arena::new(), index)
    }

    /// Draw sample `index`, reusing `arena` (saves allocations in loops).
    pub fn draw_in(&self, arena: &mut Arena, index: u64) -> Outcome {
        let mut rng = sample_rng(self.seed, index);
        let name = sample_name(index);
        let mut rejections = Vec::new();
        for attempt in 0..MAX_ATTEMPTS {
            let (design, body) = self.next_attempt(&mut rng);
            match self.check(arena, &design, body, &name) {
                Ok(built) => {
                    return Outcome::Accepted(Box::new(Sample { index, attempt, body, design, built, rejections }));
                }
                Err((reason, message)) => rejections.push(Rejection { attempt, body, reason, message }),
            }
        }
        Outcome::Exhausted { index, rejections }
    }

    /// The design and body index of one attempt of sample `index` (accepted or
    /// not), without building the earlier ones: for inspecting a rejection.
    pub fn attempt(&self, index: u64, attempt: u32) -> (Design, usize) {
        let mut rng = sample_rng(self.seed, index);
        let mut drawn = self.next_attempt(&mut rng);
        for _ in 0..attempt {
            drawn = self.next_attempt(&mut rng);
        }
        drawn
    }

    /// A random design alone (the first attempt of sample `index`, unfiltered), for
    /// interactive "random design" buttons.
    pub fn random_design(&self, index: u64) -> Design {
        self.attempt(index, 0).0
    }

    /// Build a design on a body and apply the filters: the built garment, or why
    /// it is rejected.
    pub fn check(&self, arena: &mut Arena, design: &Design, body: usize, name: &str) -> Result<Built, (Reason, String)> {
        // The cheap filter first: it needs no geometry.
        if let Err(m) = check_param_combinations(design) {
            return Err((Reason::of_combination(m), m.to_string()));
        }
        build_valid_in(arena, design, &self.bodies[body].body, name).map_err(|r| match r {
            Refusal::Build(e) => (Reason::BuildError, e.to_string()),
            Refusal::TooLong { total_length, floor_length } => {
                (Reason::TooLong, format!("total length {total_length} exceeds the floor length {floor_length}"))
            }
            Refusal::SelfIntersecting => (Reason::SelfIntersecting, "a panel outline crosses itself".into()),
        })
    }

    /// The next attempt on a sample's generator: the design, then the body.
    fn next_attempt(&self, rng: &mut impl RngCore) -> (Design, usize) {
        let design: Design = self.sampler.sample(rng);
        let body = below(rng, self.bodies.len() as u64) as usize;
        (design, body)
    }

    /// The body of a sample as written to its folder: `body_sample` names the body
    /// mesh for simulation as GarmentCodeData does (the body's name, with `_apart`,
    /// the legs-apart pose, for trousers).
    pub fn body_for(&self, body: usize, design: &Design) -> Body {
        let nb = &self.bodies[body];
        let mut b = nb.body.clone();
        let pose = if design.meta.bottom == Some(BottomKind::Pants) { "_apart" } else { "" };
        b.body_sample = Some(format!("{}{pose}", nb.name));
        b
    }
}

/// The garment type of a design, as the reference's dataset statistics
/// (`stats_utils.garment_type`) classify it: a main type and style tags.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GarmentType {
    /// `upper_garment`, `dress`, `jumpsuit`, `skirt` or `pants` (`none` for an
    /// empty design, where the reference fails).
    pub main: &'static str,
    /// `asymmetric_top`, `hoodie`, `sleeveless` / `with_sleeves` with
    /// `short_sleeve` / `long_sleeve`, and `mini` / `knee_len` / `midi` / `maxi`.
    pub styles: Vec<&'static str>,
}

impl GarmentType {
    /// Classify a design.
    pub fn of(d: &Design) -> GarmentType {
        let meta = &d.meta;
        let has_pants = meta.bottom == Some(BottomKind::Pants);
        let main = match (meta.upper, meta.bottom) {
            (Some(_), _) if has_pants => "jumpsuit",
            (Some(_), _) if vertical_len(d) < 1.4 => "upper_garment",
            (Some(_), _) => "dress",
            (None, Some(_)) if has_pants => "pants",
            (None, Some(_)) => "skirt",
            (None, None) => "none",
        };
        let mut styles = Vec::new();
        if meta.upper.is_some() {
            let asym = d.left.enable_asym;
            if asym {
                styles.push("asymmetric_top");
            }
            if !asym && d.collar.component.style == Some(crate::design::CollarStyle::Hood2Panels) {
                styles.push("hoodie");
            }
            if d.sleeve.sleeveless && (!asym || d.left.sleeve.sleeveless) {
                styles.push("sleeveless");
            } else {
                styles.push("with_sleeves");
                styles.push(if sleeve_length(d) < 0.5 { "short_sleeve" } else { "long_sleeve" });
            }
        }
        if meta.bottom.is_some() {
            let l = bottom_length(d);
            styles.push(if l < 0.3 {
                "mini"
            } else if l < 0.5 {
                "knee_len"
            } else if l < 0.65 {
                "midi"
            } else {
                "maxi"
            });
        }
        GarmentType { main, styles }
    }
}

/// The length parameter of the bottom garment's design group (0 without one).
fn bottom_length(d: &Design) -> f64 {
    match d.meta.bottom {
        None => 0.0,
        Some(BottomKind::SkirtCircle | BottomKind::AsymmSkirtCircle | BottomKind::SkirtManyPanels) => d.flare_skirt.length,
        Some(BottomKind::Pants) => d.pants.length,
        Some(BottomKind::Skirt2) => d.skirt.length,
        Some(BottomKind::PencilSkirt) => d.pencil_skirt.length,
        Some(BottomKind::SkirtLevels) => d.levels_skirt.length,
        Some(BottomKind::GodetSkirt) => match d.godet_skirt.base {
            GodetBase::Skirt2 => d.skirt.length,
            GodetBase::PencilSkirt => d.pencil_skirt.length,
        },
    }
}

fn sleeve_length(d: &Design) -> f64 {
    let right = if d.sleeve.sleeveless { 0.0 } else { d.sleeve.length };
    let left = if d.left.enable_asym && !d.left.sleeve.sleeveless { d.left.sleeve.length } else { 0.0 };
    right.max(left)
}

fn vertical_len(d: &Design) -> f64 {
    let top = match d.meta.upper {
        Some(UpperKind::FittedShirt) => 1.0,
        Some(UpperKind::Shirt) => d.shirt.length,
        None => 0.0,
    };
    let wb = if d.meta.wb.is_some() { d.waistband.width } else { 0.0 };
    top + wb + bottom_length(d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_depend_on_seed_and_index_alone() {
        let s = DatasetSampler::with_defaults(11);
        let a = s.random_design(5);
        let _ = s.random_design(4);
        assert_eq!(a, DatasetSampler::with_defaults(11).random_design(5));
        assert_ne!(a, s.random_design(6));
    }

    #[test]
    fn accepted_samples_pass_every_filter_and_replay() {
        let s = DatasetSampler::with_defaults(3);
        let mut arena = Arena::new();
        for i in 0..6 {
            match s.draw_in(&mut arena, i) {
                Outcome::Accepted(sample) => {
                    assert!(sample.built.checks.passed());
                    assert_eq!(sample.rejections.len() as u32, sample.attempt);
                    assert_eq!(s.attempt(i, sample.attempt).0, sample.design);
                    for r in &sample.rejections {
                        let (design, body) = s.attempt(i, r.attempt);
                        let got = s.check(&mut arena, &design, body, "replay").err().map(|e| e.0);
                        assert_eq!(got, Some(r.reason), "sample {i} attempt {}", r.attempt);
                    }
                }
                Outcome::Exhausted { index, .. } => panic!("sample {index} exhausted"),
            }
        }
    }

    /// The filters stop early (a torso is checked before its sleeves and collar are
    /// built), yet accept exactly the designs that pass every check of a full build.
    #[test]
    fn early_torso_check_accepts_what_full_builds_accept() {
        let s = DatasetSampler::with_defaults(5);
        let mut arena = Arena::new();
        let (mut compared, mut sleeved_torso_refused) = (0, 0);
        for i in 0..40 {
            for attempt in 0..3 {
                let (design, body) = s.attempt(i, attempt);
                if check_param_combinations(&design).is_err() {
                    continue;
                }
                let early = s.check(&mut arena, &design, body, "early");
                let panels_made = arena.panel_count();
                let full = crate::build::build_in(&mut arena, &design, &s.bodies[body].body, "full");
                let full_ok = matches!(&full, Ok(b) if b.checks.passed());
                assert_eq!(early.is_ok(), full_ok, "sample {i} attempt {attempt}: {:?}", early.err());
                // A refusal for self-intersection may pre-empt a later build error.
                if let (Err((Reason::SelfIntersecting, _)), Ok(built)) = (&early, &full) {
                    let torso_crosses = built.pattern.panels.iter().any(|p| {
                        p.name.contains("torso") && garmentcode::intersect::has_self_intersection(&garmentcode::intersect::spec_segments(p))
                    });
                    let sleeves = built.pattern.panels.iter().any(|p| p.name.contains("sleeve"));
                    // Stopped before the sleeves: fewer panels made than a full build has.
                    if torso_crosses && sleeves && panels_made < built.pattern.panels.len() {
                        sleeved_torso_refused += 1;
                    }
                }
                compared += 1;
            }
        }
        assert!(compared > 60 && sleeved_torso_refused > 3, "{compared} designs compared, {sleeved_torso_refused} sleeved torsos refused");
    }

    /// The geometry's memo tables are kept from garment to garment on a thread: a
    /// sample is the same whatever the thread built before it.
    #[test]
    fn samples_do_not_depend_on_what_the_thread_built_before() {
        let patterns = |order: Vec<u64>| -> Vec<(u64, String)> {
            std::thread::spawn(move || {
                let s = DatasetSampler::with_defaults(7);
                let mut arena = Arena::new();
                let drawn = order.into_iter().map(|i| (i, s.draw_in(&mut arena, i)));
                drawn
                    .filter_map(|(i, o)| if let Outcome::Accepted(x) = o { Some((i, x.built.pattern.to_json().ok()?)) } else { None })
                    .collect()
            })
            .join()
            .expect("the thread draws")
        };
        let forward = patterns((0..24).collect());
        let mut backward = patterns((0..24).rev().collect());
        backward.reverse();
        assert_eq!(forward.len(), 24);
        assert!(forward == backward, "the order of drawing changed a sample");
        for (i, json) in forward.iter().step_by(6) {
            assert!(patterns(vec![*i])[0].1 == *json, "sample {i} drawn alone differs");
        }
    }

    #[test]
    fn garment_types_follow_the_reference_stats() {
        let mut d = Design::defaults();
        assert_eq!(GarmentType::of(&d).main, "none");
        d.meta.upper = Some(UpperKind::Shirt);
        d.shirt.length = 1.2;
        assert_eq!(GarmentType::of(&d), GarmentType { main: "upper_garment", styles: vec!["sleeveless"] });
        d.meta.bottom = Some(BottomKind::Pants);
        d.pants.length = 0.7;
        assert_eq!(GarmentType::of(&d).main, "jumpsuit");
        d.meta.upper = None;
        assert_eq!(GarmentType::of(&d), GarmentType { main: "pants", styles: vec!["maxi"] });
    }
}
