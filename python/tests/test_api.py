"""The API contract of issue 15: shapes, pairs, result shapes, batches equal to single calls
bit for bit, errors, pickling, shapely input, 3D."""
import pickle
import types

import numpy as np
import pytest

import pendepth
from conftest import DATA, offsets_for

ENGINES = ["convex", "polygon-convex", "convex-polygon", "pair-per-query", "no-fit-polygon"]
FIELDS2 = ["depth", "translation", "normal", "witness_p", "witness_q", "feature_p", "feature_q", "overlapping"]
FIELDS3 = ["depth", "translation", "normal", "facet_normal", "witness_p", "witness_q", "feature_p", "feature_q",
           "lower_bound", "upper_bound", "candidates", "overlapping"]


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def test_pairs_cover_every_engine(pairs):
    for name, pair in pairs.items():
        assert pair.engine == name


def test_shape2_inputs(shapes):
    sq = pendepth.Shape2.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")
    assert sq.is_convex and len(sq) == 4 and sq.hole_count == 0
    holed = pendepth.Shape2(np.array([[0, 0], [4, 0], [4, 4], [0, 4]]), holes=[np.array([[1, 1], [1, 2], [2, 2], [2, 1]])],
                            name="holed")
    assert not holed.is_convex and holed.hole_count == 1 and holed.name == "holed"
    rings = holed.rings()
    assert len(rings) == 2 and rings[0].shape == (4, 2)
    # lists are fine too, and the closing vertex is optional
    assert len(pendepth.Shape2([[0, 0], [1, 0], [1, 1], [0, 0]])) == 3
    assert holed.input_vertex(0)[0] in (0, 1)
    assert "holed" in repr(holed)


def test_shapely_polygon_input():
    shapely_geometry = pytest.importorskip("shapely.geometry")
    poly = shapely_geometry.Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 2), (2, 2), (2, 1)]])
    s = pendepth.Shape2(poly, name="shapely")
    ref = pendepth.Shape2(np.array([[0, 0], [4, 0], [4, 4], [0, 4]]), holes=[np.array([[1, 1], [1, 2], [2, 2], [2, 1]])])
    assert s.hole_count == 1
    for a, b in zip(s.rings(), ref.rings()):
        assert np.array_equal(a, b)
    bar = pendepth.Shape2(np.array([[0, 0], [0.5, 0], [0.5, 0.5], [0, 0.5]]))
    t = np.array([[0.75, 0.75], [2.5, 2.5], [-1, -1]])
    assert same_bits(pendepth.Pair2(s, bar).minimum(t).depth, pendepth.Pair2(ref, bar).minimum(t).depth)


def test_duck_typed_polygon_input():
    ring = lambda pts: types.SimpleNamespace(coords=pts)  # noqa: E731
    poly = types.SimpleNamespace(exterior=ring([(0, 0, 9), (3, 0, 9), (3, 3, 9), (0, 3, 9)]), interiors=[])
    s = pendepth.Shape2(poly)  # z is dropped
    assert s.is_convex and len(s) == 4


def test_single_point_shapes(pairs):
    pair = pairs["convex"]
    r = pair.minimum(np.array([2.5, 2.0]))
    assert isinstance(r.depth, np.floating) and np.ndim(r.depth) == 0
    for f in ["translation", "normal", "witness_p", "witness_q"]:
        assert getattr(r, f).shape == (2,)
    assert isinstance(r.overlapping, (bool, np.bool_))
    assert r.kind == "minimum" and r.engine == "convex"
    assert isinstance(pair.overlapping([2.5, 2.0]), bool)
    b = pair.minimum(np.array([[2.5, 2.0]]))
    assert b.depth.shape == (1,) and b.translation.shape == (1, 2) and b.overlapping.dtype == np.bool_
    assert b.depth[0] == r.depth and np.array_equal(b.translation[0], r.translation)


def test_batch_shapes(pairs):
    pair = pairs["polygon-convex"]
    t = offsets_for(pair, 50)
    r = pair.along(t, [1.0, 0.5])
    assert len(r) == 50 and r.kind == "directional"
    assert r.depth.shape == (50,) and r.overlapping.shape == (50,)
    for f in ["translation", "normal", "witness_p", "witness_q"]:
        assert getattr(r, f).shape == (50, 2) and getattr(r, f).dtype == np.float64
    assert r.feature_p.shape == (50, 2)
    assert pair.overlapping(t).shape == (50,)
    assert pair.minimum(np.empty((0, 2))).depth.shape == (0,)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("threads", [None, 1, 2])
def test_batch_equals_single_bit_for_bit(pairs, engine, threads):
    pair = pairs[engine]
    t = offsets_for(pair, 40 if engine == "pair-per-query" else 120, seed=1)
    rng = np.random.default_rng(2)
    d = rng.normal(size=t.shape)
    for name, args in [("minimum", ()), ("along", (d,)), ("separation", (d,))]:
        batch = getattr(pair, name)(t, *args, threads=threads)
        for i in range(len(t)):
            one = getattr(pair, name)(t[i], *(a[i] for a in args))
            for f in FIELDS2:
                assert same_bits(getattr(batch, f)[i], getattr(one, f)), (name, i, f)
    ov = pair.overlapping(t, threads=threads)
    assert [pair.overlapping(x) for x in t] == list(ov)
    assert np.array_equal(ov, pair.minimum(t).overlapping)


