//! `NAME_sim.glb`: a drape as binary glTF 2.0, for any 3D viewer.
//!
//! One mesh per object (the garment, and the body if given), each a node of the one scene:
//! positions in metres (glTF's unit; y up as the reference's meshes), smooth vertex
//! normals, 32-bit triangle indices, a plain material (the garment double-sided). The
//! garment's vertices and triangles are the box mesh's, in its order. Written by hand: the
//! container is a JSON header and one binary buffer.

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;
use serde_json::{Value, json};

use crate::BodyMesh;
use crate::render::{BODY, GARMENT, garment_faces, vertex_normals};

/// A mesh of the file: name, vertices (cm), triangles, colour, whether double-sided.
type Object<'a> = (&'a str, &'a [Vec3], &'a [[u32; 3]], [f64; 3], bool);

/// glTF component types and buffer targets.
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;

/// The GLB file of the draped garment (`positions`, one per box-mesh vertex, cm) and,
/// when given, the body it was draped on.
///
/// # Panics
/// If `positions` does not have one entry per box-mesh vertex.
pub fn glb(mesh: &BoxMesh, positions: &[Vec3], body: Option<&BodyMesh>) -> Vec<u8> {
    assert_eq!(positions.len(), mesh.vertices.len(), "one position per box-mesh vertex");
    let faces = garment_faces(mesh);
    let mut objects: Vec<Object> = vec![("garment", positions, &faces, GARMENT, true)];
    if let Some(b) = body {
        objects.push(("body", &b.vertices, &b.faces, BODY, false));
    }
    let mut bin: Vec<u8> = Vec::new();
    let (mut views, mut accessors, mut meshes, mut nodes, mut materials) = (vec![], vec![], vec![], vec![], vec![]);
    for (i, (name, vertices, tris, color, double_sided)) in objects.into_iter().enumerate() {
        let metres: Vec<[f32; 3]> = vertices.iter().map(|p| (*p * 0.01).as_vec3().to_array()).collect();
        let normals: Vec<[f32; 3]> = vertex_normals(vertices, tris).iter().map(|n| n.as_vec3().to_array()).collect();
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in &metres {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let mut view = |bytes: &[u8], target: u32| {
            let offset = bin.len();
            bin.extend_from_slice(bytes);
            views.push(json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len(), "target": target }));
            views.len() - 1
        };
        let floats = |v: &[[f32; 3]]| v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
        let indices: Vec<u8> = tris.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let pv = view(&floats(&metres), ARRAY_BUFFER);
        let nv = view(&floats(&normals), ARRAY_BUFFER);
        let iv = view(&indices, ELEMENT_ARRAY_BUFFER);
        let a = accessors.len();
        accessors.push(json!({ "bufferView": pv, "componentType": FLOAT, "count": metres.len(), "type": "VEC3", "min": lo, "max": hi }));
        accessors.push(json!({ "bufferView": nv, "componentType": FLOAT, "count": normals.len(), "type": "VEC3" }));
        accessors.push(json!({ "bufferView": iv, "componentType": UNSIGNED_INT, "count": tris.len() * 3, "type": "SCALAR" }));
        materials.push(json!({
            "name": name,
            "pbrMetallicRoughness": { "baseColorFactor": [color[0], color[1], color[2], 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.9 },
            "doubleSided": double_sided,
        }));
        meshes.push(json!({
            "name": name,
            "primitives": [{ "attributes": { "POSITION": a, "NORMAL": a + 1 }, "indices": a + 2, "material": i, "mode": 4 }],
        }));
        nodes.push(json!({ "name": name, "mesh": i }));
    }
    let node_ids: Vec<usize> = (0..nodes.len()).collect();
    let doc: Value = json!({
        "asset": { "version": "2.0", "generator": "garmentcode-drape" },
        "scene": 0,
        "scenes": [{ "nodes": node_ids }],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{ "byteLength": bin.len() }],
    });
    let mut text = serde_json::to_vec(&doc).expect("a JSON value serialises");
    text.resize(text.len().next_multiple_of(4), b' ');
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(text.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&text);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}
