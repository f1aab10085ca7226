"""The design space: schema, defaults, validation, the vector encoding."""

import math

import numpy as np
import pytest

import garmentcode as gc


def test_params_describe_every_parameter():
    space = gc.DesignSpace()
    params = space.params
    assert len(params) == len(space) == len(space.paths) > 100
    upper = next(p for p in params if p["path"] == "meta.upper")
    assert upper["type"] == "select_null"
    assert "Shirt" in upper["range"]
    length = next(p for p in params if p["type"] == "float")
    lo, hi = length["range"]
    assert lo <= length["default"] <= hi and length["description"]


def test_default_and_validate():
    space = gc.DesignSpace()
    default = space.default()
    assert space.validate({}) == default
    nested = {"design": {"meta": {"upper": {"v": "FittedShirt", "range": ["x"]}}}}
    flat = {"meta.upper": "FittedShirt"}
    half = {"meta": {"upper": "FittedShirt"}}
    assert space.validate(nested) == space.validate(flat) == space.validate(half)
    assert space.validate(flat)["meta.upper"] == "FittedShirt"


def test_json_schema_lists_the_parameters():
    schema = gc.DesignSpace().json_schema()
    assert schema["type"] == "object"
    assert "design" in schema["properties"]


def test_vector_encoding_round_trips():
    space = gc.DesignSpace()
    labels = space.vector_labels()
    for i in range(20):
        design = space.sample(3, i)
        v = space.encode(design)
        assert v.shape == (len(labels),) and v.dtype == np.float64
        assert ((v >= 0) & (v <= 1)).all()
        back = space.decode(v)
        assert back.keys() == design.keys()
        for path, x in design.items():
            if isinstance(x, float):
                assert math.isclose(back[path], x, rel_tol=1e-12, abs_tol=1e-12), path
            else:
                assert back[path] == x, path
        assert space.encode(back) == pytest.approx(v, abs=1e-12)


def test_decode_gives_back_the_encoded_design_exactly():
    space = gc.DesignSpace()
    floats = [p for p in space.params if p["type"] == "float"]
    # Values as people write them (0.1 came back as 0.09999999999999998) ...
    for k in range(11):
        design = space.default()
        for p in floats:
            lo, hi = p["range"]
            design[p["path"]] = min(max(round(lo + k * (hi - lo) / 10, 2), lo), hi)
        assert space.decode(space.encode(design)) == design, k
    # The sampler's draws carry more digits than the encoding keeps where a range
    # crosses zero: they come back as the shortest number with the same encoding,
    # which then round-trips exactly.
    for i in range(50):
        design = space.sample(5, i)
        v = space.encode(design)
        back = space.decode(v)
        assert (space.encode(back) == v).all(), i
        assert space.decode(space.encode(back)) == back, i


def test_sample_gives_the_body_it_was_drawn_for(tmp_path):
    space = gc.DesignSpace()
    bodies = ["mean_all", "mean_female", "mean_male"]
    gc.sample_dataset(6, 13, tmp_path / "d", jobs=1, bodies=bodies)
    drawn = set()
    for i in range(6):
        design, body = space.sample(13, i, bodies=bodies, with_body=True)
        folder = tmp_path / "d" / f"rand_{i:07d}"
        assert design == space.sample(13, i, bodies=bodies)
        assert design == space.validate((folder / "design_params.yaml").read_text())
        assert body.to_yaml() == (folder / "body_measurements.yaml").read_text()
        assert body.name in bodies
        drawn.add(body.name)
    assert len(drawn) > 1


def test_decode_takes_any_vector_of_the_right_length():
    space = gc.DesignSpace()
    n = len(space.vector_labels())
    d = space.decode(np.full(n, 2.0))
    assert space.validate(d) == d
    with pytest.raises(ValueError, match=f"expected a vector of {n} values"):
        space.decode([0.5])


def test_a_design_file_s_space(tmp_path):
    text = gc.DesignSpace().to_yaml()
    path = tmp_path / "space.yaml"
    path.write_text(text)
    space = gc.DesignSpace(path)
    assert space.source == str(path)
    assert space.paths == gc.DesignSpace().paths
