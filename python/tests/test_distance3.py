"""Pair3.signed_distance and Pair3.cast (issue 16): values, conventions, batches = singles."""
import math

import numpy as np
import pytest

import pendepth


def cube(h=1.0):
    return pendepth.Shape3.hull(np.array([[x, y, z] for x in (-h, h) for y in (-h, h) for z in (-h, h)], float))


def test_signed_distance_apart_touching_overlapping():
    p = pendepth.Pair3(cube(), cube())
    r = p.signed_distance([3.0, 0.0, 0.0])  # faces 1 apart
    assert r.distance == 1.0 and not r.overlapping
    assert np.array_equal(r.normal, [1.0, 0.0, 0.0]) and np.array_equal(r.translation, [-1.0, 0.0, 0.0])
    assert r.lower_bound == r.upper_bound == 1.0
    assert np.allclose(r.witness_q - r.witness_p, r.distance * r.normal)
    assert p.signed_distance([3.0, 3.0, 3.0]).distance == pytest.approx(math.sqrt(3.0), rel=1e-15)
    assert p.signed_distance([2.0, 0.5, 0.0]).distance == 0.0  # touching
    o = p.signed_distance([1.5, 0.0, 0.0])
    assert o.overlapping and o.distance == -p.minimum([1.5, 0.0, 0.0]).depth


def test_signed_distance_batch_equals_singles():
    rng = np.random.default_rng(5)
    p = pendepth.Pair3(cube(), cube(0.5))
    t = rng.uniform(-4, 4, (50, 3))
    q = rng.normal(size=(50, 4))
    b = p.signed_distance(t, q, threads=2)
    assert b.distance.shape == (50,) and b.witness_p.shape == (50, 3) and b.feature_p.shape == (50, 2)
    for i in range(50):
        s = p.signed_distance(t[i], q[i])
        assert s.distance == b.distance[i] and np.array_equal(s.witness_q, b.witness_q[i])
    assert np.array_equal(b.distance < 0, p.overlapping(t, q))


def test_cast():
    p = pendepth.Pair3(cube(), cube())
    c = p.cast([5.0, 0.5, 0.0], [-2.0, 0.0, 0.0])
    assert c.hit and c.distance == 3.0 and np.array_equal(c.translation, [-3.0, 0.0, 0.0])
    assert np.array_equal(c.normal, [1.0, 0.0, 0.0])
    miss = p.cast([5.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    assert not miss.hit and miss.distance == math.inf
    inside = p.cast([0.5, 0.0, 0.0], [1.0, 0.0, 0.0])
    assert inside.hit and inside.overlapping and inside.distance == 0.0
    b = p.cast([[5.0, 0.5, 0.0], [5.0, 0.0, 0.0]], [-1.0, 0.0, 0.0])
    assert np.array_equal(b.distance, [3.0, 3.0]) and b.hit.all()
    with pytest.raises(pendepth.InvalidInput, match="direction"):
        p.cast([5.0, 0.0, 0.0], [0.0, 0.0, 0.0])
