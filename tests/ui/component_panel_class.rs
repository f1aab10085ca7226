//! Panel classes (a struct with a `#[panel]` field) and their rules.
use garmentcode::{Component, InterfaceId, PanelId, StitchRule};

#[derive(Component)]
struct TwoPanels {
    #[panel]
    front: PanelId,
    #[panel]
    back: PanelId,
}

#[derive(Component)]
struct PanelNotAnId {
    #[panel]
    panel: InterfaceId,
}

#[derive(Component)]
struct PanelWithParts {
    #[panel]
    panel: PanelId,
    #[part]
    pocket: PanelId,
}

#[derive(Component)]
struct PanelWithStitches {
    #[panel]
    panel: PanelId,
    #[stitches]
    darts: Vec<StitchRule>,
}

#[derive(Component)]
#[component(name = "band")]
struct PanelWithName {
    #[panel]
    panel: PanelId,
}

fn main() {}
