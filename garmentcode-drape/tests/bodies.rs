//! Body meshes for every body: the five built-in meshes measured back against their
//! measurement files, mannequins for other bodies measured back against theirs, and the
//! checks on a user's own body mesh.

use garmentcode::Body;
use garmentcode_drape::mannequin::{Measured, mannequin, measure};
use garmentcode_drape::{BodyError, BodyMesh};

const BODIES: [(&str, &str); 5] = [
    ("mean_all", include_str!("../data/mean_all.yaml")),
    ("mean_female", include_str!("../data/mean_female.yaml")),
    ("mean_male", include_str!("../data/mean_male.yaml")),
    ("f_smpl_average_A40", include_str!("data/f_smpl_average_A40.yaml")),
    ("m_smpl_average_A40", include_str!("data/m_smpl_average_A40.yaml")),
];

fn body(name: &str) -> Body {
    let text = BODIES.iter().find(|(n, _)| *n == name).unwrap().1;
    Body::from_yaml(text, &format!("{name}.yaml")).unwrap()
}

/// (name, measured, in the file) for the measurements [`measure`] takes.
fn pairs(m: &Measured, b: &Body) -> Vec<(&'static str, f64, f64)> {
    vec![
        ("height", m.height, b.height),
        ("bust", m.bust, b.bust),
        ("underbust", m.underbust, b.underbust),
        ("waist", m.waist, b.waist),
        ("hips", m.hips, b.hips),
        ("neck_w", m.neck_w, b.neck_w),
        ("back_width", m.back_width, b.back_width),
        ("waist_back_width", m.waist_back_width, b.waist_back_width),
        ("hip_back_width", m.hip_back_width, b.hip_back_width),
        ("arm_pose_angle", m.arm_pose_angle, b.arm_pose_angle),
        ("shoulder_w", m.shoulder_w, b.shoulder_w),
    ]
}

#[test]
fn every_built_in_body_has_its_mesh_and_measures_as_its_file() {
    for (name, _) in BODIES {
        let mesh = BodyMesh::for_body(name, &body(name)).unwrap();
        assert_eq!(mesh.name, name);
        let parts = mesh.parts().unwrap();
        assert!(parts.iter().filter(|&&p| p != 0).count() as f64 > 0.99 * parts.len() as f64, "{name}: parts");
        let m = measure(&mesh, &body(name));
        let line: Vec<String> =
            pairs(&m, &body(name)).iter().map(|(k, got, want)| format!("{k} {got:.2}/{want:.2} ({:+.2})", got - want)).collect();
        let x = mesh.self_intersections();
        let mut by_part = std::collections::BTreeMap::new();
        for (a, _) in &x {
            *by_part.entry(parts[*a as usize]).or_insert(0) += 1;
        }
        println!(
            "{name}: {} self-intersections {by_part:?} e.g. {:?}",
            x.len(),
            x.iter().take(3).map(|e| mesh.vertices[e.0 as usize]).collect::<Vec<_>>()
        );
        println!("{name}: {}; arm extent {:.2} (arm_length {:.2})", line.join(", "), m.arm_extent, body(name).arm_length);
        let b = body(name);
        if name.starts_with("mean") {
            assert!((m.height - b.height).abs() < 0.1, "{name}: height {}", m.height);
            // The girths the garments are cut to, at the levels they put them.
            for (k, got, want) in &pairs(&m, &b)[1..5] {
                assert!((got - want).abs() < 1.5, "{name}: {k} {got} vs {want}");
            }
            assert!((m.arm_pose_angle - b.arm_pose_angle).abs() < 3.0, "{name}: arm angle {}", m.arm_pose_angle);
        } else {
            // The SMPL averages' files are rounded estimates (height 165 for a 165.8 cm mesh).
            assert!((m.height - b.height).abs() < 1.5, "{name}: height {}", m.height);
        }
    }
}

