"""Datasets from Python equal the CLI's byte for byte; the sampler's designs; the
shard reader."""

import json
import subprocess
import threading

import numpy as np

import pytest

import garmentcode as gc
from conftest import tree


def run_cli(cli, *args):
    subprocess.run([cli, *args], check=True, capture_output=True)


def content(root):
    """A dataset's files, and its summary without the run's figures (time, jobs,
    samples made or resumed)."""
    files = tree(root)
    summary = gc.parse_yaml(files.pop("dataset_properties.yaml").decode())
    summary.pop("run")
    return files, summary


def test_dataset_equals_the_cli_byte_for_byte(cli, tmp_path):
    calls = []
    summary = gc.sample_dataset(24, 7, tmp_path / "py", jobs=2, bodies=["mean_all", "mean_female"], formats=["json", "svg"], progress=lambda d, t: calls.append((d, t)))
    assert summary.endswith("dataset_properties.yaml")
    run_cli(cli, "sample", "--n", "24", "--seed", "7", "--out", str(tmp_path / "cli"), "--jobs", "1", "--bodies", "mean_all,mean_female", "--formats", "json,svg")
    py_files, py_summary = content(tmp_path / "py")
    cli_files, cli_summary = content(tmp_path / "cli")
    assert sorted(py_files) == sorted(cli_files)
    for name in py_files:
        assert py_files[name] == cli_files[name], name
    assert py_summary == cli_summary
    assert calls and calls[-1] == (24, 24), calls[-3:]


def test_shards_equal_the_cli_byte_for_byte(cli, tmp_path):
    gc.sample_dataset(10, 3, tmp_path / "py", layout="shards:4", jobs=2, formats="json,mesh")
    run_cli(cli, "sample", "--n", "10", "--seed", "3", "--out", str(tmp_path / "cli"), "--layout", "shards:4", "--jobs", "2", "--formats", "json,mesh")
    py_files, _ = content(tmp_path / "py")
    cli_files, _ = content(tmp_path / "cli")
    assert py_files == cli_files
    assert sorted(n for n in py_files if n.endswith(".tar")) == ["shard-000000.tar", "shard-000001.tar", "shard-000002.tar"]


def test_the_dataset_does_not_depend_on_jobs(tmp_path):
    gc.sample_dataset(12, 5, tmp_path / "one", jobs=1)
    gc.sample_dataset(12, 5, tmp_path / "two", jobs=2)
    assert content(tmp_path / "one")[0] == content(tmp_path / "two")[0]


def test_the_space_samples_the_dataset_s_designs(tmp_path):
    gc.sample_dataset(3, 11, tmp_path / "d", jobs=1)
    space = gc.DesignSpace()
    for i in range(3):
        written = space.validate((tmp_path / "d" / f"rand_{i:07d}" / "design_params.yaml").read_text())
        assert space.sample(11, i) == written


def test_the_extended_space_samples_the_extension_like_the_cli(cli, tmp_path):
    plain, extended = gc.DesignSpace(), gc.DesignSpace(extended=True)
    assert (plain.extended, extended.extended) == (False, True)
    assert not any(p.startswith("extension.") for p in plain.paths)
    assert extended.paths[: len(plain.paths)] == plain.paths
    assert "extension.sleeve.one_piece" in extended.paths and "extension.pockets.skirt" in extended.paths
    assert "extended" in repr(extended)
    # The same seed draws the same reference parameters; some designs use the extension.
    drawn = [extended.sample(5, i) for i in range(8)]
    assert any(any(v != extended.default()[k] for k, v in d.items() if k.startswith("extension.")) for d in drawn)
    gc.sample_dataset(6, 5, tmp_path / "py", jobs=1, extended=True)
    gc.sample_dataset(6, 5, tmp_path / "space", jobs=1, design_space=extended)
    run_cli(cli, "sample", "--n", "6", "--seed", "5", "--out", str(tmp_path / "cli"), "--jobs", "1", "--extended")
    assert content(tmp_path / "py") == content(tmp_path / "cli")
    assert content(tmp_path / "space")[0] == content(tmp_path / "cli")[0]
    for i in range(6):
        written = extended.validate((tmp_path / "py" / f"rand_{i:07d}" / "design_params.yaml").read_text())
        assert extended.sample(5, i) == written


def test_iter_shards_yields_every_sample_as_a_dict(tmp_path):
    gc.sample_dataset(7, 2, tmp_path / "s", layout="shards:3", jobs=1)
    gc.sample_dataset(7, 2, tmp_path / "f", jobs=1)
    samples = list(gc.iter_shards(tmp_path / "s"))
    keys = [s["__key__"] for s in samples]
    assert keys == [f"rand_{i:07d}" for i in range(7)]
    for s in samples:
        folder = tmp_path / "f" / s["__key__"]
        spec = gc.Pattern.from_json(folder / f"{s['__key__']}_specification.json").spec
        assert s["specification.json"] == spec
        # The design flat, as everywhere else in the package.
        assert s["design_params.yaml"] == gc.DesignSpace().validate((folder / "design_params.yaml").read_text())
        assert s["body_measurements.yaml"]["body"]["height"] > 100
    raw = next(gc.iter_shards(tmp_path / "s", decode=False))
    assert isinstance(raw["specification.json"], bytes)
    picked = list(gc.iter_shards(tmp_path / "s", keys=lambda k: k.endswith("5")))
    assert [s["__key__"] for s in picked] == ["rand_0000005"]


