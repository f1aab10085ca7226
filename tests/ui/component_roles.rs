//! Misused role attributes on component fields: each struct below has one mistake.
use garmentcode::{Component, InterfaceId, PanelId, StitchRule};

#[derive(Component)]
struct PartWithArgs {
    #[part(front)]
    front: PanelId,
}

#[derive(Component)]
struct PanelWithArgs {
    #[panel(main)]
    panel: PanelId,
}

#[derive(Component)]
struct StitchesWithArgs {
    #[part]
    front: PanelId,
    #[stitches(all)]
    stitches: Vec<StitchRule>,
}

#[derive(Component)]
struct TwoStitchLists {
    #[part]
    front: PanelId,
    #[stitches]
    seams: Vec<StitchRule>,
    #[stitches]
    darts: Vec<StitchRule>,
}

#[derive(Component)]
struct TwoRoles {
    #[part]
    #[interface]
    top: InterfaceId,
}

fn main() {}
