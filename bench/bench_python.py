"""Python per-call overhead: a numpy batch against a Python loop of single calls (issue 15).

Run: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [N]
(or /usr/bin/python3 bench/bench_python.py after scripts/demo.sh installed the package).

For each pair (one per 2D engine, and a 3D pair) it times, best of 3:
  loop     one pair.minimum(t) call per placement, from Python
  batch/1  one pair.minimum(ts, threads=1) call (same thread: the per-call overhead removed)
  batch    one pair.minimum(ts) call on every core (threads=None)
and prints microseconds per query and the ratios. The batch answers equal the loop's bit for bit
(checked). Then, on the per-query pair, two Python threads each running a threads=1 batch against
the same two batches one after the other, with the C++ batch on 2 threads as the reference (the
GIL is released around the C++ call, so the threads should scale like the C++ batch).
"""
import threading
import os
import pathlib
import sys
import time

import numpy as np
import pendepth

REPO = pathlib.Path(__file__).resolve().parents[1]
DATA = REPO / "examples" / "data"


def offsets(pair, n, seed=0):
    rng = np.random.default_rng(seed)
    p, q = np.concatenate(pair.P.rings()), np.concatenate(pair.Q.rings())
    return rng.uniform(p.min(axis=0) - q.max(axis=0), p.max(axis=0) - q.min(axis=0), size=(n, 2))


def best(f, reps=3):
    t = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        t.append(time.perf_counter() - t0)
    return min(t)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    shape = lambda name: pendepth.Shape2.from_file(str(DATA / f"{name}.wkt"), name=name)  # noqa: E731
    pairs = [
        ("convex: octagon x hexagon", pendepth.Pair2(shape("octagon"), shape("hexagon")), n),
        ("polygon-convex: trousers 0 x 16", pendepth.Pair2(shape("trousers_item0"), shape("trousers_item16")), n),
        ("no-fit-polygon: trousers 0 x plate", pendepth.Pair2(shape("trousers_item0"), shape("plate_with_hole"),
                                                              prepare="full"), n),
        ("pair-per-query: trousers 0 x plate", pendepth.Pair2(shape("trousers_item0"), shape("plate_with_hole"),
                                                              prepare="queries"), max(200, n // 50)),
    ]
    print(f"pendepth {pendepth.__version__}, {os.cpu_count()} cores, N = {n} placements (σ, minimum)")
    print(f"{'pair':38s} {'N':>6s} {'loop µs':>9s} {'batch/1 µs':>11s} {'batch µs':>9s} {'loop/batch1':>12s} {'loop/batch':>11s}")
    rows = []
    for name, pair, m in pairs:
        t = offsets(pair, m)
        pair.minimum(t[:100])  # structures built on first use
        loop = best(lambda: [pair.minimum(x) for x in t])
        one = best(lambda: pair.minimum(t, threads=1))
        every = best(lambda: pair.minimum(t))
        single = [pair.minimum(x).depth for x in t[:500]]
        assert np.array_equal(np.array(single), pair.minimum(t[:500]).depth)
        rows.append((name, m, loop, one, every))
    rng = np.random.default_rng(1)
    p3 = pendepth.Pair3(pendepth.Shape3.hull(rng.normal(size=(200, 3))), pendepth.Shape3.hull(rng.normal(size=(200, 3))))
    t3 = rng.normal(size=(n // 4, 3))
    rows.append(("3D: hulls of 200 x 200 points", len(t3), best(lambda: [p3.minimum(x) for x in t3]),
                 best(lambda: p3.minimum(t3, threads=1)), best(lambda: p3.minimum(t3))))
    for name, m, loop, one, every in rows:
        print(f"{name:38s} {m:6d} {loop / m * 1e6:9.2f} {one / m * 1e6:11.2f} {every / m * 1e6:9.2f} "
              f"{loop / one:12.1f} {loop / every:11.1f}")

    two_python_threads(pairs[-1][1], offsets(pairs[-1][1], pairs[-1][2] * 6, seed=2))


def two_python_threads(pair, t):
    """Best of 5: (one after the other) / (two Python threads), and the same for the C++ batch on
    2 threads."""
    run = lambda threads=1: pair.minimum(t, threads=threads)  # noqa: E731
    seq = best(lambda: (run(), run()), reps=5)
    def both():
        th = [threading.Thread(target=run) for _ in range(2)]
        for x in th:
            x.start()
        for x in th:
            x.join()
    py = best(both, reps=5)
    cpp = best(lambda: (run(2), run(2)), reps=5)
    print(f"two Python threads, {len(t)} placements each (per-query pair): sequential {seq:.3f} s, "
          f"two threads {py:.3f} s ({seq / py:.2f}x), C++ batch on 2 threads {cpp:.3f} s ({seq / cpp:.2f}x)")


if __name__ == "__main__":
    main()
