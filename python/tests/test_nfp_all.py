"""pendepth.no_fit_polygons / read_nesting_instance: every entry equals no_fit_polygon of the
rotated pair, in the order i, a, j, b, at 1 and 2 threads; per-shape rotation lists; errors."""
import json
import os

import numpy as np
import pytest

import pendepth

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "nesting")


def same(a, b):
    if len(a.polygons) != len(b.polygons):
        return False
    for pa, pb in zip(a.polygons, b.polygons):
        if len(pa) != len(pb) or not all(np.array_equal(ra, rb) for ra, rb in zip(pa, pb)):
            return False
    return np.array_equal(a.slits, b.slits) and np.array_equal(a.points, b.points)


def small_instance(tmp_path):
    inst = {"name": "small", "items": [
        {"id": 0, "demand": 2, "allowed_orientations": [0.0, 90.0],
         "shape": {"type": "simple_polygon", "data": [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2], [0, 2], [0, 0]]}},
        {"id": "plate", "demand": 1,
         "shape": {"type": "polygon", "data": {"outer": [[0, 0], [6, 0], [6, 6], [0, 6]],
                                                "inner": [[[2, 2], [2, 4], [4, 4], [4, 2]]]}}}]}
    p = tmp_path / "small.json"
    p.write_text(json.dumps(inst))
    return str(p)


def test_entries_equal_single_calls(tmp_path):
    inst = pendepth.read_nesting_instance(small_instance(tmp_path))
    assert inst.name == "small" and [it.id for it in inst.items] == ["0", "plate"]
    assert inst.items[0].allowed_orientations == [0.0, 90.0] and inst.items[1].allowed_orientations == [0.0]
    assert inst.items[1].shape.hole_count == 1
    shapes = [it.shape for it in inst.items]
    rots = [it.allowed_orientations for it in inst.items]
    one = pendepth.no_fit_polygons(shapes, rots, threads=1)
    two = pendepth.no_fit_polygons(shapes, rots, threads=2)
    copies = [(0, 0.0), (0, 90.0), (1, 0.0)]
    assert [(e[0], e[1], e[2], e[3]) for e in one] == [(i, a, j, b) for i, a in copies for j, b in copies]
    for e, f in zip(one, two):
        i, a, j, b, n = e
        assert same(n, pendepth.no_fit_polygon(shapes[i].rotated(a), shapes[j].rotated(b)))
        assert same(n, f[4])
    # One shared list.
    shared = pendepth.no_fit_polygons(shapes, [0, 180])
    assert len(shared) == 16 and shared[5][:4] == (0, 180.0, 0, 180.0)


def test_esicup_instance():
    inst = pendepth.read_nesting_instance(os.path.join(DATA, "shirts.json"))
    shapes = [it.shape for it in inst.items]
    out = pendepth.no_fit_polygons(shapes, [0, 90])
    assert len(out) == (2 * len(shapes)) ** 2
    i, a, j, b, n = out[7]
    assert same(n, pendepth.no_fit_polygon(shapes[i].rotated(a), shapes[j].rotated(b)))


def test_errors(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"items": [{"id": 3, "demand": 1, "shape": {"type": "multi_polygon", "data": []}}]}')
    with pytest.raises(pendepth.InvalidInput, match=r"bad.json: item 0 \(id 3\): shape type \"multi_polygon\" is not supported"):
        pendepth.read_nesting_instance(str(bad))
    s = pendepth.read_nesting_instance(small_instance(tmp_path)).items[0].shape
    with pytest.raises(pendepth.InvalidInput, match="rotation list of shape 0"):
        pendepth.no_fit_polygons([s], [[]])
    with pytest.raises(pendepth.InvalidInput, match="rotation is not finite"):
        pendepth.no_fit_polygons([s], [float("nan")])
