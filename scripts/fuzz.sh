#!/usr/bin/env bash
# Fuzzing (docs/robustness.md, "Fuzzing"): installs clang and libFuzzer (Debian packages) when
# missing, builds the libFuzzer targets of tests/fuzz in build-fuzz (clang, ASan + UBSan,
# assertions on) and runs each for SECONDS from its seed corpus tests/fuzz/corpus/<target>/.
# New inputs go to build-fuzz/corpus/<target>/ (kept between runs, so a campaign can be resumed).
# Fails on the first crash, invariant violation, leak or timeout: the input is saved as
# build-fuzz/artifacts/<target>/crash-… (reproduce: build-fuzz/bin/<target> FILE); the file then
# belongs in the seed corpus, and a reader bug also gets a gtest.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 60)] [TARGET ...]   (default: every target)
#        JOBS=N sets the build parallelism (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
SECS=${1:-60}
[ $# -gt 0 ] && shift
JOBS=${JOBS:-2}

./scripts/setup.sh  # the Debian packages, clang and libfuzzer-14-dev included

LAUNCHER=()
command -v ccache >/dev/null && LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Debug keeps the assertions on; -O1 and line tables only keep the build and the runs short.
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only" -DPENDEPTH_FUZZ=ON \
      -DPENDEPTH_BUILD_TESTS=OFF -DPENDEPTH_BUILD_BENCH=OFF -DPENDEPTH_BUILD_EXAMPLES=OFF \
      -DPENDEPTH_BUILD_PYTHON=OFF -DPENDEPTH_BUILD_CLI=OFF -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
      "${LAUNCHER[@]}" >/dev/null
cmake --build build-fuzz -j"$JOBS"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in tests/fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi

# Input size caps: the targets ignore longer inputs (small inputs keep each execution fast).
max_len() {
  case "$1" in
    fuzz_query*) echo 1024 ;;
    fuzz_stl_binary) echo 8192 ;;
    *) echo 4096 ;;
  esac
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
summary=()
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t" "tests/fuzz/corpus/$t"
  log="build-fuzz/artifacts/$t/last.log"
  echo "== $t: ${SECS} s"
  rc=0
  "build-fuzz/bin/$t" -max_total_time="$SECS" -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" \
      "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$rc" -ne 0 ]; then
    tail -40 "$log" >&2
    echo "fuzz.sh: $t failed (exit $rc); the input is in build-fuzz/artifacts/$t/" >&2
    exit 1
  fi
  files=$(find "build-fuzz/corpus/$t" -type f | wc -l)
  summary+=("$(printf '%-22s %6s s %12s execs %6s corpus files' "$t" "$SECS" "${execs:-?}" "$files")")
done
echo "== fuzz.sh: no crash"
printf '%s\n' "${summary[@]}"
