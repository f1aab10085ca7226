//! A gored skirt written with the runtime crate alone (no macros, no garment
//! library): one trapezoid gore with a waist dart projected into its top edge,
//! copied around the body, neighbouring gores stitched side to side, and the
//! waist exposed as one interface made of every gore's top.
//!
//! `cargo run --example skirt_runtime [-- OUT_DIR]` writes
//! `OUT_DIR/specification.json` and `OUT_DIR/pattern.svg` (default
//! `out/skirt_runtime`).

use std::f64::consts::PI;

use garmentcode::draw::{DrawOptions, to_svg};
use garmentcode::ops::{Cut, DartSize, EdgeSide, dart_shape};
use garmentcode::{
    Arena, Component, EdgeSeq, IdMap, InterfaceId, Node, PanelId, PanelPart, Part, PartExt, Remap, Rotation, StitchRule, Vec2, Vec3,
};

/// Body measurements the skirt is fitted to (cm).
pub const WAIST: f64 = 78.0;
/// Height of the waist line above the floor (cm).
pub const WAIST_LEVEL: f64 = 104.0;

/// Skirt design.
pub const GORES: usize = 6;
const LENGTH: f64 = 60.0;
/// Hem circumference as a multiple of the waist.
const FLARE: f64 = 2.2;
const DART_WIDTH: f64 = 2.0;
const DART_DEPTH: f64 = 9.0;

/// One gore: its panel and the interfaces it is sewn by. Without the macros a
/// panel class implements [`Part`] (what it is), [`PanelPart`] (its panel) and
/// [`Remap`] (how a copy of it is rebuilt over the copied ids) by hand;
/// `#[derive(Component)]` writes these three impls.
pub struct Gore {
    pub panel: PanelId,
    pub right: InterfaceId,
    pub top: InterfaceId,
    pub left: InterfaceId,
    pub bottom: InterfaceId,
}

impl Part for Gore {
    fn node(&self) -> Node<'_> {
        Node::Panel(self.panel)
    }
}

impl PanelPart for Gore {
    fn panel_id(&self) -> PanelId {
        self.panel
    }
}

impl Remap for Gore {
    fn remap(&self, a: &mut Arena, map: &mut IdMap) -> Self {
        Gore {
            panel: self.panel.remap(a, map),
            right: self.right.remap(a, map),
            top: self.top.remap(a, map),
            left: self.left.remap(a, map),
            bottom: self.bottom.remap(a, map),
        }
    }
}

/// The assembled skirt: its gores, the seams between them, and the waist.
pub struct Skirt {
    pub gores: Vec<Gore>,
    pub seams: Vec<StitchRule>,
    pub waist: InterfaceId,
}

impl Part for Skirt {
    fn node(&self) -> Node<'_> {
        Node::Component(self)
    }
}

impl Component for Skirt {
    fn name(&self) -> String {
        "gored_skirt".into()
    }

    fn for_each_part(&self, f: &mut dyn FnMut(&dyn Part)) {
        for gore in &self.gores {
            f(gore)
        }
    }

    fn stitches(&self) -> Vec<StitchRule> {
        self.seams.clone()
    }

    /// The skirt is as long as one gore (they sit side by side, not stacked).
    fn length(&self, a: &Arena) -> f64 {
        self.gores[0].panel.length(a)
    }
}

/// One gore: a trapezoid `top_width` wide at the waist (plus the dart's intake) and
/// `hem_width` wide at the hem, with a dart in the middle of its top edge (its top
/// interface is the top edge without the dart).
fn gore(a: &mut Arena, top_width: f64, hem_width: f64) -> garmentcode::Result<Gore> {
    let top = top_width + DART_WIDTH;
    let flare = (hem_width - top) / 2.0;
    let corners = [Vec2::new(0.0, 0.0), Vec2::new(flare, LENGTH), Vec2::new(flare + top, LENGTH), Vec2::new(2.0 * flare + top, 0.0)];
    let mut outline = EdgeSeq::from_points(a, &corners, true)?;
    let (right_side, top_edge, left_side, hem) = (outline[0], outline[1], outline[2], outline[3]);

    // Project the dart into the top edge, pointing down into the panel (to the
    // right of the edge's left-to-right direction); its legs get stitched together.
    let panel = a.panel_with_edges("gore", outline.clone());
    let dart = dart_shape(a, DART_WIDTH, DartSize::Depth(DART_DEPTH))?;
    let offset = a.edge_length(top_edge) / 2.0;
    let Cut { edges: with_dart, leftovers: top_pieces, .. } = panel.add_dart(a, &dart, top_edge, offset, EdgeSide::Right)?;
    outline.substitute(top_edge, with_dart.as_slice())?;
    panel.set_edges(a, outline);

    // Rotation and placement pivot: the middle of the top edge.
    panel.set_pivot(a, Vec2::new(flare + top / 2.0, LENGTH), false);
    Ok(Gore {
        panel,
        right: a.interface(panel, right_side),
        top: a.interface(panel, top_pieces),
        left: a.interface(panel, left_side),
        bottom: a.interface(panel, hem),
    })
}

pub fn build(a: &mut Arena) -> garmentcode::Result<Skirt> {
    let first = gore(a, WAIST / GORES as f64, FLARE * WAIST / GORES as f64)?;

    // Put the first gore on the wearer's right, facing outwards at the distance
    // where the n gores' waistlines close into a regular polygon, then copy it
    // around the vertical axis.
    let waist_piece = WAIST / GORES as f64 + DART_WIDTH;
    let radius = waist_piece / (2.0 * (PI / GORES as f64).tan());
    first.panel.translate_to(a, Vec3::new(-radius, WAIST_LEVEL, 0.0));
    first.panel.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, -90.0, 0.0]));
    // Each copy is a `Gore` with its own panel and interfaces.
    let gores = garmentcode::ops::distribute_y(a, first, GORES, "gore");

    // Sew each gore's left side to the next gore's right side, closing the circle.
    let mut seams = Vec::with_capacity(GORES);
    for i in 0..GORES {
        let next = &gores[(i + 1) % GORES];
        seams.push(StitchRule::new(a, gores[i].left, next.right)?);
    }
    let tops: Vec<InterfaceId> = gores.iter().map(|g| g.top).collect();
    let waist = a.interface_from(&tops);
    Ok(Skirt { gores, seams, waist })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out/skirt_runtime".into()));
    let mut a = Arena::new();
    let skirt = build(&mut a)?;
    println!("waist interface: {:.2} cm over {} edges (body waist {WAIST} cm)", skirt.waist.length(&a), skirt.waist.len(&a));
    let pattern = skirt.assemble(&mut a, "gored_skirt")?;
    std::fs::create_dir_all(&out)?;
    std::fs::write(out.join("specification.json"), pattern.to_json()?)?;
    std::fs::write(out.join("pattern.svg"), to_svg(&pattern, &DrawOptions::default())?)?;
    println!("{} panels, {} stitches written to {}", pattern.panels.len(), pattern.stitches.len(), out.display());
    Ok(())
}
