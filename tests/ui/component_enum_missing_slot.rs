//! Every variant of an enum must fill the slots the enum declares: `Pocket` has no
//! `top` interface.
use garmentcode::{Component, InterfaceId, PanelId};

#[derive(Component)]
struct Band {
    #[panel]
    panel: PanelId,
    #[interface]
    top: InterfaceId,
}

#[derive(Component)]
struct Pocket {
    #[panel]
    panel: PanelId,
    #[interface]
    bottom: InterfaceId,
}

#[derive(Component)]
#[component(slots(garmentcode::slots::Top))]
enum Trim {
    Band(Band),
    Pocket(Pocket),
}

fn main() {}
