"""Building, drawing, meshing and writing patterns; bad inputs."""

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import garmentcode as gc
from conftest import REPO, tree

CASE = REPO / "tests" / "data" / "cases" / "case-001"


def test_every_design_form_builds_the_same_pattern():
    yaml_path = CASE / "design.yaml"
    text = yaml_path.read_text()
    nested = gc.parse_yaml(text)
    flat = gc.DesignSpace().validate(nested)
    specs = {gc.build(d, "mean_all", name="p").to_json() for d in (str(yaml_path), yaml_path, text, nested, nested["design"], flat)}
    assert len(specs) == 1


def test_builtin_designs_and_bodies():
    assert "t-shirt" in gc.builtin_designs()
    assert "mean_all" in gc.Body.builtin()
    p = gc.build("t-shirt", "mean_female")
    assert p.name == "t-shirt"
    assert p.body.name == "mean_female"
    assert p.design == gc.DesignSpace().validate("t-shirt")
    assert p.checks["passed"] and p.checks["warnings"] == []
    assert p.problems() == [] or all(x["severity"] == "warning" for x in p.problems())
    assert len(p.panels) == len(p.spec["pattern"]["panels"])
    assert len(p.stitches) == len(p.spec["pattern"]["stitches"])
    assert p.svg().startswith("<?xml") or p.svg().startswith("<svg")
    assert p.png().startswith(b"\x89PNG")
    assert len(p.png(dpi=30)) > len(p.png()) and p.png(background="none") != p.png()
    assert p.svg(layout="flat") != p.svg()


def test_write_equals_the_cli_build(cli, tmp_path):
    pattern = gc.build("fitted-dress", "mean_male")
    written = pattern.write(tmp_path / "py", formats=["json", "svg", "png", "mesh", "print"])
    assert "specification.json" in written and "fitted-dress_boxmesh.obj" in written
    assert "pattern-tiled.pdf" in written and "pattern.dxf" in written
    subprocess.run(
        [cli, "build", "--design", "fitted-dress", "--body", "mean_male", "--out", str(tmp_path / "cli"), "--formats", "json,svg,png,mesh,print"],
        check=True,
        capture_output=True,
    )
    assert tree(tmp_path / "py") == tree(tmp_path / "cli")


def test_mesh_arrays_agree_with_the_mesh_files():
    pattern = gc.build("t-shirt")
    mesh = pattern.mesh(resolution=2.0)
    v, f = mesh.vertices, mesh.faces
    assert v.ndim == 2 and v.shape[1] == 3 and f.shape[1] == 3
    assert f.min() >= 0 and f.max() < len(v)
    assert mesh.face_uvs.shape == f.shape and mesh.face_uvs.max() < len(mesh.uvs)
    assert mesh.face_panels.shape == (len(f),) and mesh.face_panels.max() < len(mesh.panel_names)
    assert len(mesh.vertex_labels) == len(v) == len(mesh.vertex_panels)
    assert sorted(mesh.panel_names) == sorted(pattern.panels)
    assert len(mesh.stitch_pairs) == len(pattern.stitches)
    for pairs in mesh.stitch_pairs:
        assert pairs.shape[1] == 2 and pairs.max() < len(v)
    edges, lengths = mesh.rest_lengths
    assert edges.shape == (len(lengths), 2) and (lengths > 0).all()
    files = mesh.files()
    obj = files["t-shirt_boxmesh.obj"].decode()
    obj_vertices = [line for line in obj.splitlines() if line.startswith("v ")]
    assert len(obj_vertices) == len(v)
    first = np.array([float(x) for x in obj_vertices[0].split()[1:]])
    assert np.allclose(first, v[0])
    assert files["t-shirt_sim_segmentation.txt"].decode().splitlines() == mesh.vertex_labels


def test_from_json_reads_text_and_files(tmp_path):
    pattern = gc.build("sundress")
    again = gc.Pattern.from_json(pattern.to_json())
    assert again.to_json() == pattern.to_json()
    assert again.checks is None and again.design is None and again.body is None
    pattern.write(tmp_path / "sundress", formats=["json"])
    from_file = gc.Pattern.from_json(tmp_path / "sundress" / "specification.json")
    assert from_file.name == "sundress" and from_file.to_json() == pattern.to_json()
    written = from_file.write(tmp_path / "again", formats=["json", "svg"])
    assert sorted(written) == ["pattern.svg", "specification.json"]


