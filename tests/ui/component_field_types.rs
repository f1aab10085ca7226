//! Type mistakes in component fields are reported at the field: a `#[part]` that is
//! not a garment part, and a part type that cannot follow a copy (no derive).
use garmentcode::{Component, Node, PanelId, Part};

/// A hand-written part without a `Remap` impl (the derive writes one).
struct Handmade {
    panel: PanelId,
}

impl Part for Handmade {
    fn node(&self) -> Node<'_> {
        Node::Panel(self.panel)
    }
}

#[derive(Component)]
struct NotAPart {
    #[part]
    length: f64,
}

#[derive(Component)]
struct NoCopy {
    #[part]
    trim: Handmade,
}

fn main() {}