/// `b` with some measurements changed.
fn edit(name: &str, changes: &[(&str, f64)]) -> Body {
    let text = BODIES.iter().find(|(n, _)| *n == name).unwrap().1;
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for (key, value) in changes {
        let at = lines.iter().position(|l| l.trim_start().starts_with(&format!("{key}:"))).unwrap();
        lines[at] = format!("  {key}: {value}");
    }
    Body::from_yaml(&lines.join("\n"), "edited.yaml").unwrap()
}

/// The mean body a mannequin was made from (the nearest by height, bust, waist, hips), and
/// its file.
fn template_of(mesh: &BodyMesh, b: &Body) -> (BodyMesh, Body) {
    let score = |t: &Body| {
        [(b.height, t.height), (b.bust, t.bust), (b.waist, t.waist), (b.hips, t.hips)]
            .iter()
            .map(|(x, y)| (x / y - 1.0).powi(2))
            .sum::<f64>()
    };
    let name = ["mean_all", "mean_female", "mean_male"].into_iter().min_by(|x, y| score(&body(x)).total_cmp(&score(&body(y)))).unwrap();
    let t = BodyMesh::builtin(name).unwrap();
    assert_eq!(t.faces, mesh.faces);
    (t, body(name))
}

/// A template mesh and its own self-crossing edges.
type Crossings = (BodyMesh, Vec<(u32, u32)>);

fn check_mannequin(label: &str, b: &Body) {
    let mesh = BodyMesh::for_body("other.yaml", b).unwrap();
    let m = measure(&mesh, b);
    let line: Vec<String> = pairs(&m, b).iter().map(|(k, got, want)| format!("{k} {:+.2}", got - want)).collect();
    println!("{label}: {}", line.join(", "));
    for (k, got, want) in pairs(&m, b).iter().filter(|(k, _, _)| ["height", "bust", "underbust", "waist", "hips", "shoulder_w"].contains(k))
    {
        assert!((got - want).abs() < 1.0, "{label}: {k} measured {got:.2}, file {want:.2}");
    }
    // The neck's back arc reads more than the reference's files; against the template's.
    let (t, tb) = template_of(&mesh, b);
    let neck = m.neck_w / measure(&t, &tb).neck_w * tb.neck_w;
    assert!((neck - b.neck_w).abs() < 1.0, "{label}: neck_w {neck:.2} (template-relative), file {:.2}", b.neck_w);
    assert!((m.arm_pose_angle - b.arm_pose_angle).abs() < 1.0, "{label}: arm angle {}", m.arm_pose_angle);
    // The reference's meshes cross themselves at the lips, between the fingers and the
    // thighs, and fold in the armpits (the few vertices their segmentation leaves out); the
    // mannequin crosses itself nowhere else (within 3 cm of those, on the template: same
    // topology).
    static TEMPLATES: std::sync::OnceLock<Vec<Crossings>> = std::sync::OnceLock::new();
    let templates = TEMPLATES.get_or_init(|| {
        ["mean_all", "mean_female", "mean_male"]
            .map(|n| {
                let t = BodyMesh::builtin(n).unwrap();
                let known = t.self_intersections();
                (t, known)
            })
            .into()
    });
    let (template, known) = templates.iter().find(|(t, _)| t.faces == mesh.faces && t.parts() == mesh.parts()).unwrap();
    let parts = mesh.parts().unwrap();
    let tparts = template.parts().unwrap();
    let near_known = |e: &(u32, u32)| {
        let p = template.vertices[e.0 as usize];
        known.iter().any(|k| (template.vertices[k.0 as usize] - p).length() < 3.0)
            || (0..tparts.len()).any(|i| tparts[i] == 0 && (template.vertices[i] - p).length() < 3.0)
    };
    let new: Vec<_> = mesh
        .self_intersections()
        .into_iter()
        .filter(|e| !near_known(e))
        .map(|e| (parts[e.0 as usize], mesh.vertices[e.0 as usize]))
        .collect();
    assert!(new.is_empty(), "{label}: the mannequin passes through itself at {} edges: {new:?}", new.len());
}

