"""Draping a pattern on a body: numpy arrays, statistics, the GIL released, errors."""

import threading
import time

import numpy as np
import pytest

import garmentcode as gc

SKIRT = {"meta.bottom": "SkirtCircle"}


@pytest.fixture(scope="module")
def skirt():
    return gc.build(SKIRT, "mean_all", name="skirt")


def test_a_skirt_drapes_into_numpy_arrays(skirt):
    mesh = skirt.mesh(resolution=3.0)
    d = skirt.drape(max_frames=5, resolution=3.0)
    assert isinstance(d, gc.Drape)
    n, m = len(mesh.vertices), len(mesh.faces)
    assert d.positions.shape == (n, 3) and d.positions.dtype == np.float64
    assert d.faces.shape == (m, 3) and d.faces.dtype == np.int64
    assert np.array_equal(d.faces, mesh.faces)
    assert d.vertex_labels == mesh.vertex_labels
    assert np.isfinite(d.positions).all()
    assert not np.array_equal(d.positions, mesh.vertices), "the garment moved"
    assert np.abs(d.positions - mesh.vertices).max() < 20.0, "five frames move it a little"
    assert d.stats["frames"] == 5 and d.stats["converged"] is False
    assert set(d.stats) == {"frames", "seconds", "converged", "at_rest", "non_static_vertices", "body_penetrations", "self_intersections"}
    assert np.array_equal(d.mesh.vertices, mesh.vertices)
    obj = d.obj()
    assert obj.count("\nv ") + obj.startswith("v ") == n
    assert repr(d) == f'Drape("skirt", {n} vertices, 5 frames, not converged)'


def test_same_inputs_same_drape(skirt):
    a = skirt.drape(max_frames=3, resolution=4.0)
    b = skirt.drape(body="mean_all", max_frames=3, resolution=4.0)
    assert np.array_equal(a.positions, b.positions)


def test_the_gil_is_released_while_it_drapes(skirt):
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.005)

    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    skirt.drape(max_frames=20, resolution=3.0)
    elapsed = time.perf_counter() - start
    done.set()
    t.join()
    during = [x for x in ticks if start <= x <= start + elapsed]
    assert elapsed < 0.05 or len(during) >= 3, f"another thread ran {len(during)} times in {elapsed:.2f} s"


def test_bad_drapes_raise_the_packages_exceptions(skirt, tmp_path):
    for frames in (0, -1, 100_001):
        with pytest.raises(gc.InputError, match="max_frames: expected a number of frames from 1 to 100000"):
            skirt.drape(max_frames=frames)
    with pytest.raises(gc.PatternError, match="cannot mesh"):
        skirt.drape(resolution=0.0)
    # A body without a body mesh (until mannequins exist), and a bad body mesh file.
    with pytest.raises(gc.BodyError):
        skirt.drape(body={"base": "mean_all", "waist": 70.0}, max_frames=1, body_mesh=tmp_path / "missing.obj")
    open_mesh = tmp_path / "open.obj"
    open_mesh.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(gc.BodyError, match="closed"):
        skirt.drape(max_frames=1, body_mesh=open_mesh)
    with pytest.raises(gc.BodyError):
        skirt.drape(body="no-such-body")
    assert issubclass(gc.BodyError, ValueError)
