"""Pictures: pendepth.plot (matplotlib, Agg), _repr_svg_, and the progress bar on stderr."""
import matplotlib.pyplot as plt
import numpy as np
import pytest

import pendepth


@pytest.mark.parametrize("engine", ["convex", "polygon-convex", "no-fit-polygon"])
def test_plot_two_panels(pairs, engine, tmp_path):
    pair = pairs[engine]
    t = np.mean(np.concatenate(pair.P.rings()), axis=0) - np.mean(np.concatenate(pair.Q.rings()), axis=0)
    fig, axes, r = pendepth.plot(pair, t)
    assert len(axes) == 2 and r.kind == "minimum"
    assert len(axes[0].patches) >= 2 and len(axes[1].patches) >= 1  # P, Q (+ moved Q); the no-fit polygon
    fig.savefig(tmp_path / "p.png")
    assert (tmp_path / "p.png").stat().st_size > 1000
    plt.close(fig)
    fig, axes, r = pendepth.plot(pair, t, direction=[0, 1])
    assert r.kind == "directional"
    plt.close(fig)


def test_plot_into_given_axes(pairs):
    fig, ax = plt.subplots()
    f, axes, r = pendepth.plot(pairs["convex"], [2.5, 2.0], ax=ax)
    assert f is fig and axes == (ax,)
    fig2, (a, b) = plt.subplots(1, 2)
    _, axes, r = pendepth.plot(pairs["convex"], [2.5, 2.0], direction=[1, 0], ax=(a, b), separation=True)
    assert axes == (a, b) and r.kind == "separation"
    plt.close("all")
    with pytest.raises(pendepth.InvalidInput):
        pendepth.plot(pairs["convex"], [np.nan, 0.0])


def test_repr_svg(shapes, pairs):
    svg = shapes["plate"]._repr_svg_()
    assert svg.startswith("<svg") and svg.endswith("</svg>") and "evenodd" in svg
    assert svg.count(" Z") == 2  # outer ring and hole
    r = pairs["convex"].minimum([2.5, 2.0])
    assert r.depth > 0 and r._repr_svg_().count("<path") == 3  # P, Q at t, Q moved
    assert pairs["convex"].minimum(np.zeros((3, 2)))._repr_svg_().startswith("<svg")


def test_progress_3d(pair3, capsys):
    t = np.random.default_rng(0).normal(size=(600, 3))
    a = pair3.minimum(t, progress=True)
    assert "600/600" in capsys.readouterr().err
    assert a.depth.tobytes() == pair3.minimum(t).depth.tobytes()
    b = pair3.along(t, [0, 0, 1], progress=True)
    assert b.depth.tobytes() == pair3.along(t, [0, 0, 1]).depth.tobytes()
    assert np.array_equal(pair3.overlapping(t, progress=True), a.overlapping)
