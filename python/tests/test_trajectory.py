"""Trajectories (issue 18 item 3): Pair3.trajectory and pendepth.trajectory equal the single
queries bit for bit, warm or cold; bad input raises InvalidInput."""
import numpy as np
import pytest

import pendepth as pd

FIELDS3 = ["depth", "translation", "normal", "facet_normal", "witness_p", "witness_q", "feature_p", "feature_q",
           "lower_bound", "upper_bound", "overlapping"]
FIELDS2 = ["depth", "translation", "normal", "witness_p", "witness_q", "feature_p", "feature_q", "overlapping"]


def same(a, b, fields):
    for f in fields:
        x, y = np.asarray(getattr(a, f)), np.asarray(getattr(b, f))
        assert x.shape == y.shape, f
        assert x.tobytes() == y.tobytes(), f


def small_walk(rng, n):
    t = np.cumsum(rng.uniform(-0.03, 0.03, size=(n, 3)), axis=0)
    q = np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))
    q[:, 1:] = np.cumsum(rng.uniform(-0.01, 0.01, size=(n, 3)), axis=0)
    return t, q


def test_pair3_trajectory_equals_minimum():
    rng = np.random.default_rng(3)
    P = pd.Shape3.hull(rng.normal(size=(40, 3)), "P")
    Q = pd.Shape3.hull(rng.normal(size=(30, 3)) * 0.7, "Q")
    pair = pd.Pair3(P, Q)
    t, q = small_walk(rng, 80)
    warm = pair.trajectory(t, q)
    cold = pair.trajectory(t, q, warm=False)
    single = pair.minimum(t, q, threads=1)
    same(warm, cold, FIELDS3)
    same(warm, single, FIELDS3)
    assert np.count_nonzero(warm.overlapping) > 40
    # the warm start does less work in all
    assert warm.candidates.sum() < cold.candidates.sum()


def test_pair3_trajectory_bad_pose_names_index():
    P = pd.Shape3.hull(np.eye(3).tolist() + [[0, 0, 0]], "P")
    pair = pd.Pair3(P, P)
    t = np.zeros((5, 3))
    t[3, 1] = np.nan
    with pytest.raises(pd.InvalidInput, match="3"):
        pair.trajectory(t)


def test_trajectory_2d_equals_pairs():
    P = pd.Shape2([(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)], name="L")
    Q = pd.Shape2([(0, 0), (1, 0), (1, 2), (0, 2)], name="bar")
    rng = np.random.default_rng(4)
    offsets = 1 + np.cumsum(rng.uniform(-0.2, 0.2, size=(30, 2)), axis=0)
    angles = np.repeat([0.0, 90.0, 33.5, -45.0, 180.0, 0.0], 5)
    warm = pd.trajectory(P, Q, offsets, angles)
    cold = pd.trajectory(P, Q, offsets, angles, warm=False)
    same(warm, cold, FIELDS2)
    assert warm.engine == "trajectory"
    # quarter turns are exact: Q rotated by hand
    quarter = {0.0: [(0, 0), (1, 0), (1, 2), (0, 2)], 90.0: [(0, 0), (0, 1), (-2, 1), (-2, 0)],
               180.0: [(0, 0), (-1, 0), (-1, -2), (0, -2)]}
    for i in range(len(angles)):
        if angles[i] not in quarter:
            continue
        one = pd.Pair2(P, pd.Shape2(quarter[angles[i]])).minimum(offsets[i])
        assert np.float64(warm.depth[i]).tobytes() == np.float64(one.depth).tobytes()
        assert warm.translation[i].tobytes() == np.asarray(one.translation).tobytes()


def test_trajectory_2d_bad_input():
    P = pd.Shape2([(0, 0), (1, 0), (1, 1), (0, 1)])
    with pytest.raises(pd.InvalidInput, match="angles"):
        pd.trajectory(P, P, np.zeros((3, 2)), np.zeros(2))
    with pytest.raises(pd.InvalidInput, match="pose 1"):
        pd.trajectory(P, P, np.zeros((3, 2)), np.array([0.0, np.inf, 0.0]))
