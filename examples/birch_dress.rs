//! The GarmentCode paper's real-garment example, a fitted dress, written with the
//! constructs the paper lists as out of its language's reach: each of its two panels
//! is fitted at the waist by two diamond darts (closed loops inside the panel, their
//! sides stitched together) instead of extra seams.
//!
//! ```text
//! cargo run --example birch_dress -- [--body FILE.yaml] [--out DIR]
//! ```
//!
//! Defaults: the neutral body `garments/data/bodies/mean_all.yaml`, `out/birch_dress`.
//! Writes `DIR/specification.json` and `DIR/pattern.svg`.
//!
//! # Step by step
//!
//! | step | the code |
//! | --- | --- |
//! | a panel class | `#[component] struct DressPanel { #[panel] panel, #[interface] side_a, .. }` |
//! | its outline | `EdgeSeq::from_points(a, &outline, true)`: hem, hips, waist, armholes, shoulders, neck |
//! | diamond darts | `diamond_dart(a, &panel, "dart_a", centre, width, length)`: a hole whose sides are sewn |
//! | a component | `#[component] struct SheathDress { #[part] front, #[part] back, .. }` |
//! | placement | `back.rotate_by(a, ..)`, `translate_to(a, ..)`: the back faces the other way |
//! | seams | `StitchRule::new(a, front.side_a, back.side_b)?`: sides and shoulders |
//! | the pattern | `dress.assemble(&mut a, "birch_dress")?`: the darts' stitches are `inner_stitches` |
//!
//! `diamond_dart` takes a panel (a `PanelPart`): a dart on an edge sequence or on a
//! whole component does not compile.

use std::path::{Path, PathBuf};

use garmentcode::draw::{DrawOptions, to_svg};
use garmentcode::inner::diamond_dart;
use garmentcode::{Arena, Body, EdgeSeq, InterfaceId, PanelId, PartExt, Rotation, StitchRule, Vec2, Vec3, component};

/// Ease around the body, cm.
pub const EASE: f64 = 6.0;
/// Length of the dress below the hip line, as a fraction of the leg.
pub const SKIRT: f64 = 0.35;

/// One half of the dress around the body (front or back): from the hem up to the
/// shoulders, as wide at the waist as at the bust, with two diamond darts that take
/// the waist in.
#[component]
pub struct DressPanel {
    #[panel]
    pub panel: PanelId,
    /// Side seam at x = 0 (hem to armhole).
    #[interface]
    pub side_a: InterfaceId,
    /// Shoulder on the side_a side.
    #[interface]
    pub shoulder_a: InterfaceId,
    /// Shoulder on the other side.
    #[interface]
    pub shoulder_b: InterfaceId,
    /// Side seam on the other side (hem to armhole).
    #[interface]
    pub side_b: InterfaceId,
}

