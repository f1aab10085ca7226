use garmentcode::{Component, PanelId};

#[derive(Component)]
struct Band {
    #[panel]
    panel: PanelId,
    #[interface]
    top: PanelId,
}

fn main() {}