def test_shard_dataset_splits_shards_over_workers(tmp_path, monkeypatch):
    gc.sample_dataset(7, 2, tmp_path / "s", layout="shards:3", jobs=1)
    ds = gc.ShardDataset(tmp_path / "s", transform=lambda s: s["__key__"])
    assert list(ds) == [f"rand_{i:07d}" for i in range(7)]

    class Info:
        def __init__(self, id, num_workers):
            self.id, self.num_workers = id, num_workers

    class FakeTorch:
        class utils:
            class data:
                info = None

                @staticmethod
                def get_worker_info():
                    return FakeTorch.utils.data.info

    import sys

    monkeypatch.setitem(sys.modules, "torch", FakeTorch)
    seen = []
    for w in range(2):
        FakeTorch.utils.data.info = Info(w, 2)
        seen += list(ds)
    assert sorted(seen) == [f"rand_{i:07d}" for i in range(7)]


def test_builds_release_the_gil(tmp_path):
    # Two Python threads sampling at once both finish with the same datasets as
    # one after the other.
    out = [tmp_path / "a", tmp_path / "b"]
    threads = [threading.Thread(target=gc.sample_dataset, args=(6, 9, o), kwargs={"jobs": 1}) for o in out]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert content(out[0])[0] == content(out[1])[0]
    assert len([n for n in content(out[0])[0] if n.endswith("specification.json")]) == 6


def test_an_exception_in_progress_stops_the_run(tmp_path):
    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        gc.sample_dataset(400, 1, tmp_path / "x", jobs=1, progress=stop)
    assert not (tmp_path / "x" / "dataset_properties.yaml").exists()
    assert len(list((tmp_path / "x").iterdir())) < 400
    # What was written is complete: a rerun resumes to the same dataset.
    gc.sample_dataset(400, 1, tmp_path / "x", jobs=1)
    gc.sample_dataset(400, 1, tmp_path / "y", jobs=2)
    assert content(tmp_path / "x")[0] == content(tmp_path / "y")[0]


def test_bad_dataset_arguments_raise_with_the_cli_s_messages(tmp_path):
    with pytest.raises(gc.InputError, match="unknown format 'obj'"):
        gc.sample_dataset(2, 1, tmp_path / "o", formats="json,obj")
    with pytest.raises(gc.InputError, match="did you mean mean_all"):
        gc.sample_dataset(2, 1, tmp_path / "o", bodies=["mean_al"])
    with pytest.raises(gc.InputError, match="expected folders, shards or shards:N"):
        gc.sample_dataset(2, 1, tmp_path / "o", layout="zip")
    with pytest.raises(ValueError):
        gc.sample_dataset(0, 1, tmp_path / "o")


def test_iter_shards_gives_meshes_as_pattern_mesh_does(tmp_path):
    gc.sample_dataset(3, 4, tmp_path / "s", layout="shards:2", jobs=1, formats="json,mesh")
    raw = {s["__key__"]: s for s in gc.iter_shards(tmp_path / "s", decode=False)}
    for s in gc.iter_shards(tmp_path / "s"):
        key = s["__key__"]
        mesh = s["mesh"]
        assert isinstance(mesh, gc.Mesh)
        assert not any(k.endswith((".obj", ".ply", ".pickle", ".mtl")) for k in s), sorted(s)
        expected = gc.Pattern.from_json(json.dumps(s["specification.json"])).mesh()
        for name in ("vertices", "faces", "uvs", "face_uvs", "face_panels", "vertex_panels"):
            assert np.array_equal(getattr(mesh, name), getattr(expected, name)), name
        assert mesh.vertex_labels == expected.vertex_labels and mesh.panel_names == expected.panel_names
        # The arrays are those of the shard's mesh files.
        files = {name.removeprefix(key + "_"): data for name, data in mesh.files().items()}
        assert files == {k: v for k, v in raw[key].items() if not k.startswith("__") and k in files}
        assert len(files) == 8


def test_shard_dataset_has_a_length_and_a_repr(tmp_path):
    gc.sample_dataset(7, 2, tmp_path / "s", layout="shards:3", jobs=1)
    ds = gc.ShardDataset(tmp_path / "s")
    assert len(ds) == 7 == len(list(ds))
    assert repr(ds) == f"ShardDataset(3 shards in {str(tmp_path / 's')!r}, decode=True)"
    assert len(gc.ShardDataset([tmp_path / "s" / "shard-000002.tar"])) == 1


def test_sample_dataset_is_quiet_unless_asked(tmp_path, capfd):
    gc.sample_dataset(2, 1, tmp_path / "a", jobs=1)
    assert capfd.readouterr().err == ""
    gc.sample_dataset(2, 1, tmp_path / "a", jobs=1, quiet=False)
    err = capfd.readouterr().err
    assert "resuming: 2 of 2 samples already made" in err and "2 samples (0 made" in err, err