def test_body_values():
    body = gc.Body("mean_all")
    m = body.measurements
    assert m["height"] > 100
    assert body["height"] == m["height"]
    assert any(k.startswith("_") for k in body.derived)
    same = gc.Body.from_dict(m)
    assert same.to_yaml().replace("body_sample", "") == body.to_yaml().replace("body_sample", "") or same.measurements == m
    assert gc.Body.from_yaml(body.to_yaml()).measurements == m
    assert gc.Body.describe("height")


def test_bad_designs_raise_with_clear_messages(tmp_path):
    with pytest.raises(gc.DesignError, match=r"design\.meta\.upper: \"Shrt\" is not allowed: expected one of \[.*Shirt"):
        gc.build({"meta.upper": "Shrt"})
    with pytest.raises(gc.DesignError, match=r"design\.meta\.uper: unknown parameter \(did you mean design\.meta\.upper\?\)"):
        gc.build({"meta": {"uper": {"v": "Shirt"}}})
    with pytest.raises(gc.DesignError, match=r"outside the allowed range"):
        gc.build({"shirt.length": 1000.0})
    with pytest.raises(gc.DesignError, match="did you mean t-shirt"):
        gc.build("t-shrt")
    bad = tmp_path / "bad.yaml"
    bad.write_text("design:\n  meta:\n    upper:\n      v: Shrt\n")
    with pytest.raises(gc.DesignError, match=r"bad\.yaml: line 4, column 10: design\.meta\.upper"):
        gc.build(str(bad))
    with pytest.raises(ValueError):
        gc.build(42)


def test_bad_bodies_raise_with_clear_messages():
    with pytest.raises(gc.BodyError, match="did you mean mean_all"):
        gc.Body("mean_al")
    body = dict(gc.Body("mean_all").measurements)
    body["height"] = 1.7
    with pytest.raises(gc.BodyError, match="it looks like metres"):
        gc.Body.from_dict(body)
    del body["height"]
    with pytest.raises(gc.BodyError, match="body.height: missing measurement"):
        gc.Body(body)


def test_unbuildable_designs_raise_build_error():
    empty = {"meta.upper": None, "meta.wb": None, "meta.bottom": None}
    with pytest.raises(gc.BuildError, match="empty garment"):
        gc.build(empty)
    assert issubclass(gc.BuildError, ValueError) and issubclass(gc.DatasetError, RuntimeError)


def test_bad_pattern_files_raise_pattern_error(tmp_path):
    with pytest.raises(gc.PatternError):
        gc.Pattern.from_json("{\"pattern\": 3}")
    with pytest.raises(gc.PatternError, match="cannot read"):
        gc.Pattern.from_json(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="unknown format 'obj'"):
        gc.build("t-shirt").write(tmp_path / "x", formats=["obj"])


def test_deep_and_self_containing_design_dicts_raise_design_error():
    # In a child interpreter: before the fix both crashed it (SIGSEGV).
    code = textwrap.dedent(
        """
        import time
        import garmentcode as gc

        deep = {"v": 1.0}
        for _ in range(20000):
            deep = {"a": deep}
        looped = {}
        looped["shirt"] = looped
        for design, message in ((deep, "nested more than 32 dicts deep"), (looped, "design.shirt: the dict contains itself")):
            start = time.monotonic()
            try:
                gc.build(design)
            except gc.DesignError as e:
                assert message in str(e), str(e)
            else:
                raise AssertionError("no DesignError")
            assert time.monotonic() - start < 2, time.monotonic() - start
        print("ok")
        """
    )
    child = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert child.returncode == 0 and child.stdout.strip() == "ok", (child.returncode, child.stderr[-2000:])


