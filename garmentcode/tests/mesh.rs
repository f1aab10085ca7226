//! The simulation box mesh (`garmentcode::mesh`).
//!
//! Parity with the reference's BoxMesh on its 20 mesh cases and 3 more
//! (`tests/data/mesh/<case>`: the reference's summary, boundary samples, vertex labels and
//! seam rest lengths, and the specification; `tools/gen_mesh_cases.py` records them):
//! what any correct triangulation must share with the reference's (vertex counts per
//! edge, stitch pairing, labels, boundary positions, areas, density, the rest lengths
//! of seams), checked in Rust the way `compare_mesh.py` judges the files. The 3 more:
//! `case-038` and `case-047`, garments with gathered seams (stitched edges of different
//! lengths, whose rest length is the shorter side's), and `count-rounding`, a 46 cm edge
//! whose square root of squares is 46.00000000000001 (the reference's `hypot` gives 46:
//! one vertex fewer). Properties on every reference pattern
//! (`../tests/data/cases`, also those the reference fails to mesh): equal stitch sides,
//! valid triangles inside their panel; a mirrored panel meshes to the mirror; a snapshot
//! of one garment's small files; our OBJ and segmentation read back.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use garmentcode::Curvature;
use garmentcode::mesh::obj::ObjMesh;
use garmentcode::mesh::write::read_segmentation;
use garmentcode::mesh::{BoxMesh, DEFAULT_RESOLUTION, MeshError, PanelMesh, SIZE_BOUND, VertexLabel};
use garmentcode::{Pattern, Vec2, Vec3};
use serde_json::Value;

fn mesh_cases() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh");
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir).expect("mesh cases").map(|e| e.expect("entry").path()).collect();
    v.sort();
    v
}

fn load(path: &Path, name: &str) -> Pattern {
    let mut p = Pattern::from_json(&std::fs::read_to_string(path).expect("specification")).expect("a specification");
    p.name = name.to_string();
    p
}

fn json(path: PathBuf) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("json")).expect("valid json")
}