def test_direction_broadcast(pairs):
    pair = pairs["convex"]
    t = offsets_for(pair, 30)
    one = pair.along(t, np.array([0.3, 1.0]))
    many = pair.along(t, np.tile([0.3, 1.0], (30, 1)))
    for f in FIELDS2:
        assert same_bits(getattr(one, f), getattr(many, f))


def test_progress_bar(pairs, capsys):
    pair = pairs["convex"]
    t = offsets_for(pair, 3000)
    with_bar = pair.minimum(t, progress=True)
    err = capsys.readouterr().err
    assert "pendepth [" in err and "3000/3000" in err
    plain = pair.minimum(t)
    for f in FIELDS2:
        assert same_bits(getattr(with_bar, f), getattr(plain, f))
    d = np.tile([1.0, 0.0], (3000, 1))
    assert same_bits(pair.along(t, d, progress=True).depth, pair.along(t, d).depth)
    capsys.readouterr()
    bad = t.copy()
    bad[2500] = np.nan
    with pytest.raises(pendepth.InvalidInput, match="placement 2500"):
        pair.minimum(bad, progress=True)
    assert capsys.readouterr().err == ""  # checked whole before anything ran


def test_errors_raise_invalid_input_with_the_message(pairs):
    assert issubclass(pendepth.InvalidInput, ValueError)
    with pytest.raises(pendepth.InvalidInput, match=r"bow tie: ring 0 \(outer\): self-intersecting"):
        pendepth.Shape2(np.array([[0, 0], [4, 4], [4, 0], [0, 4]]), name="bow tie")
    with pytest.raises(ValueError, match="bad"):
        pendepth.Shape2.from_wkt("POLYGON ((0 0, 1 0", name="bad")
    with pytest.raises(pendepth.InvalidInput, match="nowhere.wkt"):
        pendepth.Shape2.from_file("/nowhere.wkt")
    with pytest.raises(pendepth.InvalidInput, match=r"expected an \(n, 2\) array"):
        pendepth.Shape2(np.zeros((4, 3)))
    pair = pairs["convex"]
    t = np.array([[1.0, 1.0], [np.inf, 0.0]])
    with pytest.raises(pendepth.InvalidInput, match="batch: placement 1"):
        pair.minimum(t)
    with pytest.raises(pendepth.InvalidInput, match="direction 0 is zero"):
        pair.along([[1.0, 1.0]], [0.0, 0.0])
    with pytest.raises(pendepth.InvalidInput, match="3 directions for 2 placements"):
        pair.along(np.zeros((2, 2)), np.ones((3, 2)))
    with pytest.raises(pendepth.InvalidInput, match=r"offsets: expected an \(N, 2\) array"):
        pair.minimum(np.zeros((3, 3)))
    with pytest.raises(pendepth.InvalidInput, match="prepare must be"):
        pendepth.Pair2(pair.P, pair.Q, prepare="eager")
    with pytest.raises(pendepth.InvalidInput, match="threads"):
        pair.minimum(np.zeros((1, 2)), threads=-1)
    with pytest.raises(pendepth.InvalidInput):
        pendepth.Shape3.hull(np.zeros((5, 3)))  # flat
    with pytest.raises(pendepth.InvalidInput, match="nowhere.obj"):
        pendepth.Shape3.from_file("/nowhere.obj")


def test_docstrings_state_the_contracts():
    for f in [pendepth.Pair2.minimum, pendepth.Pair2.along, pendepth.Pair2.separation, pendepth.Pair2.overlapping]:
        assert "InvalidInput" in f.__doc__
    assert "translation" in pendepth.Pair2.__doc__ and "world" in pendepth.Pair2.__doc__
    assert "w, x, y, z" in pendepth.Pair3.__doc__
    assert "sigma" in pendepth.Pair3.minimum.__doc__


def test_type_stubs_cover_the_api():
    import pathlib
    stub = pathlib.Path(pendepth.__file__).with_name("__init__.pyi").read_text()
    for name in pendepth.__all__:
        assert name in stub, name
    for name in ["minimum", "along", "separation", "overlapping", "from_wkt", "hull", "from_file", "lower_bound"]:
        assert f"def {name}" in stub or f"{name}:" in stub, name


