//! `#[interface]` fields: attributes, optional slots and duplicate names.
use garmentcode::{Component, InterfaceId, PanelId};

#[derive(Component)]
struct UnknownInterfaceAttribute {
    #[panel]
    panel: PanelId,
    #[interface(name = "top")]
    waist: InterfaceId,
}

#[derive(Component)]
struct OptionalSlot {
    #[panel]
    panel: PanelId,
    #[interface(slot = garmentcode::slots::Top)]
    waist: Option<InterfaceId>,
}

#[derive(Component)]
struct DuplicateInterfaceName {
    #[panel]
    panel: PanelId,
    #[interface]
    top: InterfaceId,
    #[interface(rename = "top")]
    waist: InterfaceId,
}

fn main() {}
