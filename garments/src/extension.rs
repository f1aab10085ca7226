//! The design parameters past the reference's language (`design.extension`, see
//! [`Extension`]): patch pockets, diamond darts and folded cuffs and collars are
//! added to a built garment here; pleats are laid while the skirt is built (they
//! widen its panels: [`crate::skirt_paneled::SkirtPanel::new`]).
//!
//! With every parameter at its default nothing here changes the garment.

use crate::bands::{Cuff, StraightBandPanel};
use crate::bodice::{BodiceHalf, Shirt};
use crate::collars::Collar;
use crate::design::{Extension, PleatStyle};
use crate::pants::Pants;
use crate::shared::Pleating;
use garmentcode::inner::{PleatDirection, PleatKind, diamond_dart, fold_line, place_on};
use garmentcode::{Arena, EdgeSeq, InterfaceId, PanelId, Result, Vec2};

/// Pocket height as a multiple of its width.
const POCKET_HEIGHT: f64 = 1.15;

/// The pleats a two-panel skirt lays into its front and back waist, if any.
pub fn pleating(ext: &Extension) -> Option<[Pleating; 2]> {
    let knife = PleatKind::Knife(PleatDirection::Forward);
    let kinds = match ext.pleats.style? {
        PleatStyle::KnifePleats => [knife, knife],
        PleatStyle::BoxPleats => [PleatKind::BoxPleat, PleatKind::BoxPleat],
        PleatStyle::BoxAndKnife => [PleatKind::BoxPleat, knife],
    };
    Some(kinds.map(|kind| Pleating { kind, count: ext.pleats.count.max(1) as usize, depth: ext.pleats.depth }))
}

/// What of a bottom garment the extension adds to.
pub enum Lower<'g> {
    /// A skirt: the panels facing front, which the hip pockets go on (one panel: both
    /// pockets on it; two: one on each).
    Skirt(Vec<PanelId>),
    /// Trousers: a pocket on each front leg, their cuffs.
    Pants(&'g Pants),
    /// None, or another garment (nothing added).
    Other,
}

/// Add the extension's pieces and marks to a built upper and lower garment; the
/// pockets' panels are returned (new parts of the garment).
pub fn apply(a: &mut Arena, ext: &Extension, upper: Option<&mut Shirt>, lower: Lower<'_>) -> Result<Vec<PanelId>> {
    let mut pockets = Vec::new();
    if let Some(shirt) = upper {
        for half in [&mut shirt.right, &mut shirt.left] {
            if ext.sleeve.one_piece
                && let Some(sleeve) = half.sleeve.as_mut()
            {
                sleeve.join_panels(a)?;
            }
            if ext.darts.diamond && shirt.name == "Shirt" {
                torso_diamond_dart(a, half.ftorso.panel, ext.darts.width)?;
                torso_diamond_dart(a, half.btorso.panel, ext.darts.width)?;
            }
            if ext.cuff.double
                && let Some(Cuff::Band(c)) = half.sleeve.as_ref().and_then(|s| s.cuff.as_ref())
            {
                double_band(a, &c.front, c.front.bottom, c.front.top)?;
                double_band(a, &c.back, c.back.bottom, c.back.top)?;
            }
            if ext.collar.folded {
                fold_turtle(a, half)?;
            }
        }
        if ext.pockets.shirt {
            let front = shirt.right.ftorso.panel;
            pockets.push(pocket(a, front, ext.pockets.width, 0.35, [0.6, 0.55], "pocket")?);
        }
    }
    match lower {
        Lower::Skirt(fronts) if ext.pockets.skirt => hip_pockets(a, &fronts, ext.pockets.width, &mut pockets)?,
        Lower::Pants(p) => {
            for half in [&p.right, &p.left] {
                if ext.pockets.pants {
                    pockets.push(pocket(a, half.front.panel, ext.pockets.width, 0.45, [0.5, 0.8], "pocket")?);
                }
                if ext.cuff.double
                    && let Some(Cuff::Band(c)) = &half.cuff
                {
                    double_band(a, &c.front, c.front.bottom, c.front.top)?;
                    double_band(a, &c.back, c.back.bottom, c.back.top)?;
                }
            }
        }
        _ => {}
    }
    Ok(pockets)
}

/// A diamond dart in a torso panel: a third of the way up, in the middle of its
/// width, a third of its height long; where that does not lie inside the panel (a
/// short or cut-away panel), lower and then smaller.
fn torso_diamond_dart(a: &mut Arena, panel: PanelId, width: f64) -> Result<()> {
    let (lo, hi) = panel.bbox(a);
    let size = hi - lo;
    let width = width.min(size.x / 4.0);
    let mut refusal = None;
    for scale in [1.0, 0.6] {
        for up in [1.0 / 3.0, 0.25, 0.2] {
            let center = Vec2::new(lo.x + size.x / 2.0, lo.y + up * size.y);
            match diamond_dart(a, &panel, "diamond_dart", center, scale * width, scale * size.y / 3.0) {
                Ok(_) => return Ok(()),
                Err(e) => refusal = Some(e),
            }
        }
    }
    Err(refusal.expect("at least one try"))
}

