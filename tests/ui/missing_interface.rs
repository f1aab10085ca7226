//! A bottom garment slot needs a `top` interface; this skirt only exposes `bottom`.
use garmentcode::slots::Top;
use garmentcode::{Component, InterfaceId, PanelId, Slot, StitchRule};

#[derive(Component)]
struct Skirt {
    #[part]
    front: PanelId,
    #[interface]
    bottom: InterfaceId,
    #[stitches]
    stitches: Vec<StitchRule>,
}

fn waist_of<B: Slot<Top>>(bottom: &B) -> InterfaceId {
    bottom.slot()
}

fn hem(skirt: &Skirt) -> InterfaceId {
    let _ = (&skirt.front, &skirt.stitches);
    waist_of(skirt)
}

fn main() {
    let _ = hem;
}