def test_a_body_may_give_a_few_measurements_over_a_built_in_body(tmp_path):
    female = gc.Body("mean_female")
    for source in (
        {"base": "mean_female", "waist": 70.0, "hips": 101.5},
        {"body": {"base": "mean_female", "waist": 70.0, "hips": 101.5}},
        {"base": "mean_female", "measurements": {"waist": 70.0, "hips": 101.5}},
        "body:\n  base: mean_female\n  waist: 70.0\n  hips: 101.5\n",
    ):
        body = gc.Body.from_yaml(source) if isinstance(source, str) else gc.Body(source)
        m = body.measurements
        assert (m["waist"], m["hips"]) == (70.0, 101.5)
        # What follows the waist and the hips is scaled with them; the rest is the base's.
        f = female.measurements
        assert m["waist_back_width"] == pytest.approx(f["waist_back_width"] * 70.0 / f["waist"])
        assert m["hip_back_width"] == pytest.approx(f["hip_back_width"] * 101.5 / f["hips"])
        follows = ("waist", "hips", "waist_back_width", "hip_back_width", "leg_circ", "bum_points")
        assert {k: v for k, v in m.items() if k not in follows} == {k: v for k, v in f.items() if k not in follows}
    path = tmp_path / "me.yaml"
    path.write_text("body:\n  base: mean_female\n  waist: 70.0\n")
    assert gc.build("t-shirt", str(path)).body.measurements["waist"] == 70.0
    with pytest.raises(gc.BodyError, match=r"<dict>: body\.base: no built-in body `mean_femal` \(did you mean `mean_female`\?\)"):
        gc.Body({"base": "mean_femal", "waist": 70.0})
    with pytest.raises(gc.BodyError, match=r"body\.waist: 7000 cm is outside the plausible range 40 to 220 cm"):
        gc.Body({"base": "mean_female", "waist": 7000.0})
    bad = tmp_path / "bad.yaml"
    bad.write_text("body:\n  base: mean_female\n  wasit: 70.0\n")
    with pytest.raises(gc.BodyError, match=r"bad\.yaml: line 3: body\.wasit: unknown measurement \(did you mean `waist`\?\)"):
        gc.Body(bad)


def test_the_format_extension_reads_draws_and_meshes():
    # A pattern with a diamond dart, a keyhole, a pocket sewn onto a placement line, a
    # facing, a fold line and pleat lines (docs/pattern-extension.md).
    path = REPO / "garmentcode" / "tests" / "data" / "extension" / "specification.json"
    pattern = gc.Pattern.from_json(path)
    spec = pattern.spec
    assert spec["properties"]["extension_version"] == 1
    front = spec["pattern"]["panels"]["front"]
    assert [h["kind"] for h in front["holes"]] == ["dart", "cut"]
    assert gc.Pattern.from_json(pattern.to_json()).to_json() == pattern.to_json()
    sides = pattern.inner_stitches
    assert sides and all(set(a) >= {"panel", "edge"} and set(b) >= {"panel", "edge"} for a, b in sides)
    assert any("hole" in a and "hole" in b for a, b in sides), "the dart's sides are sewn together"
    assert any("line" in a or "line" in b for a, b in sides), "the pocket is sewn onto its placement line"
    assert pattern.problems() == []
    assert "fold" in pattern.svg()
    mesh = pattern.mesh(resolution=1.0)
    assert len(mesh.stitch_pairs) == len(pattern.stitches) + len(sides)
    labels = set(mesh.files()[f"{pattern.name}_vertex_labels.yaml"].decode().split())
    assert any(label.startswith("fold_") for label in labels)


def test_pattern_panel_gives_holes_lines_and_layer():
    path = REPO / "garmentcode" / "tests" / "data" / "extension" / "specification.json"
    pattern = gc.Pattern.from_json(path)
    front = pattern.panel("front")
    assert [h["kind"] for h in front["holes"]] == ["dart", "cut"]
    assert [line["kind"] for line in front["lines"]] == ["placement"]
    assert front["layer"] == "outer"
    assert pattern.panel("front_facing")["layer"] == "facing"
    sleeve = pattern.panel("sleeve")
    assert (sleeve["holes"], [line["kind"] for line in sleeve["lines"]]) == ([], ["fold"])
    assert sleeve["vertices"] == pattern.spec["pattern"]["panels"]["sleeve"]["vertices"]
    # A pattern without the extension: the keys are there, empty.
    shirt = gc.build("t-shirt")
    assert {k: shirt.panel("right_ftorso")[k] for k in ("holes", "lines", "layer")} == {"holes": [], "lines": [], "layer": "outer"}
    with pytest.raises(KeyError, match="no panel 'nowhere'"):
        pattern.panel("nowhere")


def test_the_one_piece_sleeve_of_the_pocket_shirt():
    shirt = gc.build("pocket-shirt")
    assert "right_sleeve_b" not in shirt.panels
    sleeve = shirt.panel("right_sleeve_f")
    assert [(line["kind"], line["angle"]) for line in sleeve["lines"]] == [("fold", 90.0)]
    assert shirt.design["extension.sleeve.one_piece"] is True
