"""Pair2.depth_value / directional_depth_value (issue 19 item 1): on every engine the lean answer's
depth, translation and overlapping equal minimum's / along's bit for bit, a single point gives
scalars, and bad input raises InvalidInput."""
import numpy as np
import pytest

import pendepth
from conftest import offsets_for


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("engine", ["convex", "polygon-convex", "convex-polygon", "pair-per-query", "no-fit-polygon"])
def test_lean_equals_full_every_engine(pairs, engine):
    pair = pairs[engine]
    ts = offsets_for(pair, 200, seed=5)
    rng = np.random.default_rng(6)
    ds = rng.normal(size=(200, 2))
    m, v = pair.minimum(ts), pair.depth_value(ts)
    assert v.depth.shape == (200,) and v.translation.shape == (200, 2) and v.overlapping.shape == (200,)
    assert v.overlapping.any() and (~v.overlapping).any()
    for f in ("depth", "translation", "overlapping"):
        assert same_bits(getattr(v, f), getattr(m, f)), f
    a, w = pair.along(ts, ds), pair.directional_depth_value(ts, ds)
    for f in ("depth", "translation", "overlapping"):
        assert same_bits(getattr(w, f), getattr(a, f)), f
    one_d = pair.directional_depth_value(ts, ds[0])  # one direction for all
    assert same_bits(one_d.depth, pair.along(ts, ds[0]).depth)
    one = pair.depth_value(ts[7])
    assert same_bits(one.depth, m.depth[7]) and same_bits(one.translation, m.translation[7])
    assert same_bits(one.overlapping, m.overlapping[7])


def test_lean_bad_input(pairs):
    pair = pairs["no-fit-polygon"]
    with pytest.raises(pendepth.InvalidInput):
        pair.depth_value([np.nan, 0.0])
    with pytest.raises(pendepth.InvalidInput):
        pair.directional_depth_value([0.0, 0.0], [0.0, 0.0])
    with pytest.raises(pendepth.InvalidInput):
        pair.directional_depth_value([[0.0, 0.0], [1.0, 1.0]], [[1.0, 0.0], [np.inf, 0.0]])
