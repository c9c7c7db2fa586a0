"""Property tests (hypothesis): sigma <= sigma_d; moving Q by the translation separates; batch =
single. Shapes are random star-shaped (simple, non-convex) or convex polygons from a seed."""
import numpy as np
from hypothesis import given, strategies as st

import pendepth
from conftest import star

seeds = st.integers(0, 2**32 - 1)
kinds = st.sampled_from(["convex", "star"])


def make_pair(seed, kind_p, kind_q, prepare="auto"):
    rng = np.random.default_rng(seed)
    P = pendepth.Shape2(star(rng, int(rng.integers(3, 14)), convex=kind_p == "convex", radius=2.0), name="P")
    Q = pendepth.Shape2(star(rng, int(rng.integers(3, 14)), convex=kind_q == "convex", radius=1.0), name="Q")
    t = rng.uniform(-2.5, 2.5, size=(24, 2))
    d = rng.normal(size=(24, 2))
    return pendepth.Pair2(P, Q, prepare=prepare), t, d


def scale(pair, t):
    return max(np.abs(np.concatenate(pair.P.rings())).max(), np.abs(np.concatenate(pair.Q.rings())).max()) + \
        np.abs(t).max()


@given(seeds, kinds, kinds, st.sampled_from(["auto", "queries", "full"]))
def test_minimum_is_at_most_directional(seed, kp, kq, prepare):
    pair, t, d = make_pair(seed, kp, kq, prepare)
    s = pair.minimum(t)
    sd = pair.along(t, d)
    tol = 1e-9 * scale(pair, t)
    assert np.all(s.depth <= sd.depth + tol)
    assert np.array_equal(s.overlapping, sd.overlapping)
    assert np.all(s.depth[~s.overlapping] == 0)
    # the translation has the reported length and, for sigma_d, the asked direction
    assert np.allclose(np.hypot(*s.translation.T), s.depth, rtol=1e-12, atol=tol)
    dn = d / np.hypot(*d.T)[:, None]
    ov = sd.overlapping & (sd.depth > 0)
    assert np.allclose(sd.normal[ov], dn[ov], atol=1e-12)


@given(seeds, kinds, kinds)
def test_moving_q_by_the_translation_separates(seed, kp, kq):
    pair, t, d = make_pair(seed, kp, kq)
    tol = 1e-9 * scale(pair, t)
    for r in [pair.minimum(t), pair.along(t, d)]:
        moved = t + r.translation
        # up to rounding: the depth left at the moved placement is (near) zero
        assert np.all(pair.minimum(moved).depth <= tol)


@given(seeds, kinds, kinds)
def test_separation_leaves_the_ray_free(seed, kp, kq):
    pair, t, d = make_pair(seed, kp, kq)
    r = pair.separation(t, d)
    sd = pair.along(t, d)
    tol = 1e-9 * scale(pair, t)
    assert np.all(r.depth >= sd.depth - tol)
    dn = d / np.hypot(*d.T)[:, None]
    for extra in [0.0, 0.5, 3.0]:
        beyond = t + r.translation + extra * dn
        assert np.all(pair.minimum(beyond).depth <= tol)


@given(seeds, kinds, kinds, st.sampled_from([None, 1, 2]))
def test_batch_equals_single(seed, kp, kq, threads):
    pair, t, d = make_pair(seed, kp, kq)
    b = pair.along(t, d, threads=threads)
    m = pair.minimum(t, threads=threads)
    for i in range(len(t)):
        one = pair.along(t[i], d[i])
        assert b.depth[i].tobytes() == one.depth.tobytes()
        assert b.translation[i].tobytes() == one.translation.tobytes()
        assert b.witness_q[i].tobytes() == one.witness_q.tobytes()
        assert m.depth[i].tobytes() == pair.minimum(t[i]).depth.tobytes()


@given(seeds)
def test_3d_minimum_is_at_most_directional_and_separates(seed):
    rng = np.random.default_rng(seed)
    pair = pendepth.Pair3(pendepth.Shape3.hull(rng.normal(size=(int(rng.integers(4, 40)), 3))),
                          pendepth.Shape3.hull(rng.normal(size=(int(rng.integers(4, 40)), 3)) * 0.5))
    t = rng.normal(size=(16, 3))
    q = rng.normal(size=(16, 4))
    d = rng.normal(size=(16, 3))
    s = pair.minimum(t, q)
    sd = pair.along(t, d, q)
    tol = 1e-9 * (np.abs(pair.P.vertices).max() + np.abs(pair.Q.vertices).max() + np.abs(t).max())
    assert np.all(s.depth <= sd.depth + tol)
    assert np.all(s.lower_bound <= s.upper_bound)
    assert np.all(pair.minimum(t + s.translation, q).depth <= tol)
    assert np.all(pair.minimum(t + sd.translation, q).depth <= tol)
