//! The operators inside a panel take a panel (or a panel class): a fold line on an
//! edge sequence, or a pocket placed on a component of several panels, does not compile.
use garmentcode::inner::{fold_line, place_on};
use garmentcode::{Arena, Component, EdgeSeq, PanelId, StitchRule, Vec2};

#[derive(Component)]
struct Skirt {
    #[part]
    front: PanelId,
    #[part]
    back: PanelId,
    #[stitches]
    seams: Vec<StitchRule>,
}

fn main() -> garmentcode::Result<()> {
    let mut a = Arena::new();
    let corners = [Vec2::ZERO, Vec2::new(0.0, 10.0), Vec2::new(10.0, 10.0), Vec2::new(10.0, 0.0)];
    let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
    // A fold line on edges, not on a panel.
    fold_line(&mut a, &edges, "fold", Vec2::ZERO, Vec2::new(10.0, 10.0), 180.0)?;

    let front = a.panel_with_edges("front", edges.clone());
    let back_edges = EdgeSeq::from_points(&mut a, &corners, true)?;
    let back = a.panel_with_edges("back", back_edges);
    let skirt = Skirt { front, back, seams: Vec::new() };
    let pocket_edges = EdgeSeq::from_points(&mut a, &corners, true)?;
    let pocket = a.panel_with_edges("pocket", pocket_edges.clone());
    let sewn = a.interface(pocket, pocket_edges);
    // A pocket placed on a whole skirt: which panel's surface?
    place_on(&mut a, &pocket, sewn, &skirt, Vec2::new(5.0, 5.0), 0.0)?;
    Ok(())
}
