"""pendepth.dask: batches over the partitions of a dask array (or dataframe) of placements.

    import dask.array as da, pendepth, pendepth.dask
    offsets = da.from_array(big_numpy_array, chunks=(1_000_000, 2))    # (N, 2)
    r = pendepth.dask.minimum(pair, offsets).compute()                  # a numpy record array
    r["depth"], r["translation"], r["overlapping"]

Each partition is one call of the pair's batch (threads=`threads` per partition: 1 by default,
so that a cluster's worker threads are the parallelism). The pair travels to the workers by
pickling (by its shapes), so the results equal the in-process batch bit for bit.

Results are dask arrays with a structured dtype, one record per placement: 2D fields depth,
translation (2,), normal (2,), witness_p (2,), witness_q (2,), overlapping; 3D fields depth,
translation, normal, facet_normal, witness_p, witness_q (3,), lower_bound, upper_bound,
overlapping. For Pair3 the placements are (N, 3) translations or (N, 7) translations followed
by quaternions w, x, y, z.
"""
import numpy as np
import dask.array as da

from . import _pendepth

DTYPE2 = np.dtype([("depth", "f8"), ("translation", "f8", (2,)), ("normal", "f8", (2,)),
                   ("witness_p", "f8", (2,)), ("witness_q", "f8", (2,)), ("overlapping", "?")])
DTYPE3 = np.dtype([("depth", "f8"), ("translation", "f8", (3,)), ("normal", "f8", (3,)),
                   ("facet_normal", "f8", (3,)), ("witness_p", "f8", (3,)), ("witness_q", "f8", (3,)),
                   ("lower_bound", "f8"), ("upper_bound", "f8"), ("overlapping", "?")])


def records(result):
    """A Depth2Result / Depth3Result batch as a numpy structured array (one record per answer)."""
    dtype = DTYPE2 if isinstance(result, _pendepth.Depth2Result) else DTYPE3
    out = np.empty(len(np.atleast_1d(result.depth)), dtype=dtype)
    for name in dtype.names:
        out[name] = getattr(result, name)
    return out


def _as_array(placements, width):
    if hasattr(placements, "to_dask_array"):  # a dask dataframe: its columns in order
        placements = placements.to_dask_array(lengths=True)
    x = da.asarray(placements)
    if x.ndim != 2 or x.shape[1] not in width:
        raise _pendepth.InvalidInput(
            f"placements: expected an (N, {' or '.join(map(str, width))}) dask array, got shape {x.shape}")
    return x.astype(np.float64).rechunk({1: -1})


def _block2(x, pair, method, direction, threads):
    if method == "minimum":
        r = pair.minimum(x, threads=threads)
    else:
        d = x[:, 2:4] if direction is None else direction
        r = getattr(pair, method)(np.ascontiguousarray(x[:, :2]), d, threads=threads)
    return records(r)


def _block3(x, pair, method, direction, threads):
    rot = x[:, 3:7] if x.shape[1] == 7 else None
    t = np.ascontiguousarray(x[:, :3])
    if method == "minimum":
        r = pair.minimum(t, rot, threads=threads)
    else:
        d = x[:, -3:] if direction is None else direction
        r = getattr(pair, method)(t, np.ascontiguousarray(d), rot, threads=threads)
    return records(r)


def _map(pair, placements, method, direction, threads):
    is3 = isinstance(pair, _pendepth.Pair3)
    if is3:
        width = (3, 7) if direction is not None or method == "minimum" else (6, 10)
    else:
        width = (2,) if direction is not None or method == "minimum" else (4,)
    x = _as_array(placements, width)
    if direction is not None:
        direction = np.asarray(direction, dtype=np.float64)
    block = _block3 if is3 else _block2
    return x.map_blocks(block, pair, method, direction, threads, drop_axis=1,
                        dtype=DTYPE3 if is3 else DTYPE2, meta=np.empty((0,), DTYPE3 if is3 else DTYPE2))


def minimum(pair, placements, threads=1):
    """sigma for every placement: Pair2 -> (N, 2) offsets; Pair3 -> (N, 3) translations or
    (N, 7) translation + quaternion (w, x, y, z). Returns a dask array of records (DTYPE2 /
    DTYPE3), equal to records(pair.minimum(...)) bit for bit. Bad placements raise
    pendepth.InvalidInput when the partition holding them is computed."""
    return _map(pair, placements, "minimum", None, threads)


def along(pair, placements, direction=None, threads=1):
    """sigma_d for every placement: direction=None takes it from the last 2 (3) columns of
    placements ((N, 4): x, y, dx, dy; 3D (N, 6) or (N, 10)), else one direction for all."""
    return _map(pair, placements, "along", direction, threads)


def separation(pair, placements, direction=None, threads=1):
    """Complete separation along d, arguments as along."""
    return _map(pair, placements, "separation", direction, threads)
