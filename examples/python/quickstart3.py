"""Quickstart (3D, Python): convex hulls, minimum and directional depth, rotations, a batch."""
import numpy as np
import pendepth

rng = np.random.default_rng(1)
cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
ball = rng.normal(size=(200, 3))
ball /= np.linalg.norm(ball, axis=1)[:, None] * 2  # points on a sphere of radius 1/2

A = pendepth.Shape3.hull(cube, name="cube")
B = pendepth.Shape3.hull(ball, name="ball")
pair = pendepth.Pair3(A, B)  # P = the cube at the identity, Q = the ball posed per query

r = pair.minimum([0.9, 0.5, 0.5])  # the ball centred at (0.9, 0.5, 0.5): pokes out of the face x = 1
print(f"sigma   = {r.depth!r}  move Q by {r.translation}  (bounds {r.lower_bound!r}, {r.upper_bound!r})")
d = pair.along([0.9, 0.5, 0.5], [0, 0, 1])
print(f"sigma_d = {d.depth!r}  along z")

# A batch of poses: translations (N, 3) and quaternions (N, 4) as w, x, y, z.
N = 2000
ts = rng.uniform(-0.5, 1.5, size=(N, 3))
qs = rng.normal(size=(N, 4))
batch = pair.minimum(ts, rotations=qs)
print(f"batch   : {int(batch.overlapping.sum())} of {N} poses overlap")
assert batch.depth[7] == pair.minimum(ts[7], rotations=qs[7]).depth
assert np.all(batch.lower_bound == batch.upper_bound)
assert 0.5 < r.depth <= 0.6 and d.depth >= r.depth  # the hull is inside the radius-1/2 sphere
