"""Batches release the GIL: two Python threads running a batch each (threads=1) finish >= 1.6x
faster than one after the other on 2 cores; and Python code keeps running during a batch."""
import os
import threading
import time

import pytest

import pendepth
from conftest import DATA, offsets_for


@pytest.fixture(scope="module")
def slow_pair():
    # Two non-convex shapes answered per query (PairDepth2): ~0.1 ms per query, so the GIL-held
    # parts (argument and result conversion) are negligible against the batch.
    P = pendepth.Shape2.from_file(str(DATA / "trousers_item0.wkt"))
    Q = pendepth.Shape2.from_file(str(DATA / "plate_with_hole.wkt"))
    return pendepth.Pair2(P, Q, prepare="queries")


def sized_batch(pair, seconds):
    """Offsets for a threads=1 batch of about `seconds`."""
    t = offsets_for(pair, 200, seed=11)
    t0 = time.perf_counter()
    pair.minimum(t, threads=1)
    per = (time.perf_counter() - t0) / len(t)
    return offsets_for(pair, max(200, int(seconds / per)), seed=12)


def test_python_runs_during_a_batch(slow_pair):
    t = sized_batch(slow_pair, 0.4)
    worker = threading.Thread(target=lambda: slow_pair.minimum(t, threads=1))
    count = 0
    worker.start()
    while worker.is_alive():  # would not run at all while a batch held the GIL
        count += 1
    worker.join()
    assert count > 1000


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="needs 2 cores")
def test_two_threads_run_batches_in_parallel(slow_pair):
    t = sized_batch(slow_pair, 0.3)
    ref = slow_pair.minimum(t, threads=1)
    results = [None, None]

    def run(k, threads=1):
        results[k] = slow_pair.minimum(t, threads=threads)

    py_ratios, cpp_ratios = [], []
    for attempt in range(5):  # best of several: the machine is shared
        w0 = time.perf_counter()
        run(0)
        run(1)
        seq = time.perf_counter() - w0
        threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
        w0 = time.perf_counter()
        for th in threads:
            th.start()
        for th in threads:
            th.join()
        py_ratios.append(seq / (time.perf_counter() - w0))
        for r in results:
            assert r.depth.tobytes() == ref.depth.tobytes()
        # the reference: the C++ batch on 2 threads, under the same conditions
        w0 = time.perf_counter()
        run(0, threads=2)
        run(1, threads=2)
        cpp_ratios.append(seq / (time.perf_counter() - w0))
        if max(py_ratios) >= 1.6 and attempt >= 2:
            break
    if max(py_ratios) < 1.6 and max(cpp_ratios) < 1.6:
        # Two cores are not ours (other processes hold them): not even the C++ batch on 2
        # threads gets 1.6x, so two Python threads cannot show it either.
        pytest.skip(f"machine busy: C++ 2-thread batch speed-up {max(cpp_ratios):.2f}, "
                    f"two Python threads {max(py_ratios):.2f}")
    assert max(py_ratios) >= 1.6, f"two Python threads {py_ratios}, C++ batch on 2 threads {cpp_ratios}"
