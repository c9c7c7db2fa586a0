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


def _polycube_off(voxels):
    """The boundary of a union of unit voxels as an OFF text (outward quads)."""
    pts, ids, faces = [], {}, []

    def vid(p):
        if p not in ids:
            ids[p] = len(pts)
            pts.append(p)
        return ids[p]

    vox = set(voxels)
    for v in vox:
        for a in range(3):
            for s in (-1, 1):
                n = list(v)
                n[a] += s
                if tuple(n) in vox:
                    continue
                b, c = (a + 1) % 3, (a + 2) % 3
                quad = []
                for k in range(4):
                    j = k if s > 0 else 3 - k
                    p = list(v)
                    p[a] += 1 if s > 0 else 0
                    p[b] += (0, 1, 1, 0)[j]
                    p[c] += (0, 0, 1, 1)[j]
                    quad.append(vid(tuple(p)))
                faces.append(quad)
    lines = ["OFF", f"{len(pts)} {len(faces)} 0"] + [" ".join(map(str, p)) for p in pts]
    lines += ["4 " + " ".join(map(str, f)) for f in faces]
    return "\n".join(lines) + "\n"


def test_pair3_on_meshes(tmp_path):
    # A non-convex L of three voxels and a unit cube: answered on the L's convex pieces.
    (tmp_path / "l.off").write_text(_polycube_off([(0, 0, 0), (1, 0, 0), (0, 1, 0)]))
    (tmp_path / "c.off").write_text(_polycube_off([(0, 0, 0)]))
    L = pendepth.Shape3.from_file(str(tmp_path / "l.off"), name="L")
    C = pendepth.Shape3.from_file(str(tmp_path / "c.off"), name="C")
    assert not L.is_convex and C.is_convex
    pair = pendepth.Pair3(L, C)
    assert not pair.overlapping([1.0, 1.0, 0.0])  # in the notch: touching
    assert pair.overlapping([0.5, 0.0, 0.0])
    t = [0.5, 0.0, 0.0]
    assert pair.along(t, [0, 1, 0]).depth == 2.0  # out past the L's upright arm
    assert pair.along(t, [1, 0, 0]).depth == 1.5
    assert pair.separation([-3.0, 0.5, 0.0], [1, 0, 0]).depth == 5.0
    s = pair.minimum(t)
    assert s.lower_bound <= s.upper_bound == s.depth == 1.0
    assert pair.signed_distance([3.0, 0.0, 0.0]).distance == 1.0
    assert pair.signed_distance(t).distance == -s.upper_bound
    ts = np.array([[0.5, 0.0, 0.0], [1.0, 1.0, 0.0], [0.25, 0.5, 0.5]])
    batch = pair.along(ts, [0, 1, 0], threads=2)
    assert list(batch.depth) == [pair.along(x, [0, 1, 0]).depth for x in ts]
    with pytest.raises(pendepth.InvalidInput, match="not implemented yet"):
        pair.cast(t, [1, 0, 0])
    with pytest.raises(pendepth.InvalidInput):
        pair.along(t, [0, 0, 0])
