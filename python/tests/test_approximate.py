"""pendepth.approximate_minimum_depth: certified bounds around the exact sigma of the hulls."""
import numpy as np
import pytest

import pendepth


def sphere(n, r, seed):
    g = np.random.default_rng(seed)
    v = g.normal(size=(n, 3))
    return r * v / np.linalg.norm(v, axis=1)[:, None]


@pytest.mark.parametrize("delta", [1e-1, 1e-2, 1e-3])
def test_bounds_bracket_the_exact_sigma(delta):
    P, Q = sphere(3000, 1.0, 1), sphere(2000, 0.6, 2)
    t, q = (0.3, -0.1, 0.2), (1.0, 0.2, 0.1, -0.3)
    r = pendepth.approximate_minimum_depth(P, Q, delta, translation=t, rotation=q)
    exact = pendepth.Pair3(pendepth.Shape3.hull(P), pendepth.Shape3.hull(Q)).minimum(np.array([t]), rotations=np.array([q])).depth[0]
    assert r["converged"] and r["overlapping"]
    assert r["lower_bound"] <= exact * (1 + 2**-44)
    assert r["upper_bound"] >= exact * (1 - 2**-44)
    assert r["upper_bound"] <= (1 + delta) * r["lower_bound"]
    assert r["depth"] == r["upper_bound"]
    assert abs(np.linalg.norm(r["normal"]) - 1) < 1e-12


def test_separated_is_zero_and_bad_input_raises():
    P = sphere(500, 1.0, 3)
    r = pendepth.approximate_minimum_depth(P, P, 0.01, translation=(5, 0, 0))
    assert r["converged"] and not r["overlapping"] and r["depth"] == 0 and r["lower_bound"] == 0
    for bad in (0.0, 1.0, float("nan")):
        with pytest.raises(pendepth.InvalidInput):
            pendepth.approximate_minimum_depth(P, P, bad)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.approximate_minimum_depth(P[:, :2], P, 0.1)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.approximate_minimum_depth(np.zeros((10, 3)), P, 0.1)
