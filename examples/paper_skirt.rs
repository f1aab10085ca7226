//! The skirt of the GarmentCode paper's code figure, written with the macros: a thin
//! trapezoid panel class, and a skirt of many such panels distributed on a circle
//! around the body, sized by the waist and hips, flared by a number of "suns", its
//! panels' top edges exposed as the skirt's `top` interface.
//!
//! ```text
//! cargo run --example paper_skirt -- [--design FILE.yaml] [--body FILE.yaml] [--out DIR]
//! ```
//!
//! Defaults: `examples/data/paper_skirt.yaml`, the neutral body
//! `garments/data/bodies/mean_all.yaml`, `out/paper_skirt`. Writes
//! `DIR/specification.json`, `DIR/pattern.svg` and `DIR/design_params.yaml` (the
//! design in the reference's format, every parameter with its range).
//!
//! # The figure and this file, step by step
//!
//! The paper writes the skirt in Python with pygarment (left, paraphrased); this
//! file writes the same program in Rust (right). Interfaces are typed fields, not
//! dictionary keys, so a misspelt interface is a compile error, and a copy made by
//! an operator is the same panel class with its own interfaces.
//!
//! | step | pygarment (the paper's figure) | garmentcode (this file) |
//! | --- | --- | --- |
//! | a panel class | `class ThinSkirtPanel(pyg.Panel)` | `#[component] struct ThinSkirtPanel { #[panel] panel, .. }` |
//! | its outline | `self.edges = EdgeSeqFactory.from_verts(..., loop=True)` | `EdgeSeq::from_points(a, &corners, true)` |
//! | its interfaces | `self.interfaces = {'right': Interface(self, self.edges[0]), ...}` | `#[interface] right` ... `right: a.interface(panel, edges[0])` |
//! | a component | `class FlareSkirt(pyg.Component)` | `#[component] struct FlareSkirt { #[part] panels, .. }` |
//! | placement | `base.translate_by(...)`, `base.rotate_by(...)` | `base.translate_to(a, ..)`, `base.rotate_by(a, ..)` |
//! | copies around the body | `self.subs = pyg.ops.distribute_Y(base, n)` | `let panels = distribute_y(a, base, n, "skirt")` (a `Vec<ThinSkirtPanel>`) |
//! | seams | `stitching_rules.append((subs[i].interfaces['left'], subs[i+1].interfaces['right']))` | `StitchRule::new(a, panels[i].left, panels[(i + 1) % n].right)?` |
//! | the waist | `self.interfaces = {'top': Interface.from_multiple(*[s.interfaces['top'] ...])}` | `#[interface] top` = `a.interface_from(&tops)` |
//! | the pattern | `skirt.assembly()` | `skirt.assemble(&mut a, "paper_skirt")?` |
//!
//! A function that needs "something with a waist" asks for `B: Slot<Top>`
//! (`waistline` below): plugging in a component without a `top` interface does
//! not compile.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use garmentcode::draw::{DrawOptions, to_svg};
use garmentcode::io::{read_design, write_design};
use garmentcode::ops::distribute_y;
use garmentcode::slots::Top;
use garmentcode::{
    Arena, Body, EdgeSeq, InterfaceId, PanelId, Params, PartExt, Rotation, Slot, SlotExt, StitchRule, Vec2, Vec3, component,
};

/// Design parameters of the skirt (the `skirt:` group of a design file).
#[derive(Clone, Debug, PartialEq, Params)]
pub struct SkirtDesign {
    /// Length below the hip line, as a fraction of the leg.
    #[param(range = 0.1..=0.95, default = 0.45)]
    pub length: f64,
    /// Fullness of the hem in full circles ("suns"): 1 is a full circle skirt.
    #[param(range = 0.05..=1.5, default = 0.3)]
    pub suns: f64,
    /// Number of panels.
    #[param(range = 3..=12, default = 6, prob = 0.4)]
    pub n_panels: i64,
}

/// A whole design file.
#[derive(Clone, Debug, PartialEq, Params)]
pub struct Design {
    /// The skirt.
    pub skirt: SkirtDesign,
}

/// A trapezoid panel `top_width` wide at the top and `bottom_width` at the hem.
#[component]
pub struct ThinSkirtPanel {
    #[panel]
    pub panel: PanelId,
    #[interface]
    pub right: InterfaceId,
    #[interface]
    pub top: InterfaceId,
    #[interface]
    pub left: InterfaceId,
}

