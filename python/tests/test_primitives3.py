"""Shape3 lower-dimensional shapes and primitives (issue 16 items 4, 5): constructors, closed forms
through Pair3, pickling, errors."""
import math
import pickle

import numpy as np
import pytest

import pendepth


def test_lower_dimensional_shapes():
    cube = pendepth.Shape3.box(1.0, 1.0, 1.0)
    p = pendepth.Shape3.point([0.0, 0.0, 0.0])
    s = pendepth.Shape3.segment([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    f = pendepth.Shape3.flat(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, 0]], float))
    assert (p.dimension, s.dimension, f.dimension, cube.dimension) == (0, 1, 2, 3)
    assert len(f) == 3 and f.vertices.shape == (3, 3)
    field = pendepth.Pair3(cube, p)  # a point Q: the signed distance field of the cube
    assert field.signed_distance([0.25, 0.0, 0.0]).distance == -0.75
    assert field.signed_distance([4.0, 0.0, 0.0]).distance == 3.0
    assert field.minimum([0.25, 0.5, 0.0]).depth == 0.5
    assert pendepth.Pair3(cube, s).along([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]).depth == 1.0
    assert pendepth.Pair3(f, cube).minimum([0.0, 0.0, 0.5]).depth == 0.5
    with pytest.raises(pendepth.InvalidInput, match="lower-dimensional"):
        pendepth.Pair3(p, s)
    with pytest.raises(pendepth.InvalidInput, match="not flat"):
        pendepth.Shape3.flat(cube.vertices)


def test_primitives_closed_forms():
    a, b = pendepth.Shape3.sphere(0.5), pendepth.Shape3.sphere(0.25)
    assert (a.dimension, a.radius, a.core.dimension) == (3, 0.5, 0)
    pair = pendepth.Pair3(a, b)
    assert pair.signed_distance([2.0, 0.0, 0.0]).distance == 1.25
    assert pair.minimum([0.5, 0.0, 0.0]).depth == 0.25
    assert pair.cast([3.0, 0.0, 0.0], [-1.0, 0.0, 0.0]).distance == 2.25
    d = pair.signed_distance([1.0, 1.0, 1.0]).distance
    assert d == pytest.approx(math.sqrt(3.0) - 0.75, rel=1e-15)
    caps = pendepth.Pair3(pendepth.Shape3.capsule(0.5, 1.0), pendepth.Shape3.box(1.0, 1.0, 1.0))
    assert caps.signed_distance([3.0, 0.0, 0.0]).distance == 1.5
    r = pendepth.Shape3.rounded(pendepth.Shape3.box(1.0, 1.0, 1.0), 0.25)
    assert pendepth.Pair3(r, b).signed_distance([3.0, 0.0, 0.0]).distance == 1.5
    for s in (a, pendepth.Shape3.capsule(0.5, 1.0), r, pendepth.Shape3.point([1.0, 2.0, 3.0])):
        t = pickle.loads(pickle.dumps(s))
        assert (t.dimension, t.radius, t.name) == (s.dimension, s.radius, s.name)
        assert np.array_equal(t.vertices, s.vertices)
    with pytest.raises(pendepth.InvalidInput, match="radius"):
        pendepth.Shape3.sphere(0.0)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.Shape3.point([0.0, 1.0])


def test_flat_files_and_exact_rounded_contact(tmp_path):
    # A file of coplanar points (or a lone face) is a flat shape, as Shape3.flat of its points.
    tri = tmp_path / "tri.obj"
    tri.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
    face = tmp_path / "face.off"
    face.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n")
    cube = pendepth.Shape3.box(1.0, 1.0, 1.0)
    t = pendepth.Shape3.from_file(str(tri), "Q")
    assert t.dimension == 2 and len(t) == 3
    assert pendepth.Shape3.from_file(str(face), "Q", True).dimension == 2
    direct = pendepth.Shape3.flat(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float))
    for off in ([0.0, 0.0, 0.5], [2.0, 0.5, 1.5]):
        assert (pendepth.Pair3(cube, t).signed_distance(off).distance
                == pendepth.Pair3(cube, direct).signed_distance(off).distance)
    # Spheres at distance 5 with radii summing to 5 (touching) or one ulp more (overlapping).
    for r2, overlap in ((3.0, False), (math.nextafter(3.0, 4.0), True), (math.nextafter(3.0, 2.0), False)):
        pair = pendepth.Pair3(pendepth.Shape3.sphere(2.0), pendepth.Shape3.sphere(r2))
        assert pair.overlapping([3.0, 4.0, 0.0]) == overlap
        sd = pair.signed_distance([3.0, 4.0, 0.0]).distance
        assert (sd < 0) == overlap and (sd == 0) == (r2 == 3.0)
        if overlap:
            a = pair.along([3.0, 4.0, 0.0], [3.0, 4.0, 0.0])
            assert a.lower_bound <= r2 - 3.0 <= a.upper_bound == a.depth  # the exit r − 5, exact


def test_curved_primitives_brackets_and_pickling():
    # Curved primitives (issue 16 item 5): certified brackets around closed forms.
    cyl = pendepth.Shape3.cylinder(0.1, 0.2)
    box = pendepth.Shape3.box(0.15, 0.05, 0.1)
    pair = pendepth.Pair3(cyl, box)
    m = pair.minimum([0.03, 0.0, 0.0])  # sigma = min(X + R - ox, Y + R, H + Z) = 0.15
    assert m.overlapping
    assert m.lower_bound <= 0.15 * (1 + 1e-15) and m.upper_bound >= 0.15 * (1 - 1e-15)
    assert m.upper_bound - m.lower_bound <= 1e-12 * 0.15
    s = pendepth.Pair3(pendepth.Shape3.ellipsoid(0.1, 0.1, 0.1), box).signed_distance([0.5, 0.0, 0.0])
    exact = pendepth.Pair3(pendepth.Shape3.sphere(0.1), box).signed_distance([0.5, 0.0, 0.0]).distance
    assert s.lower_bound <= exact <= s.upper_bound
    c = pendepth.Pair3(pendepth.Shape3.cone(0.1, 0.2), box).cast([1.0, 0.0, 0.0], [-1.0, 0.0, 0.0])
    assert c.hit and 0.7 < c.distance < 0.8
    for shape in (cyl, pendepth.Shape3.cone(0.1, 0.2, "tip"), pendepth.Shape3.ellipsoid(0.1, 0.2, 0.3),
                  pendepth.Shape3.rounded(cyl, 0.01, "soft")):
        t = pickle.loads(pickle.dumps(shape))
        assert (t.name, t.radius, t.dimension) == (shape.name, shape.radius, shape.dimension)
        q = pendepth.Pair3(t, box).minimum([0.03, 0.01, 0.0])
        assert q.depth == pendepth.Pair3(shape, box).minimum([0.03, 0.01, 0.0]).depth
    with pytest.raises(pendepth.InvalidInput, match="half height 0"):
        pendepth.Shape3.cone(1.0, 0.0)
