//! Drapes of reference patterns on the built-in `mean_all` body, checked as the reference's
//! drape judge (`judge_drape.py`) checks them, and against figures of the reference's own
//! drapes of the same patterns (its simulator on the same body).

use garmentcode::Vec3;
use garmentcode::mesh::{BoxMesh, VertexLabel};
use garmentcode_drape::{BodyError, BodyMesh, Drape, DrapeError, Next, Settings, Strain, drape, drape_with_progress, sim_obj};

const MEAN_ALL: &str = include_str!("data/mean_all.yaml");

fn box_mesh(spec: &str) -> (garmentcode::Pattern, BoxMesh) {
    let pattern = garmentcode::Pattern::from_json(spec).unwrap();
    let mesh = BoxMesh::new(&pattern, 1.0).unwrap();
    (pattern, mesh)
}

fn settings(pattern: &garmentcode::Pattern) -> Settings {
    let body = garmentcode::Body::from_yaml(MEAN_ALL, "mean_all.yaml").unwrap();
    Settings::for_body(&body).with_panel_labels(pattern)
}

/// The judge's physical checks: finite, at most 0.2 % of vertices deeper than 0.2 cm in the
/// body, p99 strain of seam edges ≤ 20 % and of the others ≤ 8 %, at most `crossings`
/// edges crossing the garment (the judge allows none), the top within 10 cm of the box mesh's.
fn assert_physical(mesh: &BoxMesh, body: &BodyMesh, result: &Drape, crossings: usize) {
    let x = &result.positions;
    assert_eq!(x.len(), mesh.vertices.len());
    assert!(x.iter().all(|p| p.is_finite()));
    let deep = x.iter().filter(|p| body.signed_distance(**p) < -0.2).count();
    assert!(deep as f64 <= 0.002 * x.len() as f64, "{deep} vertices deeper than 0.2 cm inside the body");
    let strain = Strain::of(mesh, x);
    let (seam99, other99) = (strain.seam_p99, strain.fabric_p99);
    assert!(seam99 <= 0.20, "seams not closed: p99 strain {seam99}");
    assert!(other99 <= 0.08, "stretched: p99 strain {other99}");
    assert!(result.stats.self_intersections <= crossings, "{} edges cross the garment", result.stats.self_intersections);
    let top = |v: &[Vec3]| v.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    assert!(top(&mesh.vertices) - top(x) <= 10.0, "the garment fell");
}

/// Lowest point and panel centroids within `tol` cm of the reference drape's.
fn assert_near_reference(mesh: &BoxMesh, result: &Drape, lowest: f64, centroids: &[(&str, [f64; 3])], tol: f64) {
    let low = result.positions.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    assert!((low - lowest).abs() <= tol, "lowest point {low} cm, the reference's {lowest}");
    for (name, expected) in centroids {
        let p = mesh.panels.iter().position(|p| p.name == *name).unwrap();
        let ids: Vec<usize> = (0..mesh.labels.len()).filter(|&v| mesh.labels[v] == VertexLabel::Panel(p)).collect();
        let c = ids.iter().map(|&v| result.positions[v]).sum::<Vec3>() / ids.len() as f64;
        let d = (c - Vec3::from_array(*expected)).length();
        assert!(d <= tol, "panel {name}: centroid {c} is {d} cm from the reference's");
    }
}

