//! The API without sockets: requests in, responses out.

use super::*;

fn request(method: &str, path: &str, body: &str) -> Request {
    Request {
        method: method.into(),
        path: path.into(),
        headers: vec![("content-type".into(), "application/json".into())],
        body: body.as_bytes().to_vec(),
    }
}

/// Status and JSON body of a request.
fn call(method: &str, path: &str, body: &str) -> (u16, Json) {
    let r = route(&request(method, path, body));
    let v = if r.content_type.starts_with("application/json") {
        serde_json::from_slice(&r.body).unwrap_or_else(|e| panic!("{method} {path}: response is not JSON: {e}"))
    } else {
        Json::Null
    };
    (r.status, v)
}

fn post(path: &str, body: Json) -> (u16, Json) {
    call("POST", path, &body.to_string())
}

#[test]
fn schema_lists_every_parameter_with_its_range_and_group() {
    let (status, s) = call("GET", "/api/schema", "");
    assert_eq!(status, 200);
    let params = s["params"].as_array().unwrap();
    assert_eq!(params.len(), space().params().len());
    assert!(params.len() > 100);
    let find = |p: &str| params.iter().find(|x| x["path"] == p).unwrap_or_else(|| panic!("{p}"));
    let length = find("shirt.length");
    assert_eq!(length["type"], "float");
    assert_eq!(length["group"], "shirt");
    assert_eq!(length["name"], "length");
    assert_eq!(length["range"], json!([0.5, 3.5]));
    assert!(!length["description"].as_str().unwrap().is_empty());
    let cuff = find("sleeve.cuff.type");
    assert_eq!(cuff["group"], "sleeve.cuff");
    assert_eq!(cuff["type"], "select_null");
    assert!(cuff["options"].as_array().unwrap().contains(&Json::Null));
    assert_eq!(find("collar.fc_angle")["range"], json!([70, 110]), "int ranges are integers");
    // Groups in document order, meta first, nested ones after their parent.
    let groups: Vec<&str> = s["groups"].as_array().unwrap().iter().map(|g| g.as_str().unwrap()).collect();
    assert_eq!(groups[0], "meta");
    let pos = |g: &str| groups.iter().position(|x| *x == g).unwrap();
    assert!(pos("sleeve") < pos("sleeve.cuff"));
    assert!(s["bodies"].as_array().unwrap().iter().any(|b| b == "mean_all"));
    assert!(s["designs"].as_array().unwrap().iter().any(|d| d["name"] == "t-shirt"));
    assert_eq!(s["measurements"].as_array().unwrap().len(), 26);
    assert!(s["derived"].as_array().unwrap().iter().all(|d| d["name"].as_str().unwrap().starts_with('_')));
}