#[test]
fn mannequins_measure_as_their_files() {
    let f = body("mean_female");
    check_mannequin("female bust +10", &edit("mean_female", &[("bust", f.bust + 10.0), ("underbust", f.underbust + 8.0)]));
    check_mannequin("female waist -10 hips +10", &edit("mean_female", &[("waist", f.waist - 10.0), ("hips", f.hips + 10.0)]));
    let m = body("mean_male");
    check_mannequin("male waist +10 hips -10", &edit("mean_male", &[("waist", m.waist + 10.0), ("hips", m.hips - 10.0)]));
    check_mannequin(
        "male bust -10 arms 35°",
        &edit("mean_male", &[("bust", m.bust - 10.0), ("underbust", m.underbust - 8.0), ("arm_pose_angle", 35.0)]),
    );
}

#[test]
fn short_and_tall_mannequins_measure_as_their_files() {
    let a = body("mean_all");
    let short = 150.0 / a.height;
    let scaled = |k: f64| {
        edit(
            "mean_all",
            &[
                ("height", a.height * k),
                ("head_l", a.head_l * k),
                ("waist_line", a.waist_line * k),
                ("hips_line", a.hips_line * k),
                ("vert_bust_line", a.vert_bust_line.unwrap() * k),
                ("crotch_hip_diff", a.crotch_hip_diff * k),
                ("arm_length", a.arm_length * k),
                ("arm_pose_angle", 50.0),
            ],
        )
    };
    check_mannequin("short (150 cm)", &scaled(short));
    check_mannequin("tall (195 cm)", &scaled(195.0 / a.height));
    // T-pose and arms nearly down.
    check_mannequin("arms 0°", &edit("mean_all", &[("arm_pose_angle", 0.0)]));
    check_mannequin("arms 85°", &edit("mean_all", &[("arm_pose_angle", 85.0)]));
}

#[test]
fn mannequins_are_deterministic_and_keep_the_arm_length() {
    let b = edit("mean_all", &[("arm_length", 60.0), ("bust", 105.0)]);
    let start = std::time::Instant::now();
    let one = mannequin(&b, "a.yaml").unwrap();
    println!("one mannequin: {:.2} s", start.elapsed().as_secs_f64());
    let two = mannequin(&b, "a.yaml").unwrap();
    assert_eq!(one.vertices, two.vertices);
    assert_eq!(one.parts(), two.parts());
    // Arm extent scales as the file's arm length (the template measures as its file).
    let template = measure(&BodyMesh::builtin("mean_all").unwrap(), &body("mean_all"));
    let arm = measure(&one, &b).arm_extent / template.arm_extent * body("mean_all").arm_length;
    assert!((arm - 60.0).abs() < 1.0, "arm length {arm}");
}

#[test]
fn mannequins_of_levels_out_of_order_or_arms_down_are_refused() {
    let bad = edit("mean_all", &[("hips_line", 44.0), ("crotch_hip_diff", 34.0), ("waist_line", 69.0)]);
    let err = BodyMesh::for_body("low.yaml", &bad).unwrap_err();
    assert!(err.to_string().starts_with("low.yaml: cannot make a mannequin: the crotch level"), "{err}");
    let down = BodyMesh::for_body("down.yaml", &edit("mean_all", &[("arm_pose_angle", 90.0)])).unwrap_err();
    assert!(down.to_string().starts_with("down.yaml: cannot make a mannequin: arm_pose_angle 90 is outside 0..85 degrees"), "{down}");
}

