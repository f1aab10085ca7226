"""garmentcode.compat: pygarment's pipeline with pygarment's names."""

import json
import os

import pytest

import garmentcode as gc
from garmentcode.compat import BodyParameters, BoxMesh, MetaGarment, Properties
from conftest import REPO

CASE = REPO / "tests" / "data" / "cases" / "case-001"


def body_file(tmp_path):
    path = tmp_path / "mean_all.yaml"
    path.write_text(gc.Body("mean_all").to_yaml())
    return path


def test_the_pygarment_pipeline_writes_pygarment_s_files(tmp_path):
    body = BodyParameters(body_file(tmp_path))
    design = gc.parse_yaml((CASE / "design.yaml").read_text())["design"]
    piece = MetaGarment("case", body, design)
    pattern = piece.assembly()
    assert piece.is_self_intersecting() is False
    assert piece.length() > 0
    (tmp_path / "system.json").write_text(json.dumps({"output": str(tmp_path / "Logs")}))
    props = Properties(tmp_path / "system.json")
    folder = pattern.serialize(props["output"], tag="_v1", to_subfolder=True, with_3d=False, with_text=False, view_ids=False, with_printable=True)
    body.save(folder)
    assert sorted(os.listdir(folder)) == [
        "body_measurements.yaml",
        "case__v1_pattern.png",
        "case__v1_pattern.svg",
        "case__v1_print_pattern.svg",
        "case__v1_specification.json",
    ]
    spec = open(os.path.join(folder, "case__v1_specification.json")).read()
    assert spec == gc.build(CASE / "design.yaml", "mean_all", name="case").to_json()
    assert gc.compare_specs((CASE / "specification.json").read_text(), spec)["pass"]
    assert gc.Body.from_yaml(open(os.path.join(folder, "body_measurements.yaml")).read()).measurements == body.body.measurements


def test_body_parameters_re_derive_on_update(tmp_path):
    body = BodyParameters(body_file(tmp_path))
    assert "_waist_level" in list(body)
    before = body["_waist_level"]
    body["height"] = body["height"] + 10
    assert body["_waist_level"] == pytest.approx(before + 10)
    with pytest.raises(KeyError):
        body["_waist_level"] = 3


def test_box_mesh_loads_and_serializes(tmp_path):
    spec = tmp_path / "shirt_specification.json"
    spec.write_text(gc.build("t-shirt").to_json())
    mesh = BoxMesh(spec, res=2.0)
    mesh.load()
    assert mesh.vertices.shape[1] == 3 and len(mesh.faces) > 0
    assert len(mesh.stitch_segmentation) == len(mesh.vertices)
    assert mesh.orig_lens and all(x > 0 for x in mesh.orig_lens.values())
    folder = mesh.serialize(tmp_path / "out")
    names = sorted(os.listdir(folder))
    assert "shirt_boxmesh.obj" in names and "shirt_orig_lens.pickle" in names and "shirt_specification.json" in names


def test_a_bad_design_raises_at_construction(tmp_path):
    body = BodyParameters(body_file(tmp_path))
    with pytest.raises(gc.DesignError, match="design.meta.upper"):
        MetaGarment("bad", body, {"meta": {"upper": {"v": "Tunic"}}})
