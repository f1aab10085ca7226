//! Which body part each panel drapes over, as the reference assigns them
//! (`panel_assignment`, strategy `closest`), and the part meshes that particles of panels
//! crossing each other are dragged back onto (its "reference drag").

use std::collections::BTreeMap;

use garmentcode::Vec3;
use garmentcode::mesh::{BoxMesh, VertexLabel};

use crate::body::{BodyMesh, PARTS};
use crate::bvh::Bvh;

/// Pairs of parts whose crossing panels are dragged apart (legs and body deliberately not).
const DRAG_PAIRS: [[&str; 2]; 9] = [
    ["left_arm", "body"],
    ["right_arm", "body"],
    ["left_leg", "right_leg"],
    ["left_arm", "left_leg"],
    ["right_arm", "left_leg"],
    ["left_arm", "right_leg"],
    ["right_arm", "right_leg"],
    ["left_arm", "legs"],
    ["right_arm", "legs"],
];

/// The part assignment of a garment on a segmented body.
pub(crate) struct Parts {
    /// Per particle: index into `names` (`None` for stitch vertices).
    pub label: Vec<Option<usize>>,
    /// The parts used, in order of first use (`arms` and `legs` merge both sides).
    pub names: Vec<String>,
    /// Triangles of each used part, with their tree.
    meshes: Vec<(Vec<[Vec3; 3]>, Bvh)>,
}

/// The part bits (of [`PARTS`]) that a part name covers.
fn part_bits(name: &str) -> u8 {
    let bit = |n: &str| PARTS.iter().position(|p| *p == n).map_or(0, |i| 1u8 << i);
    match name {
        "arms" => bit("left_arm") | bit("right_arm"),
        "legs" => bit("left_leg") | bit("right_leg"),
        n => bit(n),
    }
}

impl Parts {
    /// Assigns every panel of `mesh` to the body part its vertices are closest to, counting
    /// for each vertex the parts of the closest body triangle's corners (a third each). A
    /// panel label (`panel_labels`, e.g. `arm`) restricts the choice to parts whose name
    /// contains it; a leg becomes `legs` unless the panel's name contains `pant`. `None`
    /// when the body has no segmentation.
    pub fn new(mesh: &BoxMesh, body: &BodyMesh, panel_labels: &BTreeMap<String, String>) -> Option<Parts> {
        let vertex_parts = body.parts()?;
        let mut panel_label: Vec<Option<usize>> = vec![None; mesh.panels.len()];
        let mut names: Vec<String> = Vec::new();
        for (p, panel) in mesh.panels.iter().enumerate() {
            let mut stats = [0.0f64; PARTS.len()];
            let mut any = false;
            for (v, label) in mesh.labels.iter().enumerate() {
                if *label != VertexLabel::Panel(p) {
                    continue;
                }
                any = true;
                let Some(hit) = body.closest(mesh.vertices[v], f64::INFINITY) else { continue };
                for &corner in &body.faces[hit.face] {
                    for (k, s) in stats.iter_mut().enumerate() {
                        if vertex_parts[corner as usize] & (1 << k) != 0 {
                            *s += 1.0 / 3.0;
                        }
                    }
                }
            }
            if !any {
                continue;
            }
            if let Some(base) = panel_labels.get(&panel.name).filter(|l| !l.is_empty()) {
                for (k, s) in stats.iter_mut().enumerate() {
                    if !PARTS[k].contains(base.as_str()) {
                        *s = -1.0;
                    }
                }
            }
            // The first maximum, as numpy's argmax.
            let best = (0..PARTS.len()).fold(0, |b, k| if stats[k] > stats[b] { k } else { b });
            let mut name = PARTS[best];
            if matches!(name, "left_leg" | "right_leg") && !panel.name.contains("pant") {
                name = "legs";
            }
            let index = names.iter().position(|n| n == name).unwrap_or_else(|| {
                names.push(name.to_string());
                names.len() - 1
            });
            panel_label[p] = Some(index);
        }
        let label = mesh
            .labels
            .iter()
            .map(|l| match l {
                VertexLabel::Panel(p) => panel_label[*p],
                VertexLabel::Stitch(_) => None,
            })
            .collect();
        let tris = body.tris();
        let meshes = names
            .iter()
            .map(|name| {
                let bits = part_bits(name);
                let part: Vec<[Vec3; 3]> = body
                    .faces
                    .iter()
                    .zip(tris)
                    .filter(|(f, _)| f.iter().all(|&i| vertex_parts[i as usize] & bits != 0))
                    .map(|(_, t)| *t)
                    .collect();
                let bvh = Bvh::new(&part);
                (part, bvh)
            })
            .collect();
        Some(Parts { label, names, meshes })
    }

    /// Whether crossings between parts `a` and `b` are dragged apart.
    pub fn is_drag_pair(&self, a: usize, b: usize) -> bool {
        let (a, b) = (self.names[a].as_str(), self.names[b].as_str());
        DRAG_PAIRS.iter().any(|&[x, y]| (x == a && y == b) || (x == b && y == a))
    }

    /// The closest point of part `part` to `p`.
    pub fn closest(&self, part: usize, p: Vec3) -> Option<Vec3> {
        let (tris, bvh) = &self.meshes[part];
        Some(bvh.closest(tris, p, f64::INFINITY)?.point)
    }
}