impl DressPanel {
    pub fn new(a: &mut Arena, name: &str, body: &Body) -> garmentcode::Result<Self> {
        let d = body.derived();
        // Heights above the hem.
        let hip = SKIRT * d.leg_length;
        let waist = hip + body.hips_line;
        let top = waist + body.waist_line;
        let armpit = top - d.bust_line - 2.0;
        // Half of the girth (with ease) at the bust, waist and hips.
        let w_bust = (body.bust + EASE) / 2.0;
        let w_hips = ((body.hips + EASE) / 2.0).max(w_bust);
        let (x_hem, x_hip, x_bust) = (0.0, (w_hips - w_bust) / 2.0, (w_hips - w_bust) / 2.0);
        let (shoulder, neck) = (body.shoulder_w / 2.0, body.neck_w / 2.0);
        let mid = w_hips / 2.0;
        let outline = [
            Vec2::new(x_hem, 0.0),
            Vec2::new(x_hip, hip),
            Vec2::new(x_bust, armpit),
            Vec2::new(mid - shoulder, top),
            Vec2::new(mid - neck, top),
            Vec2::new(mid + neck, top),
            Vec2::new(mid + shoulder, top),
            Vec2::new(w_hips - x_bust, armpit),
            Vec2::new(w_hips - x_hip, hip),
            Vec2::new(w_hips - x_hem, 0.0),
        ];
        let edges = EdgeSeq::from_points(a, &outline, true)?;
        let panel = a.panel_with_edges(name, edges.clone());
        // Two diamond darts, at a quarter of the width from each side, widest at the
        // waist: together they take in what the waist lacks of the bust.
        let intake = (w_bust - (body.waist + EASE) / 2.0).max(1.0);
        let length = 0.7 * (armpit - hip);
        for (k, x) in [0.33, 0.67].into_iter().enumerate() {
            diamond_dart(a, &panel, &format!("dart_{k}"), Vec2::new(x * w_hips, waist), intake / 2.0, length)?;
        }
        Ok(DressPanel {
            panel,
            side_a: a.interface(panel, edges.slice(0, 2)),
            shoulder_a: a.interface(panel, edges[3]),
            shoulder_b: a.interface(panel, edges[5]),
            // From the hem up, as `side_a`: a seam pairs the hem pieces.
            side_b: a.interface(panel, EdgeSeq(vec![edges[8], edges[7]])),
        })
    }
}

/// The dress: a front and a back panel sewn at the sides and shoulders.
#[component(name = "birch_dress")]
pub struct SheathDress {
    #[part]
    pub front: DressPanel,
    #[part]
    pub back: DressPanel,
    #[stitches]
    pub seams: Vec<StitchRule>,
}

impl SheathDress {
    pub fn new(a: &mut Arena, body: &Body) -> garmentcode::Result<Self> {
        let front = DressPanel::new(a, "front", body)?;
        let back = DressPanel::new(a, "back", body)?;
        let hem = body.derived().waist_level - body.hips_line - SKIRT * body.derived().leg_length;
        let half = (body.hips + EASE) / 4.0;
        front.translate_to(a, Vec3::new(-half, hem, 15.0));
        back.rotate_by(a, Rotation::from_euler_xyz_degrees([0.0, 180.0, 0.0]));
        back.translate_to(a, Vec3::new(half, hem, -15.0));
        // The back faces the other way: its `b` side meets the front's `a` side.
        let seams = vec![
            StitchRule::new(a, front.side_a, back.side_b)?,
            StitchRule::new(a, front.side_b, back.side_a)?,
            StitchRule::new(a, front.shoulder_a, back.shoulder_b)?,
            StitchRule::new(a, front.shoulder_b, back.shoulder_a)?,
        ];
        Ok(SheathDress { front, back, seams })
    }
}

fn arg(args: &[String], name: &str) -> Option<String> {
    args.iter().position(|a| a == name).and_then(|i| args.get(i + 1).cloned())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let body_file = arg(&args, "--body").map(PathBuf::from).unwrap_or_else(|| root.join("garments/data/bodies/mean_all.yaml"));
    let out = arg(&args, "--out").map(PathBuf::from).unwrap_or_else(|| PathBuf::from("out/birch_dress"));
    let body = Body::from_yaml(&std::fs::read_to_string(&body_file)?, &body_file.display().to_string())?;

    let mut a = Arena::new();
    let dress = SheathDress::new(&mut a, &body)?;
    let pattern = dress.assemble(&mut a, "birch_dress")?;
    let holes: usize = pattern.panels.iter().map(|p| p.holes.len()).sum();
    println!(
        "{} panels, {holes} diamond darts, {} seams, {} dart seams",
        pattern.panels.len(),
        pattern.stitches.len(),
        pattern.inner_stitches.len()
    );

    std::fs::create_dir_all(&out)?;
    std::fs::write(out.join("specification.json"), pattern.to_json()?)?;
    std::fs::write(out.join("pattern.svg"), to_svg(&pattern, &DrawOptions::default())?)?;
    println!("wrote {}", out.display());
    Ok(())
}
