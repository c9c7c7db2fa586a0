"""Quickstart (2D, Python): the same steps as examples/quickstart.cpp, with numpy batches.

Run: /usr/bin/python3 examples/python/quickstart.py   (after scripts/demo.sh installed pendepth)
"""
import pathlib

import numpy as np
import pendepth

data = pathlib.Path(__file__).resolve().parent.parent / "data"

# A plate with a hole (WKT) and a bar given as an (n, 2) array (either orientation).
P = pendepth.Shape2.from_wkt("POLYGON ((0 0, 8 0, 8 6, 0 6, 0 0), (2 2, 2 4, 6 4, 6 2, 2 2))", name="plate")
Q = pendepth.Shape2(np.array([[0, 0], [3, 0], [3, 1], [0, 1]]), holes=[], name="bar")

pair = pendepth.Pair2(P, Q)  # picks the engine, prepares once
t = np.array([1.0, 1.5])     # Q placed at t overlaps the rim of the hole

s = pair.minimum(t)          # one (2,) point: scalar depth, (2,) vectors
print(f"engine  = {pair.engine}")
print(f"sigma   = {s.depth!r}  move Q by {s.translation}")
a = pair.along(t, [0, 1])    # sigma_d: move up only
print(f"sigma_d = {a.depth!r}  along (0, 1)")

# A batch over every core: (N, 2) offsets, the single calls' answers bit for bit.
ts = np.column_stack([-2 + 0.01 * np.arange(1000), np.full(1000, 1.5)])
r = pair.minimum(ts)
print(f"batch   : {int(r.overlapping.sum())} of {len(ts)} placements overlap, deepest {r.depth.max()}")
assert r.depth[300] == pair.minimum(ts[300]).depth

# Shapes from files, and a non-convex pair (the no-fit polygon engine).
item0 = pendepth.Shape2.from_file(str(data / "trousers_item0.wkt"), name="item0")
plate = pendepth.Shape2.from_file(str(data / "plate_with_hole.wkt"), name="plate_with_hole")
nc = pendepth.Pair2(item0, plate)
print(f"non-convex pair: engine {nc.engine}, sigma at (20, 2) = {nc.minimum([20, 2]).depth!r}")

# Bad input raises pendepth.InvalidInput (a ValueError) with the C++ message.
try:
    pendepth.Shape2(np.array([[0, 0], [4, 4], [4, 0], [0, 4]]), name="bow tie")
except pendepth.InvalidInput as e:
    print(f"error   : {e}")

assert s.overlapping and a.depth >= s.depth
