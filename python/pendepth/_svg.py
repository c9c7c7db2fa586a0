"""SVG pictures for Jupyter (_repr_svg_ of Shape2 and Depth2Result), no dependencies."""
import numpy as np


def _path(rings, dx=0.0, dy=0.0):
    parts = []
    for r in rings:
        r = np.asarray(r, dtype=float)
        if len(r) == 0:
            continue
        pts = " L ".join(f"{x + dx:.9g} {-(y + dy):.9g}" for x, y in r)
        parts.append(f"M {pts} Z")
    return " ".join(parts)


def _svg(items, size=240):
    """items: (rings, dx, dy, fill, stroke, opacity). y is flipped (SVG's y points down)."""
    xs, ys = [], []
    for rings, dx, dy, *_ in items:
        for r in rings:
            r = np.asarray(r, dtype=float)
            if len(r):
                xs += [r[:, 0].min() + dx, r[:, 0].max() + dx]
                ys += [r[:, 1].min() + dy, r[:, 1].max() + dy]
    if not xs:
        xs, ys = [0.0, 1.0], [0.0, 1.0]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    span = max(x1 - x0, y1 - y0) or 1.0  # a lone point: a unit view around it
    pad = 0.05 * span
    w, h = x1 - x0 + 2 * pad, y1 - y0 + 2 * pad
    stroke = span / 200
    # A point or a segment (one "ring" of 1 or 2 vertices) is drawn as a thick round stroke.
    body = "".join(
        f'<path d="{_path(rings, dx, dy)}" fill="{fill}" fill-rule="evenodd" fill-opacity="{op}" '
        f'stroke="{line}" stroke-width="{(stroke if len(rings[0]) > 2 else 6 * stroke):.6g}" stroke-linecap="round"/>'
        for rings, dx, dy, fill, line, op in items)
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size * h / w:.0f}" '
            f'viewBox="{x0 - pad:.9g} {-(y1 + pad):.9g} {w:.9g} {h:.9g}">{body}</svg>')


def shape_svg(shape):
    """The shape, holes cut out (fill rule even-odd)."""
    return _svg([(shape.rings(), 0.0, 0.0, "#4c72b0", "#1f3b63", 0.5)])


def result_svg(result):
    """P, Q at the first offset and Q after the move (the first answer of a batch)."""
    pair = result.pair
    t = np.asarray(result.offsets, dtype=float).reshape(-1, 2)
    tr = np.asarray(result.translation, dtype=float).reshape(-1, 2)
    items = [(pair.P.rings(), 0.0, 0.0, "#4c72b0", "#1f3b63", 0.5)]
    if len(t):
        items.append((pair.Q.rings(), t[0, 0], t[0, 1], "#dd8452", "#8c4a1c", 0.5))
        if np.any(tr[0] != 0):
            moved = t[0] + tr[0]
            items.append((pair.Q.rings(), moved[0], moved[1], "none", "#55a868", 1.0))
    return _svg(items)
