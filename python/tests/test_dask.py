"""pendepth.dask against a distributed.LocalCluster (2 worker processes, loopback only): the
results equal the in-process batch bit for bit."""
import numpy as np
import pytest

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("distributed")

import pendepth  # noqa: E402
import pendepth.dask  # noqa: E402
from conftest import offsets_for  # noqa: E402

TIMEOUT = 180  # seconds, for the cluster start and each computation


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None,
                                       host="127.0.0.1", timeout=TIMEOUT)
    c = distributed.Client(cluster, timeout=TIMEOUT)
    try:
        yield c
    finally:
        c.close(timeout=30)
        cluster.close(timeout=30)


def test_minimum_on_a_cluster_equals_the_batch(client, pairs):
    pair = pairs["polygon-convex"]
    t = offsets_for(pair, 5000, seed=21)
    x = da.from_array(t, chunks=(700, 2))
    got = client.compute(pendepth.dask.minimum(pair, x)).result(timeout=TIMEOUT)
    ref = pendepth.dask.records(pair.minimum(t))
    assert got.dtype == pendepth.dask.DTYPE2 and got.shape == (5000,)
    assert got.tobytes() == ref.tobytes()
    assert np.array_equal(got["depth"], pair.minimum(t).depth)


def test_along_on_a_cluster_equals_the_batch(client, pairs):
    pair = pairs["no-fit-polygon"]
    rng = np.random.default_rng(3)
    t = offsets_for(pair, 3000, seed=22)
    d = rng.normal(size=t.shape)
    x = da.from_array(np.column_stack([t, d]), chunks=(500, 4))
    got = client.compute(pendepth.dask.along(pair, x)).result(timeout=TIMEOUT)
    assert got.tobytes() == pendepth.dask.records(pair.along(t, d)).tobytes()
    one = client.compute(pendepth.dask.separation(pair, da.from_array(t, chunks=(500, 2)), direction=[0, 1]))
    assert one.result(timeout=TIMEOUT).tobytes() == pendepth.dask.records(pair.separation(t, [0, 1])).tobytes()


def test_3d_on_a_cluster_equals_the_batch(client, pair3):
    rng = np.random.default_rng(4)
    x = np.column_stack([rng.normal(size=(2000, 3)), rng.normal(size=(2000, 4))])
    got = client.compute(pendepth.dask.minimum(pair3, da.from_array(x, chunks=(300, 7)))).result(timeout=TIMEOUT)
    ref = pendepth.dask.records(pair3.minimum(x[:, :3].copy(), x[:, 3:].copy()))
    assert got.dtype == pendepth.dask.DTYPE3 and got.tobytes() == ref.tobytes()
    sep = pendepth.dask.separation(pair3, da.from_array(x, chunks=(300, 7)), direction=[0, 0, 1])
    ref = pendepth.dask.records(pair3.separation(x[:, :3].copy(), [0, 0, 1], x[:, 3:].copy()))
    assert client.compute(sep).result(timeout=TIMEOUT).tobytes() == ref.tobytes()


@pytest.mark.filterwarnings("ignore:Running on a single-machine scheduler")
def test_local_scheduler(pairs):
    pair = pairs["convex"]
    t = offsets_for(pair, 1000, seed=23)
    got = pendepth.dask.minimum(pair, da.from_array(t, chunks=(128, 2))).compute(scheduler="threads")
    assert got.tobytes() == pendepth.dask.records(pair.minimum(t)).tobytes()
    with pytest.raises(pendepth.InvalidInput, match="placements"):
        pendepth.dask.minimum(pair, da.zeros((10, 3)))


@pytest.mark.filterwarnings("ignore:Running on a single-machine scheduler")
def test_dataframe_placements(pairs):
    dd = pytest.importorskip("dask.dataframe")  # needs pandas (python3-pandas)
    pd = pytest.importorskip("pandas")
    pair = pairs["convex"]
    t = offsets_for(pair, 1000, seed=24)
    frame = dd.from_pandas(pd.DataFrame({"x": t[:, 0], "y": t[:, 1]}), npartitions=3)
    got = pendepth.dask.minimum(pair, frame).compute(scheduler="sync")
    assert got.tobytes() == pendepth.dask.records(pair.minimum(t)).tobytes()