#[test]
fn waistband_drapes_onto_the_waist_like_the_reference() {
    let (pattern, mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let body = BodyMesh::builtin("mean_all").unwrap();
    let result = drape(&mesh, &body, &settings(&pattern)).unwrap();
    // The reference stops at the first frame the static rule may run (400 attached + 5).
    assert_eq!(result.stats.frames, 406, "{:?}", result.stats);
    assert!(result.stats.converged);
    assert_eq!(result.stats.body_penetrations, 0);
    assert_physical(&mesh, &body, &result, 0);
    // The reference's drape (case-001): lowest point 104.23 cm; panel centroids.
    assert_near_reference(&mesh, &result, 104.23, &[("wb_back", [0.62, 107.18, -7.42]), ("wb_front", [-0.03, 106.91, 8.95])], 0.5);
}

#[test]
fn attached_drapes_stop_five_frames_after_the_release_as_the_reference_on_cpu_does() {
    let (pattern, mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let body = BodyMesh::builtin("mean_all").unwrap();
    // Released after 12 frames, while the seams still close: most vertices move.
    let s = Settings { attachment_frames: 12, max_frames: 24, ..settings(&pattern) };
    let stopped = drape(&mesh, &body, &s).unwrap();
    assert_eq!(stopped.stats.frames, 18, "{:?}", stopped.stats);
    assert!(stopped.stats.converged && !stopped.stats.at_rest, "{:?}", stopped.stats);
    let moving = stopped.stats.non_static_vertices;
    assert!(moving as f64 > 0.015 * mesh.vertices.len() as f64, "{moving} vertices moving: the static rule would have stopped it too");
    // Without the stop (or without attachments) only the static rule and the frame limit stop it.
    for run_on in [Settings { stop_at_release: false, ..s.clone() }, Settings { attachments: Vec::new(), ..s.clone() }] {
        let result = drape(&mesh, &body, &run_on).unwrap();
        assert_eq!((result.stats.frames, result.stats.converged, result.stats.at_rest), (24, false, false), "{:?}", result.stats);
    }
}

/// The waistband's box mesh with the front vertex nearest the middle of the front (z = 20 cm)
/// pulled behind the back panel (z = -15 cm): its edges cross the back, and through the body
/// too, so the crossing is not undone within 30 frames.
fn crossed_waistband() -> (garmentcode::Pattern, BoxMesh) {
    let (pattern, mut mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let middle = Vec3::new(0.0, 107.0, 20.0);
    let i = (0..mesh.vertices.len())
        .min_by(|&a, &b| (mesh.vertices[a] - middle).length().total_cmp(&(mesh.vertices[b] - middle).length()))
        .unwrap();
    mesh.vertices[i].z = -18.0;
    assert!(!garmentcode_drape::crossing_edges(&mesh, &mesh.vertices).is_empty());
    (pattern, mesh)
}

#[test]
fn a_drape_still_crossing_itself_at_the_release_goes_on_until_untangled() {
    let (pattern, mesh) = crossed_waistband();
    let body = BodyMesh::builtin("mean_all").unwrap();
    let s = Settings { attachment_frames: 12, max_frames: 30, ..settings(&pattern) };
    let result = drape(&mesh, &body, &s).unwrap();
    // Not at frame 18 (the release's stop): through the body too, this one is not undone
    // by frame 30, the limit. (rand_0000003 of the sampled designs, undone: docs/drape.md.)
    assert!(result.stats.self_intersections > 0, "{:?}", result.stats);
    assert_eq!((result.stats.frames, result.stats.converged), (30, false), "{:?}", result.stats);
    // Untangled (the box mesh as it is), it stops at the release.
    let (_, clean) = box_mesh(include_str!("data/waistband_specification.json"));
    assert_eq!(drape(&clean, &body, &s).unwrap().stats.frames, 18);
}

#[test]
fn a_drape_still_crossed_after_its_untangle_frames_returns_its_least_crossed_frame() {
    let (pattern, mesh) = crossed_waistband();
    let body = BodyMesh::builtin("mean_all").unwrap();
    // Released after 12 frames: the release's stop is frame 17, the window ends at frame 37.
    let s = Settings { attachment_frames: 12, max_frames: 60, untangle_frames: 20, ..settings(&pattern) };
    // crossings[i]: edges crossing at the start of frame i, that is after i frames.
    let mut crossings = Vec::new();
    let result = drape_with_progress(&mesh, &body, &s, |progress| {
        crossings.push(progress.crossings);
        Next::Continue
    })
    .unwrap();
    // Frame 37 was not simulated: the run stopped at its start.
    assert_eq!(crossings.len(), 37, "{:?}", result.stats);
    let (frames, window) = (result.stats.frames, &crossings[17..]);
    assert!(window.iter().all(|&c| c > 0), "{window:?}: undone within the window");
    assert!((17..37).contains(&frames) && !result.stats.converged, "{:?}", result.stats);
    // The first frame with the fewest crossings, and fewer than at the window's end (the
    // count grows from 7 to 11 here as the garment settles crossed).
    let least = *window.iter().min().unwrap();
    assert_eq!(crossings[frames], least, "{window:?}, returned after {frames} frames");
    assert!(crossings[17..frames].iter().all(|&c| c > least), "{window:?}: not the first least");
    assert!(least < crossings[36], "{window:?}");
    // The positions are those of the same drape stopped after that many frames by its limit.
    let stopped = drape(&mesh, &body, &Settings { max_frames: frames, ..s.clone() }).unwrap();
    assert_eq!(stopped.positions, result.positions);
    assert_eq!(stopped.stats.non_static_vertices, result.stats.non_static_vertices);
    // With no window, it stops at the release's frame, crossed.
    let at_release = drape(&mesh, &body, &Settings { untangle_frames: 0, ..s.clone() }).unwrap();
    assert_eq!((at_release.stats.frames, at_release.stats.converged), (17, false), "{:?}", at_release.stats);
}

#[test]
fn same_inputs_give_the_same_bytes_whatever_the_threads() {
    let (pattern, mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let body = BodyMesh::builtin("mean_all").unwrap();
    let settings = |threads| Settings { max_frames: 40, threads, ..settings(&pattern) };
    let a = drape(&mesh, &body, &settings(1)).unwrap();
    assert_eq!(a.stats.frames, 40);
    assert!(!a.stats.converged);
    for threads in [1, 2, 3] {
        let b = drape(&mesh, &body, &settings(threads)).unwrap();
        assert_eq!(sim_obj(&mesh, &a.positions), sim_obj(&mesh, &b.positions), "{threads} threads");
        assert_eq!((a.stats.self_intersections, a.stats.body_penetrations), (b.stats.self_intersections, b.stats.body_penetrations));
    }
    // The garment moved: the seams pulled in.
    assert_ne!(a.positions, mesh.vertices);
}

#[test]
fn the_sim_obj_keeps_the_box_mesh_lines_but_the_vertices() {
    let (_, mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let moved: Vec<Vec3> = mesh.vertices.iter().map(|v| *v + Vec3::Y).collect();
    let (obj, sim) = (mesh.obj(), sim_obj(&mesh, &moved));
    let not_v = |s: &str| s.lines().filter(|l| !l.starts_with("v ")).map(str::to_string).collect::<Vec<_>>();
    assert_eq!(not_v(&obj), not_v(&sim));
    let read = garmentcode::mesh::obj::ObjMesh::parse(&sim, Default::default()).unwrap();
    assert_eq!(read.vertices, moved);
    assert_eq!(read.triangles, mesh.faces.iter().map(|f| f.vertices).collect::<Vec<_>>());
}

#[test]
fn settings_out_of_range_are_refused_with_their_name_and_range() {
    let (pattern, mesh) = box_mesh(include_str!("data/waistband_specification.json"));
    let body = BodyMesh::builtin("mean_all").unwrap();
    let err = drape(&mesh, &body, &Settings { max_frames: 0, ..settings(&pattern) }).unwrap_err();
    assert!(matches!(&err, DrapeError::Setting { parameter, .. } if parameter == "max_frames"), "{err}");
    assert!(err.to_string().contains("1..=100000"), "{err}");
    let err = drape(&mesh, &body, &Settings { spring_ke: f64::NAN, ..settings(&pattern) }).unwrap_err();
    assert!(err.to_string().contains("spring_ke"), "{err}");
    let err = drape(&mesh, &body, &Settings { threads: 1000, ..settings(&pattern) }).unwrap_err();
    assert!(err.to_string().contains("threads = 1000: must be an integer in 0..=256"), "{err}");
    let err = drape(&mesh, &body, &Settings { untangle_frames: 100_001, ..settings(&pattern) }).unwrap_err();
    assert!(err.to_string().contains("untangle_frames = 100001: must be an integer in 0..=100000"), "{err}");
    let mut bad = settings(&pattern);
    bad.attachments[0].normal = Vec3::new(0.0, 2.0, 0.0);
    let err = drape(&mesh, &body, &bad).unwrap_err();
    assert!(err.to_string().contains("attachments[0] (lower_interface).normal"), "{err}");
}

/// A closed tetrahedron-like box, `h` metres high, as OBJ text.
fn box_obj(h: f64, drop_last_face: bool) -> String {
    let mut s = String::new();
    for (x, y, z) in [(0., 0., 0.), (1., 0., 0.), (1., 1., 0.), (0., 1., 0.), (0., 0., 1.), (1., 0., 1.), (1., 1., 1.), (0., 1., 1.)] {
        s += &format!("v {} {} {}\n", x * 0.3, y * h, z * 0.2);
    }
    let quads = ["1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"];
    for q in &quads[..if drop_last_face { 5 } else { 6 }] {
        s += &format!("f {q}\n");
    }
    s
}

#[test]
fn body_meshes_are_checked() {
    let ok = BodyMesh::from_obj(&box_obj(1.7, false), "box.obj").unwrap();
    assert_eq!(ok.faces.len(), 12);
    assert!((ok.bounds().1.y - 170.0).abs() < 1e-9, "metres are scaled to cm");
    assert!(ok.signed_distance(Vec3::new(15.0, 85.0, 10.0)) < -9.9);
    assert!((ok.signed_distance(Vec3::new(15.0, 85.0, 25.0)) - 5.0).abs() < 1e-9);

    let open = BodyMesh::from_obj(&box_obj(1.7, true), "open.obj").unwrap_err();
    assert!(matches!(open, BodyError::NotClosed { .. }), "{open}");
    assert!(open.to_string().starts_with("open.obj: the body mesh must be a closed surface: 4 edge(s)"), "{open}");

    let cm = BodyMesh::from_obj(&box_obj(170.0, false), "cm.obj").unwrap_err();
    assert!(cm.to_string().contains("cm.obj: body height 17000.000 cm") && cm.to_string().contains("in metres"), "{cm}");

    let nan = BodyMesh::from_obj("v 0 nan 0\n", "nan.obj").unwrap_err();
    assert_eq!(nan.to_string(), r#"nan.obj:1: vertex coordinate "nan" is not finite"#);
    let index = BodyMesh::from_obj("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "idx.obj").unwrap_err();
    assert_eq!(index.to_string(), r#"idx.obj:3: face index "3" names no vertex (there are 2 so far)"#);
    let missing = BodyMesh::load("no/such/body.obj".as_ref()).unwrap_err();
    assert!(missing.to_string().starts_with("no/such/body.obj: cannot read the body mesh"), "{missing}");
    let unknown = BodyMesh::builtin("mean_alll").unwrap_err();
    assert!(unknown.to_string().contains("built in: mean_all"), "{unknown}");
}

#[test]
fn the_built_in_body_is_the_reference_mean_all_with_its_parts() {
    let body = BodyMesh::builtin("mean_all").unwrap();
    assert_eq!((body.vertices.len(), body.faces.len()), (23_752, 47_500));
    let (lo, hi) = body.bounds();
    assert!((lo.y - 0.0).abs() < 0.01 && (hi.y - 171.99).abs() < 0.01, "{lo} {hi}");
    let parts = body.parts().unwrap();
    // 17 vertices are in no part; the others in exactly one.
    assert_eq!(parts.iter().filter(|&&p| p == 0).count(), 17);
    assert!(parts.iter().all(|p| p.count_ones() <= 1));
    // Packing again gives the same bytes.
    let again = BodyMesh::from_packed(&body.to_packed().unwrap(), "again").unwrap();
    assert_eq!(again.to_packed().unwrap(), body.to_packed().unwrap());
    let cut = BodyMesh::from_packed(&body.to_packed().unwrap()[..1000], "cut.body").unwrap_err();
    assert!(cut.to_string().contains("cut.body") && cut.to_string().contains("length"), "{cut}");
}

/// The t-shirt (7,000 vertices) takes about a minute in release, far longer in the dev
/// profile: `cargo test --release -p garmentcode-drape --test drape -- --ignored`.
/// No edge ends crossing the garment (the judge allows none): with the box mesh's
/// interior a regular lattice, the front panels folded through themselves along its
/// lines (3 to 41 crossing edges, see docs/drape.md); its irregular interior drapes clean.
#[test]
#[ignore]
fn t_shirt_drapes_like_the_reference() {
    let (pattern, mesh) = box_mesh(include_str!("data/t-shirt_specification.json"));
    let body = BodyMesh::builtin("mean_all").unwrap();
    let result = drape(&mesh, &body, &settings(&pattern)).unwrap();
    assert!(result.stats.converged, "{:?}", result.stats);
    assert_eq!(result.stats.body_penetrations, 0);
    assert_physical(&mesh, &body, &result, 0);
    // The reference's drape: lowest point 99.94 cm; panel centroids.
    let centroids = [
        ("left_btorso", [9.86, 121.62, -10.60]),
        ("left_ftorso", [11.33, 118.68, 7.87]),
        ("left_sleeve_b", [25.15, 130.60, -6.03]),
        ("left_sleeve_f", [24.71, 130.05, 1.49]),
        ("right_btorso", [-9.73, 121.61, -10.44]),
        ("right_ftorso", [-10.70, 118.61, 8.12]),
        ("right_sleeve_b", [-25.16, 130.34, -4.74]),
        ("right_sleeve_f", [-24.38, 129.61, 2.34]),
    ];
    assert_near_reference(&mesh, &result, 99.94, &centroids, 3.0);
}
