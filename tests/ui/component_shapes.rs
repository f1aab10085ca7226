//! What `#[derive(Component)]` accepts: structs with named fields and enums of parts.
use garmentcode::{Component, PanelId};

#[derive(Component)]
struct Tuple(PanelId);

#[derive(Component)]
union NotAStruct {
    panel: u32,
}

#[derive(Component)]
#[component(kind = "skirt")]
struct UnknownAttribute {
    #[part]
    front: PanelId,
}

#[derive(Component)]
#[component(slots(Top))]
struct SlotsOnAStruct {
    #[part]
    front: PanelId,
}

fn main() {}
