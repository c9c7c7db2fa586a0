#!/usr/bin/env bash
# The README's test command: installs what the build needs (Debian packages), builds everything
# (library, CLI, tests, benchmarks, examples, the Python package) in Release and runs the whole
# test suite and the Python tests (python/tests, pytest); then a bounded fuzz stage (every
# libFuzzer target of tests/fuzz for FUZZ_SECONDS, default 12, each: scripts/fuzz.sh; skipped with
# PENDEPTH_SKIP_FUZZ=1); then builds and runs the tests once more under AddressSanitizer +
# UndefinedBehaviorSanitizer.
# Usage: scripts/test.sh [--no-sanitize]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
JOBS=${JOBS:-2}

echo "== Release build + tests =="
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPENDEPTH_BUILD_PYTHON=ON >/dev/null
cmake --build build -j"$JOBS"
ctest --test-dir build --output-on-failure -j"$JOBS"

echo "== Python tests (Debian's /usr/bin/python3, the package built in build/python) =="
# Exit status 5 (no tests collected) is a failure too, never a silent pass.
rc=0
PYTHONPATH="$PWD/build/python" /usr/bin/python3 -m pytest -p no:cacheprovider -q python/tests || rc=$?
if [ "$rc" -eq 5 ]; then
  echo "test.sh: pytest collected no Python tests" >&2
  exit 1
fi
[ "$rc" -eq 0 ] || exit "$rc"

if [ "${PENDEPTH_SKIP_FUZZ:-0}" != 1 ]; then
  echo "== Fuzzing: ${FUZZ_SECONDS:-12} s per target (clang + libFuzzer, build-fuzz; a campaign: scripts/fuzz.sh 600) =="
  JOBS="$JOBS" ./scripts/fuzz.sh "${FUZZ_SECONDS:-12}"
fi

if [ "${1:-}" != "--no-sanitize" ]; then
  echo "== ASan + UBSan build + tests =="
  # Debug keeps assertions on; -O1 keeps the sanitized run within CI's time budget.
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DPENDEPTH_SANITIZE=ON \
        -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
        -DPENDEPTH_BUILD_BENCH=OFF -DPENDEPTH_BUILD_EXAMPLES=OFF >/dev/null
  cmake --build build-asan -j"$JOBS"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$JOBS" -LE package

  echo "== Determinism: the Release and the sanitized Debug CLI give the same bits, at 1 and 2 threads =="
  ./scripts/determinism.sh build build-asan
fi
