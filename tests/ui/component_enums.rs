//! Component enums: one part per variant, slots declared with `slots(..)`.
use garmentcode::{Component, InterfaceId, PanelId};

#[derive(Component)]
struct Band {
    #[panel]
    panel: PanelId,
    #[interface]
    top: InterfaceId,
}

#[derive(Component)]
enum Empty {}

#[derive(Component)]
enum TwoFields {
    Pair(Band, Band),
}

#[derive(Component)]
enum NamedFields {
    Band { band: Band },
}

#[derive(Component)]
enum RoleOnVariant {
    #[part]
    Band(Band),
}

#[derive(Component)]
#[component(name = "skirt")]
enum NameOnEnum {
    Band(Band),
}

#[derive(Component)]
#[component(slot(Top))]
enum UnknownEnumAttribute {
    Band(Band),
}

fn main() {}
