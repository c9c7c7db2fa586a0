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
    with pytest.raises(pendepth.InvalidInput):
        pair.along(t, [0, 0, 0])


def test_pair3_mesh_cast_and_pieces(tmp_path):
    # The shape cast on a mesh pair (exact) and the pieces every 3D result names.
    (tmp_path / "l.off").write_text(_polycube_off([(0, 0, 0), (1, 0, 0), (0, 1, 0)]))
    (tmp_path / "c.off").write_text(_polycube_off([(0, 0, 0)]))
    L = pendepth.Shape3.from_file(str(tmp_path / "l.off"), name="L")
    C = pendepth.Shape3.from_file(str(tmp_path / "c.off"), name="C")
    pair = pendepth.Pair3(L, C)
    c = pair.cast([3.0, 0.0, 0.0], [-1, 0, 0])  # onto the L's foot (x = 2)
    assert c.hit and not c.overlapping and c.distance == 1.0
    assert c.lower_bound == c.upper_bound == 1.0
    assert c.piece_p >= 0 and c.piece_q == 0  # the cube is one piece
    assert pair.cast([3.0, 1.0, 0.0], [-2, 0, 0]).distance == 1.0  # grazes the foot's top at its edge
    assert pair.cast([3.0, 1.5, 0.0], [-2, 0, 0]).distance == 2.0  # over the foot onto the upright arm
    n = pair.cast([1.0, 1.0, 0.0], [1, 1, 0])  # in the notch: touching at the start
    assert n.hit and n.distance == 0.0 and not n.overlapping
    o = pair.cast([0.5, 0.0, 0.0], [1, 0, 0])
    assert o.hit and o.overlapping and o.distance == 0.0
    m = pair.cast([3.0, 0.0, 0.0], [1, 0, 0])
    assert not m.hit and m.distance == math.inf and m.lower_bound == m.upper_bound == math.inf
    # Pieces in every result; batches carry them per row.
    s = pair.minimum([0.5, 0.0, 0.0])
    assert s.piece_p >= 0 and s.piece_q == 0
    d = pair.signed_distance([3.0, 0.0, 0.0])
    assert d.piece_p >= 0 and d.piece_q == 0
    a = pair.along(np.array([[0.5, 0.0, 0.0], [0.25, 1.5, 0.0], [5.0, 5.0, 5.0]]), [0, 1, 0])
    assert a.piece_p.dtype == np.int64 and a.piece_p.shape == (3,)
    assert list(a.piece_q[:2]) == [0, 0] and a.piece_p[2] == -1  # not overlapping: no pieces
    # A convex pair names no pieces.
    assert pendepth.Pair3(cube(), cube()).minimum([0.5, 0.0, 0.0]).piece_p == -1


def test_rounded_cast_bracket():
    # Two spheres: the entry s solves |c + s d| = r; the bracket holds it, distance its upper end.
    pair = pendepth.Pair3(pendepth.Shape3.sphere(0.3), pendepth.Shape3.sphere(0.4))
    c = pair.cast([3.0, 0.25, 0.0], [-1, 0, 0])
    exact = 3.0 - math.sqrt(0.7 ** 2 - 0.25 ** 2)
    assert c.hit and c.lower_bound <= c.upper_bound == c.distance
    assert c.lower_bound <= exact * (1 + 1e-15) and c.upper_bound >= exact * (1 - 1e-15)
    assert c.upper_bound - c.lower_bound <= 8 * 2.0 ** -52 * c.upper_bound
    b = pair.cast(np.array([[3.0, 0.25, 0.0], [3.0, 2.0, 0.0]]), [-1, 0, 0])
    assert list(b.hit) == [True, False] and b.lower_bound[1] == math.inf
