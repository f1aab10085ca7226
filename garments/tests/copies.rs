//! Typed deep copies of whole garments: a copy of a `MetaGarment` is a
//! `MetaGarment` over its own panels, edges and interfaces (the derive's `Remap`),
//! so it assembles to the same pattern as the original, stitches included, and
//! editing one leaves the other alone.

use garmentcode::{Arena, Interfaces, PartExt, Pattern};
use garments::builtin;
use garments::meta::MetaGarment;

/// The pattern with every panel name prefixed by `tag`.
fn renamed(p: &Pattern, tag: &str) -> String {
    let mut q = p.clone();
    q.name = "x".into();
    for panel in &mut q.panels {
        panel.name = format!("{tag}{}", panel.name);
    }
    for n in q.panel_order.iter_mut().flatten() {
        *n = format!("{tag}{n}");
    }
    for s in &mut q.stitches {
        for side in &mut s.sides {
            side.panel = format!("{tag}{}", side.panel);
        }
    }
    for s in &mut q.inner_stitches {
        for side in &mut s.sides {
            side.panel = format!("{tag}{}", side.panel);
        }
    }
    q.to_json().unwrap()
}

#[test]
fn a_copied_garment_assembles_to_the_same_pattern() {
    let body = builtin::body(builtin::DEFAULT_BODY).unwrap();
    for (name, _) in builtin::DESIGNS {
        let design = builtin::design(name).unwrap();
        let mut a = Arena::new();
        let garment = MetaGarment::new(&mut a, &body, &design).unwrap();
        let copy = garment.deep_copy(&mut a);

        let (orig_panels, copy_panels) = (garment.panel_ids(), copy.panel_ids());
        assert_eq!(orig_panels.len(), copy_panels.len(), "{name}");
        assert!(orig_panels.iter().all(|p| !copy_panels.contains(p)), "{name}: the copy has panels of its own");
        for p in &copy_panels {
            let n = format!("copy_{}", p.name(&a));
            p.set_name(&mut a, &n);
        }
        // The copy's interfaces are over the copy's panels only.
        let shirt = copy.upper.as_ref();
        for (iface_name, i) in shirt.map(|s| s.interfaces()).unwrap_or_default() {
            assert!(i.panels(&a).iter().all(|p| copy_panels.contains(p)), "{name}: interface {iface_name}");
        }

        let copied = copy.assemble(&mut a, name).unwrap();
        let original = garment.assemble(&mut a, name).unwrap();
        assert_eq!(renamed(&original, "copy_"), renamed(&copied, ""), "{name}");
        assert_eq!(original.stitches.len(), copied.stitches.len());
        assert_eq!(original.inner_stitches.len(), copied.inner_stitches.len());
    }
}
