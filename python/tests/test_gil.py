"""Batches release the GIL: Python code keeps running during a batch, and a second batch runs
while the first is still running. Orderings, not timings: the 2-core speed-up of two Python
threads is measured in bench/bench_python.py.

Python hands the GIL to another thread every `sys.getswitchinterval()` seconds even when a thread
never releases it; the tests raise that interval to a minute, so the main thread can run during a
batch only if the batch released the GIL."""
import sys
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


@pytest.fixture
def no_forced_switch():
    before = sys.getswitchinterval()
    sys.setswitchinterval(60.0)
    yield
    sys.setswitchinterval(before)


def sized_batch(pair, seconds):
    """Offsets for a threads=1 batch of about `seconds`."""
    t = offsets_for(pair, 200, seed=11)
    t0 = time.perf_counter()
    pair.minimum(t, threads=1)
    per = (time.perf_counter() - t0) / len(t)
    return offsets_for(pair, max(200, int(seconds / per)), seed=12)


def start_in_batch(run):
    """Starts `run` in a thread and returns once it has had the GIL to enter its batch."""
    started = threading.Event()

    def body():
        started.set()
        run()

    worker = threading.Thread(target=body)
    worker.start()
    started.wait()
    time.sleep(0.05)  # releases the GIL: the worker goes on into its batch (~1 s long)
    return worker


def test_python_runs_during_a_batch(slow_pair, no_forced_switch):
    t = sized_batch(slow_pair, 1.0)
    worker = start_in_batch(lambda: slow_pair.minimum(t, threads=1))
    count = 0
    while worker.is_alive():  # with the GIL held by the batch, this resumes only after it
        count += 1
        time.sleep(0)  # lets the worker take the GIL back when its batch returns
    worker.join()
    assert count > 1000


def test_two_batches_run_at_the_same_time(slow_pair, no_forced_switch):
    """A short batch started while a long one runs in another thread finishes first: neither the
    GIL nor a lock of the library serialises batches."""
    long_t = sized_batch(slow_pair, 1.0)
    short_t = long_t[:max(20, len(long_t) // 50)]
    ref_long, ref_short = slow_pair.minimum(long_t[:200], threads=1), slow_pair.minimum(short_t, threads=1)
    out = {}
    worker = start_in_batch(lambda: out.setdefault("long", slow_pair.minimum(long_t, threads=1)))
    short = slow_pair.minimum(short_t, threads=1)
    long_still_running = worker.is_alive()
    worker.join()
    assert long_still_running, "the short batch waited for the long one"
    assert short.depth.tobytes() == ref_short.depth.tobytes()
    assert out["long"].depth[:200].tobytes() == ref_long.depth.tobytes()
