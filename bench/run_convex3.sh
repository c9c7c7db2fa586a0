#!/usr/bin/env bash
# Runs bench_convex3 (3D convex depth: pendepth's σ against libccd, FCL and Bullet float64; σ_d
# against the linear facet scan) and prints the markdown tables kept in docs/benchmarks.md; raw
# results go to JSON and CSV.
#
# Usage: bench/run_convex3.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (convex3.json, convex3.csv, convex3.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.1)
#              REPS      repetitions; the tables use the median (default 3)
#              FILTER    --benchmark_filter regex (default: everything)
# Times are CPU time per query. A full run takes about 10 minutes on 2 cores, most of it in the
# one-off set-up of the σ_d series at n = 10⁶ (hull ≈ 1 min, O(n·m) facet list of M ≈ 4 min);
# FILTER='/(8|64|512|4096|32768)$' leaves that out.
set -euo pipefail
# Shared prologue: bench/run_common.sh; tables: bench/tables_convex3.py.
source "$(dirname "$0")/run_common.sh"
run_bench convex3 0.1 3 "$@"
