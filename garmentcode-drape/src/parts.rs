//! Which body part each panel drapes over, as the reference assigns them
//! (`panel_assignment`, strategy `closest`), and the part meshes that particles of panels
//! crossing each other are dragged back onto (its "reference drag"), and the body
//! collision filters (leg panels ignore the arms; body panels ignore the inside of the mouth).

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
    /// Per body triangle, the filters that hide it (bit k: filter k of [`FILTERS`]).
    face_filter: Vec<u8>,
    /// Per particle, the filter it sees the body through, if any.
    particle_filter: Vec<Option<usize>>,
}

/// Body collision filters: particles of the first parts do not collide with body triangles
/// of the second (a triangle belongs to a part when two of its corners do).
const FILTERS: [(&[&str], &[&str]); 2] =
    [(&["left_leg", "right_leg", "legs"], &["left_arm", "right_arm", "arms"]), (&["body"], &["face_internal"])];

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
        let label: Vec<Option<usize>> = mesh
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
        // A body vertex in several parts counts as the last (the reference's quirk).
        let last_part = |v: u32| (vertex_parts[v as usize] != 0).then(|| PARTS[7 - vertex_parts[v as usize].leading_zeros() as usize]);
        let face_filter = body
            .faces
            .iter()
            .map(|f| {
                let mut bits = 0u8;
                for (k, (_, hidden)) in FILTERS.iter().enumerate() {
                    let [a, b, c] = f.map(|v| last_part(v).is_some_and(|p| hidden.contains(&p)));
                    if if a == b || a == c { a } else { b } {
                        bits |= 1 << k;
                    }
                }
                bits
            })
            .collect();
        let in_filter = |l: Option<usize>, k: usize| l.is_some_and(|l| FILTERS[k].0.contains(&names[l].as_str()));
        let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); mesh.labels.len()];
        for f in &mesh.faces {
            let [a, b, c] = f.vertices;
            neighbours[a].extend([b, c]);
            neighbours[b].extend([a, c]);
            neighbours[c].extend([a, b]);
        }
        let particle_filter = (0..mesh.labels.len())
            .map(|i| {
                (0..FILTERS.len()).find(|&k| match label[i] {
                    Some(_) => in_filter(label[i], k),
                    // Stitch vertices: by the majority of their neighbour entries.
                    None => 2 * neighbours[i].iter().filter(|&&n| in_filter(label[n], k)).count() > neighbours[i].len(),
                })
            })
            .collect();
        Some(Parts { label, names, meshes, face_filter, particle_filter })
    }

    /// Whether particle `i` ignores body triangle `face`.
    pub fn hides(&self, i: usize, face: usize) -> bool {
        self.particle_filter[i].is_some_and(|k| self.face_filter[face] & (1 << k) != 0)
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

#[cfg(test)]
mod tests {
    use super::*;

    fn parts_of(spec: &str) -> (BoxMesh, Parts) {
        let pattern = garmentcode::Pattern::from_json(spec).unwrap();
        let mesh = BoxMesh::new(&pattern, 1.0).unwrap();
        let labels = pattern.panels.iter().filter_map(|p| Some((p.name.clone(), p.label.clone()?))).collect();
        let parts = Parts::new(&mesh, &BodyMesh::builtin("mean_all").unwrap(), &labels).unwrap();
        (mesh, parts)
    }

    #[test]
    fn t_shirt_panels_go_to_the_body_and_the_arms() {
        let (mesh, parts) = parts_of(include_str!("../tests/data/t-shirt_specification.json"));
        let part_of = |panel: &str| {
            let p = mesh.panels.iter().position(|q| q.name == panel).unwrap();
            let v = mesh.labels.iter().position(|l| *l == VertexLabel::Panel(p)).unwrap();
            parts.names[parts.label[v].unwrap()].clone()
        };
        assert_eq!(part_of("left_sleeve_f"), "left_arm");
        assert_eq!(part_of("right_sleeve_b"), "right_arm");
        assert_eq!(part_of("left_ftorso"), "body");
        assert_eq!(part_of("right_btorso"), "body");
        // Stitch vertices are unlabelled.
        assert!(mesh.labels.iter().zip(&parts.label).all(|(l, p)| matches!(l, VertexLabel::Stitch(_)) == p.is_none()));
        let index = |name: &str| parts.names.iter().position(|n| n == name).unwrap();
        assert!(parts.is_drag_pair(index("left_arm"), index("body")));
        assert!(!parts.is_drag_pair(index("left_arm"), index("right_arm")));
        // Body panels ignore the inside of the mouth, and only that.
        let v = (0..mesh.labels.len()).find(|&v| parts.label[v] == Some(index("body"))).unwrap();
        assert_eq!(parts.particle_filter[v], Some(1));
        let hidden: Vec<usize> = (0..parts.face_filter.len()).filter(|&f| parts.hides(v, f)).collect();
        assert!(!hidden.is_empty() && hidden.iter().all(|&f| parts.face_filter[f] == 2));
    }

    #[test]
    fn a_waistband_is_all_body_and_arm_triangles_are_marked_for_the_legs() {
        let (_, parts) = parts_of(include_str!("../tests/data/waistband_specification.json"));
        assert_eq!(parts.names, ["body"]);
        let arm_faces = parts.face_filter.iter().filter(|&&b| b & 1 != 0).count();
        assert!(arm_faces > 5000, "{arm_faces} arm triangles");
        assert_eq!(FILTERS[0].0, ["left_leg", "right_leg", "legs"]);
    }
}
