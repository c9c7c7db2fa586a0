"""A non-convex mesh against a point, a segment and a sphere through Pair3 (src/mesh3/mesh_mixed.cpp,
mesh_point.cpp, mesh_segment.cpp): closed forms on an L of five unit voxels, both roles, batches."""
import numpy as np
import pytest

import pendepth

# The L: voxels (0,0,0), (1,0,0), (2,0,0), (0,1,0), (0,2,0), as outward quads.
VOXELS = {(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (0, 2, 0)}


def write_l(path):
    ids, faces = {}, []

    def vid(p):
        return ids.setdefault(p, len(ids) + 1)

    for v in sorted(VOXELS):
        for a in range(3):
            for s in (-1, 1):
                n = list(v)
                n[a] += s
                if tuple(n) in VOXELS:
                    continue
                b, c = (a + 1) % 3, (a + 2) % 3
                base = list(v)
                if s > 0:
                    base[a] += 1
                quad = []
                for i, j in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    p = list(base)
                    p[b] += i
                    p[c] += j
                    quad.append(tuple(p))
                if s < 0:
                    quad.reverse()
                faces.append([vid(p) for p in quad])
    with open(path, "w") as f:
        for p, _ in sorted(ids.items(), key=lambda t: t[1]):
            f.write("v %d %d %d\n" % p)
        for q in faces:
            f.write("f " + " ".join(map(str, q)) + "\n")


def test_mesh_against_point_and_sphere(tmp_path):
    write_l(tmp_path / "L.obj")
    mesh = pendepth.Shape3.from_file(str(tmp_path / "L.obj"), "L")
    assert not mesh.is_convex
    field = pendepth.Pair3(mesh, pendepth.Shape3.point([0.0, 0.0, 0.0]))  # the L's signed distance field
    assert field.minimum([0.5, 0.5, 0.5]).depth == 0.5
    assert field.along([0.5, 0.5, 0.5], [1.0, 0.0, 0.0]).depth == 2.5  # through the shared faces x = 1, 2
    assert field.signed_distance([1.5, 1.5, 0.5]).distance == 0.5  # in the notch: apart
    assert field.signed_distance([1.0, 0.5, 0.5]).distance == -0.5  # on a face two pieces share: inside
    assert field.cast([1.5, 1.5, 0.5], [-1.0, 0.0, 0.0]).distance == 0.5
    swapped = pendepth.Pair3(pendepth.Shape3.point([0.5, 0.5, 0.5]), mesh)  # the mesh moves
    assert swapped.along([0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]).depth == 2.5
    ball = pendepth.Pair3(mesh, pendepth.Shape3.sphere(0.25))
    r = ball.along([1.5, 0.5, 0.5], [0.0, 1.0, 0.0])
    assert r.lower_bound <= 0.75 <= r.upper_bound and abs(r.depth - 0.75) < 1e-15
    ts = np.array([[0.5, 0.5, 0.5], [1.5, 1.5, 0.5], [5.0, 5.0, 5.0]])
    batch = field.signed_distance(ts)
    assert list(batch.overlapping) == [True, False, False]
    assert [field.signed_distance(t).distance for t in ts] == list(batch.distance)
    # A segment (src/mesh3/mesh_segment.cpp): in the face x = 1 inside the L (overlapping), on the
    # surface (touching); the same for a flat polygon (src/mesh3/mesh_flat.cpp).
    seg = pendepth.Pair3(mesh, pendepth.Shape3.segment([1.0, 0.25, 0.5], [1.0, 0.75, 0.5]))
    assert seg.overlapping([0.0, 0.0, 0.0])
    assert seg.along([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]).depth == 0.5
    assert not seg.overlapping([0.5, 0.75, 0.0])  # outside the L, one end on the face y = 1
    assert seg.signed_distance([0.5, 0.75, 0.0]).distance == 0.0
    square = pendepth.Shape3.flat([[1.0, 0.25, 0.25], [1.0, 0.75, 0.25], [1.0, 0.75, 0.75], [1.0, 0.25, 0.75]])
    flat = pendepth.Pair3(mesh, square)  # in the face x = 1 two pieces share: inside the L
    assert flat.overlapping([0.0, 0.0, 0.0])
    assert flat.along([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]).depth == 0.75
    assert pendepth.Pair3(square, mesh).along([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]).depth == 0.75
    floor = pendepth.Pair3(mesh, pendepth.Shape3.flat([[0, 0, 0], [1, 0, 0], [0, 1, 0]]))
    assert not floor.overlapping([0.0, 0.0, 0.0])  # on the face z = 0: touching
    assert floor.signed_distance([0.0, 0.0, 0.0]).distance == 0.0
