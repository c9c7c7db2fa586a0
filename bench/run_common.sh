# Shared prologue of bench/run_<name>.sh; sourced, not executed. Defines run_bench, which
#   parses [build-dir] [out-dir] (defaults <repo>/build and <build-dir>/bench-results),
#   configures build-dir as Release if it has no CMakeCache.txt (warns if it is not Release),
#   builds the target bench_<name>, runs it with MIN_TIME / REPS / FILTER into <name>.json and
#   turns that into <name>.csv and <name>.md with bench/tables_<name>.py.
# Usage (from run_<name>.sh): run_bench NAME DEFAULT_MIN_TIME DEFAULT_REPS "$@"

run_bench() {
  local name=$1 min_time=$2 reps=$3
  shift 3
  local root build out btype start
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  build=${1:-$root/build}
  out=${2:-$build/bench-results}
  MIN_TIME=${MIN_TIME:-$min_time}
  REPS=${REPS:-$reps}
  FILTER=${FILTER:-.}

  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
  fi
  btype=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
  [ "$btype" = Release ] || echo "run_$name: warning: $build is a '$btype' build, not Release" >&2
  cmake --build "$build" --target "bench_$name" -j2
  mkdir -p "$out"

  echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  start=$(date +%s)
  "$build/bin/bench_$name" --benchmark_min_time="$MIN_TIME" --benchmark_repetitions="$REPS" \
    --benchmark_report_aggregates_only=true --benchmark_filter="$FILTER" \
    --benchmark_out="$out/$name.json" --benchmark_out_format=json
  echo "load after: $(cut -d' ' -f1-3 /proc/loadavg); run took $(( $(date +%s) - start )) s"

  /usr/bin/python3 "$root/bench/tables_$name.py" "$out/$name.json" "$out/$name.csv" \
    "$out/$name.md" "$btype"
  echo "results: $out/$name.json, $out/$name.csv, $out/$name.md"
}
