#!/usr/bin/env bash
# The README's test command: installs what the build needs (Debian packages), builds everything
# (library, CLI, tests, benchmarks, examples) in Release and runs the whole test suite; then
# builds and runs the tests once more under AddressSanitizer + UndefinedBehaviorSanitizer.
# Usage: scripts/test.sh [--no-sanitize]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
JOBS=${JOBS:-2}

echo "== Release build + tests =="
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$JOBS"
ctest --test-dir build --output-on-failure -j"$JOBS"

if [ "${1:-}" != "--no-sanitize" ]; then
  echo "== ASan + UBSan build + tests =="
  # Debug keeps assertions on; -O1 keeps the sanitized run within CI's time budget.
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DPENDEPTH_SANITIZE=ON \
        -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
        -DPENDEPTH_BUILD_BENCH=OFF -DPENDEPTH_BUILD_EXAMPLES=OFF >/dev/null
  cmake --build build-asan -j"$JOBS"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$JOBS" -LE package
fi
