#!/usr/bin/env bash
# Runs bench_polygon2 (a simple polygon against a convex polygon, DHS §4: pendepth's implicit
# structure against CGAL's reduced convolution and Clipper's MinkowskiSum, each + a scan of the
# explicit sum) and prints the markdown tables kept in docs/benchmarks.md; raw results go to JSON
# and CSV.
#
# Usage: bench/run_polygon2.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (polygon2.json, polygon2.csv, polygon2.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.2)
#              REPS      repetitions; the tables use the median (default 1)
#              FILTER    --benchmark_filter regex (default: everything)
#              PENDEPTH_BENCH_N, PENDEPTH_BENCH_M   comma lists of sizes (see bench_polygon2.cpp)
#              PENDEPTH_BENCH_PEER_BUDGET          largest n·m for the CGAL peer (default 1e5)
#              PENDEPTH_BENCH_CLIPPER_BUDGET       largest n·m for the Clipper peer (default 1e4)
# Times are CPU time (less sensitive to other processes than wall time).
# The reduced run of docs/benchmarks.md (about 4 minutes on 2 loaded cores):
#   PENDEPTH_BENCH_N=10,100,1000,10000,100000 PENDEPTH_BENCH_M=4,100,1000 MIN_TIME=0.05 bench/run_polygon2.sh
set -euo pipefail
# Shared prologue: bench/run_common.sh; tables: bench/tables_polygon2.py.
source "$(dirname "$0")/run_common.sh"
run_bench polygon2 0.2 1 "$@"