#[test]
fn the_page_and_its_files_are_served() {
    for (path, ty) in [
        ("/", "text/html"),
        ("/app.js", "text/javascript"),
        ("/view3d.js", "text/javascript"),
        ("/drape.js", "text/javascript"),
        ("/vendor/three.module.min.js", "text/javascript"),
        ("/vendor/OrbitControls.js", "text/javascript"),
        ("/style.css", "text/css"),
        ("/icon.svg", "image/svg+xml"),
    ] {
        let r = route(&request("GET", path, ""));
        assert_eq!(r.status, 200, "{path}");
        assert!(r.content_type.starts_with(ty), "{path}: {}", r.content_type);
        assert!(!r.body.is_empty());
    }
    // Offline: nothing is loaded from elsewhere.
    for path in ["/", "/app.js", "/view3d.js", "/drape.js", "/vendor/OrbitControls.js", "/style.css"] {
        let text = String::from_utf8(route(&request("GET", path, "")).body).unwrap();
        assert!(!text.contains("http://") && !text.contains("https://") && !text.contains("//cdn"), "{path} loads nothing external");
    }
    // three.js is served from here: the page's import map and the drape view name these paths.
    let page = String::from_utf8(route(&request("GET", "/", "")).body).unwrap();
    assert!(page.contains(r#""three": "/vendor/three.module.min.js""#));
    let three = String::from_utf8(route(&request("GET", "/vendor/three.module.min.js", "")).body).unwrap();
    assert!(three.contains("SPDX-License-Identifier: MIT") && !three.contains("import "), "one self-contained module");
}

#[test]
fn pattern_of_a_design_on_a_body() {
    let (status, r) = post(
        "/api/pattern",
        json!({ "design": { "meta.upper": "Shirt", "sleeve.sleeveless": false }, "body": "mean_female", "name": "tee" }),
    );
    assert_eq!(status, 200);
    assert_eq!(r["ok"], true, "{r}");
    assert_eq!(r["name"], "tee");
    assert!(r["svg"].as_str().unwrap().starts_with("<?xml"));
    assert!(r["svg"].as_str().unwrap().contains("right_ftorso"), "panel names are drawn");
    assert!(r["specification"]["pattern"]["panels"].get("right_ftorso").is_some());
    assert_eq!(r["specification"]["properties"]["units_in_meter"], 100);
    assert_eq!(r["warnings"], json!([]));
    assert_eq!(r["checks"]["self_intersecting"], false);
    assert_eq!(r["body"]["name"], "mean_female");
    assert!(r["body"]["derived"]["_waist_level"].as_f64().unwrap() > 50.0);
    // The same garment as the library builds directly, byte for byte.
    let design = garments::builtin::design("t-shirt").unwrap();
    let body = garments::builtin::body("mean_female").unwrap();
    let direct = garments::build::build(&design, &body, "tee").unwrap().pattern.to_json().unwrap();
    let text =
        pattern_text(&json!({ "design": { "meta.upper": "Shirt", "sleeve.sleeveless": false }, "body": "mean_female", "name": "tee" }))
            .unwrap();
    assert!(text.ends_with(&format!("\"specification\":{direct}}}")));
}

#[test]
fn responses_are_deterministic() {
    let req = json!({ "design": { "meta.bottom": "SkirtCircle", "meta.upper": "FittedShirt" } }).to_string();
    let a = route(&request("POST", "/api/pattern", &req));
    let b = route(&request("POST", "/api/pattern", &req));
    assert_eq!(a, b);
}

#[test]
fn design_file_text_is_accepted() {
    let text = "design:\n  meta:\n    bottom:\n      v: Pants\n  pants:\n    length:\n      v: 0.8\n";
    let (status, r) = post("/api/pattern", json!({ "design": text }));
    assert_eq!(status, 200);
    assert_eq!(r["ok"], true, "{r}");
    assert!(r["panels"].as_array().unwrap().iter().any(|p| p.as_str().unwrap().contains("pant")), "{}", r["panels"]);
    // And read into values for the page's controls.
    let (status, d) = post("/api/design", json!({ "design": text }));
    assert_eq!(status, 200);
    assert_eq!(d["design"]["meta.bottom"], "Pants");
    assert_eq!(d["design"]["pants.length"], 0.8);
    assert_eq!(d["design"]["shirt.length"], 1.2, "others take their defaults");
}

#[test]
fn values_outside_ranges_are_refused_with_path_and_range() {
    let (status, r) = post("/api/pattern", json!({ "design": { "shirt.length": 9.0 } }));
    assert_eq!(status, 400);
    let e = r["error"].as_str().unwrap();
    assert!(e.contains("design.shirt.length") && e.contains("[0.5, 3.5]"), "{e}");
    let (status, r) =
        post("/api/pattern", json!({ "design": { "meta.upper": "Cape", "collar.fc_angle": 90.5, "nope.x": 1, "pants.length": [1] } }));
    assert_eq!(status, 400);
    let problems: Vec<&str> = r["problems"].as_array().unwrap().iter().map(|p| p.as_str().unwrap()).collect();
    assert_eq!(problems.len(), 4, "{problems:?}");
    assert!(problems.iter().any(|p| p.contains("design.meta.upper") && p.contains("FittedShirt")));
    assert!(problems.iter().any(|p| p.contains("design.collar.fc_angle") && p.contains("integer")));
    assert!(problems.iter().any(|p| p.contains("design.nope.x") && p.contains("unknown parameter")));
    assert!(problems.iter().any(|p| p.contains("design.pants.length") && p.contains("array")));
    // In a design file too, with the line.
    let (status, r) = post("/api/design", json!({ "design": "design:\n  shirt:\n    width:\n      v: 2.0\n" }));
    assert_eq!(status, 400);
    let e = r["error"].as_str().unwrap();
    assert!(e.contains("design.shirt.width") && e.contains("[1.0, 1.3]") && e.contains("line 4"), "{e}");
}

#[test]
fn a_design_the_library_refuses_is_explained() {
    let (status, r) = post("/api/pattern", json!({ "design": {} }));
    assert_eq!(status, 200);
    assert_eq!(r["ok"], false);
    assert!(r["error"].as_str().unwrap().contains("empty garment"), "{r}");
    assert!(r.get("svg").is_none());
}

#[test]
fn warnings_of_the_reference_checks_are_reported() {
    // A shirt longer than the body: too long for the floor (a short body whose
    // torso keeps the neutral body's lengths, which would otherwise follow the height).
    let torso = json!({ "height": 120.0, "head_l": 26.3262, "waist_line": 36.8913, "hips_line": 23.4837, "crotch_hip_diff": 8.81363 });
    let (status, r) =
        post("/api/pattern", json!({ "design": { "meta.upper": "Shirt", "shirt.length": 3.5 }, "body": { "measurements": torso } }));
    assert_eq!(status, 200);
    assert_eq!(r["ok"], true, "{r}");
    let w: Vec<&str> = r["warnings"].as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
    assert!(w.iter().any(|x| x.contains("too long")), "{w:?}");
    assert_eq!(r["checks"]["total_length_ok"], false);
}

#[test]
fn bodies_by_name_file_or_measurements() {
    let (status, b) = call("GET", "/api/body/mean_male", "");
    assert_eq!(status, 200);
    assert!(b["measurements"]["height"].as_f64().unwrap() > 150.0);
    assert!(b["derived"]["_leg_length"].is_number());
    assert_eq!(call("GET", "/api/body/nobody", "").0, 404);
    // Measurements over a base body.
    let (status, b) = post("/api/body", json!({ "body": { "base": "mean_all", "measurements": { "waist": 70.0, "_waist_level": 1.0 } } }));
    assert_eq!(status, 200);
    assert_eq!(b["measurements"]["waist"], 70.0);
    // A body file may do the same (`base` in its `body:` mapping).
    let (status, b) = post("/api/body", json!({ "body": { "yaml": "body:\n  base: mean_female\n  waist: 71.0\n" } }));
    assert_eq!(status, 200, "{b}");
    assert_eq!(b["measurements"]["waist"], 71.0);
    let female = garments::builtin::body("mean_female").unwrap();
    assert_eq!(b["measurements"]["height"], female.height);
    // An unknown base is named, with a suggestion.
    let (status, r) = post("/api/body", json!({ "body": { "base": "mean_femal", "measurements": { "waist": 70.0 } } }));
    assert_eq!(status, 400);
    assert!(r["error"].as_str().unwrap().contains("body.base: no built-in body `mean_femal` (did you mean `mean_female`?)"), "{r}");
    // A body file.
    let file = garments::builtin::BODIES[1].1;
    let (status, b) = post("/api/body", json!({ "body": { "yaml": file } }));
    assert_eq!(status, 200, "{b}");
    // Bad measurements name the measurement.
    let (status, r) = post("/api/body", json!({ "body": { "measurements": { "waist": -3, "wings": 2, "height": "tall" } } }));
    assert_eq!(status, 400);
    let e = r["error"].as_str().unwrap();
    assert!(e.contains("body.waist") && e.contains("plausible range") && e.contains("body.wings") && e.contains("body.height"), "{e}");
    let (status, r) = post("/api/body", json!({ "body": { "yaml": "body:\n  waist: 3\n" } }));
    assert_eq!(status, 400);
    assert!(r["error"].as_str().unwrap().contains("missing measurement"), "{r}");
    assert_eq!(post("/api/pattern", json!({ "body": "nobody" })).0, 400);
    assert_eq!(post("/api/pattern", json!({ "body": 3 })).0, 400);
    assert_eq!(post("/api/pattern", json!({ "body": { "base": "mean_all", "shape": "round" } })).0, 400);
}

#[test]
fn built_in_designs_load_and_build() {
    for (name, _) in garments::builtin::DESIGNS {
        let (status, d) = call("GET", &format!("/api/design/{name}"), "");
        assert_eq!(status, 200, "{name}");
        let (status, r) = post("/api/pattern", json!({ "design": d["design"], "name": name }));
        assert_eq!(status, 200);
        assert_eq!(r["ok"], true, "{name}: {r}");
    }
    assert_eq!(call("GET", "/api/design/cape", "").0, 404);
}

#[test]
fn random_designs_come_from_the_sampler_and_are_reproducible() {
    let (status, a) = post("/api/random", json!({ "seed": 7 }));
    assert_eq!(status, 200);
    assert_eq!(a["ok"], true, "{a}");
    let (_, b) = post("/api/random", json!({ "seed": 7 }));
    assert_eq!(a, b);
    let (_, c) = post("/api/random", json!({ "seed": 8 }));
    assert_ne!(a["design"], c["design"]);
    // The design is sample 0 of the dataset sampler for this seed and body.
    let dataset = garments::sample::DatasetSampler::with_defaults(7);
    let garments::sample::Outcome::Accepted(sample) = dataset.draw(0) else { panic!("sample 0 of seed 7 is accepted") };
    assert_eq!(a["draw"], sample.attempt);
    assert_eq!(a["design"], values_json(&design_to_values(&sample.design)));
    // And it builds.
    let (_, r) = post("/api/pattern", json!({ "design": a["design"] }));
    assert_eq!(r["ok"], true);
    assert_eq!(post("/api/random", json!({ "seed": -1 })).0, 400);
    assert_eq!(post("/api/random", json!({ "seed": "x" })).0, 400);
}

#[test]
fn files_and_zip_hold_every_file() {
    let req = json!({ "design": { "meta.upper": "Shirt" }, "name": "top" });
    let (status, f) = post("/api/files", req.clone());
    assert_eq!(status, 200);
    for name in ["design_params.yaml", "body_measurements.yaml", "specification.json", "pattern.svg", "checks.json"] {
        assert!(f["files"][name].as_str().is_some_and(|t| !t.is_empty()), "{name}");
    }
    // The design file reads back to the same design.
    let (_, d) = post("/api/design", json!({ "design": f["files"]["design_params.yaml"] }));
    assert_eq!(d["design"]["meta.upper"], "Shirt");
    let r = route(&request("POST", "/api/zip", &req.to_string()));
    assert_eq!(r.status, 200);
    assert_eq!(r.content_type, "application/zip");
    assert!(r.headers.iter().any(|(n, v)| *n == "Content-Disposition" && v.contains("top.zip")));
    let entries = zip::read_stored(&r.body).unwrap();
    let names: Vec<&str> = entries.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names[..5],
        ["top/design_params.yaml", "top/body_measurements.yaml", "top/specification.json", "top/pattern.svg", "top/checks.json"]
    );
    // Then the files to print, cut and sew: those of `garmentcode print` for this pattern.
    let print: Vec<String> = garmentcode::fabricate::FILE_NAMES.iter().map(|n| format!("top/print/{n}")).collect();
    assert_eq!(names[5..], print.iter().map(String::as_str).collect::<Vec<_>>()[..]);
    let pdf = &entries[5].1;
    assert!(pdf.starts_with(b"%PDF-"), "a PDF");
    assert_eq!(entries[2].1, f["files"]["specification.json"].as_str().unwrap().as_bytes());
    // A refused design still has its input files, and the reason.
    let (_, f) = post("/api/files", json!({ "design": {} }));
    assert_eq!(f["ok"], false);
    assert!(f["files"]["error.txt"].as_str().unwrap().contains("empty garment"));
    assert!(f["files"].get("specification.json").is_none());
}

#[test]
fn malformed_requests_get_4xx_with_a_message() {
    let cases: &[(&str, &str, &str, u16)] = &[
        ("POST", "/api/pattern", "{not json", 400),
        ("POST", "/api/pattern", "[1, 2]", 400),
        ("POST", "/api/pattern", "{\"design\": 3}", 400),
        ("POST", "/api/pattern", "{\"design\": {}, \"extra\": 1}", 400),
        ("POST", "/api/pattern", "{\"name\": \"../etc\"}", 400),
        ("POST", "/api/pattern", "{\"name\": 5}", 400),
        ("GET", "/api/pattern", "", 405),
        ("POST", "/api/schema", "", 405),
        ("DELETE", "/", "", 405),
        ("GET", "/api/nothing", "", 404),
        ("GET", "/etc/passwd", "", 404),
    ];
    for (method, path, body, status) in cases {
        let (s, r) = call(method, path, body);
        assert_eq!(s, *status, "{method} {path} {body}: {r}");
        assert_eq!(r["ok"], false);
        assert!(!r["error"].as_str().unwrap().is_empty());
    }
    let mut r = request("POST", "/api/pattern", "design=1");
    r.headers = vec![("content-type".into(), "application/x-www-form-urlencoded".into())];
    assert_eq!(route(&r).status, 415);
    assert!(route(&request("GET", "/api/pattern", "")).headers.iter().any(|(n, v)| *n == "Allow" && v == "POST"));
    // An empty body is an empty request: the defaults.
    assert_eq!(call("POST", "/api/design", "").0, 200);
}

#[test]
fn extreme_bodies_are_answered_not_panicked() {
    for m in [
        json!({ "height": 1e300 }),
        json!({ "waist": 1e-300 }),
        json!({ "shoulder_w": 1000.0, "neck_w": 900.0 }),
        json!({ "arm_length": 0.001 }),
    ] {
        for design in [
            json!({ "meta.upper": "Shirt", "sleeve.sleeveless": false }),
            json!({ "meta.bottom": "Pants" }),
            json!({ "meta.bottom": "SkirtCircle", "meta.wb": "FittedWB" }),
        ] {
            let (status, r) = post("/api/pattern", json!({ "design": design, "body": { "measurements": m } }));
            assert!(status == 200 || status == 400, "{status}: {r}");
            assert!(r["ok"].is_boolean());
        }
    }
}

fn sampler() -> garmentcode::Sampler {
    garmentcode::Sampler::new(space().clone())
}

#[test]
fn random_designs_on_every_body_never_break_the_api() {
    let bodies: Vec<&str> = garments::builtin::BODIES.iter().map(|(n, _)| *n).collect();
    for i in 0..40u64 {
        let values = sampler().sample_values(&mut garmentcode::sample_rng(99, i));
        let (status, r) = post("/api/pattern", json!({ "design": values_json(&values), "body": bodies[i as usize % bodies.len()] }));
        assert_eq!(status, 200, "{r}");
        if r["ok"] == true {
            assert!(r["svg"].is_string() && r["specification"].is_object());
        } else {
            assert!(!r["error"].as_str().unwrap().is_empty());
        }
    }
}

#[test]
fn layout_chooses_the_drawing() {
    let (_, placed) = post("/api/pattern", json!({ "design": { "meta.upper": "Shirt" } }));
    let (_, flat) = post("/api/pattern", json!({ "design": { "meta.upper": "Shirt" }, "layout": "flat" }));
    assert_eq!(placed["ok"], true);
    assert_eq!(flat["ok"], true);
    assert_ne!(placed["svg"], flat["svg"], "a different arrangement");
    assert_eq!(placed["specification"], flat["specification"], "the same pattern");
    let (status, r) = post("/api/pattern", json!({ "layout": "diagonal" }));
    assert_eq!(status, 400);
    assert!(r["error"].as_str().unwrap().contains("placed or flat"), "{r}");
}

#[test]
fn warnings_explain_the_references_internal_errors() {
    let (status, r) =
        post("/api/pattern", json!({ "design": { "meta.upper": null, "meta.wb": null, "meta.bottom": "Skirt2", "skirt.ruffle": 1.5 } }));
    assert_eq!(status, 200, "{r}");
    let w: Vec<&str> = r["warnings"].as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
    assert!(w.iter().any(|x| x.contains("refuses this combination of parameters (Skirt2 ruffles + belt)")), "{w:?}");
    assert!(w.iter().all(|x| !x.contains("ERROR::")), "{w:?}");
}

#[test]
fn mesh_of_a_design_is_the_librarys_box_mesh_in_compact_arrays() {
    let input = json!({ "design": { "meta.upper": "Shirt", "meta.bottom": "SkirtCircle" }, "body": "mean_female", "name": "tee" });
    let (status, r) = post("/api/mesh", input.clone());
    assert_eq!(status, 200, "{r}");
    assert_eq!(r["ok"], true);
    assert_eq!(r["name"], "tee");
    assert_eq!(r["resolution"], garmentcode::mesh::DEFAULT_RESOLUTION);

    // The library's mesh of the same pattern.
    let design = typed_design(&design_values(input.get("design")).unwrap()).unwrap();
    let body = garments::builtin::body("mean_female").unwrap();
    let pattern = garments::build::build(&design, &body, "tee").unwrap().pattern;
    let mesh = garmentcode::mesh::BoxMesh::new(&pattern, garmentcode::mesh::DEFAULT_RESOLUTION).unwrap();

    let n = r["vertices"].as_u64().unwrap() as usize;
    let m = r["faces"].as_u64().unwrap() as usize;
    assert_eq!((n, m), (mesh.vertices.len(), mesh.faces.len()));
    let positions: Vec<f64> = r["positions"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    let triangles: Vec<usize> = r["triangles"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as usize).collect();
    assert_eq!(positions.len(), 3 * n);
    assert_eq!(triangles.len(), 3 * m);
    assert!(triangles.iter().all(|&v| v < n));
    for (i, v) in mesh.vertices.iter().enumerate() {
        let p = &positions[3 * i..3 * i + 3];
        assert!((p[0] - v.x).abs() <= 0.005 + 1e-9 && (p[1] - v.y).abs() <= 0.005 + 1e-9 && (p[2] - v.z).abs() <= 0.005 + 1e-9);
    }
    for (k, f) in mesh.faces.iter().enumerate() {
        assert_eq!(triangles[3 * k..3 * k + 3], f.vertices);
    }
    let (lo, hi) = (&r["bounds"]["min"], &r["bounds"]["max"]);
    for k in 0..3 {
        let axis = positions.iter().skip(k).step_by(3);
        assert_eq!(lo[k].as_f64().unwrap(), axis.clone().copied().fold(f64::INFINITY, f64::min));
        assert_eq!(hi[k].as_f64().unwrap(), axis.copied().fold(f64::NEG_INFINITY, f64::max));
    }

    // Panels: every face in exactly one panel's range, in order; the pattern's panels.
    let panels = r["panels"].as_array().unwrap();
    let mut names: Vec<&str> = panels.iter().map(|p| p["name"].as_str().unwrap()).collect();
    let mut next = 0;
    for (i, p) in panels.iter().enumerate() {
        assert_eq!(p["first_face"].as_u64().unwrap() as usize, next);
        let count = p["faces"].as_u64().unwrap() as usize;
        assert!(count > 0, "{}", p["name"]);
        assert!(mesh.faces[next..next + count].iter().all(|f| f.panel == i));
        next += count;
    }
    assert_eq!(next, m);
    names.sort_unstable();
    let mut expected: Vec<&str> = pattern.panels.iter().map(|p| p.name.as_str()).collect();
    expected.sort_unstable();
    assert_eq!(names, expected);

    // Stitches: one seam line per stitch, as many vertices as the stitch has, on stitch vertices.
    let stitches = r["stitches"].as_array().unwrap();
    assert_eq!(stitches.len(), pattern.stitches.len());
    for (s, seam) in mesh.stitches.iter().zip(stitches) {
        let ids: Vec<usize> = seam.as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as usize).collect();
        assert_eq!(ids.len(), s.n);
        assert!(ids.iter().all(|&v| v < mesh.n_stitch_vertices), "seams run along merged vertices");
    }

    // Deterministic, and coarser on request.
    let bytes = || route(&request("POST", "/api/mesh", &input.to_string())).body;
    assert_eq!(bytes(), bytes());
    let mut coarse = input.clone();
    coarse["resolution"] = json!(3.0);
    let (status, c) = post("/api/mesh", coarse);
    assert_eq!(status, 200);
    assert!(c["vertices"].as_u64().unwrap() * 4 < n as u64, "{} vs {n}", c["vertices"]);
}

#[test]
fn mesh_requests_are_checked_like_the_others() {
    let (status, r) = post("/api/mesh", json!({}));
    assert_eq!(status, 200);
    assert_eq!(r["ok"], false);
    assert!(r["error"].as_str().unwrap().contains("empty garment"), "{r}");
    assert!(r.get("positions").is_none());

    let cases = [
        (json!({ "resolution": 0.1 }), "resolution: expected a number of cm from 1 to 10, got 0.1"),
        (json!({ "resolution": "fine" }), "resolution: expected a number of cm from 1 to 10, got \"fine\""),
        (json!({ "layout": "flat" }), "unknown key \"layout\" (expected design, body, name and resolution)"),
        (json!({ "design": { "shirt.length": 9 } }), "design.shirt.length: 9 is outside the allowed range [0.5, 3.5]"),
        (json!({ "body": "nobody" }), "no built-in body 'nobody'"),
    ];
    for (body, message) in cases {
        let (status, r) = post("/api/mesh", body.clone());
        assert_eq!(status, 400, "{body}: {r}");
        assert!(r["error"].as_str().unwrap().contains(message), "{body}: {r}");
    }
    assert_eq!(call("GET", "/api/mesh", "").0, 405);
    let listed = call("GET", "/api", "").1;
    assert!(listed["endpoints"].as_array().unwrap().iter().any(|e| e == "POST /api/mesh"));
}

/// Every text a request carries is refused beyond its limit, and a message shows
/// at most a short prefix of a value and its length (and numbers in a short form):
/// a 1 MB value never makes a 1 MB (let alone 2 MB) answer.
#[test]
fn huge_values_get_short_messages() {
    const MB: usize = 1 << 20;
    let huge = "x".repeat(MB);
    let shown = format!("\"{}...\" ({MB} characters)", "x".repeat(garmentcode::message::QUOTE_CHARS));
    let keyed = |v: Json| Json::Object(Map::from_iter([(huge.clone(), v)]));
    let body_file = garments::builtin::body("mean_all").unwrap().to_yaml();
    let cases: Vec<(&str, Json, &str)> = vec![
        ("/api/pattern", json!({ "name": huge }), "name: expected 1 to 64 letters"),
        ("/api/pattern", json!({ "body": { "name": huge } }), "body.name: expected 1 to 64 letters"),
        ("/api/pattern", json!({ "design": { "meta.upper": huge } }), "design.meta.upper: "),
        ("/api/pattern", json!({ "design": keyed(json!(1)) }), "unknown parameter"),
        ("/api/pattern", keyed(json!(1)), "unknown key"),
        ("/api/pattern", json!({ "layout": huge }), "unknown layout"),
        ("/api/pattern", json!({ "body": huge }), "no built-in body"),
        ("/api/pattern", json!({ "body": { "base": huge } }), "no built-in body"),
        ("/api/pattern", json!({ "body": keyed(json!(1)) }), "body: unknown key"),
        ("/api/pattern", json!({ "body": { "measurements": keyed(json!(70)) } }), "unknown measurement"),
        ("/api/mesh", json!({ "resolution": huge }), "resolution: expected a number"),
        ("/api/random", json!({ "seed": huge }), "seed must be an integer"),
        (
            "/api/body",
            json!({ "body": { "yaml": body_file.replace("\n  waist: ", &format!("\n  waist: {huge}\n  _waist: ")) } }),
            "body.waist: expected a number",
        ),
        ("/api/design", json!({ "design": format!("design:\n  meta:\n    upper:\n      v: {huge}\n") }), "design.meta.upper: "),
    ];
    for (path, body, message) in cases {
        let (status, r) = post(path, body);
        let text = r.to_string();
        assert_eq!(status, 400, "{path}: {}", &text[..text.len().min(300)]);
        let error = r["error"].as_str().unwrap();
        assert!(error.contains(message), "{path}: {error:.300}");
        assert!(error.contains(&shown), "{path}: the value's prefix and length: {error:.300}");
        assert!(text.len() < 1000, "{path}: a short answer: {} bytes: {text:.300}", text.len());
    }
    for path in [format!("/api/design/{huge}"), format!("/api/body/{huge}"), format!("/{huge}"), format!("/api/{huge}")] {
        let (status, r) = call("GET", &path, "");
        assert_eq!(status, 404);
        let error = r["error"].as_str().unwrap();
        assert!(r.to_string().len() < 1000 && error.contains("xxx...\" (") && error.contains(" characters)"), "{:.300}", r.to_string());
    }
    let (status, r) = call(&huge, "/api/pattern", "{}");
    assert_eq!(status, 405);
    assert!(r.to_string().len() < 1000, "{:.300}", r.to_string());

    // Numbers in a short form, not 309 digits.
    for (body, message) in [
        (json!({ "body": { "measurements": { "waist": 1e308 } } }), "body.waist: 1e308 cm is outside the plausible range 40 to 220 cm"),
        (json!({ "design": { "shirt.length": -1e308 } }), "design.shirt.length: -1e+308 is outside the allowed range [0.5, 3.5]"),
        (json!({ "layout": 1e300 }), "layout must be \"placed\" or \"flat\", got 1e300"),
    ] {
        let (status, r) = post("/api/pattern", body.clone());
        assert_eq!(status, 400, "{body}");
        assert!(r["error"].as_str().unwrap().contains(message), "{body}: {r}");
    }
    let (status, r) = post("/api/mesh", json!({ "resolution": 1e308 }));
    assert_eq!(status, 400);
    assert!(r["error"].as_str().unwrap().ends_with("got 1e308"), "{r}");
}

/// The body's name (a label: the size printed on the pattern) follows the
/// pattern name's rule.
#[test]
fn the_body_name_is_checked() {
    let (status, r) = post("/api/body", json!({ "body": { "base": "mean_female", "name": "size_38", "measurements": { "waist": 70 } } }));
    assert_eq!(status, 200, "{r}");
    assert_eq!(r["name"], "size_38");
    for bad in [json!("a b"), json!(""), json!(".hidden"), json!("x".repeat(65)), json!(7)] {
        let (status, r) = post("/api/body", json!({ "body": { "base": "mean_female", "name": bad } }));
        assert_eq!(status, 400, "{bad}");
        assert!(r["error"].as_str().unwrap().starts_with("body.name"), "{r}");
    }
}

#[test]
fn the_measuring_guide_is_served_for_every_measurement() {
    let (_, schema) = call("GET", "/api/schema", "");
    for m in schema["measurements"].as_array().unwrap() {
        let name = m["name"].as_str().unwrap();
        assert!(m["how"].as_str().is_some_and(|h| h.len() > 20), "{name}: how to measure it");
        let r = route(&request("GET", &format!("/api/guide/{name}.svg"), ""));
        assert_eq!((r.status, r.content_type), (200, "image/svg+xml"), "{name}");
        assert!(String::from_utf8(r.body).unwrap().contains(r#"class="tape""#), "{name}");
    }
    let (status, e) = call("GET", "/api/guide/nose.svg", "");
    assert_eq!(status, 404);
    assert!(e["error"].as_str().unwrap().contains("no measurement `nose`"), "{e}");
    assert_eq!(call("POST", "/api/guide/waist.svg", "").0, 405);
}

/// The drape view's endpoints, in one test (they share the server's one drape): a
/// small skirt draped for a few frames on the built-in body, polled to the end; a new
/// drape replaces the running one; bad requests are refused with their range.
#[test]
fn a_drape_is_started_polled_replaced_and_cancelled() {
    let skirt = json!({ "meta.bottom": "SkirtCircle" });
    let (status, d) = post("/api/drape", json!({ "design": skirt, "body": "mean_all", "resolution": 4, "max_frames": 3 }));
    assert_eq!(status, 200, "{d}");
    assert_eq!(d["ok"], true, "{d}");
    let job = d["job"].as_u64().unwrap();
    let vertices = d["mesh"]["vertices"].as_u64().unwrap() as usize;
    assert!(vertices > 10);
    assert_eq!(d["mesh"]["positions"].as_array().unwrap().len(), 3 * vertices);
    let body = &d["body_mesh"];
    assert_eq!(body["name"], "mean_all");
    assert_eq!(body["positions"].as_array().unwrap().len() % 3, 0);
    assert!(body["triangles"].as_array().unwrap().len() > 10_000);
    super::super::drape::wait();
    let (status, s) = call("GET", &format!("/api/drape/{job}"), "");
    assert_eq!(status, 200, "{s}");
    assert_eq!(s["state"], "done", "{s}");
    assert_eq!(s["frame"], 3);
    assert_eq!(s["stats"]["frames"], 3);
    assert_eq!(s["stats"]["converged"], false);
    let positions = s["positions"].as_array().unwrap();
    assert_eq!(positions.len(), 3 * vertices);
    assert_ne!(positions, d["mesh"]["positions"].as_array().unwrap(), "the garment moved");

    // A new drape stops the one running and replaces it: the old job is gone.
    let (_, a) = post("/api/drape", json!({ "design": skirt, "resolution": 4, "max_frames": 2400 }));
    let (_, b) = post("/api/drape", json!({ "design": skirt, "resolution": 4, "max_frames": 2 }));
    let (first, second) = (a["job"].as_u64().unwrap(), b["job"].as_u64().unwrap());
    assert!(second > first);
    let (status, old) = call("GET", &format!("/api/drape/{first}"), "");
    assert_eq!(status, 404, "{old}");
    assert!(old["error"].as_str().unwrap().contains("only the latest drape is kept"), "{old}");
    // Cancelling the running one stops it at its next frame.
    let (_, c) = post("/api/drape", json!({ "design": skirt, "resolution": 4, "max_frames": 2400 }));
    let third = c["job"].as_u64().unwrap();
    let (status, r) = post("/api/drape/cancel", json!({ "job": third }));
    assert_eq!(status, 200, "{r}");
    super::super::drape::wait();
    let (_, s) = call("GET", &format!("/api/drape/{third}"), "");
    assert_eq!(s["state"], "stopped", "{s}");
    assert_eq!(s["error"], "cancelled");
    assert!(s["frame"].as_u64().unwrap() < 2400);

    // Bounded in time: past its time limit, or unpolled for too long, a drape stops.
    use super::super::drape::{Bounds, start_with};
    let long = json!({ "design": skirt, "resolution": 4, "max_frames": 2400 });
    let zero = std::time::Duration::ZERO;
    let hour = std::time::Duration::from_secs(3600);
    for (bounds, why) in [
        (Bounds { time: zero, abandoned: hour }, "the time limit of 0 s was reached"),
        (Bounds { time: hour, abandoned: zero }, "nobody asked for its progress for 0 s"),
    ] {
        let d: Json = serde_json::from_str(&start_with(&long, bounds).unwrap()).unwrap();
        super::super::drape::wait();
        let (_, s) = call("GET", &format!("/api/drape/{}", d["job"]), "");
        assert_eq!((&s["state"], &s["error"], &s["frame"]), (&json!("stopped"), &json!(why), &json!(1)), "{s}");
    }

    // Bad requests: the range is named; a design that does not build is ok: false.
    let (status, e) = post("/api/drape", json!({ "design": skirt, "max_frames": 0 }));
    assert_eq!(status, 400);
    assert_eq!(e["error"], "max_frames: expected a whole number of frames from 1 to 2400, got 0");
    let (status, e) = post("/api/drape", json!({ "design": skirt, "max_frames": 1e9 }));
    assert_eq!(status, 400, "{e}");
    let (status, e) = post("/api/drape", json!({ "design": skirt, "frames": 3 }));
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().starts_with("unknown key"), "{e}");
    let (status, e) = post("/api/drape", json!({}));
    assert_eq!((status, &e["ok"]), (200, &json!(false)), "{e}");
    assert!(e["error"].as_str().unwrap().contains("empty"), "{e}");
    let (status, e) = post("/api/drape/cancel", json!({ "job": "x" }));
    assert_eq!(status, 400, "{e}");
    let (status, _) = call("GET", "/api/drape/nope", "");
    assert_eq!(status, 404);
    let (status, _) = call("POST", "/api/drape/1", "{}");
    assert_eq!(status, 405);
    let (status, _) = call("GET", "/api/drape", "");
    assert_eq!(status, 405);
}

#[test]
fn the_extension_is_in_the_schema_and_its_constructs_reach_the_pattern() {
    // The page's controls come from the schema: every `design.extension` parameter is
    // there, in its own groups, after the reference's.
    let (status, s) = call("GET", "/api/schema", "");
    assert_eq!(status, 200);
    let paths: Vec<&str> = s["params"].as_array().unwrap().iter().map(|p| p["path"].as_str().unwrap()).collect();
    let expected: Vec<String> = garments::design::extended_design_space()
        .params()
        .iter()
        .filter(|p| p.path.starts_with("extension."))
        .map(|p| p.path.clone())
        .collect();
    let served: Vec<&str> = paths.iter().copied().filter(|p| p.starts_with("extension.")).collect();
    assert_eq!(served, expected);
    for p in ["extension.pockets.shirt", "extension.pockets.skirt", "extension.pleats.style", "extension.sleeve.one_piece"] {
        assert!(served.contains(&p), "{p}");
    }
    let first_extension = paths.iter().position(|p| p.starts_with("extension.")).unwrap();
    assert!(paths[first_extension..].iter().all(|p| p.starts_with("extension.")));
    let groups: Vec<&str> = s["groups"].as_array().unwrap().iter().map(|g| g.as_str().unwrap()).collect();
    assert!(groups.contains(&"extension") && groups.contains(&"extension.pockets"));
    let (status, js) = call("GET", "/api/json-schema", "");
    assert_eq!(status, 200);
    assert!(js.to_string().contains("one_piece"), "the JSON Schema holds the extension");
    // A shirt with a pocket: the piece, its placement line, and the stitches onto it.
    let design = json!({ "meta.upper": "Shirt", "sleeve.sleeveless": false, "extension.pockets.shirt": true });
    let (status, r) = post("/api/pattern", json!({ "design": design, "body": "mean_all" }));
    assert_eq!((status, &r["ok"]), (200, &json!(true)), "{r}");
    let pattern = &r["specification"]["pattern"];
    assert!(pattern["panels"].get("right_ftorso_pocket").is_some());
    assert_eq!(pattern["panels"]["right_ftorso"]["lines"][0]["kind"], "placement");
    let inner = pattern["inner_stitches"].as_array().unwrap();
    assert_eq!(inner.len(), 3, "the pocket's sides and bottom");
    assert!(inner.iter().all(|st| st[1]["panel"] == "right_ftorso" && st[1]["line"] == 0));
    assert_eq!(r["specification"]["properties"]["extension_version"], 1);
    let svg = r["svg"].as_str().unwrap();
    assert!(svg.contains("class=\"placement\""), "the placement line is drawn");
    // The built-in pocket-shirt as the page loads it: its fold lines drawn.
    let (_, d) = call("GET", "/api/design/pocket-shirt", "");
    assert_eq!(d["design"]["extension.sleeve.one_piece"], true);
    let (_, r) = post("/api/pattern", json!({ "design": d["design"], "body": "mean_all" }));
    assert_eq!(r["ok"], true, "{r}");
    assert!(r["svg"].as_str().unwrap().contains("class=\"fold\""));
}