impl ThinSkirtPanel {
    pub fn new(a: &mut Arena, name: &str, top_width: f64, bottom_width: f64, length: f64) -> garmentcode::Result<Self> {
        let flare = (bottom_width - top_width) / 2.0;
        let corners =
            [Vec2::new(0.0, 0.0), Vec2::new(flare, length), Vec2::new(flare + top_width, length), Vec2::new(2.0 * flare + top_width, 0.0)];
        let edges = EdgeSeq::from_points(a, &corners, true)?;
        let panel = a.panel_with_edges(name, edges.clone());
        panel.top_center_pivot(a);
        Ok(ThinSkirtPanel {
            panel,
            right: a.interface(panel, edges[0]),
            top: a.interface(panel, edges[1]),
            left: a.interface(panel, edges[2]),
        })
    }
}

/// The skirt: `n_panels` gores around the body, each sewn to the next.
#[component(name = "flare_skirt")]
pub struct FlareSkirt {
    #[part]
    pub panels: Vec<ThinSkirtPanel>,
    /// The waistline, every panel's top edge in order around the body.
    #[interface]
    pub top: InterfaceId,
    #[stitches]
    pub seams: Vec<StitchRule>,
}

impl FlareSkirt {
    pub fn new(a: &mut Arena, body: &Body, design: &SkirtDesign) -> garmentcode::Result<Self> {
        let n = design.n_panels as usize;
        let length = body.hips_line + design.length * body.derived().leg_length;
        // Each panel spans 1/n of the waist at the top; at the hem, 1/n of the waist
        // plus the flare of `suns` circles of radius `length`, and never less than
        // what reaches around the hips at the hip line.
        let top_width = body.waist / n as f64;
        let hem_for_suns = (body.waist + design.suns * 2.0 * PI * length) / n as f64;
        let hem_for_hips = top_width + (body.hips - body.waist) / n as f64 * length / body.hips_line;
        let bottom_width = hem_for_suns.max(hem_for_hips);

        let base = ThinSkirtPanel::new(a, "skirt", top_width, bottom_width, length)?;
        // Face the first panel outwards on the wearer's right, far enough from the
        // body axis that the n panels' top edges close into a regular polygon.
        let radius = top_width / (2.0 * (PI / n as f64).tan());
        base.translate_to(a, Vec3::new(-radius, body.derived().waist_level, 0.0));
        base.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, -90.0, 0.0]));
        // n panels around the body: each copy is a ThinSkirtPanel with its own interfaces.
        let panels = distribute_y(a, base, n, "skirt");

        let mut seams = Vec::with_capacity(n);
        for i in 0..n {
            seams.push(StitchRule::new(a, panels[i].left, panels[(i + 1) % n].right)?);
        }
        let tops: Vec<InterfaceId> = panels.iter().map(|p| p.top).collect();
        let top = a.interface_from(&tops);
        Ok(FlareSkirt { panels, top, seams })
    }
}

/// Something that can hang from a waistband: requires the `top` slot at compile
/// time (remove `#[interface] top` from `FlareSkirt` and this stops compiling).
fn waistline<B: Slot<Top>>(bottom: &B, a: &Arena) -> f64 {
    bottom.iface::<Top>().length(a)
}

fn arg(args: &[String], name: &str) -> Option<String> {
    args.iter().position(|a| a == name).and_then(|i| args.get(i + 1).cloned())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let design_file = arg(&args, "--design").map(PathBuf::from).unwrap_or_else(|| root.join("examples/data/paper_skirt.yaml"));
    let body_file = arg(&args, "--body").map(PathBuf::from).unwrap_or_else(|| root.join("garments/data/bodies/mean_all.yaml"));
    let out = arg(&args, "--out").map(PathBuf::from).unwrap_or_else(|| PathBuf::from("out/paper_skirt"));

    let space = Design::design_space();
    let design: Design = read_design(&std::fs::read_to_string(&design_file)?, &design_file.display().to_string(), &space)?;
    let body = Body::from_yaml(&std::fs::read_to_string(&body_file)?, &body_file.display().to_string())?;

    let mut a = Arena::new();
    let skirt = FlareSkirt::new(&mut a, &body, &design.skirt)?;
    println!("{} panels, waistline {:.1} cm (body waist {:.1} cm)", skirt.panels.len(), waistline(&skirt, &a), body.waist);
    let pattern = skirt.assemble(&mut a, "paper_skirt")?;

    std::fs::create_dir_all(&out)?;
    std::fs::write(out.join("specification.json"), pattern.to_json()?)?;
    std::fs::write(out.join("pattern.svg"), to_svg(&pattern, &DrawOptions::default())?)?;
    std::fs::write(out.join("design_params.yaml"), write_design(&design, &space))?;
    println!("wrote {}", out.display());
    Ok(())
}
