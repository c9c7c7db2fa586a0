"""pendepth.plot: a matplotlib picture of a 2D query, like the command line's SVG."""
import numpy as np


def _rings_patch(rings, offset, **kw):
    from matplotlib.path import Path
    from matplotlib.patches import PathPatch
    verts, codes = [], []
    for r in rings:
        r = np.asarray(r, dtype=float) + offset
        if len(r) == 0:
            continue
        verts += list(r) + [r[0]]
        codes += [Path.MOVETO] + [Path.LINETO] * (len(r) - 1) + [Path.CLOSEPOLY]
    return PathPatch(Path(np.array(verts), codes), **kw)


def plot(pair, offset, direction=None, ax=None, separation=False):
    """Draws a 2D query of `pair` (a pendepth.Pair2) at `offset` (a (2,) point).

    Left panel (workspace): P, Q placed at the offset, and Q after the move (dashed). Right panel
    (configuration space): the no-fit polygon of the pair (the boundary of M = P + (-Q) for
    convex shapes, of the overlap set O in general), the offset t and the move to t + translation.
    direction=None asks for the minimum depth (sigma), else the depth along the direction
    (sigma_d), or the complete separation with separation=True.

    ax: None (a new figure with two panels), one Axes (the workspace panel only), or a pair of
    Axes. Returns (figure, axes tuple, result). Raises pendepth.InvalidInput like the queries.
    """
    import matplotlib.pyplot as plt

    t = np.asarray(offset, dtype=float).reshape(2)
    if direction is None:
        r = pair.minimum(t)
    elif separation:
        r = pair.separation(t, np.asarray(direction, dtype=float))
    else:
        r = pair.along(t, np.asarray(direction, dtype=float))
    if ax is None:
        fig, axes = plt.subplots(1, 2, figsize=(10, 5))
    elif isinstance(ax, (tuple, list, np.ndarray)):
        axes = tuple(ax)
        fig = axes[0].figure
    else:
        axes = (ax,)
        fig = ax.figure
    axes = tuple(axes)
    tr = np.asarray(r.translation, dtype=float)

    a = axes[0]
    a.add_patch(_rings_patch(pair.P.rings(), 0.0, facecolor="#4c72b0", alpha=0.45, edgecolor="#1f3b63", label="P"))
    a.add_patch(_rings_patch(pair.Q.rings(), t, facecolor="#dd8452", alpha=0.45, edgecolor="#8c4a1c", label="Q + t"))
    if r.depth > 0:
        a.add_patch(_rings_patch(pair.Q.rings(), t + tr, facecolor="none", edgecolor="#55a868", linestyle="--",
                                 linewidth=1.5, label="Q after the move"))
        a.plot(*np.asarray(r.witness_p), "k.", markersize=6)
    a.set_title(f"{r.kind} depth {float(r.depth):.6g} ({r.engine})")
    a.set_aspect("equal")
    a.autoscale_view()
    a.legend(loc="best", fontsize="small")

    if len(axes) > 1:
        c = axes[1]
        nfp = pair.no_fit_polygon()
        for k, poly in enumerate(nfp.polygons):
            c.add_patch(_rings_patch(poly, 0.0, facecolor="#8172b3", alpha=0.3, edgecolor="#3b2f6b",
                                     label="no-fit polygon" if k == 0 else None))
        for s in nfp.slits:
            c.plot(s[:, 0], s[:, 1], color="#3b2f6b", linewidth=1.5)
        if len(nfp.points):
            c.plot(nfp.points[:, 0], nfp.points[:, 1], "o", color="#3b2f6b", markersize=3)
        c.plot([t[0]], [t[1]], "o", color="#c44e52", label="t")
        if r.depth > 0:
            c.annotate("", xy=t + tr, xytext=t, arrowprops=dict(arrowstyle="->", color="#c44e52"))
            c.plot([t[0] + tr[0]], [t[1] + tr[1]], "x", color="#c44e52", label="t + translation")
        if direction is not None:
            d = np.asarray(direction, dtype=float)
            d = d / np.hypot(*d)
            c.plot([t[0], t[0] + d[0] * max(float(r.depth), 1e-12) * 1.5],
                   [t[1], t[1] + d[1] * max(float(r.depth), 1e-12) * 1.5], ":", color="#c44e52")
        c.set_title("configuration space (placements of Q)")
        c.set_aspect("equal")
        c.autoscale_view()
        c.legend(loc="best", fontsize="small")
    return fig, axes, r