fn area2(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// Even–odd test of `p` against the panel's sampled outline.
fn inside_outline(panel: &PanelMesh, p: Vec2) -> bool {
    let mut inside = false;
    for e in &panel.edges {
        for w in e.local.windows(2) {
            let (a, b) = (panel.points[w[0]], panel.points[w[1]]);
            if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether the panel's sampled outline crosses itself (segments meeting other than at shared ends).
fn self_crossing(panel: &PanelMesh) -> bool {
    let segs: Vec<(Vec2, Vec2)> =
        panel.edges.iter().flat_map(|e| e.local.windows(2).map(|w| (panel.points[w[0]], panel.points[w[1]]))).collect();
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            let ((a, b), (c, d)) = (segs[i], segs[j]);
            if a == c || a == d || b == c || b == d {
                continue;
            }
            let (d1, d2) = (area2(a, b, c), area2(a, b, d));
            let (d3, d4) = (area2(c, d, a), area2(c, d, b));
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                return true;
            }
        }
    }
    false
}

/// Properties every mesh must have; returns the problems found.
fn properties(mesh: &BoxMesh) -> Vec<String> {
    let mut problems = Vec::new();
    for (k, s) in mesh.stitches.iter().enumerate() {
        let [(p0, e0), (p1, e1)] = s.sides;
        let (n0, n1) = (mesh.panels[p0].edges[e0].local.len(), mesh.panels[p1].edges[e1].local.len());
        if n0 != n1 || n0 != s.n {
            problems.push(format!("stitch {k}: sides have {n0} and {n1} vertices"));
        }
    }
    if mesh.labels.len() != mesh.vertices.len() {
        problems.push("one label per vertex".into());
    }
    if mesh.labels[..mesh.n_stitch_vertices].iter().any(|l| !matches!(l, VertexLabel::Stitch(_)))
        || mesh.labels[mesh.n_stitch_vertices..].iter().any(|l| matches!(l, VertexLabel::Stitch(_)))
    {
        problems.push("stitch vertices must form the leading block".into());
    }
    for (pi, panel) in mesh.panels.iter().enumerate() {
        let crossing = self_crossing(panel);
        let sign = if panel.counter_clockwise { 1.0 } else { -1.0 };
        let (mut bad, mut outside, mut wound) = (0, 0, 0);
        for f in mesh.faces.iter().filter(|f| f.panel == pi) {
            let [a, b, c] = f.uvs.map(|t| panel.points[t - panel.texture_offset]);
            let l = [(b - a).length(), (c - b).length(), (a - c).length()];
            let max = l.iter().copied().fold(0.0, f64::max);
            if l.iter().sum::<f64>() <= 2.0 * max + 0.01 {
                bad += 1;
            }
            if sign * area2(a, b, c) <= 0.0 {
                wound += 1;
            }
            if !inside_outline(panel, (a + b + c) / 3.0) {
                outside += 1;
            }
            for (t, v) in f.uvs.iter().zip(f.vertices) {
                let local = t - panel.texture_offset;
                if local >= panel.n_stitch_side {
                    let expect = panel.to_3d(panel.points[local]);
                    if (mesh.vertices[v] - expect).length() > 1e-9 {
                        problems.push(format!("{}: vertex {v} is not at its panel's 3D image", panel.name));
                    }
                }
            }
        }
        // Self-crossing outlines: the reference's own mesh breaks these rules there too.
        if !crossing && bad + outside + wound > 0 {
            problems.push(format!("{}: {bad} degenerate, {outside} outside, {wound} wrongly wound triangles", panel.name));
        }
    }
    problems
}

fn area_of(mesh: &BoxMesh, pi: usize) -> f64 {
    let panel = &mesh.panels[pi];
    mesh.faces
        .iter()
        .filter(|f| f.panel == pi)
        .map(|f| {
            let [a, b, c] = f.uvs.map(|t| panel.points[t - panel.texture_offset]);
            area2(a, b, c).abs() / 2.0
        })
        .sum()
}

/// Everything `compare_mesh.py` checks that is fixed by the pattern, against the reference's records.
fn parity(case: &Path) -> Vec<String> {
    let name = case.file_name().expect("case name").to_string_lossy().into_owned();
    let summary = json(case.join("summary.json"));
    let pattern = load(&case.join(format!("{name}_specification.json")), &name);
    let mesh = match BoxMesh::new(&pattern, DEFAULT_RESOLUTION) {
        Ok(m) => m,
        Err(e) => return vec![format!("not meshed: {e}")],
    };
    let mut problems = properties(&mesh);
    if summary["failed"].as_bool() == Some(true) {
        return problems; // The reference has no mesh to compare with.
    }
    let boundary = json(case.join("boundary.json"));
    let panel_index: HashMap<&str, usize> = mesh.panels.iter().enumerate().map(|(i, p)| (p.name.as_str(), i)).collect();
    // Vertex counts per edge and exact boundary samples (2D) and their 3D images.
    for (key, n) in summary["edge_vertex_counts"].as_object().expect("edge counts") {
        let (p, e) = key.rsplit_once(':').expect("panel:edge");
        let (pi, ei) = (panel_index[p], e.parse::<usize>().expect("edge index"));
        let ours = &mesh.panels[pi].edges[ei];
        if ours.local.len() as u64 != n.as_u64().expect("count") {
            problems.push(format!("{key}: {} vertices, the reference {n}", ours.local.len()));
            continue;
        }
        let xy = boundary["panels"][p]["edges"][ei]["xy"].as_array().expect("samples");
        let panel = &mesh.panels[pi];
        let r = &boundary["panels"][p]["R"];
        let rot = |v: Vec2| {
            let row = |i: usize| Vec3::new(r[i][0].as_f64().unwrap(), r[i][1].as_f64().unwrap(), r[i][2].as_f64().unwrap());
            Vec3::new(row(0).dot(Vec3::new(v.x, v.y, 0.0)), row(1).dot(Vec3::new(v.x, v.y, 0.0)), row(2).dot(Vec3::new(v.x, v.y, 0.0)))
        };
        for (l, q) in ours.local.iter().zip(xy) {
            let q = Vec2::new(q[0].as_f64().unwrap(), q[1].as_f64().unwrap());
            if (panel.points[*l] - q).length() > 1e-6 {
                problems.push(format!("{key}: sample at {:?}, the reference's at {q:?}", panel.points[*l]));
                break;
            }
            if *l >= panel.n_stitch_side && (mesh.vertices[panel.global[*l]] - (rot(q) + panel.translation)).length() > 1e-6 {
                problems.push(format!("{key}: 3D position differs from the reference's"));
                break;
            }
        }
    }
    // Stitch block and per-stitch labelled vertex counts.
    if mesh.n_stitch_vertices as u64 != summary["n_stitch_vertices"].as_u64().expect("stitch vertices") {
        problems.push(format!("{} stitch vertices, the reference {}", mesh.n_stitch_vertices, summary["n_stitch_vertices"]));
    }
    for (k, s) in summary["stitches"].as_object().expect("stitches") {
        let id: usize = k.trim_start_matches("stitch_").parse().expect("stitch id");
        let ours = mesh.labels.iter().filter(|l| matches!(l, VertexLabel::Stitch(ks) if ks.contains(&id))).count();
        if ours as u64 != s["n_labeled_vertices"].as_u64().expect("count") {
            problems.push(format!("{k}: {ours} labelled vertices, the reference {}", s["n_labeled_vertices"]));
        }
    }
    // Vertex labels: same labels, same number of vertices each.
    let yaml = std::fs::read_to_string(case.join(format!("{name}_vertex_labels.yaml"))).expect("labels");
    let mut theirs: Vec<(String, usize)> = Vec::new();
    for line in yaml.lines() {
        if let Some(label) = line.strip_suffix(':') {
            theirs.push((label.to_string(), 0));
        } else if line.starts_with("- ") {
            theirs.last_mut().expect("a label first").1 += 1;
        }
    }
    let ours: Vec<(String, usize)> = mesh.vertex_labels.iter().map(|(l, ids)| (l.clone(), ids.len())).collect();
    if ours != theirs {
        problems.push(format!("vertex labels {ours:?}, the reference {theirs:?}"));
    }
    // Areas (0.5%) and interior density (size bound, count within 0.5–2× of the reference's).
    let mut interior_total = (0usize, 0u64);
    for (p, s) in summary["panels"].as_object().expect("panels") {
        let pi = panel_index[p.as_str()];
        let (ours, theirs) = (area_of(&mesh, pi), s["area_2d"].as_f64().expect("area"));
        if (ours - theirs).abs() > 0.005 * theirs {
            problems.push(format!("{p}: area {ours:.2} cm², the reference {theirs:.2}"));
        }
        let panel = &mesh.panels[pi];
        let interior = panel.points.len() - panel.n_boundary;
        let theirs = s["n_interior_vertices"].as_u64().expect("interior count");
        interior_total.0 += interior;
        interior_total.1 += theirs;
        if theirs >= 100 && !(interior as f64 >= 0.5 * theirs as f64 && interior as f64 <= 2.0 * theirs as f64) {
            problems.push(format!("{p}: {interior} interior vertices, the reference {theirs}"));
        }
        let mut long = 0;
        for f in mesh.faces.iter().filter(|f| f.panel == pi) {
            let l = f.uvs.map(|t| t - panel.texture_offset);
            for k in 0..3 {
                let (a, b) = (l[k], l[(k + 1) % 3]);
                let length = (panel.points[a] - panel.points[b]).length();
                if (a >= panel.n_boundary || b >= panel.n_boundary) && length > 1.1 * 1.5 * DEFAULT_RESOLUTION {
                    long += 1;
                }
            }
        }
        if long > 0 {
            problems.push(format!("{p}: {long} interior edges longer than 1.65 cm"));
        }
    }
    let (ours, theirs) = (interior_total.0 as f64, interior_total.1 as f64);
    if ours < 0.5 * theirs || ours > 2.0 * theirs {
        problems.push(format!("{ours} interior vertices, the reference {theirs}"));
    }
    problems.extend(seam_rest_lengths(case, &mesh));
    problems
}

/// Seam rest lengths (between consecutive vertices along each stitch) against the
/// reference's (`seam_lengths.json`, where recorded), within the judge's 5% or 0.02 cm.
fn seam_rest_lengths(case: &Path, mesh: &BoxMesh) -> Vec<String> {
    let path = case.join("seam_lengths.json");
    if !path.exists() {
        return Vec::new();
    }
    let theirs = json(path);
    let lens: HashMap<[usize; 2], f64> = mesh.rest_lengths.iter().copied().collect();
    let mut problems = Vec::new();
    for (k, s) in mesh.stitches.iter().enumerate() {
        let (p0, e0) = s.sides[0];
        let mut side = mesh.panels[p0].edges[e0].local.clone();
        if !s.right_wrong {
            side.reverse();
        }
        let glob: Vec<usize> = side.iter().map(|&l| mesh.panels[p0].global[l]).collect();
        for (i, expected) in theirs[format!("stitch_{k}")].as_array().expect("stitch lengths").iter().enumerate() {
            let (Some(expected), [a, b]) = (expected.as_f64(), [glob[i], glob[i + 1]]) else { continue };
            let ours = lens.get(&[a.min(b), a.max(b)]).copied().unwrap_or(f64::NAN);
            if ours.is_nan() || (ours - expected).abs() > 0.02f64.max(0.05 * expected) {
                problems.push(format!("stitch_{k} pair {i}: rest length {ours:.4}, the reference {expected:.4}"));
            }
        }
    }
    problems
}

#[test]
fn reference_mesh_cases_match() {
    let cases = mesh_cases();
    assert_eq!(cases.len(), 23);
    let mut report = Vec::new();
    for case in &cases {
        let problems = parity(case);
        if !problems.is_empty() {
            report.push(format!("{}: {}", case.display(), problems.join("; ")));
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
fn every_reference_pattern_meshes_with_valid_properties() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases");
    let mut specs: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("cases")
        .map(|e| e.expect("entry").path().join("specification.json"))
        .filter(|p| p.exists())
        .collect();
    specs.sort();
    assert!(specs.len() >= 50);
    let mut report = Vec::new();
    for spec in &specs {
        let pattern = load(spec, "case");
        match BoxMesh::new(&pattern, DEFAULT_RESOLUTION) {
            Ok(mesh) => {
                let p = properties(&mesh);
                if !p.is_empty() {
                    report.push(format!("{}: {}", spec.display(), p.join("; ")));
                }
            }
            Err(e) => report.push(format!("{}: {e}", spec.display())),
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

/// The panel mirrored in its local y axis (x → −x): curvature offsets and arc sides flip.
fn mirrored(pattern: &Pattern) -> Pattern {
    let mut m = pattern.clone();
    for p in &mut m.panels {
        p.vertices.iter_mut().for_each(|v| v[0] = -v[0]);
        for e in &mut p.edges {
            match &mut e.curvature {
                Some(Curvature::Quadratic(c)) => c[1] = -c[1],
                Some(Curvature::Cubic(c1, c2)) => {
                    c1[1] = -c1[1];
                    c2[1] = -c2[1];
                }
                Some(Curvature::Circle { right, .. }) => *right = !*right,
                None => {}
            }
        }
    }
    m
}

#[test]
fn a_mirrored_panel_meshes_to_the_mirrored_mesh() {
    let case = &mesh_cases()[0];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let mut pattern = load(&case.join(format!("{name}_specification.json")), &name);
    pattern.stitches.clear();
    let a = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("mesh");
    let b = BoxMesh::new(&mirrored(&pattern), DEFAULT_RESOLUTION).expect("mirrored mesh");
    for (pa, pb) in a.panels.iter().zip(&b.panels) {
        // The outline samples are exactly mirrored, and the outline orientation flips.
        assert_eq!(pa.n_boundary, pb.n_boundary);
        for (p, q) in pa.points[..pa.n_boundary].iter().zip(&pb.points[..pb.n_boundary]) {
            assert!((p.x + q.x).abs() < 1e-9 && (p.y - q.y).abs() < 1e-9, "{p:?} vs {q:?}");
        }
        assert_ne!(pa.counter_clockwise, pb.counter_clockwise);
    }
    for pi in 0..a.panels.len() {
        let (x, y) = (area_of(&a, pi), area_of(&b, pi));
        assert!((x - y).abs() < 1e-9 * x, "{}: {x} vs {y}", a.panels[pi].name);
        // Triangles: in the mirror, every triangle is the mirror image of one of the original's.
        let key = |mesh: &BoxMesh, f: &garmentcode::mesh::MeshFace, flip: f64| {
            let panel = &mesh.panels[pi];
            let mut c: Vec<(i64, i64)> = f
                .uvs
                .iter()
                .map(|t| {
                    let p = panel.points[t - panel.texture_offset];
                    ((flip * p.x * 1e6).round() as i64, (p.y * 1e6).round() as i64)
                })
                .collect();
            c.sort_unstable();
            c
        };
        let mut ta: Vec<_> = a.faces.iter().filter(|f| f.panel == pi).map(|f| key(&a, f, 1.0)).collect();
        let mut tb: Vec<_> = b.faces.iter().filter(|f| f.panel == pi).map(|f| key(&b, f, -1.0)).collect();
        ta.sort();
        tb.sort();
        assert_eq!(ta, tb, "{}: the mirrored mesh differs", a.panels[pi].name);
    }
    assert!(properties(&b).is_empty());
}

#[test]
fn written_files_read_back() {
    let case = &mesh_cases()[0];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let mesh = BoxMesh::new(&load(&case.join(format!("{name}_specification.json")), &name), DEFAULT_RESOLUTION).expect("mesh");
    let dir = std::env::temp_dir().join(format!("garmentcode-mesh-{}", std::process::id()));
    let written = mesh.write_files(&dir).expect("written");
    assert_eq!(written.len(), garmentcode::mesh::write::FILE_SUFFIXES.len());
    // The texture the material names: a PNG of the declared size.
    let material = std::fs::read_to_string(dir.join(format!("{name}_material.mtl"))).unwrap();
    let texture = material.lines().find_map(|l| l.strip_prefix("map_Kd ")).expect("map_Kd");
    let png = std::fs::read(dir.join(texture)).expect("the texture the material names is written");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let side = garmentcode::mesh::write::TEXTURE_SIZE as u32;
    let (width, height) = (u32::from_be_bytes(png[16..20].try_into().unwrap()), u32::from_be_bytes(png[20..24].try_into().unwrap()));
    assert_eq!((width, height), (side, side));
    let read =
        ObjMesh::parse(&std::fs::read_to_string(dir.join(format!("{name}_boxmesh.obj"))).unwrap(), Default::default()).expect("our OBJ");
    let vertices = read.vertices;
    assert_eq!(vertices, mesh.vertices, "positions round-trip exactly");
    assert_eq!(read.triangles, mesh.faces.iter().map(|f| f.vertices).collect::<Vec<_>>());
    let seg = read_segmentation(&std::fs::read_to_string(dir.join(format!("{name}_sim_segmentation.txt"))).unwrap());
    assert_eq!(seg.len(), vertices.len());
    for (v, labels) in seg.iter().enumerate() {
        assert_eq!(labels.join(","), mesh.segmentation_label(v));
        let is_stitch = labels[0].starts_with("stitch_");
        assert_eq!(is_stitch, v < mesh.n_stitch_vertices);
        if !is_stitch {
            // A panel vertex's label names the panel whose faces use it.
            assert!(mesh.panels.iter().any(|p| p.name == labels[0]));
        }
    }
    let welded = ObjMesh::parse(&std::fs::read_to_string(dir.join(format!("{name}_sim_mesh.obj"))).unwrap(), Default::default())
        .expect("welded OBJ");
    assert!(welded.vertices.iter().zip(&mesh.vertices).all(|(m, c)| (*m * 100.0 - *c).length() < 1e-9));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn small_files_snapshot() {
    let case = &mesh_cases()[0];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let mesh = BoxMesh::new(&load(&case.join(format!("{name}_specification.json")), &name), DEFAULT_RESOLUTION).expect("mesh");
    // Segmentation as runs of equal lines (the interior count depends on the triangulator).
    let mut runs: Vec<(String, usize)> = Vec::new();
    for v in 0..mesh.n_stitch_vertices {
        let l = mesh.segmentation_label(v);
        match runs.last_mut() {
            Some((last, n)) if *last == l => *n += 1,
            _ => runs.push((l, 1)),
        }
    }
    let seg: String = runs.iter().map(|(l, n)| format!("{l} x{n}\n")).collect();
    let panels: String =
        mesh.panels.iter().map(|p| format!("{}: {} stitch-side, {} boundary\n", p.name, p.n_stitch_side, p.n_boundary)).collect();
    insta::assert_snapshot!(
        "box_mesh_case_001",
        format!("{}\n--- stitch block\n{seg}--- panels\n{panels}--- vertex labels\n{}", mesh.material(), mesh.vertex_labels_yaml())
    );
}

/// A ruffle of a levels skirt (seen in a dataset run): a half ring 1 to 3 cm wide and
/// 16 m long, whose bounding box is 180 times its area. It meshes, with vertices in
/// proportion to its area, and with the mesh's properties.
#[test]
fn a_thin_ring_meshes_in_proportion_to_its_area() {
    let spec = r#"{"pattern": {"panels": {"ruffle": {"translation": [-514.7533775580981, 297.6170280779458, 17.5], "rotation": [0.0, 0.0, 0.0], "vertices": [[-0.7533775580981228, 0.0], [-3.784064527139094, 0.0], [1031.784064527139, 0.0], [1028.7533775580982, 0.0]], "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2], "curvature": {"type": "circle", "params": [517.7877953290746, 0, 1]}}, {"endpoints": [2, 3]}, {"endpoints": [3, 0], "curvature": {"type": "circle", "params": [514.7533775580986, 0, 0]}}], "label": "leg"}}, "stitches": [], "panel_order": ["ruffle"]}, "properties": {"curvature_coords": "relative", "normalize_panel_translation": false, "normalized_edge_loops": true, "units_in_meter": 100}}"#;
    let pattern = Pattern::from_json(spec).expect("pattern");
    let mesh = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("a thin ring meshes");
    let area = area_of(&mesh, 0);
    // The area inside the sampled outline (the two arcs are not concentric: the ring
    // narrows from 3 cm at its ends to 1 cm at its middle).
    let panel = &mesh.panels[0];
    let outline: Vec<Vec2> = panel.edges.iter().flat_map(|e| e.local[..e.local.len() - 1].iter().map(|&i| panel.points[i])).collect();
    let expected = (0..outline.len()).map(|i| outline[i].perp_dot(outline[(i + 1) % outline.len()])).sum::<f64>().abs() / 2.0;
    assert!((area - expected).abs() < 1e-6 * expected, "area {area} vs {expected}");
    assert!(mesh.vertices.len() < (3.0 * area) as usize, "{} vertices for {area} cm²", mesh.vertices.len());
    assert_eq!(properties(&mesh), Vec::<String>::new());
}

/// A skirt whose side seam is stitched in crossed pieces (sample 2337 of seed 7: the
/// front's lowest piece is stitched to the back's highest), so that merging the stitches
/// collapses a short edge onto one vertex. It meshes: the collapsed faces are dropped
/// and every other property holds.
#[test]
fn crossed_seam_pieces_mesh() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh-extra/crossed_seams_specification.json");
    let pattern = load(&path, "crossed_seams");
    let mesh = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("crossed seams mesh");
    assert_eq!(properties(&mesh), Vec::<String>::new());
    for f in &mesh.faces {
        assert!(f.vertices[0] != f.vertices[1] && f.vertices[1] != f.vertices[2] && f.vertices[0] != f.vertices[2], "a collapsed face");
    }
}

/// A resolution beyond the panels' size meshes the outlines alone (edges keep their
/// corners), with no interior points laid out at astronomical distances.
#[test]
fn a_resolution_beyond_the_garment_meshes_the_outlines() {
    let case = &mesh_cases()[0];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let pattern = load(&case.join(format!("{name}_specification.json")), &name);
    for res in [1e3, 1e300] {
        let mesh = BoxMesh::new(&pattern, res).unwrap_or_else(|e| panic!("resolution {res}: {e}"));
        assert!(mesh.panels.iter().all(|p| p.points.len() == p.n_boundary), "resolution {res}: interior points");
        assert_eq!(properties(&mesh), Vec::<String>::new(), "resolution {res}");
    }
}

#[test]
fn real_faults_are_named_errors() {
    let case = &mesh_cases()[0];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let pattern = load(&case.join(format!("{name}_specification.json")), &name);
    let mut twice = pattern.clone();
    let again = twice.stitches[0].clone();
    twice.stitches.push(again);
    let side = &pattern.stitches[0].sides[0];
    assert_eq!(
        BoxMesh::new(&twice, DEFAULT_RESOLUTION),
        Err(MeshError::StitchedTwice { panel: side.panel.clone(), edge: side.edge, first: 0, second: pattern.stitches.len() })
    );
    let mut bad = pattern.clone();
    bad.stitches[0].sides[1].edge = 99;
    assert!(matches!(BoxMesh::new(&bad, DEFAULT_RESOLUTION), Err(MeshError::MissingEdge { stitch: 0, edge: 99, .. })));
    assert!(matches!(BoxMesh::new(&pattern, 0.0), Err(MeshError::Resolution(_))));
    // Bounded memory: a resolution far too fine for the garment is refused before triangulating.
    let started = cpu_time::ThreadTime::now();
    assert!(matches!(BoxMesh::new(&pattern, 0.001), Err(MeshError::TooLarge { .. })));
    assert!(started.elapsed().as_secs() < 5);
}

#[test]
fn rest_lengths_cover_every_face_touching_a_stitch() {
    let case = &mesh_cases()[1];
    let name = case.file_name().unwrap().to_string_lossy().into_owned();
    let mesh = BoxMesh::new(&load(&case.join(format!("{name}_specification.json")), &name), DEFAULT_RESOLUTION).expect("mesh");
    let lens: HashMap<[usize; 2], f64> = mesh.rest_lengths.iter().copied().collect();
    for f in &mesh.faces {
        if f.vertices.iter().any(|&v| v < mesh.n_stitch_vertices) {
            let mut v = f.vertices;
            v.sort_unstable();
            for key in [[v[0], v[1]], [v[1], v[2]], [v[0], v[2]]] {
                let l = lens.get(&key).copied().unwrap_or(f64::NAN);
                assert!(l > 0.0 && l <= SIZE_BOUND * 2.0 * DEFAULT_RESOLUTION, "{key:?}: {l}");
            }
        }
    }
    // The pickle holds them all: 3 header bytes, 20 per item, one mark and setitems per 1000, stop.
    let bytes = mesh.rest_lengths_pickle();
    let batches = mesh.rest_lengths.len().div_ceil(1000);
    assert_eq!(bytes.len(), 3 + 20 * mesh.rest_lengths.len() + 2 * batches + 1);
    assert_eq!(&bytes[..3], &[0x80, 2, b'}']);
    assert_eq!(bytes.last(), Some(&b'.'));
}

/// A reproducer of bad input (`../tests/data/hardening`).
fn hardening(name: &str) -> Pattern {
    load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/hardening").join(name), name.trim_end_matches(".json"))
}

/// A quadratic edge bulging 900 edge lengths out (within the specification's limits)
/// hung the mesher measuring its length. It is measured and meshed in bounded time:
/// a 350 m outline around 46 m² of cloth, about 560,000 vertices at 1 cm.
#[test]
fn a_far_control_point_meshes_in_bounded_time() {
    let pattern = hardening("spec-mesh-far-control-point.json");
    // Bounded work, measured as this thread's CPU (wall time swings with the machine's
    // load): 8–9 s in the test profile, a hang before the fix.
    let started = cpu_time::ThreadTime::now();
    let mesh = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect("meshes");
    assert!(started.elapsed().as_secs() < 30, "meshed in {:?} of CPU", started.elapsed());
    assert!(mesh.vertices.len() > 500_000 && mesh.vertices.len() <= garmentcode::mesh::MAX_MESH_VERTICES, "{}", mesh.vertices.len());
    let bulge = &mesh.panels[0].edges[3];
    assert!(bulge.length > 35_000.0, "{}", bulge.length);
    assert_eq!(bulge.local.len() as f64, bulge.length.ceil() + 1.0);
    // The mesh's properties, at a resolution where checking them is quick.
    assert_eq!(properties(&BoxMesh::new(&pattern, 8.0).expect("meshes at 8 cm")), Vec::<String>::new());
}

/// What `garmentcode check` calls errors is refused before any work: a panel scaled
/// down to 1e-9 cm (its edges degenerate), a panel whose outline encloses no
/// area, a panel of two corners.
#[test]
fn structural_errors_are_refused_before_any_work() {
    for (file, kind) in [
        ("spec-mesh-tiny-panel.json", "degenerate_edge"),
        ("spec-zero-area-panel.json", "zero_area"),
        ("spec-two-vertex-panel.json", "empty_panel"),
    ] {
        let pattern = hardening(file);
        let started = cpu_time::ThreadTime::now();
        match BoxMesh::new(&pattern, DEFAULT_RESOLUTION) {
            Err(MeshError::Structural(message)) => assert!(message.contains(kind), "{file}: {message}"),
            other => panic!("{file}: expected a structural error, got {:?}", other.map(|m| m.vertices.len())),
        }
        assert!(started.elapsed().as_millis() < 500, "{file}: {:?}", started.elapsed());
    }
}

/// A 200 m square (the coordinate limit) would need 460 million vertices at 1 cm: it is
/// refused at once with the resolution that fits, not laid out (over 10 s and 1 GB).
#[test]
fn a_panel_at_the_coordinate_limit_is_refused_with_the_resolution_that_fits() {
    let pattern = hardening("spec-mesh-100m-panel.json");
    let started = cpu_time::ThreadTime::now();
    let e = BoxMesh::new(&pattern, DEFAULT_RESOLUTION).expect_err("too large");
    assert!(started.elapsed().as_millis() < 500, "{:?}", started.elapsed());
    let MeshError::TooLarge { needed, coarser, .. } = e else { panic!("{e}") };
    assert!(needed > 400_000_000, "{needed}");
    assert_eq!(coarser, 22.0);
    assert!(e.to_string().contains("mesh it at 22 cm or coarser"), "{e}");
}
