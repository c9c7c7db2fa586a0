#!/usr/bin/env bash
# Runs bench_convex2 (2D convex depth: pendepth against the naive linear scans and Box2D) and
# prints the markdown tables kept in docs/benchmarks.md; raw results go to JSON and CSV.
#
# Usage: bench/run_convex2.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (convex2.json, convex2.csv, convex2.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.2)
#              REPS      repetitions; the tables use the median (default 3)
#              FILTER    --benchmark_filter regex (default: everything)
# Times are CPU time per query (less sensitive to other processes than wall time). A full run
# takes about 3 minutes on 2 cores.
set -euo pipefail
# Shared prologue: bench/run_common.sh; tables: bench/tables_convex2.py.
source "$(dirname "$0")/run_common.sh"
run_bench convex2 0.2 3 "$@"