/// Two hip pockets on a skirt, below the hips: on one front panel, each at most a
/// fifth of its width, centred a quarter of the way in from each side; on two
/// panels (gores either side of the front), one in the middle of each, at most 45%
/// of its width. A skirt without room for them is refused, naming the parameter.
fn hip_pockets(a: &mut Arena, fronts: &[PanelId], width: f64, out: &mut Vec<PanelId>) -> Result<()> {
    let spots: Vec<(PanelId, f64, f64)> = match fronts {
        [front] => vec![(*front, 0.2, 0.28), (*front, 0.2, 0.72)],
        _ => fronts.iter().map(|p| (*p, 0.45, 0.5)).collect(),
    };
    for (k, (panel, share, x)) in spots.into_iter().enumerate() {
        let placed = pocket(a, panel, width, share, [x, 0.65], &format!("pocket_{k}")).map_err(|e| {
            garmentcode::Error::Design(format!("extension.pockets.skirt: no room for a hip pocket on '{}': {e}", panel.name(a)))
        })?;
        out.push(placed);
    }
    Ok(())
}

/// A patch pocket `width` wide (at most `share` of the panel's width) on `target`,
/// its centre at fractions `at` of the panel's bounding box, sewn along its sides
/// and bottom. Named `<target>_<tag>`. Where it does not lie inside the panel (a
/// short or cut-away panel), it is tried lower and higher and then smaller; the
/// last refusal is the error.
fn pocket(a: &mut Arena, target: PanelId, width: f64, share: f64, at: [f64; 2], tag: &str) -> Result<PanelId> {
    let (lo, hi) = target.bbox(a);
    let size = hi - lo;
    let name = format!("{}_{tag}", target.name(a));
    let label = target.label(a).to_string();
    let mut refusal = None;
    for scale in [1.0, 0.75, 0.5] {
        for shift in [0.0, -0.1, 0.1, -0.2] {
            let w = scale * width.min(share * size.x);
            let h = (POCKET_HEIGHT * w).min(0.4 * size.y);
            let corners = [Vec2::ZERO, Vec2::new(0.0, h), Vec2::new(w, h), Vec2::new(w, 0.0)];
            let edges = EdgeSeq::from_points(a, &corners, true)?;
            let panel = a.panel_with_edges(&name, edges.clone());
            panel.set_label(a, &label, true);
            let sewn = a.interface(panel, EdgeSeq(vec![edges[2], edges[3], edges[0]]));
            let center = Vec2::new(lo.x + at[0] * size.x, lo.y + (at[1] + shift) * size.y);
            match place_on(a, &panel, sewn, &target, center, 0.0) {
                Ok(_) => return Ok(panel),
                Err(e) => refusal = Some(e),
            }
        }
    }
    Err(refusal.expect("at least one try"))
}

/// Fold the turtle neck of a bodice half, if it has one.
fn fold_turtle(a: &mut Arena, half: &BodiceHalf) -> Result<()> {
    if let Some(Collar::Turtle(t)) = &half.collar {
        double_band(a, &t.front, t.front.top, t.front.bottom)?;
        double_band(a, &t.back, t.back.top, t.back.bottom)?;
    }
    Ok(())
}

/// Double a band: its free edge moves out by the band's depth and a fold line
/// (folded flat, 180°) marks where the edge was, so the band folds back onto itself
/// to its first depth. The line runs so that the part turned (the part right of it)
/// is the free one, whichever way the panel's outline runs (a band's front and back
/// panels run opposite ways): the half sewn on stays where it is. The side seams
/// keep their one edge each.
fn double_band(a: &mut Arena, band: &StraightBandPanel, free: InterfaceId, attached: InterfaceId) -> Result<()> {
    let edge = free.edges(a)[0];
    let (s, t) = (a.pos(a.start(edge)), a.pos(a.end(edge)));
    let (p, q) = attached.edges(a).shortcut(a);
    let out = (s + t) / 2.0 - (p + q) / 2.0;
    let (vs, vt) = (a.start(edge), a.end(edge));
    a.set_pos(vs, s + out);
    a.set_pos(vt, t + out);
    let (from, to) = if (t - s).perp_dot(out) < 0.0 { (s, t) } else { (t, s) };
    fold_line(a, &band.panel, "fold", from, to, 180.0)?;
    Ok(())
}
