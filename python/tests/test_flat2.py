"""Points and segments as 2D shapes (Shape2.point, Shape2.segment; issue 16 item 4): analytic
answers on a square and an L, either role, batches equal singles, pickling, and the errors."""
import math
import pickle

import numpy as np
import pytest

import pendepth

SQUARE = [[0, 0], [4, 0], [4, 4], [0, 4]]
L_SHAPE = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]


def test_point_is_the_distance_field_of_p():
    P = pendepth.Shape2(L_SHAPE, name="L")
    q = pendepth.Shape2.point([0.25, 0.5])
    assert q.dimension == 0 and not q.is_convex and len(q) == 1
    pair = pendepth.Pair2(P, q)
    assert pair.engine == "flat"
    # σ at a point of the L's foot: the nearest side.
    r = pair.minimum([0.25, 0.0])  # the point at (0.5, 0.5)
    assert r.overlapping and r.depth == 0.5
    # Outside, above the foot: the distance to its top edge; beyond the reflex corner (1, 1): to it.
    d = pair.signed_distance([1.75, 1.5])  # the point at (2, 2)
    assert d.distance == 1.0 and not d.overlapping
    assert np.array_equal(d.witness_p, [2.0, 1.0])
    d = pair.signed_distance([1.75, 1.25])  # the point at (2, 1.75): nearer the corner's edges
    assert d.distance == 0.75
    d = pair.signed_distance([2.75, 3.5])  # the point at (3, 4): 2 from the upright x = 1
    assert d.distance == 2.0
    # Inside: −σ.
    assert pair.signed_distance([0.25, 0.0]).distance == -0.5
    assert pair.along([0.25, 0.0], [1, 0]).depth == 3.5
    c = pair.cast([4.75, 2.5], [-1, 0])  # the point at (5, 3) moving left: hits x = 1
    assert c.hit and c.distance == 4.0


def test_segment_either_role_and_batches():
    S = pendepth.Shape2(SQUARE)
    seg = pendepth.Shape2.segment([0, 0], [4, 0], name="bar")
    assert seg.dimension == 1
    a = pendepth.Pair2(S, seg)
    b = pendepth.Pair2(seg, S)
    assert a.minimum([0, 1]).depth == 1.0
    assert a.minimum([-1, 2]).depth == 2.0
    assert not a.overlapping([0, 0])  # on the bottom edge: touching
    assert b.minimum([0, -1]).depth == 1.0
    ts = np.array([[0.0, 1.0], [-1.0, 2.0], [10.0, 10.0], [3.5, 2.0]])
    batch = a.minimum(ts, threads=2)
    assert list(batch.depth) == [a.minimum(t).depth for t in ts]
    sd = a.signed_distance(ts)
    assert list(sd.distance) == [a.signed_distance(t).distance for t in ts]
    assert sd.distance[2] == math.hypot(6.0, 6.0)


def test_pickling_and_errors():
    for s in (pendepth.Shape2.point([1.5, -2], name="p"), pendepth.Shape2.segment([0, 0], [1, 3], name="s")):
        t = pickle.loads(pickle.dumps(s))
        assert t.name == s.name and t.dimension == s.dimension
        assert all(np.array_equal(x, y) for x, y in zip(t.rings(), s.rings()))
    with pytest.raises(pendepth.InvalidInput, match="coincide"):
        pendepth.Shape2.segment([1, 1], [1, 1])
    with pytest.raises(pendepth.InvalidInput, match="not finite"):
        pendepth.Shape2.point([math.nan, 0])
    with pytest.raises(pendepth.InvalidInput, match="both lower-dimensional"):
        pendepth.Pair2(pendepth.Shape2.point([0, 0]), pendepth.Shape2.segment([0, 0], [1, 0]))
    # A unit segment in the L's corner: spanning [0.5, 1.5] × {2} it overlaps the upright by 0.5.
    pair = pendepth.Pair2(pendepth.Shape2(L_SHAPE), pendepth.Shape2.segment([0, 0], [1, 0]))
    assert pair.minimum([0.5, 2.0]).depth == 0.5
    assert not pair.overlapping([1.0, 2.0])  # touches the upright's right side


def test_pictures_of_points_and_segments():
    for s in (pendepth.Shape2.point([1, 2]), pendepth.Shape2.segment([0, 0], [1, 1])):
        svg = s._repr_svg_()
        assert svg.startswith("<svg") and "e-30" not in svg and 'stroke-linecap="round"' in svg
