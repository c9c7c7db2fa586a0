"""Pair2.signed_distance and Pair2.cast (issue 16): every engine, batch equal to single calls bit
for bit, the sign convention against overlapping / minimum, casts that touch, errors."""
import numpy as np
import pytest

import pendepth
from conftest import offsets_for

FIELDS = ["distance", "translation", "normal", "witness_p", "witness_q", "feature_p", "feature_q", "overlapping"]


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("engine", ["convex", "polygon-convex", "convex-polygon", "pair-per-query", "no-fit-polygon"])
def test_signed_distance_every_engine(pairs, engine):
    pair = pairs[engine]
    ts = offsets_for(pair, 200, seed=3) * 1.3
    r = pair.signed_distance(ts, threads=2)
    assert r.distance.shape == (200,) and r.translation.shape == (200, 2) and r.feature_p.shape == (200, 2)
    over = pair.overlapping(ts)
    assert np.array_equal(r.overlapping, over)
    assert np.array_equal(r.distance < 0, over)
    assert over.any() and (~over).any()
    m = pair.minimum(ts)
    assert same_bits(r.distance[over], -m.depth[over])
    assert np.allclose(r.translation, -r.distance[:, None] * r.normal, rtol=0, atol=1e-12)
    # batch == singles, bit for bit, whatever the thread count
    for i in range(0, 200, 37):
        one = pair.signed_distance(ts[i])
        for f in FIELDS:
            assert same_bits(getattr(one, f), getattr(r, f)[i]), (f, i)
    for th in (1, 4, None):
        again = pair.signed_distance(ts, threads=th, progress=th == 4)
        for f in FIELDS:
            assert same_bits(getattr(again, f), getattr(r, f))


def test_signed_distance_analytic():
    L = pendepth.Shape2.from_wkt("POLYGON ((0 0, 6 0, 6 2, 2 2, 2 5, 0 5, 0 0))")
    bar = pendepth.Shape2.from_wkt("POLYGON ((0 0, 3 0, 3 1, 0 1, 0 0))")
    pair = pendepth.Pair2(L, bar)
    r = pair.signed_distance([3.0, 3.0])
    assert float(r.distance) == 1.0 and not bool(r.overlapping)
    assert np.array_equal(r.translation, [-1.0, 0.0]) and np.array_equal(r.normal, [1.0, 0.0])
    assert float(pair.signed_distance([2.0, 3.0]).distance) == 0.0  # touching


def test_cast(pairs):
    L = pendepth.Shape2.from_wkt("POLYGON ((0 0, 6 0, 6 2, 2 2, 2 5, 0 5, 0 0))")
    bar = pendepth.Shape2.from_wkt("POLYGON ((0 0, 3 0, 3 1, 0 1, 0 0))")
    pair = pendepth.Pair2(L, bar)
    c = pair.cast([3.0, 6.0], [0.0, -2.0])
    assert float(c.distance) == 4.0 and bool(c.hit) and np.array_equal(c.normal, [0.0, 1.0])
    miss = pair.cast([3.0, 6.0], [0.0, 1.0])
    assert np.isinf(miss.distance) and not bool(miss.hit)
    over = pair.cast([1.0, 1.0], [1.0, 0.0])
    assert float(over.distance) == 0.0 and bool(over.overlapping)
    for engine, p in pairs.items():
        ts = offsets_for(p, 60, seed=5) * 1.5
        ds = np.random.default_rng(6).uniform(-1, 1, size=(60, 2))
        c = p.cast(ts, ds)
        assert c.hit.shape == (60,)
        hit = c.hit & ~c.overlapping
        assert hit.any(), engine
        # moving Q by the cast's translation touches P
        after = p.signed_distance(ts[hit] + c.translation[hit])
        assert np.all(np.abs(after.distance) <= 1e-12 * (1 + np.abs(ts[hit]).max())), engine
        assert np.all(c.distance[hit] >= p.signed_distance(ts[hit]).distance * (1 - 1e-15))
        one = p.cast(ts[0], ds[0])
        assert same_bits(one.distance, c.distance[0])


def test_errors(pairs):
    pair = pairs["convex"]
    with pytest.raises(pendepth.InvalidInput, match="placement 1"):
        pair.signed_distance(np.array([[0.0, 0.0], [np.nan, 0.0]]))
    with pytest.raises(pendepth.InvalidInput):
        pair.cast([0.0, 0.0], [0.0, 0.0])
    with pytest.raises(pendepth.InvalidInput):
        pair.signed_distance(np.zeros((3, 3)))