def test_pickle_round_trips(shapes, pairs, pair3):
    for s in shapes.values():
        s2 = pickle.loads(pickle.dumps(s))
        assert s2.name == s.name and len(s2) == len(s) and s2.is_convex == s.is_convex
        for a, b in zip(s.rings(), s2.rings()):
            assert np.array_equal(a, b)
    for pair in pairs.values():
        p2 = pickle.loads(pickle.dumps(pair))
        assert p2.engine == pair.engine and p2.prepare == pair.prepare
        t = offsets_for(pair, 30, seed=5)
        a, b = pair.minimum(t), p2.minimum(t)
        for f in FIELDS2:
            assert same_bits(getattr(a, f), getattr(b, f))
    q3 = pickle.loads(pickle.dumps(pair3))
    assert np.array_equal(q3.P.vertices, pair3.P.vertices) and np.array_equal(q3.Q.vertices, pair3.Q.vertices)
    t = np.random.default_rng(1).normal(size=(20, 3))
    a, b = pair3.minimum(t), q3.minimum(t)
    # The hull is rebuilt from the vertices: the same polytope and the same answers; only the
    # numbering of edges and faces in feature_p / feature_q may differ (their kinds do not).
    for f in FIELDS3:
        if f.startswith("feature"):
            assert same_bits(getattr(a, f)[:, 0], getattr(b, f)[:, 0])
        else:
            assert same_bits(getattr(a, f), getattr(b, f)), f


def test_no_fit_polygon(shapes, pairs):
    n = pendepth.no_fit_polygon(shapes["square"], shapes["bar"])
    assert len(n.polygons) == 1 and len(n.polygons[0]) == 1
    assert np.array_equal(np.sort(n.polygons[0][0], axis=0)[[0, -1]], [[-2, -1], [4, 4]])
    m = pairs["no-fit-polygon"].no_fit_polygon()
    assert len(m.polygons) >= 1 and m.slits.shape[1:] == (2, 2) and m.points.shape[1:] == (2,)


def test_pair3(pair3):
    rng = np.random.default_rng(4)
    t = rng.normal(size=(50, 3))
    q = rng.normal(size=(50, 4))
    r = pair3.minimum(t, rotations=q)
    assert r.depth.shape == (50,) and r.translation.shape == (50, 3) and r.kind == "minimum"
    assert np.array_equal(r.lower_bound, r.depth) and np.array_equal(r.upper_bound, r.depth)
    assert np.allclose(np.linalg.norm(r.translation, axis=1), r.depth)
    for i in range(0, 50, 7):
        one = pair3.minimum(t[i], q[i])
        for f in FIELDS3:
            assert same_bits(getattr(r, f)[i], getattr(one, f))
    a = pair3.along(t, [0.0, 0.0, 2.0], rotations=q, threads=1)
    assert np.all(a.depth >= r.depth * (1 - 1e-12) - 1e-12)
    assert np.array_equal(a.overlapping, r.overlapping)
    assert np.array_equal(pair3.overlapping(t, q), r.overlapping)
    sep = pair3.separation(t, [0.0, 0.0, 2.0], rotations=q, threads=1)
    assert sep.kind == "separation" and sep.depth.tobytes() == a.depth.tobytes()
    one = pair3.separation(t[3], [0.0, 0.0, 2.0], q[3])
    assert one.kind == "separation" and one.depth.tobytes() == a.depth[3].tobytes()
    single = pair3.along(t[0], [0, 0, 1])
    assert np.ndim(single.depth) == 0 and single.witness_p.shape == (3,)
    with pytest.raises(pendepth.InvalidInput, match="zero quaternion"):
        pair3.minimum(t[:2], rotations=np.zeros(4))
    with pytest.raises(pendepth.InvalidInput, match="batch: pose 1 rotation"):
        pair3.minimum(t[:2], rotations=[[1, 0, 0, 0], [np.nan, 0, 0, 0]], progress=True)


def test_shape3_from_file(tmp_path):
    f = tmp_path / "tet.off"
    f.write_text("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")  # closed
    s = pendepth.Shape3.from_file(str(f), name="tet")
    assert len(s) == 4 and s.vertices.shape == (4, 3) and s.triangles.shape == (4, 3)
    p = pendepth.Pair3(s, s)
    assert p.minimum([0.1, 0.1, 0.1]).overlapping
    assert not p.overlapping([5.0, 0.0, 0.0])


def test_shape3_from_file_meshes(tmp_path):
    # An L-shaped prism whose top and bottom are non-convex hexagons: rejected as faces (give
    # triangles); hull=True takes the hull of the vertices.
    f = tmp_path / "l.off"
    f.write_text("OFF\n12 8 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n"
                 "0 0 1\n2 0 1\n2 1 1\n1 1 1\n1 2 1\n0 2 1\n"
                 "6 0 5 4 3 2 1\n6 6 7 8 9 10 11\n4 0 1 7 6\n4 1 2 8 7\n4 2 3 9 8\n4 3 4 10 9\n4 4 5 11 10\n4 5 0 6 11\n")
    with pytest.raises(pendepth.InvalidInput, match="not a strictly convex polygon"):
        pendepth.Shape3.from_file(str(f), name="L")
    h = pendepth.Shape3.from_file(str(f), name="L", hull=True)
    assert h.is_convex and len(h) == 10


def test_data_dir_exists():
    assert (DATA / "octagon.wkt").exists()
