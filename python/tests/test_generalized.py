"""pendepth.generalized_depth (issue 18): the binding equals the C++ front door's contract —
convex pairs give sigma (2D and 3D, the theorem), a peg turned in a slot is freed by turning back
(far below sigma), the reported motion separates (checked with Pair2 on a rotation of Q's
coordinates by the same formula), bounds are ordered, bad input raises InvalidInput."""
import math
import pathlib

import numpy as np
import pytest

import pendepth


def square(h, c=(0.0, 0.0)):
    return np.array([[c[0] - h, c[1] - h], [c[0] + h, c[1] - h], [c[0] + h, c[1] + h], [c[0] - h, c[1] + h]])


def turned(pts, deg):
    a = math.radians(deg % 360.0)
    c, s = math.cos(a), math.sin(a)
    return np.array([[c * x - s * y, s * x + c * y] for x, y in pts])


def test_convex_2d_is_sigma():
    rng = np.random.default_rng(18)
    for _ in range(10):
        P = pendepth.Shape2(square(1.0, tuple(rng.normal(size=2) * 0.1)))
        Q = pendepth.Shape2(turned(square(0.5), float(rng.uniform(0, 90))))
        t = rng.uniform(-0.8, 0.8, size=2)
        s = pendepth.Pair2(P, Q).minimum(t)
        g = pendepth.generalized_depth(P, Q, t)
        assert g.kind == "generalized"
        assert g.depth == float(s.depth) == g.lower_bound == g.upper_bound
        assert g.angle == 0.0
        assert np.array_equal(g.translation, s.translation)


def test_peg_in_slot_turns_back():
    slot = pendepth.Shape2(np.array([[-3, -5], [3, -5], [3, 4], [0.26, 4], [0.26, -4], [-0.26, -4], [-0.26, 4], [-3, 4]], float))
    bar = turned(np.array([[-0.25, -3], [0.25, -3], [0.25, 3], [-0.25, 3]]), 3.0)
    Q = pendepth.Shape2(bar)
    g = pendepth.generalized_depth(slot, Q, (0.0, 0.0))
    assert g.overlapping
    assert g.lower_bound <= g.upper_bound == g.depth
    assert g.depth < 0.1 * g.sigma
    assert -4 < g.angle < 0
    # The motion separates: Q's coordinates rotated by the same formula as Shape2.rotated.
    moved = pendepth.Shape2(turned(bar, g.angle))
    assert not pendepth.Pair2(slot, moved).overlapping(g.translation)
    # Its cost: the largest displacement of Q's vertices.
    cost = max(np.hypot(*(turned(bar, g.angle)[i] + g.translation - bar[i])) for i in range(4))
    assert cost <= g.depth * (1 + 1e-12)
    # The branch and bound over angle intervals closes the gap; a budget of one interval reports it.
    assert g.converged and g.upper_bound - g.lower_bound <= 1e-6 * g.upper_bound and g.intervals > 0
    small = pendepth.generalized_depth(slot, Q, (0.0, 0.0), max_intervals=1)
    assert small.lower_bound <= g.upper_bound and g.lower_bound <= small.upper_bound
    assert small.converged == (small.upper_bound - small.lower_bound <= 1e-6 * small.upper_bound)


def test_convex_3d_is_sigma():
    rng = np.random.default_rng(3)
    P = pendepth.Shape3.hull(rng.normal(size=(20, 3)))
    Q = pendepth.Shape3.hull(rng.normal(size=(15, 3)) * 0.7)
    t = np.array([0.1, -0.2, 0.05])
    q = np.array([0.9, 0.1, -0.3, 0.2])
    s = pendepth.Pair3(P, Q).minimum(t, q)
    g = pendepth.generalized_depth(P, Q, t, q)
    assert g.depth == float(s.depth)
    assert np.array_equal(g.rotation, [1.0, 0.0, 0.0, 0.0])
    assert np.array_equal(g.translation, s.translation)
    assert g.lower_bound <= g.depth <= g.upper_bound


def test_bad_input():
    P = pendepth.Shape2(square(1.0))
    with pytest.raises(pendepth.InvalidInput):
        pendepth.generalized_depth(P, P, (math.nan, 0.0))
    with pytest.raises(pendepth.InvalidInput):
        pendepth.generalized_depth(P, P, (0.0, 0.0), min_degrees=5.0)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.generalized_depth(P, P, np.zeros((3, 2)))


def _box_off(lo, hi):
    # A box as a closed mesh (OFF, outward quads).
    pts = [(x, y, z) for z in (lo[2], hi[2]) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return "OFF\n8 6 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in pts) + "".join("4 " + " ".join(map(str, f)) + "\n" for f in faces)


def test_mesh_3d_turns_a_stuck_bar_free(tmp_path):
    # P: a floor of 3 x 3 unit voxels with a block on its left above y = 1 and one on its right
    # below y = 0 (an L-free "Z"); Q: a bar turned about z so that its ends poke into both blocks.
    import sys
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    from test_distance3 import _polycube_off
    vox = [(x, y, 0) for x in range(3) for y in range(3)] + [(0, 2, 1), (2, 0, 1)]
    (tmp_path / "p.off").write_text(_polycube_off(vox))
    (tmp_path / "q.off").write_text(_box_off((-1.5, -0.5, 0.0), (1.5, 0.5, 0.5)))
    P = pendepth.Shape3.from_file(str(tmp_path / "p.off"), name="P")
    Q = pendepth.Shape3.from_file(str(tmp_path / "q.off"), name="Q")
    assert not P.is_convex
    phi = -0.1
    q = np.array([math.cos(phi / 2), 0.0, 0.0, math.sin(phi / 2)])
    t = np.array([1.5, 1.5, 1.0])  # the bar's middle in the middle cell, above the floor
    pair = pendepth.Pair3(P, Q)
    s = pair.minimum(t, q)
    assert s.overlapping
    g = pendepth.generalized_depth(P, Q, t, q, max_probes=48)
    assert g.kind == "generalized" and g.overlapping and g.probes <= 48
    assert g.lower_bound <= g.upper_bound == g.depth <= s.upper_bound * (1 + 1e-12)
    assert g.sigma == float(s.depth)
    # The motion: verified separating at the returned pose, which recomposes from the motion.
    assert not pair.overlapping(g.pose_translation, g.pose_rotation)
    assert np.array_equal(g.pose_translation, t + g.translation)
    # Turning back by |phi| about z frees it: DISP = 2 sin(|phi|/2)·|(1.5, 0.5)|, far below sigma.
    turn = 2 * math.sin(abs(phi) / 2) * math.hypot(1.5, 0.5)
    assert g.upper_bound <= 1.05 * turn < 0.5 * s.upper_bound
    with pytest.raises(pendepth.InvalidInput):
        pendepth.generalized_depth(P, Q, t, q, tolerance=-1.0)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.generalized_depth(P, Q, (math.nan, 0.0, 0.0))
