"""Shared fixtures of the Python tests. Run with Debian's python3 against the build tree:
PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests (scripts/test.sh does)."""
import pathlib

import matplotlib
import numpy as np
import pytest
from hypothesis import settings

matplotlib.use("Agg")

# No example database in the source tree; no per-example deadline on a shared 2-core machine.
settings.register_profile("pendepth", database=None, deadline=None, max_examples=60)
settings.load_profile("pendepth")

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "examples" / "data"

import pendepth  # noqa: E402


def star(rng, n, convex=False, radius=1.0, center=(0.0, 0.0)):
    """A random simple polygon, star-shaped around `center` (convex: points on an ellipse)."""
    n = max(n, 4)  # one angle per sector of 2 pi / n: consecutive gaps < pi, so the star is simple
    ang = 2 * np.pi * (np.arange(n) + rng.uniform(0.1, 0.9, n)) / n
    if convex:
        a, b = radius * rng.uniform(0.5, 1.5), radius * rng.uniform(0.5, 1.5)
        pts = np.column_stack([a * np.cos(ang), b * np.sin(ang)])
    else:
        r = radius * rng.uniform(0.3, 1.0, len(ang))
        pts = np.column_stack([r * np.cos(ang), r * np.sin(ang)])
    return pts + np.asarray(center)


@pytest.fixture(scope="session")
def shapes():
    """Named shapes covering every 2D engine."""
    rng = np.random.default_rng(7)
    return {
        "square": pendepth.Shape2(np.array([[0, 0], [4, 0], [4, 4], [0, 4]]), name="square"),
        "bar": pendepth.Shape2(np.array([[0, 0], [2, 0], [2, 1], [0, 1]]), name="bar"),
        "octagon": pendepth.Shape2.from_file(str(DATA / "octagon.wkt"), name="octagon"),
        "hexagon": pendepth.Shape2.from_file(str(DATA / "hexagon.wkt"), name="hexagon"),
        "plate": pendepth.Shape2.from_file(str(DATA / "plate_with_hole.wkt"), name="plate"),
        "item0": pendepth.Shape2.from_file(str(DATA / "trousers_item0.wkt"), name="item0"),
        "star": pendepth.Shape2(star(rng, 12), name="star"),
    }


@pytest.fixture(scope="session")
def pairs(shapes):
    """One pair per engine."""
    s = shapes
    return {
        "convex": pendepth.Pair2(s["octagon"], s["hexagon"]),
        "polygon-convex": pendepth.Pair2(s["item0"], s["hexagon"]),
        "convex-polygon": pendepth.Pair2(s["hexagon"], s["plate"]),
        "pair-per-query": pendepth.Pair2(s["item0"], s["plate"], prepare="queries"),
        "no-fit-polygon": pendepth.Pair2(s["item0"], s["star"], prepare="full"),
    }


def offsets_for(pair, n, seed=0):
    """Offsets spread over the configuration space of the pair (many overlapping)."""
    rng = np.random.default_rng(seed)
    p = np.concatenate(pair.P.rings())
    q = np.concatenate(pair.Q.rings())
    lo = p.min(axis=0) - q.max(axis=0)
    hi = p.max(axis=0) - q.min(axis=0)
    return rng.uniform(lo, hi, size=(n, 2))


@pytest.fixture(scope="session")
def pair3():
    rng = np.random.default_rng(3)
    A = pendepth.Shape3.hull(rng.normal(size=(60, 3)), name="A")
    B = pendepth.Shape3.hull(rng.normal(size=(40, 3)) * 0.7, name="B")
    return pendepth.Pair3(A, B)
