#!/usr/bin/env bash
# Runs bench_nonconvex2 (two non-convex polygons, issue 5: pendepth's no-fit polygon NoFitPolygon2
# and per-query PairDepth2 against CGAL's reduced convolution and Clipper's MinkowskiSum, each + a
# scan of the explicit sum) and prints the markdown tables kept in docs/benchmarks.md; raw results
# go to JSON and CSV.
#
# Usage: bench/run_nonconvex2.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (nonconvex2.json, nonconvex2.csv, nonconvex2.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.1)
#              REPS      repetitions; the tables use the median (default 1)
#              FILTER    --benchmark_filter regex (default: everything)
#              PENDEPTH_BENCH_N                 comma list of star sizes n = m (default 10,30,100,300)
#              PENDEPTH_BENCH_PEER_BUDGET       largest n·m for the CGAL peer (default 1e5)
#              PENDEPTH_BENCH_CLIPPER_BUDGET    largest n·m for the Clipper peer (default 1e4)
#              PENDEPTH_BENCH_NFP_BUDGET        largest n·m for NoFitPolygon2 (default 1e5)
#              PENDEPTH_BENCH_PAIR_SIGMA_BUDGET largest n·m for PairDepth2 σ (default 1e3)
# Times are CPU time (less sensitive to other processes than wall time); build times in the
# tables are per pair (a nesting benchmark builds every pair of its instance per iteration).
set -euo pipefail
# Shared prologue: bench/run_common.sh; tables: bench/tables_nonconvex2.py.
source "$(dirname "$0")/run_common.sh"
run_bench nonconvex2 0.1 1 "$@"
