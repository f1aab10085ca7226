//! A design-parameter struct written with the derives: its schema, a random sample,
//! and a round trip through the reference's design-file format.
//!
//! `cargo run --example params_demo`

use garmentcode::io::{read_design, write_design};
use garmentcode::{Choice, Params, Sampler, sample_rng};

/// How the hem is finished.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Choice)]
pub enum Hem {
    /// Plain hem.
    Plain,
    /// Scalloped hem.
    Scalloped,
    /// Rolled hem.
    #[param(rename = "rolled-hem")]
    Rolled,
}

/// A simple skirt.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct SkirtDesign {
    /// Length below the hips as a fraction of the leg.
    #[param(range = 0.1..=0.95, default = 0.4)]
    pub length: f64,
    /// Number of gores.
    #[param(range = 4..=12, default = 6, prob = 0.5)]
    pub panels: i64,
    /// Fullness of the hem in suns (full circles).
    #[param(range = 0.1..=1.5, default = 0.5, prob = 0.3)]
    pub suns: f64,
    /// Hem finish (none: raw edge).
    #[param(default = Plain, prob = 0.4)]
    pub hem: Option<Hem>,
    /// Add pockets.
    #[param(default = false, prob = 0.8)]
    pub pockets: bool,
}

/// The whole design: groups nest, keys can be renamed.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Design {
    /// The skirt.
    #[param(rename = "flare-skirt")]
    pub skirt: SkirtDesign,
}

fn main() {
    let space = Design::design_space();
    println!("# Schema");
    for p in space.params() {
        let prob = p.default_prob.map(|x| format!(", keeps its default with p = {x}")).unwrap_or_default();
        println!("{:<20} {:<11} {:<42} default {}{prob}  -- {}", p.path, p.kind.as_str(), p.range.to_string(), p.default, p.description);
    }

    println!("\n# A sample (seed 7, index 0)");
    let sample: Design = Sampler::new(space.clone()).sample(&mut sample_rng(7, 0));
    println!("{sample:#?}");

    println!("\n# Design file (reference format)");
    let text = write_design(&sample, &space);
    print!("{text}");
    let back: Design = read_design(&text, "<memory>", &space).expect("a written design reads back");
    assert_eq!(back, sample);
    println!("\nround trip: identical");
}
