"""pendepth: exact penetration depth of 2D and 3D shapes.

The Python face of the C++ front door (include/pendepth/pendepth.hpp):

    import numpy as np, pendepth
    P = pendepth.Shape2.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4))")
    Q = pendepth.Shape2(np.array([[0, 0], [2, 0], [2, 1], [0, 1]]))
    pair = pendepth.Pair2(P, Q)                  # P fixed, Q moving
    r = pair.minimum(np.array([[1.0, 1.0], [3.5, 3.5]]))
    r.depth, r.translation                       # (N,), (N, 2): the move to apply to Q

Conventions (docs/design.md section 1): P is fixed and Q is placed at the offset t (posed, in
3D); the translation is the move to apply to Q after t to separate the interiors; depth is its
length; touching is not overlapping (depth 0); everything is in world coordinates. Bad input
raises pendepth.InvalidInput, a ValueError carrying the C++ message. Batches release the GIL,
run on every core (threads=None) or on `threads` threads, and equal the single calls bit for
bit. See docs/python.md.

Submodules: pendepth.dask (batches over the partitions of a dask array), pendepth.plot (a
function: matplotlib pictures of a 2D pair).
"""
from ._pendepth import (  # noqa: F401
    FEATURE_EDGE,
    FEATURE_FACE,
    FEATURE_NONE,
    FEATURE_VERTEX,
    Depth2Result,
    Depth3Result,
    InvalidInput,
    Pair2,
    Pair3,
    Shape2,
    Shape3,
    __version__,
    approximate_minimum_depth,
    generalized_depth,
    no_fit_polygon,
    trajectory,
    no_fit_polygons,
    read_nesting_instance,
)
from ._plot import plot  # noqa: F401
from . import _svg

Shape2._repr_svg_ = _svg.shape_svg
Depth2Result._repr_svg_ = _svg.result_svg

__all__ = [
    "Shape2", "Pair2", "Shape3", "Pair3", "Depth2Result", "Depth3Result", "InvalidInput",
    "no_fit_polygon", "no_fit_polygons", "read_nesting_instance", "approximate_minimum_depth", "generalized_depth", "trajectory", "plot", "FEATURE_NONE", "FEATURE_VERTEX", "FEATURE_EDGE", "FEATURE_FACE", "__version__",
]


def __getattr__(name):
    # `pendepth.dask` without an explicit `import pendepth.dask` (dask itself is imported then).
    if name == "dask":
        import importlib
        return importlib.import_module(".dask", __name__)
    raise AttributeError(f"module 'pendepth' has no attribute {name!r}")