#[test]
fn user_body_meshes_in_wrong_units_or_huge_are_refused() {
    let dir = std::env::temp_dir().join(format!("gc-bodies-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Millimetres: 1720 "metres" tall.
    let mm = dir.join("mm.obj");
    std::fs::write(&mm, "v 0 0 0\nv 1720 0 0\nv 0 1720 0\nv 0 0 1720\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n").unwrap();
    let err = BodyMesh::load(&mm).unwrap_err();
    assert!(matches!(err, BodyError::Height { .. }) && err.to_string().contains("mm.obj: body height 172000.000 cm"), "{err}");
    // Larger than any body file (a sparse file: nothing is written).
    let huge = dir.join("huge.obj");
    std::fs::File::create(&huge).unwrap().set_len(garmentcode_drape::body::MAX_FILE_BYTES + 1).unwrap();
    let err = BodyMesh::load(&huge).unwrap_err();
    assert!(matches!(err, BodyError::TooLarge { .. }) && err.to_string().starts_with(&format!("{}: file of", huge.display())), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mannequins_of_the_smpl_files_and_of_large_and_slim_bodies() {
    // The SMPL averages' files as any other body file (their arm_length of 80 cm included).
    check_mannequin("f_smpl file", &body("f_smpl_average_A40"));
    check_mannequin("m_smpl file", &body("m_smpl_average_A40"));
    check_mannequin("large", &edit("mean_female", &[("bust", 130.0), ("underbust", 112.0), ("waist", 118.0), ("hips", 135.0)]));
    check_mannequin(
        "slim",
        &edit("mean_male", &[("bust", 84.0), ("underbust", 76.0), ("waist", 66.0), ("hips", 86.0), ("shoulder_w", 35.0)]),
    );
}

#[test]
fn smpl_segmentations_are_grouped_into_body_parts() {
    let tetra = "v 0 0 0\nv 1 0 0\nv 0 1.7 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    let body = BodyMesh::from_obj(tetra, "t.obj").unwrap();
    let seg = r#"{"leftForeArm": [0], "rightHandIndex1": [1], "spine2": [2], "rightToeBase": [3], "unknown": [0, 1]}"#;
    let body = body.with_parts_json(seg, "seg.json").unwrap();
    let bit = |name: &str| 1u8 << garmentcode_drape::body::PARTS.iter().position(|p| *p == name).unwrap();
    assert_eq!(body.parts().unwrap(), [bit("left_arm"), bit("right_arm"), bit("body"), bit("right_leg")]);
    let bad = BodyMesh::from_obj(tetra, "t.obj").unwrap().with_parts_json(r#"{"leftArm": [9]}"#, "seg.json").unwrap_err();
    assert_eq!(bad.to_string(), "seg.json:1: part 'leftArm': 9 is not a vertex id (0..4)");
}

/// Plausible bodies drawn around the three mean bodies (a fixed pseudo-random sequence):
/// height ±12 %, bust, waist and hips −12 to +15 cm, shoulders ±3 cm, neck ±2 cm, arm length
/// ±10 %, arms at 30° to 60°.
#[test]
fn drawn_plausible_mannequins_measure_as_their_files() {
    let mut seed = 12345u64;
    let mut draw = |lo: f64, hi: f64| {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((seed >> 11) as f64 / (1u64 << 53) as f64)
    };
    for k in 0..6 {
        let base = ["mean_all", "mean_female", "mean_male"][k % 3];
        let a = body(base);
        let h = draw(0.88, 1.12);
        let b = edit(
            base,
            &[
                ("height", a.height * h),
                ("head_l", a.head_l * h),
                ("waist_line", a.waist_line * h),
                ("hips_line", a.hips_line * h),
                ("vert_bust_line", a.vert_bust_line.unwrap() * h),
                ("crotch_hip_diff", a.crotch_hip_diff * h),
                ("arm_length", a.arm_length * draw(0.9, 1.1)),
                ("bust", a.bust + draw(-12.0, 15.0)),
                ("waist", a.waist + draw(-12.0, 15.0)),
                ("hips", a.hips + draw(-12.0, 15.0)),
                ("shoulder_w", a.shoulder_w + draw(-3.0, 3.0)),
                ("arm_pose_angle", draw(30.0, 60.0)),
                ("neck_w", a.neck_w + draw(-2.0, 2.0)),
            ],
        );
        check_mannequin(&format!("drawn {k} ({base})"), &b);
    }
}
